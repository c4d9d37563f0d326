//! The piecewise Bézier form against de Boor's evaluation of the B-spline it came from: values
//! and derivatives (every degree of the fixed-size paths and the general one), Horner's value
//! and slope, restrictions to sub-intervals.
#![allow(clippy::unwrap_used)]

use bspline::{BSpline, Piecewise, ValueSlope};
use proptest::prelude::*;

fn spline() -> BSpline {
    let knots = vec![0., 0., 0., 0., 0.3, 0.5, 0.5, 0.8, 1., 1., 1., 1.];
    let coefs: Vec<f64> = (0..16).map(|i| ((i as f64) * 1.7).sin() * 2.0).collect();
    BSpline::new(3, knots, 2, coefs).unwrap()
}

/// Value and three derivatives of the pieces against de Boor's, at `n + 1` samples of
/// [0, 1], each within `tol · (1 + |value|)`.
fn assert_derivs_match(f: &BSpline, n: usize, tol: f64) {
    let pw = Piecewise::from_bspline(f);
    let len = 4 * f.dim();
    for i in 0..=n {
        let u = i as f64 / n as f64;
        let (mut a, mut b) = ([0.0; 40], [0.0; 40]);
        f.eval_derivs(u, 3, &mut a[..len]);
        pw.eval_derivs(u, 3, &mut b[..len]);
        for j in 0..len {
            testkit::assert_near!(
                a[j],
                b[j],
                tol * (1.0 + a[j].abs()),
                "degree {} u {u} j {j}: {a:?} {b:?}",
                f.degree()
            );
        }
    }
}

proptest! {
    /// Value and slope of random splines (degrees 1–12, dimensions 1 and 2, subdivided)
    /// against de Boor's evaluation, anywhere in every piece.
    #[test]
    fn value_slope_matches_bspline(
        deg in 1usize..=12,
        dim in 1usize..=2,
        coefs in proptest::collection::vec(-3.0f64..3.0, 60),
        fine in 1usize..=8,
        xs in proptest::collection::vec(0.0f64..=1.0, 20),
    ) {
        let n = (coefs.len() / dim).min(deg + 1 + 5);
        let f = BSpline::clamped_uniform(deg, dim, coefs[..n * dim].to_vec()).unwrap();
        let pw = Piecewise::from_bspline(&f).subdivided(fine);
        let vs = ValueSlope::new(&pw, &pw.derivative()).unwrap();
        for &x in &xs {
            let i = pw.piece_at(x);
            let (a, b) = pw.piece_span(i);
            let (v, g) = vs.eval(i, (x - a) / (b - a));
            let mut want = [0.0; 4];
            f.eval_derivs(x, 1, &mut want[..2 * dim]);
            for c in 0..dim {
                let (wv, wg) = (want[c], want[dim + c]);
                testkit::prop_assert_near!(v[c], wv, 1e-11 * (1.0 + wv.abs()), "value {c} at {x}: {} vs {wv}", v[c]);
                testkit::prop_assert_near!(g[c], wg, 1e-9 * (1.0 + wg.abs()), "slope {c} at {x}: {} vs {wg}", g[c]);
            }
        }
    }
}

#[test]
fn derivatives_match_bspline() {
    assert_derivs_match(&spline(), 50, 1e-11);
}

#[test]
fn derivatives_match_bspline_in_dimension_3() {
    // Every instance of the fixed-size path (degrees 1–7) and the general one (8).
    for p in 1..=8usize {
        let n = p + 4;
        let coefs: Vec<f64> = (0..3 * n)
            .map(|i| ((i as f64) * 0.77).cos() + 2.0)
            .collect();
        let f = BSpline::clamped_uniform(p, 3, coefs).unwrap();
        assert_derivs_match(&f, 40, 1e-9);
    }
}

#[test]
fn derivatives_match_bspline_in_higher_dimensions() {
    // Functions stacked for one evaluation (the general path, its levels off the stack past
    // dimension 3).
    for (p, dim) in [(2usize, 4usize), (4, 7), (6, 10)] {
        let n = p + 3;
        let coefs: Vec<f64> = (0..dim * n)
            .map(|i| ((i as f64) * 0.41).sin() * 3.0)
            .collect();
        let f = BSpline::clamped_uniform(p, dim, coefs).unwrap();
        assert_derivs_match(&f, 40, 1e-10);
    }
}

#[test]
fn restriction_matches_bspline() {
    let f = spline();
    let pw = Piecewise::from_bspline(&f);
    for (lo, hi) in [(0.1, 0.2), (0.25, 0.7), (0.0, 1.0), (0.5, 0.9), (0.3, 0.5)] {
        let mut got: Vec<(f64, f64, Vec<f64>)> = Vec::new();
        pw.for_each_restricted(&[1.0, -0.5], lo, hi, |_, x0, x1, c, _| {
            got.push((x0, x1, c.to_vec()));
            true
        });
        for (x0, x1, c) in got {
            // The Bernstein coefficients reproduce the function at the piece's ends.
            let g = |u: f64| {
                let v = f.eval(u);
                v[0] - 0.5 * v[1]
            };
            let n = c.len() - 1;
            testkit::assert_near!(c[0], g(x0), 1e-12);
            // Evaluate the right end from the left (c[n] is the left limit at x1).
            let eps = 1e-9;
            testkit::assert_near!(c[n], g(x1 - eps), 1e-7, "{lo} {hi} {x1}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// A Bézier piece evaluates to its end coefficients exactly at its ends, whatever their
    /// magnitudes beside each other (weights 1e82 and 1 once gave 1e82 − 1e82 = 0 at the end,
    /// and a NaN point), in every dimension and degree and by both evaluation paths.
    #[test]
    fn ends_are_the_end_coefficients(
        degree in 1usize..=9,
        dim in 1usize..=3,
        mant in proptest::collection::vec(-1.0f64..1.0, 30),
        exps in proptest::collection::vec(-120i32..120, 30),
    ) {
        let n = (degree + 1) * dim;
        let coefs: Vec<f64> = (0..n).map(|i| mant[i] * 10f64.powi(exps[i])).collect();
        let f = Piecewise::from_bspline(&BSpline::bezier(dim, coefs.clone()).unwrap());
        let mut out = vec![0.0; 4 * dim];
        f.eval_derivs(0.0, 0, &mut out);
        prop_assert_eq!(&out[..dim], &coefs[..dim]);
        f.eval_derivs(1.0, 0, &mut out);
        prop_assert_eq!(&out[..dim], &coefs[n - dim..]);
    }
}
