//! Headline figures of issue 42 (grasps with friction), each beside the figure it is judged
//! against, measured in the same run:
//! - every force-closure region of the papers' shapes at μ = 0.3, cold and from a prepared
//!   curve (warm), against the warm `antipodal` of the same curve (the target: at most 10
//!   times its time);
//! - how the cost grows with the number of control points of random periodic cubics, and
//!   with the number of sides of random star polygons (whose cells of two sides are affine);
//! - a batch of random outlines of 8–20 points on all cores, as periodic cubics through
//!   them and as polygons (the target: 10,000 in 10 s on two cores, so this batch of 100 in
//!   100 ms).
#![allow(missing_docs, clippy::unwrap_used)]

use antipodal::shapes::{Convexities, Ellipse, EllipticLemniscate, Limacon};
use antipodal::{prepare, Options, PlaneCurve, SplineCurve};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use grasp::{grasps, GraspOptions};
use rayon::prelude::*;
use std::time::Duration;
use testkit::stars::Star;

#[path = "common/outlines.rs"]
mod outlines;
use outlines::{cubics, outline_points, polygons};

/// The friction of the headline figures.
const MU: f64 = 0.3;

/// A random star-shaped periodic cubic B-spline with `n` control points (deterministic seed).
fn star(n: usize, seed: u64) -> SplineCurve {
    let points = Star::default().drawn(n, &mut testkit::rng(seed));
    SplineCurve::periodic(3, &points, None).unwrap()
}

/// Grasps of one curve, and the warm antipodal run it is compared with.
fn pair(c: &mut Criterion, name: &str, curve: &dyn PlaneCurve) {
    let opts = GraspOptions::friction(MU);
    let g = grasps(curve, &opts).unwrap();
    assert!(g.complete, "{name}");
    let prepared = prepare(curve);
    let warm = Options::default();
    c.bench_function(&format!("grasps_{name}"), |b| {
        b.iter(|| grasps(black_box(curve), black_box(&opts)).unwrap())
    });
    let prepared_grasps = grasp::prepare(curve).unwrap();
    c.bench_function(&format!("grasps_{name}_warm"), |b| {
        b.iter(|| prepared_grasps.grasps(black_box(&opts)).unwrap())
    });
    c.bench_function(&format!("grasps_{name}_antipodal_warm"), |b| {
        b.iter(|| prepared.antipodal(black_box(&warm)).unwrap())
    });
}

fn papers_shapes(c: &mut Criterion) {
    pair(
        c,
        "ellipse_3x2",
        &Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap(),
    );
    pair(c, "limacon_4_2.5", &Limacon::new(4.0, 2.5).unwrap());
    pair(
        c,
        "lemniscate_6_3",
        &EllipticLemniscate::new(6.0, 3.0).unwrap(),
    );
    pair(
        c,
        "convexities_4.5_0.2_4",
        &Convexities::new(4.5, 0.2, 4).unwrap(),
    );
}

fn growth(c: &mut Criterion) {
    let opts = GraspOptions::friction(MU);
    let mut g = c.benchmark_group("grasps_cubic_n");
    for n in [8usize, 12, 16, 20] {
        let curve = star(n, n as u64);
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| grasps(black_box(&curve), black_box(&opts)).unwrap())
        });
    }
    g.finish();
    let mut g = c.benchmark_group("grasps_polygon_n");
    for n in [8usize, 16, 32, 64] {
        let points = Star::default().drawn(n, &mut testkit::rng(n as u64));
        let polygon = testkit::outlines::polygon(&points);
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| grasps(black_box(&polygon), black_box(&opts)).unwrap())
        });
    }
    g.finish();
}

fn batch(c: &mut Criterion) {
    let outlines = outline_points();
    batch_of(c, "outlines", &cubics(&outlines));
    // The same outlines read as polygons (the straight sides' cells affine).
    batch_of(c, "polygons", &polygons(&outlines));
}

/// The grasps of every one of `items` on all cores.
fn batch_of<T>(c: &mut Criterion, name: &str, items: &[T])
where
    T: Sync,
    for<'a> &'a T: Into<curve::Boundary<'a>>,
{
    let opts = GraspOptions::friction(MU);
    c.bench_function(&format!("grasps_batch_100_{name}_all_cores"), |b| {
        b.iter(|| {
            items
                .par_iter()
                .map(|item| grasps(item, &opts).map(|g| g.regions.len()).unwrap_or(0))
                .sum::<usize>()
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).sample_size(20);
    targets = papers_shapes, growth, batch
}
criterion_main!(benches);
