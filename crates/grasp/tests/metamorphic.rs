//! Metamorphic tests (issue 42): a rotated, scaled and translated curve has the same regions;
//! the curve traversed backwards has them mapped by the parameter's reversal; a periodic
//! spline whose control points are rotated by one (its parameter shifted by one knot span)
//! has them shifted. Regions are compared by membership on a grid of pairs, away from the
//! boundaries of both results (polylines differ in their vertices).
#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use common::{chord, holders, lines, off_lines, on_torus, Documented};
use curve::shapes::Ellipse;
use curve::{ParamCurve, SplineCurve};
use grasp::{grasps, GraspOptions, Grasps};
use proptest::prelude::*;
use testkit::profiles::bezier_chain_profile;
use testkit::stars::star;

/// Grid points per side.
const GRID: usize = 80;

/// How closely the mapped curve must match the original at the mapped parameter for the map
/// to be the one sought, relative to the curve's size: the same control points in another
/// order give the same points up to rounding.
const SAME_POINT: f64 = 1e-12;

/// The result, complete.
fn computed(c: &SplineCurve, opts: &GraspOptions) -> Result<Grasps, TestCaseError> {
    let g = grasps(c, opts).map_err(|e| TestCaseError::fail(format!("grasps: {e}")))?;
    prop_assert!(g.complete);
    Ok(g)
}

/// Compares the membership of each grid pair `p` in `g` with that of `map(p)` in `h`, where
/// both are farther than the chord tolerance from their result's boundaries; returns the
/// number of pairs compared.
fn same_membership(
    domain: (f64, f64),
    opts: &GraspOptions,
    g: &Grasps,
    h: &Grasps,
    map: impl Fn([f64; 2]) -> [f64; 2],
) -> Result<usize, TestCaseError> {
    let (a, b) = domain;
    let margin = chord(domain, opts);
    let (lg, lh) = (lines(g), lines(h));
    let mut compared = 0;
    for i in 0..GRID {
        for j in i + 1..GRID {
            let p = [
                a + (b - a) * (i as f64 + 0.33) / GRID as f64,
                a + (b - a) * (j as f64 + 0.57) / GRID as f64,
            ];
            let q = on_torus(domain, map(p));
            if off_lines(p, &lg) <= margin || off_lines(q, &lh) <= margin {
                continue;
            }
            compared += 1;
            prop_assert_eq!(
                holders(g, domain, p),
                holders(h, domain, q),
                "pair {:?} ↦ {:?}",
                p,
                q
            );
        }
    }
    Ok(compared)
}

/// The numbers of regions of the curve, of its reversal and of its seam shift.
fn region_counts(points: &[[f64; 2]], degree: usize, mu: f64) -> Result<[usize; 3], TestCaseError> {
    let reversed: Vec<[f64; 2]> = points.iter().rev().copied().collect();
    let mut rotated = points.to_vec();
    rotated.rotate_left(1);
    let opts = GraspOptions::friction(mu);
    let mut counts = [0; 3];
    for (count, p) in counts.iter_mut().zip([points, &reversed, &rotated]) {
        let c = SplineCurve::periodic(degree, p, None).unwrap();
        *count = computed(&c, &opts)?.regions.len();
    }
    Ok(counts)
}

/// The shift `m` (a whole number of knot spans) with `moved(u) = original(sign·u + m)`, if
/// any.
fn knot_shift(original: &SplineCurve, moved: &SplineCurve, sign: f64) -> Option<f64> {
    let size = original
        .control_points()
        .iter()
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    whole_shift(original, moved, sign, size)
}

/// The whole number `m` with `moved(u) = original(sign·u + m)` (read modulo the period), if
/// any, `size` the curves' size.
fn whole_shift(
    original: &dyn ParamCurve,
    moved: &dyn ParamCurve,
    sign: f64,
    size: f64,
) -> Option<f64> {
    let (a, b) = original.domain();
    let n = (b - a).round() as i64;
    (0..n).map(|m| m as f64).find(|&m| {
        (0..7).all(|k| {
            let u = a + (b - a) * (k as f64 + 0.13) / 7.0;
            let v = a + (sign * u + m - a).rem_euclid(b - a);
            let (p, q) = (moved.jet(u).p, original.jet(v).p);
            (p.x - q.x).hypot(p.y - q.y) <= SAME_POINT * size
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(24)))]

    /// A similarity (rotation, uniform scale, translation) of the control points: the same
    /// parameters, the same regions.
    #[test]
    fn a_similarity_keeps_the_regions(
        seed in prop::collection::vec(0.0..1.0f64, 12..=18),
        mu in 0.05..1.0f64,
        angle in 0.0..std::f64::consts::TAU,
        log_scale in -3.0..3.0f64,
        shift in prop::array::uniform2(-1e3..1e3f64),
    ) {
        let points = star(&seed);
        let scale = 10f64.powf(log_scale);
        let (sin, cos) = angle.sin_cos();
        let moved: Vec<[f64; 2]> = points
            .iter()
            .map(|p| [
                scale * (cos * p[0] - sin * p[1]) + shift[0],
                scale * (sin * p[0] + cos * p[1]) + shift[1],
            ])
            .collect();
        let (c, d) = (
            SplineCurve::periodic(3, &points, None).unwrap(),
            SplineCurve::periodic(3, &moved, None).unwrap(),
        );
        let opts = GraspOptions::friction(mu);
        let (g, h) = (computed(&c, &opts)?, computed(&d, &opts)?);
        prop_assert_eq!(g.regions.len(), h.regions.len());
        let compared = same_membership(c.domain(), &opts, &g, &h, |p| p)?;
        prop_assert!(compared > GRID * GRID / 4);
    }

    /// The curve backwards (its control points reversed): the regions mapped by the
    /// parameter's reversal `u ↦ m − u`.
    #[test]
    fn reversal_maps_the_regions(
        seed in prop::collection::vec(0.0..1.0f64, 12..=18),
        degree in 2usize..=4,
        mu in 0.05..1.0f64,
    ) {
        let points = star(&seed);
        let reversed: Vec<[f64; 2]> = points.iter().rev().copied().collect();
        let (c, d) = (
            SplineCurve::periodic(degree, &points, None).unwrap(),
            SplineCurve::periodic(degree, &reversed, None).unwrap(),
        );
        regions_map_by_reversal(&c, &d, mu)?;
    }

    /// A rational spline backwards (control points and weights reversed).
    #[test]
    fn reversal_maps_the_regions_of_rational_splines(
        seed in prop::collection::vec(0.0..1.0f64, 12..=16),
        weights in prop::collection::vec(0.3..3.0f64, 8),
        mu in 0.05..1.0f64,
    ) {
        let points = star(&seed);
        let weights = &weights[..points.len()];
        let reversed: Vec<[f64; 2]> = points.iter().rev().copied().collect();
        let reversed_weights: Vec<f64> = weights.iter().rev().copied().collect();
        let (c, d) = (
            SplineCurve::periodic(2, &points, Some(weights)).unwrap(),
            SplineCurve::periodic(2, &reversed, Some(&reversed_weights)).unwrap(),
        );
        regions_map_by_reversal(&c, &d, mu)?;
    }

    /// An ellipse moved and scaled (its centre and both semi-axes): the same regions.
    #[test]
    fn a_moved_and_scaled_ellipse_keeps_the_regions(
        axes in (0.5..3.0f64, 0.2..0.95f64),
        log_scale in -3.0..3.0f64,
        center in prop::array::uniform2(-1e6..1e6f64),
        mu in 0.05..1.0f64,
    ) {
        let (a, b) = (axes.0, axes.0 * axes.1);
        let k = 10f64.powf(log_scale);
        let (e, f) = (
            Ellipse::new(a, b, [0.0, 0.0]).unwrap(),
            Ellipse::new(k * a, k * b, center).unwrap(),
        );
        let opts = GraspOptions::friction(mu);
        let computed = |c: &Ellipse| {
            let g = grasps(c, &opts).map_err(|e| TestCaseError::fail(format!("grasps: {e}")))?;
            prop_assert!(g.complete);
            Ok(g)
        };
        let (g, h) = (computed(&e)?, computed(&f)?);
        prop_assert_eq!(g.regions.len(), h.regions.len());
        same_membership(e.domain(), &opts, &g, &h, |p| p)?;
    }

    /// The reversal and the seam shift keep the number of regions (the membership tests above
    /// see only their union).
    #[test]
    fn reversal_and_seam_shift_keep_the_number_of_regions(
        seed in prop::collection::vec(0.0..1.0f64, 12..=18),
        degree in 2usize..=4,
        mu in 0.05..1.0f64,
    ) {
        let [original, reversed, shifted] = region_counts(&star(&seed), degree, mu)?;
        prop_assert_eq!(original, reversed);
        prop_assert_eq!(original, shifted);
    }

    /// The control points rotated by one (the parameter shifted by one knot span, the seam
    /// moved): the regions shifted.
    #[test]
    fn a_seam_shift_shifts_the_regions(
        seed in prop::collection::vec(0.0..1.0f64, 12..=18),
        degree in 2usize..=4,
        mu in 0.05..1.0f64,
    ) {
        let points = star(&seed);
        let mut rotated = points.clone();
        rotated.rotate_left(1);
        let (c, d) = (
            SplineCurve::periodic(degree, &points, None).unwrap(),
            SplineCurve::periodic(degree, &rotated, None).unwrap(),
        );
        let m = knot_shift(&c, &d, 1.0);
        prop_assert!(m.is_some(), "no shift u ↦ u + m maps one curve onto the other");
        let m = m.unwrap_or_default();
        let opts = GraspOptions::friction(mu);
        let (g, h) = (computed(&c, &opts)?, computed(&d, &opts)?);
        // (A pair (s, t) of the curve is the pair (s − m, t − m) of the shifted one.)
        same_membership(c.domain(), &opts, &g, &h, |[s, t]| [s - m, t - m])?;
    }
}

/// The regions of `c` and of `d`, the same curve backwards, map onto each other by the
/// reversal `u ↦ m − u` of the parameter.
fn regions_map_by_reversal(c: &SplineCurve, d: &SplineCurve, mu: f64) -> Result<(), TestCaseError> {
    let m = knot_shift(c, d, -1.0);
    prop_assert!(
        m.is_some(),
        "no reversal u ↦ m − u maps one curve onto the other"
    );
    let m = m.unwrap_or_default();
    let opts = GraspOptions::friction(mu);
    let (g, h) = (computed(c, &opts)?, computed(d, &opts)?);
    // (A pair (s, t) of the curve is the pair (m − s, m − t) of its reversal.)
    same_membership(c.domain(), &opts, &g, &h, |[s, t]| [m - s, m - t])?;
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(24)))]

    /// A profile with corners reassembled from another segment, or run backwards: the same
    /// regions, mapped by the shift (and reversal) of the document's parameter. Frictions up
    /// to 1.5 bring pinch grasps at sharp corners.
    #[test]
    fn a_profile_started_elsewhere_or_run_backwards_keeps_the_regions(
        radii in prop::collection::vec(0.6..1.0f64, 3..=6),
        wobble in prop::collection::vec((-0.2..0.2f64, -0.2..0.2f64), 6),
        smooth in prop::collection::vec(any::<bool>(), 6),
        start in 0usize..6,
        reverse in any::<bool>(),
        mu in 0.05..1.5f64,
    ) {
        let n = radii.len();
        let chain = |start: usize, reverse: bool| {
            bezier_chain_profile(&radii, &wobble[..n], &smooth[..n], start % n, reverse)
        };
        let (Some(p), Some(q)) = (chain(0, false), chain(start, reverse)) else { return Ok(()) };
        let opts = GraspOptions::friction(mu);
        let computed = |p: &curve::Profile| {
            let g = grasps(p, &opts).map_err(|e| TestCaseError::fail(format!("grasps: {e}")))?;
            prop_assert!(g.complete);
            Ok(g)
        };
        let (g, h) = (computed(&p)?, computed(&q)?);
        let (dp, dq) = (Documented(p.clone()), Documented(q.clone()));
        let sign = if reverse { -1.0 } else { 1.0 };
        let m = whole_shift(&dp, &dq, sign, 2.0);
        prop_assert!(m.is_some(), "no map u ↦ ±u + m takes one profile onto the other");
        let m = m.unwrap_or_default();
        prop_assert_eq!(g.regions.len(), h.regions.len());
        // (The pair (s, t) of the first is the pair (sign (s − m), sign (t − m)) of the second.)
        let compared = same_membership(dp.domain(), &opts, &g, &h, |[s, t]| {
            [sign * (s - m), sign * (t - m)]
        })?;
        prop_assert!(compared > GRID * GRID / 4);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(12)))]

    /// One preparation answers every friction and width as a fresh computation does: the
    /// same result, exactly (a spline curve and a profile with corners, each asked in turn
    /// at frictions and widths in any order).
    #[test]
    fn a_prepared_curve_answers_as_a_fresh_one(
        seed in prop::collection::vec(0.0..1.0f64, 8..=14),
        radii in prop::collection::vec(0.6..1.0f64, 3..=5),
        frictions in prop::collection::vec(0.05..1.5f64, 3),
        widths in prop::collection::vec(prop::option::of(0.2..1.5f64), 3),
    ) {
        let c = testkit::stars::star_curve(3, &seed, None);
        let n = radii.len();
        let Some(p) = bezier_chain_profile(&radii, &[(0.0, 0.0); 5][..n], &[false; 5][..n], 0, false)
        else { return Ok(()) };
        let (pc, pp) = (grasp::prepare(&c).unwrap(), grasp::prepare(&p).unwrap());
        for (&mu, &max_width) in frictions.iter().zip(&widths) {
            let opts = GraspOptions { max_width: max_width.map(|w| 4.0 * w), ..GraspOptions::friction(mu) };
            prop_assert_eq!(pc.grasps(&opts).unwrap(), grasps(&c, &opts).unwrap());
            prop_assert_eq!(pp.grasps(&opts).unwrap(), grasps(&p, &opts).unwrap());
        }
    }
}
