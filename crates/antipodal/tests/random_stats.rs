//! Hundreds of random simple closed B-splines (degree 3–5, up to 20 control points, several
//! inflections) against the brute-force oracle, with statistics so that the comparison is not
//! vacuous (most curves valid, many pairs and inflections exercised).

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use antipodal::{antipodal, Error, Options, ParamCurve, SplineCurve};
use numeric::certificate::Verdict;
use testkit::stars::Star;

#[test]
fn random_bsplines_against_oracle() {
    run(0x5eed_1234, 300, 0.35, 200, &Options::default());
}

/// The same curves on the path of curves without symbolic forms (Jia's sampled inflections,
/// signs at segment ends, Table 1's ε), which elliptic lemniscates more slender than a/b = 5 take.
#[test]
fn random_bsplines_uncertified_against_oracle() {
    run(
        0x5eed_1234,
        300,
        0.35,
        200,
        &Options::default().certify(false),
    );
}

/// Wilder curves (deep dents, many inflections, near-degenerate pairs): run on demand.
#[test]
#[ignore]
fn stress_random_bsplines() {
    run(0xabcd_0042, 1000, 0.12, 0, &Options::default());
    run(
        0xabcd_0042,
        1000,
        0.12,
        0,
        &Options::default().certify(false),
    );
}

fn run(seed: u64, cases: usize, rmin: f64, min_valid: usize, opts: &Options) {
    let mut rng = testkit::Lcg(seed);
    let (mut valid, mut skipped, mut pairs, mut infl, mut certified) = (0, 0, 0, 0, 0);
    let mut types = std::collections::BTreeMap::new();
    for case in 0..cases {
        let deg = 3 + (rng.next() * 3.0) as usize;
        let n = 6 + (rng.next() * 15.0) as usize;
        let size = 0.1 + 10.0 * rng.next();
        let star = Star {
            inner: rmin,
            size,
            center: [3.0, -1.0],
            ..Star::default()
        };
        let mut pts = star.drawn(n, &mut || rng.next());
        if case % 2 == 1 {
            pts.reverse();
        }
        let w: Option<Vec<f64>> =
            (case % 3 == 2).then(|| (0..n).map(|_| 0.5 + 1.5 * rng.next()).collect());
        let c = SplineCurve::periodic(deg, &pts, w.as_deref()).unwrap();
        let r = match antipodal(&c, opts) {
            Ok(r) => r,
            Err(Error::SelfIntersecting { .. } | Error::Winding { .. } | Error::Cusp { .. }) => {
                skipped += 1;
                continue;
            }
            Err(e) => panic!("case {case}: {e}"),
        };
        valid += 1;
        pairs += r.pairs.len();
        infl += r.inflections.len();
        certified += r.certified() as usize;
        for p in &r.pairs {
            let kind = p.kind.expect("a smooth curve's pair has a type");
            *types.entry(format!("{kind:?}")).or_insert(0) += 1;
            assert!(
                common::residual(&c, p.s, p.t) <= 1e-12,
                "case {case} residual"
            );
        }
        let oracle = common::antipodal_oracle(&c, 600);
        let per = c.domain().1 - c.domain().0;
        let mut size_bb = 0.0f64;
        for j in common::jets(&c, 200).1.iter() {
            size_bb = size_bb.max(j.p.norm());
        }
        for &(s, t) in &oracle {
            let isolated = oracle.iter().all(|&(x, y)| {
                (x == s && y == t)
                    || !(common::same_param(&c, x, s, 1e-4 * per)
                        && common::same_param(&c, y, t, 1e-4 * per))
            });
            if !isolated {
                continue;
            }
            let ok = r
                .pairs
                .iter()
                .any(|p| common::same_points(&c, s, t, p.p, p.q, 1e-9 * size_bb));
            assert!(
                ok,
                "case {case}: missed ({s}, {t})\nfound {:?}\noracle {:?}",
                r.pairs.iter().map(|p| (p.s, p.t)).collect::<Vec<_>>(),
                oracle
            );
        }
        for p in &r.pairs {
            let ok = oracle
                .iter()
                .any(|&(s, t)| common::same_pair(&c, (s, t), (p.s, p.t), 1e-6 * per));
            assert!(
                ok,
                "case {case}: extra {:?}\noracle {:?}",
                (p.s, p.t),
                oracle
            );
        }
    }
    eprintln!("valid {valid} skipped {skipped} pairs {pairs} inflections {infl} certified {certified} types {types:?}");
    assert!(
        valid >= min_valid,
        "too many invalid random curves: {skipped}"
    );
    assert!(infl >= valid, "random curves should have inflections");
}
