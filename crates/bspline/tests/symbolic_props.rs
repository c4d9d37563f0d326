//! Rational evaluation and the symbolic numerators against pointwise formulas.
#![allow(clippy::unwrap_used)]

mod common;
use bspline::{symbolic, Rational};
use common::*;
use proptest::prelude::*;

/// A random planar curve, rational or not, with degree 2..=5.
fn curve() -> impl Strategy<Value = Rational> {
    (
        spline(5, 12, 2),
        any::<bool>(),
        prop::collection::vec(0.2f64..5.0, 12),
    )
        .prop_filter_map("degree ≥ 2", |(pts, rational, w)| {
            if pts.degree() < 2 {
                return None;
            }
            let w = rational.then(|| w[..pts.n_ctrl()].to_vec());
            Some(Rational::new(pts, w.as_deref()).unwrap())
        })
}

/// Value, first and second derivative of the curve at `u`.
fn derivs(c: &Rational, u: f64) -> [[f64; 2]; 3] {
    let mut o = [0.0; 6];
    c.eval_derivs(u, 2, &mut o);
    [[o[0], o[1]], [o[2], o[3]], [o[4], o[5]]]
}

/// Interior sample parameters away from the knots (where derivatives jump).
fn interior_params(c: &Rational) -> Vec<f64> {
    let bp = c.homogeneous().breakpoints();
    bp.windows(2)
        .flat_map(|w| [0.25, 0.5, 0.75].map(|s| w[0] + (w[1] - w[0]) * s))
        .collect()
}

fn weight(c: &Rational, u: f64) -> f64 {
    c.homogeneous().eval(u)[2]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    #[test]
    fn rational_derivatives_match_finite_differences(c in curve()) {
        let bp = c.homogeneous().breakpoints();
        for w in bp.windows(2) {
            let h = (w[1] - w[0]) * 1e-3;
            let u = 0.5 * (w[0] + w[1]);
            let d = derivs(&c, u);
            let p = |s: f64| c.point(u + s * h);
            for k in 0..2 {
                let fd1 = (-p(-3.0)[k] + 9.0 * p(-2.0)[k] - 45.0 * p(-1.0)[k] + 45.0 * p(1.0)[k] - 9.0 * p(2.0)[k] + p(3.0)[k]) / (60.0 * h);
                let fd2 = (2.0 * p(-3.0)[k] - 27.0 * p(-2.0)[k] + 270.0 * p(-1.0)[k] - 490.0 * p(0.0)[k] + 270.0 * p(1.0)[k] - 27.0 * p(2.0)[k] + 2.0 * p(3.0)[k]) / (180.0 * h * h);
                let s1 = d[1][0].abs().max(d[1][1].abs()).max(1.0);
                let s2 = d[2][0].abs().max(d[2][1].abs()).max(s1 / (w[1] - w[0]));
                testkit::prop_assert_near!(d[0][k], p(0.0)[k], 1e-12 * d[0][k].abs().max(1.0));
                testkit::prop_assert_near!(d[1][k], fd1, 1e-6 * s1, "d1 {} vs {}", d[1][k], fd1);
                testkit::prop_assert_near!(d[2][k], fd2, 1e-4 * s2, "d2 {} vs {}", d[2][k], fd2);
            }
        }
    }

    #[test]
    fn rational_products_match_pointwise(a in curve(), b in curve()) {
        let (lo, hi) = a.domain();
        let b = Rational::from_homogeneous(b.homogeneous().reparam(lo, hi).unwrap()).unwrap();
        let dot = a.dot(&b).unwrap();
        let cross = a.cross(&b).unwrap();
        let sx = Rational::from_homogeneous(a.homogeneous().map_points(2, |h, o| { o[0] = h[0]; o[1] = h[2]; })).unwrap();
        let scaled = sx.mul(&b).unwrap();
        for u in interior_params(&a) {
            let (p, q) = (a.point(u), b.point(u));
            let scale = p[0].hypot(p[1]).max(1.0) * q[0].hypot(q[1]).max(1.0);
            testkit::prop_assert_near!(dot.point(u)[0], p[0] * q[0] + p[1] * q[1], 1e-11 * scale);
            testkit::prop_assert_near!(cross.point(u)[0], p[0] * q[1] - p[1] * q[0], 1e-11 * scale);
            let m = scaled.point(u);
            prop_assert!((m[0] - p[0] * q[0]).abs() <= 1e-11 * scale && (m[1] - p[0] * q[1]).abs() <= 1e-11 * scale);
        }
    }

    #[test]
    fn curvature_numerator_matches_formula(c in curve()) {
        let k = symbolic::curvature_numerator(&c).unwrap();
        let expect_deg = if c.is_rational() { 3 * c.degree() - 3 } else { 2 * c.degree() - 3 };
        prop_assert_eq!(k.degree(), expect_deg);
        for u in interior_params(&c) {
            let [_, d1, d2] = derivs(&c, u);
            let cross = d1[0] * d2[1] - d1[1] * d2[0];
            let w = if c.is_rational() { weight(&c, u).powi(3) } else { 1.0 };
            let want = w * cross;
            let scale = (d1[0].hypot(d1[1]) * d2[0].hypot(d2[1]) * w).max(1e-300);
            testkit::prop_assert_near!(k.eval_scalar(u), want, 1e-10 * scale, "{} vs {}", k.eval_scalar(u), want);
        }
    }

    #[test]
    fn primitive_numerators_have_the_right_sign(c in curve(), q in prop::array::uniform2(-10.0f64..10.0), ang in 0.0f64..6.3) {
        let v = [ang.cos(), ang.sin()];
        let td = symbolic::tangent_dot(&c, v).unwrap();
        let tf = symbolic::tangency_from(&c, q).unwrap();
        let od = symbolic::offset_dot(&c, q, v).unwrap();
        for u in interior_params(&c) {
            let [p, d1, _] = derivs(&c, u);
            let w = weight(&c, u);
            // Each numerator equals the geometric quantity times a known positive power of w.
            let (wd, wt, wo) = if c.is_rational() { (w * w, w * w, w) } else { (1.0, 1.0, 1.0) };
            let want_td = (d1[0] * v[0] + d1[1] * v[1]) * wd;
            let want_tf = ((p[0] - q[0]) * d1[1] - (p[1] - q[1]) * d1[0]) * wt;
            let want_od = ((p[0] - q[0]) * v[0] + (p[1] - q[1]) * v[1]) * wo;
            let sd = d1[0].hypot(d1[1]) * wd;
            let sp = (p[0] - q[0]).hypot(p[1] - q[1]).max(1.0);
            testkit::prop_assert_near!(td.eval_scalar(u), want_td, 1e-10 * sd.max(1e-300));
            testkit::prop_assert_near!(tf.eval_scalar(u), want_tf, 1e-10 * (sd * sp).max(1e-300));
            testkit::prop_assert_near!(od.eval_scalar(u), want_od, 1e-10 * (sp * wo));
        }
    }
}

#[test]
fn bad_weights_are_rejected() {
    let pts = bspline::BSpline::bezier(2, vec![0., 0., 1., 1., 2., 0.]).unwrap();
    assert!(matches!(
        Rational::new(pts.clone(), Some(&[1.0, 0.0, 1.0])),
        Err(bspline::Error::NonPositiveWeight { index: 1, .. })
    ));
    assert!(matches!(
        Rational::new(pts.clone(), Some(&[1.0, 1.0])),
        Err(bspline::Error::CountMismatch { .. })
    ));
    assert!(matches!(
        Rational::new(pts, Some(&[1.0, f64::NAN, 1.0])),
        Err(bspline::Error::NotFinite {
            what: "weights",
            index: 1,
            ..
        })
    ));
}
