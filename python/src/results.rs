//! The results: each keeps the library's result as computed (nothing is converted until asked
//! for), gives numpy arrays of its main fields, `to_dict()`/`to_json()` as the tool's `--json`
//! document, and pickles as that document.

use curvekit::commands::{
    json_document_of, AntipodalFound, BisectorFound, CurveSummary, InflectionsFound, TangentsFound,
};
use curvekit::numeric::certificate::Verdict;
use medial::MedialAxis;
use numpy::{PyArray1, PyArray2, PyArray3, PyArrayMethods};
use offset::{Offsets, VCarve};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use serde::de::DeserializeOwned;
use serde::Serialize;

/// A result kept as the library gave it, with the variant it is (a curve's or a profile's), so
/// that its document can be read back into the same type.
pub(crate) trait Kept: Serialize + Sized {
    /// Which variant, for reading the document back.
    fn variant(&self) -> &'static str;
    /// The result of `variant` from its document.
    fn from_document(variant: &str, json: &str) -> serde_json::Result<Self>;
}

/// Reads `json` as `T` (a result type), for [`Kept::from_document`].
fn read<T: DeserializeOwned>(json: &str) -> serde_json::Result<T> {
    serde_json::from_str(json)
}

macro_rules! kept_two_ways {
    ($found:ident) => {
        impl Kept for $found {
            fn variant(&self) -> &'static str {
                match self {
                    $found::Curve(_) => "curve",
                    $found::Profile(_) => "profile",
                }
            }
            fn from_document(variant: &str, json: &str) -> serde_json::Result<Self> {
                Ok(match variant {
                    "profile" => $found::Profile(read(json)?),
                    _ => $found::Curve(read(json)?),
                })
            }
        }
    };
}

kept_two_ways!(AntipodalFound);
kept_two_ways!(InflectionsFound);
kept_two_ways!(TangentsFound);
kept_two_ways!(BisectorFound);

/// The results on regions, each of one type.
macro_rules! kept_one_way {
    ($found:ty) => {
        impl Kept for $found {
            fn variant(&self) -> &'static str {
                "region"
            }
            fn from_document(_: &str, json: &str) -> serde_json::Result<Self> {
                read(json)
            }
        }
    };
}

kept_one_way!(Offsets);
kept_one_way!(MedialAxis);
kept_one_way!(VCarve);

/// The `(n, 2)` array of points.
pub(crate) fn points2<'py>(py: Python<'py>, points: &[[f64; 2]]) -> Bound<'py, PyArray2<f64>> {
    let flat: Vec<f64> = points.iter().flatten().copied().collect();
    let n = points.len();
    PyArray1::from_vec(py, flat)
        .reshape([n, 2])
        .unwrap_or_else(|_| PyArray2::zeros(py, [0, 2], false))
}

/// The `(n, 2, 2)` array of point pairs.
fn pairs2<'py>(py: Python<'py>, pairs: &[[[f64; 2]; 2]]) -> Bound<'py, PyArray3<f64>> {
    let flat: Vec<f64> = pairs.iter().flatten().flatten().copied().collect();
    let n = pairs.len();
    PyArray1::from_vec(py, flat)
        .reshape([n, 2, 2])
        .unwrap_or_else(|_| PyArray3::zeros(py, [0, 2, 2], false))
}

/// `True` or `False`, as Python spells a truth value in a repr.
pub(crate) fn py_bool(b: bool) -> &'static str {
    if b {
        "True"
    } else {
        "False"
    }
}

/// A result's repr: its class, what it counts, and whether it is certified
/// (`Tangents(2 lines, certified=True)`).
pub(crate) fn verdict_repr(class: &str, counts: &str, found: &impl Verdict) -> String {
    format!(
        "{class}({counts}, certified={})",
        py_bool(found.certified())
    )
}

/// `$body` on whichever result a two-way result `$found` (of enum `$two_ways`) holds, a
/// curve's or a profile's: for the fields the two share, which the getters read alike.
macro_rules! either {
    ($found:expr, $two_ways:ident, $f:ident => $body:expr) => {
        match $found {
            $two_ways::Curve($f) => $body,
            $two_ways::Profile($f) => $body,
        }
    };
}

/// The common methods of a result class: its document, pickling, and the shared fields.
/// A result's curve as it pickles: its summary with what its drawing said (which the
/// summary's JSON leaves to the result's own fields).
#[derive(serde::Serialize, serde::Deserialize)]
pub(crate) struct PickledCurve {
    summary: CurveSummary,
    drawing: Option<curvekit::commands::DrawingSummary>,
}

impl PickledCurve {
    pub(crate) fn of(c: &CurveSummary) -> Self {
        Self {
            summary: c.clone(),
            drawing: c.drawing.clone(),
        }
    }

    pub(crate) fn summary(self) -> CurveSummary {
        CurveSummary {
            drawing: self.drawing,
            ..self.summary
        }
    }
}

/// Whether a result is complete (no search limit hit, every loop joined): the results whose
/// class has a `complete` getter.
pub(crate) trait Completeness {
    fn complete(&self) -> bool;
}

impl Completeness for AntipodalFound {
    fn complete(&self) -> bool {
        self.result().complete
    }
}

macro_rules! complete_field {
    ($($t:ty),*) => {
        $(impl Completeness for $t {
            fn complete(&self) -> bool {
                self.complete
            }
        })*
    };
}
complete_field!(MedialAxis, Offsets, VCarve);

macro_rules! result_class {
    // (A result whose `len` is the length of its `$list()`, which its repr counts as `$noun`:
    // `Tangents(2 lines, certified=True)`.)
    ($class:ident, $name:literal, $found:ty, $verdict:ident = $doc:literal, counting $noun:literal in $list:ident, { $($extra:tt)* }) => {
        result_class!($class, $name, $found, $verdict = $doc, {
            fn __len__(&self) -> usize {
                self.$list().len()
            }

            fn __repr__(&self) -> String {
                let counts = format!(concat!("{} ", $noun), self.$list().len());
                verdict_repr($name, &counts, &self.found)
            }

            $($extra)*
        });
    };
    // (A result with `certified`, `complete` and `reason`, documented as every region's is.)
    ($class:ident, $name:literal, $found:ty, verdict, { $($extra:tt)* }) => {
        result_class!($class, $name, $found, verdict = "Whether the result is certified (what that proves is the command's: see its documentation); `reason` says why not.", {
            $($extra)*
        });
    };
    // (A result with `certified`, `complete` and `reason`: their getters, the verdict's from
    // the one `Verdict` trait every result answers it by.)
    ($class:ident, $name:literal, $found:ty, verdict = $doc:literal, { $($extra:tt)* }) => {
        result_class!($class, $name, $found, certified = $doc, {
            /// Whether the result is complete (no search limit hit, every loop joined).
            #[getter]
            fn complete(&self) -> bool {
                $crate::results::Completeness::complete(&self.found)
            }

            /// Why the result is not certified, when it is not.
            #[getter]
            fn reason(&self) -> Option<String> {
                curvekit::numeric::certificate::Verdict::reason(&self.found)
            }

            $($extra)*
        });
    };
    // (A result with `certified` alone, from `Verdict`, documented as `doc`.)
    ($class:ident, $name:literal, $found:ty, certified = $doc:literal, { $($extra:tt)* }) => {
        result_class!($class, $name, $found, {
            #[doc = $doc]
            #[getter]
            fn certified(&self) -> bool {
                curvekit::numeric::certificate::Verdict::certified(&self.found)
            }

            $($extra)*
        });
    };
    ($class:ident, $name:literal, $found:ty, { $($extra:tt)* }) => {
        #[doc = concat!("The result of `curvekit.", $name, "`.")]
        #[pyclass(name = $name, module = "curvekit", frozen)]
        pub(crate) struct $class {
            found: $found,
            curves: Vec<CurveSummary>,
        }

        impl $class {
            pub(crate) fn new(found: $found, curves: Vec<CurveSummary>) -> Self {
                Self { found, curves }
            }
        }

        #[pymethods]
        impl $class {
            /// The tool's `--json` document, as one JSON text.
            fn to_json(&self) -> String {
                json_document_of(&self.found, &self.curves, None).trim_end().to_string()
            }

            /// The tool's `--json` document, as a dict.
            fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                py.import("json")?.call_method1("loads", (self.to_json(),))
            }

            /// Pickles as its document.
            fn __reduce__<'py>(
                &self,
                py: Python<'py>,
            ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
                let rebuild = py.import("curvekit._curvekit")?.getattr("_result_from_json")?;
                let found = serde_json::to_string(&self.found)
                    .map_err(|e| PyValueError::new_err(e.to_string()))?;
                let kept: Vec<PickledCurve> = self.curves.iter().map(PickledCurve::of).collect();
                let curves = serde_json::to_string(&kept)
                    .map_err(|e| PyValueError::new_err(e.to_string()))?;
                let args = ($name, self.found.variant(), found, curves).into_pyobject(py)?;
                Ok((rebuild, args))
            }

            /// What the drawing the input came from held and was not read, by type: a list of
            /// `{"type", "count"}` (empty for a drawing read whole; `None` for a curve file).
            #[getter]
            fn skipped<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
                let drawing = self.curves.iter().find_map(|c| c.drawing.as_ref());
                drawing
                    .map(|d| {
                        let entries: Vec<serde_json::Value> =
                            d.skipped.iter().map(|s| s.entry()).collect();
                        let text = serde_json::to_string(&entries)
                            .map_err(|e| PyValueError::new_err(e.to_string()))?;
                        py.import("json")?.call_method1("loads", (text,))
                    })
                    .transpose()
            }

            /// The unit of the input drawing's coordinates, where it says (`"mm"`, `"in"`, …).
            #[getter]
            fn units(&self) -> Option<String> {
                self.curves
                    .iter()
                    .find_map(|c| c.drawing.as_ref().and_then(|d| d.units.clone()))
            }

            /// Equal where the documents are (a result read back from its document, unpickled,
            /// keeps each doubt as the reason it states, not its kind).
            fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
                let document = |found: &$found| serde_json::to_value(found).ok();
                other.cast::<$class>().is_ok_and(|o| {
                    o.get().curves == self.curves
                        && document(&o.get().found) == document(&self.found)
                })
            }

            $($extra)*
        }
    };
}

pub(crate) use result_class;

result_class!(
    PyAntipodal,
    "Antipodal",
    AntipodalFound,
    verdict = "Every pair proven (sign tests on exact forms) to be antipodal, and nothing missed.",
    counting "pairs" in pair_fields,
    {
        /// The pairs' parameters `(s, t)`, an `(n, 2)` array sorted by `s`.
        #[getter]
        fn pairs<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
            points2(
                py,
                &self.pair_fields().iter().map(|p| p.0).collect::<Vec<_>>(),
            )
        }

        /// The pairs' points `(p, q)`, an `(n, 2, 2)` array.
        #[getter]
        fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray3<f64>> {
            pairs2(
                py,
                &self.pair_fields().iter().map(|p| p.1).collect::<Vec<_>>(),
            )
        }

        /// The pairs' distances `|q − p|`, an `(n,)` array.
        #[getter]
        fn distances<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
            PyArray1::from_vec(py, self.pair_fields().iter().map(|p| p.2).collect())
        }

        /// The pairs' types (`"A"` to `"E"`, Jia 2004 §3.3; `None` at a corner or a straight end).
        #[getter]
        fn types(&self) -> Vec<Option<String>> {
            let pairs = &self.found.result().pairs;
            pairs.iter().map(|p| p.kind.map(|k| format!("{k:?}"))).collect()
        }

        /// The inflections' parameters, an `(m,)` array.
        #[getter]
        fn inflections<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
            let list = &self.found.result().inflections;
            PyArray1::from_vec(py, list.iter().map(|i| i.u).collect())
        }

        /// The families (arcs of non-isolated pairs): `[[s0, s1], [t0, t1]]` each, a `(k, 2, 2)`
        /// array.
        #[getter]
        fn families<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray3<f64>> {
            let families = &self.found.result().families;
            let ranges: Vec<[[f64; 2]; 2]> = families.iter().map(|g| [g.s, g.t]).collect();
            pairs2(py, &ranges)
        }
    }
);

impl PyAntipodal {
    /// Each pair's `([s, t], [p, q], distance)`, for both variants.
    fn pair_fields(&self) -> Vec<([f64; 2], [[f64; 2]; 2], f64)> {
        let pairs = &self.found.result().pairs;
        pairs
            .iter()
            .map(|p| ([p.s, p.t], [p.p, p.q], p.distance))
            .collect()
    }
}

result_class!(
    PyInflections,
    "Inflections",
    InflectionsFound,
    certified = "Every inflection proven, and nothing missed.",
    counting "inflections" in list,
    {
        /// The inflections' parameters, an `(m,)` array.
        #[getter]
        fn params<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
            PyArray1::from_vec(py, self.list().iter().map(|i| i.u).collect())
        }

        /// The inflection points, an `(m, 2)` array.
        #[getter]
        fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
            points2(py, &self.list().iter().map(|i| i.p).collect::<Vec<_>>())
        }

        /// A profile's corners' parameters (empty for a smooth curve), a `(c,)` array.
        #[getter]
        fn corners<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
            let us = self.found.result().corner_list().iter().map(|c| c.u).collect();
            PyArray1::from_vec(py, us)
        }
    }
);

impl PyInflections {
    fn list(&self) -> &[antipodal::Inflection] {
        &self.found.result().inflections
    }
}

result_class!(
    PyTangents,
    "Tangents",
    TangentsFound,
    certified = "Every line proven, and nothing missed.",
    counting "lines" in lines,
    {
        /// The lines' parameters `(s, t)` on the two curves, an `(n, 2)` array.
        #[getter]
        fn params<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
            points2(py, &self.lines().iter().map(|l| l.0).collect::<Vec<_>>())
        }

        /// The lines' points of tangency `(p, q)`, an `(n, 2, 2)` array.
        #[getter]
        fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray3<f64>> {
            pairs2(py, &self.lines().iter().map(|l| l.1).collect::<Vec<_>>())
        }
    }
);

impl PyTangents {
    fn lines(&self) -> Vec<([f64; 2], [[f64; 2]; 2])> {
        let lines = &self.found.result().lines;
        lines.iter().map(|l| ([l.s, l.t], [l.p, l.q])).collect()
    }
}

result_class!(PyBisector, "Bisector", BisectorFound, {
    /// No search limit was hit.
    #[getter]
    fn complete(&self) -> bool {
        either!(&self.found, BisectorFound, f => f.complete)
    }

    /// The branches, each `(tr, xy)`: the foot-point parameters `(t, r)` and the bisector
    /// points, two `(k, 2)` arrays.
    #[getter]
    #[allow(clippy::type_complexity)]
    fn branches<'py>(
        &self,
        py: Python<'py>,
    ) -> Vec<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>)> {
        let pair = |tr: &[[f64; 2]], xy: &[[f64; 2]]| (points2(py, tr), points2(py, xy));
        either!(&self.found, BisectorFound, f => f.branches.iter().map(|b| pair(&b.tr, &b.xy)).collect())
    }

    fn __len__(&self) -> usize {
        either!(&self.found, BisectorFound, f => f.branches.len())
    }

    fn __repr__(&self) -> String {
        format!("Bisector({} branches)", self.__len__())
    }
});
