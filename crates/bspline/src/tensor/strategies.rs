//! The random splines and the tolerance that the property tests of the tensor modules share:
//! one copy for the tests of evaluation, subdivision and arithmetic.

use crate::spline::BSpline;
use proptest::prelude::*;

/// A clamped scalar spline on [0, 1] of degree `p` with coefficients from `c` (at least p+1).
fn spline(p: usize, c: &[f64]) -> BSpline {
    BSpline::clamped_uniform(p, 1, c.to_vec()).expect("valid spline")
}

pub(super) fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-11 * scale.max(1.0)
}

prop_compose! {
    pub(super) fn arb_spline()(p in 1usize..4, extra in 0usize..4)
        (c in prop::collection::vec(-2.0..2.0f64, p + 1 + extra), p in Just(p)) -> BSpline {
        spline(p, &c)
    }
}
