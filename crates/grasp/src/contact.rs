//! Independent contact regions: the largest products of stretches `[s0, s1] × [t0, t1]` whose
//! pairs are all force closure, proven by the sign test on every function's Bernstein
//! coefficients over the rectangle (cut into the cells it meets).

use crate::cells::Cell;
use crate::model::{wrap, Cone, Model};
use bspline::tensor::{BezierPatch, TensorBSpline};
use numeric::rounding::UNIT_ROUNDOFF;
use smallvec::SmallVec;
use std::cell::{OnceCell, RefCell};

/// Halvings of a rectangle whose coefficients do not all show the sign, before it is given
/// up as not proven.
const PROOF_DEPTH: usize = 2;

/// Bisection steps at most for the size of the square, and for each side pushed out.
const SIZE_STEPS: usize = 24;
const SIDE_STEPS: usize = 14;

/// The searches stop when the size or the push is known to this share of the square's size
/// or the side's length: the contact region is then the largest to within a ten-millionth of
/// its stretches (a circle's band, up to π/2 wide, is met within 1e-6), while no step is
/// spent below that.
const SEARCH_ACCURACY: f64 = 1e-7;

/// One function's Bézier patches on their grid, with the rounding allowance of their
/// restricted coefficients.
struct Function {
    /// Row by row in `t`.
    patches: Vec<BezierPatch>,
    /// Where the rows start in `t` and the columns in `r`, and where the last ends.
    t_breaks: Vec<f64>,
    r_breaks: Vec<f64>,
    err: f64,
    /// Per patch, whether its own coefficients all show the sign: then so do those of every
    /// rectangle in it (each a convex combination of them), and no restriction is needed.
    whole: Vec<bool>,
    /// Per patch, what the proofs so far found there.
    known: Vec<RefCell<Known>>,
}

/// What the proofs so far found on one function's patch. The searches try nested and
/// overlapping rectangles, most of whose parts on a patch were settled before.
#[derive(Default)]
struct Known {
    /// The last part proven positive `[s0, s1, t0, t1]`: so is every rectangle inside it
    /// (its coefficients are convex combinations of that one's).
    proven: Option<[f64; 4]>,
    /// Points where the function was found negative (a corner coefficient, a value, below its
    /// rounding): no rectangle holding one is proven.
    negative: Vec<[f64; 2]>,
}

/// Points found negative kept per patch (the latest): the searches close in on one place.
const NEGATIVE_POINTS: usize = 4;

/// What the sign test found on a rectangle.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Verdict {
    Positive,
    /// The function is negative at this point of it.
    NegativeAt([f64; 2]),
    Unproven,
}

impl Function {
    fn new(f: &TensorBSpline) -> Self {
        let err = 64.0 * (f.deg_t() + f.deg_r() + 2) as f64 * UNIT_ROUNDOFF * f.max_abs_coef();
        let patches = f.bezier_patches();
        // (Row by row: the first row's columns are every row's.)
        let (ts, rs) = (f.domain_t(), f.domain_r());
        let columns = patches.iter().take_while(|p| p.t0 == ts.0).count().max(1);
        let t_breaks = patches
            .iter()
            .step_by(columns)
            .map(|p| p.t0)
            .chain([ts.1])
            .collect();
        let r_breaks = patches[..columns.min(patches.len())]
            .iter()
            .map(|p| p.r0)
            .chain([rs.1])
            .collect();
        let whole = patches
            .iter()
            .map(|p| p.coefs.iter().all(|&c| c > err))
            .collect();
        let known = patches.iter().map(|_| RefCell::default()).collect();
        Self {
            patches,
            t_breaks,
            r_breaks,
            err,
            whole,
            known,
        }
    }

    /// The patches that meet the open rectangle `s × t`.
    fn meeting(&self, s: [f64; 2], t: [f64; 2]) -> impl Iterator<Item = usize> + '_ {
        let span = |breaks: &[f64], [lo, hi]: [f64; 2]| {
            let first = breaks.partition_point(|&b| b <= lo).saturating_sub(1);
            let last = breaks.partition_point(|&b| b < hi).min(breaks.len() - 1);
            first..last.max(first)
        };
        let columns = self.r_breaks.len() - 1;
        let rows = span(&self.t_breaks, s);
        let cols = span(&self.r_breaks, t);
        rows.flat_map(move |i| cols.clone().map(move |j| i * columns + j))
    }
}

/// A stretch of one segment: its index and an interval of its form's parameter.
type SegmentStretch = (usize, [f64; 2]);

/// A rectangle's part on one cell: the cell's index and the intervals of its two contacts.
type CellPart = (usize, [f64; 2], [f64; 2]);

/// The proof that every function is positive on rectangles of the profile's parameter.
pub(crate) struct Positivity<'a> {
    model: &'a Model<'a>,
    /// The cells of the square of pairs.
    source: &'a [Cell],
    /// Per cell, its functions' patches, made when a proof first meets the cell (a contact
    /// region meets a few of them).
    cells: Vec<OnceCell<Vec<Function>>>,
    /// The cell, function and patch where the last proof failed.
    last_failure: std::cell::Cell<Option<(usize, usize, usize)>>,
}

impl<'a> Positivity<'a> {
    pub(crate) fn new(model: &'a Model<'a>, cells: &'a [Cell]) -> Self {
        Self {
            model,
            source: cells,
            cells: cells.iter().map(|_| OnceCell::new()).collect(),
            last_failure: std::cell::Cell::new(None),
        }
    }

    /// The functions of cell `k`.
    fn functions(&self, k: usize) -> &[Function] {
        self.cells[k].get_or_init(|| self.source[k].fs.iter().map(Function::new).collect())
    }

    /// Whether every pair of `[s0, s1] × [t0, t1]` (profile parameters, read modulo `n`) is
    /// proven force closure.
    pub(crate) fn proves(&self, s: [f64; 2], t: [f64; 2]) -> bool {
        let n = self.model.n() as f64;
        // (A stretch of no length is a corner line's, not a contact region.)
        if !(s[1] > s[0] && t[1] > t[0]) || s[1] - s[0] >= n || t[1] - t[0] >= n {
            return false;
        }
        let (Some(ss), Some(ts)) = (self.pieces(s), self.pieces(t)) else {
            return false;
        };
        // The rectangle's parts on the cells: the conditions hold for a pair in either order,
        // so a part below the diagonal is its mirror's.
        let parts: SmallVec<[CellPart; 8]> = ss
            .iter()
            .flat_map(|&(i, si)| {
                ts.iter().map(move |&(j, tj)| {
                    if i <= j {
                        (self.cell_index(i, j), si, tj)
                    } else {
                        (self.cell_index(j, i), tj, si)
                    }
                })
            })
            .collect();
        // The patch that failed last is tried first: the searches try nested rectangles,
        // and the one that fails them is most often the same.
        let last = self.last_failure.get();
        if let Some(at) = last {
            if parts
                .iter()
                .any(|&(k, si, tj)| k == at.0 && !self.holds_on(at, si, tj))
            {
                return false;
            }
        }
        for &(k, si, tj) in &parts {
            for (f, function) in self.functions(k).iter().enumerate() {
                for p in function.meeting(si, tj) {
                    let at = (k, f, p);
                    if Some(at) != last && !self.holds_on(at, si, tj) {
                        self.last_failure.set(Some(at));
                        return false;
                    }
                }
            }
        }
        true
    }

    /// Whether function `f` of cell `k` is proven positive on its patch `p`'s part of
    /// `si × tj` (true where they do not meet).
    fn holds_on(&self, (k, f, p): (usize, usize, usize), si: [f64; 2], tj: [f64; 2]) -> bool {
        let function = &self.functions(k)[f];
        let (patch, err) = (&function.patches[p], function.err);
        let s = [si[0].max(patch.t0), si[1].min(patch.t1)];
        let t = [tj[0].max(patch.r0), tj[1].min(patch.r1)];
        if !(s[0] < s[1] && t[0] < t[1]) || function.whole[p] {
            return true;
        }
        let mut known = function.known[p].borrow_mut();
        let holds = |x: [f64; 2]| s[0] <= x[0] && x[0] <= s[1] && t[0] <= x[1] && x[1] <= t[1];
        if known
            .proven
            .is_some_and(|[a, b, c, d]| a <= s[0] && s[1] <= b && c <= t[0] && t[1] <= d)
        {
            return true;
        }
        if known.negative.iter().any(|&x| holds(x)) {
            return false;
        }
        match positive(patch, s, t, err, PROOF_DEPTH) {
            Verdict::Positive => {
                known.proven = Some([s[0], s[1], t[0], t[1]]);
                true
            }
            Verdict::NegativeAt(x) => {
                if known.negative.len() == NEGATIVE_POINTS {
                    known.negative.remove(0);
                }
                known.negative.push(x);
                false
            }
            Verdict::Unproven => false,
        }
    }

    fn cell_index(&self, i: usize, j: usize) -> usize {
        // Cells are listed row by row: (0, 0), (0, 1), …, (0, n − 1), (1, 1), …
        let n = self.model.n();
        i * n - i * i.saturating_sub(1) / 2 + (j - i)
    }

    /// `[lo, hi]` cut at the joints into stretches of segments (in their forms' parameters);
    /// `None` when it runs across a reflex corner, whose pairs take no part.
    fn pieces(&self, [lo, hi]: [f64; 2]) -> Option<SmallVec<[SegmentStretch; 4]>> {
        let n = self.model.n();
        let mut out = SmallVec::new();
        let mut at = lo;
        while at < hi {
            let k = at.floor();
            let end = (k + 1.0).min(hi);
            let (i, v0) = self.model.locate(at);
            let (_, b) = self.model.forms[i].domain();
            let v1 = if end == k + 1.0 {
                b
            } else {
                self.model.locate(end).1
            };
            out.push((i, [v0, v1]));
            let joint = (wrap(end, n as f64) as usize) % n;
            if end < hi && self.model.joints[joint].cone == Cone::Reflex {
                return None;
            }
            at = end;
        }
        Some(out)
    }
}

/// Whether `f` is proven positive on `s × t`, halving the longer side up to `depth` times.
fn positive(f: &BezierPatch, s: [f64; 2], t: [f64; 2], err: f64, depth: usize) -> Verdict {
    let g = f.restrict(s, t);
    if g.coefs.iter().all(|&c| c > err) {
        return Verdict::Positive;
    }
    // The corners are values of f: a negative one ends the search.
    let (w, n) = (g.deg_r + 1, g.coefs.len());
    let corners = [
        (0, [s[0], t[0]]),
        (w - 1, [s[0], t[1]]),
        (n - w, [s[1], t[0]]),
        (n - 1, [s[1], t[1]]),
    ];
    if let Some(&(_, x)) = corners.iter().find(|&&(i, _)| g.coefs[i] < -err) {
        return Verdict::NegativeAt(x);
    }
    if depth == 0 {
        return Verdict::Unproven;
    }
    let halves = if s[1] - s[0] >= t[1] - t[0] {
        let m = 0.5 * (s[0] + s[1]);
        [([s[0], m], t), ([m, s[1]], t)]
    } else {
        let m = 0.5 * (t[0] + t[1]);
        [(s, [t[0], m]), (s, [m, t[1]])]
    };
    match positive(f, halves[0].0, halves[0].1, err, depth - 1) {
        Verdict::Positive => positive(f, halves[1].0, halves[1].1, err, depth - 1),
        other => other,
    }
}

/// Arc length per unit of the profile's parameter at `u`.
fn speed(model: &Model<'_>, u: f64) -> f64 {
    let (i, _) = model.locate(u);
    let (a, b) = model.forms[i].domain();
    let (_, d) = model.point_tangent(u);
    d[0].hypot(d[1]) * (b - a)
}

/// An upper bound on the half arc length of the square [`around`] can prove round `center`,
/// a point `room` (in the profile's parameter) from the region's edge: the disk inscribed in
/// the square's rectangle of parameters lies in the region.
pub(crate) fn square_at_most(model: &Model<'_>, center: [f64; 2], room: f64) -> f64 {
    room * speed(model, center[0]).max(speed(model, center[1]))
}

/// The independent contact region around `center` (a force-closure pair, profile parameters):
/// the largest square of equal arc lengths around it that is proven, then each side pushed
/// out as far as proven; with the square's half arc length. `reach` is the region's extent in
/// each parameter: no square nor push goes beyond it. `None` when not even a tiny square is
/// proven (a pair on the region's boundary, or a region that is a line or a point).
pub(crate) fn around(
    model: &Model<'_>,
    proof: &Positivity<'_>,
    center: [f64; 2],
    reach: [f64; 2],
) -> Option<([f64; 2], [f64; 2], f64)> {
    let (vs, vt) = (speed(model, center[0]), speed(model, center[1]));
    if !(vs > 0.0 && vt > 0.0) {
        return None;
    }
    let n = model.n() as f64;
    let cap = (0.5 * n * vs.min(vt))
        .min(reach[0] * vs)
        .min(reach[1] * vt)
        .max(0.0);
    let square = |l: f64| {
        (
            [center[0] - l / vs, center[0] + l / vs],
            [center[1] - l / vt, center[1] + l / vt],
        )
    };
    let proven = |(s, t): ([f64; 2], [f64; 2])| proof.proves(s, t);
    let (mut lo, mut hi) = (0.0, cap);
    if proven(square(hi)) {
        lo = hi;
    } else {
        for _ in 0..SIZE_STEPS {
            if lo > 0.0 && hi - lo <= SEARCH_ACCURACY * lo {
                break;
            }
            let mid = 0.5 * (lo + hi);
            if proven(square(mid)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    if lo <= 0.0 {
        return None;
    }
    let (mut s, mut t) = square(lo);
    // Push each side out in turn, as far as the proof goes: at most to the region's extent
    // (the rectangle lies in one of its parts).
    for side in 0..4 {
        let (extent, width) = if side < 2 {
            (reach[0], s[1] - s[0])
        } else {
            (reach[1], t[1] - t[0])
        };
        let (mut good, mut bad) = (0.0, (0.5 * n).min(extent));
        for _ in 0..SIDE_STEPS {
            if bad - good <= SEARCH_ACCURACY * width {
                break;
            }
            let mid = 0.5 * (good + bad);
            let (mut s2, mut t2) = (s, t);
            match side {
                0 => s2[0] -= mid,
                1 => s2[1] += mid,
                2 => t2[0] -= mid,
                _ => t2[1] += mid,
            }
            if proof.proves(s2, t2) {
                good = mid;
            } else {
                bad = mid;
            }
        }
        match side {
            0 => s[0] -= good,
            1 => s[1] += good,
            2 => t[0] -= good,
            _ => t[1] += good,
        }
    }
    Some((s, t, lo))
}
