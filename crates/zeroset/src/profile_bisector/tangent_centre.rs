//! An arc and a line tangent to its circle: the closed form's `D` vanishes for one sign
//! ([`super::arcs`]), whose points all lie on the normal common to both at the point of
//! contact. All but one have both feet there; the circle's centre has every point of the arc
//! for a foot, at the radius, as the point of contact is: where that point lies on the line
//! segment, the centre is a bisector point with feet apart (reported as isolated, as the
//! centre of two arcs of one circle is). So is each centre of two circles tangent to each
//! other, where the contact lies on the other arc (the closed form has it as 0/0).

use crate::bisector::BisectorPoint;
use bspline::Rational;
use curve::{ParamCurve, Profile, Segment};
use geometry::NearestPoint;

/// The point of contact may lie this share of the line's domain beyond its ends (their
/// rounding): a line ending where it touches the arc (a profile's smooth joint) keeps it.
const AT_END: f64 = 1e-9;

/// The centre `center` of the arc `arc` as a bisector point of `line` (tangent to the
/// circle) and the arc, its feet `[t, r]` on the line at the point of contact and on the arc
/// at the middle of its domain (any point of it is a foot), `[r, t]` when `swapped`; `None`
/// where the point of contact is off the segment.
pub(super) fn tangent_centre(
    line: &Rational,
    arc: &Rational,
    center: [f64; 2],
    swapped: bool,
) -> Option<BisectorPoint> {
    let (lo, hi) = line.domain();
    let (p, q) = (line.point(lo), line.point(hi));
    let along = [q[0] - p[0], q[1] - p[1]];
    let length2 = along[0] * along[0] + along[1] * along[1];
    if length2 == 0.0 || !length2.is_finite() {
        return None;
    }
    // (The line's parameter is affine: the contact's share of the segment is its parameter's.)
    let share = ((center[0] - p[0]) * along[0] + (center[1] - p[1]) * along[1]) / length2;
    if !(-AT_END..=1.0 + AT_END).contains(&share) {
        return None;
    }
    let t = lo + share.clamp(0.0, 1.0) * (hi - lo);
    let (a, b) = arc.domain();
    let r = 0.5 * (a + b);
    Some(isolated(if swapped { [r, t] } else { [t, r] }, center))
}

/// Two circles tangent to each other (outside or inside) when the distance of their centres
/// is the sum or the difference of their radii to this share of their sizes: a drawing's
/// rounding of tangent arcs.
const TANGENT_CIRCLES: f64 = 1e-12;

/// The point of contact lies on an arc when it is this share of the radius from it.
const ON_ARC: f64 = 1e-9;

/// Arcs `s1` and `s2` of distinct circles tangent to each other: each centre whose circle's
/// point of contact lies on the other arc is a bisector point, at its radius from every point
/// of its own arc and from the contact on the other (feet apart). Parameters `[t, r]` are the
/// segments' exact forms', its own foot at the middle of its domain.
pub(super) fn tangent_circle_centres(s1: &Segment, s2: &Segment) -> Vec<BisectorPoint> {
    let (Some((c1, r1)), Some((c2, r2))) = (s1.circle(), s2.circle()) else {
        return Vec::new();
    };
    let apart = [c2[0] - c1[0], c2[1] - c1[1]];
    let d = apart[0].hypot(apart[1]);
    let slack = TANGENT_CIRCLES * (r1 + r2 + d);
    if d == 0.0 || !d.is_finite() {
        return Vec::new();
    }
    let u = [apart[0] / d, apart[1] / d];
    // The contact, from the first centre along u (outside, or the first circle the larger)
    // or against it (inside the first).
    let along = if (d - (r1 + r2)).abs() <= slack || (d - (r1 - r2)).abs() <= slack {
        r1
    } else if (d - (r2 - r1)).abs() <= slack {
        -r1
    } else {
        return Vec::new();
    };
    let contact = [c1[0] + along * u[0], c1[1] + along * u[1]];
    let mid = |s: &Segment| {
        let (a, b) = s.curve().domain();
        0.5 * (a + b)
    };
    let mut out = Vec::new();
    // The first centre: its whole arc, and the contact on the second arc.
    if let Some(r) = param_on_arc(s2, contact, r2) {
        out.push(isolated([mid(s1), r], c1));
    }
    if let Some(t) = param_on_arc(s1, contact, r1) {
        out.push(isolated([t, mid(s2)], c2));
    }
    out
}

/// The exact form's parameter of the point `x` of an arc's circle (radius `radius`), if the
/// arc holds it.
fn param_on_arc(s: &Segment, x: [f64; 2], radius: f64) -> Option<f64> {
    let one = Profile::of_curve(s.clone(), (0.0, 1.0)).ok()?;
    let foot = one.nearest(x, 0.0);
    let (a, b) = s.curve().domain();
    (foot.distance <= ON_ARC * radius).then_some(a + foot.u * (b - a))
}

fn isolated(tr: [f64; 2], xy: [f64; 2]) -> BisectorPoint {
    BisectorPoint {
        tr,
        xy,
        segment: None,
        corner: None,
    }
}
