//! Two independent methods on one question: Jia's antipodal points and common tangents
//! (`antipodal`) against the subdivision solver for square systems of `zeroset`, applied to the
//! defining equations written as tensor-product B-splines.
//!
//! For a closed polynomial curve `C = (x, y)`, antipodal pairs `(s, t)` are the zeros of
//! `C'(s) × C'(t)` (parallel tangents) and `(C(t) − C(s)) · C'(s)` (the chord is normal) with
//! `C'(s) · C'(t) < 0` (opposite tangents, so opposite normals) and the normals facing each
//! other. Common tangents of two curves are the zeros of `C1'(s) × C2'(t)` and
//! `(C2(t) − C1(s)) × C1'(s)`.
#![allow(clippy::unwrap_used)]

use curvekit::antipodal::{self, Options, ParamCurve, PlaneCurve, SplineCurve};
use curvekit::bspline::tensor::TensorBSpline;
use curvekit::bspline::BSpline;
use curvekit::zeroset::{solve_system, SystemOptions};
use proptest::prelude::*;
use testkit::stars::star;

/// The clamped form of the periodic curve through `pts`, and its coordinate functions.
fn coordinates(degree: usize, pts: &[[f64; 2]]) -> (BSpline, BSpline) {
    let flat: Vec<f64> = pts.iter().flat_map(|p| [p[0], p[1]]).collect();
    let c = BSpline::periodic(degree, 2, flat).unwrap().clamped();
    (c.component(0).unwrap(), c.component(1).unwrap())
}

fn one(f: &BSpline) -> BSpline {
    let (a, b) = f.domain();
    BSpline::constant(&[1.0], 0, a, b).unwrap()
}

/// `f1(s)·g1(t) − f2(s)·g2(t)`.
fn cross_form(f1: &BSpline, g1: &BSpline, f2: &BSpline, g2: &BSpline) -> TensorBSpline {
    TensorBSpline::sum_of_outer(&[(f1.clone(), g1.clone()), (f2.scale(-1.0), g2.clone())]).unwrap()
}

/// Solutions of the system on the box, restricted first (a box avoids the diagonal).
fn solve_on(f: &TensorBSpline, g: &TensorBSpline, b: [f64; 4]) -> Vec<(f64, f64)> {
    let (f, g) = (
        f.restrict(b[0], b[1], b[2], b[3]).unwrap(),
        g.restrict(b[0], b[1], b[2], b[3]).unwrap(),
    );
    solve_system(&f, &g, &SystemOptions::default())
        .unwrap()
        .into_iter()
        .map(|s| (s.t, s.r))
        .collect()
}

fn distance(c: &dyn PlaneCurve, s: f64, t: f64) -> f64 {
    let (p, q) = (c.jet(s).p, c.jet(t).p);
    (q.x - p.x).hypot(q.y - p.y)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Every antipodal pair found by Jia's method is a solution of the system, and every
    /// solution of the system that is an antipodal pair was found, away from the diagonal
    /// band of the parameter square (where no pair of a smooth curve can sit: tangents there
    /// point the same way).
    #[test]
    fn antipodal_pairs_solve_the_system(degree in 3usize..=4, seed in prop::collection::vec(0.0f64..1.0, 16..=24)) {
        let pts = star(&seed);
        let n = pts.len() as f64;
        let curve = SplineCurve::periodic(degree, &pts, None).unwrap();
        let found = match antipodal::antipodal(&curve, &Options::default()) {
            Ok(r) => r,
            Err(antipodal::Error::SelfIntersecting { .. } | antipodal::Error::Winding { .. } | antipodal::Error::Cusp { .. }) => return Ok(()),
            Err(e) => panic!("{e}"),
        };
        prop_assume!(found.families.is_empty());
        let (x, y) = coordinates(degree, &pts);
        let (dx, dy) = (x.deriv(), y.deriv());
        let tangents = cross_form(&dx, &dy, &dy, &dx);
        // (C(t) − C(s))·C'(s) = x'(s)x(t) + y'(s)y(t) − (x x' + y y')(s)·1.
        let xx = x.mul(&dx).unwrap().add(&y.mul(&dy).unwrap()).unwrap();
        let chord = TensorBSpline::sum_of_outer(&[(dx.clone(), x.clone()), (dy.clone(), y.clone()), (xx.scale(-1.0), one(&x))]).unwrap();
        // Cells of a k×k grid over [0, n)², keeping s < t, off the diagonal and its wrap.
        let k = 12;
        let h = n / k as f64;
        let mut solutions = Vec::new();
        for i in 0..k {
            for j in i + 2..k {
                if i == 0 && j == k - 1 { continue; }
                let cell = [i as f64 * h, (i + 1) as f64 * h, j as f64 * h, (j + 1) as f64 * h];
                solutions.extend(solve_on(&tangents, &chord, cell));
            }
        }
        let band = |s: f64, t: f64| {
            let d = (t - s).rem_euclid(n);
            d.min(n - d) < 2.0 * h
        };
        let size = 2.0;
        // Antipodal solutions of the system: opposite tangents, normals facing each other.
        let antipodal_solutions: Vec<(f64, f64)> = solutions
            .iter()
            .copied()
            .filter(|&(s, t)| {
                let (js, jt) = (curve.jet(s), curve.jet(t));
                let chord = jt.p - js.p;
                // The curve runs counterclockwise: the inward normal of a tangent d is (−d.y, d.x).
                let inward = |d: antipodal::V2| antipodal::V2 { x: -d.y, y: d.x };
                js.d1.dot(jt.d1) < 0.0 && chord.dot(inward(js.d1)) > 0.0 && (-chord).dot(inward(jt.d1)) > 0.0
            })
            .collect();
        let same = |a: (f64, f64), p: &antipodal::AntipodalPair| {
            let close = |u: f64, v: f64| { let d = (u - v).rem_euclid(n); d.min(n - d) < 1e-7 * n };
            (close(a.0, p.s) && close(a.1, p.t)) || (close(a.0, p.t) && close(a.1, p.s))
        };
        for &a in &antipodal_solutions {
            prop_assert!(found.pairs.iter().any(|p| same(a, p)),
                "system solution {a:?} (distance {}) missed; found {:?}", distance(&curve, a.0, a.1), found.pairs);
        }
        for p in &found.pairs {
            if band(p.s, p.t) { continue; }
            prop_assert!(antipodal_solutions.iter().any(|&a| same(a, p)),
                "pair {p:?} is not a solution of the system {antipodal_solutions:?}");
            testkit::prop_assert_near!(p.distance, distance(&curve, p.s, p.t), 1e-12 * size);
        }
    }

    /// Every common tangent line of two curves is a zero of the system, and every zero of the
    /// system is reported.
    #[test]
    fn common_tangents_solve_the_system(
        seed1 in prop::collection::vec(0.0f64..1.0, 12..=20),
        seed2 in prop::collection::vec(0.0f64..1.0, 12..=20),
        off in (-2.5f64..2.5, -2.5f64..2.5),
    ) {
        let p1 = star(&seed1);
        let p2: Vec<[f64; 2]> = star(&seed2).iter().map(|p| [p[0] + off.0, p[1] + off.1]).collect();
        let (c1, c2) = (SplineCurve::periodic(3, &p1, None).unwrap(), SplineCurve::periodic(3, &p2, None).unwrap());
        let found = match antipodal::common_tangents(&c1, &c2, &Options::default()) {
            Ok(r) => r,
            Err(antipodal::Error::SelfIntersecting { .. } | antipodal::Error::Winding { .. } | antipodal::Error::Cusp { .. }) => return Ok(()),
            Err(e) => panic!("{e}"),
        };
        let (x1, y1) = coordinates(3, &p1);
        let (x2, y2) = coordinates(3, &p2);
        let (dx1, dy1, dx2, dy2) = (x1.deriv(), y1.deriv(), x2.deriv(), y2.deriv());
        let parallel = cross_form(&dx1, &dy2, &dy1, &dx2);
        // (C2(t) − C1(s)) × C1'(s) = x2(t)y1'(s) − y2(t)x1'(s) − (x1 y1' − y1 x1')(s)·1.
        let own = x1.mul(&dy1).unwrap().sub(&y1.mul(&dx1).unwrap()).unwrap();
        let on_line = TensorBSpline::sum_of_outer(&[(dy1.clone(), x2.clone()), (dx1.scale(-1.0), y2.clone()), (own.scale(-1.0), one(&x2))]).unwrap();
        let (n1, n2) = (p1.len() as f64, p2.len() as f64);
        let solutions = solve_on(&parallel, &on_line, [0.0, n1, 0.0, n2]);
        let close = |u: f64, v: f64, n: f64| { let d = (u - v).rem_euclid(n); d.min(n - d) < 1e-7 * n };
        for &(s, t) in &solutions {
            prop_assert!(found.lines.iter().any(|l| close(l.s, s, n1) && close(l.t, t, n2)),
                "system solution ({s}, {t}) missed; found {:?}", found.lines.iter().map(|l| (l.s, l.t)).collect::<Vec<_>>());
        }
        for l in &found.lines {
            prop_assert!(solutions.iter().any(|&(s, t)| close(l.s, s, n1) && close(l.t, t, n2)),
                "line ({}, {}) is not a solution of the system {solutions:?}", l.s, l.t);
        }
    }
}
