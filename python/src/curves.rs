//! `curvekit.Curve`: a curve (or profile, or region) read from a JSON document, a file or a
//! drawing, kept with its source so that it pickles as that source and is read again.

use crate::detached;
use curvekit::commands::{CommandError, CurveSummary, PreparedCurve};
use curvekit::io::{self, Curve, CurveKind, DrawingFormat};
use numpy::{PyArray2, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::path::Path;
use std::sync::{Arc, OnceLock};

/// How far (a share of the size) the GeoJSON of a curve may stray from it: the default chord
/// tolerance of every result's polylines.
const GEO_TOLERANCE: f64 = 1e-3;

/// How far the GeoJSON of `regions` may stray from them: [`GEO_TOLERANCE`] of their size.
pub(crate) fn geo_flatness(regions: &[&curve::Region]) -> f64 {
    let size = curve::box_size(
        regions
            .iter()
            .map(|r| r.bounding_box())
            .reduce(curve::box_union)
            .unwrap_or([0.0; 4]),
    );
    GEO_TOLERANCE * size
}

/// Where a curve came from: what it is read again from when unpickled.
#[derive(Clone)]
struct Source {
    /// The name in messages and reports (a file's path, or the name given).
    name: String,
    /// The document or drawing.
    bytes: Vec<u8>,
    /// A drawing's format; `None`: a JSON curve document.
    format: Option<DrawingFormat>,
    /// Which of a drawing's profiles or regions.
    pick: Option<usize>,
}

impl Source {
    fn format_name(&self) -> Option<&'static str> {
        self.format.map(|f| match f {
            DrawingFormat::Svg => "svg",
            DrawingFormat::Dxf => "dxf",
        })
    }

    fn with_format_name(mut self, name: Option<&str>) -> PyResult<Self> {
        self.format = match name {
            None => None,
            Some("svg") => Some(DrawingFormat::Svg),
            Some("dxf") => Some(DrawingFormat::Dxf),
            Some(other) => {
                return Err(PyValueError::new_err(format!(
                    "format: {other:?} is not one of \"svg\", \"dxf\""
                )))
            }
        };
        Ok(self)
    }

    /// The curve it holds, as the tool reads it.
    fn read(&self) -> Result<Curve, CommandError> {
        Ok(match self.format {
            Some(format) => io::parse_drawing(&self.name, format, &self.bytes, self.pick)?,
            None => io::parse_curve(&self.name, &self.text()?)?,
        })
    }

    /// The region it holds or encloses, as `medial` reads it.
    fn read_region(&self) -> Result<Curve, io::CurveFileError> {
        io::parse_region(&self.name, self.format, &self.bytes, self.pick)
    }

    fn text(&self) -> Result<String, CommandError> {
        String::from_utf8(self.bytes.clone()).map_err(|e| {
            CommandError::Input(io::CurveFileError {
                file: self.name.clone(),
                field: "document".into(),
                problem: io::Problem::Syntax(format!("not UTF-8: {e}")),
            })
        })
    }
}

/// A curve, profile or region, as the tool reads it: from a JSON document (`Curve.from_json`,
/// `curvekit.from_dict`, the constructors `BSpline`, `Bezier`, `Circle`, …) or a file
/// (`curvekit.read`: `.json`, `.svg`, `.dxf`). Immutable; pickles as its source. Each run on
/// it prepares it afresh and lets the preparation go; `curvekit.prepare` keeps one for runs
/// that answer warm.
#[pyclass(name = "Curve", module = "curvekit", frozen)]
pub(crate) struct PyCurve {
    curve: Arc<Curve>,
    source: Source,
    region: OnceLock<Result<Curve, io::CurveFileError>>,
}

impl PyCurve {
    /// The curve of `source`; a drawing that holds no one curve but a region (nested closed
    /// profiles: a pocket and its islands) is that region, as `medial` reads it.
    fn from_source(source: Source) -> Result<Self, CommandError> {
        let curve = match source.read() {
            Ok(curve) => curve,
            Err(e) if source.format.is_some() => source.read_region().map_err(|_| e)?,
            Err(e) => return Err(e),
        };
        Ok(Self {
            curve: Arc::new(curve),
            source,
            region: OnceLock::new(),
        })
    }

    /// The curve read.
    pub(crate) fn curve(&self) -> &Curve {
        &self.curve
    }

    /// The `curve` object of the JSON reports.
    pub(crate) fn summary(&self) -> CurveSummary {
        CurveSummary::of(&self.curve)
    }

    /// A curve from a JSON document made here (a part, a boundary, an offset's region), named
    /// `name` in messages.
    pub(crate) fn from_document(name: String, text: String) -> Result<Self, CommandError> {
        Self::from_source(Source {
            name,
            bytes: text.into_bytes(),
            format: None,
            pick: None,
        })
    }

    /// The curve's document: a curve file's own text, or what a drawing was read as.
    fn document(&self) -> Result<String, CommandError> {
        if self.source.format.is_none() {
            return self.source.text();
        }
        io::shape_document(&self.curve.shape)
            .map(|d| d.to_string())
            .ok_or(CommandError::Internal(
                "a drawing read as no profile or region",
            ))
    }

    /// The regions the curve is or encloses (a closed curve's, one).
    fn parts_read(&self) -> Result<Vec<&curve::Region>, CommandError> {
        Ok(self.region()?.parts())
    }

    /// The one part of the region the curve is, for the getter `getter`; refused where there
    /// are several, each with its own `each` (`outer boundary`, `holes`).
    fn only_part(&self, getter: &str, each: &str) -> PyResult<&curve::Region> {
        let parts = self.parts_read().map_err(crate::to_py_err)?;
        match parts.as_slice() {
            [one] => Ok(*one),
            _ => Err(PyValueError::new_err(format!(
                "{getter}: {} has {} parts, each with its {each}: take .parts",
                self.curve.file,
                parts.len()
            ))),
        }
    }

    /// The curve made of `doc`, named after this one with `what`.
    fn made(&self, what: &str, doc: &serde_json::Value) -> PyResult<PyCurve> {
        Self::from_document(format!("{} {what}", self.curve.file), doc.to_string())
            .map_err(crate::to_py_err)
    }

    /// The curve shared (for a prepared curve to keep).
    pub(crate) fn shared(&self) -> Arc<Curve> {
        self.curve.clone()
    }

    /// The region the curve is, or encloses (a closed curve or profile: read once as one).
    pub(crate) fn region(&self) -> Result<&Curve, CommandError> {
        if let CurveKind::Region(_) = self.curve.shape {
            return Ok(&self.curve);
        }
        self.region
            .get_or_init(|| self.source.read_region())
            .as_ref()
            .map_err(|e| CommandError::Input(e.clone()))
    }
}

#[pymethods]
impl PyCurve {
    /// A curve from one JSON curve document (the tool's format); `name` stands for the file
    /// name in messages and reports.
    #[staticmethod]
    #[pyo3(signature = (text, name = "curve"))]
    fn from_json(py: Python<'_>, text: &str, name: &str) -> PyResult<Self> {
        let source = Source {
            name: name.into(),
            bytes: text.as_bytes().to_vec(),
            format: None,
            pick: None,
        };
        detached(py, || Self::from_source(source))
    }

    /// `kind` of the document: `bspline`, `circle`, `profile`, `region`, ….
    #[getter]
    fn kind(&self) -> &'static str {
        self.curve.kind()
    }

    /// The file's path, or the name given.
    #[getter]
    fn name(&self) -> &str {
        &self.curve.file
    }

    /// Whether the curve is closed.
    #[getter]
    fn closed(&self) -> bool {
        self.curve.is_closed()
    }

    /// The parameter domain `(a, b)`.
    #[getter]
    fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    /// Points at the parameters `u` (an array of `n` values in the domain), as an `(n, 2)`
    /// array; a region has no single parameter and is refused.
    fn evaluate<'py>(
        &self,
        py: Python<'py>,
        u: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        if let CurveKind::Region(_) = self.curve.shape {
            return Err(PyValueError::new_err(
                "evaluate: a region has no single parameter; evaluate its boundaries",
            ));
        }
        let (a, b) = self.curve.domain();
        let mut points = Vec::with_capacity(u.len()?);
        for (k, &t) in u.as_array().iter().enumerate() {
            if !(a..=b).contains(&t) {
                return Err(PyValueError::new_err(format!(
                    "evaluate: u[{k}] = {t} is outside the domain [{a}, {b}]"
                )));
            }
            // (In the document's parameter, as every result reports them.)
            points.push(self.curve.point_at(t).to_vec());
        }
        if points.is_empty() {
            return Ok(PyArray2::zeros(py, [0, 2], false));
        }
        Ok(PyArray2::from_vec2(py, &points)?)
    }

    /// The curve's JSON document, as one text: a curve file's own, or what a drawing was read
    /// as (its profiles and regions as the contract writes them).
    fn to_json(&self) -> PyResult<String> {
        self.document().map_err(crate::to_py_err)
    }

    /// The curve's JSON document, as a dict.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("json")?.call_method1("loads", (self.to_json()?,))
    }

    /// The outer boundary of the region the curve is (or encloses), as a closed profile; a
    /// multi-part input has several: see `parts`.
    #[getter]
    fn outer(&self) -> PyResult<PyCurve> {
        let one = self.only_part("outer", "outer boundary")?;
        self.made("outer", &io::profile_document(one.outer()))
    }

    /// The holes of the region the curve is, as closed profiles (none for a closed curve).
    #[getter]
    fn holes(&self) -> PyResult<Vec<PyCurve>> {
        let one = self.only_part("holes", "holes")?;
        one.holes()
            .iter()
            .enumerate()
            .map(|(k, h)| self.made(&format!("hole {k}"), &io::profile_document(h)))
            .collect()
    }

    /// The disjoint regions of the curve, each a region (one for a region or a closed curve).
    #[getter]
    fn parts(&self) -> PyResult<Vec<PyCurve>> {
        let parts = self.parts_read().map_err(crate::to_py_err)?;
        parts
            .iter()
            .enumerate()
            .map(|(k, r)| self.made(&format!("part {k}"), &io::region_document(r)))
            .collect()
    }

    /// GeoJSON geometry (as shapely's `shape()` takes it): a region or closed curve as a
    /// `Polygon` (`MultiPolygon` for several parts), an open curve as a `LineString`, its
    /// curves flattened within 1e-3 of its size (every vertex on the curve).
    #[getter]
    fn __geo_interface__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let geometry = if self.curve.is_closed() {
            let parts = self.parts_read().map_err(crate::to_py_err)?;
            io::regions_geometry(&parts, geo_flatness(&parts))
        } else {
            let profile = match &self.curve.shape {
                CurveKind::Profile(p) => (**p).clone(),
                _ => io::curve_profile(&self.curve)
                    .ok_or_else(|| PyValueError::new_err("no profile to draw"))?
                    .map_err(|e| crate::to_py_err(e.into()))?,
            };
            io::line_geometry(&profile, GEO_TOLERANCE * profile.scale())
        };
        py.import("json")?
            .call_method1("loads", (geometry.to_string(),))
    }

    fn __repr__(&self) -> String {
        let (a, b) = self.curve.domain();
        format!(
            "Curve(kind={:?}, name={:?}, closed={}, domain=({a}, {b}))",
            self.curve.kind(),
            self.curve.file,
            crate::results::py_bool(self.curve.is_closed())
        )
    }

    /// Pickles as the source it was read from.
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let rebuild = py
            .import("curvekit._curvekit")?
            .getattr("_curve_from_source")?;
        let s = &self.source;
        let args = (
            s.name.clone(),
            pyo3::types::PyBytes::new(py, &s.bytes),
            s.format_name(),
            s.pick,
        )
            .into_pyobject(py)?;
        Ok((rebuild, args))
    }
}

/// A curve prepared once for many antipodal and inflection runs (its frame, exact forms and
/// enclosures), as a compiled regular expression is for many matches: runs on it answer warm.
/// It holds much more memory than its curve (about a megabyte for a cubic of a dozen points):
/// keep the ones asked again. Pickles as its curve, prepared again where it lands.
#[pyclass(name = "PreparedCurve", module = "curvekit", frozen)]
pub(crate) struct PyPrepared {
    curve: Py<PyCurve>,
    prepared: PreparedCurve,
}

impl PyPrepared {
    /// The preparation.
    pub(crate) fn prepared(&self) -> &PreparedCurve {
        &self.prepared
    }
}

#[pymethods]
impl PyPrepared {
    /// The curve prepared.
    #[getter]
    fn curve(&self, py: Python<'_>) -> Py<PyCurve> {
        self.curve.clone_ref(py)
    }

    fn __repr__(&self) -> String {
        format!("PreparedCurve({})", self.curve.get().__repr__())
    }

    /// Pickles as its curve, prepared again when unpickled.
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let prepare = py.import("curvekit._curvekit")?.getattr("prepare")?;
        let args = (self.curve.clone_ref(py),).into_pyobject(py)?;
        Ok((prepare, args))
    }
}

/// Prepares a curve (or profile) for many runs of `antipodal` and `inflections`; a region is
/// refused.
#[pyfunction]
fn prepare(py: Python<'_>, curve: Bound<'_, PyCurve>) -> PyResult<PyPrepared> {
    let shared = curve.get().shared();
    let prepared = detached(py, || PreparedCurve::new(shared, "antipodal"))?;
    Ok(PyPrepared {
        curve: curve.unbind(),
        prepared,
    })
}

/// Reads a curve, profile or region file (`.json`), or a drawing (`.svg`, `.dxf`; `pick`
/// chooses among its profiles), as the tool does.
#[pyfunction]
#[pyo3(signature = (path, *, pick = None))]
fn read(py: Python<'_>, path: std::path::PathBuf, pick: Option<usize>) -> PyResult<PyCurve> {
    detached(py, || {
        let name = path.display().to_string();
        let bytes = std::fs::read(&path).map_err(|e| {
            CommandError::Input(io::CurveFileError {
                file: name.clone(),
                field: "document".into(),
                problem: io::Problem::Unreadable(e.to_string()),
            })
        })?;
        PyCurve::from_source(Source {
            name,
            bytes,
            format: drawing_format(&path),
            pick,
        })
    })
}

/// A drawing's format by its extension, as the tool tells them.
fn drawing_format(path: &Path) -> Option<DrawingFormat> {
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    match ext.as_str() {
        "svg" => Some(DrawingFormat::Svg),
        "dxf" => Some(DrawingFormat::Dxf),
        _ => None,
    }
}

/// Unpickling: the curve read again from its source.
#[pyfunction]
fn _curve_from_source(
    py: Python<'_>,
    name: String,
    bytes: Vec<u8>,
    format: Option<&str>,
    pick: Option<usize>,
) -> PyResult<PyCurve> {
    let source = Source {
        name,
        bytes,
        format: None,
        pick,
    }
    .with_format_name(format)?;
    detached(py, || PyCurve::from_source(source))
}

/// Registers `read` and the unpickling function.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyPrepared>()?;
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(prepare, m)?)?;
    m.add_function(wrap_pyfunction!(_curve_from_source, m)?)?;
    Ok(())
}
