//! Errors of the medial axis.

/// Why a medial axis could not be computed.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The bisectors it is made of could not be computed (a curve the exact algebra refuses;
    /// the options are checked first, as [`Error::BadOption`]).
    #[error(transparent)]
    Bisector(#[from] zeroset::Error),
    /// An option is out of range (the field is named).
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
