//! `grasps`: every two-finger force-closure grasp of a closed curve or profile with friction,
//! on the library `grasp` directly (the tool's commands layer has no such command to call),
//! its result's `to_dict()` the library's serde form with the `curve` summary beside, as the
//! tool's other `--json` documents are.

use crate::many::{each, items};
use crate::results::{points2, py_bool, result_class, Kept, PickledCurve};
use crate::{detached, Failure, OneCurve};
use curvekit::commands::{json_document_of, CommandError, CurveSummary, FailureKind, UsageError};
use curvekit::io::{self, CurveFileError, CurveKind, Problem};
use grasp::{BestGrasp, ContactRegion, GraspOptions, GraspRegion, Grasps};
use numpy::{PyArray1, PyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// Why `grasps` failed on one curve: as the tool's commands fail where the failure is one of
/// theirs (bad input, options out of range, the spline arithmetic, the antipodal pairs), else
/// the grasp computation's own (its zero sets), which no command error names.
pub(crate) enum GraspFailure {
    /// A failure the tool's commands have a kind and a message for.
    Command(CommandError),
    /// The grasp computation failed (its zero sets could not be traced).
    Computation(grasp::Error),
}

impl Failure for GraspFailure {
    fn kind(&self) -> FailureKind {
        match self {
            GraspFailure::Command(e) => e.kind(),
            GraspFailure::Computation(_) => FailureKind::Computation,
        }
    }

    fn message(&self) -> String {
        match self {
            GraspFailure::Command(e) => e.message(),
            GraspFailure::Computation(e) => format!("grasps: {e}").replace('\n', " "),
        }
    }

    fn panicked() -> Self {
        GraspFailure::Command(CommandError::panicked())
    }
}

impl GraspFailure {
    /// The library's error on curve `c`: an option out of range is a usage error naming it
    /// (as the tool spells it: `--min-width`), a curve the library cannot take an input error
    /// naming the file and the field (as the curve commands blame a curve), the rest the
    /// computation's.
    fn of(e: grasp::Error, c: &io::Curve) -> Self {
        use grasp::Error as E;
        let command = match e {
            E::Option {
                field,
                value,
                expected,
            } => UsageError::out_of_range(field.replace('_', "-"), value, expected).into(),
            E::NotExact | E::NotClosed | E::Curve(_) => CommandError::Input(CurveFileError {
                file: c.file.clone(),
                field: blamed_field(c).into(),
                problem: Problem::Geometry(e.to_string()),
            }),
            E::Spline(e) => CommandError::Spline(e),
            E::Antipodal(e) => CommandError::Antipodal(e),
            E::ZeroSet(_) => return GraspFailure::Computation(e),
        };
        GraspFailure::Command(command)
    }
}

/// The field of a curve's document a geometric refusal blames (as the curve commands do).
fn blamed_field(c: &io::Curve) -> &'static str {
    match c.shape {
        CurveKind::Spline(_) => "points",
        CurveKind::Analytic(_) | CurveKind::Segment(_) => "kind",
        CurveKind::Profile(_) => "segments",
        CurveKind::Region(_) | CurveKind::Regions(_) => "outer",
    }
}

/// A curve refused before any computation (a region), as the one-curve commands refuse it.
fn refused(c: &io::Curve, why: String) -> GraspFailure {
    GraspFailure::Command(CommandError::Input(CurveFileError {
        file: c.file.clone(),
        field: "kind".into(),
        problem: Problem::Unsupported(why),
    }))
}

/// The options of one call (checked by the library, before any work on each curve).
fn grasp_options(friction: f64, min_width: Option<f64>, max_width: Option<f64>) -> GraspOptions {
    GraspOptions {
        min_width,
        max_width,
        ..GraspOptions::friction(friction)
    }
}

/// The grasps of curve `c`, in its document's parameter; doubted where the drawing's outline
/// is (as every command's result is).
pub(crate) fn grasps_work(c: &io::Curve, opts: &GraspOptions) -> Result<Grasps, GraspFailure> {
    let found = match &c.shape {
        CurveKind::Region(_) => {
            return Err(refused(
                c,
                "grasps takes a curve or a profile, not a region".into(),
            ))
        }
        CurveKind::Regions(parts) => {
            return Err(refused(
                c,
                format!(
                    "grasps takes one curve, and the input holds {} parts: choose one with \
                     pick=N (0 to {})",
                    parts.len(),
                    parts.len().saturating_sub(1)
                ),
            ))
        }
        CurveKind::Profile(p) => grasp::grasps(p.as_ref(), opts),
        // (A line or an arc: its document's parameter is its profile's, not its exact form's.)
        CurveKind::Segment(_) => match io::curve_profile(c) {
            Some(Ok(p)) => grasp::grasps(&p, opts),
            Some(Err(e)) => return Err(GraspFailure::Command(CommandError::Input(e))),
            None => {
                return Err(GraspFailure::Command(CommandError::Internal(
                    "a line or an arc without a profile",
                )))
            }
        },
        CurveKind::Spline(_) | CurveKind::Analytic(_) => grasp::grasps(c.plane_curve(), opts),
    };
    let mut found = found.map_err(|e| GraspFailure::of(e, c))?;
    if let Some(doubt) = c.drawing_outline_doubt() {
        found.doubts.add(doubt);
    }
    Ok(found)
}

impl Kept for Grasps {
    fn variant(&self) -> &'static str {
        "curve"
    }
    fn from_document(_: &str, json: &str) -> serde_json::Result<Self> {
        serde_json::from_str(json)
    }
}

/// A pair of parameters as a length-2 array.
fn pair1<'py>(py: Python<'py>, pair: [f64; 2]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, pair.to_vec())
}

result_class!(PyGrasps, "Grasps", Grasps, {
    /// Whether every region's boundary follows from certified zero sets and every best grasp
    /// is proven; `reason` says why not.
    #[getter]
    fn certified(&self) -> bool {
        self.found.doubts.is_empty()
    }

    /// Why the result is not certified, when it is not.
    #[getter]
    fn reason(&self) -> Option<String> {
        self.found.doubts.reason()
    }

    /// False when a work limit was hit (regions may then be missing).
    #[getter]
    fn complete(&self) -> bool {
        self.found.complete
    }

    /// The friction coefficient μ.
    #[getter]
    fn friction(&self) -> f64 {
        self.found.friction
    }

    /// The gripper's least opening, if limited.
    #[getter]
    fn min_width(&self) -> Option<f64> {
        self.found.min_width
    }

    /// The gripper's greatest opening, if limited.
    #[getter]
    fn max_width(&self) -> Option<f64> {
        self.found.max_width
    }

    /// The regions of force-closure pairs `(s, t)`, `s < t`, in the curve's parameter.
    #[getter]
    fn regions(&self) -> Vec<PyGraspRegion> {
        self.found
            .regions
            .iter()
            .map(|r| PyGraspRegion { region: r.clone() })
            .collect()
    }

    fn __len__(&self) -> usize {
        self.found.regions.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "Grasps({} regions, friction={}, certified={})",
            self.found.regions.len(),
            self.found.friction,
            py_bool(self.certified())
        )
    }
});

/// One connected region of force-closure pairs `(s, t)` of a `Grasps` result.
#[pyclass(name = "GraspRegion", module = "curvekit", frozen)]
pub(crate) struct PyGraspRegion {
    region: GraspRegion,
}

#[pymethods]
impl PyGraspRegion {
    /// Its boundary, an `(n, 2)` array of pairs `(s, t)`: a closed polyline, the region on its
    /// left (the largest part of a region across the seam; there and back along a stretch for
    /// a region of pairs with a finger at a corner, which has no area).
    #[getter]
    fn boundary<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        points2(py, &self.region.boundary)
    }

    /// All its parts in the square, `boundary` first (a region across the curve's seam has
    /// several; any other has just `boundary`), each an `(n, 2)` array.
    #[getter]
    fn parts<'py>(&self, py: Python<'py>) -> Vec<Bound<'py, PyArray2<f64>>> {
        if self.region.parts.is_empty() {
            return vec![points2(py, &self.region.boundary)];
        }
        self.region.parts.iter().map(|p| points2(py, p)).collect()
    }

    /// Its holes, each a closed `(n, 2)` polyline (clockwise).
    #[getter]
    fn holes<'py>(&self, py: Python<'py>) -> Vec<Bound<'py, PyArray2<f64>>> {
        self.region.holes.iter().map(|h| points2(py, h)).collect()
    }

    /// Its independent contact region (any `s` of one stretch with any `t` of the other is
    /// force closure), or `None` where none was proven.
    #[getter]
    fn contact(&self) -> Option<PyContactRegion> {
        self.region
            .contact
            .map(|contact| PyContactRegion { contact })
    }

    /// Its most robust grasp.
    #[getter]
    fn best(&self) -> PyBestGrasp {
        PyBestGrasp {
            best: self.region.best.clone(),
        }
    }

    /// Whether its boundary is proven (every piece from certified zero sets, every end
    /// joined).
    #[getter]
    fn certified(&self) -> bool {
        self.region.certified
    }

    fn __repr__(&self) -> String {
        format!(
            "GraspRegion({} points, best=({}, {}), certified={})",
            self.region.boundary.len(),
            self.region.best.s,
            self.region.best.t,
            py_bool(self.region.certified)
        )
    }
}

/// An independent contact region: every pair of `[s0, s1] × [t0, t1]` is force closure. An
/// interval may run across the curve's seam: its ends then lie beyond the domain, to be read
/// modulo the period.
#[pyclass(name = "ContactRegion", module = "curvekit", frozen)]
pub(crate) struct PyContactRegion {
    contact: ContactRegion,
}

#[pymethods]
impl PyContactRegion {
    /// The first finger's stretch `[s0, s1]`, a length-2 array.
    #[getter]
    fn s<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        pair1(py, self.contact.s)
    }

    /// The second finger's stretch `[t0, t1]`, a length-2 array.
    #[getter]
    fn t<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        pair1(py, self.contact.t)
    }

    /// The ends of the first stretch, `C(s0)` and `C(s1)`, a `(2, 2)` array.
    #[getter]
    fn p<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        points2(py, &self.contact.p)
    }

    /// The ends of the second stretch, a `(2, 2)` array.
    #[getter]
    fn q<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        points2(py, &self.contact.q)
    }

    fn __repr__(&self) -> String {
        let [s0, s1] = self.contact.s;
        let [t0, t1] = self.contact.t;
        format!("ContactRegion(s=[{s0}, {s1}], t=[{t0}, {t1}])")
    }
}

/// A region's most robust grasp: the pair farthest (in angle) from the edges of both friction
/// cones.
#[pyclass(name = "BestGrasp", module = "curvekit", frozen)]
pub(crate) struct PyBestGrasp {
    best: BestGrasp,
}

#[pymethods]
impl PyBestGrasp {
    /// The first contact's parameter.
    #[getter]
    fn s(&self) -> f64 {
        self.best.s
    }

    /// The second contact's parameter.
    #[getter]
    fn t(&self) -> f64 {
        self.best.t
    }

    /// The first contact, a length-2 array.
    #[getter]
    fn p<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        pair1(py, self.best.p)
    }

    /// The second contact, a length-2 array.
    #[getter]
    fn q<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        pair1(py, self.best.q)
    }

    /// The least friction coefficient for which this pair is force closure (0 at an antipodal
    /// pair).
    #[getter]
    fn min_friction(&self) -> f64 {
        self.best.min_friction
    }

    /// Stretches `[u0, u1]` of the curve's parameter round corners the region does not reach
    /// (a reflex corner) toward which its least friction falls without being attained: pairs
    /// with a finger in one may need less friction than this one, no other pair of the region
    /// does. A `(k, 2)` array, empty where the least friction is attained.
    #[getter]
    fn toward<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        points2(py, &self.best.toward)
    }

    fn __repr__(&self) -> String {
        format!(
            "BestGrasp(s={}, t={}, min_friction={})",
            self.best.s, self.best.t, self.best.min_friction
        )
    }
}

/// Every two-finger force-closure grasp of a closed curve or profile for Coulomb friction
/// `friction` (μ > 0), pairs closer than `min_width` or farther apart than `max_width` left
/// out: regions of the square of contact parameters, each with its independent contact
/// region and its most robust grasp.
#[pyfunction(name = "grasps")]
#[pyo3(signature = (curve, friction, *, min_width = None, max_width = None))]
fn grasps_of(
    py: Python<'_>,
    curve: OneCurve<'_>,
    friction: f64,
    min_width: Option<f64>,
    max_width: Option<f64>,
) -> PyResult<PyGrasps> {
    let opts = grasp_options(friction, min_width, max_width);
    let c: &io::Curve = match &curve {
        OneCurve::Prepared(p) => p.get().prepared().curve(),
        OneCurve::Curve(c) => c.get().curve(),
    };
    let found = detached(py, || grasps_work(c, &opts))?;
    Ok(PyGrasps::new(found, vec![CurveSummary::of(c)]))
}

/// `grasps` of each curve, in parallel without the GIL, in the list's order.
#[pyfunction]
#[pyo3(signature = (curves, friction, *, min_width = None, max_width = None))]
fn grasps_many(
    py: Python<'_>,
    curves: Vec<Bound<'_, PyAny>>,
    friction: f64,
    min_width: Option<f64>,
    max_width: Option<f64>,
) -> PyResult<Vec<PyGrasps>> {
    let items = items(&curves)?;
    let opts = grasp_options(friction, min_width, max_width);
    let found = each(py, &items, |item| grasps_work(item.curve(), &opts))?;
    Ok(found
        .into_iter()
        .zip(&items)
        .map(|(f, item)| PyGrasps::new(f, vec![CurveSummary::of(item.curve())]))
        .collect())
}

/// Registers `grasps`, its list form and its classes.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyGrasps>()?;
    m.add_class::<PyGraspRegion>()?;
    m.add_class::<PyContactRegion>()?;
    m.add_class::<PyBestGrasp>()?;
    m.add_function(wrap_pyfunction!(grasps_of, m)?)?;
    m.add_function(wrap_pyfunction!(grasps_many, m)?)?;
    Ok(())
}
