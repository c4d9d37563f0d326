//! The proofs of ends' places: at the centre of an arc a foot is on, or at a centre of
//! curvature where the curvature's magnitude is proven to peak within the tolerance.

use super::{distance, DiskContact, JUNCTION_ROOM};
use crate::curvature::proven_rate_sign;
use crate::sites::Sites;
use crate::Node;
use curve::ParamCurve;

/// Whether an end lies at the centre of an arc one of its feet is on (at a joint, either
/// segment there), with its radius; where it has no edge (the whole axis), at the centre of
/// every arc of the boundary, which is then one circle.
pub(super) fn end_on_arc(sites: &Sites<'_>, node: &Node, feet: &[DiskContact]) -> bool {
    let room = JUNCTION_ROOM[1] * sites.size;
    let centre_of = |s: &curve::Segment| {
        s.circle()
            .is_some_and(|(c, r)| distance(c, node.xy) <= room && (r - node.radius).abs() <= room)
    };
    if feet.is_empty() {
        // (A node with no edge is the whole axis: the disk touches the whole boundary.)
        return sites
            .boundaries
            .iter()
            .all(|b| b.segments().iter().all(centre_of));
    }
    feet.iter().any(|f| {
        let b = sites.boundaries[f.boundary];
        let (i, n) = (b.locate(f.u).0, b.segments().len());
        // A foot at a joint is on both segments there (which one its parameter locates is
        // a matter of rounding): the neighbour across is tried too.
        let seg = &b.segments()[i];
        let at = |p: curve::V2| distance(p.arr(), f.xy) <= room;
        let before = (i > 0 || b.is_closed()).then(|| (i + n - 1) % n);
        let after = (i + 1 < n || b.is_closed()).then(|| (i + 1) % n);
        [
            Some(i),
            before.filter(|_| at(seg.start())),
            after.filter(|_| at(seg.end())),
        ]
        .into_iter()
        .flatten()
        .any(|j| centre_of(&b.segments()[j]))
    })
}

/// Whether an end lies at the centre of curvature of one of its feet (on either segment at
/// a joint), with that radius, where the curvature's magnitude is proven to rise `tol`
/// before the foot and to fall `tol` after it; at a corner, on that segment's side only.
pub(super) fn end_at_curvature_peak(
    sites: &Sites<'_>,
    node: &Node,
    feet: &[DiskContact],
    tol: f64,
) -> bool {
    let room = JUNCTION_ROOM[1] * sites.size;
    feet.iter().any(|f| {
        let b = sites.boundaries[f.boundary];
        let n = b.domain().1;
        let (i, _) = b.locate(f.u);
        let beside = if f.u == i as f64 && (i > 0 || b.is_closed()) {
            Some((i + b.segments().len() - 1) % b.segments().len())
        } else {
            None
        };
        let at_centre = |s: usize| {
            let j = b.jet_on(s, f.u, 2);
            let k = j.curvature();
            let centre = j.p + j.d1.perp().unit() * (1.0 / k);
            k != 0.0
                && distance(centre.arr(), node.xy) <= room
                && (1.0 / k.abs() - node.radius).abs() <= room
        };
        // At a corner the branch ends as the foot on one segment closes in on the corner's
        // point: the curvature need peak on that segment's side only.
        let corner = f.u == i as f64 && b.corners().any(|j| j.u == f.u);
        let (before, after) = (f.u - tol, f.u + tol);
        let on = |u: f64| {
            if b.is_closed() {
                Some(u.rem_euclid(n))
            } else {
                (0.0..=n).contains(&u).then_some(u)
            }
        };
        let rate = |u: Option<f64>| u.and_then(|u| proven_rate_sign(b, b.locate(u).0, u));
        let rises_before = || rate(on(before)) == Some(1.0);
        let falls_after = || rate(on(after)) == Some(-1.0);
        // On the segment holding the foot (starting there at a corner), or on the one
        // ending there.
        let on_this = at_centre(i) && (corner || rises_before()) && falls_after();
        let on_beside =
            beside.is_some_and(at_centre) && rises_before() && (corner || falls_after());
        on_this || on_beside
    })
}
