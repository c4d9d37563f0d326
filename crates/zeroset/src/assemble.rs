//! Gluing the arcs of simple patches into connected polylines.
//!
//! Every arc ends on a patch edge. An end on an interior line meets the end of the arc of the
//! patch across the line at the same edge root (computed twice, from each side, so compared
//! with a tolerance); ends on the domain border stay free. Ends that find no partner lie on the
//! border of an unresolved leaf; touching leaves form clusters, and a cluster is a singular point
//! (one, three or more ends meet there), a pass-through (two) or an isolated point (none, and
//! only where ∇F may vanish: a closed zero curve or an isolated zero needs a critical point).

use crate::extract::{Arc, End, Leaf, Pieces};
use crate::patch::{Patch, EPS};
use std::collections::HashMap;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Link {
    Free,
    End(usize),
    Node(usize),
    /// Continues through singular point `.1` into end `.0` (the opposite arm of a crossing).
    Via(usize, usize),
}

/// Polylines in `(t, r)` and the special points, before any mapping.
#[derive(Debug, Default)]
pub(crate) struct Assembled {
    /// Each polyline and whether it is closed.
    pub(crate) lines: Vec<(Vec<[f64; 2]>, bool)>,
    pub(crate) singular: Vec<[f64; 2]>,
    pub(crate) isolated: Vec<[f64; 2]>,
}

/// An interior grid line: axis (0: `t` = const, 1: `r` = const) and the constant's bits.
type LineKey = (u8, u64);
/// An arc end on a line: position along it, side of the line, end id.
type LineEnd = (f64, u8, usize, f64);

/// Domain box `[t0, t1, r0, r1]`.
pub(crate) fn assemble(pieces: &Pieces, dom: [f64; 4], cells: &[Patch]) -> Assembled {
    let arcs = &pieces.arcs;
    let n_ends = 2 * arcs.len();
    let mut link = vec![Link::Free; n_ends];
    let ext = [dom[1] - dom[0], dom[3] - dom[2]];
    let cl = cluster_leaves(&pieces.leaves, ext, cells);
    let (cluster_of, n_clusters) = (&cl.of, cl.n);
    let mut attached: Vec<Vec<usize>> = vec![Vec::new(); n_clusters];
    let leaf_at = LeafIndex::new(&pieces.leaves, ext);
    // Ends grouped by the interior line they lie on: (axis, line bits) → (v, side, id).
    let mut lines: HashMap<LineKey, Vec<LineEnd>> = HashMap::new();
    for (i, a) in arcs.iter().enumerate() {
        for (j, e) in a.ends.iter().enumerate() {
            // An end on the border of an unresolved leaf belongs to that leaf's cluster: the
            // patch across the line is the leaf. Matching it along the line instead could pair
            // it with another arm that crosses the line within the matching tolerance — near a
            // crossing, where the arms are as close as the roots are uncertain.
            if let Some(k) = leaf_at.across(e) {
                attached[cluster_of[k]].push(2 * i + j);
                continue;
            }
            let (axis, v, side) = match e.edge {
                0 => (1u8, e.p[0], 1u8),
                2 => (1, e.p[0], 0),
                1 => (0, e.p[1], 0),
                _ => (0, e.p[1], 1),
            };
            let on_border = if axis == 0 {
                e.line == dom[0] || e.line == dom[1]
            } else {
                e.line == dom[2] || e.line == dom[3]
            };
            if !on_border {
                lines.entry((axis, e.line.to_bits())).or_default().push((
                    v,
                    side,
                    2 * i + j,
                    e.unc,
                ));
            }
        }
    }
    let mut unmatched: Vec<usize> = Vec::new();
    for ((axis, _), mut v) in lines {
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        let tol = MATCH_TOL * ext[if axis == 0 { 1 } else { 0 }];
        // Within the tolerance, or within what rounding leaves of both roots.
        let close =
            |a: &LineEnd, b: &LineEnd| (b.0 - a.0).abs() <= tol.max(ROOT_SLACK * (a.3 + b.3));
        // Neighbours from opposite sides, closest first: with three ends within the tolerance
        // (beside a crossing) the nearest two are the one root seen twice.
        let mut pairs: Vec<(f64, usize)> = (0..v.len().saturating_sub(1))
            .filter(|&i| v[i].1 != v[i + 1].1 && close(&v[i], &v[i + 1]))
            .map(|i| (v[i + 1].0 - v[i].0, i))
            .collect();
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut taken = vec![false; v.len()];
        for (_, i) in pairs {
            if !taken[i] && !taken[i + 1] {
                taken[i] = true;
                taken[i + 1] = true;
                link[v[i].2] = Link::End(v[i + 1].2);
                link[v[i + 1].2] = Link::End(v[i].2);
            }
        }
        unmatched.extend((0..v.len()).filter(|&i| !taken[i]).map(|i| v[i].2));
    }
    let mut out = Assembled::default();
    let (hull, node_pt) = (&cl.hull, &cl.node);
    let end_of = |id: usize| &arcs[id / 2].ends[id % 2];
    let unit = ext[0].min(ext[1]);
    // Two ends of other arcs as close as two computations of one root can be.
    let twins = |x: usize, y: usize| -> Option<f64> {
        let (a, b) = (end_of(x), end_of(y));
        let d = ((a.p[0] - b.p[0]) / ext[0]).hypot((a.p[1] - b.p[1]) / ext[1]);
        let tol = MATCH_TOL.max(ROOT_SLACK * (a.unc + b.unc) / unit);
        (x / 2 != y / 2 && d <= tol).then_some(d)
    };
    // An end with no partner across its line goes to a leaf within the matching tolerance,
    // or else to the nearest cluster whose hull, grown by its own size, holds it. This happens
    // beside flat regions: the patch across saw the root as a corner zero (a value within its
    // rounding bound counts as positive) and handed it to the leaf there. Where F vanishes to
    // high order (three lines through a point) the flat region and the uncertainty of roots
    // beside it grow together, hence the second, relative rule.
    let mut pending: Vec<usize> = Vec::new();
    for id in unmatched {
        match leaf_at.find(end_of(id).p, MATCH_TOL) {
            Some(k) => attached[cluster_of[k]].push(id),
            None => pending.push(id),
        }
    }
    // Before that second rule, the two ends of a root at a patch corner (the zero set passed
    // within rounding of the corner, and the patches on either side saw it on the two
    // different lines through it) are joined: the border of a grown hull can pass between
    // them, and then one went to the cluster and the other, left alone, ended a branch
    // (beside a crossing, one of its arms was cut off there).
    let at_corner = |x: usize, y: usize| -> Option<f64> {
        let (a, b) = (end_of(x), end_of(y));
        if a.edge % 2 == b.edge % 2 {
            return None;
        }
        // Edges 1 and 3 lie on lines t = const, edges 0 and 2 on lines r = const.
        let corner = if a.edge % 2 == 1 {
            [a.line, b.line]
        } else {
            [b.line, a.line]
        };
        let tol = MATCH_TOL.max(ROOT_SLACK * (a.unc + b.unc) / unit);
        let off = |q: [f64; 2]| ((q[0] - corner[0]) / ext[0]).hypot((q[1] - corner[1]) / ext[1]);
        if off(a.p) > tol || off(b.p) > tol {
            return None;
        }
        // Not at a corner in a cluster's hull: there the flat region, not rounding at one
        // corner, makes the roots uncertain (a self-bisector's knot corner on the diagonal,
        // where F is flat to fourth order), and the ends go to the cluster.
        let in_hull = |h: &[f64; 4]| {
            corner[0] >= h[0] && corner[0] <= h[1] && corner[1] >= h[2] && corner[1] <= h[3]
        };
        if hull.iter().any(in_hull) {
            return None;
        }
        twins(x, y)
    };
    let taken = pair_closest(&pending, &at_corner, &mut link);
    let mut rest: Vec<usize> = Vec::new();
    for (&id, _) in pending.iter().zip(taken).filter(|(_, t)| !t) {
        let p = end_of(id).p;
        let mut best: Option<(f64, usize)> = None;
        for (c, h) in hull.iter().enumerate() {
            let (wt, wr) = (h[1] - h[0], h[3] - h[2]);
            let dt = (h[0] - p[0]).max(p[0] - h[1]).max(0.0) / wt.max(f64::MIN_POSITIVE);
            let dr = (h[2] - p[1]).max(p[1] - h[3]).max(0.0) / wr.max(f64::MIN_POSITIVE);
            let d = dt.max(dr);
            if d <= 1.0 && best.is_none_or(|b| d < b.0) {
                best = Some((d, c));
            }
        }
        match best {
            Some((_, c)) => attached[c].push(id),
            None => rest.push(id),
        }
    }
    // Ends left over, away from any cluster, that are as close as two computations of one
    // root can be are joined: the zero set passed (within rounding) by a patch corner, and
    // the patches on either side saw it on different edges of the corner.
    pair_closest(&rest, &twins, &mut link);
    // Inside the neighbourhood of a cluster (its hull grown by its own size) rounding decides
    // nothing: F is within a few rounding bounds of zero there, and arcs traced through gaps
    // between its leaves are artefacts — fragments that leave the cluster and come back, or
    // a bridge that joins two arms just outside it (two arms of a crossing seen as a V, the
    // pair of edge roots between them lost in rounding). Every arc lying entirely in that
    // neighbourhood is dropped, and whatever it was joined to is attached to the cluster:
    // the arms leaving the neighbourhood decide the topology.
    let mut dropped = vec![false; arcs.len()];
    for c in 0..n_clusters {
        let g = grown(hull[c]);
        let near = |q: &[f64; 2]| q[0] >= g[0] && q[0] <= g[1] && q[1] >= g[2] && q[1] <= g[3];
        let inside: Vec<usize> = (0..arcs.len())
            .filter(|&i| !dropped[i] && near(&arcs[i].ends[0].p) && near(&arcs[i].ends[1].p))
            .filter(|&i| arcs[i].pts.iter().all(near))
            .collect();
        for &i in &inside {
            dropped[i] = true;
        }
        for &i in &inside {
            for e in [2 * i, 2 * i + 1] {
                attached[c].retain(|&x| x != e);
                if let Link::End(o) = link[e] {
                    link[e] = Link::Free;
                    if !dropped[o / 2] {
                        link[o] = Link::Free;
                        attached[c].push(o);
                    }
                }
            }
        }
    }
    // An end attached twice (to two clusters, or once more by the rule above) counts once;
    // two ends of different arcs at one point (the same edge root, seen from both sides, both
    // handed to the cluster) are joined to each other instead: a curve passing by.
    for ends in attached.iter_mut() {
        ends.sort_unstable();
        ends.dedup();
        let mut joined: Vec<usize> = Vec::new();
        for x in 0..ends.len() {
            for y in x + 1..ends.len() {
                let (a, b) = (ends[x], ends[y]);
                if a / 2 == b / 2 || joined.contains(&a) || joined.contains(&b) {
                    continue;
                }
                let (ea, eb) = (&arcs[a / 2].ends[a % 2], &arcs[b / 2].ends[b % 2]);
                let (p, q) = (ea.p, eb.p);
                // Seen from both sides of one grid line: opposite edges on the same line.
                let across = ea.edge == (eb.edge + 2) % 4 && ea.line == eb.line;
                if across && ((p[0] - q[0]) / ext[0]).hypot((p[1] - q[1]) / ext[1]) <= SAME_POINT {
                    link[a] = Link::End(b);
                    link[b] = Link::End(a);
                    joined.extend([a, b]);
                }
            }
        }
        ends.retain(|e| !joined.contains(e));
    }
    let mut node_id = vec![usize::MAX; n_clusters];
    for (c, ends) in attached.iter().enumerate() {
        match ends.len() {
            0 if no_critical_point(cells, grown(hull[c]), node_pt[c]) => {}
            0 => out.isolated.push(node_pt[c]),
            2 => {
                link[ends[0]] = Link::End(ends[1]);
                link[ends[1]] = Link::End(ends[0]);
            }
            _ => {
                node_id[c] = out.singular.len();
                out.singular.push(node_pt[c]);
                for &e in ends {
                    link[e] = Link::Node(node_id[c]);
                }
            }
        }
    }
    // Through a crossing, each smooth curve continues into the arm leaving the node in the
    // opposite direction: pair those arms so a curve that crosses another stays one polyline.
    for ends in attached.iter().filter(|e| e.len() >= 3) {
        let Link::Node(n) = link[ends[0]] else {
            continue;
        };
        let node = out.singular[n];
        let dirs: Vec<[f64; 2]> = ends
            .iter()
            .map(|&e| arm_direction(arcs, &link, e, node, ext))
            .collect();
        let mut free: Vec<usize> = (0..ends.len()).collect();
        // Bounded: each round pairs two arms or stops.
        while free.len() >= 2 {
            let mut best: Option<(f64, usize, usize)> = None;
            for (x, &i) in free.iter().enumerate() {
                for &j in &free[x + 1..] {
                    let c = dirs[i][0] * dirs[j][0] + dirs[i][1] * dirs[j][1];
                    if best.is_none_or(|b| c < b.0) {
                        best = Some((c, i, j));
                    }
                }
            }
            match best {
                Some((c, i, j)) if c < -OPPOSITE => {
                    link[ends[i]] = Link::Via(ends[j], n);
                    link[ends[j]] = Link::Via(ends[i], n);
                    free.retain(|&k| k != i && k != j);
                }
                _ => break,
            }
        }
    }
    // An arc both of whose ends found nothing (no partner, no cluster, not on the border),
    // and that is no longer than its ends are uncertain, is rounding debris: a patch saw the
    // zero set passing within rounding of its corner (through the corner itself, traced by
    // the patches on either side) and cut the corner with a duplicate of it.
    let on_dom_border =
        |q: [f64; 2]| q[0] == dom[0] || q[0] == dom[1] || q[1] == dom[2] || q[1] == dom[3];
    for (i, a) in arcs.iter().enumerate() {
        let loose = |e: usize| link[e] == Link::Free && !on_dom_border(end_of(e).p);
        if dropped[i] || !loose(2 * i) || !loose(2 * i + 1) {
            continue;
        }
        let (lo, hi) = a.pts.iter().fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), q| {
                (
                    [lo[0].min(q[0]), lo[1].min(q[1])],
                    [hi[0].max(q[0]), hi[1].max(q[1])],
                )
            },
        );
        let size = ((hi[0] - lo[0]) / ext[0]).max((hi[1] - lo[1]) / ext[1]);
        let (x, y) = (&a.ends[0], &a.ends[1]);
        dropped[i] = size <= MATCH_TOL.max(ROOT_SLACK * (x.unc + y.unc) / unit);
    }
    out.lines = walk(arcs, &link, &out.singular, dropped);
    // An open piece shorter than the matching tolerance that ends nowhere (neither on the
    // border nor at a singular point) is rounding debris: a patch that saw the zero set
    // passing within rounding of its corner traced a duplicate of a few ulps of it.
    let on_border =
        |q: &[f64; 2]| q[0] == dom[0] || q[0] == dom[1] || q[1] == dom[2] || q[1] == dom[3];
    let at_node = |q: &[f64; 2]| out.singular.contains(q);
    out.lines.retain(|(pts, closed)| {
        let (Some(a), Some(b)) = (pts.first(), pts.last()) else {
            return false;
        };
        // Nor does a piece that never leaves the neighbourhood of a cluster (see above).
        let within = |h: &[f64; 4]| {
            let (wt, wr) = (h[1] - h[0], h[3] - h[2]);
            pts.iter().all(|q| {
                q[0] >= h[0] - wt && q[0] <= h[1] + wt && q[1] >= h[2] - wr && q[1] <= h[3] + wr
            })
        };
        if hull.iter().any(within) {
            return false;
        }
        if *closed || on_border(a) || on_border(b) || at_node(a) || at_node(b) {
            return true;
        }
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for q in pts {
            for k in 0..2 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
        (hi[0] - lo[0]) / ext[0] > MATCH_TOL || (hi[1] - lo[1]) / ext[1] > MATCH_TOL
    });
    out
}

/// Two ends on one grid line are the same edge root when they are this close (relative to
/// the domain): the root computed from either side differs by rounding / slope, which is
/// far below this except beside flat regions (unresolved leaves), where ends go to leaves.
const MATCH_TOL: f64 = 1e-7;

/// Two ends attached to one cluster closer than this (relative to the domain) are one root.
const SAME_POINT: f64 = 1e-9;

/// Two ends also match when their distance is within this many times the sum of their
/// rounding uncertainties.
const ROOT_SLACK: f64 = 4.0;

/// Arms of a singular point whose directions have a cosine below `−OPPOSITE` continue each
/// other (a transversal crossing has exactly opposite arms; 0.9 is about 25°).
const OPPOSITE: f64 = 0.9;
/// Distance from a singular point (relative to the domain) at which an arm's direction is
/// measured: far enough that the vertex positions (noisy like rounding / distance near a
/// crossing, where |∇F| vanishes) give the angle to ~1e-8, near enough to be a tangent.
const ARM_REACH: f64 = 1e-4;

/// Unit direction (in coordinates scaled by the domain) from `node` to the chain of arcs
/// leaving it through end `e`, measured at about [`ARM_REACH`] or at the chain's end.
fn arm_direction(arcs: &[Arc], link: &[Link], e: usize, node: [f64; 2], ext: [f64; 2]) -> [f64; 2] {
    let rel = |q: [f64; 2]| [(q[0] - node[0]) / ext[0], (q[1] - node[1]) / ext[1]];
    let mut entry = e;
    let mut far = rel(arcs[e / 2].ends[e % 2].p);
    // Bounded by the number of arcs (and in practice by the reach).
    'chain: for _ in 0..arcs.len() {
        let a = &arcs[entry / 2].pts;
        let pts: Box<dyn Iterator<Item = &[f64; 2]>> = if entry % 2 == 0 {
            Box::new(a.iter())
        } else {
            Box::new(a.iter().rev())
        };
        for q in pts {
            far = rel(*q);
            if far[0].hypot(far[1]) >= ARM_REACH {
                break 'chain;
            }
        }
        match link[entry ^ 1] {
            Link::End(next) if next / 2 != e / 2 => entry = next,
            _ => break,
        }
    }
    let len = far[0].hypot(far[1]);
    if len > 0.0 {
        [far[0] / len, far[1] / len]
    } else {
        [0.0, 0.0]
    }
}

/// Leaf boxes sorted by `t0`, to find the leaf holding a point.
struct LeafIndex<'a> {
    leaves: &'a [Leaf],
    order: Vec<usize>,
    t0s: Vec<f64>,
    max_w: f64,
    ext: [f64; 2],
}

impl<'a> LeafIndex<'a> {
    fn new(leaves: &'a [Leaf], ext: [f64; 2]) -> Self {
        let mut order: Vec<usize> = (0..leaves.len()).collect();
        order.sort_by(|&a, &b| leaves[a].bx[0].total_cmp(&leaves[b].bx[0]));
        let t0s = order.iter().map(|&k| leaves[k].bx[0]).collect();
        let max_w = leaves.iter().fold(0.0f64, |m, l| m.max(l.bx[1] - l.bx[0]));
        Self {
            leaves,
            order,
            t0s,
            max_w,
            ext,
        }
    }

    /// The leaf just across the patch edge that `e` lies on, holding `e` on its own edge
    /// (exact tests: the boxes of the subdivision share their split values bit for bit).
    fn across(&self, e: &End) -> Option<usize> {
        let p = e.p;
        let lo = self.t0s.partition_point(|&x| x < p[0] - self.max_w);
        let hi = self.t0s.partition_point(|&x| x <= p[0]);
        self.order[lo..hi].iter().copied().find(|&k| {
            let b = self.leaves[k].bx;
            let (along, lim) = match e.edge {
                0 => (p[0], b[3] == e.line),
                2 => (p[0], b[2] == e.line),
                1 => (p[1], b[0] == e.line),
                _ => (p[1], b[1] == e.line),
            };
            let range = if e.edge % 2 == 0 {
                [b[0], b[1]]
            } else {
                [b[2], b[3]]
            };
            lim && along >= range[0] && along <= range[1]
        })
    }

    /// A leaf whose box, grown by `slack` of the domain, holds `p`.
    fn find(&self, p: [f64; 2], slack: f64) -> Option<usize> {
        let s = [slack * self.ext[0], slack * self.ext[1]];
        // Candidates: t0 in [p − max_w − slack, p + slack].
        let lo = self.t0s.partition_point(|&x| x < p[0] - self.max_w - s[0]);
        let hi = self.t0s.partition_point(|&x| x <= p[0] + s[0]);
        self.order[lo..hi].iter().copied().find(|&k| {
            let b = self.leaves[k].bx;
            p[0] >= b[0] - s[0] && p[0] <= b[1] + s[0] && p[1] >= b[2] - s[1] && p[1] <= b[3] + s[1]
        })
    }
}

/// Joins ends of `ids` in pairs: each, in turn, with the closest still unpaired later one
/// that `close` accepts (`close` gives the distance). Returns which were paired.
fn pair_closest(
    ids: &[usize],
    close: &dyn Fn(usize, usize) -> Option<f64>,
    link: &mut [Link],
) -> Vec<bool> {
    let mut paired = vec![false; ids.len()];
    for x in 0..ids.len() {
        if paired[x] {
            continue;
        }
        let mut best = None::<(f64, usize)>;
        for y in x + 1..ids.len() {
            if paired[y] {
                continue;
            }
            if let Some(d) = close(ids[x], ids[y]) {
                if best.is_none_or(|b| d < b.0) {
                    best = Some((d, y));
                }
            }
        }
        if let Some((_, y)) = best {
            paired[x] = true;
            paired[y] = true;
            link[ids[x]] = Link::End(ids[y]);
            link[ids[y]] = Link::End(ids[x]);
        }
    }
    paired
}

/// A hull grown by its own size on every side: the neighbourhood of a cluster.
fn grown(h: [f64; 4]) -> [f64; 4] {
    let (wt, wr) = (h[1] - h[0], h[3] - h[2]);
    [h[0] - wt, h[1] + wt, h[2] - wr, h[3] + wr]
}

/// Whether one partial derivative of `F` has one trusted sign on all of the box `g`: then `F`
/// is strictly monotone along every line of `g` in that direction, so no zero of `F` in `g` is
/// isolated and no closed curve of zeros lies in `g`.
///
/// A cluster with no arcs attached is reported as an isolated point (or a loop below the
/// tolerance), which needs just that. Its leaves are flat — `|F|` below its rounding bound —
/// but flatness alone proves nothing: beside the arms of a crossing the flat region is a band
/// along each arm (where `F` is the product of the distances to the lines, narrowing as
/// `1/distance` from the crossing), and a column of leaves inside such a band, just beside the
/// arm, holds no zero at all while `∇F` there is far above its rounding level.
fn no_critical_point(cells: &[Patch], g: [f64; 4], at: [f64; 2]) -> bool {
    let err = |cell: &Patch| 4.0 * (cell.pt + cell.pr + 2) as f64 * EPS * cell.max_abs();
    // The partial at `at` (a point of `g`) is within the range of the coefficients the proof
    // needs above `2 err`; where it is not even above `err` (the evaluation's own error is
    // below a quarter of that), the proof cannot succeed and is not tried: at a crossing or
    // a degenerate corner it would always fail.
    let inside = |c: &&Patch| at[0] >= c.t0 && at[0] <= c.t1 && at[1] >= c.r0 && at[1] <= c.r1;
    let hopeless = cells.iter().find(inside).map(|cell| {
        let d = cell.eval_grad(at[0], at[1]);
        let e = err(cell);
        [
            d[1].abs() * (cell.t1 - cell.t0) <= e * cell.pt as f64,
            d[2].abs() * (cell.r1 - cell.r0) <= e * cell.pr as f64,
        ]
    });
    (0..2).any(|k| {
        if hopeless.is_some_and(|h| h[k]) {
            return false;
        }
        let mut sign = 0i8;
        for cell in cells {
            match cell.partial_sign(k, g, err(cell)) {
                None => {}
                Some(s) if s != 0 && (sign == 0 || s == sign) => sign = s,
                Some(_) => return false,
            }
        }
        sign != 0
    })
}

/// Newton on `∇F = 0` from `x`, with the Hessian from central differences of the exact
/// gradient; `None` if it leaves the (doubled) box. (At a degenerate critical point, where
/// F vanishes to higher order, it only creeps; the last iterate is returned.)
fn critical_point(cell: &Patch, x: [f64; 2], bx: [f64; 4]) -> Option<[f64; 2]> {
    let (wt, wr) = ((bx[1] - bx[0]).max(1e-300), (bx[3] - bx[2]).max(1e-300));
    let lim = [bx[0] - wt, bx[1] + wt, bx[2] - wr, bx[3] + wr];
    let (ht, hr) = (1e-4 * (cell.t1 - cell.t0), 1e-4 * (cell.r1 - cell.r0));
    let mut p = x;
    for _ in 0..30 {
        let g = cell.eval_grad(p[0], p[1]);
        let (gtp, gtm) = (
            cell.eval_grad(p[0] + ht, p[1]),
            cell.eval_grad(p[0] - ht, p[1]),
        );
        let (grp, grm) = (
            cell.eval_grad(p[0], p[1] + hr),
            cell.eval_grad(p[0], p[1] - hr),
        );
        let htt = (gtp[1] - gtm[1]) / (2.0 * ht);
        let hrr = (grp[2] - grm[2]) / (2.0 * hr);
        let htr = 0.5 * ((gtp[2] - gtm[2]) / (2.0 * ht) + (grp[1] - grm[1]) / (2.0 * hr));
        let det = htt * hrr - htr * htr;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let dt = (g[1] * hrr - g[2] * htr) / det;
        let dr = (g[2] * htt - g[1] * htr) / det;
        p = [p[0] - dt, p[1] - dr];
        if !(p[0] >= lim[0] && p[0] <= lim[1] && p[1] >= lim[2] && p[1] <= lim[3]) {
            return None;
        }
        if dt.abs() <= 1e-15 * (cell.t1 - cell.t0) && dr.abs() <= 1e-15 * (cell.r1 - cell.r0) {
            return Some(p);
        }
    }
    Some(p)
}

/// The clusters of unresolved leaves: for each leaf its cluster, and per cluster the hull of
/// its boxes and its representative point.
struct Clusters {
    of: Vec<usize>,
    n: usize,
    hull: Vec<[f64; 4]>,
    node: Vec<[f64; 2]>,
}

/// Connected components of touching leaf boxes (sweep over boxes sorted by `t0`), then merged
/// where their neighbourhoods (hulls grown by their own size) overlap.
///
/// Representative point: the leaf centre with the smallest |F|, sharpened by Newton on
/// ∇F = 0 (leaves resolve a crossing only to about the square root of the rounding level).
/// The flat region of a crossing (where |F| is below its rounding bound) reaches out along
/// the arms, thinning, and can come out of the subdivision in pieces separated by small
/// simple patches; apart, the pieces would each claim some of the arms. (A larger reach
/// also catches satellites farther along an arm, but it merges the flat corners of a
/// self-bisector's cells on the diagonal with the short genuine branches that start there.)
fn cluster_leaves(leaves: &[Leaf], ext: [f64; 2], cells: &[Patch]) -> Clusters {
    let n = leaves.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| leaves[a].bx[0].total_cmp(&leaves[b].bx[0]));
    let slack = [1e-9 * ext[0], 1e-9 * ext[1]];
    let max_w = leaves.iter().fold(0.0f64, |m, l| m.max(l.bx[1] - l.bx[0]));
    for (ia, &a) in order.iter().enumerate() {
        let la = leaves[a].bx;
        for &b in &order[ia + 1..] {
            let lb = leaves[b].bx;
            if lb[0] > la[1] + slack[0] + max_w {
                break;
            }
            let touch = lb[0] <= la[1] + slack[0]
                && la[0] <= lb[1] + slack[0]
                && lb[2] <= la[3] + slack[1]
                && la[2] <= lb[3] + slack[1];
            if touch {
                let (x, y) = (find(&mut parent, a), find(&mut parent, b));
                parent[x] = y;
            }
        }
    }
    // Per root: hull, best leaf, node.
    let mut hull: Vec<Option<[f64; 4]>> = vec![None; n];
    let mut best: Vec<(f64, usize)> = vec![(f64::INFINITY, 0); n];
    for (i, l) in leaves.iter().enumerate() {
        let r = find(&mut parent, i);
        let h = hull[r].get_or_insert(l.bx);
        h[0] = h[0].min(l.bx[0]);
        h[1] = h[1].max(l.bx[1]);
        h[2] = h[2].min(l.bx[2]);
        h[3] = h[3].max(l.bx[3]);
        if l.fabs < best[r].0 {
            best[r] = (l.fabs, i);
        }
    }
    let mut node = vec![[f64::NAN; 2]; n];
    // |∇F| at the node (scaled by the domain): zero at a crossing, so when clusters merge the
    // node nearest to being a critical point represents them.
    let mut slope = vec![f64::INFINITY; n];
    for r in 0..n {
        let Some(h) = hull[r] else { continue };
        let l = &leaves[best[r].1];
        node[r] = l.center;
        if let Some(cell) = cells.get(l.cell) {
            if let Some(q) = critical_point(cell, l.center, h) {
                node[r] = q;
            }
            let g = cell.eval_grad(node[r][0], node[r][1]);
            slope[r] = (g[1] * ext[0]).hypot(g[2] * ext[1]);
        }
    }
    let roots: Vec<usize> = (0..n).filter(|&i| hull[i].is_some()).collect();
    let meet =
        |g: [f64; 4], h: [f64; 4]| h[0] <= g[1] && g[0] <= h[1] && h[2] <= g[3] && g[2] <= h[3];
    // Bounded: each pass merges two clusters or stops.
    for _ in 0..roots.len() {
        let mut merged = false;
        let live: Vec<usize> = roots
            .iter()
            .copied()
            .filter(|&i| find(&mut parent, i) == i)
            .collect();
        'pairs: for (x, &a) in live.iter().enumerate() {
            for &b in &live[x + 1..] {
                let (Some(ha), Some(hb)) = (hull[a], hull[b]) else {
                    continue;
                };
                // Their neighbourhoods (each hull grown by its own size) overlap.
                if meet(grown(ha), grown(hb)) {
                    parent[a] = b;
                    hull[b] = Some([
                        ha[0].min(hb[0]),
                        ha[1].max(hb[1]),
                        ha[2].min(hb[2]),
                        ha[3].max(hb[3]),
                    ]);
                    // The node nearer to a critical point represents both.
                    if slope[a] < slope[b] {
                        node[b] = node[a];
                        slope[b] = slope[a];
                    }
                    merged = true;
                    break 'pairs;
                }
            }
        }
        if !merged {
            break;
        }
    }
    let mut id = vec![usize::MAX; n];
    let mut out = Clusters {
        of: vec![0; n],
        n: 0,
        hull: Vec::new(),
        node: Vec::new(),
    };
    for i in 0..n {
        let r = find(&mut parent, i);
        if id[r] == usize::MAX {
            id[r] = out.n;
            out.n += 1;
            out.hull.push(hull[r].unwrap_or([f64::NAN; 4]));
            out.node.push(node[r]);
        }
        out.of[i] = id[r];
    }
    out
}

/// Follows links from free or node ends, then closes the remaining cycles.
fn walk(
    arcs: &[Arc],
    link: &[Link],
    nodes: &[[f64; 2]],
    dropped: Vec<bool>,
) -> Vec<(Vec<[f64; 2]>, bool)> {
    let mut seen = dropped;
    let mut out = Vec::new();
    let follow = |start: usize, seen: &mut Vec<bool>| -> (Vec<[f64; 2]>, bool) {
        let mut pts: Vec<[f64; 2]> = Vec::new();
        if let Link::Node(n) = link[start] {
            pts.push(nodes[n]);
        }
        let mut entry = start;
        let mut closed = false;
        let mut shared_joint = !pts.is_empty();
        // Each step consumes one unseen arc, so this ends after at most arcs.len() steps.
        loop {
            let i = entry / 2;
            seen[i] = true;
            let a = &arcs[i].pts;
            let iter: Box<dyn Iterator<Item = &[f64; 2]>> = if entry % 2 == 0 {
                Box::new(a.iter())
            } else {
                Box::new(a.iter().rev())
            };
            for (k, q) in iter.enumerate() {
                if k == 0 && shared_joint {
                    continue; // the joint was already added from the previous arc
                }
                pts.push(*q);
            }
            let exit = entry ^ 1;
            let (next, via) = match link[exit] {
                Link::Free => break,
                Link::Node(n) => {
                    pts.push(nodes[n]);
                    break;
                }
                Link::End(e) => (e, None),
                Link::Via(e, n) => (e, Some(n)),
            };
            if let Some(n) = via {
                pts.push(nodes[n]);
            }
            shared_joint = via.is_none();
            if next / 2 == start / 2 {
                closed = true;
                if via.is_some() {
                    // Closed through a singular point: the node is the last vertex, the
                    // first arc's start follows it.
                    if let Some(&f) = pts.first() {
                        pts.push(f);
                    }
                }
                break;
            }
            if seen[next / 2] {
                break;
            }
            entry = next;
        }
        if closed && shared_joint {
            // The last arc ends where the first began: make the loop exactly closed.
            if let Some(&f) = pts.first() {
                if let Some(l) = pts.last_mut() {
                    *l = f;
                }
            }
        }
        (pts, closed)
    };
    for i in 0..arcs.len() {
        for j in 0..2 {
            let id = 2 * i + j;
            if !seen[i] && matches!(link[id], Link::Free | Link::Node(_)) {
                out.push(follow(id, &mut seen));
            }
        }
    }
    for i in 0..arcs.len() {
        if !seen[i] {
            out.push(follow(2 * i, &mut seen));
        }
    }
    out
}
