//! Why a command failed: the library's errors as the tool reports them.

use crate::io::{Curve, CurveFileError, CurveKind, Problem};
use thiserror::Error;

/// Why a command failed, and so the tool's exit status and the Python exception.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CommandError {
    /// Bad input: the file, the field and what is wrong (exit 2; Python `InputError`).
    #[error(transparent)]
    Input(#[from] CurveFileError),
    /// An option out of range (exit 2; Python `ValueError`).
    #[error("{0}")]
    Usage(String),
    /// Anything else: a computation that could not be carried out (exit 1).
    #[error("{0}")]
    Other(String),
}

impl CommandError {
    /// The tool's exit status for this failure.
    pub fn exit_code(&self) -> u8 {
        match self {
            CommandError::Input(_) | CommandError::Usage(_) => 2,
            CommandError::Other(_) => 1,
        }
    }

    /// The message on one line, as the tool prints it after `curvekit: `.
    pub fn message(&self) -> String {
        self.to_string().replace('\n', " ")
    }
}

/// Bad input in `field` of `curve`'s file: unsupported there.
pub(super) fn refuse(curve: &Curve, field: &str, why: &str) -> CommandError {
    CommandError::Input(CurveFileError {
        file: curve.file.clone(),
        field: field.into(),
        problem: Problem::Unsupported(why.into()),
    })
}

/// Options errors are usage errors, geometric refusals are input errors naming the curve that
/// caused them, the rest is internal.
pub(super) fn antipodal_error(e: antipodal::Error, curves: &[&Curve]) -> CommandError {
    use antipodal::Error as E;
    match e {
        E::InvalidOption {
            field,
            value,
            expected,
        } => CommandError::Usage(format!("--{field}: {value} is out of range: {expected}")),
        E::NotClosed { .. }
        | E::Cusp { .. }
        | E::Corner { .. }
        | E::SelfIntersecting { .. }
        | E::Winding { .. }
        | E::InSegment { .. }
        | E::Curve(_) => match blame(curves) {
            Some(culprit) => CommandError::Input(CurveFileError {
                file: culprit.file.clone(),
                field: match culprit.shape {
                    CurveKind::Spline(_) => "points",
                    CurveKind::Analytic(_) | CurveKind::Segment(_) => "kind",
                    CurveKind::Profile(_) => "segments",
                    CurveKind::Region(_) | CurveKind::Regions(_) => "outer",
                }
                .into(),
                problem: Problem::Geometry(e.to_string()),
            }),
            None => CommandError::Other(e.to_string()),
        },
        E::Spline(e) => CommandError::Other(format!("spline arithmetic failed: {e}")),
        E::TooComplex { .. } => CommandError::Other(e.to_string()),
        // (A refusal of the two profiles together: the first names them.)
        E::TooManySegmentPairs { .. } => match curves.first() {
            Some(c) => refuse(c, "segments", &e.to_string()),
            None => CommandError::Other(e.to_string()),
        },
    }
}

/// The curve a geometric refusal is about: with two curves, the first one that is refused on
/// its own (paired with a unit circle, which is never refused), else the second.
fn blame<'c>(curves: &[&'c Curve]) -> Option<&'c Curve> {
    let refused = |c: &Curve| {
        let Ok(circle) = antipodal::shapes::Circle::new(1.0, [0.0, 0.0]) else {
            return false;
        };
        antipodal::common_tangents(c.plane_curve(), &circle, &antipodal::Options::default())
            .is_err()
    };
    match curves {
        [first, second, ..] if !refused(first) => Some(second),
        _ => curves.first().copied(),
    }
}

/// A bisector option out of range is a usage error (named as the command line spells it);
/// the rest is internal.
pub(super) fn zeroset_error(e: zeroset::Error) -> CommandError {
    match e {
        zeroset::Error::BadOption { field, value, why } => {
            let flag = field.replace('_', "-");
            CommandError::Usage(format!(
                "--{flag}: {} is out of range: {why}",
                number(value)
            ))
        }
        e => CommandError::Other(format!("bisector: {e}")),
    }
}

/// A number as a user would write it: the shorter of the plain and the scientific notation
/// (`1e-12`, not `0.000000000001`).
fn number(x: f64) -> String {
    let (plain, scientific) = (format!("{x}"), format!("{x:e}"));
    if scientific.len() < plain.len() {
        scientific
    } else {
        plain
    }
}
