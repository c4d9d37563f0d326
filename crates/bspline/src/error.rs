//! The crate's error type.

use thiserror::Error;

/// Everything that can be wrong with the input of a `bspline` operation.
///
/// Each variant names the offending field or index so that a caller can point a user at it.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A knot, coefficient, weight or parameter is NaN or infinite.
    #[error("{what}[{index}] is not finite ({value})")]
    NotFinite {
        /// Which array holds the value (`knots`, `coefs`, `weights`, ...).
        what: &'static str,
        /// Position of the value in that array.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// Knots must be non-decreasing.
    #[error("knots[{index}] = {value} is smaller than the knot before it ({previous})")]
    DecreasingKnots {
        /// Position of the offending knot.
        index: usize,
        /// Its value.
        value: f64,
        /// The knot just before it.
        previous: f64,
    },
    /// A knot value repeats more often than the degree allows.
    #[error("knot {value} has multiplicity {multiplicity}, more than the allowed {max}")]
    KnotMultiplicity {
        /// The repeated knot value.
        value: f64,
        /// How often it occurs.
        multiplicity: usize,
        /// The largest multiplicity allowed at that place.
        max: usize,
    },
    /// The parameter domain `[knots[p], knots[n]]` is empty.
    #[error("the parameter domain [{start}, {end}] is empty")]
    EmptyDomain {
        /// Domain start.
        start: f64,
        /// Domain end.
        end: f64,
    },
    /// Some count does not match what the other inputs imply.
    #[error("{what}: expected {expected}, got {got}")]
    CountMismatch {
        /// What was counted.
        what: &'static str,
        /// The count the other inputs imply.
        expected: usize,
        /// The count that was given.
        got: usize,
    },
    /// Not enough control points for the degree.
    #[error("degree {degree} needs at least {needed} control points, got {got}")]
    TooFewPoints {
        /// The degree.
        degree: usize,
        /// The minimum number of control points.
        needed: usize,
        /// The number given.
        got: usize,
    },
    /// Two operands (or an operand and an operation) disagree on the dimension.
    #[error("dimension mismatch: expected {expected}, got {got}")]
    DimensionMismatch {
        /// The dimension required.
        expected: usize,
        /// The dimension given.
        got: usize,
    },
    /// Two operands of a binary operation live on different parameter domains.
    #[error("domain mismatch: [{}, {}] vs [{}, {}]", .left.0, .left.1, .right.0, .right.1)]
    DomainMismatch {
        /// Domain of the left operand.
        left: (f64, f64),
        /// Domain of the right operand.
        right: (f64, f64),
    },
    /// A parameter lies outside the domain, or an interval is empty or reversed.
    #[error("parameter interval [{a}, {b}] is not inside the domain [{}, {}]", .domain.0, .domain.1)]
    OutOfDomain {
        /// Interval start (equal to `b` for a single parameter).
        a: f64,
        /// Interval end.
        b: f64,
        /// The domain.
        domain: (f64, f64),
    },
    /// A rational weight is zero or negative.
    #[error("weights[{index}] = {value} must be > 0")]
    NonPositiveWeight {
        /// Position of the weight.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A function treated as periodic takes different values at its domain ends.
    #[error("not periodic: the value at the domain start ({start}) differs from the value at its end ({end})")]
    NotPeriodic {
        /// Value at the domain start.
        start: f64,
        /// Value at the domain end.
        end: f64,
    },
    /// The dimension is zero.
    #[error("dimension must be at least 1")]
    ZeroDimension,
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that every value is finite, naming the first one that is not.
pub(crate) fn check_finite(what: &'static str, values: &[f64]) -> Result<()> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(Error::NotFinite {
            what,
            index,
            value: values[index],
        }),
        None => Ok(()),
    }
}
