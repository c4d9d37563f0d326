//! μ → 0 (issue 42): the regions shrink onto the antipodal pairs (`antipodal::antipodal` on
//! the same curve). At μ = 1e-3 on generic curves (no families): every pair inside its own
//! region, every vertex of every region force closure, and every region round a pair where
//! the linearised cone conditions hold at the scale of μ within their reach (a multiple of μ
//! in parameter).
//!
//! A region may also hold no antipodal pair: the slip angle `max(|θs|, |θt|)` can have a local
//! minimum above 0 where the two angles' gradients oppose (at a knot of a quadratic spline,
//! where the curvature jumps, such minima are common), and below μ it makes a region of its
//! own, which vanishes as μ → 0 but not always by 1e-3. Such a region is checked to be one:
//! its best grasp needs friction (no pair hides in it) and is a local minimum by the oracle.
#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use common::{chord, holders, off_lines, on_torus, outlines, region_holds, Oracle, TestCurve};
use curve::ParamCurve;
use grasp::{grasps, GraspOptions};
use numeric::certificate::Doubt;
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

/// How far beyond the linearised parallelogram `|J δ|∞ ≤ α` a region may reach where the
/// linearisation holds at its scale ([`LINEAR_AT_SCALE`]): the second-order terms move its
/// edges by less than a quarter of α, its corners by a share of the reach.
const REACH_FACTOR: f64 = 2.0;

/// The linearisation holds at the scale of μ where the angles at the parallelogram's corners
/// differ from their linear values by at most this share of α. Elsewhere (J nearly singular)
/// the force-closure set bends into a crescent whose length grows like √μ, not μ (four linear
/// reaches seen, confirmed by a fine flood of the oracle): not a generic pair at this μ, and
/// its region is checked only to lie in the force-closure set.
const LINEAR_AT_SCALE: f64 = 0.25;

/// How far a region's vertex may lie outside the force-closure set, in slip angle: vertices
/// lie on the traced zero sets, to the parameter tolerance (1e-12 of the domain) times the
/// angles' rates.
const VERTEX_ANGLE_SLACK: f64 = 1e-9;

/// Samples of the straight path between two pairs sharing a region.
const PATH_SAMPLES: usize = 200;

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
            // (Pairs closer than the reach share a region: joined in it by force closure,
            // straight across or along a curved band, whose edge the region's outline is.)
            for p in inside.iter().skip(1) {
                let (from, to) = ([inside[0].s, inside[0].t], [p.s, p.t]);
                prop_assert!(
                    joined(&oracle, from, to) || joined_along_outline(&oracle, r, from, to),
                    "region {} holds the pairs ({}, {}) and ({}, {}), not joined by force \
                     closure",
                    k, inside[0].s, inside[0].t, p.s, p.t
                );
            }
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
            let pairs: Vec<_> = inside
                .iter()
                .map(|p| {
                    let pair = on_torus(domain, [p.s, p.t]);
                    (pair, linear_reach(&oracle, pair))
                })
                .collect();
            let linear = pairs.iter().all(|&(pair, _)| linear_at_scale(&oracle, pair));
            let (parts, holes) = outlines(r);
            let period = domain.1 - domain.0;
            for v in parts.into_iter().chain(holes).flatten() {
                let angle = oracle.slip_angle(v[0], v[1]);
                prop_assert!(
                    angle <= oracle.alpha + VERTEX_ANGLE_SLACK,
                    "region {}: vertex {:?} has slip angle {} against α = {}",
                    k, v, angle, oracle.alpha
                );
                // (The vertex's offsets from its nearest pair on the torus of unordered pairs,
                // in either order, in units of the pair's reach.)
                let offsets = |w: [f64; 2], pair: [f64; 2]| {
                    [0, 1].map(|i| {
                        let d = (w[i] - pair[i]).rem_euclid(period);
                        d.min(period - d)
                    })
                };
                let share = |o: [f64; 2], reach: [f64; 2]| (o[0] / reach[0]).max(o[1] / reach[1]);
                let (off, pair, reach) = pairs
                    .iter()
                    .flat_map(|&(pair, reach)| {
                        [*v, [v[1], v[0]]].map(|w| (offsets(w, pair), pair, reach))
                    })
                    .min_by(|x, y| share(x.0, x.2).total_cmp(&share(y.0, y.2)))
                    .unwrap_or(([0.0; 2], [0.0; 2], [1.0; 2]));
                for i in 0..2 {
                    prop_assert!(
                        !linear || off[i] <= REACH_FACTOR * reach[i] + slack,
                        "region {}: vertex {:?} is {} from its pair {:?} in coordinate {}, \
                         the linear reach {}",
                        k, v, off[i], pair, i, reach[i]
                    );
                }
            }
        }
    }
}

/// Whether the straight path between two pairs (on the torus, each read in the order nearer
/// the other) is force closure all along, sampled.
fn joined(oracle: &Oracle<'_>, from: [f64; 2], to: [f64; 2]) -> bool {
    let (a, b) = oracle.domain();
    let period = b - a;
    let near = |x: f64, y: f64| y + (x - y + 0.5 * period).rem_euclid(period) - 0.5 * period;
    let direct = [near(to[0], from[0]), near(to[1], from[1])];
    let crossed = [near(to[1], from[0]), near(to[0], from[1])];
    let length = |p: [f64; 2]| (p[0] - from[0]).abs() + (p[1] - from[1]).abs();
    let to = if length(direct) <= length(crossed) {
        direct
    } else {
        crossed
    };
    (0..=PATH_SAMPLES).all(|i| {
        let x = i as f64 / PATH_SAMPLES as f64;
        let p = [0, 1].map(|c| from[c] + x * (to[c] - from[c]));
        oracle.slip_angle(p[0], p[1]) <= oracle.alpha
    })
}

/// An outline's vertex is a pair of the region's edge within its chord tolerance: its slip
/// angle within this share of α of the edge's α (the chord tolerance, 1e-6 of the square,
/// moves an angle by far less than 5 % of α = 1e-3 rad).
const OUTLINE_SLACK: f64 = 0.05;

/// Whether the region's outline runs from the vertex nearest `from` to the one nearest `to`,
/// one way round or the other, through pairs force closure (to [`OUTLINE_SLACK`]): the two
/// pairs are joined along the edge of the band between them.
fn joined_along_outline(
    oracle: &Oracle<'_>,
    region: &grasp::GraspRegion,
    from: [f64; 2],
    to: [f64; 2],
) -> bool {
    let domain = oracle.domain();
    let (from, to) = (on_torus(domain, from), on_torus(domain, to));
    let (parts, _) = outlines(region);
    let nearest = |line: &[[f64; 2]], p: [f64; 2]| {
        (0..line.len())
            .min_by(|&i, &j| {
                let d = |k: usize| (line[k][0] - p[0]).hypot(line[k][1] - p[1]);
                d(i).total_cmp(&d(j))
            })
            .unwrap_or(0)
    };
    let holds = |q: [f64; 2]| oracle.slip_angle(q[0], q[1]) <= (1.0 + OUTLINE_SLACK) * oracle.alpha;
    parts.iter().any(|line| {
        let n = line.len();
        let (a, b) = (nearest(line, from), nearest(line, to));
        let forward = (0..=(b + n - a) % n).all(|k| holds(line[(a + k) % n]));
        let backward = (0..=(a + n - b) % n).all(|k| holds(line[(b + k) % n]));
        n > 0 && (forward || backward)
    })
}

/// Whether the linearised conditions hold at the scale of μ round the pair: the angles at the
/// parallelogram's corners `δ = J⁻¹ (±α, ±α)` within [`LINEAR_AT_SCALE`] α of `±α`.
fn linear_at_scale(oracle: &Oracle<'_>, pair: [f64; 2]) -> bool {
    let inverse = inverse_jacobian(oracle, pair);
    let alpha = oracle.alpha;
    [[1.0, 1.0], [1.0, -1.0], [-1.0, 1.0], [-1.0, -1.0]]
        .iter()
        .all(|u| {
            let d = [0, 1].map(|c| alpha * (inverse[c][0] * u[0] + inverse[c][1] * u[1]));
            let angles = oracle.signed_angles(pair[0] + d[0], pair[1] + d[1]);
            (0..2).all(|c| (angles[c] - alpha * u[c]).abs() <= LINEAR_AT_SCALE * alpha)
        })
}

/// The inverse of J, the derivative of the two contact angles at the pair (by central
/// differences of the oracle's angles).
fn inverse_jacobian(oracle: &Oracle<'_>, [s, t]: [f64; 2]) -> [[f64; 2]; 2] {
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
    [
        [jacobian[1][1] / det, -jacobian[0][1] / det],
        [-jacobian[1][0] / det, jacobian[0][0] / det],
    ]
}

/// The largest offsets `|δs|`, `|δt|` of the parallelogram `|J δ|∞ ≤ α`, J the derivative of
/// the two contact angles at the pair (by central differences of the oracle's angles).
fn linear_reach(oracle: &Oracle<'_>, pair: [f64; 2]) -> [f64; 2] {
    let inverse = inverse_jacobian(oracle, pair);
    let alpha = oracle.alpha;
    [0, 1].map(|c| alpha * (inverse[c][0].abs() + inverse[c][1].abs()))
}

/// The ellipse 3 × 2 and its axes' pairs `(0, π)` and `(π/2, 3π/2)`, at frictions `mus`:
/// asserts two regions, each holding one pair, wherever the result is certified (regions
/// narrower than the zero sets resolve may come out unresolved, and then say so); returns the
/// certified results.
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
            if g.regions.iter().any(|r| r.certified) {
                assert_eq!(g.regions.len(), 2, "μ = {mu}: {:#?}", g.regions);
                // (A pair on the seam may lie outside its region's polylines by less than
                // their chord tolerance.)
                let tol = chord(domain, &GraspOptions::friction(mu));
                for axis in axes {
                    let near = g
                        .regions
                        .iter()
                        .filter(|r| {
                            let (parts, holes) = outlines(r);
                            let p = on_torus(domain, axis);
                            region_holds(r, domain, axis)
                                || off_lines(p, &[parts, holes].concat()) <= tol
                        })
                        .count();
                    assert_eq!(near, 1, "μ = {mu}: {axis:?}");
                }
            }
            g
        })
        .filter(|g| g.regions.iter().all(|r| r.certified))
        .collect()
}

/// The ellipse's two regions round its axes, down to μ = 1e-7.
#[test]
fn an_ellipse_s_regions_shrink_onto_its_axes() {
    ellipse_regions(&[1e-3, 1e-5, 1e-7]);
}

/// At μ = 1e-9 and 1e-10 the ellipse's regions are still two, certified (regions a few
/// 1e-10 of a cell wide, round the axes' pairs: one across the seam, one on two knots of the
/// rational ellipse, whose zero sets the cells on either side each traced).
#[test]
fn an_ellipse_at_friction_1e_9_keeps_two_regions() {
    assert_eq!(ellipse_regions(&[1e-9, 1e-10]).len(), 2);
}

/// Below what the subdivision resolves (regions narrower than its smallest patch), the
/// result says an antipodal pair was lost and certifies nothing (it once reported no region,
/// certified).
#[test]
fn below_what_the_subdivision_resolves_a_lost_pair_is_said() {
    let ellipse = curve::shapes::Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap();
    for mu in [1e-11, 1e-14, 1e-20] {
        let g = grasps(&ellipse, &GraspOptions::friction(mu)).unwrap();
        let axes = [
            [0.0, std::f64::consts::PI],
            [std::f64::consts::FRAC_PI_2, 1.5 * std::f64::consts::PI],
        ];
        let held = axes
            .iter()
            .all(|&a| holders(&g, (0.0, std::f64::consts::TAU), a) == 1);
        assert!(
            held || g.doubts.iter().any(|d| *d == Doubt::GraspPairLost),
            "μ = {mu}: {:?}",
            g.doubts
        );
        assert!(held || g.regions.iter().all(|r| !r.certified), "μ = {mu}");
    }
}

/// Every region of the ellipse at small friction is more than a point: it has a contact
/// region.
#[test]
fn an_ellipse_s_regions_at_small_friction_have_contact_regions() {
    for g in ellipse_regions(&[1e-5, 1e-7]) {
        for r in &g.regions {
            assert!(r.contact.is_some(), "μ = {}: {r:?}", g.friction);
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

/// A limaçon within 0.3 % of a circle, at a small friction (found by a stress run of the dense
/// check, 10 times its cases): the cone conditions at the two contacts nearly coincide along
/// the band round the diameter pairs, and the subdivision that parts their zero sets reaches
/// the patch limit. The result says so (complete: false); it certifies nothing it has not
/// traced.
#[test]
#[ignore = "crate limitation: the limaçon a = 0.5, b = 0.0015 at μ = 0.05 hits the patch limit \
            after ~50 s (complete: false)"]
fn a_nearly_circular_limacon_is_complete() {
    let limacon = curve::shapes::Limacon::new(0.5, 0.001_514_719_659_393_623).unwrap();
    let g = grasps(&limacon, &GraspOptions::friction(0.05)).unwrap();
    assert!(g.complete, "{:?}", g.doubts);
}
