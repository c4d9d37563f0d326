//! The fast path against the plain one: Jia's method with every proof, cache and shortcut
//! (`Options::default()`, on the curve's symbolic forms) and Jia's method as the paper gives it
//! (`certify(false)`: sampled inflections, signs at segment ends, Table 1's ε, no proofs and
//! no caches) must find the same pairs, of the same types, at the same points, and the same
//! inflections, on random closed splines (periodic, rational or not, degrees 2 to 6) and on the
//! papers' shapes.
#![allow(clippy::unwrap_used)]

mod common;

use antipodal::shapes::{Convexities, Ellipse, EllipticLemniscate, Limacon};
use antipodal::{antipodal, Antipodal, Error, Options, PlaneCurve, SplineCurve};
use numeric::certificate::Verdict;
use testkit::stars::Star;

/// Both paths on one curve; `None` when the curve is not simple (both must refuse it alike).
fn both(c: &dyn PlaneCurve) -> Option<(Antipodal, Antipodal)> {
    let fast = antipodal(c, &Options::default());
    let plain = antipodal(c, &Options::default().certify(false));
    match (fast, plain) {
        (Ok(f), Ok(p)) => Some((f, p)),
        (Err(Error::SelfIntersecting { .. } | Error::Winding { .. } | Error::Cusp { .. }), _) => {
            None
        }
        (f, p) => panic!("the paths disagree on the curve: fast {f:?}, plain {p:?}"),
    }
}

/// The same pairs (points within `tol` of the curve's size, same types) and inflections.
fn same_answers(c: &dyn PlaneCurve, f: &Antipodal, p: &Antipodal) -> Result<(), String> {
    if !(f.complete && p.complete) {
        return Ok(()); // a search limit: nothing to compare
    }
    let size = common::jets(c, 200)
        .1
        .iter()
        .fold(0.0f64, |m, j| m.max(j.p.norm()));
    let tol = 1e-7 * size;
    let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) <= tol;
    let matches = |x: &antipodal::AntipodalPair, y: &antipodal::AntipodalPair| {
        x.kind == y.kind
            && ((near(x.p, y.p) && near(x.q, y.q)) || (near(x.p, y.q) && near(x.q, y.p)))
    };
    if f.pairs.len() != p.pairs.len() || f.families.len() != p.families.len() {
        return Err(format!(
            "fast: {} pairs {} families; plain: {} pairs {} families\nfast {:?}\nplain {:?}",
            f.pairs.len(),
            f.families.len(),
            p.pairs.len(),
            p.families.len(),
            f.pairs,
            p.pairs
        ));
    }
    for x in &f.pairs {
        if !p.pairs.iter().any(|y| matches(x, y)) {
            return Err(format!("fast pair {x:?} not found plainly: {:?}", p.pairs));
        }
    }
    if f.inflections.len() != p.inflections.len() {
        return Err(format!(
            "inflections: fast {:?}, plain {:?}",
            f.inflections, p.inflections
        ));
    }
    // (An inflection across a straight stretch lies anywhere along it: the paths may place it
    // at different ends.)
    let straight_between = |a: f64, b: f64| {
        let (lo, hi) = (a.min(b), a.max(b));
        (0..=64).all(|i| {
            let j = c.jet(lo + (hi - lo) * i as f64 / 64.0);
            j.d1.cross(j.d2).abs() <= 1e-9 * j.d1.norm() * j.d2.norm().max(j.d1.norm() / size)
        })
    };
    // (Each found by the other path, wherever the seam puts it in the list.)
    for a in &f.inflections {
        let found = p
            .inflections
            .iter()
            .any(|b| near(a.p, b.p) || (a.u - b.u).abs() <= 1e-6 || straight_between(a.u, b.u));
        if !found {
            let us = |r: &Antipodal| r.inflections.iter().map(|i| i.u).collect::<Vec<_>>();
            return Err(format!(
                "inflection {a:?} not found plainly: fast {:?}, plain {:?}",
                us(f),
                us(p)
            ));
        }
    }
    Ok(())
}

/// Where the paths disagree, the fast one must agree with the dense oracles: the same
/// inflections (count) and every isolated pair the oracle finds, and no pair it does not.
fn fast_matches_oracle(c: &dyn PlaneCurve, f: &Antipodal) -> Result<(), String> {
    let per = c.domain().1 - c.domain().0;
    let infl = common::inflection_oracle(c, 20_000);
    if infl.len() != f.inflections.len() {
        return Err(format!(
            "oracle inflections {infl:?}, fast {:?}",
            f.inflections
        ));
    }
    let oracle = common::antipodal_oracle(c, 600);
    for &(s, t) in &oracle {
        let isolated = oracle.iter().all(|&(x, y)| {
            (x == s && y == t)
                || !(common::same_param(c, x, s, 1e-4 * per)
                    && common::same_param(c, y, t, 1e-4 * per))
        });
        if isolated
            && !f
                .pairs
                .iter()
                .any(|p| common::same_pair(c, (s, t), (p.s, p.t), 1e-6 * per))
        {
            return Err(format!("fast missed the oracle's pair ({s}, {t})"));
        }
    }
    for p in &f.pairs {
        if !oracle
            .iter()
            .any(|&(s, t)| common::same_pair(c, (s, t), (p.s, p.t), 1e-6 * per))
        {
            return Err(format!("fast pair {p:?} is not the oracle's"));
        }
    }
    Ok(())
}

/// Random closed splines: periodic, degrees 2 to 6, 6 to 15 points, a third rational. Most
/// agree; where the plain path differs (its sampled inflections miss close pairs, its ε a pair
/// beside another), the fast path must be the one the oracles confirm.
#[test]
fn random_closed_splines_agree() {
    let mut rng = testkit::Lcg(0xd1ff_0017);
    let (mut valid, mut agreed) = (0, 0);
    for case in 0..common::cases(300) {
        let degree = 2 + (rng.next() * 5.0) as usize;
        let n = 6 + (rng.next() * 10.0) as usize;
        let rmin = 0.3 + 0.6 * rng.next();
        let seed: Vec<(f64, f64)> = (0..n).map(|_| (rng.next(), rng.next())).collect();
        let star = Star {
            inner: rmin,
            center: [2.0, -1.0],
            ..Star::default()
        };
        let pts = star.points(&seed);
        let w: Option<Vec<f64>> =
            (case % 3 == 2).then(|| (0..n).map(|_| 0.5 + 1.5 * rng.next()).collect());
        if n <= degree {
            continue;
        }
        let c = SplineCurve::periodic(degree, &pts, w.as_deref()).unwrap();
        let Some((f, p)) = both(&c) else { continue };
        valid += 1;
        match same_answers(&c, &f, &p) {
            Ok(()) => agreed += 1,
            Err(diff) => {
                if let Err(e) = fast_matches_oracle(&c, &f) {
                    panic!("case {case}: the paths differ ({diff}) and the fast one is wrong: {e}");
                }
            }
        }
    }
    assert!(
        valid >= common::cases(300) / 2,
        "only {valid} simple curves"
    );
    assert!(agreed * 10 >= valid * 9, "only {agreed} of {valid} agree");
}

#[test]
fn papers_shapes_agree() {
    let shapes: Vec<Box<dyn PlaneCurve>> = vec![
        Box::new(Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap()),
        Box::new(Limacon::new(4.0, 2.5).unwrap()),
        Box::new(EllipticLemniscate::new(6.0, 3.0).unwrap()),
        Box::new(Convexities::new(3.0, 0.5, 3).unwrap()),
        Box::new(Convexities::new(4.5, 0.2, 4).unwrap()),
        Box::new(Convexities::new(4.5, 0.2, 7).unwrap()),
        Box::new(Convexities::new(3.0, 0.75, 7).unwrap()),
    ];
    for c in &shapes {
        let (f, p) = both(c.as_ref()).unwrap();
        assert!(f.certified(), "{:?}", f.reason());
        same_answers(c.as_ref(), &f, &p).unwrap();
    }
}
