//! Why a command failed: the libraries' errors, typed, as the tool reports them.

use crate::io::{Curve, CurveFileError, CurveKind, Problem};
use std::fmt;
use thiserror::Error;

/// Why a command failed, and so the tool's exit status and the Python exception. Each
/// library's error is carried as it came (its `source`); the message is the tool's.
#[derive(Debug, Error)]
pub enum CommandError {
    /// Bad input: the file, the field and what is wrong (exit 2; Python `InputError`).
    #[error(transparent)]
    Input(#[from] CurveFileError),
    /// Options the command cannot take (exit 2; Python `ValueError`).
    #[error(transparent)]
    Usage(#[from] UsageError),
    /// A curve the curve commands could not compute on, blamed on no file (exit 1).
    #[error("{0}")]
    Antipodal(#[source] antipodal::Error),
    /// The spline arithmetic under the curve commands failed (exit 1).
    #[error("spline arithmetic failed: {0}")]
    Spline(#[source] bspline::Error),
    /// The bisector could not be computed (exit 1).
    #[error("bisector: {0}")]
    Bisector(#[source] zeroset::Error),
    /// The medial axis could not be computed, or was cancelled (exit 1).
    #[error("medial: {0}")]
    Medial(#[source] medial::Error),
    /// The offsets could not be computed: cancelled (exit 1).
    #[error("offset: {0}")]
    Offset(#[source] offset::Error),
    /// The V-carving could not be computed: cancelled (exit 1).
    #[error("vcarve: {0}")]
    Vcarve(#[source] offset::Error),
    /// The grasps could not be computed (exit 1; the curves the command does not take are
    /// [`CommandError::Input`], its options out of range [`CommandError::Usage`]).
    #[error("grasps: {0}")]
    Grasp(#[source] grasp::Error),
    /// A result the format cannot hold (exit 1).
    #[error(transparent)]
    Export(#[from] crate::export::ExportError),
    /// A file, a folder or the standard output that could not be written (exit 1).
    #[error("{doing}: {source}")]
    Io {
        /// What was being done, naming its path (`cannot write out.svg`).
        doing: String,
        /// Why it failed.
        source: std::io::Error,
    },
    /// The batch's pool of threads could not be started (exit 1).
    #[error("batch: cannot start {jobs} threads: {source}")]
    Threads {
        /// The threads asked for.
        jobs: usize,
        /// Why they could not be started.
        source: rayon::ThreadPoolBuildError,
    },
    /// Inputs of a batch that failed, each on its own line already (exit 1 if a computation
    /// failed, else 2).
    #[error("batch: {failed} of {inputs} inputs failed (the first: {})", first.message())]
    Batch {
        /// The inputs that failed.
        failed: usize,
        /// All the inputs.
        inputs: usize,
        /// The first failure, in the inputs' order.
        first: Box<CommandError>,
        /// Whether a failure was a computation's (exit 1), not only bad input or options.
        computation_failed: bool,
    },
    /// A defect, never expected: a panic caught ([`CommandError::panicked`]), or a state the
    /// code holds impossible, in its words (exit 1).
    #[error("{0}")]
    Internal(&'static str),
}

/// What kind of failure a [`CommandError`] is: what decides the exit status and the Python
/// exception.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FailureKind {
    /// Bad input: a file, a field (exit 2; Python `InputError`).
    Input,
    /// Options the command cannot take (exit 2; Python `ValueError`).
    Usage,
    /// A computation that could not be carried out (exit 1; Python `CurvekitError`).
    Computation,
}

impl CommandError {
    /// A panic caught: a defect, reported as `internal error`.
    pub fn panicked() -> Self {
        CommandError::Internal("internal error")
    }

    /// Whether the failure is bad input, bad options or a computation's.
    pub fn kind(&self) -> FailureKind {
        match self {
            CommandError::Input(_) => FailureKind::Input,
            CommandError::Usage(_) => FailureKind::Usage,
            // (A batch of only bad inputs and options was a usage error before its kind had
            // a name: exit 2.)
            CommandError::Batch {
                computation_failed: false,
                ..
            } => FailureKind::Usage,
            CommandError::Antipodal(_)
            | CommandError::Spline(_)
            | CommandError::Bisector(_)
            | CommandError::Medial(_)
            | CommandError::Offset(_)
            | CommandError::Vcarve(_)
            | CommandError::Grasp(_)
            | CommandError::Export(_)
            | CommandError::Io { .. }
            | CommandError::Threads { .. }
            | CommandError::Batch { .. }
            | CommandError::Internal(_) => FailureKind::Computation,
        }
    }

    /// The tool's exit status for this failure.
    pub fn exit_code(&self) -> u8 {
        match self.kind() {
            FailureKind::Input | FailureKind::Usage => 2,
            FailureKind::Computation => 1,
        }
    }

    /// The message on one line, as the tool prints it after `curvekit: `.
    pub fn message(&self) -> String {
        self.to_string().replace('\n', " ")
    }

    /// `source` of writing, creating or reading `doing` (`cannot write out.svg`).
    pub fn io(doing: String, source: std::io::Error) -> Self {
        CommandError::Io { doing, source }
    }
}

/// Options a command cannot take: each says the option as the command line spells it.
#[derive(Debug, Error)]
pub enum UsageError {
    /// An option's value out of the range the command takes.
    #[error("{}--{option}: {value} is out of range: {expected}", InCommand(*command))]
    OutOfRange {
        /// The command that names itself first (`vcarve: --max-depth: …`), if one does.
        command: Option<&'static str>,
        /// The option (`chord-tol`).
        option: String,
        /// Its value, as a user would write it.
        value: String,
        /// What it must be.
        expected: String,
    },
    /// An option the command needs, missing (the text names it).
    #[error("{0}")]
    Missing(&'static str),
    /// Options, or inputs, that do not go together (the text names them).
    #[error("{0}")]
    Conflict(&'static str),
    /// Options of the batch that its command does not take.
    #[error("batch {command}: does not take {}", options.join("; "))]
    NotTaken {
        /// The batch's command.
        command: &'static str,
        /// The options it does not take.
        options: Vec<&'static str>,
    },
    /// The medial axis's options, refused (as the crate names them).
    #[error("medial: {0}")]
    Medial(#[source] medial::Error),
    /// The offsets' options or axis, refused.
    #[error("offset: {0}")]
    Offset(#[source] offset::Error),
    /// The V-carving's axis, refused (its options out of range are [`UsageError::OutOfRange`]).
    #[error("vcarve: {0}")]
    Vcarve(#[source] offset::Error),
}

impl UsageError {
    /// `option` out of range at `value`: it must be `expected` (no command named first).
    pub fn out_of_range(
        option: impl Into<String>,
        value: impl fmt::Display,
        expected: impl Into<String>,
    ) -> Self {
        UsageError::OutOfRange {
            command: None,
            option: option.into(),
            value: value.to_string(),
            expected: expected.into(),
        }
    }
}

/// The command an out-of-range message names first, with its colon (`vcarve: `), or nothing.
struct InCommand(Option<&'static str>);

impl fmt::Display for InCommand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(command) => write!(f, "{command}: "),
            None => Ok(()),
        }
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
/// caused them, the rest is the computation's.
pub(super) fn antipodal_error(e: antipodal::Error, curves: &[&Curve]) -> CommandError {
    use antipodal::Error as E;
    match e {
        E::InvalidOption {
            field,
            value,
            expected,
        } => UsageError::out_of_range(field, value, expected).into(),
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
            None => CommandError::Antipodal(e),
        },
        E::Spline(e) => CommandError::Spline(e),
        // (The tool takes every curve as a profile itself where one is needed.)
        E::TooComplex { .. } | E::NoSegment { .. } => CommandError::Antipodal(e),
        // (A refusal of the two profiles together: the first names them.)
        E::TooManySegmentPairs { .. } => match curves.first() {
            Some(c) => refuse(c, "segments", &e.to_string()),
            None => CommandError::Antipodal(e),
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

/// A bisector that could not be computed: the computation's failure (its options are
/// valid by construction).
pub(super) fn zeroset_error(e: zeroset::Error) -> CommandError {
    CommandError::Bisector(e)
}

/// A V-carving option out of range as the command line names it (`vcarve: --max-depth: …`);
/// a cancelled carving is the computation's failure, any other refusal a usage error.
pub(super) fn vcarve_error(e: offset::Error) -> CommandError {
    match e {
        offset::Error::Cancelled => CommandError::Vcarve(e),
        offset::Error::BadOption { field, value, why } => UsageError::OutOfRange {
            command: Some("vcarve"),
            option: field.replace('_', "-"),
            value: value.to_string(),
            expected: why.into(),
        }
        .into(),
        e => UsageError::Vcarve(e).into(),
    }
}

/// A number as a user would write it: the shorter of the plain and the scientific notation
/// (`1e-12`, not `0.000000000001`).
pub(super) fn number(x: f64) -> String {
    let (plain, scientific) = (format!("{x}"), format!("{x:e}"));
    if scientific.len() < plain.len() {
        scientific
    } else {
        plain
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each typed error prints the text the tool printed when it was a string.
    #[test]
    fn typed_errors_print_the_tools_texts() {
        let chord_refused = format!(
            "--chord-tol: 1e-12 is out of range: {}",
            numeric::tolerance::ChordTol::REQUIREMENT
        );
        let cases: Vec<(CommandError, &str, u8)> = vec![
            (
                UsageError::out_of_range("tol", 0.5, "must be < 1e-3").into(),
                "--tol: 0.5 is out of range: must be < 1e-3",
                2,
            ),
            (
                vcarve_error(offset::Error::BadOption {
                    field: "max_depth",
                    value: -1.0,
                    why: "must be > 0",
                }),
                "vcarve: --max-depth: -1 is out of range: must be > 0",
                2,
            ),
            (
                super::super::settings(super::super::CommandFamily::Bisector, 1e-12, 1e-12)
                    .unwrap_err(),
                &chord_refused,
                2,
            ),
            (
                UsageError::NotTaken {
                    command: "medial",
                    options: vec!["--with", "--trimmed"],
                }
                .into(),
                "batch medial: does not take --with; --trimmed",
                2,
            ),
            (
                zeroset_error(zeroset::Error::NotPlanar { which: 1, dim: 3 }),
                "bisector: curve 1 has dimension 3; bisectors need planar curves",
                1,
            ),
            (
                CommandError::Offset(offset::Error::Cancelled),
                "offset: cancelled",
                1,
            ),
            (
                vcarve_error(offset::Error::Cancelled),
                "vcarve: cancelled",
                1,
            ),
            (
                CommandError::Grasp(grasp::Error::ZeroSet(zeroset::Error::NotPlanar {
                    which: 1,
                    dim: 3,
                })),
                "grasps: curve 1 has dimension 3; bisectors need planar curves",
                1,
            ),
            (
                CommandError::io(
                    "cannot write out.svg".into(),
                    std::io::Error::other("disk full"),
                ),
                "cannot write out.svg: disk full",
                1,
            ),
            (CommandError::panicked(), "internal error", 1),
        ];
        for (error, text, exit) in cases {
            assert_eq!(error.message(), text);
            assert_eq!(error.exit_code(), exit, "{text}");
        }
    }

    /// A batch's failure names the first input's and keeps the worst exit status.
    #[test]
    fn a_batch_fails_as_its_worst_input() {
        let first = || Box::new(CommandError::panicked());
        let batch = |computation_failed| CommandError::Batch {
            failed: 2,
            inputs: 5,
            first: first(),
            computation_failed,
        };
        assert_eq!(
            batch(true).message(),
            "batch: 2 of 5 inputs failed (the first: internal error)"
        );
        assert_eq!(batch(true).exit_code(), 1);
        assert_eq!(batch(false).exit_code(), 2);
    }
}
