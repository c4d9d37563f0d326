//! The Python package `curvekit` (its native module `curvekit._curvekit`): curves read from
//! the tool's documents, files and arrays, the tool's commands as functions that release the
//! GIL, and their results as small objects with numpy arrays whose `to_dict()` is the tool's
//! JSON. The geometry is the library's (`curvekit::commands`); this crate only translates.

mod curves;
mod grasps;
mod many;
mod region_results;
mod registry;
mod results;

use curve::watch::Watch;
use curvekit::commands::{self, CommandError, CommandFamily, FailureKind};
use curves::{PyCurve, PyPrepared};
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyValueError};
use pyo3::prelude::*;
use region_results::{PyMedialAxis, PyOffsets, PyVCarve};
use results::{PyAntipodal, PyBisector, PyInflections, PyTangents};
use std::sync::mpsc;
use std::sync::Arc;
use std::time::Duration;

create_exception!(
    curvekit,
    InputError,
    PyValueError,
    "Bad input: the message names the file (or the name given), the field and what is wrong, \
     as the tool's does."
);
create_exception!(
    curvekit,
    CurvekitError,
    PyException,
    "A computation that could not be carried out (the tool's exit status 1)."
);

/// A failure a call can end in: its kind decides the Python exception, its message the text.
/// The tool's commands fail with a [`CommandError`]; the calls built on a library directly
/// (`grasps`) with their own type.
pub(crate) trait Failure: Send {
    /// Bad input, bad options or a computation's failure.
    fn kind(&self) -> FailureKind;
    /// The message on one line.
    fn message(&self) -> String;
    /// A panic caught: a defect, reported as `internal error`.
    fn panicked() -> Self;
}

impl Failure for CommandError {
    fn kind(&self) -> FailureKind {
        CommandError::kind(self)
    }
    fn message(&self) -> String {
        CommandError::message(self)
    }
    fn panicked() -> Self {
        CommandError::panicked()
    }
}

/// The library's failure as a Python exception: bad input `InputError` (a `ValueError`), an
/// option out of range `ValueError`, anything else `CurvekitError`.
pub(crate) fn to_py_err(e: CommandError) -> PyErr {
    failure_to_py_err(e)
}

/// [`to_py_err`] for any [`Failure`].
pub(crate) fn failure_to_py_err(e: impl Failure) -> PyErr {
    match e.kind() {
        FailureKind::Input => InputError::new_err(e.message()),
        FailureKind::Usage => PyValueError::new_err(as_keyword(&e.message())),
        FailureKind::Computation => CurvekitError::new_err(e.message()),
    }
}

/// A usage message as Python spells the option: `--chord-tol: …` is `chord_tol: …`.
fn as_keyword(message: &str) -> String {
    match message.strip_prefix("--").and_then(|m| m.split_once(':')) {
        Some((flag, rest)) => format!("{}:{rest}", flag.replace('-', "_")),
        None => message.to_string(),
    }
}

/// Runs `work` without the GIL (other Python threads go on meanwhile); a panic, a defect never
/// expected, becomes a `CurvekitError` instead of ending the interpreter's thread. For the
/// calls that take microseconds to milliseconds: see [`cancellable`] for the long ones.
pub(crate) fn detached<T: Send, E: Failure>(
    py: Python<'_>,
    work: impl FnOnce() -> Result<T, E> + Send,
) -> PyResult<T> {
    py.detach(|| {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(work))
            .unwrap_or_else(|_| Err(E::panicked()))
    })
    .map_err(failure_to_py_err)
}

/// How often a long call looks for a signal (Ctrl-C): a cancelled computation stops at its
/// next unit of work, within 0.1 s of the signal in all.
const SIGNAL_POLL: Duration = Duration::from_millis(20);

/// [`detached`] for the calls that may take seconds (the medial axis, offsets): `work` runs
/// on a worker thread under a watch ([`curve::watch`]) while this thread, the one Python's
/// signal handlers run on, looks for signals; on Ctrl-C the work is cancelled and the
/// signal's exception (`KeyboardInterrupt`) raised. (The worker costs tens of microseconds
/// a call, which the short commands are spared.)
pub(crate) fn cancellable<T: Send>(
    py: Python<'_>,
    work: impl FnOnce() -> Result<T, CommandError> + Send,
) -> PyResult<T> {
    let internal = || Err(CommandError::panicked());
    let watch = Arc::new(Watch::default());
    let outcome = py.detach(|| {
        std::thread::scope(|scope| {
            let (send, receive) = mpsc::channel();
            let worker = Arc::clone(&watch);
            scope.spawn(move || {
                let found = worker.run(|| {
                    std::panic::catch_unwind(std::panic::AssertUnwindSafe(work))
                        .unwrap_or_else(|_| internal())
                });
                let _ = send.send(found);
            });
            let mut interrupted = None;
            loop {
                match receive.recv_timeout(SIGNAL_POLL) {
                    Ok(found) => break interrupted.map_or(Ok(found), Err),
                    Err(mpsc::RecvTimeoutError::Disconnected) => {
                        break interrupted.map_or(Ok(internal()), Err)
                    }
                    Err(mpsc::RecvTimeoutError::Timeout) if interrupted.is_none() => {
                        if let Err(e) = Python::attach(|py| py.check_signals()) {
                            watch.cancel();
                            interrupted = Some(e);
                        }
                    }
                    Err(mpsc::RecvTimeoutError::Timeout) => {}
                }
            }
        })
    });
    outcome?.map_err(to_py_err)
}

/// A curve as the one-curve commands take it: prepared (warm) or not (prepared for this run).
#[derive(FromPyObject)]
pub(crate) enum OneCurve<'py> {
    Prepared(Bound<'py, PyPrepared>),
    Curve(Bound<'py, PyCurve>),
}

impl OneCurve<'_> {
    /// Runs `command` with `opts`: warm on the prepared curve, cold on the curve.
    fn run<T: Send>(
        &self,
        py: Python<'_>,
        command: &OneCurveCommand<T>,
        opts: &::antipodal::Options,
    ) -> PyResult<(T, commands::CurveSummary)> {
        match self {
            OneCurve::Prepared(p) => {
                let prepared = p.get().prepared();
                let found = detached(py, || (command.warm)(prepared, opts))?;
                Ok((found, commands::CurveSummary::of(prepared.curve())))
            }
            OneCurve::Curve(c) => {
                let c = c.get();
                Ok((
                    detached(py, || (command.cold)(c.curve(), opts))?,
                    c.summary(),
                ))
            }
        }
    }
}

/// A one-curve command: on a curve prepared (warm), and on a curve (prepared for the run).
pub(crate) struct OneCurveCommand<T> {
    warm: fn(&commands::PreparedCurve, &::antipodal::Options) -> Result<T, CommandError>,
    cold: fn(&curvekit::io::Curve, &::antipodal::Options) -> Result<T, CommandError>,
}

/// `antipodal`, on a curve prepared or not.
pub(crate) const ANTIPODAL_WARM_OR_COLD: OneCurveCommand<commands::AntipodalFound> =
    OneCurveCommand {
        warm: commands::PreparedCurve::antipodal,
        cold: commands::antipodal,
    };

/// `inflections`, on a curve prepared or not.
pub(crate) const INFLECTIONS_WARM_OR_COLD: OneCurveCommand<commands::InflectionsFound> =
    OneCurveCommand {
        warm: commands::PreparedCurve::inflections,
        cold: commands::inflections,
    };

/// A one-curve command's two Python functions, alike but for the command and its result
/// class: `$single` (`$name` in Python) on one curve, prepared or not, and `$many` on a list
/// of them, computed in parallel.
macro_rules! one_curve_functions {
    ($(#[doc = $doc:literal])* $name:literal: $single:ident, $many:ident, $command:ident => $class:ident) => {
        $(#[doc = $doc])*
        #[pyfunction(name = $name)]
        #[pyo3(signature = (curve, *, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
        fn $single(py: Python<'_>, curve: OneCurve<'_>, tol: f64) -> PyResult<$class> {
            let opts = curve_options(tol).map_err(to_py_err)?;
            let (found, summary) = curve.run(py, &$command, &opts)?;
            Ok($class::new(found, vec![summary]))
        }

        #[doc = concat!("`", $name, "` of each curve.")]
        #[pyfunction]
        #[pyo3(signature = (curves, *, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
        fn $many(
            py: Python<'_>,
            curves: Vec<Bound<'_, PyAny>>,
            tol: f64,
        ) -> PyResult<Vec<$class>> {
            many::one_curve_each(py, &curves, tol, &$command, $class::new)
        }
    };
}

one_curve_functions!(
    /// The antipodal point pairs of a closed curve or profile (Jia 2004): grasps of a two-finger
    /// gripper. `tol` is the parameter tolerance relative to the domain's length.
    "antipodal": antipodal_of, antipodal_many, ANTIPODAL_WARM_OR_COLD => PyAntipodal
);

one_curve_functions!(
    /// The inflections of a curve (and the corners of a profile).
    "inflections": inflections_of, inflections_many, INFLECTIONS_WARM_OR_COLD => PyInflections
);

/// The lines tangent to two curves.
#[pyfunction(name = "tangents")]
#[pyo3(signature = (curve1, curve2, *, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn tangents_of(
    py: Python<'_>,
    curve1: &Bound<'_, PyCurve>,
    curve2: &Bound<'_, PyCurve>,
    tol: f64,
) -> PyResult<PyTangents> {
    let opts = curve_options(tol).map_err(to_py_err)?;
    let (a, b) = (curve1.get(), curve2.get());
    let found = detached(py, || commands::tangents(a.curve(), b.curve(), &opts))?;
    Ok(PyTangents::new(found, vec![a.summary(), b.summary()]))
}

/// The bisector of two curves, or the self-bisector of one (`curve2` omitted), as polylines
/// within `chord_tol` (relative to the curves' size) of the true bisector.
#[pyfunction(name = "bisector")]
#[pyo3(signature = (curve1, curve2 = None, *, method = "f3", trimmed = false,
                    chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn bisector_of(
    py: Python<'_>,
    curve1: &Bound<'_, PyCurve>,
    curve2: Option<&Bound<'_, PyCurve>>,
    method: &str,
    trimmed: bool,
    chord_tol: f64,
    tol: f64,
) -> PyResult<PyBisector> {
    let opts =
        bisector_options(bisector_method(method)?, trimmed, chord_tol, tol).map_err(to_py_err)?;
    let a = curve1.get();
    let b = curve2.map(|c| c.get());
    let found = detached(py, || {
        commands::bisector(a.curve(), b.map(PyCurve::curve), &opts)
    })?;
    let summaries = std::iter::once(a).chain(b).map(PyCurve::summary).collect();
    Ok(PyBisector::new(found, summaries))
}

/// The medial axis of a region (a region, or the area inside a closed curve or profile).
#[pyfunction(name = "medial")]
#[pyo3(signature = (region, *, chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL, fit = false,
                    exterior = false, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn medial_of(
    py: Python<'_>,
    region: &Bound<'_, PyCurve>,
    chord_tol: f64,
    fit: bool,
    exterior: bool,
    tol: f64,
) -> PyResult<PyMedialAxis> {
    let opts = medial_options(chord_tol, fit, exterior, tol).map_err(to_py_err)?;
    let c = region.get();
    let (axis, summary) = cancellable(py, || medial_work(c, &opts))?;
    Ok(PyMedialAxis::new(axis, vec![summary]))
}

/// The inward (or `outward`) offsets of a region at `distance`, at each of `distances`, or at
/// every multiple of `step` while the region lasts (one of them), from its medial axis.
#[pyfunction(name = "offset")]
#[pyo3(signature = (region, *, distance = None, distances = None, step = None,
                    outward = false, chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL,
                    tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
// (One argument per keyword of the Python function.)
#[allow(clippy::too_many_arguments)]
fn offset_of(
    py: Python<'_>,
    region: &Bound<'_, PyCurve>,
    distance: Option<f64>,
    distances: Option<Vec<f64>>,
    step: Option<f64>,
    outward: bool,
    chord_tol: f64,
    tol: f64,
) -> PyResult<PyOffsets> {
    let asked = offset_distances(distance, distances, step)?;
    let (opts, medial_opts) = offset_options(&asked, outward, chord_tol, tol).map_err(to_py_err)?;
    let c = region.get();
    let (found, summary) = cancellable(py, || offset_work(c, &asked, &opts, &medial_opts))?;
    Ok(PyOffsets::new(found, vec![summary]))
}

/// The bisector function named by the keyword `method` (one of `"f1"`, `"f2"`, `"f3"`).
pub(crate) fn bisector_method(method: &str) -> PyResult<zeroset::Method> {
    match method {
        "f1" => Ok(zeroset::Method::F1),
        "f2" => Ok(zeroset::Method::F2),
        "f3" => Ok(zeroset::Method::F3),
        other => Err(PyValueError::new_err(format!(
            "method: {other:?} is not one of \"f1\", \"f2\", \"f3\""
        ))),
    }
}

/// The bisector's options from the keywords, their settings built once (out of range: the
/// usage error the call raises).
pub(crate) fn bisector_options(
    method: zeroset::Method,
    trimmed: bool,
    chord_tol: f64,
    tol: f64,
) -> Result<zeroset::BisectorOptions, CommandError> {
    Ok(zeroset::BisectorOptions {
        method,
        settings: commands::settings(CommandFamily::Bisector, tol, chord_tol)?,
        trimmed,
        ..zeroset::BisectorOptions::default()
    })
}

/// The curve commands' options from the keyword `tol` (they take no chord tolerance).
pub(crate) fn curve_options(tol: f64) -> Result<::antipodal::Options, CommandError> {
    let settings = commands::settings(
        CommandFamily::Curves,
        tol,
        curvekit::numeric::tolerance::DEFAULT_CHORD_TOL,
    )?;
    let opts = ::antipodal::Options {
        settings,
        ..::antipodal::Options::default()
    };
    commands::validate_options(&opts)?;
    Ok(opts)
}

/// The distances `offset` is asked for: exactly one of the three keywords.
pub(crate) fn offset_distances(
    distance: Option<f64>,
    distances: Option<Vec<f64>>,
    step: Option<f64>,
) -> PyResult<commands::Distances> {
    match (distance, distances, step) {
        (Some(d), None, None) => Ok(commands::Distances::List(vec![d])),
        (None, Some(list), None) => Ok(commands::Distances::List(list)),
        (None, None, Some(s)) => Ok(commands::Distances::Step(s)),
        _ => Err(PyValueError::new_err(
            "offset: give one of distance, distances and step",
        )),
    }
}

/// The medial axis's options from the keywords (the size is the region's own, or all its
/// parts').
pub(crate) fn medial_options(
    chord_tol: f64,
    fit: bool,
    exterior: bool,
    tol: f64,
) -> Result<::medial::MedialOptions, CommandError> {
    Ok(::medial::MedialOptions {
        settings: commands::settings(CommandFamily::Regions, tol, chord_tol)?,
        fit,
        exterior,
    })
}

/// The offsets' options and the medial axis's, from the keywords, the distances `asked`
/// checked first.
pub(crate) fn offset_options(
    asked: &commands::Distances,
    outward: bool,
    chord_tol: f64,
    tol: f64,
) -> Result<(::offset::OffsetOptions, ::medial::MedialOptions), CommandError> {
    commands::validate_offset(asked, outward)?;
    let medial_opts = medial_options(chord_tol, false, outward, tol)?;
    let opts = ::offset::OffsetOptions {
        settings: medial_opts.settings,
    };
    Ok((opts, medial_opts))
}

/// The V-carving options and the medial axis's, from the keywords, the bit checked first.
pub(crate) fn vcarve_options(
    angle: f64,
    max_depth: Option<f64>,
    chord_tol: f64,
    tol: f64,
) -> Result<(::offset::VCarveOptions, ::medial::MedialOptions), CommandError> {
    let bit = ::offset::VCarveOptions {
        angle,
        max_depth,
        offset: ::offset::OffsetOptions::default(),
    };
    commands::validate_vcarve_options(&bit)?;
    let medial_opts = medial_options(chord_tol, false, false, tol)?;
    let opts = ::offset::VCarveOptions {
        offset: ::offset::OffsetOptions {
            settings: medial_opts.settings,
        },
        ..bit
    };
    Ok((opts, medial_opts))
}

/// The tool paths of a V-bit of included `angle` (degrees) over a region's medial axis, at
/// most `max_depth` deep (with a flat pass there).
#[pyfunction(name = "vcarve")]
#[pyo3(signature = (region, *, angle, max_depth = None,
                    chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn vcarve_of(
    py: Python<'_>,
    region: &Bound<'_, PyCurve>,
    angle: f64,
    max_depth: Option<f64>,
    chord_tol: f64,
    tol: f64,
) -> PyResult<PyVCarve> {
    let (opts, medial_opts) =
        vcarve_options(angle, max_depth, chord_tol, tol).map_err(to_py_err)?;
    let c = region.get();
    let (found, summary) = cancellable(py, || vcarve_work(c, &opts, &medial_opts))?;
    Ok(PyVCarve::new(found, vec![summary]))
}

/// The medial axis of the region a curve is or encloses, and that region's summary (one
/// call's work, alone or in a list).
pub(crate) fn medial_work(
    c: &PyCurve,
    opts: &::medial::MedialOptions,
) -> Result<(::medial::MedialAxis, commands::CurveSummary), CommandError> {
    let region = c.region()?;
    Ok((
        commands::medial(region, opts)?,
        commands::CurveSummary::of(region),
    ))
}

/// The offsets of the region a curve is or encloses, and that region's summary.
pub(crate) fn offset_work(
    c: &PyCurve,
    asked: &commands::Distances,
    opts: &::offset::OffsetOptions,
    medial_opts: &::medial::MedialOptions,
) -> Result<(::offset::Offsets, commands::CurveSummary), CommandError> {
    commands::validate_offset(asked, medial_opts.exterior)?;
    let region = c.region()?;
    Ok((
        commands::offset(region, asked, opts, medial_opts)?,
        commands::CurveSummary::of(region),
    ))
}

/// The V-carving of the region a curve is or encloses, and that region's summary.
pub(crate) fn vcarve_work(
    c: &PyCurve,
    opts: &::offset::VCarveOptions,
    medial_opts: &::medial::MedialOptions,
) -> Result<(::offset::VCarve, commands::CurveSummary), CommandError> {
    commands::validate_vcarve_options(opts)?;
    let region = c.region()?;
    Ok((
        commands::vcarve(region, opts, medial_opts)?,
        commands::CurveSummary::of(region),
    ))
}

/// The native module: classes, functions and exceptions (the package `curvekit` re-exports
/// them beside its curve constructors).
#[pymodule]
fn _curvekit(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("CurvekitError", py.get_type::<CurvekitError>())?;
    m.add_class::<PyCurve>()?;
    registry::register(m)?;
    curves::register(m)?;
    m.add_function(wrap_pyfunction!(antipodal_of, m)?)?;
    m.add_function(wrap_pyfunction!(inflections_of, m)?)?;
    m.add_function(wrap_pyfunction!(antipodal_many, m)?)?;
    m.add_function(wrap_pyfunction!(inflections_many, m)?)?;
    m.add_function(wrap_pyfunction!(tangents_of, m)?)?;
    m.add_function(wrap_pyfunction!(bisector_of, m)?)?;
    m.add_function(wrap_pyfunction!(medial_of, m)?)?;
    m.add_function(wrap_pyfunction!(offset_of, m)?)?;
    m.add_function(wrap_pyfunction!(vcarve_of, m)?)?;
    many::register(m)?;
    grasps::register(m)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
