//! The crate's error type.

use thiserror::Error;

/// What can be wrong with the input of a grasp computation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// An error of the underlying B-spline algebra.
    #[error(transparent)]
    Spline(#[from] bspline::Error),
    /// The curve could not be taken as a profile.
    #[error(transparent)]
    Curve(#[from] curve::Error),
    /// The zero sets could not be traced.
    #[error(transparent)]
    ZeroSet(#[from] zeroset::Error),
    /// The antipodal pairs (the frictionless grasps) could not be found.
    #[error(transparent)]
    Antipodal(#[from] antipodal::Error),
    /// The curve is known by evaluation only.
    #[error("the curve is known by evaluation only: grasps need its exact form (a spline or an analytic shape)")]
    NotExact,
    /// The boundary is open: grasps need a closed curve or profile.
    #[error("the boundary is open: grasps need a closed curve or profile")]
    NotClosed,
    /// An option out of range.
    #[error("{field} = {value}: {expected}")]
    Option {
        /// The option.
        field: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        expected: &'static str,
    },
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
