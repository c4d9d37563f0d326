//! Pairs exactly at the seam of a periodic B-spline are found once, at `s = 0`.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use antipodal::{antipodal, Options, PlaneCurve, SplineCurve};

/// A periodic cubic on an elliptic control polygon, symmetric about the x axis with `C(0)` on
/// the axis: antipodal pairs at `0 ↔ n/2` and `n/4 ↔ 3n/4`.
fn symmetric(n: usize, a: f64, b: f64) -> SplineCurve {
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let th = std::f64::consts::TAU * (k as f64 - 1.0) / n as f64;
            [a * th.cos(), b * th.sin()]
        })
        .collect();
    SplineCurve::periodic(3, &pts, None).unwrap()
}

#[test]
fn seam_pair_reported_once() {
    for (n, cw) in [(8, false), (12, false), (8, true)] {
        let mut c = symmetric(n, 3.0, 1.5);
        if cw {
            let (a, b) = (3.0, 1.5);
            let pts: Vec<[f64; 2]> = (0..n)
                .map(|k| {
                    let th = -std::f64::consts::TAU * (k as f64 - 1.0) / n as f64;
                    [a * th.cos(), b * th.sin()]
                })
                .collect();
            c = SplineCurve::periodic(3, &pts, None).unwrap();
        }
        let r = antipodal(&c, &Options::default()).unwrap();
        assert_eq!(r.pairs.len(), 2, "{:?}", r.pairs);
        let half = n as f64 / 2.0;
        let seam = r
            .pairs
            .iter()
            .filter(|p| p.s.abs() < 1e-9 || (p.s - n as f64).abs() < 1e-9)
            .count();
        assert_eq!(seam, 1, "{:?}", r.pairs);
        let p = r.pairs[0];
        assert!(p.s.abs() < 1e-9 && (p.t - half).abs() < 1e-9, "{p:?}");
        let (a, b) = c.domain();
        assert!(r.pairs.iter().all(|p| p.s >= a && p.t < b));
    }
}
