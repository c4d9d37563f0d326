//! The result classes as the module registers them, and read back from their documents when
//! unpickled (each pickles as its document: see `result_class!`).

use crate::grasps::PyGrasps;
use crate::region_results::{PyMedialAxis, PyOffsets, PyVCarve};
use crate::results::{Kept, PickledCurve, PyAntipodal, PyBisector, PyInflections, PyTangents};
use curvekit::commands::CurveSummary;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// Unpickling: a result read back from its document.
#[pyfunction]
fn _result_from_json(
    py: Python<'_>,
    class: &str,
    variant: &str,
    found: &str,
    curves: &str,
) -> PyResult<Py<PyAny>> {
    let bad = |e: serde_json::Error| PyValueError::new_err(format!("{class}: {e}"));
    let kept: Vec<PickledCurve> = serde_json::from_str(curves).map_err(bad)?;
    let curves: Vec<CurveSummary> = kept.into_iter().map(PickledCurve::summary).collect();
    fn make<T: Kept>(variant: &str, found: &str) -> serde_json::Result<T> {
        T::from_document(variant, found)
    }
    // (Each class by its Python name: the arm that rebuilds it by its `new`.)
    macro_rules! rebuilt {
        ($($name:literal => $class:ident),* $(,)?) => {
            match class {
                $($name => $class::new(make(variant, found).map_err(bad)?, curves)
                    .into_pyobject(py)?
                    .into_any(),)*
                other => return Err(PyValueError::new_err(format!("no result class {other:?}"))),
            }
        };
    }
    let object = rebuilt! {
        "Antipodal" => PyAntipodal,
        "Inflections" => PyInflections,
        "Tangents" => PyTangents,
        "Bisector" => PyBisector,
        "MedialAxis" => PyMedialAxis,
        "Offsets" => PyOffsets,
        "VCarve" => PyVCarve,
        "Grasps" => PyGrasps,
    };
    Ok(object.unbind())
}

/// Registers the result classes and the unpickling function.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyAntipodal>()?;
    m.add_class::<PyInflections>()?;
    m.add_class::<PyTangents>()?;
    m.add_class::<PyBisector>()?;
    m.add_class::<PyMedialAxis>()?;
    m.add_class::<PyOffsets>()?;
    m.add_class::<PyVCarve>()?;
    m.add_function(wrap_pyfunction!(_result_from_json, m)?)?;
    Ok(())
}
