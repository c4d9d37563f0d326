//! Centrally symmetric periodic splines (`P(i + m) = −P(i)`, so `C(u + m) = −C(u)`): the
//! normals at `u` and `u + m` are opposite, and the pair is antipodal exactly where the
//! distance from the centre is stationary, `C(u) · C′(u) = 0`. That gives an oracle sharing
//! nothing with the crate: the sign changes of `C · C′` over half the domain (rational curves
//! too, their weights repeated half a turn on). Equal radii of
//! neighbouring control points put such zeros on knots, where a quadratic's curvature jumps,
//! often from one sign to the other: pairs of inflections whose normals are opposite, which
//! no section of Jia's search holds (the pieces' ranges of normals only touch there).

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use antipodal::{antipodal, Antipodal, Error, Options, ParamCurve, SplineCurve};
use proptest::prelude::*;

/// Samples of `C · C′` per knot span for the oracle's sign changes (the knots themselves
/// among them).
const PER_SPAN: usize = 64;

/// `C · C′` this small (relative to `|C| |C′|`) at a sample is a zero there, bracketed by its
/// neighbours.
const ZERO: f64 = 1e-12;

/// The radii the control points take: few, so that neighbours often share one.
const RADII: [f64; 3] = [0.55, 0.8, 1.0];

/// The weights of a rational curve's control points: few, so that neighbours often share one.
const WEIGHTS: [f64; 3] = [0.6, 1.0, 1.7];

/// A centrally symmetric control polygon of `2m` points, counterclockwise and star-shaped
/// about the origin: angles jittered within their spacing, radii drawn from [`RADII`].
fn symmetric_polygon(angles: &[f64], radii: &[usize]) -> Vec<[f64; 2]> {
    let m = angles.len();
    let n = 2 * m;
    let half: Vec<[f64; 2]> = (0..m)
        .map(|i| {
            let a = std::f64::consts::TAU * (i as f64 + 0.6 * (angles[i] - 0.5)) / n as f64;
            let r = RADII[radii[i] % RADII.len()];
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    half.iter()
        .copied()
        .chain(half.iter().map(|p| [-p[0], -p[1]]))
        .collect()
}

/// The antipodal pairs of `c`; `None` where the crate refuses the curve (a spline cut off
/// from its polygon's star shape may cross itself).
fn searched(c: &SplineCurve) -> Option<Antipodal> {
    match antipodal(c, &Options::default()) {
        Ok(r) => Some(r),
        Err(Error::SelfIntersecting { .. } | Error::Winding { .. } | Error::Cusp { .. }) => None,
        Err(e) => panic!("{e}"),
    }
}

/// Whether `found` holds the pair of parameters `u` and `v` (either way round, modulo the
/// `period`, to 1e-9).
fn holds_pair(found: &Antipodal, period: f64, u: f64, v: f64) -> bool {
    let near = |x: f64, y: f64| {
        let d = (x - y).rem_euclid(period);
        d.min(period - d) <= 1e-9
    };
    found
        .pairs
        .iter()
        .any(|p| (near(p.s, u) && near(p.t, v)) || (near(p.t, u) && near(p.s, v)))
}

/// The brackets `[lo, hi]` of `[0, m]` where `C · C′` changes sign, and whether the inward
/// normals of the pair there face each other (the pair is antipodal, not just opposite).
fn oracle(c: &SplineCurve, m: usize) -> Vec<[f64; 2]> {
    let steps = m * PER_SPAN;
    let us: Vec<f64> = (0..=steps).map(|k| k as f64 / PER_SPAN as f64).collect();
    let value = |u: f64| {
        let j = c.jet(u);
        let v = j.p.dot(j.d1);
        if v.abs() <= ZERO * j.p.norm() * j.d1.norm() {
            0.0
        } else {
            v
        }
    };
    let vs: Vec<f64> = us.iter().map(|&u| value(u)).collect();
    let mut out = Vec::new();
    let mut k = 0;
    while k < steps {
        if vs[k] == 0.0 {
            k += 1;
            continue;
        }
        // The next sample off zero: a sign change to it brackets a zero (on a zero sample
        // between, as at a knot).
        let Some(next) = (k + 1..=steps).find(|&i| vs[i] != 0.0) else {
            break;
        };
        if (vs[k] < 0.0) != (vs[next] < 0.0) {
            out.push([us[k], us[next]]);
        }
        k = next;
    }
    // (A zero at u = 0 has no sample before it: its bracket is the one at u = m, where
    // `C · C′` repeats.)
    out
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(96), ..ProptestConfig::default() })]

    #[test]
    fn every_stationary_distance_from_the_centre_is_a_pair(
        (degree, angles, radii, weights) in (2usize..=3, 3usize..=6).prop_flat_map(|(d, m)| (
            Just(d),
            proptest::collection::vec(0.0f64..1.0, m),
            proptest::collection::vec(0usize..RADII.len(), m),
            proptest::option::of(proptest::collection::vec(0usize..WEIGHTS.len(), m)),
        ))
    ) {
        let m = angles.len();
        let pts = symmetric_polygon(&angles, &radii);
        // (Weights repeated half a turn on keep the symmetry.)
        let weights: Option<Vec<f64>> =
            weights.map(|w| w.iter().chain(&w).map(|&k| WEIGHTS[k]).collect());
        let c = SplineCurve::periodic(degree, &pts, weights.as_deref()).unwrap();
        let Some(found) = searched(&c) else {
            return Ok(());
        };
        prop_assert!(found.complete);
        // Only a certified result promises every pair.
        prop_assume!(found.doubts.is_empty());
        let n = (2 * m) as f64;
        let on = |x: f64, [lo, hi]: [f64; 2]| {
            let slack = 1e-9;
            [x, x - n, x + n, x - n / 2.0, x + n / 2.0]
                .iter()
                .any(|&y| y >= lo - slack && y <= hi + slack)
        };
        for bracket in oracle(&c, m) {
            // The pair (u, u + m): inward normals face each other where the curve is star-
            // shaped about the centre; where not, it is no antipodal pair.
            let u = 0.5 * (bracket[0] + bracket[1]);
            let j = c.jet(u);
            let inward = [-j.d1.y, j.d1.x];
            if inward[0] * -j.p.x + inward[1] * -j.p.y <= 0.0 {
                continue;
            }
            let hit = found.pairs.iter().any(|p| {
                let half = ((p.t - p.s).rem_euclid(n) - n / 2.0).abs() <= 1e-7;
                half && (on(p.s, bracket) || on(p.t, bracket))
            });
            prop_assert!(
                hit,
                "degree {degree}, polygon {pts:?}: no pair with C·C' = 0 in {bracket:?}; found {:?}",
                found.pairs.iter().map(|p| (p.s, p.t)).collect::<Vec<_>>()
            );
        }
    }
}

/// Cases of the knot-pair property: the old search missed about one pair in a thousand draws.
const KNOT_PAIR_CASES: u32 = 2048;

/// A quadratic star whose control points 0, 1 and `m`, `m + 1` are opposite, with `|P₀| =
/// |P₁|`: `C(0) = (P₀ + P₁)/2` and `C(m)` are opposite, with opposite tangents along `P₁ − P₀`,
/// which is perpendicular to `C(0)`. The knots 0 and `m` are a pair with opposite normals
/// along the chord, antipodal where the normals face each other. A quadratic's curvature on
/// the span after knot `k` has the sign of the polygon's turn at `P(k+1)`, and its radius of
/// curvature there shrinks as the turn sharpens; the radii of the points beside set them:
/// - with `inflecting`, `P₀` and `P(m+1)` are reflex and `P₁` and `P(m)` convex, so both knots
///   are inflections, the normal's angle least at one and greatest at the other (the pieces'
///   normals are opposite only at their ends);
/// - else the star's own radii decide: the curvature mostly jumps at the knots but keeps its
///   sign, and the pair lies inside a section. Where the two radii of curvature add up to
///   less than the chord on one side of the knots and to more on the other (about one draw in
///   eight), θ along that section touches zero at the kink without changing sign.
fn knot_pair_star(seed: &[f64], inflecting: bool) -> (Vec<[f64; 2]>, usize) {
    let mut pts = testkit::stars::star(seed);
    let n = pts.len();
    let m = n / 2;
    let radius = |p: &mut [f64; 2], r: f64| {
        let l = p[0].hypot(p[1]);
        *p = [p[0] * r / l, p[1] * r / l];
    };
    radius(&mut pts[0], 0.7);
    radius(&mut pts[1], 0.7);
    if inflecting {
        for (k, r) in [(2, 0.4), (m - 1, 0.4), (m + 2, 1.0), (n - 1, 1.0)] {
            radius(&mut pts[k], r);
        }
    }
    pts[m] = [-pts[0][0], -pts[0][1]];
    pts[m + 1] = [-pts[1][0], -pts[1][1]];
    (pts, m)
}

proptest! {
    // (A pair missed at a kink is rare among the draws, which are cheap: many cases. Some
    // draws are passed over: normals pointing apart, or a result with doubts.)
    #![proptest_config(ProptestConfig {
        cases: common::cases(KNOT_PAIR_CASES),
        max_global_rejects: common::cases(KNOT_PAIR_CASES),
        ..ProptestConfig::default()
    })]

    #[test]
    fn opposite_knots_with_a_perpendicular_chord_are_a_pair(
        seed in (4usize..=7).prop_flat_map(|m| proptest::collection::vec(0.0f64..1.0, 4 * m)),
        inflecting in any::<bool>(),
    ) {
        let (pts, m) = knot_pair_star(&seed, inflecting);
        let c = SplineCurve::periodic(2, &pts, None).unwrap();
        let Some(found) = searched(&c) else {
            return Ok(());
        };
        prop_assert!(found.complete);
        // Only a certified result promises every pair.
        prop_assume!(found.doubts.is_empty());
        let n = (2 * m) as f64;
        let (j0, jm) = (c.jet(0.0), c.jet(m as f64));
        let inward = [-j0.d1.y, j0.d1.x];
        let chord = [jm.p.x - j0.p.x, jm.p.y - j0.p.y];
        // (Normals pointing apart: no grasp, no pair.)
        prop_assume!(inward[0] * chord[0] + inward[1] * chord[1] > 0.0);
        prop_assert!(
            holds_pair(&found, n, 0.0, m as f64),
            "polygon {pts:?}: the knots 0 and {m} are no reported pair; found {:?}",
            found.pairs.iter().map(|p| (p.s, p.t)).collect::<Vec<_>>()
        );
    }
}

/// The case that showed the defect (found through the grasp regions, which held the pair):
/// a quadratic whose control points 0, 1 and 5, 6 are opposite, so that its knots 0 and 5
/// are inflections with opposite normals and the pair `(0, 5)` at the seam is antipodal.
#[test]
fn inflections_with_opposite_normals_on_knots_are_a_pair() {
    let seed = [
        0.0,
        0.0,
        0.0,
        0.0,
        0.22987590784433154,
        0.44192659430827164,
        0.960465314474176,
        0.4119753585180522,
        0.045081255627357736,
        0.21742674966594924,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.6691279716063284,
        0.0,
        0.0,
        0.0,
        0.804799164534928,
    ];
    let c = testkit::stars::star_curve(2, &seed, None);
    let found = antipodal(&c, &Options::default()).unwrap();
    assert!(
        found.complete && found.doubts.is_empty(),
        "{:?}",
        found.doubts
    );
    let (a, b) = c.domain();
    assert!(
        holds_pair(&found, b - a, a, a + 5.0),
        "{:?}",
        found.pairs.iter().map(|p| (p.s, p.t)).collect::<Vec<_>>()
    );
}

/// A pair on two knots where the curvature jumps but keeps its sign (found by a stress run of
/// `opposite_knots_with_a_perpendicular_chord_are_a_pair`): `sin θ` along the section through
/// `(5, 10)` falls to zero at `s = 5` and rises again, a touching zero at the kink. Jia's march
/// stepped over it and the result was certified without the pair; sections are now cut where
/// the curvature may jump, and the pair is an end of two.
#[test]
fn a_touching_pair_on_knots_inside_a_section_is_found() {
    let pts = [
        [0.6008903958808688, 0.05731342560741305],
        [0.5353465200672588, 0.2788515735451385],
        [0.20750926160698477, 0.4704550519165854],
        [-0.05101304960148028, 0.8108292045130531],
        [-0.6252247405891821, 0.27558502439896576],
        [-0.6008903958808688, -0.05731342560741305],
        [-0.5353465200672588, -0.2788515735451385],
        [-0.3761664580625621, -0.7883720010270816],
        [0.3662504776350914, -0.7441342257263224],
        [0.25683263092546965, -0.29185893143880065],
    ];
    let c = SplineCurve::periodic(2, &pts, None).unwrap();
    let found = antipodal(&c, &Options::default()).unwrap();
    assert!(
        holds_pair(&found, 10.0, 0.0, 5.0) || !found.doubts.is_empty(),
        "{:?}",
        found.pairs.iter().map(|p| (p.s, p.t)).collect::<Vec<_>>()
    );
}
