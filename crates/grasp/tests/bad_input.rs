//! Bad input gets a typed error, never a panic (issue 42): friction ≤ 0, NaN or infinite;
//! widths ≤ 0, not finite, or min ≥ max; an open curve; a curve known by evaluation only.
#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use curve::shapes::Ellipse;
use curve::{PlaneCurve, SplineCurve};
use grasp::{grasps, Error, GraspOptions};
use testkit::evaluation_only::EvaluationOnly;

fn ellipse() -> Ellipse {
    Ellipse::new(3.0, 2.0, [1.0, -1.0]).unwrap()
}

/// The option named in the error, if it is an option's error.
fn refused_option(opts: &GraspOptions) -> Option<&'static str> {
    match grasps(&ellipse(), opts) {
        Err(Error::Option { field, .. }) => Some(field),
        _ => None,
    }
}

#[test]
fn friction_must_be_finite_and_positive() {
    for mu in [0.0, -0.0, -0.5, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(
            refused_option(&GraspOptions::friction(mu)),
            Some("friction"),
            "μ = {mu}"
        );
    }
    // (A tiny and a large coefficient are accepted.)
    assert!(grasps(&ellipse(), &GraspOptions::friction(1e-9)).is_ok());
    assert!(grasps(&ellipse(), &GraspOptions::friction(10.0)).is_ok());
}

#[test]
fn widths_must_be_finite_positive_and_ordered() {
    let with = |min_width, max_width| GraspOptions {
        min_width,
        max_width,
        ..GraspOptions::friction(0.3)
    };
    for w in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(
            refused_option(&with(Some(w), None)),
            Some("min_width"),
            "{w}"
        );
        assert_eq!(
            refused_option(&with(None, Some(w))),
            Some("max_width"),
            "{w}"
        );
    }
    assert_eq!(
        refused_option(&with(Some(2.0), Some(2.0))),
        Some("max_width")
    );
    assert_eq!(
        refused_option(&with(Some(3.0), Some(2.0))),
        Some("max_width")
    );
    assert!(grasps(&ellipse(), &with(Some(2.0), Some(5.0))).is_ok());
}

#[test]
fn an_open_curve_is_refused() {
    let open = SplineCurve::clamped(
        3,
        &[[0.0, 0.0], [1.0, 1.0], [2.0, -1.0], [3.0, 0.0]],
        None,
        None,
    )
    .unwrap();
    assert!(matches!(
        grasps(&open, &GraspOptions::friction(0.3)),
        Err(Error::NotClosed)
    ));
}

#[test]
fn a_curve_known_by_evaluation_only_is_refused() {
    let sampled = EvaluationOnly(ellipse());
    let curve: &dyn PlaneCurve = &sampled;
    assert!(matches!(
        grasps(curve, &GraspOptions::friction(0.3)),
        Err(Error::NotExact)
    ));
}
