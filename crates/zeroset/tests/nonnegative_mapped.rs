//! [`nonnegative_set_mapped`]: the chord tolerance holds where the map sends the pairs. On a
//! disk's boundary (known exactly) under maps that stretch one coordinate unevenly, every
//! stretch of the true circle between two consecutive vertices, mapped, stays within the
//! tolerance of the segment between the mapped vertices.
#![allow(clippy::unwrap_used)]

use bspline::tensor::TensorBSpline;
use bspline::BSpline;
use numeric::tolerance::{Settings, Size};
use proptest::prelude::*;
use zeroset::{nonnegative_set, nonnegative_set_mapped, NonNegativeOptions, NonNegativeSet};

/// What the measured deviation may add to the tolerance (its climb's margin is 1 %).
const MEASURED_SLACK: f64 = 1.02;

/// `ρ² − |p − c|²` on the unit square: non-negative on the disk.
fn disk(c: [f64; 2], rho: f64) -> TensorBSpline {
    // (x − c)² in Bernstein form of degree 2 on [0, 1].
    let square =
        |c: f64| BSpline::bezier(1, vec![c * c, c * c - c, (1.0 - c) * (1.0 - c)]).unwrap();
    let one = BSpline::constant(&[1.0], 0, 0.0, 1.0).unwrap();
    let radius = BSpline::constant(&[rho * rho], 0, 0.0, 1.0).unwrap();
    TensorBSpline::sum_of_outer(&[
        (square(c[0]).scale(-1.0), one.clone()),
        (one.clone(), square(c[1]).scale(-1.0)),
        (one, radius),
    ])
    .unwrap()
}

/// `x ↦ (e^{kx} − 1) / (e^k − 1)`: from [0, 1] onto itself, `k` times steeper at one end.
fn stretch(k: f64, x: f64) -> f64 {
    (k * x).exp_m1() / k.exp_m1()
}

/// The largest distance, relative to `tol`, of the mapped true circle from the mapped
/// segments of the pieces.
fn worst_deviation(
    set: &NonNegativeSet,
    c: [f64; 2],
    map: &dyn Fn([f64; 2]) -> [f64; 2],
    tol: f64,
) -> f64 {
    let mut worst: f64 = 0.0;
    for piece in &set.pieces {
        for w in piece.pts.windows(2) {
            let angle = |p: [f64; 2]| (p[1] - c[1]).atan2(p[0] - c[0]);
            let (a, mut b) = (angle(w[0]), angle(w[1]));
            // (The shorter way round: consecutive vertices are close.)
            if b - a > std::f64::consts::PI {
                b -= std::f64::consts::TAU;
            } else if a - b > std::f64::consts::PI {
                b += std::f64::consts::TAU;
            }
            let rho = (w[0][0] - c[0]).hypot(w[0][1] - c[1]);
            let (ma, mb) = (map(w[0]), map(w[1]));
            for k in 1..64 {
                let th = a + (b - a) * k as f64 / 64.0;
                let q = map([c[0] + rho * th.cos(), c[1] + rho * th.sin()]);
                worst = worst.max(testkit::boundary_oracle::off_segment(q, ma, mb) / tol);
            }
        }
    }
    worst
}

fn options(size: f64) -> NonNegativeOptions {
    let mut opts = NonNegativeOptions::default();
    opts.zero.settings = Settings {
        size: Some(Size::new(size).unwrap()),
        ..opts.zero.settings
    };
    opts
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(48)))]

    /// Disks inside the square under uneven stretches of `t`, `r` or both.
    #[test]
    fn chords_keep_to_the_tolerance_where_mapped(
        cx in 0.3..0.7f64, cy in 0.3..0.7f64, rho in 0.1..0.28f64,
        kt in 0.5..4.0f64, kr in 0.5..4.0f64, which in 0usize..3,
    ) {
        let c = [cx, cy];
        let f = disk(c, rho);
        let map = |p: [f64; 2]| match which {
            0 => [stretch(kt, p[0]), p[1]],
            1 => [p[0], stretch(kr, p[1])],
            _ => [stretch(kt, p[0]), stretch(kr, p[1])],
        };
        let opts = options(std::f64::consts::SQRT_2);
        let set = nonnegative_set_mapped(&[f], &opts, &|_| false, &|t, r| Some(map([t, r]))).unwrap();
        prop_assert!(set.complete);
        prop_assert!(!set.pieces.is_empty());
        let tol = opts.zero.settings.chord_tol.get() * std::f64::consts::SQRT_2;
        let worst = worst_deviation(&set, c, &map, tol);
        prop_assert!(worst <= MEASURED_SLACK, "deviation {worst} tolerances");
    }
}

/// The check above is sharp: traced unmapped, the steepest stretch puts chords beyond it.
#[test]
fn unmapped_chords_stray_where_stretched() {
    let c = [0.6, 0.6];
    let f = disk(c, 0.38);
    let map = |p: [f64; 2]| [stretch(4.0, p[0]), stretch(4.0, p[1])];
    let opts = options(std::f64::consts::SQRT_2);
    let tol = opts.zero.settings.chord_tol.get() * std::f64::consts::SQRT_2;
    let plain = nonnegative_set(std::slice::from_ref(&f), &opts, &|_| false).unwrap();
    // (3.5 tolerances, where the stretch is 3.7 times its mean.)
    let strayed = worst_deviation(&plain, c, &map, tol);
    assert!(strayed > 2.0, "{strayed}");
    let mapped =
        nonnegative_set_mapped(&[f], &opts, &|_| false, &|t, r| Some(map([t, r]))).unwrap();
    assert!(worst_deviation(&mapped, c, &map, tol) <= MEASURED_SLACK);
}
