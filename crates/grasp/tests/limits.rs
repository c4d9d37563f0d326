//! μ → 0 (issue 42): the regions shrink onto the antipodal pairs (`antipodal::antipodal` on
//! the same curve). At μ = 1e-3 on generic curves (no families): every pair inside its own
//! region, every such region within the reach the linearised cone conditions give round its
//! pair (a multiple of μ in parameter).
//!
//! A region may also hold no antipodal pair: the slip angle `max(|θs|, |θt|)` can have a local
//! minimum above 0 where the two angles' gradients oppose (at a knot of a quadratic spline,
//! where the curvature jumps, such minima are common), and below μ it makes a region of its
//! own, which vanishes as μ → 0 but not always by 1e-3. Such a region is checked to be one:
//! its best grasp needs friction (no pair hides in it) and is a local minimum by the oracle.
#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use common::{chord, holders, on_torus, outlines, Oracle, TestCurve};
use curve::ParamCurve;
use grasp::{grasps, GraspOptions};
use numeric::tolerance::ChordTol;
use proptest::prelude::*;
use testkit::stars::star_curve;

/// The friction of the limit.
const MU: f64 = 1e-3;

/// The chord tolerance (relative to the square's diagonal): the regions at μ = 1e-3 are
/// about μ wide, far below the default 1e-3 of a domain of several units, which would hide
/// any reach of the order of μ.
const CHORD_TOL: f64 = 1e-6;

/// Step of the central differences of the contact angles (their second derivatives are of
/// the curve's size: the error is of order the step squared, far below the rates).
const DIFF_STEP: f64 = 1e-6;

/// How far beyond the linearised parallelogram `|J δ|∞ ≤ α` a region may reach: at α = 1e-3
/// the angles' second-order terms shift its edges by a share of order α times the
/// conditioning of J (up to 1.5 % seen on these curves); a quarter is ample for curves whose
/// J is not singular.
const REACH_FACTOR: f64 = 1.25;

/// The friction an antipodal pair needs, at most: zero up to the rounding of the angles.
const PAIR_FRICTION: f64 = 1e-9;

/// The radius of the neighbourhood a region's best grasp is compared with, in parameter.
const NEIGHBOURHOOD: f64 = 1e-4;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(32)))]

    /// Random periodic splines of degree 2 to 4.
    #[test]
    fn the_regions_shrink_onto_the_antipodal_pairs(
        degree in 2usize..=4,
        seed in prop::collection::vec(0.0..1.0f64, 12..=20),
    ) {
        let c = star_curve(degree, &seed, None);
        let found = antipodal::antipodal(&c, &antipodal::Options::default())
            .map_err(|e| TestCaseError::fail(format!("antipodal: {e}")))?;
        // (Generic curves: families, which a random star has with probability 0, are left
        // to the circle's closed form.)
        prop_assume!(found.families.is_empty());
        let mut opts = GraspOptions::friction(MU);
        opts.settings.chord_tol = ChordTol::new(CHORD_TOL).unwrap();
        let g = grasps(&c, &opts).map_err(|e| TestCaseError::fail(format!("grasps: {e}")))?;
        prop_assert!(g.complete);
        let domain = c.domain();
        let test_curve = TestCurve::Spline(Box::new(c.clone()));
        let oracle = Oracle::new(test_curve.param(), &opts);
        for p in &found.pairs {
            prop_assert_eq!(holders(&g, domain, [p.s, p.t]), 1, "pair ({}, {})", p.s, p.t);
        }
        let slack = chord(domain, &opts);
        for (k, r) in g.regions.iter().enumerate() {
            // The pair inside it, and the reach of the linearised cone conditions round it.
            let inside: Vec<_> = found
                .pairs
                .iter()
                .filter(|p| common::region_holds(r, domain, [p.s, p.t]))
                .collect();
            prop_assert!(inside.len() <= 1, "region {} holds {} pairs", k, inside.len());
            if inside.is_empty() {
                let (s, t) = (r.best.s, r.best.t);
                let least = oracle.min_friction(s, t);
                prop_assert!(
                    least > PAIR_FRICTION,
                    "region {} holds no pair, its best ({}, {}) needs {}", k, s, t, least
                );
                for step in 0..8 {
                    let turn = std::f64::consts::TAU * step as f64 / 8.0;
                    let (u, v) = (s + NEIGHBOURHOOD * turn.cos(), t + NEIGHBOURHOOD * turn.sin());
                    prop_assert!(
                        oracle.min_friction(u, v) >= least,
                        "region {} holds no pair, and ({}, {}) needs less than its best", k, u, v
                    );
                }
                continue;
            }
            let pair = on_torus(domain, [inside[0].s, inside[0].t]);
            let reach = linear_reach(&oracle, pair);
            let (parts, holes) = outlines(r);
            for v in parts.into_iter().chain(holes).flatten() {
                // (The vertex's offset from the pair on the torus, each coordinate.)
                let period = domain.1 - domain.0;
                let off = |i: usize| {
                    let d = (v[i] - pair[i]).rem_euclid(period);
                    d.min(period - d)
                };
                for (i, reach) in reach.iter().enumerate() {
                    prop_assert!(
                        off(i) <= REACH_FACTOR * reach + slack,
                        "region {}: vertex {:?} is {} from its pair {:?} in coordinate {}, \
                         the linear reach {}",
                        k, v, off(i), pair, i, reach
                    );
                }
            }
        }
    }
}

/// The largest offsets `|δs|`, `|δt|` of the parallelogram `|J δ|∞ ≤ α`, J the derivative of
/// the two contact angles at the pair (by central differences of the oracle's angles).
fn linear_reach(oracle: &Oracle<'_>, [s, t]: [f64; 2]) -> [f64; 2] {
    let h = DIFF_STEP;
    let diff = |ds: f64, dt: f64| {
        let (p, m) = (
            oracle.signed_angles(s + ds, t + dt),
            oracle.signed_angles(s - ds, t - dt),
        );
        [(p[0] - m[0]) / (2.0 * h), (p[1] - m[1]) / (2.0 * h)]
    };
    let (by_s, by_t) = (diff(h, 0.0), diff(0.0, h));
    let jacobian = [[by_s[0], by_t[0]], [by_s[1], by_t[1]]];
    let det = jacobian[0][0] * jacobian[1][1] - jacobian[0][1] * jacobian[1][0];
    let inverse = [
        [jacobian[1][1] / det, -jacobian[0][1] / det],
        [-jacobian[1][0] / det, jacobian[0][0] / det],
    ];
    let alpha = oracle.alpha;
    [
        alpha * (inverse[0][0].abs() + inverse[0][1].abs()),
        alpha * (inverse[1][0].abs() + inverse[1][1].abs()),
    ]
}

/// The ellipse 3 × 2 and its axes' pairs `(0, π)` and `(π/2, 3π/2)`, at frictions `mus`:
/// asserts two regions, each holding one pair; returns the results.
fn ellipse_regions(mus: &[f64]) -> Vec<grasp::Grasps> {
    let ellipse = curve::shapes::Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap();
    let domain = (0.0, std::f64::consts::TAU);
    let axes = [
        [0.0, std::f64::consts::PI],
        [std::f64::consts::FRAC_PI_2, 1.5 * std::f64::consts::PI],
    ];
    mus.iter()
        .map(|&mu| {
            let g = grasps(&ellipse, &GraspOptions::friction(mu)).unwrap();
            assert!(g.complete, "μ = {mu}");
            assert_eq!(g.regions.len(), 2, "μ = {mu}: {:#?}", g.regions);
            for axis in axes {
                assert_eq!(holders(&g, domain, axis), 1, "μ = {mu}: {axis:?}");
            }
            g
        })
        .collect()
}

/// The ellipse's two regions round its axes, down to μ = 1e-7.
#[test]
fn an_ellipse_s_regions_shrink_onto_its_axes() {
    ellipse_regions(&[1e-3, 1e-5, 1e-7]);
}

/// At μ = 1e-9 the ellipse's regions are still two.
#[test]
#[ignore = "crate defect: at μ = 1e-9 the ellipse 3 × 2 gets four regions: the minor axis's \
            twice, and the major axis's two parts across the seam as two regions"]
fn an_ellipse_at_friction_1e_9_keeps_two_regions() {
    ellipse_regions(&[1e-9]);
}

/// Every region of the ellipse at small friction is more than a point: it has a contact
/// region.
#[test]
#[ignore = "crate defect: at μ = 1e-7 the major axis's region of the ellipse 3 × 2 has no \
            contact region (found at 1e-5 and 1e-9)"]
fn an_ellipse_s_regions_at_small_friction_have_contact_regions() {
    for (g, mu) in ellipse_regions(&[1e-5, 1e-7]).iter().zip([1e-5, 1e-7]) {
        for r in &g.regions {
            assert!(r.contact.is_some(), "μ = {mu}: {r:?}");
        }
    }
}

/// Large friction (μ = 100, cones of half-angle 89.4°): every pair but those near the
/// diagonal is force closure, and the result is complete.
#[test]
#[ignore = "crate limitation: at μ = 100 the ellipse 3 × 2 hits the work limit after 11 s \
            (complete: false, SearchLimit, GraspBoundaryUnresolved); μ = 50 takes 3.6 s"]
fn a_large_friction_is_complete() {
    let ellipse = curve::shapes::Ellipse::new(3.0, 2.0, [1.0, -1.0]).unwrap();
    let g = grasps(&ellipse, &GraspOptions::friction(100.0)).unwrap();
    assert!(g.complete, "{:?}", g.doubts);
    assert_eq!(g.regions.len(), 1);
}
