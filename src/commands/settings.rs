//! The settings of a command, built once from its flags (or Python's keywords) and handed to
//! the options of every algorithm it runs: a tolerance out of range is refused here, in the
//! words the tool has always used for the command.

use super::errors::number;
use super::{CommandError, UsageError};
use numeric::tolerance::{Settings, SettingsError, Size};

/// The commands that report a tolerance out of range alike.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CommandFamily {
    /// `antipodal`, `inflections`, `tangents` (and `demo`): `--tol: 0.5 is out of range: …`.
    Curves,
    /// `bisector`: `--chord-tol: 1e-12 is out of range: …`.
    Bisector,
    /// `medial`, `offset`, `vcarve`, as the medial axis names its options:
    /// `medial: option chord_tol = 0.6 is invalid: …`.
    Regions,
}

/// The settings of a command of `family` from its numbers (no size: each algorithm takes its
/// input's own, or the commands on regions the size of all the parts): a number out of range
/// is a usage error.
///
/// ```
/// use curvekit::commands::{settings, CommandFamily};
/// let s = settings(CommandFamily::Bisector, 1e-12, 1e-4).unwrap();
/// assert_eq!(s.chord_tol.get(), 1e-4);
/// let refused = settings(CommandFamily::Bisector, 1e-12, 1e-12).unwrap_err();
/// assert!(refused.message().starts_with("--chord-tol: 1e-12 is out of range: must be at least 1e-9"));
/// ```
pub fn settings(family: CommandFamily, tol: f64, chord_tol: f64) -> Result<Settings, CommandError> {
    Settings::new(tol, chord_tol, None).map_err(|e| refused(family, e))
}

/// `settings` with the size `size` (the contract's, of all the parts of an input).
pub(super) fn sized(settings: &Settings, size: f64) -> Result<Settings, CommandError> {
    let size = Size::new(size).map_err(|error| {
        refused(
            CommandFamily::Regions,
            SettingsError {
                field: "size",
                error,
            },
        )
    })?;
    Ok(Settings {
        size: Some(size),
        ..*settings
    })
}

/// A number of the settings out of range, as `family` reports it.
fn refused(family: CommandFamily, e: SettingsError) -> CommandError {
    let SettingsError { field, error } = e;
    match family {
        CommandFamily::Curves => {
            UsageError::out_of_range(field.replace('_', "-"), error.value, error.requirement)
        }
        CommandFamily::Bisector => UsageError::out_of_range(
            field.replace('_', "-"),
            number(error.value),
            error.requirement,
        ),
        CommandFamily::Regions => UsageError::Medial(medial::Error::BadOption {
            field,
            value: error.value,
            why: error.requirement,
        }),
    }
    .into()
}

#[cfg(test)]
mod tests {
    use super::*;
    use numeric::tolerance::{ChordTol, ParamTol, Size};

    /// Each family words a number out of range as the tool always has.
    #[test]
    fn each_family_refuses_in_its_words() {
        let cases = [
            (
                settings(CommandFamily::Curves, 0.5, 1e-3),
                format!("--tol: 0.5 is out of range: {}", ParamTol::REQUIREMENT),
            ),
            (
                settings(CommandFamily::Bisector, 1e-12, 1e-12),
                format!(
                    "--chord-tol: 1e-12 is out of range: {}",
                    ChordTol::REQUIREMENT
                ),
            ),
            (
                settings(CommandFamily::Bisector, 1e-16, 1e-3),
                format!("--tol: 1e-16 is out of range: {}", ParamTol::REQUIREMENT),
            ),
            (
                settings(CommandFamily::Regions, 1e-12, 0.6),
                format!(
                    "medial: option chord_tol = 0.6 is invalid: {}",
                    ChordTol::REQUIREMENT
                ),
            ),
            (
                sized(&Settings::default(), 0.0),
                format!("medial: option size = 0 is invalid: {}", Size::REQUIREMENT),
            ),
        ];
        for (found, text) in cases {
            let e = found.unwrap_err();
            assert_eq!(e.message(), text);
            assert_eq!(e.exit_code(), 2, "{text}");
        }
        assert!(settings(CommandFamily::Regions, 1e-12, 0.5).is_ok());
    }
}
