//! The tolerances the commands take, as validated types: each knows its accepted range and
//! why, written once here, and a value of one is in range by construction.
//!
//! - [`ParamTol`]: a parameter tolerance, relative to a domain's length.
//! - [`ChordTol`]: a chord tolerance, relative to the size of the input (how far a polyline
//!   may stray from the curve it stands for).
//! - [`Size`]: the size the relative tolerances are taken of (the contract's: max(width,
//!   height) of the inputs' box).
//! - [`Settings`]: the three together, built once where a command's numbers come in (the
//!   tool's flags, Python's keywords) and carried by every options struct: a library that
//!   receives one never checks it again.

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

/// The constructor, the accessor and the default of a tolerance type: `new` accepts a finite
/// value in `$range` (its `FINEST` to its `COARSEST`, the end excluded or included) and
/// refuses any other quoting its `REQUIREMENT`; the default is `$default`.
macro_rules! tolerance_in_range {
    ($kind:ident, $range:expr, $default:expr) => {
        impl $kind {
            /// The tolerance `value`, when it is in range.
            pub fn new(value: f64) -> Result<Self, ToleranceError> {
                let range = $range;
                checked(value, range.contains(&value), Self::REQUIREMENT).map(Self)
            }

            /// The tolerance as a number.
            pub const fn get(self) -> f64 {
                self.0
            }
        }

        impl Default for $kind {
            fn default() -> Self {
                Self($default)
            }
        }
    };
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
}

tolerance_in_range!(ParamTol, Self::FINEST..Self::COARSEST, DEFAULT_PARAM_TOL);

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
}

tolerance_in_range!(ChordTol, Self::FINEST..=Self::COARSEST, DEFAULT_CHORD_TOL);

/// The size relative tolerances are taken of: the contract's, max(width, height) of the
/// bounding box of the command's inputs (all the parts of a multi-part input together), a
/// finite number above zero.
///
/// ```
/// use numeric::tolerance::Size;
/// assert_eq!(Size::new(4.0).unwrap().get(), 4.0);
/// assert!(Size::new(0.0).is_err() && Size::new(f64::INFINITY).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct Size(f64);

impl Size {
    /// What a size must satisfy, in words.
    pub const REQUIREMENT: &'static str = "must be a finite number > 0";

    /// The size `value`, when it is finite and above zero.
    pub fn new(value: f64) -> Result<Self, ToleranceError> {
        checked(value, value > 0.0, Self::REQUIREMENT).map(Self)
    }

    /// The size as a number.
    pub const fn get(self) -> f64 {
        self.0
    }
}

/// The tolerances of a command, and the size they are relative to, each valid by
/// construction: built once at the edge (from the tool's flags or Python's keywords) and
/// carried by the options of every algorithm it runs.
///
/// The default is the two default tolerances ([`DEFAULT_PARAM_TOL`], [`DEFAULT_CHORD_TOL`])
/// and no size: each algorithm then takes the size of its own input.
///
/// ```
/// use numeric::tolerance::{ChordTol, ParamTol, Settings, Size};
/// let settings = Settings::new(1e-9, 1e-4, Some(20.0)).unwrap();
/// assert_eq!(settings.tol.get(), 1e-9);
/// assert_eq!(settings.chord_tol.get(), 1e-4);
/// assert_eq!(settings.size.map(Size::get), Some(20.0));
/// // A number out of range is refused, naming its field.
/// let refused = Settings::new(1e-12, 2.0, None).unwrap_err();
/// assert_eq!((refused.field, refused.error.value), ("chord_tol", 2.0));
/// // The typed fields can be set on their own.
/// let fine = Settings { tol: ParamTol::new(1e-14).unwrap(), ..Settings::default() };
/// assert_eq!((fine.chord_tol, fine.size), (ChordTol::default(), None));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Settings {
    /// The parameter tolerance, relative to a domain's length.
    pub tol: ParamTol,
    /// The chord tolerance, relative to the size.
    pub chord_tol: ChordTol,
    /// The size the relative tolerances are taken of; `None`: each algorithm's own input's.
    pub size: Option<Size>,
}

/// A number of [`Settings`] out of range: the field it was for (`tol`, `chord_tol` or
/// `size`), and why.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SettingsError {
    /// The field: `tol`, `chord_tol` or `size`.
    pub field: &'static str,
    /// The value and what it must satisfy.
    pub error: ToleranceError,
}

impl fmt::Display for SettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.field, self.error)
    }
}

impl std::error::Error for SettingsError {}

impl Settings {
    /// The settings of these numbers, each checked in turn (`tol`, `chord_tol`, `size`): the
    /// first out of range is refused, named.
    pub fn new(tol: f64, chord_tol: f64, size: Option<f64>) -> Result<Self, SettingsError> {
        let named = |field| move |error| SettingsError { field, error };
        Ok(Self {
            tol: ParamTol::new(tol).map_err(named("tol"))?,
            chord_tol: ChordTol::new(chord_tol).map_err(named("chord_tol"))?,
            size: size.map(Size::new).transpose().map_err(named("size"))?,
        })
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
        assert!(Size::new(f64::MIN_POSITIVE).is_ok() && Size::new(f64::MAX).is_ok());
        assert!(Size::new(-0.0).is_err() && Size::new(f64::NAN).is_err());
    }

    /// The defaults are the two default tolerances and no size.
    #[test]
    fn the_default_settings_are_the_defaults() {
        let s = Settings::default();
        assert_eq!(s.tol.get(), DEFAULT_PARAM_TOL);
        assert_eq!(s.chord_tol.get(), DEFAULT_CHORD_TOL);
        assert_eq!(s.size, None);
        assert_eq!(
            Settings::new(DEFAULT_PARAM_TOL, DEFAULT_CHORD_TOL, None),
            Ok(s)
        );
    }

    mod props {
        use super::super::*;
        use proptest::prelude::*;

        /// A number out of `[lo, hi)` (or `[lo, hi]` with `closed`), or not finite.
        fn outside(lo: f64, hi: f64, closed: bool) -> impl Strategy<Value = f64> {
            let above = if closed {
                (hi.next_up()..f64::MAX).boxed()
            } else {
                (hi..f64::MAX).boxed()
            };
            prop_oneof![
                -f64::MAX..lo,
                above,
                Just(lo.next_down()),
                Just(if closed { hi.next_up() } else { hi }),
                Just(f64::NAN),
                Just(f64::INFINITY),
                Just(f64::NEG_INFINITY),
            ]
        }

        /// A number in `[lo, hi)`, evenly in its logarithm, with the ends.
        fn inside(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
            prop_oneof![
                (lo.ln()..hi.ln()).prop_map(move |l| l.exp().clamp(lo, hi.next_down())),
                Just(lo),
                Just(hi.next_down()),
            ]
        }

        proptest! {
            /// Every three numbers in range make settings holding them.
            #[test]
            fn every_value_in_range_is_accepted(
                tol in inside(ParamTol::FINEST, ParamTol::COARSEST),
                chord in prop_oneof![
                    inside(ChordTol::FINEST, ChordTol::COARSEST),
                    Just(ChordTol::COARSEST),
                ],
                size in prop_oneof![
                    Just(None),
                    inside(f64::MIN_POSITIVE, f64::MAX).prop_map(Some),
                    Just(Some(f64::MAX)),
                ],
            ) {
                let s = Settings::new(tol, chord, size).unwrap();
                prop_assert_eq!(s.tol.get(), tol);
                prop_assert_eq!(s.chord_tol.get(), chord);
                prop_assert_eq!(s.size.map(Size::get), size);
            }

            /// A number out of range, or NaN, is refused, naming its field, whatever the
            /// others are.
            #[test]
            fn every_value_out_of_range_is_refused_by_name(
                which in 0..3usize,
                bad_tol in outside(ParamTol::FINEST, ParamTol::COARSEST, false),
                bad_chord in outside(ChordTol::FINEST, ChordTol::COARSEST, true),
                bad_size in prop_oneof![-f64::MAX..=0.0, Just(f64::NAN), Just(f64::INFINITY)],
            ) {
                let (mut tol, mut chord, mut size) = (DEFAULT_PARAM_TOL, DEFAULT_CHORD_TOL, None);
                let (field, bad) = match which {
                    0 => { tol = bad_tol; ("tol", bad_tol) }
                    1 => { chord = bad_chord; ("chord_tol", bad_chord) }
                    _ => { size = Some(bad_size); ("size", bad_size) }
                };
                let e = Settings::new(tol, chord, size).unwrap_err();
                prop_assert_eq!(e.field, field);
                prop_assert!(e.error.value.to_bits() == bad.to_bits());
                let requirement = match field {
                    "tol" => ParamTol::REQUIREMENT,
                    "chord_tol" => ChordTol::REQUIREMENT,
                    _ => Size::REQUIREMENT,
                };
                prop_assert_eq!(e.error.requirement, requirement);
                prop_assert_eq!(e.to_string(), format!("{field}: {} {requirement}", e.error.value));
            }
        }
    }
}
