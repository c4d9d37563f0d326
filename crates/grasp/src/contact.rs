//! Independent contact regions: the largest products of stretches `[s0, s1] × [t0, t1]` whose
//! pairs are all force closure, proven by the sign test on every function's Bernstein
//! coefficients over the rectangle.

use crate::cones::Form;
use crate::quality::point_tangent;
use bspline::tensor::TensorBSpline;
use numeric::rounding::UNIT_ROUNDOFF;

/// Halvings of a rectangle whose coefficients do not all show the sign, before it is given
/// up as not proven.
const PROOF_DEPTH: usize = 3;

/// Bisection steps for the size of the square and for each side pushed out.
const SIZE_STEPS: usize = 24;
const SIDE_STEPS: usize = 16;

/// The proof that every function is positive on rectangles.
pub(crate) struct Positivity<'a> {
    fs: &'a [TensorBSpline],
    domain: (f64, f64),
    /// Per function, the rounding allowance of its restricted coefficients.
    err: Vec<f64>,
}

impl<'a> Positivity<'a> {
    pub(crate) fn new(fs: &'a [TensorBSpline], domain: (f64, f64)) -> Self {
        let err = fs
            .iter()
            .map(|f| 64.0 * (f.deg_t() + f.deg_r() + 2) as f64 * UNIT_ROUNDOFF * f.max_abs_coef())
            .collect();
        Self { fs, domain, err }
    }

    /// Whether every pair of `[s0, s1] × [t0, t1]` (read modulo the period) is proven force
    /// closure.
    pub(crate) fn proves(&self, s: [f64; 2], t: [f64; 2]) -> bool {
        let (ss, ts) = (self.pieces(s), self.pieces(t));
        ss.iter()
            .all(|&s| ts.iter().all(|&t| self.proves_in_domain(s, t)))
    }

    /// `[lo, hi]` (no longer than the period) cut at the seam into stretches of the domain.
    fn pieces(&self, [lo, hi]: [f64; 2]) -> Vec<[f64; 2]> {
        let (a, b) = self.domain;
        let w = b - a;
        let shift = ((lo - a) / w).floor() * w;
        let (lo, hi) = (lo - shift, hi - shift);
        if hi <= b {
            vec![[lo, hi]]
        } else {
            vec![[lo, b], [a, (hi - w).min(b)]]
        }
    }

    fn proves_in_domain(&self, s: [f64; 2], t: [f64; 2]) -> bool {
        self.fs
            .iter()
            .zip(&self.err)
            .all(|(f, &err)| positive(f, s, t, err, PROOF_DEPTH))
    }
}

/// Whether `f` is proven positive on `s × t`, halving the longer side up to `depth` times.
fn positive(f: &TensorBSpline, s: [f64; 2], t: [f64; 2], err: f64, depth: usize) -> bool {
    let Ok(g) = f.restrict(s[0], s[1], t[0], t[1]) else {
        return false;
    };
    let (lo, _) = g.coef_range();
    if lo > err {
        return true;
    }
    // The corners are values of f: a negative one ends the search.
    let n = g.coefs().len();
    let corner_negative = [0, g.n_r() - 1, n - g.n_r(), n - 1]
        .iter()
        .any(|&i| g.coefs()[i] < -err);
    if depth == 0 || corner_negative {
        return false;
    }
    if s[1] - s[0] >= t[1] - t[0] {
        let m = 0.5 * (s[0] + s[1]);
        positive(f, [s[0], m], t, err, depth - 1) && positive(f, [m, s[1]], t, err, depth - 1)
    } else {
        let m = 0.5 * (t[0] + t[1]);
        positive(f, s, [t[0], m], err, depth - 1) && positive(f, s, [m, t[1]], err, depth - 1)
    }
}

/// The independent contact region around `center` (a force-closure pair): the largest square
/// of equal arc lengths around it that is proven, then each side pushed out as far as
/// proven. `None` when not even a tiny square is proven (a pair on the region's boundary).
pub(crate) fn around(
    form: &Form,
    proof: &Positivity<'_>,
    center: [f64; 2],
    reach: [f64; 2],
) -> Option<([f64; 2], [f64; 2])> {
    let speed = |u: f64| {
        let (_, d) = point_tangent(form, u);
        d[0].hypot(d[1])
    };
    let (vs, vt) = (speed(center[0]), speed(center[1]));
    if !(vs > 0.0 && vt > 0.0) {
        return None;
    }
    let period = form.domain().1 - form.domain().0;
    // Half arc lengths: ℓ / v in each parameter, at most a half period.
    let cap = (0.5 * period * vs.min(vt))
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
    // Push each side out in turn, as far as the proof goes.
    for side in 0..4 {
        let (mut good, mut bad) = (0.0, period * 0.5);
        for _ in 0..SIDE_STEPS {
            let mid = 0.5 * (good + bad);
            let (mut s2, mut t2) = (s, t);
            match side {
                0 => s2[0] -= mid,
                1 => s2[1] += mid,
                2 => t2[0] -= mid,
                _ => t2[1] += mid,
            }
            if s2[1] - s2[0] < period && t2[1] - t2[0] < period && proof.proves(s2, t2) {
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
    Some((s, t))
}
