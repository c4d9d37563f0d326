//! Force closure judged from a profile's points and tangents alone, sharing no code with the
//! `grasp` crate.

use curve::{ParamCurve, Profile};

/// The share of its `min_friction` to which a grasp region's best grasp is proven the most
/// robust of its region (the contract's "Grasps: compatible additions").
pub const BEST_PROVEN_SHARE: f64 = 1e-4;

/// The larger angle between a contact's inward normal and the chord to the other, at the
/// profile's document parameters `s` and `t` (points off its corners: the normal of the
/// segment there).
pub fn slip_angle(p: &Profile, s: f64, t: f64) -> f64 {
    let (js, jt) = (p.jet(p.internal_param(s)), p.jet(p.internal_param(t)));
    let o = p.orientation();
    let d = [jt.p.x - js.p.x, jt.p.y - js.p.y];
    let angle = |tan: [f64; 2], d: [f64; 2]| {
        let n = [-o * tan[1], o * tan[0]];
        (tan[0] * d[0] + tan[1] * d[1])
            .abs()
            .atan2(n[0] * d[0] + n[1] * d[1])
    };
    angle([js.d1.x, js.d1.y], d).max(angle([jt.d1.x, jt.d1.y], [-d[0], -d[1]]))
}

/// The least friction coefficient for which the pair `(s, t)` is force closure (infinite
/// where a chord leaves a contact outward or along the boundary).
pub fn least_friction(p: &Profile, s: f64, t: f64) -> f64 {
    let a = slip_angle(p, s, t);
    if a >= std::f64::consts::FRAC_PI_2 {
        f64::INFINITY
    } else {
        a.tan()
    }
}

/// [`least_friction`] of a pair with the first finger at the convex corner at document
/// parameter `corner`: its cone is the fan between the inward normals of the segments meeting
/// there (taken a hair either side), and the chord needs no friction there when inside it.
pub fn least_friction_at_corner(p: &Profile, corner: f64, t: f64) -> f64 {
    let (a, b) = p.document_domain();
    let hair = 1e-9 * (b - a);
    let o = p.orientation();
    let normal = |u: f64| {
        let j = p.jet(p.internal_param(u));
        let len = j.d1.x.hypot(j.d1.y);
        [-o * j.d1.y / len, o * j.d1.x / len]
    };
    let wrap = |u: f64| a + (u - a).rem_euclid(b - a);
    let (before, after) = (normal(wrap(corner - hair)), normal(wrap(corner + hair)));
    let (c, q) = (
        p.jet(p.internal_param(corner)).p,
        p.jet(p.internal_param(t)).p,
    );
    let d = [q.x - c.x, q.y - c.y];
    let angle = |n: [f64; 2], d: [f64; 2]| {
        (n[1] * d[0] - n[0] * d[1])
            .abs()
            .atan2(n[0] * d[0] + n[1] * d[1])
    };
    let cross = |u: [f64; 2], v: [f64; 2]| u[0] * v[1] - u[1] * v[0];
    let turn = cross(before, after).signum();
    let at_corner = if turn * cross(before, d) >= 0.0 && turn * cross(d, after) >= 0.0 {
        0.0
    } else {
        angle(before, d).min(angle(after, d))
    };
    let at_t = angle(normal(t), [-d[0], -d[1]]);
    let slip = at_corner.max(at_t);
    if slip >= std::f64::consts::FRAC_PI_2 {
        f64::INFINITY
    } else {
        slip.tan()
    }
}

/// Whether a finger of the pair `p` lies in one of the `stretches` `[u0, u1]` of a curve's
/// parameter on `domain` (read modulo its period, as a grasp region's `best.toward`).
pub fn in_stretches(stretches: &[[f64; 2]], (a, b): (f64, f64), p: [f64; 2]) -> bool {
    stretches
        .iter()
        .any(|&[lo, hi]| p.iter().any(|&u| (u - lo).rem_euclid(b - a) <= hi - lo))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::outlines::polygon;

    #[test]
    fn a_square_s_opposite_sides_need_the_chord_s_tilt() {
        let p = polygon(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        let (a, b) = p.document_domain();
        let at = |side: f64, x: f64| a + (b - a) * (side + x) / 4.0;
        // The bottom at x = 0.5 and the top at x = 0.25 (the top runs right to left).
        let f = least_friction(&p, at(0.0, 0.5), at(2.0, 0.75));
        assert!((f - 0.25).abs() < 1e-12, "{f}");
        assert!(slip_angle(&p, at(0.0, 0.5), at(2.0, 0.5)).abs() < 1e-12);
        // From the corner (1, 0) to the top's (0.5, 1), inside the corner's fan (up to
        // left): the top's normal is half off the chord.
        let f = least_friction_at_corner(&p, at(1.0, 0.0), at(2.0, 0.5));
        assert!((f - 0.5).abs() < 1e-12, "{f}");
    }

    #[test]
    fn stretches_are_read_modulo_the_period() {
        let around_seam = [[-0.1, 0.1]];
        assert!(in_stretches(&around_seam, (0.0, 6.0), [3.0, 5.95]));
        assert!(in_stretches(&around_seam, (0.0, 6.0), [0.05, 3.0]));
        assert!(!in_stretches(&around_seam, (0.0, 6.0), [0.2, 5.8]));
    }

    #[test]
    fn a_chord_outside_a_corner_s_fan_needs_its_angle_to_the_nearer_edge() {
        // A stem with a bar on its right: from the stem's corner (1, 0) up to the bar's top
        // at (1.5, 3), a sixth right of upright at both ends.
        let p = polygon(&[
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 2.0],
            [2.0, 2.0],
            [2.0, 3.0],
            [1.0, 3.0],
            [1.0, 4.0],
            [0.0, 4.0],
        ]);
        let (a, b) = p.document_domain();
        let at = |side: f64, x: f64| a + (b - a) * (side + x) / 8.0;
        let f = least_friction_at_corner(&p, at(1.0, 0.0), at(4.0, 0.5));
        assert!((f - 1.0 / 6.0).abs() < 1e-12, "{f}");
    }
}
