//! The crate's error type.

use thiserror::Error;

/// Why a curve cannot be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// The spline data is invalid.
    #[error(transparent)]
    Spline(#[from] bspline::Error),
    /// An analytic shape parameter is out of range.
    #[error("{field} = {value}: {why}")]
    InvalidShape {
        /// The offending field.
        field: &'static str,
        /// Its value.
        value: f64,
        /// What is required.
        why: &'static str,
    },
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
