//! Least-squares fits of clamped B-splines to sampled curves, within a measured tolerance.
//!
//! The fit passes through the first and last samples (so fitted pieces meet where the curves
//! they stand for do) and is solved by a QR factorisation (nalgebra's Householder). Knots are added in the spans where the fit
//! strays from its target, until it is within the tolerance at every sample and at points
//! between them. The target is the caller's: the deviation of a fitted point from it, measured
//! by a closure (from a polyline, or from the exact curve the samples were taken on).

use crate::knots::basis_at;
use nalgebra::DMatrix;

/// Rounds of knot insertion before the fit is given up.
const MAX_ROUNDS: usize = 40;

/// Knots stay this far apart (in the parameter over `[0, 1]`): closer, the least-squares
/// system loses rank.
const KNOT_GAP: f64 = 1e-9;

/// A clamped B-spline on `[0, 1]` of points in `D` dimensions, with the largest deviation
/// measured from its target.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit<const D: usize> {
    /// The degree.
    pub degree: usize,
    /// The knots (clamped: the first and last repeated `degree + 1` times).
    pub knots: Vec<f64>,
    /// The control points.
    pub points: Vec<[f64; D]>,
    /// The largest deviation measured.
    pub error: f64,
}

impl<const D: usize> Fit<D> {
    /// The point at parameter `t ∈ [0, 1]`.
    pub fn eval(&self, t: f64) -> [f64; D] {
        let (first, basis) = basis_at(self.degree, &self.knots, t);
        let mut out = [0.0; D];
        for (j, b) in basis.iter().enumerate() {
            for (o, p) in out.iter_mut().zip(&self.points[first + j]) {
                *o += b * p;
            }
        }
        out
    }
}

/// The clamped B-spline of degree at most `degree` through the first and last of `samples`
/// (at least two, at the increasing parameters `t` from 0 to 1), with the fewest knots found
/// by insertion for which `deviation(i, s, point)` (how far the fitted `point` at `s`, between
/// samples `i` and `i + 1`, is from the target) stays within `tol` at each sample and at
/// `checks_per_step - 1` points between each two. `None` where no fit gets there: too few
/// samples to place the knots among, or a system not solved to finite values.
///
/// ```
/// use bspline::fit::fit_samples;
/// // A quarter circle sampled at 50 points: a cubic within 1e-6 of the circle.
/// let t: Vec<f64> = (0..50).map(|i| i as f64 / 49.0).collect();
/// let at = |s: f64| {
///     let a = std::f64::consts::FRAC_PI_2 * s;
///     [a.cos(), a.sin()]
/// };
/// let samples: Vec<[f64; 2]> = t.iter().map(|&s| at(s)).collect();
/// let deviation = |_: usize, s: f64, p: [f64; 2]| {
///     let q = at(s);
///     (p[0] - q[0]).hypot(p[1] - q[1])
/// };
/// let fit = fit_samples(&samples, &t, 3, 1e-6, 8, &deviation).unwrap();
/// assert!(fit.error <= 1e-6 && fit.points.len() < 20);
/// ```
pub fn fit_samples<const D: usize>(
    samples: &[[f64; D]],
    t: &[f64],
    degree: usize,
    tol: f64,
    checks_per_step: usize,
    deviation: &dyn Fn(usize, f64, [f64; D]) -> f64,
) -> Option<Fit<D>> {
    if samples.len() < 2 || samples.len() != t.len() {
        return None;
    }
    let degree = degree.clamp(1, samples.len() - 1);
    let mut interior: Vec<f64> = Vec::new();
    for _ in 0..MAX_ROUNDS {
        let knots = clamped(degree, &interior);
        let points = least_squares(samples, t, degree, &knots)?;
        let mut fit = Fit {
            degree,
            knots,
            points,
            error: 0.0,
        };
        let span_errors = measure(&fit, t, checks_per_step.max(1), deviation);
        fit.error = span_errors.iter().map(|e| e.1).fold(0.0, f64::max);
        if fit.error <= tol {
            return Some(fit);
        }
        // A knot at the middle sample parameter of every span that strays (each span keeps
        // samples inside, so the least-squares system keeps full rank).
        let before = interior.len();
        for &(span_lo, e, worst) in &span_errors {
            if e <= tol {
                continue;
            }
            let span_hi = next_knot(&interior, span_lo);
            let inside: Vec<f64> = t
                .iter()
                .copied()
                .filter(|&s| s > span_lo && s < span_hi)
                .collect();
            // (Where the span holds too few samples to split them, at the worst point: the
            // least-squares system only needs samples under every basis function's support.)
            let knot = if inside.len() >= 2 {
                inside[inside.len() / 2]
            } else {
                worst
            };
            if knot - span_lo > KNOT_GAP && span_hi - knot > KNOT_GAP {
                interior.push(knot);
            }
        }
        if interior.len() == before || interior.len() + degree + 1 > samples.len() {
            return None;
        }
        interior.sort_by(f64::total_cmp);
    }
    None
}

/// The clamped knot vector on `[0, 1]` with the given interior knots.
fn clamped(degree: usize, interior: &[f64]) -> Vec<f64> {
    let mut k = vec![0.0; degree + 1];
    k.extend_from_slice(interior);
    k.extend(std::iter::repeat_n(1.0, degree + 1));
    k
}

/// The knot after `lo` (1 past the last interior one).
fn next_knot(interior: &[f64], lo: f64) -> f64 {
    interior.iter().copied().find(|&k| k > lo).unwrap_or(1.0)
}

/// The control points of the least-squares fit with the first and last fixed at the ends of
/// the samples; `None` where the system is not solved to finite values.
fn least_squares<const D: usize>(
    samples: &[[f64; D]],
    t: &[f64],
    degree: usize,
    knots: &[f64],
) -> Option<Vec<[f64; D]>> {
    let n = knots.len() - degree - 1;
    let m = samples.len();
    let (first, last) = (samples[0], samples[m - 1]);
    let mut points = vec![first; n];
    points[n - 1] = last;
    if n <= 2 {
        return Some(points);
    }
    let unknowns = n - 2;
    let mut a = DMatrix::<f64>::zeros(m - 2, unknowns);
    let mut b = DMatrix::<f64>::zeros(m - 2, D);
    for i in 1..m - 1 {
        let (f, values) = basis_at(degree, knots, t[i]);
        let mut rhs = samples[i];
        for (j, &v) in values.iter().enumerate() {
            let col = f + j;
            if col == 0 || col == n - 1 {
                let end = if col == 0 { first } else { last };
                for (r, e) in rhs.iter_mut().zip(end) {
                    *r -= v * e;
                }
            } else {
                a[(i - 1, col - 1)] = v;
            }
        }
        for (k, r) in rhs.iter().enumerate() {
            b[(i - 1, k)] = *r;
        }
    }
    // (A = QR with R square, as the samples outnumber the unknowns: the least-squares
    // solution solves R x = the first rows of Qᵀ b.)
    let qr = a.qr();
    qr.q_tr_mul(&mut b);
    let x = qr.r().solve_upper_triangular(&b.rows(0, unknowns))?;
    for j in 0..unknowns {
        let mut p = [0.0; D];
        for (k, c) in p.iter_mut().enumerate() {
            *c = x[(j, k)];
        }
        if !p.iter().all(|c| c.is_finite()) {
            return None;
        }
        points[j + 1] = p;
    }
    Some(points)
}

/// Per knot span (its lower knot), the largest deviation measured in it and the parameter
/// where it is.
fn measure<const D: usize>(
    fit: &Fit<D>,
    t: &[f64],
    checks_per_step: usize,
    deviation: &dyn Fn(usize, f64, [f64; D]) -> f64,
) -> Vec<(f64, f64, f64)> {
    let degree = fit.degree;
    let spans: Vec<f64> = fit.knots[degree..fit.knots.len() - degree - 1].to_vec();
    let mut errors: Vec<(f64, f64, f64)> = spans.iter().map(|&k| (k, 0.0, k)).collect();
    for i in 0..t.len() - 1 {
        // (The last step's end is checked too: the sample at 1.)
        let checks = if i + 2 == t.len() {
            checks_per_step + 1
        } else {
            checks_per_step
        };
        for c in 0..checks {
            let s = t[i] + (t[i + 1] - t[i]) * c as f64 / checks_per_step as f64;
            let d = deviation(i, s, fit.eval(s));
            let k = spans.iter().rposition(|&k| k <= s).unwrap_or(0);
            // (A deviation that is not a number is no fit.)
            if d.is_nan() || d > errors[k].1 {
                errors[k].1 = if d.is_nan() { f64::INFINITY } else { d };
                errors[k].2 = s;
            }
        }
    }
    errors
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Distance from `p` to the segment `a`–`b`.
    fn to_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
        let d = [b[0] - a[0], b[1] - a[1]];
        let v = [p[0] - a[0], p[1] - a[1]];
        let dd = d[0] * d[0] + d[1] * d[1];
        let s = if dd > 0.0 {
            ((v[0] * d[0] + v[1] * d[1]) / dd).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (v[0] - s * d[0]).hypot(v[1] - s * d[1])
    }

    proptest! {
        /// A random cubic Bézier, sampled: a cubic with no interior knot fits it, through both
        /// ends and within the tolerance of the curve at 64 points a step (eight times as many
        /// as it measured).
        #[test]
        fn a_fit_is_within_the_tolerance_everywhere(
            c in proptest::collection::vec((-10.0f64..10.0, -10.0f64..10.0), 4),
            samples in 5usize..60,
            tol in prop_oneof![Just(1e-9), Just(1e-6), Just(1e-3)],
        ) {
            let at = |s: f64| {
                let b = [(1.0 - s).powi(3), 3.0 * s * (1.0 - s).powi(2), 3.0 * s * s * (1.0 - s), s.powi(3)];
                let mut p = [0.0; 2];
                for (k, w) in b.iter().enumerate() {
                    p[0] += w * c[k].0;
                    p[1] += w * c[k].1;
                }
                p
            };
            let t: Vec<f64> = (0..samples).map(|i| i as f64 / (samples - 1) as f64).collect();
            let pts: Vec<[f64; 2]> = t.iter().map(|&s| at(s)).collect();
            let deviation = |_: usize, s: f64, p: [f64; 2]| {
                let q = at(s);
                (p[0] - q[0]).hypot(p[1] - q[1])
            };
            let fit = fit_samples(&pts, &t, 3, tol, 8, &deviation).unwrap();
            prop_assert_eq!(fit.points[0], pts[0]);
            prop_assert_eq!(fit.points[fit.points.len() - 1], pts[samples - 1]);
            prop_assert_eq!(fit.knots.len(), 8, "{:?}", fit.knots);
            for k in 0..=64 * (samples - 1) {
                let s = k as f64 / (64 * (samples - 1)) as f64;
                let d = deviation(0, s, fit.eval(s));
                prop_assert!(d <= tol, "{s}: {d} > {tol}");
            }
        }

        /// A zigzag polyline no cubic follows: where a fit against it is returned, its error is
        /// the largest deviation at the points it measured, and within the tolerance.
        #[test]
        fn a_fit_to_a_polyline_stays_within_it(
            ys in proptest::collection::vec(-1.0f64..1.0, 3..40),
            tol in 1e-4f64..1e-1,
        ) {
            let n = ys.len();
            let pts: Vec<[f64; 2]> = ys.iter().enumerate().map(|(i, &y)| [i as f64, y]).collect();
            let t: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
            let near = |i: usize, _: f64, p: [f64; 2]| {
                let lo = i.saturating_sub(1);
                let hi = (i + 2).min(n - 1);
                (lo..hi).map(|j| to_segment(p, pts[j], pts[j + 1])).fold(f64::INFINITY, f64::min)
            };
            if let Some(fit) = fit_samples(&pts, &t, 3, tol, 8, &near) {
                let mut worst = 0.0f64;
                for i in 0..n - 1 {
                    for c in 0..=8 {
                        let s = t[i] + (t[i + 1] - t[i]) * c as f64 / 8.0;
                        worst = worst.max(near(i, s, fit.eval(s)));
                    }
                }
                prop_assert!(worst <= tol, "{worst} > {tol}");
                prop_assert!(fit.error <= worst, "{} > {worst}", fit.error);
            }
        }
    }

    /// Two samples: the straight line, exactly; bad input: none.
    #[test]
    fn two_samples_give_the_line_and_bad_input_none() {
        let pts = [[0.0, 0.0], [1.0, 1.0]];
        let zero = |_: usize, _: f64, _: [f64; 2]| 0.0;
        let fit = fit_samples(&pts, &[0.0, 1.0], 3, 1e-9, 8, &zero).unwrap();
        assert_eq!((fit.degree, fit.error), (1, 0.0));
        assert_eq!(fit.eval(0.5), [0.5, 0.5]);
        assert_eq!(fit_samples(&pts[..1], &[0.0], 3, 1e-9, 8, &zero), None);
        assert_eq!(fit_samples(&pts, &[0.0], 3, 1e-9, 8, &zero), None);
        let nan = |_: usize, _: f64, _: [f64; 2]| f64::NAN;
        let three = [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]];
        assert_eq!(
            fit_samples(&three, &[0.0, 0.5, 1.0], 3, 1e-9, 8, &nan),
            None
        );
    }
}
