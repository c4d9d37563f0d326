//! Headline figures of the `antipodal` issue: every antipodal pair of the papers' shapes and of
//! random periodic cubic B-splines, at the default tolerance, on one core: warm (on a prepared
//! curve) and cold (`_cold`: preparing the curve and answering once). (Jia reports about
//! 10 ms per shape on a 933 MHz Pentium III; IRIT 11 takes 1.3–5 ms; the target is ≤ 20 µs.)
//! The convexities family `m = 3 … 12` shows how the cost grows with the number of pairs.
#![allow(missing_docs, clippy::unwrap_used)]

use antipodal::shapes::{Convexities, Ellipse, EllipticLemniscate, Limacon};
use antipodal::{antipodal, prepare, Options, PlaneCurve, SplineCurve};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use testkit::stars::Star;

/// A random star-shaped periodic cubic B-spline with `n` control points (deterministic seed).
fn star(n: usize, seed: u64) -> SplineCurve {
    let points = Star::default().drawn(n, &mut testkit::rng(seed));
    SplineCurve::periodic(3, &points, None).unwrap()
}

/// A warm run (on the prepared curve) and a cold one (preparing and answering once).
fn bench_one(c: &mut Criterion, name: &str, curve: &dyn PlaneCurve) {
    let opts = Options::default();
    // The run must succeed and be complete before it is timed.
    let prepared = prepare(curve);
    let r = prepared.antipodal(&opts).unwrap();
    assert!(r.complete, "{name}");
    c.bench_function(name, |b| {
        b.iter(|| prepared.antipodal(black_box(&opts)).unwrap())
    });
    c.bench_function(&format!("{name}_cold"), |b| {
        b.iter(|| antipodal(black_box(curve), black_box(&opts)).unwrap())
    });
}

fn papers_shapes(c: &mut Criterion) {
    bench_one(
        c,
        "antipodal_ellipse_3x2",
        &Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap(),
    );
    bench_one(
        c,
        "antipodal_limacon_4_2.5",
        &Limacon::new(4.0, 2.5).unwrap(),
    );
    bench_one(
        c,
        "antipodal_lemniscate_6_3",
        &EllipticLemniscate::new(6.0, 3.0).unwrap(),
    );
    bench_one(
        c,
        "antipodal_convexities_3_0.5_3",
        &Convexities::new(3.0, 0.5, 3).unwrap(),
    );
    bench_one(
        c,
        "antipodal_convexities_4.5_0.2_4",
        &Convexities::new(4.5, 0.2, 4).unwrap(),
    );
}

fn random_splines(c: &mut Criterion) {
    bench_one(c, "antipodal_bspline_cubic_8", &star(8, 7));
    bench_one(c, "antipodal_bspline_cubic_20", &star(20, 11));
}

/// Convexities `r = 4.5 / (1 + 0.2 cos mφ)` (the papers' m = 4 shape, for m = 3 … 12): 2m
/// inflections and a number of antipodal pairs growing as about 2m². (With ε = 0.5 the m = 11
/// member has nearly double pairs on which the march creeps; it is reported incomplete.)
fn convexities_family(c: &mut Criterion) {
    let opts = Options::default();
    let mut g = c.benchmark_group("antipodal_convexities_m");
    for m in 3..=12u32 {
        let curve = Convexities::new(4.5, 0.2, m).unwrap();
        let prepared = prepare(&curve);
        let r = prepared.antipodal(&opts).unwrap();
        assert!(r.complete);
        g.bench_with_input(BenchmarkId::from_parameter(m), &m, |b, _| {
            b.iter(|| prepared.antipodal(black_box(&opts)).unwrap())
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .sample_size(20);
    targets = papers_shapes, random_splines, convexities_family
}
criterion_main!(benches);
