//! Whether a clamped curve is closed is judged on its own scale, however far from the origin.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use curve::{ParamCurve, SplineCurve};
use proptest::prelude::*;

/// The points `pts` moved by `by` (exactly: the shapes below are on a grid the move keeps).
fn moved(pts: &[(f64, f64)], by: [f64; 2]) -> Vec<[f64; 2]> {
    pts.iter().map(|&(x, y)| [x + by[0], y + by[1]]).collect()
}

/// Whether the clamped quadratic on `pts` moved by `by`, with `weights` and `knots`, is
/// taken for closed.
fn quadratic_moved_is_closed(
    pts: &[(f64, f64)],
    by: [f64; 2],
    weights: Option<&[f64]>,
    knots: Vec<f64>,
) -> bool {
    let c = SplineCurve::clamped(2, &moved(pts, by), weights, Some(knots)).unwrap();
    c.is_closed()
}

/// A quadratic B-spline on uniform unclamped knots whose ends are 8 units apart (3 % of its
/// size), 2^56 units from the origin: open. (Evaluated in place, the ends rounded to the same
/// point, and the curve was taken for closed; found by fuzzing.)
#[test]
fn an_open_curve_far_from_the_origin_is_open() {
    let far = 2f64.powi(56);
    let pts = [
        (0.0, 0.0),
        (-32.0, -16.0),
        (0.0, -112.0),
        (104.0, 104.0),
        (0.0, 0.0),
        (-32.0, 0.0),
    ];
    let knots: Vec<f64> = (1..=9).map(|i| i as f64 / 16.0).collect();
    assert!(!quadratic_moved_is_closed(&pts, [-far, -far], None, knots));
}

/// The same with a weight of 2^-14.25 at 8e16 from the origin: the ends are 24 units apart,
/// within the rounding of `X / w` there, but the points as given are exact. (Judged on the
/// homogeneous form, the curve was taken for closed; found by fuzzing.)
#[test]
fn an_open_rational_curve_far_from_the_origin_is_open() {
    let far = 2f64.powi(50);
    let pts = [
        (0.0, 103.0),
        (-1.0, -1.0),
        (-27.0, -1.0),
        (3.0, -22.0),
        (0.0, 71.0),
    ];
    let knots = vec![
        7.1875, 23.125, 39.0625, 55.0, 70.9375, 86.875, 102.8125, 118.75,
    ];
    let w = [2f64.powf(-14.25), 1.0, 1.0, 1.0, 1.0];
    let by = [71.0 * far, -33.0 * far];
    assert!(!quadratic_moved_is_closed(&pts, by, Some(&w), knots));
}

proptest! {
    /// A clamped curve with equal first and last points is closed, and one whose last point is
    /// moved by a thousandth of its size is open, at any offset a double can carry the shape at.
    #[test]
    fn closedness_survives_translation(
        pts in proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 4..9),
        w in proptest::collection::vec(0.5f64..2.0, 9),
        rational in any::<bool>(),
        exp in 0i32..40,
        sx in -1.0f64..1.0, sy in -1.0f64..1.0,
    ) {
        let off = [sx * 2f64.powi(exp), sy * 2f64.powi(exp)];
        let mut p = moved(&pts, off);
        let n = p.len();
        p[n - 1] = p[0];
        let weights = rational.then(|| w[..n].to_vec());
        let closed = SplineCurve::clamped(3, &p, weights.as_deref(), None).unwrap();
        prop_assert!(closed.is_closed());
        p[n - 1] = [p[0][0] + 2e-3, p[0][1]];
        let open = SplineCurve::clamped(3, &p, weights.as_deref(), None).unwrap();
        prop_assert!(!open.is_closed());
    }
}
