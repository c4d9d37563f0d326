//! The crate's error type.

use thiserror::Error;

/// What can be wrong with the input of a zero-set, system or bisector computation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// An error of the underlying B-spline algebra (invalid curve, domain mismatch, ...).
    #[error(transparent)]
    Spline(#[from] bspline::Error),
    /// A curve is not planar.
    #[error("curve {which} has dimension {dim}; bisectors need planar curves")]
    NotPlanar {
        /// 1 or 2.
        which: usize,
        /// Its dimension.
        dim: usize,
    },
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
