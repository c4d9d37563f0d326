//! Segments decided whole against a disk: an arc on its circle, a line by its exact
//! distance from the centre.

use curve::piece_bounds::CLEARANCE_ROUNDING_ULPS;
use curve::ParamCurve;
use curve::V2;
use curve::{Segment, SegmentKind};
use numeric::rounding::ulps;

/// Units of rounding allowed between an arc's rational form and its circle: its control
/// points and weights are rounded from the circle's centre, radius and angles.
const ARC_ROUNDING_ULPS: f64 = 64.0;

/// A lower bound on the distance from `x` to the arc `seg` of the circle about `c`: to its
/// nearer end where the circle's nearest point lies clearly off the arc (on the other side
/// of its chord than its middle), else to the circle; less the rounding of the computation
/// and of the arc's form.
pub(super) fn arc_distance(seg: &Segment, c: V2, radius: f64, x: V2) -> f64 {
    let (a, b) = (seg.start(), seg.end());
    let mag = x.x.abs().max(x.y.abs()) + c.x.abs().max(c.y.abs()) + radius;
    let room = ulps(ARC_ROUNDING_ULPS) * mag + 4.0 * seg.curve().curve().coefficient_error();
    let v = x - c;
    let len = v.norm();
    let to_circle = (len - radius).abs();
    let to_ends = (x - a).norm().min((x - b).norm());
    let (lo, hi) = seg.curve().domain();
    let m = seg.curve().jet_to(0.5 * (lo + hi), 0).p;
    let chord = b - a;
    // The side of the chord of the circle's nearest point, and of the arc's middle, in
    // units of the chord length times the radius (the rounding is ~mag of those).
    let side = |q: V2| chord.cross(q - a);
    let tol = ulps(8.0) * mag * (chord.norm() + radius);
    // The circle's distance bounds the arc's everywhere; where the circle's nearest point
    // lies clearly off the arc, the arc's nearest point is an end.
    let bound = if len <= room || chord.norm() <= room {
        to_circle // at the centre, or a full circle
    } else {
        let q = c + v * (radius / len);
        let (sq, sm) = (side(q), side(m));
        if sq * sm < 0.0 && sq.abs() > tol && sm.abs() > tol {
            to_ends
        } else {
            to_circle
        }
    };
    bound - room
}

/// Whether `seg` is a line whose exact distance from `x` is at least `r`, past its rounding:
/// a wide disk's reach holds the boxes of many lines that pass it by (about a junction of
/// nearly cocircular corners, most of them), which the pieces' tests would each decide at
/// many times the cost.
pub(super) fn line_passes_by(seg: &Segment, x: V2, r: f64) -> bool {
    if seg.kind() != SegmentKind::Line {
        return false;
    }
    let (a, b) = (seg.start(), seg.end());
    let squared = curve::squared_distance_to_segment(x.arr(), a.arr(), b.arr());
    // (The foot and the difference round by a few units of the coordinates; the squares by
    // a few units of themselves.)
    let room = ulps(CLEARANCE_ROUNDING_ULPS) * (x.norm() + a.norm() + b.norm() + r);
    squared >= (r + room) * (r + room) * (1.0 + ulps(4.0))
}
