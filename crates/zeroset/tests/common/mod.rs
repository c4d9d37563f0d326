//! Helpers shared by the integration tests: functions with known zero sets, curves, oracles.
#![allow(dead_code, unreachable_pub)]

use bspline::tensor::TensorBSpline;
use bspline::{BSpline, Rational};

/// The linear function `a + b u` on `[d0, d1]`.
pub fn lin(a: f64, b: f64, d0: f64, d1: f64) -> BSpline {
    let mut f = BSpline::bezier(1, vec![a + b * d0, a + b * d1]).unwrap();
    f = f.reparam(d0, d1).unwrap();
    f
}

/// The constant `c` on `[d0, d1]`.
pub fn cst(c: f64, d0: f64, d1: f64) -> BSpline {
    BSpline::constant(&[c], 0, d0, d1).unwrap()
}

/// `a t + b r + c` on the box as a tensor.
pub fn plane(a: f64, b: f64, c: f64, bx: [f64; 4]) -> TensorBSpline {
    TensorBSpline::sum_of_outer(&[
        (lin(0.0, a, bx[0], bx[1]), cst(1.0, bx[2], bx[3])),
        (cst(1.0, bx[0], bx[1]), lin(c, b, bx[2], bx[3])),
    ])
    .unwrap()
}

/// `(t − cx)² + (r − cy)² − ρ²` on the box.
pub fn circle(cx: f64, cy: f64, rho: f64, bx: [f64; 4]) -> TensorBSpline {
    let lt = lin(-cx, 1.0, bx[0], bx[1]);
    let lr = lin(-cy, 1.0, bx[2], bx[3]);
    TensorBSpline::sum_of_outer(&[
        (lt.mul(&lt).unwrap(), cst(1.0, bx[2], bx[3])),
        (cst(1.0, bx[0], bx[1]), lr.mul(&lr).unwrap()),
        (cst(-rho * rho, bx[0], bx[1]), cst(1.0, bx[2], bx[3])),
    ])
    .unwrap()
}

/// A polynomial Bézier curve from points.
pub fn bez(pts: &[[f64; 2]]) -> Rational {
    let c: Vec<f64> = pts.iter().flat_map(|p| [p[0], p[1]]).collect();
    Rational::polynomial(&BSpline::bezier(2, c).unwrap())
}

/// A clamped uniform B-spline curve of degree `p` on `[0, 1]`.
pub fn bsp(p: usize, pts: &[[f64; 2]]) -> Rational {
    let c: Vec<f64> = pts.iter().flat_map(|q| [q[0], q[1]]).collect();
    Rational::polynomial(&BSpline::clamped_uniform(p, 2, c).unwrap())
}

/// Point and tangent of a curve.
pub fn pd(c: &Rational, u: f64) -> ([f64; 2], [f64; 2]) {
    let mut o = [0.0; 4];
    c.eval_derivs(u, 1, &mut o);
    ([o[0], o[1]], [o[2], o[3]])
}

/// Distance from `q` to a polyline.
pub fn dist_to_polyline(q: [f64; 2], pts: &[[f64; 2]]) -> f64 {
    let mut best = f64::INFINITY;
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let l2 = dx * dx + dy * dy;
        let s = if l2 == 0.0 {
            0.0
        } else {
            (((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / l2).clamp(0.0, 1.0)
        };
        best = best.min((q[0] - a[0] - s * dx).hypot(q[1] - a[1] - s * dy));
    }
    if pts.len() == 1 {
        best = (q[0] - pts[0][0]).hypot(q[1] - pts[0][1]);
    }
    best
}

/// Points from a flat list of coordinates.
pub fn pts(v: &[f64]) -> Vec<[f64; 2]> {
    v.chunks(2).map(|c| [c[0], c[1]]).collect()
}

/// `n` random control points in the square [-1, 1]² (drawn as a flat list of coordinates,
/// see [`pts`]).
pub fn control_points(n: usize) -> impl proptest::strategy::Strategy<Value = Vec<[f64; 2]>> {
    use proptest::strategy::Strategy;
    proptest::collection::vec(-1.0..1.0f64, 2 * n).prop_map(|v| pts(&v))
}

/// The points `p` moved by `by`.
pub fn shifted(p: &[[f64; 2]], by: [f64; 2]) -> Vec<[f64; 2]> {
    p.iter().map(|q| [q[0] + by[0], q[1] + by[1]]).collect()
}

/// Regular curves only (the paper's assumption): no collapsed control-polygon legs.
pub fn regular(p: &[[f64; 2]]) -> bool {
    p.windows(2)
        .all(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]) > 0.05)
}

/// `c` as the spline curve the bisector entries take.
pub fn as_curve(c: &Rational) -> curve::SplineCurve {
    curve::SplineCurve::new(c.clone()).expect("a planar curve")
}
