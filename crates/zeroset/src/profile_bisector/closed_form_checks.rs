//! Checks the closed-form bisectors' tests share: every vertex a bisector point, vertices as
//! dense in each foot as a traced zero set, and the closed form and the general traced
//! bisector within the chord tolerance of each other.

use super::lines::STEPS;
use super::polyline::off_chord;
use crate::bisector::{curve_bisector, Bisector, BisectorOptions, Branch};
use bspline::Rational;
use proptest::prelude::*;

/// Every vertex of `found` (the bisector of `c1` and `c2`) is equidistant from its two feet
/// and on both feet's normals, within `tol(x)`; no foot moves more than a [`STEPS`]-th of its
/// domain between vertices (the medial axis brackets its junctions between them).
pub(super) fn check_vertices(
    c1: &Rational,
    c2: &Rational,
    found: &Bisector,
    tol: impl Fn([f64; 2]) -> f64,
) -> Result<(), TestCaseError> {
    let ext = |c: &Rational| c.domain().1 - c.domain().0;
    for br in &found.branches {
        for w in br.tr.windows(2) {
            for (k, e) in [ext(c1), ext(c2)].into_iter().enumerate() {
                let step = (w[1][k] - w[0][k]).abs();
                prop_assert!(
                    step <= (1.0 + 1e-9) * e / STEPS as f64,
                    "foot {k} moves {step} between vertices"
                );
            }
        }
        for (tr, x) in br.tr.iter().zip(&br.xy) {
            let (mut o1, mut o2) = ([0.0; 4], [0.0; 4]);
            c1.eval_derivs(tr[0], 1, &mut o1);
            c2.eval_derivs(tr[1], 1, &mut o2);
            let to = |o: [f64; 4]| (x[0] - o[0]).hypot(x[1] - o[1]);
            let along =
                |o: [f64; 4]| ((x[0] - o[0]) * o[2] + (x[1] - o[1]) * o[3]) / o[2].hypot(o[3]);
            let tol = tol(*x);
            testkit::prop_assert_near!(to(o1), to(o2), tol, "{tr:?} {x:?}: {} {}", to(o1), to(o2));
            prop_assert!(
                along(o1).abs() <= tol && along(o2).abs() <= tol,
                "{tr:?} {x:?}: off the normals by {} {}",
                along(o1),
                along(o2)
            );
        }
    }
    Ok(())
}

/// The closed form `closed` (found with the absolute chord tolerance `chord`, cut at `far`
/// from the origin) and the traced zero set of the general bisector (at an eighth of the
/// tolerance, relative to the pair's size, at most `size`) lie within twice the tolerance of
/// each other, away from the cut.
pub(super) fn agrees_with_traced(
    c1: &Rational,
    c2: &Rational,
    closed: &Bisector,
    chord: f64,
    far: f64,
    size: f64,
) -> Result<(), TestCaseError> {
    let opts = BisectorOptions {
        settings: numeric::tolerance::Settings {
            chord_tol: numeric::tolerance::ChordTol::new(chord / 8.0).expect("in range"),
            ..Default::default()
        },
        trimmed: false,
        ..BisectorOptions::default()
    };
    let traced = curve_bisector(c1, c2, &opts).expect("traced");
    prop_assume!(traced.complete);
    let room = 2.0 * chord * size;
    for x in traced.branches.iter().flat_map(|br| &br.xy) {
        if x[0].hypot(x[1]) < 0.9 * far {
            prop_assert!(
                off_polylines(*x, &closed.branches) <= room,
                "traced point {x:?} off the closed form"
            );
        }
    }
    for x in closed.branches.iter().flat_map(|br| &br.xy) {
        prop_assert!(
            off_polylines(*x, &traced.branches) <= room,
            "closed-form point {x:?} off the traced zero set"
        );
    }
    Ok(())
}

/// The distance from `x` to the nearest of the polylines.
fn off_polylines(x: [f64; 2], branches: &[Branch]) -> f64 {
    branches
        .iter()
        .flat_map(|b| b.xy.windows(2).map(move |w| off_chord(x, w[0], w[1])))
        .fold(f64::INFINITY, f64::min)
}
