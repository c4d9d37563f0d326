//! What an axis's `certified` rests on, node by node, decided by sign tests on bounds.
//!
//! - A **junction**: a disk about it of radius `h` (a tiny share of the size) holds a point
//!   equidistant from three stretches of the boundary, one about each of three of its feet.
//!   With `dA, dB, dC` the distances to those stretches (each 1-Lipschitz), the map
//!   `(dA − dB, dA − dC)` is shown to wind round zero along a polygon in that disk (Brouwer's
//!   degree): every distance at a polygon's corner is enclosed by proven disks (one clear of
//!   the stretch, one entered by it), and along each side one component keeps its sign
//!   within the Lipschitz bound.
//! - An **end** on an arc: at the arc's centre, its radius the arc's (exact data). An end on
//!   a spline: at the centre of curvature of one of its feet, the curvature's magnitude
//!   proven rising `tol` (the parameter tolerance) before that foot and falling `tol` after
//!   it, by bounds on the rate's numerator
//!   ([`proven_rate_sign`](crate::curvature::proven_rate_sign)): a peak lies within `tol` of
//!   the foot. At a corner, where the leaf ends as the foot on one segment closes in on the
//!   corner's point, on that segment's side only.
//! - A **corner**, the **joint** of an annulus and a **clip** leaf: at a corner of the
//!   boundary, anywhere on a cycle, on the clip box (exact data or no claim of place).

mod ends;
mod junctions;

use crate::assemble::root;
use crate::coverage::within_in_x;
use crate::sites::{Disk, Sites};
use crate::{MedialAxis, Node, NodeKind};
use curve::ParamCurve;
use ends::{end_at_curvature_peak, end_on_arc};
use junctions::{closed_form_junction_proven, junction_proven};
use numeric::certificate::{Doubt, UnreachedCorner};
use std::collections::HashSet;

/// Radii of the disks about a junction searched for its exact point, as shares of the size:
/// the first well above the enclosures' rounding (~1e-15 of the coordinates), the second
/// for junctions far from the origin; no more than the contract's claim of place for a
/// vertex.
pub(crate) const JUNCTION_ROOM: [f64; 2] = [1e-10, 1e-9];

/// Feet of a node's edges within this share of the size are one contact with the boundary
/// (the stretches meeting at a junction found it to ~1e-12 of the size each).
const SAME_FOOT: f64 = 1e-6;

/// `doubt` placed on `axis` of `sites`: where the axis's graph or its feet show a piece
/// may be missing, the first convex corner no leaf reaches (if any), which its reason names.
pub(crate) fn placed(doubt: Doubt, sites: &Sites<'_>, axis: &MedialAxis) -> Doubt {
    let unreached = || {
        let corners = crate::coverage::unreached_convex_corners(sites, axis);
        corners.first().map(|first| UnreachedCorner {
            at: first.xy,
            boundary: first.boundary,
            turn: first.turn,
            more: corners.len() - 1,
        })
    };
    match doubt {
        Doubt::AxisGraph { unreached: None } => Doubt::AxisGraph {
            unreached: unreached(),
        },
        Doubt::Coverage { unreached: None } => Doubt::Coverage {
            unreached: unreached(),
        },
        other => other,
    }
}

/// The first node of `axis` whose place is not proven, as a doubt; `tol` is the parameter
/// tolerance an end's peak of curvature is proven to. Junctions at the places in `proven`
/// (bits of their coordinates) were proven by the caller, disk and place.
pub(crate) fn doubt(
    sites: &Sites<'_>,
    axis: &MedialAxis,
    tol: f64,
    proven: &HashSet<[u64; 2]>,
) -> Option<Doubt> {
    // The edges at each node, for its feet.
    let mut edges_at: Vec<Vec<usize>> = vec![Vec::new(); axis.nodes.len()];
    for (k, e) in axis.edges.iter().enumerate() {
        edges_at[e.from].push(k);
        if e.to != e.from {
            edges_at[e.to].push(k);
        }
    }
    let corners = Corners::of(sites);
    // (A node's proof may take milliseconds: the watch is looked at for each.)
    let stage = curve::watch::stage("medial axis: the certificate, node by node");
    axis.nodes.iter().find_map(|node| {
        if !stage.go_on(1) {
            return Some(Doubt::Cancelled);
        }
        // A junction's or an end's disk is empty (to the slack): the node is on the axis.
        let empty = || sites.disk(node.xy, node.radius) == Disk::Empty;
        let same = SAME_FOOT * sites.size;
        let feet = || feet_of(sites, axis, &edges_at[node.id], node.id, same);
        let proven = match node.kind {
            NodeKind::Junction => {
                proven.contains(&node.xy.map(f64::to_bits))
                    || (empty()
                        && (junction_proven(sites, node, &feet())
                            || closed_form_junction_proven(
                                sites,
                                node,
                                &feet_of(sites, axis, &edges_at[node.id], node.id, 0.0),
                            )))
            }
            NodeKind::End => {
                let feet = feet();
                empty()
                    && (end_on_arc(sites, node, &feet)
                        || end_at_curvature_peak(sites, node, &feet, tol))
            }
            NodeKind::Corner => corners.at_corner(sites, node),
            NodeKind::Joint | NodeKind::Clip => true,
        };
        (!proven).then_some(match node.kind {
            NodeKind::Junction => Doubt::Junction,
            NodeKind::Corner => Doubt::CornerLeaf,
            _ => Doubt::AxisEnd,
        })
    })
}

/// Whether the graph is connected with `holes` independent cycles, as the axis inside a
/// region with that many holes is (a deformation retract of it).
pub(crate) fn shaped_like_the_region(axis: &MedialAxis, holes: usize) -> bool {
    let n = axis.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    for e in &axis.edges {
        let (a, b) = (root(&mut parent, e.from), root(&mut parent, e.to));
        parent[a] = b;
    }
    let pieces = (0..n).filter(|&i| root(&mut parent, i) == i).count();
    pieces == 1 && axis.edges.len() + 1 == n + holes
}

/// A contact of a node's disk with the boundary: boundary, profile parameter, point.
#[derive(Debug, Clone, Copy)]
struct DiskContact {
    boundary: usize,
    u: f64,
    xy: [f64; 2],
}

/// The feet of the ends at node `id` of `edges` (the axis's edges that end there), those on
/// one boundary within `same` of each other as one.
fn feet_of(
    sites: &Sites<'_>,
    axis: &MedialAxis,
    edges: &[usize],
    id: usize,
    same: f64,
) -> Vec<DiskContact> {
    let mut out: Vec<DiskContact> = Vec::new();
    for e in edges.iter().map(|&k| &axis.edges[k]) {
        let ends = [(e.from == id, 0), (e.to == id, e.feet.len() - 1)];
        for (at, k) in ends {
            if !at {
                continue;
            }
            for s in 0..2 {
                let (b, u) = (e.boundary[k][s], e.feet[k][s]);
                let xy = sites.foot(b, u);
                if !out
                    .iter()
                    .any(|f| f.boundary == b && distance(f.xy, xy) <= same)
                {
                    out.push(DiskContact { boundary: b, u, xy });
                }
            }
        }
    }
    out
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The corners of the boundaries (boundary, profile parameter), sorted by their points' x.
struct Corners(Vec<([f64; 2], usize, f64)>);

impl Corners {
    fn of(sites: &Sites<'_>) -> Self {
        let mut all: Vec<([f64; 2], usize, f64)> = sites
            .boundaries
            .iter()
            .enumerate()
            .flat_map(|(k, b)| b.corners().map(move |j| (b.jet(j.u).p.arr(), k, j.u)))
            .collect();
        all.sort_by(|a, b| a.0[0].total_cmp(&b.0[0]));
        Self(all)
    }

    /// Whether a corner leaf lies at a corner of the boundary that is convex for the part
    /// of the plane whose axis is sought (a reflex one's cone points into it: no leaf ends
    /// there).
    fn at_corner(&self, sites: &Sites<'_>, node: &Node) -> bool {
        let room = JUNCTION_ROOM[1] * sites.size;
        within_in_x(&self.0, |c| c.0, node.xy, room).any(|&(p, k, u)| {
            distance(p, node.xy) <= room && !sites.inside_of(k, 0, u, true, node.xy)
        })
    }
}

#[cfg(test)]
mod tests;
