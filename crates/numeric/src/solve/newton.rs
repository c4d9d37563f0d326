//! Newton's method without a bracket, kept inside an interval: the finish of a root already
//! located, where no sign change brackets it (a double or clustered root).

/// A Newton step below this part of `1 + |x|` is below the rounding of `x` (half a unit in
/// the last place of 1 is 1.1e-16): the iteration has stalled.
const STEP_STALL: f64 = 1e-16;

/// A root of `f` by Newton's method from `x`, every iterate clamped into `[lo, hi]`:
/// `f(x)` returns the value and the derivative. For a root the caller has located already
/// but cannot bracket (a cluster of roots, a double root, a root within rounding of an end,
/// where [`super::bracketed`] has no sign change to keep).
///
/// **Convergence.** Quadratic near a simple root; linear, with rate `1 − 1/m`, near a root
/// of multiplicity `m`. From a poor start nothing is promised beyond staying in `[lo, hi]`.
///
/// **Stopping rule and bound.** It stops where the value or the derivative is 0, where a step
/// (after the clamp) moves `x` by no more than `1e-16 (1 + |x|)` (the rounding of `x`; that
/// step is still taken), and after `max_steps` evaluations, the bound.
///
/// ```
/// use numeric::solve::newton_within;
/// // The double root of (x − 0.3)² converges linearly, the simple root of x² − 2 at once.
/// let x = newton_within(|x| ((x - 0.3) * (x - 0.3), 2.0 * (x - 0.3)), 0.5, (0.0, 1.0), 60);
/// assert!((x - 0.3).abs() < 1e-7);
/// let x = newton_within(|x| (x * x - 2.0, 2.0 * x), 1.5, (1.0, 2.0), 8);
/// assert!((x - 2f64.sqrt()).abs() < 1e-15);
/// ```
pub fn newton_within(
    mut f: impl FnMut(f64) -> (f64, f64),
    mut x: f64,
    (lo, hi): (f64, f64),
    max_steps: usize,
) -> f64 {
    for _ in 0..max_steps {
        let (value, slope) = f(x);
        if slope == 0.0 || value == 0.0 {
            break;
        }
        let next = (x - value / slope).clamp(lo, hi);
        let stalled = (next - x).abs() <= STEP_STALL * (1.0 + x.abs());
        x = next;
        if stalled {
            break;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(5000))]

        /// On a cubic with a root of multiplicity one or two at a closed-form point (and the
        /// other root far), from a start near it, the iteration reaches that root: to
        /// rounding for a simple one, to the square root of rounding for a double one, and it
        /// never leaves the interval.
        #[test]
        fn reaches_the_closed_form_root(
            root in -1.0f64..1.0,
            far in 2.0f64..4.0,
            double in any::<bool>(),
            off in -0.1f64..0.1,
        ) {
            let m = if double { 2 } else { 1 };
            // (x − root)^m (x − root − far)^(3 − m), with its derivative.
            let f = |x: f64| {
                let (a, b) = (x - root, x - root - far);
                if double {
                    (a * a * b, 2.0 * a * b + a * a)
                } else {
                    (a * b * b, b * b + 2.0 * a * b)
                }
            };
            let (lo, hi) = (root - 0.5, root + 0.5);
            let mut inside = true;
            let x = newton_within(|x| { inside &= x >= lo && x <= hi; f(x) }, root + off, (lo, hi), 80);
            prop_assert!(inside && x >= lo && x <= hi);
            let reach = if m == 1 { crate::rounding::ulps(4.0) * (1.0 + root.abs()) } else { 1e-7 };
            prop_assert!((x - root).abs() <= reach, "{x} vs {root}");
        }
    }

    /// A step that leaves the interval is clamped to its end; a zero derivative stops it.
    #[test]
    fn clamps_and_stops() {
        let x = newton_within(|x| (x - 3.0, 1.0), 0.5, (0.0, 1.0), 8);
        assert_eq!(x, 1.0);
        let calls = std::cell::Cell::new(0);
        let flat = newton_within(
            |_| {
                calls.set(calls.get() + 1);
                (1.0, 0.0)
            },
            0.5,
            (0.0, 1.0),
            8,
        );
        assert_eq!((flat, calls.get()), (0.5, 1));
    }
}
