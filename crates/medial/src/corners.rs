//! Disks beside a convex corner that turns by little.
//!
//! A disk tangent to one side of a convex corner at (or near) the corner's point is entered
//! by the other side, which turns into it: by `r (1 − cos θ)` for a corner turning by `θ`, at
//! `r sin θ` from the corner. For corners turning by less than about 1e-4 rad (drawings are
//! full of them: a Bézier's handle a unit in the last place written off its neighbour's
//! line) that is below the slack of the disk tests ([`crate::sites::EMPTY_SLACK`] of the
//! size), which then call the disk empty: a branch whose foot runs up to such a corner ran on
//! to the end of its bisector's domain at the corner's point, up to `r θ` past the junction
//! where the other side touches its disk, and the axis came apart there (the other branches
//! meeting at the junction end where they should). Beside such a corner the other side's
//! distance is therefore measured, not bounded: its nearest point, by Newton's method from
//! the corner, compared with the disk's radius to rounding.

use crate::candidates::{Candidate, Vertex};
use crate::sites::{Sites, EMPTY_SLACK};
use curve::{JointKind, ParamCurve};
use geometry::NearestPoint;
use numeric::rounding::ulps;

/// Units of rounding (of the centre's coordinates and the radius) by which the other side
/// must be nearer than the feet's sides to enter the disk: both are distances to nearest
/// points found alike, each rounded by a few units.
const CORNER_ROUNDING_ULPS: f64 = 64.0;

/// Where Newton's method starts on the side before a corner: this share of its parameter
/// from the corner (the side's own parameter locates the segment after at the corner).
const BEFORE_CORNER: f64 = 1e-9;

/// The side across a convex corner at an end of one of the (non-corner) feet's segments of
/// `v` that enters its disk, as the disk tests would report it: its boundary, the profile
/// parameter of its point nearest the centre, and how deep that point lies in the disk.
/// Only corners whose point is within the slack of the disk's circle are looked at (the
/// other side enters deeper than the slack elsewhere, where the disk tests see it).
///
/// The depth is measured against the feet's own sides' distances found the same way (their
/// nearest points, by Newton's method from the feet), not against the vertex's radius: near
/// a centre of curvature a foot solved to the bisectors' tolerance stands off its side's
/// nearest point by more than rounding (where an arc's centre is an end, every point of the
/// arc and the corner's other side are at one distance from it).
pub(crate) fn entered_across_corner(
    sites: &Sites<'_>,
    c: &Candidate,
    v: &Vertex,
) -> Option<(usize, f64, f64)> {
    let slack = EMPTY_SLACK * sites.size;
    let rounding = ulps(CORNER_ROUNDING_ULPS) * (v.xy[0].abs().max(v.xy[1].abs()) + v.radius);
    let own = || {
        (0..2)
            .map(|s| {
                let b = sites.boundaries[c.boundary[s]];
                if c.corner[s] {
                    let p = b.jet(v.tr[s]).p;
                    (p.x - v.xy[0]).hypot(p.y - v.xy[1])
                } else {
                    // (On the foot's own segment: a foot at its end, the corner, locates
                    // the segment across it, whose distance is the one to compare with.)
                    let i = c.segment[s];
                    let u = if b.locate(v.tr[s]).0 == i {
                        v.tr[s]
                    } else {
                        i as f64 + 1.0 - BEFORE_CORNER
                    };
                    b.nearest_near(v.xy, u).distance
                }
            })
            .fold(f64::INFINITY, f64::min)
    };
    (0..2).filter(|&s| !c.corner[s]).find_map(|s| {
        let k = c.boundary[s];
        let b = sites.boundaries[k];
        let n = b.segments().len();
        let i = c.segment[s];
        // The joints at the segment's start and end, with the segment across each.
        let start = (i > 0 || b.is_closed()).then(|| (i as f64, (i + n - 1) % n, true));
        let end = (i + 1 < n || b.is_closed()).then(|| (((i + 1) % n) as f64, (i + 1) % n, false));
        [start, end]
            .into_iter()
            .flatten()
            .find_map(|(u, across, before)| {
                let at = b.joints().binary_search_by(|j| j.u.total_cmp(&u)).ok()?;
                let joint = &b.joints()[at];
                // (A corner whose cone points into the region is a site of its own.)
                if joint.kind == JointKind::Smooth || sites.inside_of(k, 0, u, true, v.xy) {
                    return None;
                }
                let p = b.jet(u).p;
                if (p.x - v.xy[0]).hypot(p.y - v.xy[1]) > v.radius + slack {
                    return None;
                }
                let from = if before {
                    across as f64 + 1.0 - BEFORE_CORNER
                } else {
                    across as f64
                };
                let near = b.nearest_near(v.xy, from);
                let depth = own() - near.distance;
                (depth > rounding).then_some((k, near.u, depth))
            })
    })
}
