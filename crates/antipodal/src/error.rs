//! The crate's error type.

use thiserror::Error;

/// Why a curve or a request cannot be processed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// The spline data is invalid.
    #[error(transparent)]
    Spline(#[from] bspline::Error),
    /// The curve cannot be made (an analytic shape's parameter out of range).
    #[error(transparent)]
    Curve(#[from] curve::Error),
    /// An option is out of the range the algorithms can deliver.
    #[error("option {field} = {value} is out of range: {expected}")]
    InvalidOption {
        /// The option.
        field: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        expected: &'static str,
    },
    /// The curve oscillates more than the sampled search is bounded to resolve (an analytic
    /// shape with many lobes).
    #[error("the curve oscillates too often for the search's bounds ({lobes} lobes)")]
    TooComplex {
        /// The number of lobes.
        lobes: usize,
    },
    /// Two profiles with more pairs of curved segments than the common tangents search takes.
    #[error(
        "{pairs} pairs of curved segments: the common tangents of profiles search at most \
         {limit} (each pair is a search of its own)"
    )]
    TooManySegmentPairs {
        /// The pairs the profiles have.
        pairs: usize,
        /// The most searched.
        limit: usize,
    },
    /// A segment of a profile was refused.
    #[error("segment {segment}: {source}")]
    InSegment {
        /// The segment.
        segment: usize,
        /// Why.
        source: Box<Error>,
    },
    /// A curve known by evaluation only was paired with a profile: it has no exact form to be
    /// taken as a profile's segment.
    #[error(
        "curve {which} is known by evaluation only: it has no exact form to be taken as a \
         profile's segment"
    )]
    NoSegment {
        /// 1 or 2: which of the command's curves.
        which: usize,
    },
    /// The operation needs a closed curve.
    #[error("the curve is not closed (its ends are {gap} apart)")]
    NotClosed {
        /// Distance between the end points.
        gap: f64,
    },
    /// The curve has a cusp or a stationary point (zero speed): no tangent or normal there.
    #[error("the curve is singular (zero speed or cusp) near u = {u}, or too close to singular there for double precision to tell")]
    Cusp {
        /// Parameter near the singularity.
        u: f64,
    },
    /// The tangent direction jumps at the seam of a closed curve (a corner).
    #[error("the closed curve has a corner at its seam (tangents differ by {angle} rad)")]
    Corner {
        /// Angle between the two one-sided tangents.
        angle: f64,
    },
    /// The closed curve crosses itself.
    #[error("the curve is not simple: it crosses itself near u = {s} and u = {t}")]
    SelfIntersecting {
        /// One parameter near the crossing.
        s: f64,
        /// The other.
        t: f64,
    },
    /// The tangent of the closed curve does not turn exactly once around over one period, so
    /// the curve crosses itself (a loop, or a curve wound more than once).
    #[error("the curve is not simple: its tangent turns {turns:.1} times around over one period (once for a simple closed curve)")]
    Winding {
        /// Total turning of the tangent, in whole turns (2π).
        turns: f64,
    },
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
