//! Closeness of test values: the gap between two values, for [`assert_near!`](crate::assert_near!) and
//! [`prop_assert_near!`](crate::prop_assert_near!).

/// A value compared by its coordinates: a number, a point, a list of numbers, or a
/// reference to one (so that `x` and `&x` compare alike).
pub trait Near {
    /// The value's coordinates, in order.
    fn coordinates(&self) -> Vec<f64>;
}

impl Near for f64 {
    fn coordinates(&self) -> Vec<f64> {
        vec![*self]
    }
}

impl<const N: usize> Near for [f64; N] {
    fn coordinates(&self) -> Vec<f64> {
        self.to_vec()
    }
}

impl Near for (f64, f64) {
    fn coordinates(&self) -> Vec<f64> {
        vec![self.0, self.1]
    }
}

impl Near for [f64] {
    fn coordinates(&self) -> Vec<f64> {
        self.to_vec()
    }
}

impl Near for Vec<f64> {
    fn coordinates(&self) -> Vec<f64> {
        self.clone()
    }
}

impl<T: Near + ?Sized> Near for &T {
    fn coordinates(&self) -> Vec<f64> {
        (**self).coordinates()
    }
}

/// The largest absolute difference of two values' coordinates: infinite when they have
/// different numbers of coordinates, NaN when a coordinate is (so that no NaN passes).
pub fn gap(a: &(impl Near + ?Sized), b: &(impl Near + ?Sized)) -> f64 {
    let (a, b) = (a.coordinates(), b.coordinates());
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    a.iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        // (`f64::max` would drop a NaN; a gap of NaN must fail every comparison.)
        .fold(0.0, |m, d| if d.is_nan() || d > m { d } else { m })
}

/// Whether a gap is within the tolerance, `gap <= tol` (never for a NaN gap): the test
/// [`assert_near!`](crate::assert_near!) and [`prop_assert_near!`](crate::prop_assert_near!) make.
pub fn within(gap: f64, tol: f64) -> bool {
    gap <= tol
}

/// The message of a failed [`assert_near!`](crate::assert_near!) (named `call`, on the
/// expressions `exprs`), or `None` where the values are within the tolerance.
#[doc(hidden)]
pub fn failure(
    call: &str,
    exprs: [&str; 3],
    what: std::fmt::Arguments<'_>,
    (left, right): (
        &(impl Near + std::fmt::Debug + ?Sized),
        &(impl Near + std::fmt::Debug + ?Sized),
    ),
    tol: f64,
) -> Option<String> {
    let gap = gap(left, right);
    (!within(gap, tol)).then(|| {
        format!(
            "{call}!({}, {}, {}) failed {what}\n  left: {left:?}\n right: {right:?}\n   gap: {gap:e} (tolerance {tol:e})",
            exprs[0], exprs[1], exprs[2],
        )
    })
}

/// The message of a failed `call!(left, right, tol, what…)` ([`failure`]), or `None`: what
/// [`assert_near!`](crate::assert_near!) and [`prop_assert_near!`](crate::prop_assert_near!)
/// both ask, each then failing its own way.
#[doc(hidden)]
#[macro_export]
macro_rules! __near_failure {
    ($call:literal, $left:expr, $right:expr, $tol:expr, $($what:tt)+) => {
        $crate::near::failure(
            $call,
            [stringify!($left), stringify!($right), stringify!($tol)],
            format_args!($($what)+),
            (&$left, &$right),
            $tol,
        )
    };
}

/// Asserts that two values lie within `tol` of each other ([`gap`] `<= tol`),
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
    ($left:expr, $right:expr, $tol:expr, $($what:tt)+) => {
        if let Some(message) =
            $crate::__near_failure!("assert_near", $left, $right, $tol, $($what)+)
        {
            panic!("{}", message);
        }
    };
}

/// [`assert_near!`](crate::assert_near!) inside a proptest body: a failing case is reported
/// to proptest (and shrunk) instead of panicking.
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
    ($left:expr, $right:expr, $tol:expr, $($what:tt)+) => {
        if let Some(message) =
            $crate::__near_failure!("prop_assert_near", $left, $right, $tol, $($what)+)
        {
            return ::core::result::Result::Err(
                $crate::__proptest::test_runner::TestCaseError::fail(message),
            );
        }
    };
}

#[cfg(test)]
mod tests {
    use super::gap;

    #[test]
    fn the_gap_is_the_largest_coordinate_difference() {
        assert_eq!(gap(&[1.0, 2.0], &[1.5, 1.0]), 1.0);
        assert_eq!(gap(&(0.0, 0.0), &(0.0, -0.25)), 0.25);
        assert_eq!(gap(&vec![1.0], &vec![1.0, 2.0]), f64::INFINITY);
        assert_eq!(gap(&&2.0, &1.5), 0.5);
    }

    #[test]
    fn a_nan_is_never_near() {
        assert!(gap(&[f64::NAN, 0.0], &[0.0, 0.0]).is_nan());
        assert!(gap(&[0.0, f64::NAN], &[0.0, 0.0]).is_nan());
        let caught = std::panic::catch_unwind(|| crate::assert_near!(f64::NAN, 0.0, 1.0));
        assert!(caught.is_err());
    }

    #[test]
    fn the_tolerance_bounds_the_gap_and_the_message_names_the_values() {
        let caught = std::panic::catch_unwind(|| crate::assert_near!(1.0, 1.75, 0.5, "at {}", 7));
        let message = *caught.unwrap_err().downcast::<String>().unwrap();
        assert!(
            message.contains("at 7") && message.contains("left: 1.0"),
            "{message}"
        );
        crate::assert_near!(1.0, 1.5, 0.5);
    }
}
