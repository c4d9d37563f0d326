//! Regularity proofs (`symbolic::singular_point`, `roots::prove_positive`) against curves with
//! known cusps and against dense sampling of the speed.
#![allow(clippy::unwrap_used)]

mod common;
use bspline::roots::{prove_positive, RootOptions};
use bspline::{symbolic, BSpline, Rational};
use common::*;
use proptest::prelude::*;

/// `(g², g³)` with `g(s) = s − r` on `[0, 1]`, rotated, scaled and moved, optionally with a
/// positive weight function: a curve with exactly one cusp, at `s = r`.
fn cusp_curve(r: f64, angle: f64, scale: f64, shift: [f64; 2], w: Option<[f64; 3]>) -> Rational {
    let g = BSpline::bezier(1, vec![-r, 1.0 - r]).unwrap();
    let g2 = g.mul(&g).unwrap();
    let g3 = g2.mul(&g).unwrap();
    let x = g2.elevate(1);
    let (c, s) = (angle.cos() * scale, angle.sin() * scale);
    let coefs: Vec<f64> = x
        .coefs()
        .iter()
        .zip(g3.coefs())
        .flat_map(|(&a, &b)| [c * a - s * b + shift[0], s * a + c * b + shift[1]])
        .collect();
    let pts = BSpline::bezier(2, coefs).unwrap();
    match w {
        None => Rational::polynomial(&pts),
        Some(w) => {
            // The same curve with a weight function w(s) (a quadratic raised to degree 3).
            let wq = BSpline::bezier(1, w.to_vec()).unwrap();
            // Homogeneous (w x, w y, w), exactly: the product and the weight raised to it.
            let wx = wq.mul(&pts).unwrap();
            let h = BSpline::stack(&[&wx.component(0).unwrap(), &wx.component(1).unwrap(), &wq])
                .unwrap();
            Rational::from_homogeneous(h).unwrap()
        }
    }
}

fn speed(c: &Rational, u: f64) -> f64 {
    let mut o = [0.0; 4];
    c.eval_derivs(u, 1, &mut o);
    o[2].hypot(o[3])
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    /// A cusp is always found, where it is, for polynomial and rational forms.
    #[test]
    fn cusps_are_found(r in 0.05f64..0.95, angle in 0.0f64..6.3, scale in 0.01f64..100.0,
                       sx in -10.0f64..10.0, sy in -10.0f64..10.0, rational in any::<bool>(),
                       w in (0.2f64..5.0, 0.2f64..5.0, 0.2f64..5.0)) {
        let c = cusp_curve(r, angle, scale, [sx, sy], rational.then_some([w.0, w.1, w.2]));
        let u = symbolic::singular_point(&c, 1e-12).unwrap();
        prop_assert!(u.is_some_and(|u| (u - r).abs() < 1e-5), "cusp at {r}, reported {u:?}");
    }

    /// A cusp at an end of the domain is reported at that end.
    #[test]
    fn cusps_at_the_ends(at_start in any::<bool>(), angle in 0.0f64..6.3, scale in 0.01f64..100.0) {
        let r = if at_start { 0.0 } else { 1.0 };
        let c = cusp_curve(r, angle, scale, [1.0, -2.0], None);
        prop_assert_eq!(symbolic::singular_point(&c, 1e-12).unwrap(), Some(r));
    }

    /// On random curves a proof of regularity is never contradicted by sampling (it cannot
    /// be: the test guards the implementation), and a reported singular point is a place where
    /// the speed really is within rounding of zero.
    #[test]
    fn regular_curves_are_proven_regular(pts in spline(5, 12, 2), rational in any::<bool>(),
                                         w in prop::collection::vec(0.2f64..5.0, 12)) {
        prop_assume!(pts.degree() >= 1);
        let w = rational.then(|| w[..pts.n_ctrl()].to_vec());
        let c = Rational::new(pts, w.as_deref()).unwrap();
        let (a, b) = c.domain();
        let max_speed = (0..=400).map(|i| speed(&c, a + (b - a) * i as f64 / 400.0)).fold(0.0, f64::max);
        match symbolic::singular_point(&c, 1e-12).unwrap() {
            None => {
                let min = (0..=4000).map(|i| speed(&c, a + (b - a) * i as f64 / 4000.0)).fold(f64::INFINITY, f64::min);
                prop_assert!(min > 0.0);
            }
            Some(u) => {
                // Either side of u (the speed may jump at a knot).
                let h = 1e-9 * (b - a);
                let s = speed(&c, (u - h).max(a)).min(speed(&c, (u + h).min(b)));
                prop_assert!(s <= 1e-6 * max_speed, "false singular point {u}: speed {s} of {max_speed}");
            }
        }
    }

    /// Positivity of a random spline agrees with dense sampling: a proof means no sample is
    /// ≤ 0; a failure is reported near a sample within rounding of zero or below it.
    #[test]
    fn positivity_matches_sampling(f in spline(6, 14, 1), lift in -1.0f64..3.0) {
        let shift = lift * f.max_abs_coef();
        let g = f.add(&BSpline::constant(&[shift], f.degree(), f.domain().0, f.domain().1).unwrap()).unwrap();
        let (a, b) = g.domain();
        let samples: Vec<f64> = (0..=2000).map(|i| g.eval_scalar(a + (b - a) * i as f64 / 2000.0)).collect();
        let min = samples.iter().copied().fold(f64::INFINITY, f64::min);
        match prove_positive(&g, a, b, &RootOptions::default()).unwrap() {
            None => prop_assert!(min > 0.0, "proven positive but a sample is {min}"),
            Some(u) => {
                prop_assert!((a..=b).contains(&u));
                // Not proven: somewhere the function comes within rounding of zero or below.
                prop_assert!(min <= 1e-9 * g.max_abs_coef() || g.eval_scalar(u) <= 1e-9 * g.max_abs_coef(),
                    "not proven positive at {u}, yet min sample {min}");
            }
        }
    }
}
