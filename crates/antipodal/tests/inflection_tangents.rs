//! A curve and its copy slid along the tangent at one of its inflections, or mirrored across a
//! line perpendicular to it: that line is tangent to both at their inflections, where each
//! piece's normal is at its extreme. Mirrored, the two pieces' ranges of normal angles may only
//! touch there.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use antipodal::{common_tangents, inflections, Options, ParamCurve, SplineCurve};
use proptest::prelude::*;
use testkit::stars::Star;

/// `pts` moved by `by`.
fn moved(pts: &[[f64; 2]], by: [f64; 2]) -> Vec<[f64; 2]> {
    pts.iter().map(|p| [p[0] + by[0], p[1] + by[1]]).collect()
}

/// `pts` mirrored across the line through `at` perpendicular to the unit vector `e`.
fn mirrored(pts: &[[f64; 2]], at: [f64; 2], e: [f64; 2]) -> Vec<[f64; 2]> {
    pts.iter()
        .map(|p| {
            let k = 2.0 * ((p[0] - at[0]) * e[0] + (p[1] - at[1]) * e[1]);
            [p[0] - k * e[0], p[1] - k * e[1]]
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(64), ..ProptestConfig::default() })]

    #[test]
    fn a_copy_slid_along_an_inflection_tangent_shares_it(
        deg in 2usize..=4,
        seed in (6usize..=12).prop_flat_map(|n| proptest::collection::vec(0.0f64..1.0, 2 * n)),
        pick in 0.0f64..1.0,
        gap in 2.5f64..6.0,
        mirror in any::<bool>(),
        weights in proptest::option::of(proptest::collection::vec(0.5f64..2.0, 12)),
    ) {
        let pts = Star::default().points_from_seed(&seed);
        // (Rational too: the copy keeps the weights, as moving or mirroring the control
        // points moves or mirrors the curve.)
        let weights = weights.as_deref().map(|w| &w[..pts.len()]);
        let c1 = SplineCurve::periodic(deg, &pts, weights).unwrap();
        let Ok(found) = inflections(&c1, &Options::default()) else {
            return Ok(());
        };
        prop_assume!(!found.inflections.is_empty());
        let u = found.inflections[(pick * found.inflections.len() as f64) as usize % found.inflections.len()].u;
        let j = c1.jet(u);
        let dir = j.d1.unit();
        // Beyond the curve's size (a star of radius 1): the copy does not meet it.
        let by = [gap * dir.x, gap * dir.y];
        let other = if mirror {
            let at = [j.p.x + 0.5 * by[0], j.p.y + 0.5 * by[1]];
            mirrored(&pts, at, [dir.x, dir.y])
        } else {
            moved(&pts, by)
        };
        let c2 = SplineCurve::periodic(deg, &other, weights).unwrap();
        let r = common_tangents(&c1, &c2, &Options::default()).unwrap();
        prop_assume!(r.doubts.is_empty());
        let per = c1.domain().1 - c1.domain().0;
        let hit = r.lines.iter().any(|l| {
            common::same_param(&c1, l.s, u, 1e-7 * per) && common::same_param(&c2, l.t, u, 1e-7 * per)
        });
        prop_assert!(hit, "the tangent at the inflections ({u}, {u}) is missing; found {:?}",
            r.lines.iter().map(|l| (l.s, l.t)).collect::<Vec<_>>());
    }
}
