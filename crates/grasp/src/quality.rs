//! How far a pair is from slipping: the angles between the chord and the inward normals.

use crate::model::{Cone, Model};
use std::f64::consts::{FRAC_PI_2, PI};

/// The angle between `d` and the inward normals a contact at profile parameter `u` offers: at
/// a smooth point the angle to its normal; at a convex corner the angle to the nearer edge of
/// its cone (0 inside it); a reflex corner takes no part (π).
fn contact_angle(model: &Model<'_>, u: f64, tan: [f64; 2], d: [f64; 2]) -> f64 {
    let angle = |n: [f64; 2]| {
        let along = (n[1] * d[0] - n[0] * d[1]).abs();
        along.atan2(n[0] * d[0] + n[1] * d[1])
    };
    match model.joint_at(u).map(|j| j.cone) {
        Some(Cone::Reflex) => PI,
        Some(Cone::Convex { before, after }) => {
            // Inside the cone (less than π wide) when on the inner side of both edges.
            let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
            let turn = cross(before, after).signum();
            if turn * cross(before, d) >= 0.0 && turn * cross(d, after) >= 0.0 {
                0.0
            } else {
                angle(before).min(angle(after))
            }
        }
        Some(Cone::Smooth) | None => {
            let o = model.profile.orientation();
            angle([-o * tan[1], o * tan[0]])
        }
    }
}

/// The larger of the two contacts' angles between the inward normals and the chord toward
/// the other contact (`[0, π]`): the pair is force closure for friction μ exactly when this
/// is at most `atan μ`.
pub(crate) fn slip_angle(model: &Model<'_>, s: f64, t: f64) -> f64 {
    let [at_s, at_t] = contact_angles(model, s, t);
    at_s.max(at_t)
}

/// The angles of [`slip_angle`] at each contact: at `s` between its inward normals and the
/// chord, at `t` between its inward normals and the chord reversed.
pub(crate) fn contact_angles(model: &Model<'_>, s: f64, t: f64) -> [f64; 2] {
    let (p, tan_s) = model.point_tangent(s);
    let (q, tan_t) = model.point_tangent(t);
    let d = [q[0] - p[0], q[1] - p[1]];
    if d == [0.0, 0.0] {
        // One point: no chord, no grasp.
        return [PI; 2];
    }
    [
        contact_angle(model, s, tan_s, d),
        contact_angle(model, t, tan_t, [-d[0], -d[1]]),
    ]
}

/// The least friction coefficient that makes the pair force closure (infinite where a chord
/// leaves a contact outward or along the boundary).
pub(crate) fn min_friction(model: &Model<'_>, s: f64, t: f64) -> f64 {
    let a = slip_angle(model, s, t);
    if a >= FRAC_PI_2 {
        f64::INFINITY
    } else {
        a.tan()
    }
}

/// Whether the pair `p` (profile parameters) is force closure for the friction angle `alpha`
/// within the width limits `widths` (in the frame's units).
pub(crate) fn force_closure(
    model: &Model<'_>,
    alpha: f64,
    widths: [Option<f64>; 2],
    p: [f64; 2],
) -> bool {
    let (a, _) = model.point_tangent(p[0]);
    let (b, _) = model.point_tangent(p[1]);
    let d = (b[0] - a[0]).hypot(b[1] - a[1]);
    slip_angle(model, p[0], p[1]) <= alpha
        && widths[0].is_none_or(|w| d >= w)
        && widths[1].is_none_or(|w| d <= w)
}
