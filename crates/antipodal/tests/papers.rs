//! The papers' shapes with their known antipodal counts, checked against the oracle and
//! snapshotted (rounded numbers).

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use antipodal::shapes::{Circle, Convexities, Ellipse, EllipticLemniscate, Limacon};
use antipodal::{antipodal, Antipodal, Options, PlaneCurve};
use serde::Serialize;

#[derive(Serialize)]
struct Rounded {
    pairs: Vec<(f64, f64, f64, String)>,
    inflections: Vec<f64>,
    families: usize,
    certified: bool,
}

fn round(x: f64) -> f64 {
    let r = (x * 1e6).round() / 1e6;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

fn rounded(r: &Antipodal) -> Rounded {
    Rounded {
        pairs: r
            .pairs
            .iter()
            .map(|p| {
                (
                    round(p.s),
                    round(p.t),
                    round(p.distance),
                    format!("{:?}", p.kind),
                )
            })
            .collect(),
        inflections: r.inflections.iter().map(|i| round(i.u)).collect(),
        families: r.families.len(),
        certified: r.certified,
    }
}

/// Runs the algorithm, checks the count, residuals and the oracle, returns the result.
fn check(c: &dyn PlaneCurve, count: usize) -> Antipodal {
    let r = antipodal(c, &Options::default()).unwrap();
    assert!(r.complete);
    assert_eq!(r.pairs.len(), count, "{:?}", r.pairs);
    for p in &r.pairs {
        assert!(common::residual(c, p.s, p.t) <= 1e-12);
        assert!(
            (p.distance - (antipodal::V2::from_arr(p.q) - antipodal::V2::from_arr(p.p)).norm())
                .abs()
                < 1e-12
        );
    }
    let oracle = common::antipodal_oracle(c, 900);
    assert_eq!(oracle.len(), count, "oracle disagrees: {oracle:?}");
    for (s, t) in oracle {
        assert!(r.pairs.iter().any(|p| {
            (common::same_param(c, p.s, s, 1e-9) && common::same_param(c, p.t, t, 1e-9))
                || (common::same_param(c, p.s, t, 1e-9) && common::same_param(c, p.t, s, 1e-9))
        }));
    }
    for w in r.pairs.windows(2) {
        assert!(w[0].s <= w[1].s);
    }
    r
}

#[test]
fn ellipse_has_two_pairs() {
    let r = check(&Ellipse::new(3.0, 2.0, [1.0, -2.0]).unwrap(), 2);
    assert!(r.inflections.is_empty());
    insta::assert_json_snapshot!("ellipse", rounded(&r));
}

#[test]
fn limacon_has_two_pairs() {
    // The papers place the second pair at π/2, 3π/2; those points are not antipodal.
    let r = check(&Limacon::new(4.0, 2.5).unwrap(), 2);
    assert_eq!(r.inflections.len(), 2);
    insta::assert_json_snapshot!("limacon", rounded(&r));
}

#[test]
fn elliptic_lemniscate_has_four_pairs() {
    let r = check(&EllipticLemniscate::new(6.0, 3.0).unwrap(), 4);
    insta::assert_json_snapshot!("lemniscate", rounded(&r));
}

#[test]
fn convexities_3_has_six_pairs() {
    let r = check(&Convexities::new(3.0, 0.5, 3).unwrap(), 6);
    insta::assert_json_snapshot!("convexities_3", rounded(&r));
}

#[test]
fn convexities_4_has_sixteen_pairs() {
    let r = check(&Convexities::new(4.5, 0.2, 4).unwrap(), 16);
    insta::assert_json_snapshot!("convexities_4", rounded(&r));
}

#[test]
fn convex_shapes_have_at_least_two_pairs() {
    for (a, b) in [(1.0, 0.3), (5.0, 4.9), (2.0, 1.0)] {
        let r = antipodal(
            &Ellipse::new(a, b, [0.0, 0.0]).unwrap(),
            &Options::default(),
        )
        .unwrap();
        assert_eq!(r.pairs.len(), 2);
    }
    for (a, b) in [(4.0, 0.5), (4.0, 1.0), (3.0, 1.4)] {
        // Convex limaçons (a ≥ 2b): no inflections.
        let r = antipodal(&Limacon::new(a, b).unwrap(), &Options::default()).unwrap();
        assert!(r.inflections.is_empty());
        assert!(r.pairs.len() >= 2);
    }
}

#[test]
fn circle_is_one_family_not_a_flood() {
    let r = antipodal(&Circle::new(2.0, [1.0, 1.0]).unwrap(), &Options::default()).unwrap();
    assert!(r.pairs.is_empty(), "{:?}", r.pairs);
    assert!(!r.families.is_empty());
    // Together the families cover every point once as s or t.
    let per = std::f64::consts::TAU;
    let covered: f64 = r
        .families
        .iter()
        .map(|f| 2.0 * (f.s[1] - f.s[0]).rem_euclid(per))
        .sum();
    assert!((covered - per).abs() < 1e-6, "{:?}", r.families);
}
