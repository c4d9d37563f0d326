//! The algorithm against an independent brute-force oracle on random simple closed B-splines.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use antipodal::{
    antipodal, common_tangents, inflections, Error, Options, ParamCurve, PlaneCurve, SplineCurve,
};
use numeric::certificate::Verdict;
use proptest::prelude::*;
use testkit::stars::Star;

/// A random simple closed curve, of degree 2 (curvature jumping at every knot) to 5.
fn random_curve() -> impl Strategy<Value = CurveSpec> {
    (
        2usize..=5,
        6usize..=20,
        any::<bool>(),
        any::<bool>(),
        0.1f64..10.0,
    )
        .prop_flat_map(|(deg, n, clockwise, rational, size)| {
            (
                Just(deg),
                proptest::collection::vec(0.0f64..1.0, 2 * n),
                Just(clockwise),
                proptest::collection::vec(0.5f64..2.0, n),
                Just(rational),
                Just(size),
            )
                .prop_map(move |(deg, seed, cw, w, rational, size)| {
                    let mut pts = Star {
                        size,
                        ..Star::default()
                    }
                    .points_from_seed(&seed[..2 * n]);
                    if cw {
                        pts.reverse();
                    }
                    (deg, pts, cw, rational.then_some(w))
                })
        })
}

fn size_of(c: &dyn PlaneCurve) -> f64 {
    let (_, js) = common::jets(c, 400);
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for j in js {
        lo = [lo[0].min(j.p.x), lo[1].min(j.p.y)];
        hi = [hi[0].max(j.p.x), hi[1].max(j.p.y)];
    }
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

/// Oracle pairs whose Jacobian is nearly singular (two pairs about to merge) are not decided
/// reliably by any finite-precision method; they are excluded from the comparison.
fn well_conditioned(c: &dyn PlaneCurve, s: f64, t: f64, others: &[(f64, f64)]) -> bool {
    let (a, b) = c.domain();
    let per = b - a;
    others.iter().all(|&(x, y)| {
        (x == s && y == t)
            || !(common::same_param(c, x, s, 1e-4 * per) && common::same_param(c, y, t, 1e-4 * per))
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(160), ..ProptestConfig::default() })]

    #[test]
    fn antipodal_matches_oracle((deg, pts, _cw, w) in random_curve()) {
        let c = SplineCurve::periodic(deg, &pts, w.as_deref()).unwrap();
        let r = match antipodal(&c, &Options::default()) {
            Ok(r) => r,
            Err(Error::SelfIntersecting { .. } | Error::Winding { .. } | Error::Cusp { .. }) => return Ok(()),
            Err(e) => panic!("{e}"),
        };
        prop_assert!(r.complete);
        let size = size_of(&c);
        let (a, b) = c.domain();
        let per = b - a;
        let oracle = common::antipodal_oracle(&c, 700);
        for p in &r.pairs {
            prop_assert!(common::residual(&c, p.s, p.t) <= 1e-12, "residual {} at {:?}", common::residual(&c, p.s, p.t), p);
            prop_assert!(p.s <= p.t && p.s >= a && p.t < b);
        }
        for &(s, t) in &oracle {
            if !well_conditioned(&c, s, t, &oracle) { continue; }
            let hit = r.pairs.iter().any(|p| common::same_points(&c, s, t, p.p, p.q, 1e-9 * size));
            prop_assert!(hit, "missed oracle pair ({s}, {t}); found {:?}; oracle {:?}", r.pairs, oracle);
        }
        // Not in the grid oracle is acceptable only for a genuine pair the grid was too coarse
        // to see (two within one of its cells, as beside a quadratic's curvature jump): one
        // satisfying the equations to rounding (checked above).
        for p in &r.pairs {
            let hit = oracle.iter().any(|&(s, t)| {
                common::same_pair(&c, (s, t), (p.s, p.t), 1e-6 * per)
            });
            prop_assert!(hit || common::residual(&c, p.s, p.t) <= 1e-12, "extra pair {:?}; oracle {:?}", p, oracle);
        }
        // Seam: every unordered pair once.
        for (i, p) in r.pairs.iter().enumerate() {
            for q in &r.pairs[i + 1..] {
                prop_assert!(!(common::same_param(&c, p.s, q.s, 1e-9 * per) && common::same_param(&c, p.t, q.t, 1e-9 * per)));
            }
        }
    }

    #[test]
    fn inflections_match_oracle((deg, pts, _cw, w) in random_curve()) {
        let c = SplineCurve::periodic(deg, &pts, w.as_deref()).unwrap();
        let r = inflections(&c, &Options::default()).unwrap();
        let oracle = common::inflection_oracle(&c, 20_000);
        let per = c.domain().1 - c.domain().0;
        // The fine scan misses pairs closer than its step; the certified isolation does not.
        for &z in &oracle {
            prop_assert!(r.inflections.iter().any(|i| common::same_param(&c, i.u, z, 1e-9 * per)),
                "missed inflection {z}: {:?}", r.inflections);
        }
        for i in &r.inflections {
            let (a, b) = c.domain();
            // (Below the domain's start: the closed curve's end.)
            let k = |u: f64| { let j = c.jet(if u < a { u + (b - a) } else { u }); j.d1.cross(j.d2) };
            let h = 1e-6 * per;
            prop_assert!((k(i.u - h) > 0.0) != (k(i.u + h) > 0.0) || oracle.iter().any(|&z| common::same_param(&c, i.u, z, 1e-9 * per)),
                "extra inflection {}", i.u);
        }
    }
}

type CurveSpec = (usize, Vec<[f64; 2]>, bool, Option<Vec<f64>>);

fn tangent_case() -> impl Strategy<Value = (CurveSpec, CurveSpec, [f64; 2])> {
    (random_curve(), random_curve(), (-6.0f64..6.0, -6.0f64..6.0))
        .prop_map(|(a, b, (x, y))| (a, b, [x, y]))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(48), ..ProptestConfig::default() })]

    #[test]
    fn tangents_match_oracle(((d1, p1, _, w1), (d2, p2, _, w2), off) in tangent_case()) {
        let c1 = SplineCurve::periodic(d1, &p1, w1.as_deref()).unwrap();
        let p2: Vec<[f64; 2]> = p2.iter().map(|p| [p[0] + off[0], p[1] + off[1]]).collect();
        let c2 = SplineCurve::periodic(d2, &p2, w2.as_deref()).unwrap();
        let r = common_tangents(&c1, &c2, &Options::default()).unwrap();
        let oracle = common::tangent_oracle(&c1, &c2, 900);
        let (per1, per2) = (c1.domain().1 - c1.domain().0, c2.domain().1 - c2.domain().0);
        // Ill-conditioned tangents (two about to merge) are excluded, as for antipodal pairs.
        for &(s, t) in &oracle {
            let isolated = oracle.iter().all(|&(x, y)| (x == s && y == t) || !(common::same_param(&c1, x, s, 1e-4 * per1) && common::same_param(&c2, y, t, 1e-4 * per2)));
            if !isolated { continue; }
            prop_assert!(r.lines.iter().any(|l| common::same_param(&c1, l.s, s, 1e-7 * per1) && common::same_param(&c2, l.t, t, 1e-7 * per2)),
                "missed tangent ({s}, {t}); found {:?}; oracle {:?}", r.lines.iter().map(|l| (l.s, l.t)).collect::<Vec<_>>(), oracle);
        }
        for l in &r.lines {
            prop_assert!(common::tangent_residual(&c1, &c2, l.s, l.t) <= 1e-12, "tangent residual");
        }
        for l in &r.lines {
            // Not in the grid oracle is acceptable only for a genuine solution the grid was too
            // coarse to see: one satisfying the equations to rounding.
            prop_assert!(oracle.iter().any(|&(s, t)| common::same_param(&c1, l.s, s, 1e-6 * per1) && common::same_param(&c2, l.t, t, 1e-6 * per2))
                || common::tangent_residual(&c1, &c2, l.s, l.t) <= 1e-12,
                "extra tangent {:?}; oracle {:?}", (l.s, l.t), oracle);
        }
    }

    /// Shifting the control points cyclically moves the seam: the pairs (as point sets) must
    /// not change. Reversing them flips the orientation; clamping keeps the curve.
    #[test]
    fn seam_orientation_and_clamping_invariance((deg, pts, _cw, w) in random_curve(), shift in 1usize..6) {
        let c = SplineCurve::periodic(deg, &pts, w.as_deref()).unwrap();
        let Ok(base) = antipodal(&c, &Options::default()) else { return Ok(()); };
        let n = pts.len();
        let k = shift % n;
        let rot: Vec<[f64; 2]> = (0..n).map(|i| pts[(i + k) % n]).collect();
        let wrot = w.as_ref().map(|w| (0..n).map(|i| w[(i + k) % n]).collect::<Vec<_>>());
        let rev: Vec<[f64; 2]> = pts.iter().rev().copied().collect();
        let wrev = w.as_ref().map(|w| w.iter().rev().copied().collect::<Vec<_>>());
        let hom: Vec<f64> = pts.iter().enumerate().flat_map(|(i, p)| {
            let wi = w.as_ref().map_or(1.0, |w| w[i]);
            [p[0] * wi, p[1] * wi, wi]
        }).collect();
        let clamped = bspline::BSpline::periodic(deg, 3, hom).unwrap().clamped();
        let variants = [
            SplineCurve::periodic(deg, &rot, wrot.as_deref()).unwrap(),
            SplineCurve::periodic(deg, &rev, wrev.as_deref()).unwrap(),
            SplineCurve::new(bspline::Rational::from_homogeneous(clamped).unwrap()).unwrap(),
        ];
        let size = size_of(&c);
        for (vi, v) in variants.iter().enumerate() {
            prop_assert!(v.is_closed());
            let r = antipodal(v, &Options::default()).unwrap();
            prop_assert_eq!(r.pairs.len(), base.pairs.len(), "variant {}: {:?} vs {:?}", vi, r.pairs, base.pairs);
            prop_assert_eq!(r.inflections.len(), base.inflections.len());
            for p in &base.pairs {
                prop_assert!(r.pairs.iter().any(|q| common::same_points(v, q.s, q.t, p.p, p.q, 1e-9 * size)), "variant {}: lost {:?}", vi, p);
            }
        }
    }
}

/// Two pairs beside a knot of a quadratic spline, where the curvature jumps: a proof that the
/// tangential offset keeps its sign (the maximum principle over the rates of the radii of
/// curvature) must count the radius's jump there, or it clears a stretch holding both. Every
/// start of the control polygon (the knot moves with it) gives the oracle's eight pairs.
#[test]
fn quadratic_pairs_beside_a_knot() {
    let pts = [
        [0.5731639862060547, -0.1013946533203125],
        [0.6886005401611328, 0.5743770599365234],
        [-0.02361774444580078, 0.4529561996459961],
        [-0.8133888244628906, 0.46659278869628906],
        [-0.3824787139892578, -0.14910221099853516],
        [-0.06475448608398438, -0.794734001159668],
        [0.2630796432495117, -0.5616989135742188],
    ];
    let n = pts.len();
    for shift in 0..n {
        let rot: Vec<[f64; 2]> = (0..n).map(|i| pts[(i + shift) % n]).collect();
        let c = SplineCurve::periodic(2, &rot, None).unwrap();
        let r = antipodal(&c, &Options::default()).unwrap();
        let oracle = common::antipodal_oracle(&c, 700);
        assert_eq!(oracle.len(), 8, "shift {shift}: oracle {oracle:?}");
        assert!(r.certified() && r.complete);
        for &(s, t) in &oracle {
            assert!(
                r.pairs
                    .iter()
                    .any(|p| common::same_pair(&c, (s, t), (p.s, p.t), 1e-7 * n as f64)),
                "shift {shift}: missed ({s}, {t}) among {:?}",
                r.pairs
            );
        }
    }
}
