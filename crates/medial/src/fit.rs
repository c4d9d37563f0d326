//! Each edge as one cubic B-spline of the axis point and the radius, `(x, y, r)`: fitted by
//! least squares (faer's QR) to the edge's vertices, which lie on the axis, with its ends
//! fixed at the edge's nodes so that fitted edges meet where the edges do. Knots are added
//! in the spans where the fit strays, until it is within the tolerance of the edge's polyline,
//! measured at every vertex and at points between them.

use bspline::knots::basis_at;
use faer::linalg::solvers::SolveLstsq;
use faer::Mat;
use serde::{Deserialize, Serialize};

/// The degree of the fitted curves (lower for edges of fewer vertices).
const DEGREE: usize = 3;

/// Rounds of knot insertion before the fit is returned as it is (with its measured error).
const MAX_ROUNDS: usize = 40;

/// Knots stay this far apart (in the parameter over `[0, 1]`): closer, the least-squares
/// system loses rank.
const KNOT_GAP: f64 = 1e-9;

/// Points of the fitted curve compared with the polyline in each step between two vertices
/// (the vertices' own parameters included).
const CHECKS_PER_STEP: usize = 8;

/// An edge as a B-spline: the axis point in `points`, the radius in `radius_points`, on one
/// clamped knot vector over `[0, 1]` (proportional to the length of the edge's polyline in
/// `(x, y, r)`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EdgeSpline {
    /// The degree.
    pub degree: usize,
    /// The knots (clamped: the first and last repeated `degree + 1` times).
    pub knots: Vec<f64>,
    /// The control points of the axis.
    pub points: Vec<[f64; 2]>,
    /// The control points of the radius.
    pub radius_points: Vec<f64>,
    /// The largest distance measured in `(x, y, r)` between the curve and the edge's
    /// polyline.
    pub error: f64,
}

impl EdgeSpline {
    /// The axis point and radius at parameter `t ∈ [0, 1]`.
    pub fn eval(&self, t: f64) -> ([f64; 2], f64) {
        let (first, n) = basis_at(self.degree, &self.knots, t);
        let mut out = ([0.0; 2], 0.0);
        for (j, b) in n.iter().enumerate() {
            let p = self.points[first + j];
            out.0[0] += b * p[0];
            out.0[1] += b * p[1];
            out.1 += b * self.radius_points[first + j];
        }
        out
    }
}

/// The fit of the edge with vertices `xy` and radii `radius` (at least two) within `tol` of
/// its polyline: a cubic where knot insertion gets there, else the polyline itself.
pub(crate) fn fit_edge(xy: &[[f64; 2]], radius: &[f64], tol: f64) -> EdgeSpline {
    let data: Vec<[f64; 3]> = xy
        .iter()
        .zip(radius)
        .map(|(p, &r)| [p[0], p[1], r])
        .collect();
    let t = chord_parameters(&data);
    let degree = DEGREE.min(data.len() - 1);
    let mut interior: Vec<f64> = Vec::new();
    let mut best: Option<EdgeSpline> = None;
    for _ in 0..MAX_ROUNDS {
        let knots = clamped(degree, &interior);
        let Some(points) = least_squares(&data, &t, degree, &knots) else {
            break;
        };
        let mut fit = EdgeSpline {
            degree,
            knots,
            points: points.iter().map(|p| [p[0], p[1]]).collect(),
            radius_points: points.iter().map(|p| p[2]).collect(),
            error: 0.0,
        };
        let span_errors = measure(&fit, &data, &t);
        fit.error = span_errors.iter().map(|e| e.1).fold(0.0, f64::max);
        let done = fit.error <= tol;
        let better = best.as_ref().is_none_or(|b| fit.error < b.error);
        if better {
            best = Some(fit);
        }
        if done {
            break;
        }
        // A knot at the middle data parameter of every span that strays (each span keeps
        // data inside, so the least-squares system keeps full rank).
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
            // (Where the span holds too few data to split them, at the worst point: the
            // least-squares system only needs data under every basis function's support.)
            let knot = if inside.len() >= 2 {
                inside[inside.len() / 2]
            } else {
                worst
            };
            if knot - span_lo > KNOT_GAP && span_hi - knot > KNOT_GAP {
                interior.push(knot);
            }
        }
        if interior.len() == before || interior.len() + degree + 1 > data.len() {
            break;
        }
        interior.sort_by(f64::total_cmp);
    }
    match best {
        Some(fit) if fit.error <= tol => fit,
        // The polyline itself, as a B-spline of degree 1: always within the tolerance.
        _ => polyline(&data, &t),
    }
}

/// Parameters in `[0, 1]` proportional to the polyline's length in `(x, y, r)` (uniform where
/// it has none).
fn chord_parameters(data: &[[f64; 3]]) -> Vec<f64> {
    let mut t = vec![0.0];
    for w in data.windows(2) {
        let d = ((w[1][0] - w[0][0]).powi(2)
            + (w[1][1] - w[0][1]).powi(2)
            + (w[1][2] - w[0][2]).powi(2))
        .sqrt();
        t.push(t[t.len() - 1] + d);
    }
    let total = t[t.len() - 1];
    let n = (data.len() - 1) as f64;
    t.iter()
        .enumerate()
        .map(|(i, &s)| if total > 0.0 { s / total } else { i as f64 / n })
        .collect()
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
/// the data; `None` where the system is not solved to finite values.
fn least_squares(
    data: &[[f64; 3]],
    t: &[f64],
    degree: usize,
    knots: &[f64],
) -> Option<Vec<[f64; 3]>> {
    let n = knots.len() - degree - 1;
    let m = data.len();
    let (first, last) = (data[0], data[m - 1]);
    let mut points = vec![first; n];
    points[n - 1] = last;
    if n <= 2 {
        return Some(points);
    }
    let unknowns = n - 2;
    let rows = m - 2;
    let mut a = Mat::<f64>::zeros(rows, unknowns);
    let mut b = Mat::<f64>::zeros(rows, 3);
    for i in 1..m - 1 {
        let (f, values) = basis_at(degree, knots, t[i]);
        let mut rhs = data[i];
        for (j, &v) in values.iter().enumerate() {
            let col = f + j;
            if col == 0 || col == n - 1 {
                let end = if col == 0 { first } else { last };
                for k in 0..3 {
                    rhs[k] -= v * end[k];
                }
            } else {
                a[(i - 1, col - 1)] = v;
            }
        }
        for k in 0..3 {
            b[(i - 1, k)] = rhs[k];
        }
    }
    let x = a.qr().solve_lstsq(&b);
    for j in 0..unknowns {
        let p = [x[(j, 0)], x[(j, 1)], x[(j, 2)]];
        if !p.iter().all(|c| c.is_finite()) {
            return None;
        }
        points[j + 1] = p;
    }
    Some(points)
}

/// Per knot span (its lower knot), the largest distance between the fitted curve and the
/// polyline, at every vertex and between them, and the parameter where it is.
fn measure(fit: &EdgeSpline, data: &[[f64; 3]], t: &[f64]) -> Vec<(f64, f64, f64)> {
    let degree = fit.degree;
    let spans: Vec<f64> = fit.knots[degree..fit.knots.len() - degree - 1].to_vec();
    let mut errors: Vec<(f64, f64, f64)> = spans.iter().map(|&k| (k, 0.0, k)).collect();
    for i in 0..data.len() - 1 {
        for c in 0..CHECKS_PER_STEP {
            let s = t[i] + (t[i + 1] - t[i]) * c as f64 / CHECKS_PER_STEP as f64;
            let (p, r) = fit.eval(s);
            let q = [p[0], p[1], r];
            // The polyline near the step: it and its neighbours.
            let lo = i.saturating_sub(1);
            let hi = (i + 2).min(data.len() - 1);
            let d = (lo..hi)
                .map(|j| to_segment(q, data[j], data[j + 1]))
                .fold(f64::INFINITY, f64::min);
            let k = spans.iter().rposition(|&k| k <= s).unwrap_or(0);
            if d > errors[k].1 {
                errors[k].1 = d;
                errors[k].2 = s;
            }
        }
    }
    errors
}

/// Distance from `q` to the segment `a`–`b` in `(x, y, r)`.
fn to_segment(q: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [q[0] - a[0], q[1] - a[1], q[2] - a[2]];
    let dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let s = if dd > 0.0 {
        ((v[0] * d[0] + v[1] * d[1] + v[2] * d[2]) / dd).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let e = [v[0] - s * d[0], v[1] - s * d[1], v[2] - s * d[2]];
    (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt()
}

/// The polyline through the data as a B-spline of degree 1 (the fit where no smoother one
/// meets the tolerance: few vertices to place knots among, or no solve).
fn polyline(data: &[[f64; 3]], t: &[f64]) -> EdgeSpline {
    let mut knots = vec![0.0];
    knots.extend_from_slice(t);
    knots.push(1.0);
    EdgeSpline {
        degree: 1,
        knots,
        points: data.iter().map(|q| [q[0], q[1]]).collect(),
        radius_points: data.iter().map(|q| q[2]).collect(),
        error: 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quarter circle of radius 2 sampled at 600 points (the polyline within 2e-6 of it),
    /// the radius growing linearly: the fit is within the tolerance of the polyline (checked
    /// here at 50 points a step) with far fewer control points, passes through both ends, and
    /// is within the tolerance of the circle itself.
    #[test]
    fn a_sampled_arc_is_fitted_within_the_tolerance() {
        let n = 600;
        let xy: Vec<[f64; 2]> = (0..n)
            .map(|i| {
                let a = std::f64::consts::FRAC_PI_2 * i as f64 / (n - 1) as f64;
                [2.0 * a.cos(), 2.0 * a.sin()]
            })
            .collect();
        let radius: Vec<f64> = (0..n).map(|i| 1.0 + i as f64 / n as f64).collect();
        let tol = 1e-5;
        let fit = fit_edge(&xy, &radius, tol);
        assert!(fit.error <= tol, "{}", fit.error);
        assert!(fit.points.len() < 40, "{} control points", fit.points.len());
        assert_eq!(fit.points[0], xy[0]);
        assert_eq!(fit.points[fit.points.len() - 1], xy[n - 1]);
        let data: Vec<[f64; 3]> = xy
            .iter()
            .zip(&radius)
            .map(|(p, &r)| [p[0], p[1], r])
            .collect();
        let t = chord_parameters(&data);
        for i in 0..n - 1 {
            for c in 0..50 {
                let s = t[i] + (t[i + 1] - t[i]) * c as f64 / 50.0;
                let (p, r) = fit.eval(s);
                let d = to_segment([p[0], p[1], r], data[i], data[i + 1])
                    .min(to_segment(
                        [p[0], p[1], r],
                        data[i.saturating_sub(1)],
                        data[i],
                    ))
                    .min(to_segment(
                        [p[0], p[1], r],
                        data[i + 1],
                        data[(i + 2).min(n - 1)],
                    ));
                assert!(d <= tol, "{s}: {d}");
                assert!((p[0].hypot(p[1]) - 2.0).abs() <= tol, "{s}: {p:?}");
            }
        }
    }

    /// Two vertices: the straight line, exactly; three far off a parabola (a corner the
    /// cubic cannot follow within the tolerance): the polyline itself.
    #[test]
    fn few_vertices_give_the_polyline() {
        let fit = fit_edge(&[[0.0, 0.0], [1.0, 1.0]], &[0.5, 0.25], 1e-9);
        assert_eq!(fit.degree, 1);
        assert_eq!(fit.error, 0.0);
        assert_eq!(fit.eval(0.5), ([0.5, 0.5], 0.375));
        let xy = [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 0.0]];
        let fit = fit_edge(&xy, &[1.0; 4], 1e-6);
        assert_eq!((fit.degree, fit.error), (1, 0.0));
        for (k, p) in xy.iter().enumerate() {
            assert_eq!(fit.points[k], *p);
        }
    }
}
