//! Timings of the headline cases (ignored by default; run with
//! `cargo test --release -p curvekit-zeroset --test timing -- --ignored --nocapture`).
#![allow(clippy::unwrap_used)]
mod common;
use common::*;
use std::time::{Duration, Instant};
use zeroset::{bisector, bisector_function, self_bisector, BisectorOptions, Method};

fn median(mut f: impl FnMut()) -> Duration {
    let mut v: Vec<Duration> = (0..101)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed()
        })
        .collect();
    v.sort();
    v[50]
}

#[test]
#[ignore]
fn headline_timings() {
    let c1 = bez(&[[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 1.0]]);
    let c2 = bez(&[[0.0, 3.0], [1.0, 2.0], [2.0, 4.0], [3.0, 3.5]]);
    let o = BisectorOptions::default();
    eprintln!(
        "F3 of two cubic Béziers: {:?}",
        median(|| drop(bisector_function(&c1, &c2, Method::F3).unwrap()))
    );
    eprintln!(
        "bisector of two cubic Béziers: {:?}",
        median(|| drop(bisector(&c1, &c2, &o).unwrap()))
    );
    let c = bsp(
        3,
        &[
            [0.0, 0.0],
            [1.0, 2.0],
            [3.0, 2.5],
            [4.0, 0.5],
            [3.0, -1.5],
            [1.5, -1.0],
            [2.0, 0.5],
        ],
    );
    eprintln!(
        "self-bisector, cubic B-spline, 7 points: {:?}",
        median(|| drop(self_bisector(&c, &o).unwrap()))
    );
}
