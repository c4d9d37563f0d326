//! Gluing the arcs of simple patches into connected polylines.
//!
//! Every arc ends on a patch edge. An end on an interior line meets the end of the arc of the
//! patch across the line at the same edge root (computed twice, from each side, so compared
//! with a tolerance); ends on the domain border stay free. Ends that find no partner lie on the
//! border of an unresolved leaf; touching leaves form clusters, and a cluster is a singular point
//! (one, three or more ends meet there), a pass-through (two) or an isolated point (none).

use crate::extract::{Arc, Leaf, Pieces};
use crate::patch::Patch;
use std::collections::HashMap;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Link {
    Free,
    End(usize),
    Node(usize),
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
type LineEnd = (f64, u8, usize);

/// Domain box `[t0, t1, r0, r1]`.
pub(crate) fn assemble(pieces: &Pieces, dom: [f64; 4], cells: &[Patch]) -> Assembled {
    let arcs = &pieces.arcs;
    let n_ends = 2 * arcs.len();
    let mut link = vec![Link::Free; n_ends];
    let ext = [dom[1] - dom[0], dom[3] - dom[2]];
    // Ends grouped by the interior line they lie on: (axis, line bits) → (v, side, id).
    let mut lines: HashMap<LineKey, Vec<LineEnd>> = HashMap::new();
    for (i, a) in arcs.iter().enumerate() {
        for (j, e) in a.ends.iter().enumerate() {
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
                lines
                    .entry((axis, e.line.to_bits()))
                    .or_default()
                    .push((v, side, 2 * i + j));
            }
        }
    }
    let mut unmatched: Vec<usize> = Vec::new();
    for ((axis, _), mut v) in lines {
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        let tol = 1e-7 * ext[if axis == 0 { 1 } else { 0 }];
        let mut i = 0;
        while i < v.len() {
            if i + 1 < v.len() && v[i].1 != v[i + 1].1 && (v[i + 1].0 - v[i].0).abs() <= tol {
                link[v[i].2] = Link::End(v[i + 1].2);
                link[v[i + 1].2] = Link::End(v[i].2);
                i += 2;
            } else {
                unmatched.push(v[i].2);
                i += 1;
            }
        }
    }
    let (cluster_of, n_clusters) = cluster_leaves(&pieces.leaves, ext);
    // Attach unmatched ends to the leaf whose box holds them.
    let mut attached: Vec<Vec<usize>> = vec![Vec::new(); n_clusters];
    let slack = [1e-9 * ext[0], 1e-9 * ext[1]];
    for id in unmatched {
        let p = arcs[id / 2].ends[id % 2].p;
        if let Some(k) = pieces.leaves.iter().position(|l| {
            p[0] >= l.bx[0] - slack[0]
                && p[0] <= l.bx[1] + slack[0]
                && p[1] >= l.bx[2] - slack[1]
                && p[1] <= l.bx[3] + slack[1]
        }) {
            attached[cluster_of[k]].push(id);
        }
    }
    let mut out = Assembled::default();
    let mut node_pt: Vec<[f64; 2]> = vec![[f64::NAN; 2]; n_clusters];
    // Representative point of a cluster: the leaf centre with the smallest |F|.
    let mut best = vec![f64::INFINITY; n_clusters];
    let mut best_cell = vec![0usize; n_clusters];
    let mut hull = vec![
        [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY
        ];
        n_clusters
    ];
    for (k, l) in pieces.leaves.iter().enumerate() {
        let c = cluster_of[k];
        if l.fabs < best[c] {
            best[c] = l.fabs;
            node_pt[c] = l.center;
            best_cell[c] = l.cell;
        }
        let h = &mut hull[c];
        h[0] = h[0].min(l.bx[0]);
        h[1] = h[1].max(l.bx[1]);
        h[2] = h[2].min(l.bx[2]);
        h[3] = h[3].max(l.bx[3]);
    }
    // Leaves resolve a crossing only to about the square root of the rounding level; Newton
    // on ∇F = 0 (a crossing or an isolated zero is a critical point) sharpens it.
    for c in 0..n_clusters {
        if let Some(cell) = cells.get(best_cell[c]) {
            if let Some(q) = critical_point(cell, node_pt[c], hull[c]) {
                node_pt[c] = q;
            }
        }
    }
    let mut node_id = vec![usize::MAX; n_clusters];
    for (c, ends) in attached.iter().enumerate() {
        match ends.len() {
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
    out.lines = walk(arcs, &link, &out.singular);
    out
}

/// Newton on `∇F = 0` from `x`, with the Hessian from central differences of the exact
/// gradient; `None` unless it converges inside the (doubled) box.
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

/// Connected components of touching leaf boxes (sweep over boxes sorted by `t0`).
fn cluster_leaves(leaves: &[Leaf], ext: [f64; 2]) -> (Vec<usize>, usize) {
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
    let mut id = vec![usize::MAX; n];
    let mut count = 0;
    let mut out = vec![0; n];
    for (i, o) in out.iter_mut().enumerate() {
        let r = find(&mut parent, i);
        if id[r] == usize::MAX {
            id[r] = count;
            count += 1;
        }
        *o = id[r];
    }
    (out, count)
}

/// Follows links from free or node ends, then closes the remaining cycles.
fn walk(arcs: &[Arc], link: &[Link], nodes: &[[f64; 2]]) -> Vec<(Vec<[f64; 2]>, bool)> {
    let mut seen = vec![false; arcs.len()];
    let mut out = Vec::new();
    let follow = |start: usize, seen: &mut Vec<bool>| -> (Vec<[f64; 2]>, bool) {
        let mut pts: Vec<[f64; 2]> = Vec::new();
        if let Link::Node(n) = link[start] {
            pts.push(nodes[n]);
        }
        let mut entry = start;
        let mut closed = false;
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
                if k == 0 && !pts.is_empty() {
                    continue; // the joint was already added from the previous arc
                }
                pts.push(*q);
            }
            let exit = entry ^ 1;
            match link[exit] {
                Link::Free => break,
                Link::Node(n) => {
                    pts.push(nodes[n]);
                    break;
                }
                Link::End(e) => {
                    if e / 2 == start / 2 {
                        closed = true;
                        break;
                    }
                    if seen[e / 2] {
                        break;
                    }
                    entry = e;
                }
            }
        }
        if closed {
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
            if !seen[i] && !matches!(link[id], Link::End(_)) {
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
