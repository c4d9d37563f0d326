//! The exact rational shapes against their analytic definitions.
#![allow(clippy::unwrap_used)]

use bspline::shapes::{
    circle_angle, circle_param, convexities, ellipse, elliptic_lemniscate, limacon,
};
use proptest::prelude::*;
use std::f64::consts::TAU;

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn angle_and_parameter_are_inverse(u in 0.0f64..4.0) {
        let phi = circle_angle(u);
        prop_assert!((0.0..TAU).contains(&phi));
        prop_assert!((circle_param(phi) - u).abs() < 1e-12 || (u > 4.0 - 1e-12 && circle_param(phi) < 1e-12));
    }

    #[test]
    fn polar_shapes_match_their_equations(
        u in 0.0f64..4.0,
        a in 1.0f64..5.0, bfrac in 0.0f64..0.99,
        p in 0.5f64..5.0, eps in 0.01f64..0.95, m in 2usize..9,
    ) {
        let phi = circle_angle(u);
        let lim = limacon(a, a * bfrac).unwrap();
        let r = a + a * bfrac * phi.cos();
        let q = lim.point(u);
        prop_assert!((q[0] - r * phi.cos()).abs() < 1e-12 * a && (q[1] - r * phi.sin()).abs() < 1e-12 * a);
        let cv = convexities(p, eps, m).unwrap();
        prop_assert_eq!(cv.degree(), 2 * m);
        let r = p / (1.0 + eps * (m as f64 * phi).cos());
        let q = cv.point(u);
        prop_assert!((q[0] - r * phi.cos()).abs() < 1e-11 * r && (q[1] - r * phi.sin()).abs() < 1e-11 * r,
            "{:?} vs {}", q, r);
        // The lemniscate's point of parameter u lies at tan φ = (a/b) tan ψ, ψ = circle_angle(u).
        let lem = elliptic_lemniscate(a, p).unwrap();
        prop_assert_eq!(lem.degree(), 4);
        let (sl, cl) = phi.sin_cos();
        let phl = (sl / p).atan2(cl / a);
        let r = (a * a * phl.cos().powi(2) + p * p * phl.sin().powi(2)).sqrt();
        let q = lem.point(u);
        prop_assert!((q[0] - r * phl.cos()).abs() < 1e-12 * a.max(p) && (q[1] - r * phl.sin()).abs() < 1e-12 * a.max(p),
            "{:?} vs {}", q, r);
        let el = ellipse([1.0, -2.0], a, p).unwrap();
        let q = el.point(u);
        prop_assert!((q[0] - 1.0 - a * phi.cos()).abs() < 1e-12 * a && (q[1] + 2.0 - p * phi.sin()).abs() < 1e-12 * a.max(p));
    }
}

#[test]
fn shapes_are_closed_counterclockwise_and_validated() {
    for c in [
        limacon(4.0, 2.5).unwrap(),
        convexities(3.0, 0.5, 3).unwrap(),
        ellipse([0.0; 2], 2.0, 1.0).unwrap(),
        elliptic_lemniscate(6.0, 3.0).unwrap(),
        elliptic_lemniscate(1.0, 20.0).unwrap(),
    ] {
        let (p0, p1) = (c.point(0.0), c.point(4.0));
        assert!((p0[0] - p1[0]).abs() < 1e-14 && (p0[1] - p1[1]).abs() < 1e-14);
        // Counterclockwise: positive signed area (shoelace on a dense polygon).
        let n = 400;
        let pts: Vec<_> = (0..n).map(|i| c.point(4.0 * i as f64 / n as f64)).collect();
        let area: f64 = (0..n)
            .map(|i| {
                let (a, b) = (&pts[i], &pts[(i + 1) % n]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum();
        assert!(area > 0.0);
    }
    assert!(convexities(3.0, 1.5, 3).is_err());
    assert!(ellipse([0.0; 2], -1.0, 1.0).is_err());
    assert!(elliptic_lemniscate(1.0, 0.0).is_err());
    assert!(elliptic_lemniscate(f64::NAN, 1.0).is_err());
}
