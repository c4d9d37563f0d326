//! Errors of the medial axis.

/// Why a medial axis could not be computed.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The bisectors it is made of could not be computed (a curve the exact algebra refuses).
    #[error(transparent)]
    Bisector(#[from] zeroset::Error),
    /// A tolerance derived from the options is out of range (the field is named): the chord
    /// tolerance of a part's bisectors, relative to a size given for many parts together,
    /// too coarse for a part that small.
    #[error("option {field} = {value} is invalid: {why}")]
    BadOption {
        /// The option's name.
        field: &'static str,
        /// Its value.
        value: f64,
        /// What it must satisfy.
        why: &'static str,
    },
    /// The computation was cancelled by its watcher ([`curve::watch`]).
    #[error("cancelled")]
    Cancelled,
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
