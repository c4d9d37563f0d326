//! Each edge as one cubic B-spline of the axis point and the radius, `(x, y, r)`: fitted by
//! least squares ([`bspline::fit`]) to the edge's vertices, which lie on the axis, with its
//! ends fixed at the edge's nodes so that fitted edges meet where the edges do, within the
//! tolerance of the edge's polyline, measured at every vertex and at points between them.

use bspline::fit::fit_samples;
use bspline::knots::basis_at;
use serde::{Deserialize, Serialize};

/// The degree of the fitted curves (lower for edges of fewer vertices).
const DEGREE: usize = 3;

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
    // (How far a fitted point between vertices `i` and `i + 1` is from the polyline there:
    // that step and its neighbours.)
    let deviation = |i: usize, _: f64, q: [f64; 3]| {
        let lo = i.saturating_sub(1);
        let hi = (i + 2).min(data.len() - 1);
        (lo..hi)
            .map(|j| to_segment(q, data[j], data[j + 1]))
            .fold(f64::INFINITY, f64::min)
    };
    match fit_samples(&data, &t, DEGREE, tol, CHECKS_PER_STEP, &deviation) {
        Some(fit) => EdgeSpline {
            degree: fit.degree,
            knots: fit.knots,
            points: fit.points.iter().map(|p| [p[0], p[1]]).collect(),
            radius_points: fit.points.iter().map(|p| p[2]).collect(),
            error: fit.error,
        },
        // The polyline itself, as a B-spline of degree 1: always within the tolerance.
        None => polyline(&data, &t),
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
                testkit::assert_near!(p[0].hypot(p[1]), 2.0, tol, "{s}: {p:?}");
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
