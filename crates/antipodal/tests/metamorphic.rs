//! Metamorphic properties: the same curve moved, scaled, turned, run backwards, started
//! elsewhere or split gives the same answer. A scaling by a power of two leaves the numbers the
//! curve is computed from as they were: the same answer, certificate and all. Moving the
//! curve far away (by amounts its coordinates absorb exactly), quarter turns, reversal and a
//! shifted seam keep the curve but change the numbers, and a turn by any angle, a scaling by
//! 3.7 and a split into Bézier pieces round them: two certified answers must agree (every
//! pair and inflection mapped onto its image), and a certificate may be lost only rarely.
#![allow(clippy::unwrap_used)]

use antipodal::{antipodal, Antipodal, Error, Options, PairType, SplineCurve};
use numeric::certificate::Verdict;
mod common;

use common::cases;
use proptest::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use testkit::stars::Star;

/// A random curve: a star-shaped control polygon with coordinates on a grid of `2^-20` (so that
/// translations up to `2^32` and scalings by powers of two are exact), periodic of degree
/// `degree`, rational with weights on a grid of `2^-6` when given.
#[derive(Debug, Clone)]
struct Spec {
    degree: usize,
    points: Vec<[f64; 2]>,
    weights: Option<Vec<f64>>,
}

impl Spec {
    fn curve(&self) -> Option<SplineCurve> {
        SplineCurve::periodic(self.degree, &self.points, self.weights.as_deref()).ok()
    }

    /// The same data moved by `f` (points) and permuted by `order` (indices).
    fn mapped(&self, f: impl Fn([f64; 2]) -> [f64; 2], order: &[usize]) -> Spec {
        Spec {
            degree: self.degree,
            points: order.iter().map(|&i| f(self.points[i])).collect(),
            weights: self
                .weights
                .as_ref()
                .map(|w| order.iter().map(|&i| w[i]).collect()),
        }
    }

    fn identity(&self) -> Vec<usize> {
        (0..self.points.len()).collect()
    }
}

fn grid(x: f64, bits: i32) -> f64 {
    let s = 2f64.powi(bits);
    (x * s).round() / s
}

fn spec(degrees: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Spec> {
    degrees
        .prop_flat_map(|p| (Just(p), (p + 3).max(6)..=(p + 14).max(20)))
        .prop_flat_map(|(p, n)| {
            (
                Just(p),
                proptest::collection::vec((0.0f64..1.0, 0.0f64..1.0), n),
                proptest::option::of(proptest::collection::vec(0.5f64..2.0, n)),
            )
        })
        .prop_map(|(degree, seed, weights)| {
            let points = Star::default()
                .points(&seed)
                .into_iter()
                .map(|p| [grid(p[0], 20), grid(p[1], 20)])
                .collect();
            let weights = weights.map(|w| w.iter().map(|&x| grid(x, 6)).collect());
            Spec {
                degree,
                points,
                weights,
            }
        })
}

/// The size of the control polygon's box (the unit of the geometric tolerances).
fn size(spec: &Spec) -> f64 {
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for p in &spec.points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (hi[0] - lo[0]).max(hi[1] - lo[1])
}

/// The same curve split into Bézier pieces: clamped at its seam, every knot inserted to full
/// multiplicity (a curve only C⁰ as far as its knots tell, given by homogeneous coefficients
/// that the insertion rounded).
fn split(spec: &Spec) -> Option<SplineCurve> {
    let p = spec.degree;
    let hom: Vec<f64> = spec
        .points
        .iter()
        .enumerate()
        .flat_map(|(i, q)| {
            let w = spec.weights.as_ref().map_or(1.0, |w| w[i]);
            [q[0] * w, q[1] * w, w]
        })
        .collect();
    let clamped = bspline::BSpline::periodic(p, 3, hom).ok()?.clamped();
    let (a, b) = clamped.domain();
    let knots: Vec<f64> = (a as usize + 1..b as usize)
        .flat_map(|k| std::iter::repeat_n(k as f64, p - 1))
        .collect();
    let pieces = clamped.refine(&knots).ok()?;
    SplineCurve::new(bspline::Rational::from_homogeneous(pieces).ok()?).ok()
}

/// The answer for a spec (`None` where the curve is refused: not simple, singular).
fn answer(spec: &Spec) -> Option<Antipodal> {
    answer_for(&spec.curve()?)
}

fn answer_for(curve: &SplineCurve) -> Option<Antipodal> {
    match antipodal(curve, &Options::default()) {
        Ok(r) => Some(r),
        Err(Error::SelfIntersecting { .. } | Error::Winding { .. } | Error::Cusp { .. }) => None,
        Err(e) => panic!("{e}"),
    }
}

fn types(r: &Antipodal) -> Vec<Option<PairType>> {
    let mut t: Vec<Option<PairType>> = r.pairs.iter().map(|p| p.kind).collect();
    t.sort_by_key(|k| k.map(|k| k as u8));
    t
}

/// Every pair and inflection of `a`, mapped by `f`, is one of `b`'s (points within `tol`), and
/// the counts agree.
fn same_answer(
    a: &Antipodal,
    b: &Antipodal,
    f: &impl Fn([f64; 2]) -> [f64; 2],
    tol: f64,
) -> Result<(), String> {
    let (na, nb) = (
        (a.pairs.len(), a.inflections.len(), a.families.len()),
        (b.pairs.len(), b.inflections.len(), b.families.len()),
    );
    if na != nb {
        return Err(format!(
            "counts (pairs, inflections, families) {na:?} vs {nb:?}"
        ));
    }
    if types(a) != types(b) {
        return Err(format!("types {:?} vs {:?}", types(a), types(b)));
    }
    let near = |x: [f64; 2], y: [f64; 2]| (x[0] - y[0]).hypot(x[1] - y[1]) <= tol;
    for p in &a.pairs {
        let (fp, fq) = (f(p.p), f(p.q));
        let hit = b
            .pairs
            .iter()
            .any(|q| (near(fp, q.p) && near(fq, q.q)) || (near(fp, q.q) && near(fq, q.p)));
        if !hit {
            return Err(format!("pair {p:?} has no image among {:?}", b.pairs));
        }
    }
    for i in &a.inflections {
        if !b.inflections.iter().any(|j| near(f(i.p), j.p)) {
            return Err(format!(
                "inflection {i:?} has no image among {:?}",
                b.inflections
            ));
        }
    }
    Ok(())
}

/// Compared pairs of answers (the properties must not be vacuous).
static COMPARED: AtomicUsize = AtomicUsize::new(0);
/// Answers to the same curve computed differently that differ in certification or in
/// refusal (allowed where precision is borderline; counted, and bounded below).
static LOST: AtomicUsize = AtomicUsize::new(0);

/// How a transform acts on the computation.
#[derive(Clone, Copy, PartialEq)]
enum Transform {
    /// The curve's local data are the same numbers (a scaling by a power of two: the frame
    /// undoes it exactly): the same answer, certification and all.
    Identical,
    /// The same curve, computed from other numbers (moved far away, turned by a quarter,
    /// reversed, started elsewhere): two certified answers agree.
    SameCurve,
    /// A curve the rounding of the data moved (a turn by any angle, a scaling by 3.7): two
    /// certified answers agree to the rounding.
    Rounded,
}

/// Checks the answer for `t` against that for `s` under the point map `f` (see
/// [`Transform`]).
fn check(
    s: &Spec,
    t: &Spec,
    f: impl Fn([f64; 2]) -> [f64; 2],
    tol: f64,
    how: Transform,
) -> Result<(), TestCaseError> {
    check_answers(s, answer(s), answer(t), f, tol, how)
}

/// [`check`] on the answers.
fn check_answers(
    s: &Spec,
    a: Option<Antipodal>,
    b: Option<Antipodal>,
    f: impl Fn([f64; 2]) -> [f64; 2],
    tol: f64,
    how: Transform,
) -> Result<(), TestCaseError> {
    let (Some(a), Some(b)) = (a.as_ref(), b.as_ref()) else {
        if a.is_some() != b.is_some() {
            prop_assert!(how != Transform::Identical, "refused one way only: {:?}", s);
            LOST.fetch_add(1, Ordering::Relaxed);
        }
        return Ok(());
    };
    COMPARED.fetch_add(1, Ordering::Relaxed);
    if how == Transform::Identical {
        prop_assert_eq!(
            (a.certified(), a.complete),
            (b.certified(), b.complete),
            "{:?}\nvs\n{:?}",
            a,
            b
        );
    } else if a.certified() != b.certified() {
        LOST.fetch_add(1, Ordering::Relaxed);
        return Ok(());
    }
    if a.certified() && a.complete {
        let r = same_answer(a, b, &f, tol);
        prop_assert!(r.is_ok(), "{}\n{:?}", r.unwrap_err(), s);
    }
    Ok(())
}

/// `s` scaled by 2^`k` has the identical answer (scaled), and moved by `by` (whole numbers,
/// of one size either way) then scaled, the same curve's.
fn scaled_and_moved(s: &Spec, k: i32, by: [f64; 2]) -> Result<(), TestCaseError> {
    let scale = 2f64.powi(k);
    let scaled = |p: [f64; 2]| [p[0] * scale, p[1] * scale];
    let tol = 1e-9 * size(s) * scale;
    check(
        s,
        &s.mapped(scaled, &s.identity()),
        scaled,
        tol,
        Transform::Identical,
    )?;
    let moved = |p: [f64; 2]| [(p[0] + by[0]) * scale, (p[1] + by[1]) * scale];
    let tol = tol + 4.0 * f64::EPSILON * by[0].abs().max(by[1].abs()) * scale;
    check(
        s,
        &s.mapped(moved, &s.identity()),
        moved,
        tol,
        Transform::SameCurve,
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(120), ..ProptestConfig::default() })]

    /// Scaling by powers of two from 2^-600 to 2^600 (identical), and moving far from the
    /// origin as well (up to 1e9 times the size, exact on the grid).
    #[test]
    fn translation_and_scaling(
        s in spec(2..=6),
        offset in prop_oneof![-1e9f64..1e9, Just(1e9), Just(-3.3e7)],
        k in -600i32..600,
    ) {
        let offset = grid(offset, 0);
        scaled_and_moved(&s, k, [offset, -offset])?;
    }

    /// Quarter turns, reversal and a shifted seam (the same curve), and a turn by any angle,
    /// a scaling by 3.7 and a split into Bézier pieces (rounding the data).
    #[test]
    fn turns_reversal_and_seam(
        s in spec(2..=6),
        shift in 0usize..64,
        angle in 0.0f64..std::f64::consts::TAU,
    ) {
        let n = s.points.len();
        let tol = 1e-9 * size(&s);
        let same = Transform::SameCurve;
        let quarter = |p: [f64; 2]| [-p[1], p[0]];
        check(&s, &s.mapped(quarter, &s.identity()), quarter, tol, same)?;
        let reversed: Vec<usize> = (0..n).rev().collect();
        check(&s, &s.mapped(|p| p, &reversed), |p| p, tol, same)?;
        let shifted: Vec<usize> = (0..n).map(|i| (i + shift) % n).collect();
        check(&s, &s.mapped(|p| p, &shifted), |p| p, tol, same)?;
        let (sn, cs) = angle.sin_cos();
        let turn = |p: [f64; 2]| [cs * p[0] - sn * p[1], sn * p[0] + cs * p[1]];
        check(&s, &s.mapped(turn, &s.identity()), turn, 1e-7 * size(&s), Transform::Rounded)?;
        let grow = |p: [f64; 2]| [3.7 * p[0], 3.7 * p[1]];
        let tol = 1e-7 * 3.7 * size(&s);
        check(&s, &s.mapped(grow, &s.identity()), grow, tol, Transform::Rounded)?;
        let pieces = split(&s).and_then(|c| answer_for(&c));
        check_answers(&s, answer(&s), pieces, |p| p, 1e-7 * size(&s), Transform::Rounded)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(12), ..ProptestConfig::default() })]

    /// High degrees (up to 64) scaled, and moved far away.
    #[test]
    fn high_degrees(
        s in spec(20..=64),
        offset in -1e9f64..1e9,
        k in -300i32..300,
    ) {
        let offset = grid(offset, 0);
        scaled_and_moved(&s, k, [offset, offset])?;
    }
}

/// The properties compare answers on most cases, and computing the same curve from other
/// numbers rarely costs a certificate.
#[test]
fn metamorphic_properties_compare_answers() {
    translation_and_scaling();
    turns_reversal_and_seam();
    let compared = COMPARED.load(Ordering::Relaxed);
    let lost = LOST.load(Ordering::Relaxed);
    assert!(compared >= 400, "only {compared} pairs of answers compared");
    assert!(
        20 * lost <= compared,
        "{lost} of {compared} lost a certificate"
    );
    eprintln!("{compared} pairs of answers compared, {lost} lost a certificate or were refused");
}
