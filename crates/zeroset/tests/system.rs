//! Square systems: common zeros of two bivariate functions.
#![allow(clippy::unwrap_used)]
mod common;
use common::*;
use proptest::prelude::*;
use zeroset::{solve_system, SystemOptions};

const UNIT: [f64; 4] = [0.0, 1.0, 0.0, 1.0];

#[test]
fn two_circles_meet_twice() {
    let f = circle(0.4, 0.5, 0.25, UNIT);
    let g = circle(0.6, 0.5, 0.25, UNIT);
    let s = solve_system(&f, &g, &SystemOptions::default()).unwrap();
    assert_eq!(s.len(), 2, "{s:?}");
    let h = (0.25f64 * 0.25 - 0.01).sqrt();
    for (x, y) in s.iter().zip([0.5 - h, 0.5 + h]) {
        assert!(x.certified);
        assert!(
            (x.t - 0.5).abs() < 1e-12 && (x.r - y).abs() < 1e-12,
            "{x:?}"
        );
    }
}

#[test]
fn no_solution_when_disjoint() {
    let f = circle(0.2, 0.2, 0.1, UNIT);
    let g = circle(0.8, 0.8, 0.1, UNIT);
    assert!(solve_system(&f, &g, &SystemOptions::default())
        .unwrap()
        .is_empty());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Two random lines: exactly their intersection when it is inside, reported once.
    #[test]
    fn line_pairs(a in -1.0..1.0f64, b in -1.0..1.0f64, c in -1.0..1.0f64, d in -1.0..1.0f64, e in -1.0..1.0f64, g in -1.0..1.0f64) {
        let det = a * e - b * d;
        prop_assume!(det.abs() > 0.05);
        let f1 = plane(a, b, c, UNIT);
        let f2 = plane(d, e, g, UNIT);
        let t = (-c * e + b * g) / det;
        let r = (-a * g + c * d) / det;
        let s = solve_system(&f1, &f2, &SystemOptions::default()).unwrap();
        let inside = (0.001..0.999).contains(&t) && (0.001..0.999).contains(&r);
        if inside {
            prop_assert_eq!(s.len(), 1);
            prop_assert!(s[0].certified);
            prop_assert!((s[0].t - t).abs() < 1e-10 && (s[0].r - r).abs() < 1e-10);
        } else if !(-0.001..1.001).contains(&t) || !(-0.001..1.001).contains(&r) {
            prop_assert!(s.is_empty());
        }
    }
}
