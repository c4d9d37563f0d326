//! Shared generators and helpers for the property tests.
#![allow(dead_code, unreachable_pub)]
#![allow(clippy::unwrap_used)]

pub mod exact;

#[allow(unused_imports)] // (each test crate uses what it needs)
pub use testkit::cases;

use bspline::BSpline;
use proptest::prelude::*;

/// A random clamped knot vector on a random domain with `n` control points and degree `p`,
/// with interior multiplicities up to `p` (so continuity varies).
pub fn knots(p: usize, n: usize) -> impl Strategy<Value = Vec<f64>> {
    let interior = n - p - 1;
    (
        -3.0f64..3.0,
        0.2f64..5.0,
        prop::collection::vec(0.05f64..1.0, interior + 1),
        prop::collection::vec(0usize..4, interior),
    )
        .prop_map(move |(a, len, gaps, reps)| {
            // Build distinct interior values, then repeat some (up to p times in total).
            let total: f64 = gaps.iter().sum();
            let mut vals = Vec::new();
            let mut acc = 0.0;
            for g in &gaps[..interior] {
                acc += g;
                vals.push(a + len * acc / total);
            }
            let mut inner = Vec::new();
            let mut i = 0;
            while inner.len() < interior {
                let v = vals[i];
                let m = (1 + reps[i] % p).min(interior - inner.len());
                inner.extend(std::iter::repeat_n(v, m));
                i += 1;
            }
            let mut k = vec![a; p + 1];
            k.extend(inner);
            k.extend(std::iter::repeat_n(a + len, p + 1));
            k
        })
}

/// A random B-spline of degree 1..=max_p with up to `max_n` control points of dimension `dim`.
pub fn spline(max_p: usize, max_n: usize, dim: usize) -> impl Strategy<Value = BSpline> {
    (1..=max_p)
        .prop_flat_map(move |p| (Just(p), p + 1..=max_n.max(p + 1)))
        .prop_flat_map(move |(p, n)| {
            (
                Just(p),
                knots(p, n),
                prop::collection::vec(-10.0f64..10.0, n * dim),
            )
        })
        .prop_map(move |(p, k, c)| BSpline::new(p, k, dim, c).expect("valid by construction"))
}

/// Same-domain pairs: the second spline is reparametrised onto the first one's domain.
pub fn pair(
    max_p: usize,
    max_n: usize,
    da: usize,
    db: usize,
) -> impl Strategy<Value = (BSpline, BSpline)> {
    (spline(max_p, max_n, da), spline(max_p, max_n, db)).prop_map(|(a, b)| {
        let (lo, hi) = a.domain();
        let b = b.reparam(lo, hi).expect("valid domain");
        (a, b)
    })
}

/// Parameters spread over the domain, including its ends and every knot.
pub fn sample_params(f: &BSpline, n: usize) -> Vec<f64> {
    let (a, b) = f.domain();
    let mut v: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    v.extend(f.breakpoints());
    v
}

/// Relative closeness: |x - y| <= tol * max(1, scale).
pub fn close(x: f64, y: f64, scale: f64, tol: f64) -> bool {
    (x - y).abs() <= tol * scale.max(1.0)
}
