//! Shapes the benchmarks share (the medial axis tests take the chain of Béziers from here
//! too, so a fault found on a benchmark shape is tested on that very shape).
#![allow(dead_code)] // each benchmark takes what it needs

use curve::{Profile, Segment, SegmentKind, SplineCurve, V2};

/// Deterministic pseudo-random numbers in [0, 1).
pub(crate) fn rng(seed: u64) -> impl FnMut() -> f64 {
    let mut x = seed;
    move || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (x >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A closed chain of `n` cubic Béziers round a star, with corners at every joint.
pub(crate) fn bezier_chain(n: usize) -> Profile {
    let mut rnd = rng(7);
    let joints: Vec<V2> = (0..n)
        .map(|i| V2::polar(std::f64::consts::TAU * i as f64 / n as f64) * (1.0 + 0.5 * rnd()))
        .collect();
    let segs = (0..n)
        .map(|i| {
            let (a, b) = (joints[i], joints[(i + 1) % n]);
            let w = 0.3 * (rnd() - 0.5);
            let pts = [
                a.arr(),
                (a + (b - a) * 0.3 + (b - a).perp() * w).arr(),
                (a + (b - a) * 0.7 - (b - a).perp() * w).arr(),
                b.arr(),
            ];
            let c = SplineCurve::clamped(3, &pts, None, None).unwrap();
            Segment::spline(SegmentKind::Bezier, c).unwrap()
        })
        .collect();
    Profile::new(segs, None).unwrap()
}
