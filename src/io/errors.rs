//! What is wrong with a curve file: the error naming its file and field, and the problems.

use thiserror::Error;

/// A curve file that cannot be used: which file, which field, what is wrong.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{file}: {field}: {problem}")]
pub struct CurveFileError {
    /// The file as named on the command line.
    pub file: String,
    /// The offending field (`points[2][0]`, `knots`), or `document` for the file as a whole.
    pub field: String,
    /// What is wrong with it.
    pub problem: Problem,
}

/// What is wrong with a field of a curve file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Problem {
    /// The file could not be read.
    #[error("cannot read the file: {0}")]
    Unreadable(String),
    /// The text is not JSON (or a number is out of the f64 range).
    #[error("invalid JSON: {0}")]
    Json(String),
    /// A drawing file's syntax is broken (XML, path data, a transform, DXF group codes).
    #[error("{0}")]
    Syntax(String),
    /// A required field is absent.
    #[error("missing required field")]
    Missing,
    /// A field given twice (JSON parsers differ on which one counts: none is taken).
    #[error("given more than once")]
    Duplicate,
    /// A field that the kind does not have (a typo, most likely).
    #[error("unknown field for kind `{kind}` (allowed: {allowed})")]
    UnknownField {
        /// The curve kind.
        kind: String,
        /// The fields it allows.
        allowed: String,
    },
    /// `kind` names no known curve kind.
    #[error("unknown kind `{0}` (expected one of: {KINDS})")]
    UnknownKind(String),
    /// A value of the wrong JSON type.
    #[error("expected {expected}, got {got}")]
    WrongType {
        /// What the field must be.
        expected: &'static str,
        /// The JSON type found.
        got: &'static str,
    },
    /// A number beyond [`MAX_ABS`](super::MAX_ABS).
    #[error("{0:e} is too large (|value| must be at most 1e100)")]
    TooLarge(f64),
    /// A number that violates its range.
    #[error("must be {rule}, got {value}")]
    OutOfRange {
        /// The rule, e.g. "> 0".
        rule: String,
        /// The value given.
        value: f64,
    },
    /// An array of the wrong length.
    #[error("expected {expected}, got {got}")]
    WrongCount {
        /// The length required.
        expected: String,
        /// The length given.
        got: usize,
    },
    /// `knots` together with `periodic: true`.
    #[error("must be absent when `periodic` is true (a periodic curve has uniform knots)")]
    KnotsWithPeriodic,
    /// The curve's geometry does not suit the command (open where a closed curve is needed,
    /// a cusp, a corner at the seam, a self-intersection).
    #[error("{0}")]
    Geometry(String),
    /// The command does not take this kind of curve.
    #[error("{0}")]
    Unsupported(String),
    /// All control points coincide.
    #[error("all points coincide: the curve is a single point")]
    Degenerate,
    /// The spline cannot be represented: the rule is in the message.
    #[error("{0}")]
    Spline(#[from] bspline::Error),
    /// Derivatives overflow f64 (knots far too close for the coordinates).
    #[error("knot spacing too small for the coordinates: derivatives overflow f64")]
    Overflow,
}

const KINDS: &str = "bezier, bspline, circle, ellipse, limacon, elliptic_lemniscate, convexities, \
     line, arc, profile, region, regions";
