//! Gluing the arcs of simple patches into connected polylines.
//!
//! Every arc ends on a patch edge. An end on an interior line meets the end of the arc of the
//! patch across the line at the same edge root (computed twice, from each side, so compared
//! with a tolerance); ends on the domain border stay free. Ends that find no partner lie on the
//! border of an unresolved leaf; touching leaves form clusters, and a cluster is a singular point
//! (one, three or more ends meet there), a pass-through (two) or an isolated point (none, and
//! only where ∇F may vanish: a closed zero curve or an isolated zero needs a critical point).

mod clusters;
mod links;

use crate::extract::Pieces;
use crate::patch::Patch;
use clusters::{cluster_leaves, grown, no_critical_point, LeafIndex};
use links::{arm_direction, pair_closest, walk, Link};
use numeric::Rect;
use std::collections::HashMap;

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
pub(crate) fn assemble(pieces: &Pieces, dom: Rect, cells: &[Patch]) -> Assembled {
    let arcs = &pieces.arcs;
    let n_ends = 2 * arcs.len();
    let mut link = vec![Link::Free; n_ends];
    let ext = [dom.t.width(), dom.r.width()];
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
                e.line == dom.t.lo || e.line == dom.t.hi
            } else {
                e.line == dom.r.lo || e.line == dom.r.hi
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
        let in_hull = |h: &Rect| h.contains(corner);
        if hull.iter().any(in_hull) {
            return None;
        }
        twins(x, y)
    };
    // (Two ends `twins` accepts lie within its largest tolerance of each other in `t`.)
    let key = |id: usize| end_of(id).p[0] / ext[0];
    let reach = |ids: &[usize]| {
        let unc = ids.iter().map(|&id| end_of(id).unc).fold(0.0, f64::max);
        MATCH_TOL.max(ROOT_SLACK * 2.0 * unc / unit)
    };
    let taken = pair_closest(&pending, &at_corner, &key, reach(&pending), &mut link);
    let mut rest: Vec<usize> = Vec::new();
    for (&id, _) in pending.iter().zip(taken).filter(|(_, t)| !t) {
        let p = end_of(id).p;
        let mut best: Option<(f64, usize)> = None;
        for (c, h) in hull.iter().enumerate() {
            let [wt, wr] = h.widths();
            let dt = (h.t.lo - p[0]).max(p[0] - h.t.hi).max(0.0) / wt.max(f64::MIN_POSITIVE);
            let dr = (h.r.lo - p[1]).max(p[1] - h.r.hi).max(0.0) / wr.max(f64::MIN_POSITIVE);
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
    pair_closest(&rest, &twins, &key, reach(&rest), &mut link);
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
        let near = |q: &[f64; 2]| g.contains(*q);
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
                if across && ((p[0] - q[0]) / ext[0]).hypot((p[1] - q[1]) / ext[1]) <= SAME_ROOT {
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
        |q: [f64; 2]| q[0] == dom.t.lo || q[0] == dom.t.hi || q[1] == dom.r.lo || q[1] == dom.r.hi;
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
        |q: &[f64; 2]| q[0] == dom.t.lo || q[0] == dom.t.hi || q[1] == dom.r.lo || q[1] == dom.r.hi;
    let at_node = |q: &[f64; 2]| out.singular.contains(q);
    out.lines.retain(|(pts, closed)| {
        let (Some(a), Some(b)) = (pts.first(), pts.last()) else {
            return false;
        };
        // Nor does a piece that never leaves the neighbourhood of a cluster (see above).
        let within = |h: &Rect| {
            let g = grown(*h);
            pts.iter().all(|q| g.contains(*q))
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
pub(crate) const MATCH_TOL: f64 = 1e-7;

/// Two ends attached to one cluster closer than this (relative to the domain) are one root.
const SAME_ROOT: f64 = 1e-9;

/// Two ends also match when their distance is within this many times the sum of their
/// rounding uncertainties.
const ROOT_SLACK: f64 = 4.0;

/// Arms of a singular point whose directions have a cosine below `−OPPOSITE` continue each
/// other (a transversal crossing has exactly opposite arms; 0.9 is about 25°).
const OPPOSITE: f64 = 0.9;
