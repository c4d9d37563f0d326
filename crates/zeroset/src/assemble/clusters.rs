//! The unresolved leaves of the subdivision: finding the leaf at a point, clustering touching
//! leaves into singular or isolated points, and the tests for critical points of `F` there.
//! Apart from the matching of arc ends, which only asks which cluster an end goes to.

use crate::extract::{End, Leaf};
use crate::patch::Patch;
use nalgebra::{Matrix2, Vector2};
use numeric::newton2::{newton2, Iterate, Newton2, Outcome, StepVerdict};
use numeric::rounding::UNIT_ROUNDOFF;
use numeric::Rect;

/// Leaf boxes closer than this fraction of the domain count as touching: neighbours in the
/// subdivision meet exactly (split values are shared bit for bit), and leaves this close are
/// one point at the resolution at which two arc ends are one root (`SAME_POINT`).
const TOUCH: f64 = 1e-9;

/// Least width of a leaf box in the limits of Newton's search for a critical point: a
/// degenerate (zero-width) leaf still gets limits around it, and no width the subdivision
/// makes is this small, so no other box changes.
const TINY_WIDTH: f64 = 1e-300;

/// Step of the central differences of the exact gradient for the Hessian, relative to the
/// cell: truncation (~step², 1e-8) and rounding (~ε / step, 1e-12) leave a Hessian that only
/// slows Newton from quadratic convergence to a contraction of ~1e-8 per step.
const HESSIAN_STEP: f64 = 1e-4;

/// Newton on `∇F = 0` has converged when its step is this small relative to the cell: a few
/// units of rounding of a parameter of the cell's size, below which steps are noise.
const CRITICAL_STEP: f64 = 1e-15;

/// Leaf boxes sorted by `t0`, to find the leaf holding a point.
pub(super) struct LeafIndex<'a> {
    leaves: &'a [Leaf],
    order: Vec<usize>,
    t0s: Vec<f64>,
    max_w: f64,
    ext: [f64; 2],
}

impl<'a> LeafIndex<'a> {
    pub(super) fn new(leaves: &'a [Leaf], ext: [f64; 2]) -> Self {
        let mut order: Vec<usize> = (0..leaves.len()).collect();
        order.sort_by(|&a, &b| leaves[a].bx.t.lo.total_cmp(&leaves[b].bx.t.lo));
        let t0s = order.iter().map(|&k| leaves[k].bx.t.lo).collect();
        let max_w = leaves.iter().fold(0.0f64, |m, l| m.max(l.bx.t.width()));
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
    pub(super) fn across(&self, e: &End) -> Option<usize> {
        let p = e.p;
        let lo = self.t0s.partition_point(|&x| x < p[0] - self.max_w);
        let hi = self.t0s.partition_point(|&x| x <= p[0]);
        self.order[lo..hi].iter().copied().find(|&k| {
            let b = self.leaves[k].bx;
            let (along, lim) = match e.edge {
                0 => (p[0], b.r.hi == e.line),
                2 => (p[0], b.r.lo == e.line),
                1 => (p[1], b.t.lo == e.line),
                _ => (p[1], b.t.hi == e.line),
            };
            let range = if e.edge.is_multiple_of(2) { b.t } else { b.r };
            lim && along >= range.lo && along <= range.hi
        })
    }

    /// A leaf whose box, grown by `slack` of the domain, holds `p`.
    pub(super) fn find(&self, p: [f64; 2], slack: f64) -> Option<usize> {
        let s = [slack * self.ext[0], slack * self.ext[1]];
        // Candidates: t0 in [p − max_w − slack, p + slack].
        let lo = self.t0s.partition_point(|&x| x < p[0] - self.max_w - s[0]);
        let hi = self.t0s.partition_point(|&x| x <= p[0] + s[0]);
        self.order[lo..hi]
            .iter()
            .copied()
            .find(|&k| self.leaves[k].bx.grown(s).contains(p))
    }
}

/// A hull grown by its own size on every side: the neighbourhood of a cluster.
pub(super) fn grown(h: Rect) -> Rect {
    h.grown(h.widths())
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
pub(super) fn no_critical_point(cells: &[Patch], g: Rect, at: [f64; 2]) -> bool {
    let err = |cell: &Patch| 4.0 * (cell.pt + cell.pr + 2) as f64 * UNIT_ROUNDOFF * cell.max_abs();
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

/// Newton steps on `∇F = 0`: the difference Hessian contracts the error ~1e-8 per step, so a
/// handful reach the rounding level; the rest is for a degenerate critical point's creep.
const CRITICAL_NEWTON_STEPS: usize = 30;

/// Newton on `∇F = 0` from `x` ([`numeric::newton2`]), with the Hessian from central
/// differences of the exact gradient; `None` if it leaves the (doubled) box. (At a degenerate
/// critical point, where F vanishes to higher order, it only creeps; the last iterate is
/// returned.)
fn critical_point(cell: &Patch, x: [f64; 2], bx: Rect) -> Option<[f64; 2]> {
    let (wt, wr) = (
        (bx.t.width()).max(TINY_WIDTH),
        (bx.r.width()).max(TINY_WIDTH),
    );
    let lim = bx.grown([wt, wr]);
    let (ht, hr) = (
        HESSIAN_STEP * (cell.t1 - cell.t0),
        HESSIAN_STEP * (cell.r1 - cell.r0),
    );
    // The Hessian of `F` by central differences of its exact gradient.
    let linearize = |p: &Vector2<f64>| {
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
        (Vector2::new(g[1], g[2]), Matrix2::new(htt, htr, htr, hrr))
    };
    let judge = |step: &Iterate<Vector2<f64>>| {
        let (p, d) = (step.to, step.step);
        if !lim.contains([p[0], p[1]]) {
            StepVerdict::Abandon
        } else if d[0].abs() <= CRITICAL_STEP * (cell.t1 - cell.t0)
            && d[1].abs() <= CRITICAL_STEP * (cell.r1 - cell.r0)
        {
            StepVerdict::Converged
        } else {
            StepVerdict::Continue
        }
    };
    let limits = Newton2::steps(CRITICAL_NEWTON_STEPS);
    match newton2(Vector2::from(x), limits, linearize, |p, d| p - d, judge) {
        Outcome::Converged(p) | Outcome::Exhausted(p) => Some([p[0], p[1]]),
        Outcome::Singular(_) | Outcome::Abandoned(_) => None,
    }
}

/// The clusters of unresolved leaves: for each leaf its cluster, and per cluster the hull of
/// its boxes and its representative point.
pub(super) struct Clusters {
    pub(super) of: Vec<usize>,
    pub(super) n: usize,
    pub(super) hull: Vec<Rect>,
    pub(super) node: Vec<[f64; 2]>,
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
pub(super) fn cluster_leaves(leaves: &[Leaf], ext: [f64; 2], cells: &[Patch]) -> Clusters {
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
    order.sort_by(|&a, &b| leaves[a].bx.t.lo.total_cmp(&leaves[b].bx.t.lo));
    let slack = [TOUCH * ext[0], TOUCH * ext[1]];
    let max_w = leaves.iter().fold(0.0f64, |m, l| m.max(l.bx.t.width()));
    for (ia, &a) in order.iter().enumerate() {
        let la = leaves[a].bx;
        for &b in &order[ia + 1..] {
            let lb = leaves[b].bx;
            if lb.t.lo > la.t.hi + slack[0] + max_w {
                break;
            }
            let touch = lb.t.lo <= la.t.hi + slack[0]
                && la.t.lo <= lb.t.hi + slack[0]
                && lb.r.lo <= la.r.hi + slack[1]
                && la.r.lo <= lb.r.hi + slack[1];
            if touch {
                let (x, y) = (find(&mut parent, a), find(&mut parent, b));
                parent[x] = y;
            }
        }
    }
    // Per root: hull, best leaf, node.
    let mut hull: Vec<Option<Rect>> = vec![None; n];
    let mut best: Vec<(f64, usize)> = vec![(f64::INFINITY, 0); n];
    for (i, l) in leaves.iter().enumerate() {
        let r = find(&mut parent, i);
        let h = hull[r].get_or_insert(l.bx);
        *h = h.hull(&l.bx);
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
                if grown(ha).overlaps(&grown(hb)) {
                    parent[a] = b;
                    hull[b] = Some(ha.hull(&hb));
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
            out.hull
                .push(hull[r].unwrap_or(Rect::of((f64::NAN, f64::NAN), (f64::NAN, f64::NAN))));
            out.node.push(node[r]);
        }
        out.of[i] = id[r];
    }
    out
}
