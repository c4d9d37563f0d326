//! The tolerances the commands take, as validated types: each knows its accepted range and
//! why, written once here, and a value of one is in range by construction.
//!
//! - [`ParamTol`]: a parameter tolerance, relative to a domain's length.
//! - [`ChordTol`]: a chord tolerance, relative to the size of the input (how far a polyline
//!   may stray from the curve it stands for).

use std::fmt;

/// The default parameter tolerance: brackets of 1e-12 of a domain are a thousand times what
/// double precision resolves (the finest accepted, 1e-15), so decisions stay above rounding,
/// and far below any feature of an ordinary curve.
pub const DEFAULT_PARAM_TOL: f64 = 1e-12;

/// The default chord tolerance: a thousandth of the size draws smoothly; denser polylines cost
/// in proportion to their vertices (1e-6: ~10×). It sets the vertices' spacing, not their
/// accuracy (each is refined onto its curve to rounding).
pub const DEFAULT_CHORD_TOL: f64 = 1e-3;

/// A tolerance outside its range: the value, and what it must satisfy in words.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToleranceError {
    /// The value given.
    pub value: f64,
    /// What it must satisfy (the range, and why), as the errors quote it.
    pub requirement: &'static str,
}

impl fmt::Display for ToleranceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.value, self.requirement)
    }
}

impl std::error::Error for ToleranceError {}

/// `value` when it is finite and `in_range`, else the error quoting `requirement`.
fn checked(value: f64, in_range: bool, requirement: &'static str) -> Result<f64, ToleranceError> {
    if value.is_finite() && in_range {
        Ok(value)
    } else {
        Err(ToleranceError { value, requirement })
    }
}

/// The two tolerances of a command that traces curves, checked: `Err` names the field
/// (`tol` or `chord_tol`) that is out of range, with the error.
///
/// ```
/// use numeric::tolerance::check_pair;
/// assert!(check_pair(1e-12, 1e-3).is_ok());
/// assert_eq!(check_pair(1e-12, 2.0).unwrap_err().0, "chord_tol");
/// ```
pub fn check_pair(
    tol: f64,
    chord_tol: f64,
) -> Result<(ParamTol, ChordTol), (&'static str, ToleranceError)> {
    let param = ParamTol::new(tol).map_err(|e| ("tol", e))?;
    let chord = ChordTol::new(chord_tol).map_err(|e| ("chord_tol", e))?;
    Ok((param, chord))
}

/// A parameter tolerance relative to a domain's length, in `[1e-15, 1e-3)`.
///
/// ```
/// use numeric::tolerance::ParamTol;
/// assert_eq!(ParamTol::default().get(), 1e-12);
/// assert!(ParamTol::new(1e-9).is_ok());
/// assert!(ParamTol::new(1e-20).is_err() && ParamTol::new(f64::NAN).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct ParamTol(f64);

impl ParamTol {
    /// The finest: a few units of rounding of a parameter, below which steps are noise.
    pub const FINEST: f64 = 1e-15;
    /// The coarsest, excluded: brackets this wide merge the features (pairs, inflections,
    /// branches) of ordinary curves.
    pub const COARSEST: f64 = 1e-3;
    /// What a parameter tolerance must satisfy, in words.
    pub const REQUIREMENT: &'static str = "must be at least 1e-15 (what double precision \
        resolves of a domain) and below 1e-3 (coarser brackets merge the features of a curve)";

    /// The tolerance `value`, when it is in range.
    pub fn new(value: f64) -> Result<Self, ToleranceError> {
        let range = Self::FINEST..Self::COARSEST;
        checked(value, range.contains(&value), Self::REQUIREMENT).map(Self)
    }

    /// The tolerance as a number.
    pub const fn get(self) -> f64 {
        self.0
    }
}

impl Default for ParamTol {
    fn default() -> Self {
        Self(DEFAULT_PARAM_TOL)
    }
}

/// A chord tolerance relative to the size of the input, in `[1e-9, 0.5]`.
///
/// ```
/// use numeric::tolerance::ChordTol;
/// assert_eq!(ChordTol::default().get(), 1e-3);
/// assert!(ChordTol::new(0.5).is_ok() && ChordTol::new(0.6).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct ChordTol(f64);

impl ChordTol {
    /// The finest: a bisector's polyline within 1e-9 of it has up to a few hundred thousand
    /// vertices on the papers' figures; within 1e-11, millions (and gigabytes), closer than
    /// its vertices are computed.
    pub const FINEST: f64 = 1e-9;
    /// The coarsest, included: a polyline half the size away from the curve it stands for.
    pub const COARSEST: f64 = 0.5;
    /// What a chord tolerance must satisfy, in words.
    pub const REQUIREMENT: &'static str = "must be at least 1e-9 (finer polylines run to \
        millions of points, past the accuracy of their vertices) and at most 0.5";

    /// The tolerance `value`, when it is in range.
    pub fn new(value: f64) -> Result<Self, ToleranceError> {
        let range = Self::FINEST..=Self::COARSEST;
        checked(value, range.contains(&value), Self::REQUIREMENT).map(Self)
    }

    /// The tolerance as a number.
    pub const fn get(self) -> f64 {
        self.0
    }
}

impl Default for ChordTol {
    fn default() -> Self {
        Self(DEFAULT_CHORD_TOL)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The requirements quote the ranges the checks apply, at their ends and just past them.
    #[test]
    fn the_ranges_are_the_ones_the_words_give() {
        assert!(ParamTol::new(ParamTol::FINEST).is_ok());
        assert!(ParamTol::new(ParamTol::FINEST * (1.0 - 1e-15)).is_err());
        assert!(ParamTol::new(ParamTol::COARSEST).is_err());
        assert!(ParamTol::new(ParamTol::COARSEST * (1.0 - 1e-15)).is_ok());
        assert!(ChordTol::new(ChordTol::FINEST).is_ok());
        assert!(ChordTol::new(ChordTol::FINEST * (1.0 - 1e-15)).is_err());
        assert!(ChordTol::new(ChordTol::COARSEST).is_ok());
        assert!(ChordTol::new(f64::INFINITY).is_err());
        for (words, lo, hi) in [
            (ParamTol::REQUIREMENT, ParamTol::FINEST, ParamTol::COARSEST),
            (ChordTol::REQUIREMENT, ChordTol::FINEST, ChordTol::COARSEST),
        ] {
            assert!(words.contains(&format!("at least {lo:e}")), "{words}");
            assert!(words.contains(&format!("{hi}")) || words.contains(&format!("{hi:e}")));
        }
        assert!(
            ParamTol::new(DEFAULT_PARAM_TOL).is_ok() && ChordTol::new(DEFAULT_CHORD_TOL).is_ok()
        );
        let e = ParamTol::new(-1.0).unwrap_err();
        assert_eq!(e.to_string(), format!("-1 {}", ParamTol::REQUIREMENT));
    }
}
