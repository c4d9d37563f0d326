//! Headline figures of the `bspline` issue: exact products, curvature numerators and certified
//! root isolation. (The reference is IRIT 11: product of two cubic B-splines with 10 control
//! points each 26–33 µs, with 40 each 147–474 µs.)
#![allow(missing_docs, clippy::unwrap_used)]

use bspline::roots::{find_roots, RootOptions};
use bspline::{symbolic, BSpline, Rational};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};

/// A cubic scalar B-spline with `n` control points, non-uniform simple interior knots.
fn cubic(n: usize, seed: f64) -> BSpline {
    let interior = n - 4;
    let mut knots = vec![0.0; 4];
    let mut acc = 0.0;
    let gaps: Vec<f64> = (0..=interior)
        .map(|i| 1.0 + 0.5 * ((i as f64 + seed) * 1.7).sin())
        .collect();
    let total: f64 = gaps.iter().sum();
    for g in &gaps[..interior] {
        acc += g;
        knots.push(acc / total);
    }
    knots.extend([1.0; 4]);
    let coefs = (0..n)
        .map(|i| ((i as f64) * 0.9 + seed).sin() * 3.0)
        .collect();
    BSpline::new(3, knots, 1, coefs).unwrap()
}

fn products(c: &mut Criterion) {
    let mut g = c.benchmark_group("product_cubic_x_cubic");
    for n in [10, 40, 68] {
        // 68 control points = 64 interior knots. The factors have different knots, so the
        // product's knot vector is the union of both (minimal multiplicities).
        let (a, b) = (cubic(n, 0.3), cubic(n, 1.1));
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |bch, _| {
            bch.iter(|| black_box(&a).mul(black_box(&b)).unwrap())
        });
    }
    g.finish();
}

fn curvature(c: &mut Criterion) {
    let pts: Vec<f64> = (0..32)
        .flat_map(|i| {
            let t = i as f64 / 32.0 * std::f64::consts::TAU;
            let r = 3.0 + 0.8 * (5.0 * t).cos();
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    let curve = Rational::polynomial(&BSpline::periodic(3, 2, pts).unwrap().clamped());
    c.bench_function("curvature_numerator_closed_cubic_32", |b| {
        b.iter(|| symbolic::curvature_numerator(black_box(&curve)).unwrap())
    });
    let k = symbolic::curvature_numerator(&curve).unwrap();
    c.bench_function("inflections_closed_cubic_32", |b| {
        b.iter(|| {
            bspline::roots::find_roots_periodic(black_box(&k), &RootOptions::default()).unwrap()
        })
    });
}

fn roots(c: &mut Criterion) {
    // (u − r₁)…(u − r₁₅) as a degree-15 Bézier, built exactly from linear factors.
    let mut f = BSpline::new(0, vec![0.0, 1.0], 1, vec![1.0]).unwrap();
    for i in 0..15 {
        let r = (i as f64 + 0.5) / 15.0;
        let lin = BSpline::new(1, vec![0.0, 0.0, 1.0, 1.0], 1, vec![-r, 1.0 - r]).unwrap();
        f = f.mul(&lin).unwrap();
    }
    assert_eq!(
        find_roots(&f, 0.0, 1.0, &RootOptions::default())
            .unwrap()
            .len(),
        15
    );
    c.bench_function("roots_degree15_bezier_15_roots", |b| {
        b.iter(|| find_roots(black_box(&f), 0.0, 1.0, &RootOptions::default()).unwrap())
    });
}

fn tensor_subdivision(c: &mut Criterion) {
    use bspline::tensor::TensorBSpline;
    // A degree (10, 10) Bézier patch: a sum of three outer products of degree-10 functions.
    let bez = |seed: f64| {
        BSpline::bezier(
            1,
            (0..11).map(|i| ((i as f64) * 1.3 + seed).sin()).collect(),
        )
        .unwrap()
    };
    let f = TensorBSpline::sum_of_outer(&[
        (bez(0.1), bez(0.7)),
        (bez(1.9), bez(2.3)),
        (bez(3.1), bez(4.2)),
    ])
    .unwrap();
    assert_eq!((f.deg_t(), f.deg_r()), (10, 10));
    c.bench_function("tensor_deg10x10_quad_subdivision", |b| {
        b.iter(|| {
            let (lo, hi) = black_box(&f).split_t(0.5).unwrap();
            (lo.split_r(0.5).unwrap(), hi.split_r(0.5).unwrap())
        })
    });
}

criterion_group!(benches, products, curvature, roots, tensor_subdivision);
criterion_main!(benches);
