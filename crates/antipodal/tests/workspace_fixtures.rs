//! Closed curves from the workspace fixtures (clamped-closed with non-uniform knots, periodic
//! NURBS) against the oracle.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use antipodal::{antipodal, inflections, Options, ParamCurve, PlaneCurve, SplineCurve};
use numeric::certificate::Verdict;

fn check(c: &dyn PlaneCurve) -> usize {
    let r = antipodal(c, &Options::default()).unwrap();
    assert!(r.complete);
    let oracle = common::antipodal_oracle(c, 1200);
    assert_eq!(r.pairs.len(), oracle.len(), "{:?} vs {oracle:?}", r.pairs);
    for &(s, t) in &oracle {
        assert!(r
            .pairs
            .iter()
            .any(|p| common::same_pair(c, (p.s, p.t), (s, t), 1e-9)));
    }
    for p in &r.pairs {
        assert!(common::residual(c, p.s, p.t) <= 1e-12);
    }
    let infl = inflections(c, &Options::default()).unwrap();
    assert_eq!(infl.inflections.len(), r.inflections.len());
    assert_eq!(
        common::inflection_oracle(c, 20_000).len(),
        infl.inflections.len()
    );
    r.pairs.len()
}

#[test]
fn clamped_closed_fixture() {
    let pts = testkit::outlines::CLAMPED_CLOSED_POINTS;
    let knots = testkit::outlines::CLAMPED_CLOSED_KNOTS.to_vec();
    let c = SplineCurve::clamped(3, &pts, None, Some(knots)).unwrap();
    assert!(c.is_closed());
    assert!(check(&c) >= 2);
}

#[test]
fn periodic_nurbs_fixture() {
    let pts = testkit::outlines::PERIODIC_NURBS_POINTS;
    let w = testkit::outlines::PERIODIC_NURBS_WEIGHTS;
    let c = SplineCurve::periodic(3, &pts, Some(&w)).unwrap();
    assert!(check(&c) >= 2);
}

#[test]
fn periodic_cubic_fixture() {
    let pts = testkit::outlines::PERIODIC_CUBIC_POINTS;
    let c = SplineCurve::periodic(3, &pts, None).unwrap();
    assert_eq!(check(&c), 2);
}

#[test]
fn open_fixtures_tangents_and_inflections() {
    let c7 = SplineCurve::clamped(
        3,
        &[
            [0.0, 0.0],
            [0.5, 2.5],
            [2.0, 3.0],
            [3.0, 1.0],
            [4.0, -0.5],
            [5.5, 0.5],
            [6.0, 2.5],
        ],
        None,
        None,
    )
    .unwrap();
    let q7 = SplineCurve::clamped(
        2,
        &[
            [0.0, 0.0],
            [1.0, 2.0],
            [2.5, 2.2],
            [3.0, 0.5],
            [4.5, 0.0],
            [5.0, 2.0],
            [6.0, 2.5],
        ],
        None,
        None,
    )
    .unwrap();
    let c11 = SplineCurve::clamped(
        3,
        &[
            [0.0, 1.0],
            [0.5, 2.5],
            [1.5, 3.0],
            [2.5, 2.0],
            [3.0, 3.2],
            [4.0, 3.5],
            [5.0, 2.2],
            [5.5, 3.0],
            [6.5, 3.4],
            [7.5, 2.5],
            [8.0, 1.5],
        ],
        None,
        None,
    )
    .unwrap();
    for c in [&c7, &q7, &c11] {
        let r = inflections(c, &Options::default()).unwrap();
        let o = common::inflection_oracle(c, 20_000);
        assert_eq!(r.inflections.len(), o.len(), "{:?} vs {o:?}", r.inflections);
        assert!(r.certified());
    }
    for (a, b) in [(&c7, &q7), (&c7, &c11), (&q7, &c11)] {
        let r = antipodal::common_tangents(a, b, &Options::default()).unwrap();
        let o = common::tangent_oracle(a, b, 1500);
        for &(s, t) in &o {
            assert!(
                r.lines
                    .iter()
                    .any(|l| (l.s - s).abs() < 1e-8 && (l.t - t).abs() < 1e-8),
                "missed ({s}, {t}): {:?}",
                r.lines
            );
        }
        for l in &r.lines {
            assert!(common::tangent_residual(a, b, l.s, l.t) <= 1e-12);
        }
    }
}
