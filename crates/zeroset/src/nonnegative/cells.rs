//! One function's Bézier cells on a grid: the sign facts of the set's subdivision read off
//! them, and the values and gradients the cutting of the zero sets reads at points.

use crate::bisector::DIVISIBLE;
use crate::patch::{common_sign, Patch};
use bspline::tensor::TensorBSpline;
use numeric::rounding::UNIT_ROUNDOFF;
use numeric::Rect;

/// One function's Bézier cells, indexed by their breakpoints, with the sign of each cell's
/// values relative to the function's (a divided diagonal cell holds `F / (t − r)`).
pub(super) struct Cells {
    t_breaks: Vec<f64>,
    r_breaks: Vec<f64>,
    /// Row-major: `cells[i * (r_breaks.len() − 1) + j]` spans `t_breaks[i..=i+1]` ×
    /// `r_breaks[j..=j+1]`.
    pub(super) cells: Vec<Patch>,
    /// Per cell: −1 where the cell holds `F / (t − r)` (negative on `t < r`), else +1.
    pub(super) sign: Vec<f64>,
    /// The largest coefficient of each cell: the scale of its rounding.
    scale: Vec<f64>,
}

impl Cells {
    /// The function's cells to trace (on a domain of `pairs`, each diagonal cell that holds
    /// the factor `t − r` divided by it), and its cells of values (the function itself), from
    /// one conversion to Bézier form.
    pub(super) fn of(f: &TensorBSpline, pairs: bool) -> (Self, Self) {
        let patches = f.bezier_patches();
        let values: Vec<Patch> = patches.iter().map(Patch::from_bezier).collect();
        let mut traced = values.clone();
        let mut sign = vec![1.0; traced.len()];
        if pairs {
            for ((c, s), b) in traced.iter_mut().zip(sign.iter_mut()).zip(&patches) {
                if c.t0 == c.r0 && c.t1 == c.r1 {
                    // (The division needs one degree both ways; the other cells keep theirs.)
                    let d = b.deg_t.max(b.deg_r);
                    let square = b.to_tensor().elevate(d - b.deg_t, d - b.deg_r);
                    let square = square.bezier_patches();
                    if let Some(q) = square
                        .first()
                        .and_then(|e| Patch::from_bezier(e).divide_diagonal(DIVISIBLE))
                    {
                        *c = q;
                        *s = -1.0;
                    }
                }
            }
        }
        let traced = Self::of_patches(traced, sign);
        let ones = vec![1.0; values.len()];
        (traced, Self::of_patches(values, ones))
    }

    /// The cells `cells`, with their signs relative to the function's.
    fn of_patches(cells: Vec<Patch>, sign: Vec<f64>) -> Self {
        let scale = cells.iter().map(Patch::max_abs).collect();
        Self::grid(cells, sign, scale)
    }

    /// The cells sorted row by row, with their breakpoints.
    fn grid(cells: Vec<Patch>, sign: Vec<f64>, scale: Vec<f64>) -> Self {
        let breaks = |pick: fn(&Patch) -> (f64, f64)| {
            let mut v: Vec<f64> = cells
                .iter()
                .flat_map(|p| {
                    let (a, b) = pick(p);
                    [a, b]
                })
                .collect();
            v.sort_unstable_by(f64::total_cmp);
            v.dedup();
            v
        };
        let t_breaks = breaks(|p| (p.t0, p.t1));
        let r_breaks = breaks(|p| (p.r0, p.r1));
        let index = |p: &Patch| {
            let i = t_breaks.partition_point(|&x| x < p.t0);
            let j = r_breaks.partition_point(|&x| x < p.r0);
            i * (r_breaks.len() - 1) + j
        };
        // (No two cells share a place on the grid.)
        let mut keyed: Vec<(usize, usize)> = cells
            .iter()
            .enumerate()
            .map(|(k, c)| (index(c), k))
            .collect();
        keyed.sort_unstable();
        let order: Vec<usize> = keyed.into_iter().map(|(_, k)| k).collect();
        let mut taken: Vec<Option<Patch>> = cells.into_iter().map(Some).collect();
        Self {
            cells: order.iter().filter_map(|&k| taken[k].take()).collect(),
            sign: order.iter().map(|&k| sign[k]).collect(),
            scale: order.iter().map(|&k| scale[k]).collect(),
            t_breaks,
            r_breaks,
        }
    }

    /// The cells with every one that a cut `(axis, at)` crosses (`axis` 0: at `t = at`, 1: at
    /// `r = at`) split there, cut after cut, each part keeping its cell's sign and its scale of
    /// rounding; sorted into the grid once.
    pub(super) fn split(self, cuts: &[(usize, f64)]) -> Self {
        let mut parts: Vec<(Patch, f64, f64)> = self
            .cells
            .into_iter()
            .zip(self.sign)
            .zip(self.scale)
            .map(|((c, s), e)| (c, s, e))
            .collect();
        for &(axis, at) in cuts {
            let mut next = Vec::with_capacity(parts.len() + 8);
            for (c, s, e) in parts {
                let (lo, hi) = if axis == 0 {
                    (c.t0, c.t1)
                } else {
                    (c.r0, c.r1)
                };
                if lo < at && at < hi {
                    let u = (at - lo) / (hi - lo);
                    let (a, b) = if axis == 0 {
                        c.split_t(u)
                    } else {
                        c.split_r(u)
                    };
                    next.extend([(a, s, e), (b, s, e)]);
                } else {
                    next.push((c, s, e));
                }
            }
            parts = next;
        }
        let mut cells = Vec::with_capacity(parts.len());
        let (mut sign, mut scale) = (Vec::new(), Vec::new());
        for (c, s, e) in parts {
            cells.push(c);
            sign.push(s);
            scale.push(e);
        }
        Self::grid(cells, sign, scale)
    }

    /// The cell holding the middle of `bx`.
    fn cell_at(&self, bx: Rect) -> Option<usize> {
        let i = self
            .t_breaks
            .partition_point(|&x| x <= bx.t.mid())
            .checked_sub(1)?;
        let j = self
            .r_breaks
            .partition_point(|&x| x <= bx.r.mid())
            .checked_sub(1)?;
        let nr = self.r_breaks.len() - 1;
        (i < self.t_breaks.len() - 1 && j < nr).then_some(i * nr + j)
    }

    /// The function on `bx`, a box inside one cell (`None` if it is in none).
    pub(super) fn restricted(&self, bx: Rect) -> Option<Patch> {
        self.cells.get(self.cell_at(bx)?)?.restrict(bx)
    }

    /// Whether `q`, the function restricted to a box inside one cell
    /// ([`Cells::restricted`]), is proven negative there: [`Cells::negative_on`] that box.
    pub(super) fn negative_restricted(&self, q: &Patch) -> bool {
        self.cell_at(q.rect())
            .is_some_and(|at| self.negative_in(at, q))
    }

    /// Whether `q`, cell `at` restricted to a box, shows the function negative there.
    fn negative_in(&self, at: usize, q: &Patch) -> bool {
        // Four de Casteljau splits, each adding rounding of the order of the degree.
        let err = 16.0 * (q.pt + q.pr + 2) as f64 * UNIT_ROUNDOFF * self.scale[at];
        let want = if self.sign[at] < 0.0 { 1 } else { -1 };
        common_sign(q.c.iter().copied(), err) == want
    }

    /// Whether the function is proven negative on `bx` (all Bernstein coefficients of every
    /// cell it meets, restricted to it, negative beyond their rounding).
    pub(super) fn negative_on(&self, bx: Rect) -> bool {
        let span = |breaks: &[f64], lo: f64, hi: f64| {
            let a = breaks.partition_point(|&x| x <= lo).saturating_sub(1);
            let b = breaks.partition_point(|&x| x < hi).min(breaks.len() - 1);
            a..b.max(a + 1)
        };
        let nr = self.r_breaks.len() - 1;
        for i in span(&self.t_breaks, bx.t.lo, bx.t.hi) {
            for j in span(&self.r_breaks, bx.r.lo, bx.r.hi) {
                let at = i * nr + j;
                let Some(cell) = self.cells.get(at) else {
                    return false;
                };
                let Some(p) = cell.restrict(bx) else {
                    continue;
                };
                if !self.negative_in(at, &p) {
                    return false;
                }
            }
        }
        true
    }

    /// Value and partials `[F, F_t, F_r]` at `(t, r)` (clamped into the grid), from the cell
    /// there (at a breakpoint, the one after it, as the B-spline's basis reads it). Only for
    /// cells that hold the function itself ([`Cells::of`] not on pairs): cheaper than the
    /// B-spline's basis, which the cutting of the zero sets would read at every vertex.
    pub(super) fn eval_grad(&self, [t, r]: [f64; 2]) -> [f64; 3] {
        let index = |breaks: &[f64], x: f64| {
            let last = breaks.len().saturating_sub(2);
            (breaks.partition_point(|&b| b <= x).saturating_sub(1)).min(last)
        };
        let clamp = |breaks: &[f64], x: f64| x.clamp(breaks[0], breaks[breaks.len() - 1]);
        let (t, r) = (clamp(&self.t_breaks, t), clamp(&self.r_breaks, r));
        let at = index(&self.t_breaks, t) * (self.r_breaks.len() - 1) + index(&self.r_breaks, r);
        self.cells[at].eval_grad(t, r)
    }

    /// The value at `(t, r)` ([`Cells::eval_grad`]).
    pub(super) fn eval(&self, p: [f64; 2]) -> f64 {
        self.eval_grad(p)[0]
    }
}
