//! Random regions against the oracle: filleted polygons, chains of Béziers and closed splines,
//! with round holes, each property checked for not being vacuous.

use crate::helpers::{closed_spline, with_holes};
use crate::oracle::{bump, check, CERTIFIED, MEDIAL_POINTS, NEAR_CUSPS, WITH_HOLES};
use curve::Profile;
use proptest::prelude::*;
use std::cell::Cell;
use testkit::cases;

fn hole() -> impl Strategy<Value = ([f64; 2], f64)> {
    ([-1.0f64..1.0, -1.0f64..1.0], 0.05f64..0.3)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(16), ..ProptestConfig::default() })]

    fn filleted_polygons(
        outer in testkit::profiles::filleted_polygons(3..7, 12),
        holes in proptest::collection::vec(hole(), 0..3),
    ) {
        check_drawn(outer, &holes)?;
    }

    // Joints of either kind: a corner, or smooth with a jump of the curvature (G1, not G2).
    fn bezier_chains(
        outer in testkit::profiles::bezier_chains(3..6, 6, 0.3),
        holes in proptest::collection::vec(hole(), 0..3),
    ) {
        check_drawn(outer, &holes)?;
    }
}

/// [`check`] on a drawn region: inside `outer` (where it is a profile) with those of the
/// round `holes` it accepts, counted when it keeps some.
fn check_drawn(outer: Option<Profile>, holes: &[([f64; 2], f64)]) -> Result<(), TestCaseError> {
    let Some(region) = outer.and_then(|p| with_holes(p, holes)) else {
        return Ok(());
    };
    if !region.holes().is_empty() {
        bump(&WITH_HOLES, 1);
    }
    check(&region)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(8), ..ProptestConfig::default() })]

    /// Smooth closed B-splines and NURBS of 8 to 24 spans (cut at their knots, pairs of
    /// spans pruned), with holes.
    fn closed_splines(
        radii in proptest::collection::vec(1.0f64..2.0, 8..24),
        weights in proptest::option::of(proptest::collection::vec(0.5f64..2.0, 24)),
        holes in proptest::collection::vec(hole(), 0..3),
    ) {
        let w = weights.as_ref().map(|w| &w[..radii.len()]);
        check_drawn(closed_spline(&radii, w), &holes)?;
    }
}

/// Checks that the property just run on this thread (of `n` cases) was not vacuous: medial
/// points found by the oracle, regions with holes, certified axes; and that near-cusps, which
/// the oracle cannot judge, were rare.
fn assert_not_vacuous(n: u32) {
    let n = n as usize;
    let count = |c: &'static std::thread::LocalKey<Cell<usize>>| c.with(Cell::get);
    assert!(count(&MEDIAL_POINTS) >= n);
    assert!(count(&WITH_HOLES) > n / 8);
    // (Filleted polygons of lines and arcs are certified but where rounding leaves a
    // decision open.)
    assert!(count(&CERTIFIED) >= n / 2);
    // (Near-cusps are rare in the generators: a few in a hundred regions at most.)
    assert!(count(&NEAR_CUSPS) <= n / 4 + 1);
}

#[test]
fn filleted_polygons_match_the_oracle() {
    filleted_polygons();
    assert_not_vacuous(cases(16));
}

#[test]
fn bezier_chains_match_the_oracle() {
    bezier_chains();
    assert_not_vacuous(cases(16));
}

#[test]
fn closed_splines_match_the_oracle() {
    closed_splines();
    assert_not_vacuous(cases(8));
}
