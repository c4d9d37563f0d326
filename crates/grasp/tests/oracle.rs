//! The regions against an independent dense check (issue 42): on a grid of pairs `(s, t)`,
//! the force-closure condition evaluated from the curve's points and tangents alone (no
//! B-spline algebra) agrees with membership in the reported regions wherever the grid point
//! is farther from every reported boundary than the chord tolerance; every contact rectangle
//! is sampled densely; every best grasp is recomputed and no grid point of its region needs
//! less friction. On periodic splines of degree 2 to 4, NURBS, the analytic shapes and the
//! benchmarks' star outlines, far from the origin and at tiny and huge scales, with and
//! without width limits.
#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use common::{check_result, dense_check, dense_check_of, Checks, Documented, Seen, TestCurve};
use curve::shapes::{Circle, Convexities, Ellipse, EllipticLemniscate, Limacon, Shape};
use curve::SplineCurve;
use grasp::GraspOptions;
use proptest::prelude::*;
use testkit::outlines::{bezier_chain, polygon, star_polygon, PERIODIC_CUBIC_POINTS};
use testkit::stars::{star_curve_with, Star};

/// Where and how large a drawn spline is: at the origin, far from it, tiny, huge.
const PLACEMENTS: [(f64, [f64; 2]); 4] = [
    (1.0, [0.0, 0.0]),
    (1.0, [1e6, -1e6]),
    (1e-3, [0.0, 0.0]),
    (1e3, [0.0, 0.0]),
];

/// The dense check, as a property's verdict.
fn verdict(curve: &TestCurve, opts: &GraspOptions) -> Result<Seen, TestCaseError> {
    dense_check(curve, opts).map_err(|e| TestCaseError::fail(format!("{curve:?}: {e}")))
}

/// A periodic spline of `degree` on the star of `seed`, placed.
fn star_spline(degree: usize, seed: &[f64], weights: Option<&[f64]>, place: usize) -> TestCurve {
    let (size, center) = PLACEMENTS[place];
    let star = Star {
        size,
        center,
        ..Star::default()
    };
    TestCurve::Spline(Box::new(star_curve_with(&star, degree, seed, weights)))
}

/// One of the analytic shapes, from draws in `[0, 1)`.
fn shape(kind: usize, [x, y, z]: [f64; 3]) -> TestCurve {
    let s = match kind {
        0 => Shape::Circle(Circle::new(0.5 + 2.0 * x, [y - 0.5, z - 0.5]).unwrap()),
        1 => {
            let a = 0.5 + 2.0 * x;
            // (b up to 0.95 a: a rounder ellipse is a near circle, tested on its own.)
            Shape::Ellipse(Ellipse::new(a, a * (0.2 + 0.75 * y), [z, -z]).unwrap())
        }
        2 => {
            let a = 0.5 + 2.0 * x;
            Shape::Limacon(Limacon::new(a, a * 0.9 * y).unwrap())
        }
        3 => {
            // (a/b up to 5 either way: the lemniscates with an exact form.)
            let ratio = 0.2 + 4.8 * y;
            Shape::EllipticLemniscate(EllipticLemniscate::new(1.0 + x, (1.0 + x) * ratio).unwrap())
        }
        _ => Shape::Convexities(
            Convexities::new(0.5 + x, 0.05 + 0.55 * y, 2 + (4.0 * z) as u32).unwrap(),
        ),
    };
    TestCurve::Shape(s)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(400)))]

    /// Random periodic B-splines of degree 2 to 4 on star polygons, placed anywhere, μ from
    /// 0.05 to 1.
    #[test]
    fn regions_match_the_dense_check_on_splines(
        degree in 2usize..=4,
        seed in prop::collection::vec(0.0..1.0f64, 12..=20),
        place in 0usize..PLACEMENTS.len(),
        mu in 0.05..1.0f64,
    ) {
        verdict(&star_spline(degree, &seed, None, place), &GraspOptions::friction(mu))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(160)))]

    /// Random rational (NURBS) quadratics and cubics (the best grasps' robustness where the
    /// crate does not doubt it: see [`the_best_grasp_is_the_most_robust_at_a_knot`]).
    #[test]
    fn regions_match_the_dense_check_on_rational_splines(
        degree in 2usize..=3,
        seed in prop::collection::vec(0.0..1.0f64, 12..=16),
        weights in prop::collection::vec(0.3..3.0f64, 8),
        place in 0usize..PLACEMENTS.len(),
        mu in 0.05..1.0f64,
    ) {
        let c = star_spline(degree, &seed, Some(&weights), place);
        dense_check_of(&c, &GraspOptions::friction(mu), Checks::UnlessBestDoubted)
            .map_err(|e| TestCaseError::fail(format!("{c:?}: {e}")))?;
    }

    /// Width limits: the dense check also tests `|C(t) − C(s)|` against them (on the grid:
    /// the best grasps and contact rectangles are spoilt by a defect, which
    /// [`the_best_grasp_keeps_to_the_width_limits`] shows).
    #[test]
    fn regions_match_the_dense_check_within_width_limits(
        seed in prop::collection::vec(0.0..1.0f64, 12..=16),
        place in 0usize..PLACEMENTS.len(),
        mu in 0.05..1.0f64,
        limits in (0.0..1.0f64, 0.0..1.0f64),
        which in 0usize..3,
    ) {
        let (size, _) = PLACEMENTS[place];
        // (Widths of the star's curves run from about 0.35 to 2 sizes.)
        let lo = size * (0.3 + 1.2 * limits.0);
        let hi = lo + size * (0.05 + 1.0 * limits.1);
        let opts = GraspOptions {
            min_width: (which != 1).then_some(lo),
            max_width: (which != 0).then_some(hi),
            ..GraspOptions::friction(mu)
        };
        let c = star_spline(3, &seed, None, place);
        dense_check_of(&c, &opts, Checks::Grid)
            .map_err(|e| TestCaseError::fail(format!("{c:?}: {e}")))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(160)))]

    /// The grid alone (no best grasps, no contact rectangles) on the splines, NURBS and
    /// curves with convexities of the tests above, while a defect at the seam spoils the rest.
    #[test]
    fn regions_match_the_dense_grid_on_splines_nurbs_and_convexities(
        kind in 0usize..3,
        degree in 2usize..=4,
        seed in prop::collection::vec(0.0..1.0f64, 12..=16),
        weights in prop::collection::vec(0.3..3.0f64, 8),
        draws in prop::array::uniform3(0.0..1.0f64),
        place in 0usize..PLACEMENTS.len(),
        mu in 0.05..1.0f64,
    ) {
        let c = match kind {
            0 => star_spline(degree, &seed, None, place),
            1 => star_spline(degree.min(3), &seed, Some(&weights), place),
            // (Few: each takes the crate a third of a second.)
            _ if draws[0] < 0.2 => shape(4, draws),
            _ => star_spline(degree, &seed, None, place),
        };
        dense_check_of(&c, &GraspOptions::friction(mu), Checks::Grid)
            .map_err(|e| TestCaseError::fail(format!("{c:?}: {e}")))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(24)))]

    /// Circles, ellipses and limaçons with random parameters.
    #[test]
    fn regions_match_the_dense_check_on_conics_and_limacons(
        kind in 0usize..3,
        draws in prop::array::uniform3(0.0..1.0f64),
        mu in 0.05..1.0f64,
    ) {
        verdict(&shape(kind, draws), &GraspOptions::friction(mu))?;
    }

    /// Curves with convexities with random parameters.
    #[test]
    fn regions_match_the_dense_check_on_curves_with_convexities(
        draws in prop::array::uniform3(0.0..1.0f64),
        mu in 0.05..1.0f64,
    ) {
        verdict(&shape(4, draws), &GraspOptions::friction(mu))?;
    }
}

proptest! {
    // (Each takes the crate about a second and a half: few cases.)
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(6)))]

    /// Elliptic lemniscates with random parameters.
    #[test]
    fn regions_match_the_dense_check_on_elliptic_lemniscates(
        draws in prop::array::uniform3(0.0..1.0f64),
        mu in 0.05..1.0f64,
    ) {
        verdict(&shape(3, draws), &GraspOptions::friction(mu))?;
    }
}

/// The smallest case of the lemniscates' failure: a region's boundary (between its vertices,
/// which lie on the true boundary) strays from it by more than the chord tolerance in the
/// document's parameter φ, so that a pair with slip angle 0.7958 > π/4 is held.
#[test]
fn a_lemniscate_s_boundary_keeps_to_the_chord_tolerance() {
    let c = TestCurve::Shape(Shape::EllipticLemniscate(
        EllipticLemniscate::new(1.0, 2.0).unwrap(),
    ));
    dense_check(&c, &GraspOptions::friction(1.0)).unwrap_or_else(|e| panic!("{c:?}: {e}"));
}

/// A stress run's case (seed 777, 4 times the cases): on this lemniscate a certified region's
/// boundary strayed 0.0106 from the true one, beyond the chord tolerance (0.0089), so that a
/// pair with slip angle 3.4e-4 beyond α was held. The chords were measured in the exact
/// form's parameter, against which the document's angle runs up to twice as fast; they are
/// now measured in the document's parameter, where the result is reported.
#[test]
fn chords_keep_to_the_tolerance_in_the_document_s_parameter() {
    let c = TestCurve::Shape(Shape::EllipticLemniscate(
        EllipticLemniscate::new(1.0, 0.2 + 4.8 * 0.093_289_498_591_733_48).unwrap(),
    ));
    dense_check(&c, &GraspOptions::friction(0.827_719_313_158_126_1))
        .unwrap_or_else(|e| panic!("{c:?}: {e}"));
}

/// A stress run's case (seed 777, 4 times the cases): on this star with a least width, two
/// zero sets cross 8e-8 inside the cell's top edge, and the piece from that crossing to the
/// edge was closed on itself by the border walk: the region's boundary was left open, in two
/// uncertified regions missing a stretch of pairs. Now one region, certified.
#[test]
fn a_crossing_just_inside_a_cell_s_edge_does_not_close_on_itself() {
    let seed = [
        0.6623139947651441,
        0.16766375317060805,
        0.35981898134670626,
        0.9620640715531822,
        0.7059863995236941,
        0.8020942796960978,
        0.3437187031839851,
        0.16859541286513152,
        0.9537182636150403,
        0.24613539538002374,
        0.2684752705376784,
        0.4406116117613525,
        0.315125022522638,
        0.9859985513794227,
    ];
    let c = star_spline(3, &seed, None, 0);
    let opts = GraspOptions {
        min_width: Some(0.3 + 1.2 * 0.637_852_292_607_927_4),
        ..GraspOptions::friction(0.809_771_139_179_504_9)
    };
    dense_check_of(&c, &opts, Checks::Grid).unwrap_or_else(|e| panic!("{c:?}: {e}"));
    let g = grasp::grasps(c.boundary(), &opts).unwrap();
    assert_eq!(g.regions.len(), 1);
    assert!(g.regions[0].certified);
}

/// The smallest case of the width limits' failure: on the ellipse 3 × 2 with widths limited
/// to [4.2, 5.8], the minor axis's pair (width 4) is reported as a region's best grasp.
#[test]
fn the_best_grasp_keeps_to_the_width_limits() {
    let c = TestCurve::Shape(Shape::Ellipse(Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap()));
    let opts = GraspOptions {
        min_width: Some(4.2),
        max_width: Some(5.8),
        ..GraspOptions::friction(0.3)
    };
    dense_check(&c, &opts).unwrap_or_else(|e| panic!("{c:?}: {e}"));
}

/// The smallest case found of the local search's failure: on this rational quadratic (μ =
/// 0.4169), the search stopped at a best grasp needing friction 0.33441 where pairs near the
/// knot t = 5 need 0.3314 (the minimum sits on a knot, where the curvature jumps). The set
/// traced again just below 0.33441 holds those pairs, and the search restarts from them.
#[test]
fn the_best_grasp_is_the_most_robust_at_a_knot() {
    let seed = [
        0.3303152248646873,
        0.06705896069451227,
        0.11208870231423208,
        0.5198452322883061,
        0.14627685047968397,
        0.0691587909708816,
        0.5650503852452404,
        0.35248180362621495,
        0.17386830306730489,
        0.2960577088426986,
        0.803550686036769,
        0.06075426715955702,
    ];
    let weights = [
        1.7179907005291661,
        0.9610400718030284,
        1.333806478787023,
        2.389553223733758,
        0.7758199168251199,
        1.6249286977333703,
    ];
    let c = star_spline(2, &seed, Some(&weights), 0);
    dense_check(&c, &GraspOptions::friction(0.41694879972843363))
        .unwrap_or_else(|e| panic!("{c:?}: {e}"));
}

/// A region across the seam (here round the pair (0.19, 2.95) of a quartic, with a part at
/// the top edge t = 6) is one region, its best grasp inside it.
#[test]
fn a_region_across_the_seam_is_one_region() {
    let seed = [
        0.2659476931622764,
        0.9494889801679826,
        0.02057210774628421,
        0.4623095638697482,
        0.8654280953776543,
        0.6901749641458311,
        0.43330784598781336,
        0.8308766841836551,
        0.13739269133565882,
        0.5920925669832178,
        0.36000001773296597,
        0.11511528244602473,
    ];
    let c = star_spline(4, &seed, None, 0);
    let opts = GraspOptions::friction(0.12261116952818156);
    let seen = dense_check(&c, &opts).unwrap_or_else(|e| panic!("{c:?}: {e}"));
    assert_eq!(seen.regions, 2);
}

/// The benchmarks' profiles with corners: star polygons and a chain of Béziers, on the grid
/// only (the best grasps and contact rectangles may sit at corners, whose cones are the fans
/// of their sides' normals, which the oracle's jets do not see).
#[test]
fn regions_match_the_dense_check_on_the_benchmark_profiles() {
    let profiles = [
        polygon(&star_polygon(6)),
        polygon(&star_polygon(10)),
        bezier_chain(5),
    ];
    for p in profiles {
        let c = TestCurve::Profile(Box::new(Documented(p)));
        for mu in [0.05, 0.3, 1.0] {
            let seen = dense_check_of(&c, &GraspOptions::friction(mu), Checks::Grid)
                .unwrap_or_else(|e| panic!("{c:?}, μ = {mu}: {e}"));
            assert!(seen.decided > 0, "{c:?}: nothing decided");
        }
    }
}

/// The benchmarks' star outlines as periodic splines (smooth closed curves through the star's
/// control polygon), and the medial issue's periodic cubic, at a few frictions.
#[test]
fn regions_match_the_dense_check_on_the_benchmark_outlines() {
    let mut curves: Vec<TestCurve> = [6, 10, 16]
        .into_iter()
        .flat_map(|n| {
            let points = star_polygon(n);
            [2, 3].map(|degree| {
                TestCurve::Spline(Box::new(
                    SplineCurve::periodic(degree, &points, None).unwrap(),
                ))
            })
        })
        .collect();
    curves.push(TestCurve::Spline(Box::new(
        SplineCurve::periodic(3, &PERIODIC_CUBIC_POINTS, None).unwrap(),
    )));
    for c in &curves {
        for mu in [0.05, 0.3, 1.0] {
            let seen = dense_check(c, &GraspOptions::friction(mu))
                .unwrap_or_else(|e| panic!("{c:?}, μ = {mu}: {e}"));
            assert!(seen.decided > 0, "{c:?}: nothing decided");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(12)))]

    /// Circles and ellipses as drawn (axes in halves, centres on the integer grid) at
    /// frictions as typed or any: their axis pairs sit on the knots of the rational forms,
    /// and typed frictions meet round curvature ratios.
    #[test]
    fn round_conics_match_the_dense_check(
        a in (2u32..=8).prop_map(|k| 0.5 * f64::from(k)),
        halves in 1u32..=8,
        center in ((-2i32..=2), (-2i32..=2)).prop_map(|(x, y)| [f64::from(x), f64::from(y)]),
        circle in any::<bool>(),
        mu in prop_oneof![
            prop::sample::select(vec![0.1, 0.2, 0.25, 0.3, 0.5, 0.75, 1.0]),
            0.05..1.0f64,
        ],
    ) {
        let s = if circle {
            Shape::Circle(Circle::new(a, center).unwrap())
        } else {
            // (b in halves up to 0.8 a: a rounder ellipse is a near circle, tested on its own.)
            let b = 0.5 * f64::from(halves).min((1.6 * a).floor());
            Shape::Ellipse(Ellipse::new(a, b, center).unwrap())
        };
        let curve = TestCurve::Shape(s);
        let opts = GraspOptions::friction(mu);
        let g = grasp::grasps(curve.boundary(), &opts)
            .map_err(|e| TestCaseError::fail(format!("{e}")))?;
        prop_assert!(g.complete, "{:?}", curve);
        check_result(curve.param(), &opts, &g)
            .map_err(|e| TestCaseError::fail(format!("{curve:?}: {e}")))?;
        // Resolved, too: round numbers are no excuse.
        prop_assert!(
            !g.doubts.iter().any(|d| *d == numeric::certificate::Doubt::GraspBoundaryUnresolved),
            "{:?}: {:?}", curve, g.doubts
        );
    }
}
