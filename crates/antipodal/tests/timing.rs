//! Run-time of the papers' shapes and random B-splines (`cargo test --release -- --ignored
//! --nocapture timing`); the criterion benchmarks live in the workspace `benches/`.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use antipodal::shapes::{Convexities, Ellipse, EllipticLemniscate, Limacon};
use antipodal::{antipodal, Options, PlaneCurve, SplineCurve};
use std::time::Instant;

fn median_us(c: &dyn PlaneCurve) -> f64 {
    let mut ts: Vec<f64> = (0..31)
        .map(|_| {
            let t0 = Instant::now();
            let r = antipodal(c, &Options::default()).unwrap();
            std::hint::black_box(r);
            t0.elapsed().as_secs_f64() * 1e6
        })
        .collect();
    ts.sort_by(f64::total_cmp);
    ts[15]
}

fn star(n: usize, seed: u64) -> SplineCurve {
    let mut x = seed;
    let mut rnd = || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * (i as f64 + 0.8 * (rnd() - 0.5)) / n as f64;
            let r = 0.35 + 0.65 * rnd();
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    SplineCurve::periodic(3, &pts, None).unwrap()
}

#[test]
#[ignore]
fn timing() {
    let shapes: Vec<(&str, Box<dyn PlaneCurve>)> = vec![
        (
            "ellipse 3x2",
            Box::new(Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap()),
        ),
        ("limacon 4,2.5", Box::new(Limacon::new(4.0, 2.5).unwrap())),
        (
            "lemniscate 6,3",
            Box::new(EllipticLemniscate::new(6.0, 3.0).unwrap()),
        ),
        (
            "convexities 3,0.5,3",
            Box::new(Convexities::new(3.0, 0.5, 3).unwrap()),
        ),
        (
            "convexities 4.5,0.2,4",
            Box::new(Convexities::new(4.5, 0.2, 4).unwrap()),
        ),
        ("bspline 8 pts", Box::new(star(8, 7))),
        ("bspline 20 pts", Box::new(star(20, 11))),
    ];
    for (name, c) in &shapes {
        let r = antipodal(c.as_ref(), &Options::default()).unwrap();
        eprintln!(
            "{name:24} {:3} pairs {:2} inflections  median {:9.1} µs  certified {}",
            r.pairs.len(),
            r.inflections.len(),
            median_us(c.as_ref()),
            r.certified
        );
    }
}
