//! Vectorised calls, in the manner of shapely 2: one command over a list of curves, computed in
//! parallel on rayon's pool with the GIL released, the answers in the list's order. Between
//! rounds of a few curves per thread the call looks for a signal, so Ctrl-C stops it there.

use crate::curves::{PyCurve, PyPrepared};
use crate::region_results::{PyMedialAxis, PyOffsets, PyVCarve};
use crate::results::{PyBisector, PyTangents};
use crate::{
    bisector_method, bisector_options, CurvekitError, Failure, InputError, OneCurveCommand,
};
use curvekit::commands::{self, CommandError, CurveSummary, FailureKind};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;

/// Curves per thread in one round: enough to keep every thread busy to the round's end (its
/// slowest curve), few enough that a signal is seen soon after it comes.
const ROUND_PER_THREAD: usize = 32;

/// The failure of curve `k` of the list, as [`crate::to_py_err`] raises it, the message
/// starting with the curve's place.
fn failed_at(k: usize, e: impl Failure) -> PyErr {
    let message = format!("[{k}] {}", e.message());
    match e.kind() {
        FailureKind::Input => InputError::new_err(message),
        FailureKind::Usage => PyValueError::new_err(message),
        FailureKind::Computation => CurvekitError::new_err(message),
    }
}

/// The options of a list's call, built once: refused, they are the failure of its first item
/// (as each item's would be); an empty list has no item to fail (`None`).
fn built<T>(items: usize, opts: Result<T, CommandError>) -> PyResult<Option<T>> {
    match opts {
        Ok(opts) => Ok(Some(opts)),
        Err(_) if items == 0 => Ok(None),
        Err(e) => Err(failed_at(0, e)),
    }
}

/// `work` on every item, in parallel without the GIL, in rounds with a look for signals after
/// each; the first failure (in the list's order) raised, naming its place.
pub(crate) fn each<I: Sync, T: Send, E: Failure>(
    py: Python<'_>,
    items: &[I],
    work: impl Fn(&I) -> Result<T, E> + Sync,
) -> PyResult<Vec<T>> {
    let round = ROUND_PER_THREAD * rayon::current_num_threads().max(1);
    let mut found = Vec::with_capacity(items.len());
    for (r, block) in items.chunks(round).enumerate() {
        let answers: Vec<Result<T, E>> = py.detach(|| {
            block
                .par_iter()
                .map(|item| {
                    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(item)))
                        .unwrap_or_else(|_| Err(E::panicked()))
                })
                .collect()
        });
        for (i, answer) in answers.into_iter().enumerate() {
            found.push(answer.map_err(|e| failed_at(r * round + i, e))?);
        }
        py.check_signals()?;
    }
    Ok(found)
}

/// A curve of a list as the one-curve commands take it: prepared (warm) or not.
pub(crate) enum Item<'a> {
    Prepared(&'a PyPrepared),
    Curve(&'a PyCurve),
}

/// The items of a list of curves and prepared curves.
pub(crate) fn items<'a>(curves: &'a [Bound<'_, PyAny>]) -> PyResult<Vec<Item<'a>>> {
    curves
        .iter()
        .enumerate()
        .map(|(k, c)| {
            if let Ok(p) = c.cast::<PyPrepared>() {
                Ok(Item::Prepared(p.get()))
            } else if let Ok(c) = c.cast::<PyCurve>() {
                Ok(Item::Curve(c.get()))
            } else {
                Err(pyo3::exceptions::PyTypeError::new_err(format!(
                    "[{k}]: expected a curvekit.Curve or PreparedCurve, got {}",
                    c.get_type().name()?
                )))
            }
        })
        .collect()
}

/// The curves of a list (no prepared ones: the region commands and the two-curve ones).
fn plain<'a>(curves: &'a [Bound<'_, PyCurve>]) -> Vec<&'a PyCurve> {
    curves.iter().map(|c| c.get()).collect()
}

impl Item<'_> {
    /// The curve read (a prepared curve's own).
    pub(crate) fn curve(&self) -> &curvekit::io::Curve {
        match self {
            Item::Prepared(p) => p.prepared().curve(),
            Item::Curve(c) => c.curve(),
        }
    }

    /// Runs `command` with `opts`: warm on a prepared curve, cold on a curve (prepared for
    /// this run); the result with the curve's summary.
    fn run<T>(
        &self,
        command: &OneCurveCommand<T>,
        opts: &::antipodal::Options,
    ) -> Result<(T, CurveSummary), CommandError> {
        Ok(match self {
            Item::Prepared(p) => (
                (command.warm)(p.prepared(), opts)?,
                CurveSummary::of(p.prepared().curve()),
            ),
            Item::Curve(c) => ((command.cold)(c.curve(), opts)?, c.summary()),
        })
    }
}

/// The answers of a list, each of one curve, as results of one class (its `new`).
fn classes<T, C>(found: Vec<(T, CurveSummary)>, class: fn(T, Vec<CurveSummary>) -> C) -> Vec<C> {
    found.into_iter().map(|(f, s)| class(f, vec![s])).collect()
}

/// A one-curve command on each of `curves` (curves and prepared curves), as results of
/// `class`.
pub(crate) fn one_curve_each<T: Send, C>(
    py: Python<'_>,
    curves: &[Bound<'_, PyAny>],
    tol: f64,
    command: &OneCurveCommand<T>,
    class: fn(T, Vec<CurveSummary>) -> C,
) -> PyResult<Vec<C>> {
    let items = items(curves)?;
    let Some(opts) = built(items.len(), crate::curve_options(tol))? else {
        return Ok(Vec::new());
    };
    let found = each(py, &items, |item| item.run(command, &opts))?;
    Ok(classes(found, class))
}

/// Two lists that pair up, refused where their lengths differ.
fn paired_lengths(command: &str, first: usize, second: usize) -> PyResult<()> {
    if first == second {
        return Ok(());
    }
    Err(PyValueError::new_err(format!(
        "{command}: {first} curves against {second}: the lists pair up, so their lengths must match"
    )))
}

/// `tangents` of each pair `(curves1[k], curves2[k])`.
#[pyfunction]
#[pyo3(signature = (curves1, curves2, *, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn tangents_many(
    py: Python<'_>,
    curves1: Vec<Bound<'_, PyCurve>>,
    curves2: Vec<Bound<'_, PyCurve>>,
    tol: f64,
) -> PyResult<Vec<PyTangents>> {
    paired_lengths("tangents", curves1.len(), curves2.len())?;
    let Some(opts) = built(curves1.len(), crate::curve_options(tol))? else {
        return Ok(Vec::new());
    };
    let pairs: Vec<(&PyCurve, &PyCurve)> =
        plain(&curves1).into_iter().zip(plain(&curves2)).collect();
    let found = each(py, &pairs, |(a, b)| {
        commands::tangents(a.curve(), b.curve(), &opts)
    })?;
    Ok(found
        .into_iter()
        .zip(&pairs)
        .map(|(f, (a, b))| PyTangents::new(f, vec![a.summary(), b.summary()]))
        .collect())
}

/// `bisector` of each curve with itself, or of each pair `(curves1[k], curves2[k])`.
#[pyfunction]
#[pyo3(signature = (curves1, curves2 = None, *, method = "f3", trimmed = false,
                    chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn bisector_many(
    py: Python<'_>,
    curves1: Vec<Bound<'_, PyCurve>>,
    curves2: Option<Vec<Bound<'_, PyCurve>>>,
    method: &str,
    trimmed: bool,
    chord_tol: f64,
    tol: f64,
) -> PyResult<Vec<PyBisector>> {
    let method = bisector_method(method)?;
    let first = plain(&curves1);
    let second: Vec<Option<&PyCurve>> = match &curves2 {
        Some(list) => {
            paired_lengths("bisector", first.len(), list.len())?;
            plain(list).into_iter().map(Some).collect()
        }
        None => vec![None; first.len()],
    };
    let pairs: Vec<(&PyCurve, Option<&PyCurve>)> = first.into_iter().zip(second).collect();
    let options = bisector_options(method, trimmed, chord_tol, tol);
    let Some(opts) = built(pairs.len(), options)? else {
        return Ok(Vec::new());
    };
    let found = each(py, &pairs, |(a, b)| {
        commands::bisector(a.curve(), b.map(PyCurve::curve), &opts)
    })?;
    Ok(found
        .into_iter()
        .zip(&pairs)
        .map(|(f, (a, b))| {
            let summaries = std::iter::once(*a)
                .chain(*b)
                .map(PyCurve::summary)
                .collect();
            PyBisector::new(f, summaries)
        })
        .collect())
}

/// `medial` of each region.
#[pyfunction]
#[pyo3(signature = (regions, *, chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL, fit = false,
                    exterior = false, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn medial_many(
    py: Python<'_>,
    regions: Vec<Bound<'_, PyCurve>>,
    chord_tol: f64,
    fit: bool,
    exterior: bool,
    tol: f64,
) -> PyResult<Vec<PyMedialAxis>> {
    let options = crate::medial_options(chord_tol, fit, exterior, tol);
    let Some(opts) = built(regions.len(), options)? else {
        return Ok(Vec::new());
    };
    let found = each(py, &plain(&regions), |c| crate::medial_work(c, &opts))?;
    Ok(classes(found, PyMedialAxis::new))
}

/// `offset` of each region.
#[pyfunction]
#[pyo3(signature = (regions, *, distance = None, distances = None, step = None,
                    outward = false, chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL,
                    tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
// (One argument per keyword of the Python function.)
#[allow(clippy::too_many_arguments)]
fn offset_many(
    py: Python<'_>,
    regions: Vec<Bound<'_, PyCurve>>,
    distance: Option<f64>,
    distances: Option<Vec<f64>>,
    step: Option<f64>,
    outward: bool,
    chord_tol: f64,
    tol: f64,
) -> PyResult<Vec<PyOffsets>> {
    let asked = crate::offset_distances(distance, distances, step)?;
    let options = crate::offset_options(&asked, outward, chord_tol, tol);
    let Some((opts, medial_opts)) = built(regions.len(), options)? else {
        return Ok(Vec::new());
    };
    let found = each(py, &plain(&regions), |c| {
        crate::offset_work(c, &asked, &opts, &medial_opts)
    })?;
    Ok(classes(found, PyOffsets::new))
}

/// `vcarve` of each region.
#[pyfunction]
#[pyo3(signature = (regions, *, angle, max_depth = None,
                    chord_tol = curvekit::numeric::tolerance::DEFAULT_CHORD_TOL, tol = curvekit::numeric::tolerance::DEFAULT_PARAM_TOL))]
fn vcarve_many(
    py: Python<'_>,
    regions: Vec<Bound<'_, PyCurve>>,
    angle: f64,
    max_depth: Option<f64>,
    chord_tol: f64,
    tol: f64,
) -> PyResult<Vec<PyVCarve>> {
    let options = crate::vcarve_options(angle, max_depth, chord_tol, tol);
    let Some((opts, medial_opts)) = built(regions.len(), options)? else {
        return Ok(Vec::new());
    };
    let found = each(py, &plain(&regions), |c| {
        crate::vcarve_work(c, &opts, &medial_opts)
    })?;
    Ok(classes(found, PyVCarve::new))
}

/// Registers the vectorised functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(tangents_many, m)?)?;
    m.add_function(wrap_pyfunction!(bisector_many, m)?)?;
    m.add_function(wrap_pyfunction!(medial_many, m)?)?;
    m.add_function(wrap_pyfunction!(offset_many, m)?)?;
    m.add_function(wrap_pyfunction!(vcarve_many, m)?)?;
    Ok(())
}
