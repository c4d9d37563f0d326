//! How far a pair is from slipping: the angles between the chord and the inward normals.

use crate::cones::Form;

/// The point and tangent at `u` (any real: read modulo the period of a closed curve).
pub(crate) fn point_tangent(form: &Form, u: f64) -> ([f64; 2], [f64; 2]) {
    let (a, b) = form.domain();
    let w = b - a;
    let u = if (a..=b).contains(&u) {
        u
    } else {
        a + (u - a).rem_euclid(w)
    };
    let mut out = [0.0; 4];
    form.curve().eval_derivs(u, 1, &mut out);
    ([out[0], out[1]], [out[2], out[3]])
}

/// The larger of the two angles between a contact's inward normal and the chord toward the
/// other contact (`[0, π]`): the pair is force closure for friction μ exactly when this is
/// at most `atan μ`.
pub(crate) fn slip_angle(form: &Form, s: f64, t: f64) -> f64 {
    let (p, ts) = point_tangent(form, s);
    let (q, tt) = point_tangent(form, t);
    let d = [q[0] - p[0], q[1] - p[1]];
    if d == [0.0, 0.0] {
        // One point: no chord, no grasp.
        return std::f64::consts::PI;
    }
    let o = form.orientation();
    let angle = |tan: [f64; 2], d: [f64; 2]| {
        let n = [-o * tan[1], o * tan[0]];
        let along = (tan[0] * d[0] + tan[1] * d[1]).abs();
        let across = n[0] * d[0] + n[1] * d[1];
        along.atan2(across)
    };
    angle(ts, d).max(angle(tt, [-d[0], -d[1]]))
}

/// The least friction coefficient that makes the pair force closure (infinite where a chord
/// leaves a contact outward or along the boundary).
pub(crate) fn min_friction(form: &Form, s: f64, t: f64) -> f64 {
    let a = slip_angle(form, s, t);
    if a >= std::f64::consts::FRAC_PI_2 {
        f64::INFINITY
    } else {
        a.tan()
    }
}
