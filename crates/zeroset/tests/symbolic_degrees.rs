//! §3: the functions vanish exactly on matched foot points and have the degrees of §3.4.
#![allow(clippy::unwrap_used)]
mod common;
use bspline::tensor::TensorBSpline;
use common::*;
use zeroset::{bisector_function, Method};

/// Whether F restricted to the line (t, r) = (a + s u, b + s v), s ∈ [0, 1], has degree exactly
/// `d` (an independent check of the degree in (t, r) jointly): with d + 2 equally spaced samples,
/// the (d+1)-th finite difference vanishes to rounding and the d-th does not.
fn has_total_degree(f: &TensorBSpline, d: usize) -> bool {
    let (a, b, u, v) = (0.13, 0.07, 0.71, 0.83);
    let n = d + 1;
    let mut vals: Vec<f64> = (0..=n)
        .map(|i| f.eval(a + i as f64 / n as f64 * u, b + i as f64 / n as f64 * v))
        .collect();
    let scale = vals.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for _ in 0..d {
        vals = vals.windows(2).map(|w| w[1] - w[0]).collect();
    }
    let dth = vals[0].abs();
    let next = (vals[1] - vals[0]).abs();
    next <= 1e-9 * scale && dth >= 1e-8 * scale
}

#[test]
fn degrees_of_section_3_4() {
    for m in 1..=4usize {
        // Generic points (leading coefficients not parallel, which would cancel top terms).
        let a = [[0.0, 0.0], [1.0, 2.0], [2.3, -1.0], [3.0, 1.4], [4.2, 0.3]];
        let b = [[0.1, 3.0], [1.5, 2.2], [1.7, 4.1], [3.2, 3.5], [3.9, 5.0]];
        let (p1, p2) = (a[..=m].to_vec(), b[..=m].to_vec());
        let (c1, c2) = (bez(&p1), bez(&p2));
        let f1 = bisector_function(&c1, &c2, Method::F1).unwrap();
        let f2 = bisector_function(&c1, &c2, Method::F2).unwrap();
        let f3 = bisector_function(&c1, &c2, Method::F3).unwrap();
        assert!(has_total_degree(&f1, 6 * m - 4), "F1, m = {m}");
        assert!(has_total_degree(&f2, 6 * m - 4), "F2, m = {m}");
        assert!(has_total_degree(&f3, 4 * m - 2), "F3, m = {m}");
        // Tensor degrees are lower than the total degree in each variable.
        assert_eq!((f1.deg_t(), f1.deg_r()), (4 * m - 2, 4 * m - 2));
        assert_eq!((f2.deg_t(), f2.deg_r()), (4 * m - 2, 4 * m - 2));
        assert_eq!((f3.deg_t(), f3.deg_r()), (3 * m - 1, 3 * m - 1));
    }
}

/// F3 against its defining formula (Eq. 13 times the denominator), F1 against Eq. 3 and F2
/// against its normal form, at random points, for polynomial and rational curves.
#[test]
fn functions_match_their_formulas() {
    let w = [1.0, 0.6, 1.7, 0.9];
    let c1 = bspline::Rational::new(
        bspline::BSpline::bezier(2, vec![0., 0., 1., 2., 2., -1., 3., 1.]).unwrap(),
        Some(&w),
    )
    .unwrap();
    let c2 = bsp(
        3,
        &[[0.0, 3.0], [1.0, 2.0], [2.0, 4.0], [3.0, 3.5], [4.0, 3.0]],
    );
    for (a, b) in [(&c1, &c2), (&c2, &c1)] {
        let fs = [Method::F1, Method::F2, Method::F3].map(|m| bisector_function(a, b, m).unwrap());
        for k in 0..20 {
            let t = (k as f64 * 0.618).fract();
            let r = (k as f64 * 0.414 + 0.1).fract();
            let (p1, d1) = pd(a, t);
            let (p2, d2) = pd(b, r);
            let d = [p1[0] - p2[0], p1[1] - p2[1]];
            let dot = |x: [f64; 2], y: [f64; 2]| x[0] * y[0] + x[1] * y[1];
            let cross = |x: [f64; 2], y: [f64; 2]| x[0] * y[1] - x[1] * y[0];
            let e1 = dot(d1, d1) * dot(d, d2).powi(2) - dot(d2, d2) * dot(d, d1).powi(2);
            let e2 = dot(d2, d2) * cross(d, d1).powi(2) - dot(d1, d1) * cross(d, d2).powi(2);
            let a1 = dot(p1, d1);
            let a2 = dot(p2, d2);
            let e3 = a1 * cross(d, d2)
                - a2 * cross(d, d1)
                - 0.5 * cross(d1, d2) * (dot(p1, p1) - dot(p2, p2));
            // The tensors differ from the formulas by positive weight factors (none for polynomials);
            // compare signs and, where both are polynomial, values.
            for (f, e) in fs.iter().zip([e1, e2, e3]) {
                let v = f.eval(t, r);
                let tol = 1e-9 * f.max_abs_coef();
                if v.abs() > tol && e.abs() > 1e-9 {
                    assert_eq!(v > 0.0, e > 0.0, "t {t} r {r} v {v} e {e}");
                }
            }
            if a == &c2 {
                continue;
            }
        }
    }
    // Polynomial pair: equal values.
    let c3 = bez(&[[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 1.0]]);
    let f3 = bisector_function(&c3, &c2, Method::F3).unwrap();
    let (p1, d1) = pd(&c3, 0.3);
    let (p2, d2) = pd(&c2, 0.6);
    let d = [p1[0] - p2[0], p1[1] - p2[1]];
    let dot = |x: [f64; 2], y: [f64; 2]| x[0] * y[0] + x[1] * y[1];
    let cross = |x: [f64; 2], y: [f64; 2]| x[0] * y[1] - x[1] * y[0];
    let e3 = dot(p1, d1) * cross(d, d2)
        - dot(p2, d2) * cross(d, d1)
        - 0.5 * cross(d1, d2) * (dot(p1, p1) - dot(p2, p2));
    testkit::assert_near!(f3.eval(0.3, 0.6), e3, 1e-10 * f3.max_abs_coef());
}
