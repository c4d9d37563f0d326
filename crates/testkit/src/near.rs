//! Closeness of test values: the gap between two values, for [`assert_near!`] and
//! [`prop_assert_near!`].

/// A value whose distance to another of its kind is one number: the largest absolute
/// difference of their coordinates (NaN when either has a NaN, so that no NaN passes).
pub trait Near {
    /// The largest absolute difference of the two values' coordinates.
    fn gap(&self, other: &Self) -> f64;
}

impl Near for f64 {
    fn gap(&self, other: &Self) -> f64 {
        (self - other).abs()
    }
}

impl<const N: usize> Near for [f64; N] {
    fn gap(&self, other: &Self) -> f64 {
        self.as_slice().gap(other.as_slice())
    }
}

impl Near for (f64, f64) {
    fn gap(&self, other: &Self) -> f64 {
        [self.0, self.1].gap(&[other.0, other.1])
    }
}

impl Near for [f64] {
    fn gap(&self, other: &Self) -> f64 {
        if self.len() != other.len() {
            return f64::INFINITY;
        }
        self.iter()
            .zip(other)
            .map(|(a, b)| (a - b).abs())
            // (`f64::max` would drop a NaN; a gap of NaN must fail every comparison.)
            .fold(0.0, |m, d| if d.is_nan() || d > m { d } else { m })
    }
}

impl Near for Vec<f64> {
    fn gap(&self, other: &Self) -> f64 {
        self.as_slice().gap(other.as_slice())
    }
}

impl<T: Near + ?Sized> Near for &T {
    fn gap(&self, other: &Self) -> f64 {
        (**self).gap(*other)
    }
}

/// Whether a gap is within the tolerance, `gap <= tol` (never for a NaN gap): the test
/// [`assert_near!`] and [`prop_assert_near!`] make.
pub fn within(gap: f64, tol: f64) -> bool {
    gap <= tol
}

/// Asserts that two values lie within `tol` of each other ([`Near::gap`] `<= tol`),
/// printing both, their gap and the tolerance when they do not. A further format string and
/// arguments say what was compared.
///
/// ```
/// testkit::assert_near!(0.1 + 0.2, 0.3, 1e-15);
/// testkit::assert_near!([1.0, 2.0], [1.0, 2.0 + 1e-12], 1e-9, "the point at {}", 0.5);
/// ```
#[macro_export]
macro_rules! assert_near {
    ($left:expr, $right:expr, $tol:expr $(,)?) => {
        $crate::assert_near!($left, $right, $tol, "")
    };
    ($left:expr, $right:expr, $tol:expr, $($what:tt)+) => {{
        let (left, right, tol) = (&$left, &$right, $tol);
        let gap = $crate::Near::gap(left, right);
        if !$crate::within(gap, tol) {
            panic!(
                "assert_near!({}, {}, {}) failed {}\n  left: {:?}\n right: {:?}\n   gap: {:e} (tolerance {:e})",
                stringify!($left),
                stringify!($right),
                stringify!($tol),
                format_args!($($what)+),
                left,
                right,
                gap,
                tol,
            );
        }
    }};
}

/// [`assert_near!`] inside a proptest body: a failing case is reported to proptest (and
/// shrunk) instead of panicking.
///
/// ```
/// use proptest::prelude::*;
/// proptest!(|(x in 0.0f64..1.0)| {
///     testkit::prop_assert_near!(x * 3.0 / 3.0, x, 1e-15);
/// });
/// ```
#[macro_export]
macro_rules! prop_assert_near {
    ($left:expr, $right:expr, $tol:expr $(,)?) => {
        $crate::prop_assert_near!($left, $right, $tol, "")
    };
    ($left:expr, $right:expr, $tol:expr, $($what:tt)+) => {{
        let (left, right, tol) = (&$left, &$right, $tol);
        let gap = $crate::Near::gap(left, right);
        if !$crate::within(gap, tol) {
            return ::core::result::Result::Err($crate::__proptest::test_runner::TestCaseError::fail(format!(
                "prop_assert_near!({}, {}, {}) failed {}\n  left: {:?}\n right: {:?}\n   gap: {:e} (tolerance {:e})",
                stringify!($left),
                stringify!($right),
                stringify!($tol),
                format_args!($($what)+),
                left,
                right,
                gap,
                tol,
            )));
        }
    }};
}

#[cfg(test)]
mod tests {
    use super::Near;

    #[test]
    fn the_gap_is_the_largest_coordinate_difference() {
        assert_eq!([1.0, 2.0].gap(&[1.5, 1.0]), 1.0);
        assert_eq!((0.0, 0.0).gap(&(0.0, -0.25)), 0.25);
        assert_eq!(vec![1.0].gap(&vec![1.0, 2.0]), f64::INFINITY);
    }

    #[test]
    fn a_nan_is_never_near() {
        assert!([f64::NAN, 0.0].gap(&[0.0, 0.0]).is_nan());
        assert!([0.0, f64::NAN].gap(&[0.0, 0.0]).is_nan());
        let caught = std::panic::catch_unwind(|| crate::assert_near!(f64::NAN, 0.0, 1.0));
        assert!(caught.is_err());
    }

    #[test]
    fn the_tolerance_is_strict_and_the_message_names_the_values() {
        let caught = std::panic::catch_unwind(|| crate::assert_near!(1.0, 1.5, 0.5, "at {}", 7));
        let message = *caught.unwrap_err().downcast::<String>().unwrap();
        assert!(
            message.contains("at 7") && message.contains("left: 1.0"),
            "{message}"
        );
        crate::assert_near!(1.0, 1.25, 0.5);
    }
}
