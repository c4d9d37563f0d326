//! Move 6 (issue 41), zeroset's first step: a profile of one spline segment without a corner
//! is the curve it is. On the bisector fixtures the tool takes the curve's path on, and on
//! random open and periodic splines, the one entry (`bisector`, `self_bisector`) answers a
//! spline given as a profile as it answers the spline given as a curve (on its rational
//! form), for every method, trimmed or not: the same points exactly, the
//! same parameters to within [`PARAM_AGREEMENT`] of the domain (the profile's are shares of
//! it), a periodic spline on its whole curve. And the tool writes the curve documents it wrote
//! before, byte for byte.
#![allow(clippy::unwrap_used)]

use curve::{ExactCurve, Profile, Segment, SegmentKind, SplineCurve};
use curvekit::commands::BisectorFound;
use curvekit::io::{curve_profile, parse_curve, Curve};
use proptest::prelude::*;
use zeroset::{Bisector, BisectorOptions, Method};

/// The parameters of the two entries agree to this share of the domain: the profile's is the
/// curve's share of the domain, one rounding each way.
const PARAM_AGREEMENT: f64 = 1e-12;

/// The fixture pairs whose bisector the tool takes on the curves' path.
const PAIRS: [(&str, &str); 6] = [
    ("bisector-fig2-quadratic", "bisector-fig2-line"),
    ("bisector-fig3-quadratic1", "bisector-fig3-quadratic2"),
    ("bisector-fig6-cubic-bspline", "bisector-fig6-line"),
    ("bisector-fig7-quadratic1", "bisector-fig7-quadratic2"),
    ("bisector-bench-cubic1", "bisector-bench-cubic2"),
    ("bisector-cubic", "bisector-quadratic"),
];

/// The fixtures whose self-bisector the tool takes on the curve's path.
const SELF: [&str; 13] = [
    "bisector-fig4-quadratic-bspline",
    "bisector-fig5-cubic-bspline",
    "bisector-fig6-cubic-bspline",
    "bisector-cubic",
    "bisector-quadratic",
    "bisector-fig2-quadratic",
    "bezier_s",
    "open_quadratic",
    "open_nurbs",
    "clamped_closed",
    "periodic_cubic",
    "periodic_nurbs",
    "antipodal-bspline-wavy",
];

/// The periodic fixtures: their profiles' segments keep the spline as their whole curve.
const PERIODIC: [&str; 3] = ["periodic_cubic", "periodic_nurbs", "antipodal-bspline-wavy"];

fn fixture(name: &str) -> Curve {
    let text = std::fs::read_to_string(format!("fixtures/{name}.json")).unwrap();
    parse_curve(name, &text).unwrap()
}

fn profile(c: &Curve) -> Profile {
    curve_profile(c).unwrap().unwrap()
}

/// Every method, trimmed and not.
fn all_options() -> Vec<BisectorOptions> {
    let methods = [Method::F1, Method::F2, Method::F3];
    methods
        .iter()
        .flat_map(|&method| {
            [false, true].map(|trimmed| BisectorOptions {
                method,
                trimmed,
                ..Default::default()
            })
        })
        .collect()
}

/// Where the profile's bisector (in its parameters, [0, 1) per segment) and the curve's (on
/// the curves' `domains`) differ, if they do.
fn difference(
    on_profile: &Bisector,
    on_curve: &Bisector,
    domains: [(f64, f64); 2],
) -> Option<String> {
    let counts = |b: &Bisector| (b.branches.len(), b.singular.len(), b.isolated.len());
    if counts(on_profile) != counts(on_curve) || on_profile.complete != on_curve.complete {
        return Some(format!(
            "counts {:?} against {:?}, complete {} against {}",
            counts(on_profile),
            counts(on_curve),
            on_profile.complete,
            on_curve.complete
        ));
    }
    let same_tr = |p: &[f64; 2], c: &[f64; 2]| {
        (0..2).all(|k| {
            let (a, b) = domains[k];
            (a + p[k] * (b - a) - c[k]).abs() <= PARAM_AGREEMENT * (b - a)
        })
    };
    for (p, c) in on_profile.branches.iter().zip(&on_curve.branches) {
        if p.xy != c.xy {
            return Some(format!("branch points {:?} against {:?}", p.xy, c.xy));
        }
        if let Some((p, c)) = p.tr.iter().zip(&c.tr).find(|(p, c)| !same_tr(p, c)) {
            return Some(format!("branch parameters {p:?} against {c:?}"));
        }
    }
    let points = |b: &Bisector| {
        let list = b.singular.iter().chain(&b.isolated);
        list.map(|p| (p.tr, p.xy)).collect::<Vec<_>>()
    };
    for ((ptr, pxy), (ctr, cxy)) in points(on_profile).iter().zip(&points(on_curve)) {
        if pxy != cxy || !same_tr(ptr, ctr) {
            return Some(format!("point {ptr:?} {pxy:?} against {ctr:?} {cxy:?}"));
        }
    }
    None
}

/// The profile entry against the curve entry on `a` and `b` (`b` `None`: the self-bisector).
fn compare(
    a: (&Profile, &SplineCurve),
    b: Option<(&Profile, &SplineCurve)>,
    opts: &BisectorOptions,
) -> Option<String> {
    let (on_profile, on_curve) = match b {
        Some(b) => (
            zeroset::bisector(a.0, b.0, opts),
            zeroset::bisector(a.1, b.1, opts),
        ),
        None => (
            zeroset::self_bisector(a.0, opts),
            zeroset::self_bisector(a.1, opts),
        ),
    };
    let domain = |c: &SplineCurve| curve::ParamCurve::domain(c);
    let domains = [domain(a.1), domain(b.unwrap_or(a).1)];
    match (on_profile, on_curve) {
        (Ok(p), Ok(c)) => difference(&p.without_sites(), &c, domains),
        (Err(p), Err(c)) if p.to_string() == c.to_string() => None,
        (p, c) => Some(format!("results {:?} against {:?}", p.err(), c.err())),
    }
}

/// A spline fixture's curve as read.
fn spline(c: &Curve) -> &SplineCurve {
    match &c.shape {
        curvekit::io::CurveKind::Spline(s) => &s.plane,
        _ => panic!("{} is no spline", c.file),
    }
}

#[test]
fn fixtures_profile_bisectors_are_the_curves() {
    for opts in all_options() {
        for (a, b) in PAIRS {
            let (ca, cb) = (fixture(a), fixture(b));
            let (pa, pb) = (profile(&ca), profile(&cb));
            let found = compare((&pa, spline(&ca)), Some((&pb, spline(&cb))), &opts);
            assert_eq!(found, None, "{a} + {b}, {opts:?}");
        }
        for name in SELF {
            let c = fixture(name);
            let found = compare((&profile(&c), spline(&c)), None, &opts);
            assert_eq!(found, None, "self {name}, {opts:?}");
        }
    }
}

#[test]
fn periodic_fixtures_run_on_their_whole_curve() {
    for name in PERIODIC {
        let c = fixture(name);
        let p = profile(&c);
        let whole = p.segments()[0].whole_curve();
        assert!(
            matches!(whole, Some(ExactCurve::Spline(s)) if s.as_ref() == spline(&c)),
            "{name}"
        );
        let opts = BisectorOptions::default();
        let on_profile = zeroset::self_bisector(&p, &opts).unwrap().without_sites();
        let on_curve = zeroset::self_bisector(spline(&c), &opts).unwrap();
        let points = |b: &Bisector| {
            b.branches
                .iter()
                .map(|br| br.xy.clone())
                .collect::<Vec<_>>()
        };
        assert_eq!(points(&on_profile), points(&on_curve), "{name}");
    }
}

/// The tool's documents of the curves' bisectors: the curve path's, byte for byte.
#[test]
fn tool_writes_the_curve_documents() {
    let options = [
        BisectorOptions::default(),
        BisectorOptions {
            trimmed: true,
            ..Default::default()
        },
        BisectorOptions {
            method: Method::F1,
            ..Default::default()
        },
    ];
    let cases = PAIRS
        .iter()
        .map(|&(a, b)| (fixture(a), Some(fixture(b))))
        .chain(SELF.iter().map(|&a| (fixture(a), None)));
    for (a, b) in cases {
        for opts in &options {
            let found = curvekit::commands::bisector(&a, b.as_ref(), opts).unwrap();
            assert!(matches!(found, BisectorFound::Curve(_)), "{}", a.file);
            // (A spline's document parameter is its own.)
            let on_curve = match &b {
                Some(b) => zeroset::bisector(a.plane_curve(), b.plane_curve(), opts),
                None => zeroset::self_bisector(a.plane_curve(), opts),
            };
            let want = serde_json::to_string(&BisectorFound::Curve(on_curve.unwrap())).unwrap();
            assert_eq!(serde_json::to_string(&found).unwrap(), want, "{}", a.file);
        }
    }
}

/// An open cubic B-spline on a random star's polygon about `center`, and its profile (`None`
/// where the spline crosses itself).
fn open_star(seed: &[f64], center: [f64; 2]) -> Option<(Profile, SplineCurve)> {
    let star = testkit::stars::Star {
        center,
        ..Default::default()
    };
    let points = star.points_from_seed(seed);
    let c = SplineCurve::clamped(3, &points, None, None).unwrap();
    let segment = Segment::spline(SegmentKind::BSpline, c.clone()).unwrap();
    let domain = curve::ParamCurve::domain(&c);
    Some((Profile::of_curve(segment, domain).ok()?, c))
}

/// A periodic cubic B-spline on a random star's polygon about `center`, and its profile.
fn periodic_star(seed: &[f64], center: [f64; 2]) -> Option<(Profile, SplineCurve)> {
    let star = testkit::stars::Star {
        center,
        ..Default::default()
    };
    let c = SplineCurve::periodic(3, &star.points_from_seed(seed), None).unwrap();
    let segment = Segment::periodic_spline(SegmentKind::BSpline, &c).unwrap();
    let domain = curve::ParamCurve::domain(&c);
    Some((Profile::of_curve(segment, domain).ok()?, c))
}

fn options(method: usize, trimmed: bool) -> BisectorOptions {
    BisectorOptions {
        method: [Method::F1, Method::F2, Method::F3][method],
        trimmed,
        ..Default::default()
    }
}

/// The profile bisector of `a` and `b`, and the self-bisector of `a`, are the curves'.
fn check_pair_and_self(
    a: &(Profile, SplineCurve),
    b: &(Profile, SplineCurve),
    opts: &BisectorOptions,
) -> Result<(), TestCaseError> {
    let pair = compare((&a.0, &a.1), Some((&b.0, &b.1)), opts);
    prop_assert_eq!(pair, None);
    prop_assert_eq!(compare((&a.0, &a.1), None, opts), None);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Two random open cubics apart, and the self-bisector of one.
    #[test]
    fn random_open_splines(
        seed_a in prop::collection::vec(0.0f64..1.0, 10..=14),
        seed_b in prop::collection::vec(0.0f64..1.0, 10..=14),
        method in 0usize..3,
        trimmed: bool,
    ) {
        let a = open_star(&seed_a, [0.0, 0.0]);
        let b = open_star(&seed_b, [2.6, 0.4]);
        let (Some(a), Some(b)) = (a, b) else { return Ok(()) };
        check_pair_and_self(&a, &b, &options(method, trimmed))?;
    }

    /// Two random periodic cubics apart, and the self-bisector of one.
    #[test]
    fn random_periodic_splines(
        seed_a in prop::collection::vec(0.0f64..1.0, 10..=16),
        seed_b in prop::collection::vec(0.0f64..1.0, 10..=16),
        method in 0usize..3,
        trimmed: bool,
    ) {
        let a = periodic_star(&seed_a, [0.0, 0.0]);
        let b = periodic_star(&seed_b, [2.6, 0.4]);
        let (Some(a), Some(b)) = (a, b) else { return Ok(()) };
        prop_assert!(a.0.segments()[0].whole_curve().is_some());
        check_pair_and_self(&a, &b, &options(method, trimmed))?;
    }
}
