//! Straight spans proven from the data against sampling: every reported span is straight (its
//! sampled points on the line of its two data points), and every span shaped by a run of
//! collinear control points (made exactly collinear on a grid) is reported.
#![allow(clippy::unwrap_used)]

use curve::{ParamCurve, SplineCurve};
use proptest::prelude::*;

/// A control polygon with a run of `run` points on a line of slope `dy/dx` (grid values: the
/// run is exactly collinear), starting at index `at`, the rest random.
fn polygon(seed: &[(f64, f64)], run: usize, at: usize, slope: (i32, i32)) -> Vec<[f64; 2]> {
    let grid = |x: f64| (x * 256.0).round() / 256.0;
    let mut pts: Vec<[f64; 2]> = seed.iter().map(|&(x, y)| [grid(x), grid(y)]).collect();
    let base = pts[at];
    for k in 1..run {
        let i = (at + k) % pts.len();
        let k = k as f64;
        pts[i] = [
            base[0] + k * f64::from(slope.0) / 8.0,
            base[1] + k * f64::from(slope.1) / 8.0,
        ];
    }
    pts
}

fn distance_to_line(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    ((p[0] - a[0]) * dy - (p[1] - a[1]) * dx).abs() / dx.hypot(dy)
}

proptest! {
    #[test]
    fn straight_spans_are_straight_and_found(
        degree in 1usize..=4,
        seed in proptest::collection::vec((-4.0f64..4.0, -4.0f64..4.0), 8..16),
        run in 0usize..8,
        at in 0usize..8,
        slope in (-3i32..=3, -3i32..=3),
        periodic in any::<bool>(),
    ) {
        prop_assume!(slope != (0, 0));
        let pts = polygon(&seed, run, at % seed.len(), slope);
        let c = match periodic {
            true => SplineCurve::periodic(degree, &pts, None),
            false => SplineCurve::clamped(degree, &pts, None, None),
        };
        let Ok(c) = c else { return Ok(()) };
        let (a, b) = c.domain();
        let spans = c.straight_spans();
        for s in &spans {
            prop_assert!(s.lo < s.hi && s.lo >= a && s.from != s.to);
            for i in 0..=32 {
                let mut u = s.lo + (s.hi - s.lo) * f64::from(i) / 32.0;
                if periodic && u >= b {
                    u -= b - a;
                }
                let p = c.jet(u).p.arr();
                prop_assert!(distance_to_line(p, s.from, s.to) <= 1e-12, "{:?} at {}", s, u);
            }
        }
        // A run of p + 1 collinear points shapes a straight span: the spans whose control
        // points all lie in the run (periodic: points i..i+p shape [i, i+1] of [0, n)).
        if periodic && run > degree {
            let n = pts.len();
            for first in 0..=run - 1 - degree {
                let j = ((at % n) + first) % n;
                let (lo, hi) = (j as f64, j as f64 + 1.0);
                let covered = spans.iter().any(|s| {
                    let inside = |u: f64| (s.lo <= u && u <= s.hi) || (s.lo <= u + n as f64 && u + n as f64 <= s.hi);
                    inside(lo) && inside(hi)
                });
                prop_assert!(covered, "span [{lo}, {hi}] not found among {:?}", spans);
            }
        }
    }
}
