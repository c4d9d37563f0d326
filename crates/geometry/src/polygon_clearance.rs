//! Whether a convex polygon holds a point of a profile of lines, proven by separating axes.
//!
//! A medial axis tests the disks along a bisector of two lines all at once: disks whose
//! centres and radii move linearly sweep the convex hull of the two end disks, which is the
//! two disks and the quadrilateral between their points of tangency. The disks are tested one
//! by one ([`crate::ProfileClearance::clearance`]); the quadrilateral here, against each line near it, by the
//! separating axis theorem (two convex sets of the plane are apart if and only if the
//! projections on the normal of some edge of either are). Every comparison leaves room for
//! the rounding of the projections, so a separation found holds for the exact lines.

use curve::Profile;
use curve::SegmentKind;
use curve::V2;
use numeric::rounding::ulps;

/// Units of rounding allowed in a projection: a dot product of coordinates with an edge's
/// normal (two products and a sum, each rounding by half a unit of the largest coordinate
/// times the normal), doubled for the difference of two of them.
const POLYGON_ROUNDING_ULPS: f64 = 8.0;

/// [`crate::ProfileClearance::misses_convex_polygon`].
pub(crate) fn misses_convex_polygon(profile: &Profile, corners: &[[f64; 2]]) -> bool {
    if corners.len() < 3 || corners.iter().flatten().any(|c| !c.is_finite()) {
        return false;
    }
    let pts: Vec<V2> = corners.iter().map(|&c| V2::from_arr(c)).collect();
    let (mut lo, mut hi) = (pts[0], pts[0]);
    for p in &pts {
        lo = V2::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = V2::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    let centre = (lo + hi) * 0.5;
    // (A shade beyond the half diagonal: the tree passes over no box the test needs.)
    let reach = (hi - lo).norm() * 0.5 * (1.0 + 1e-12) + f64::MIN_POSITIVE;
    let mut apart = true;
    profile.box_tree().within(centre, reach, |i| {
        if !apart {
            return;
        }
        let b = profile.segment_box(i);
        // (Boxes apart: the segment, inside its box, is apart from the polygon too.)
        if b[2] < lo.x || b[0] > hi.x || b[3] < lo.y || b[1] > hi.y {
            return;
        }
        let seg = &profile.segments()[i];
        apart = seg.kind() == SegmentKind::Line && separated(&pts, [seg.start(), seg.end()]);
    });
    apart
}

/// Whether the segment `s` and the convex polygon `poly` are apart along the normal of an
/// edge of either, by more than the rounding of the projections.
fn separated(poly: &[V2], s: [V2; 2]) -> bool {
    let scale = poly
        .iter()
        .chain(&s)
        .map(|p| p.x.abs().max(p.y.abs()))
        .fold(0.0, f64::max);
    let apart_along = |n: V2| {
        let room = ulps(POLYGON_ROUNDING_ULPS) * scale * (n.x.abs() + n.y.abs());
        let (mut pmin, mut pmax) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in poly {
            let d = p.dot(n);
            pmin = pmin.min(d);
            pmax = pmax.max(d);
        }
        let (a, b) = (s[0].dot(n), s[1].dot(n));
        a.max(b) < pmin - room || a.min(b) > pmax + room
    };
    let edges = (0..poly.len()).map(|k| poly[(k + 1) % poly.len()] - poly[k]);
    std::iter::once(s[1] - s[0])
        .chain(edges)
        .filter(|e| e.x != 0.0 || e.y != 0.0)
        .any(|e| apart_along(V2::new(-e.y, e.x)))
}

#[cfg(test)]
mod tests {
    use super::separated;
    use crate::ProfileClearance;
    use curve::V2;
    use curve::{Profile, Segment};
    use proptest::prelude::*;

    /// Whether the segment meets the convex polygon, by dense samples of the segment tested
    /// against every edge's half-plane (the independent method), with `grow` of room.
    fn meets(poly: &[V2], s: [V2; 2], grow: f64) -> bool {
        let area: f64 = (0..poly.len())
            .map(|k| poly[k].cross(poly[(k + 1) % poly.len()]))
            .sum();
        (0..=2000).any(|i| {
            let x = s[0] + (s[1] - s[0]) * (i as f64 / 2000.0);
            (0..poly.len()).all(|k| {
                let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
                (b - a).cross(x - a) * area.signum() >= -grow * (b - a).norm()
            })
        })
    }

    proptest! {
        /// A separation is never found where samples of the segment lie in the polygon, and
        /// is found wherever the segment keeps a clear distance from it (the axes are
        /// complete for a convex polygon and a segment).
        #[test]
        fn separation_agrees_with_samples(
            centre in prop::array::uniform2(-5.0f64..5.0),
            radius in 0.1f64..3.0,
            turn in 0.0f64..6.3,
            sides in 3usize..7,
            s in prop::array::uniform4(-8.0f64..8.0),
        ) {
            let poly: Vec<V2> = (0..sides)
                .map(|k| V2::from_arr(centre) + V2::polar(turn + std::f64::consts::TAU * k as f64 / sides as f64) * radius)
                .collect();
            let seg = [V2::new(s[0], s[1]), V2::new(s[2], s[3])];
            let apart = separated(&poly, seg);
            if meets(&poly, seg, 0.0) {
                prop_assert!(!apart);
            }
            if !meets(&poly, seg, 1e-2) {
                prop_assert!(apart);
            }
        }
    }

    #[test]
    fn a_polygon_inside_or_across_a_profile() {
        let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
        let sides = (0..4)
            .map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap())
            .collect();
        let p = Profile::new(sides, None).unwrap();
        // Touching a side is not apart; a hair inside is; a polygon outside the box is too.
        assert!(!p.misses_convex_polygon(&[[1.0, 0.0], [3.0, 0.5], [2.0, 1.0]]));
        assert!(p.misses_convex_polygon(&[[1.0, 1e-12], [3.0, 0.5], [2.0, 1.0]]));
        assert!(p.misses_convex_polygon(&[[5.0, 5.0], [6.0, 5.0], [6.0, 6.0]]));
        assert!(!p.misses_convex_polygon(&[[1.0, 1.0], [2.0, 1.0]]));
        assert!(!p.misses_convex_polygon(&[[1.0, 1.0], [2.0, f64::NAN], [2.0, 1.5]]));
    }
}
