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
    /// A profile with no segments.
    #[error("a profile needs at least one segment")]
    EmptyProfile,
    /// A segment does not start where the previous one ends (segment 0: a closed profile's
    /// last segment does not end where the first starts).
    #[error(
        "segment {segment} starts {gap:e} away from where the previous one ends (at ({x}, {y})): \
         more than 1e-9 of the profile's size",
        x = at[0],
        y = at[1]
    )]
    Gap {
        /// The segment that should start there.
        segment: usize,
        /// The distance between the two ends.
        gap: f64,
        /// Where the previous segment ends.
        at: [f64; 2],
    },
    /// A segment with no direction at an end (all its points at one place).
    #[error("segment {segment} has zero length")]
    ZeroLength {
        /// The segment.
        segment: usize,
    },
    /// Two segments meet head on: the profile turns back on itself.
    #[error("the profile turns back on itself where segment {segment} starts (at ({x}, {y}))", x = at[0], y = at[1])]
    Cusp {
        /// The segment starting there.
        segment: usize,
        /// Where.
        at: [f64; 2],
    },
    /// Two segments of a profile cross or touch away from their joint.
    #[error("the profile crosses itself: segments {first} and {second} meet at ({x}, {y})", x = at[0], y = at[1])]
    SelfCrossing {
        /// The first segment along the profile.
        first: usize,
        /// The second.
        second: usize,
        /// A point where they meet.
        at: [f64; 2],
    },
    /// A boundary of a region that is not closed (0: the outer one, `1 + i`: hole `i`).
    #[error("boundary {boundary} of the region is not closed")]
    OpenBoundary {
        /// The boundary.
        boundary: usize,
    },
    /// Two boundaries of a region cross or touch (0: the outer one, `1 + i`: hole `i`).
    #[error("boundaries {first} and {second} of the region meet at ({x}, {y})", x = at[0], y = at[1])]
    BoundariesCross {
        /// The first boundary.
        first: usize,
        /// The second.
        second: usize,
        /// A point where they meet.
        at: [f64; 2],
    },
    /// Two closed outlines of a drawing cross or touch (their indices).
    #[error("outlines {first} and {second} meet at ({x}, {y})", x = at[0], y = at[1])]
    OutlinesCross {
        /// The first outline.
        first: usize,
        /// The second.
        second: usize,
        /// A point where they meet.
        at: [f64; 2],
    },
    /// A hole not inside the outer boundary.
    #[error("hole {hole} is not inside the outer boundary")]
    HoleOutside {
        /// The hole.
        hole: usize,
    },
    /// A hole inside another hole.
    #[error("hole {hole} lies inside hole {other}")]
    HoleInHole {
        /// The hole.
        hole: usize,
        /// The hole around it.
        other: usize,
    },
    /// A closed profile that encloses no area.
    #[error("the closed profile encloses no area (signed area {area:e})")]
    FlatProfile {
        /// Its signed area.
        area: f64,
    },
    /// The test of whether profiles cross, or of which lies inside which, did not finish
    /// within its bound on the work (curves that run along each other over long stretches,
    /// closer than a ten-millionth of their size).
    #[error("whether the profile crosses itself or another was not decided within {tests} tests")]
    Undecided {
        /// The bound on the tests.
        tests: usize,
    },
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
