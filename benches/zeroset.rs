//! Headline figures of the `zeroset` issue: bisectors by Elber and Kim's zero sets, on one core.
//! (Elber and Kim report seconds to a minute on a 1997 workstation; IRIT 11 needs 2.5 ms at
//! tolerance 0.1 and 30 ms at 0.01 for the two quadratics of figure 3, 20 ms to 0.2 s for the
//! self-bisector of an open cubic. Targets: ≤ 300 µs for two cubics, ≤ 2 ms for the
//! self-bisector of a cubic B-spline with seven control points.)
//!
//! **What "to 1e-9" means here.** The parameter tolerance `tol = 1e-9`: the subdivision
//! resolves the zero set down to patches of 1e-9 of the domain (a loop or a pair of branches
//! closer than that would become an isolated or singular point), every reported vertex is
//! refined onto `F = 0` by Newton to rounding, and every reported bisector point satisfies the
//! three bisector conditions to a relative residual ≤ 1e-9 (`zeroset::RESIDUAL`). That is
//! what IRIT's subdivision tolerance controls (0.1 and 0.01 above), far tighter. The spacing
//! of the vertices is a separate choice, the chord tolerance: the default 1e-3 of the
//! bounding-box diagonal, as `curvekit bisector` uses. A denser polyline costs in proportion
//! to its vertices, which `two_cubic_beziers_chord_1e-6` shows (~10× the vertices). A chord
//! tolerance of 1e-9 would mean ~10⁵ vertices (≈ 0.1–0.4 s): a polyline is the wrong
//! output at that density.
//!
//! The inputs are the fixture files, so `curvekit bisector FILE1 [FILE2] --tol 1e-9 --time`
//! measures the same computations (it reports the median of repeated runs in-process).
#![allow(missing_docs, clippy::unwrap_used)]

use bspline::tensor::TensorBSpline;
use bspline::BSpline;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use curve::SplineCurve;
use curvekit::io::parse_curve;
use std::time::Duration;
use zeroset::{
    bisector, bisector_function, self_bisector, zero_set, BisectorOptions, Method, ZeroSetOptions,
};

/// Parameter tolerance of every bench (see the module docs).
const TOL: f64 = 1e-9;

fn parsed(name: &str, text: &str) -> SplineCurve {
    SplineCurve::new(parse_curve(name, text).unwrap().rational().unwrap().clone()).unwrap()
}

/// The spline of fixture `$name` (`fixtures/$name.json`, embedded).
macro_rules! fixture {
    ($name:literal) => {
        parsed($name, include_str!(concat!("../fixtures/", $name, ".json")))
    };
}

fn opts() -> BisectorOptions {
    BisectorOptions {
        settings: numeric::tolerance::Settings::new(
            TOL,
            numeric::tolerance::DEFAULT_CHORD_TOL,
            None,
        )
        .expect("settings in range"),
        ..BisectorOptions::default()
    }
}

fn bisectors(c: &mut Criterion) {
    let cub1 = fixture!("bisector-bench-cubic1");
    let cub2 = fixture!("bisector-bench-cubic2");
    let quad1 = fixture!("bisector-fig3-quadratic1");
    let quad2 = fixture!("bisector-fig3-quadratic2");
    let seven = fixture!("bisector-fig5-cubic-bspline");
    let o = opts();
    // The results the figures are for (complete, and the branch counts of the demo).
    let check = |b: zeroset::Bisector, n: usize| {
        assert!(b.complete);
        assert_eq!(b.branches.len(), n);
    };
    check(bisector(&cub1, &cub2, &o).unwrap(), 2);
    check(bisector(&quad1, &quad2, &o).unwrap(), 5);
    check(self_bisector(&seven, &o).unwrap(), 4);

    let mut g = c.benchmark_group("bisector");
    g.bench_function("two_cubic_beziers", |b| {
        b.iter(|| bisector(black_box(&cub1), black_box(&cub2), &o).unwrap())
    });
    let dense = BisectorOptions {
        settings: numeric::tolerance::Settings::new(
            numeric::tolerance::DEFAULT_PARAM_TOL,
            1e-6,
            None,
        )
        .expect("settings in range"),
        ..o
    };
    g.bench_function("two_cubic_beziers_chord_1e-6", |b| {
        b.iter(|| bisector(black_box(&cub1), black_box(&cub2), &dense).unwrap())
    });
    g.bench_function("two_quadratic_beziers_fig3", |b| {
        b.iter(|| bisector(black_box(&quad1), black_box(&quad2), &o).unwrap())
    });
    g.bench_function("self_cubic_bspline_7_points_fig5", |b| {
        b.iter(|| self_bisector(black_box(&seven), &o).unwrap())
    });
    g.bench_function("f3_function_two_cubic_beziers", |b| {
        b.iter(|| {
            bisector_function(black_box(cub1.curve()), black_box(cub2.curve()), Method::F3).unwrap()
        })
    });
    g.finish();
}

/// `(t − cx)² + (r − cy)² − ρ²` on the unit square.
fn circle(cx: f64, cy: f64, rho: f64) -> TensorBSpline {
    let lin = |c: f64| {
        BSpline::bezier(1, vec![-c, 1.0 - c])
            .unwrap()
            .reparam(0.0, 1.0)
            .unwrap()
    };
    let one = BSpline::constant(&[1.0], 0, 0.0, 1.0).unwrap();
    let (lt, lr) = (lin(cx), lin(cy));
    TensorBSpline::sum_of_outer(&[
        (lt.mul(&lt).unwrap(), one.clone()),
        (one.clone(), lr.mul(&lr).unwrap()),
        (BSpline::constant(&[-rho * rho], 0, 0.0, 1.0).unwrap(), one),
    ])
    .unwrap()
}

fn known_zero_set(c: &mut Criterion) {
    // Three nested circles (radii 0.3, 0.1, 0.004) and a separate one of radius 0.002: a
    // degree (8, 8) function whose zero set is four loops, two of them tiny.
    let mut f = circle(0.45, 0.5, 0.3);
    for r in [0.1, 0.004] {
        f = f.mul(&circle(0.45, 0.5, r)).unwrap();
    }
    f = f.mul(&circle(0.85, 0.15, 0.002)).unwrap();
    let o = ZeroSetOptions::default()
        .tolerance(numeric::tolerance::ParamTol::new(TOL).expect("in range"));
    let z = zero_set(&f, &o).unwrap();
    assert!(z.complete && z.branches.len() == 4 && z.branches.iter().all(|b| b.closed));
    c.bench_function("zero_set_four_nested_and_tiny_circles", |b| {
        b.iter(|| zero_set(black_box(&f), &o).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    targets = bisectors, known_zero_set
}
criterion_main!(benches);
