//! The crate's error type.

use thiserror::Error;

/// What can be wrong with the input of a zero-set, system or bisector computation.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// An error of the underlying B-spline algebra (invalid curve, domain mismatch, ...).
    #[error(transparent)]
    Spline(#[from] bspline::Error),
    /// A curve could not be taken as a profile's segment.
    #[error(transparent)]
    Curve(#[from] curve::Error),
    /// A curve is known by evaluation only: bisectors need an exact form.
    #[error(
        "curve {which} is known by evaluation only: bisectors need its exact form (a spline \
         or an analytic shape)"
    )]
    NotExact {
        /// 1 or 2.
        which: usize,
    },
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
