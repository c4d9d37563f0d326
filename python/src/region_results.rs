//! The results on regions (the medial axis, offsets, V-carving tool paths): numpy arrays of
//! their fields, the tool's `--json` document, and the files CAD and CAM programs read (DXF,
//! SVG paths), as the tool writes them.

use crate::results::{points2, result_class, verdict_repr, Kept, PickledCurve};
use curvekit::commands::{json_document_of, CurveSummary};
use curvekit::export::{dxf_file, svg_paths, ExportError};
use medial::MedialAxis;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use offset::{Offsets, VCarve};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};

/// A result that could not be written, as Python's error.
fn export_error(e: ExportError) -> PyErr {
    crate::CurvekitError::new_err(e.to_string())
}

/// A DXF file as written, as Python's bytes.
fn dxf_bytes<'py>(
    py: Python<'py>,
    written: Result<Vec<u8>, ExportError>,
) -> PyResult<Bound<'py, PyBytes>> {
    Ok(PyBytes::new(py, &written.map_err(export_error)?))
}

result_class!(PyMedialAxis, "MedialAxis", MedialAxis, verdict, {
    /// The nodes' points, an `(n, 2)` array (row `i` is node `i`).
    #[getter]
    fn nodes<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        points2(
            py,
            &self.found.nodes.iter().map(|n| n.xy).collect::<Vec<_>>(),
        )
    }

    /// The nodes' radii (of the largest inscribed disks there), an `(n,)` array.
    #[getter]
    fn node_radii<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, self.found.nodes.iter().map(|n| n.radius).collect())
    }

    /// The part of a multi-part input each node belongs to, an `(n,)` array (all 0 for one
    /// part).
    #[getter]
    fn node_parts<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<usize>> {
        PyArray1::from_vec(
            py,
            self.found
                .nodes
                .iter()
                .map(|n| n.part.unwrap_or(0))
                .collect(),
        )
    }

    /// The part each edge belongs to, an `(m,)` array (all 0 for one part).
    #[getter]
    fn edge_parts<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<usize>> {
        PyArray1::from_vec(
            py,
            self.found
                .edges
                .iter()
                .map(|e| e.part.unwrap_or(0))
                .collect(),
        )
    }

    /// The nodes' kinds: `"junction"`, `"end"`, `"corner"`, `"joint"` or `"clip"`.
    #[getter]
    fn node_kinds(&self) -> PyResult<Vec<String>> {
        self.found
            .nodes
            .iter()
            .map(|n| match serde_json::to_value(n.kind) {
                Ok(serde_json::Value::String(s)) => Ok(s),
                _ => Err(PyValueError::new_err("a node kind without a name")),
            })
            .collect()
    }

    /// The edges, each `(from, to, xy, radius)`: node indices, the polyline as a `(k, 2)`
    /// array and the radius at each vertex as a `(k,)` array.
    #[getter]
    #[allow(clippy::type_complexity)]
    fn edges<'py>(
        &self,
        py: Python<'py>,
    ) -> Vec<(
        usize,
        usize,
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray1<f64>>,
    )> {
        self.found
            .edges
            .iter()
            .map(|e| {
                (
                    e.from,
                    e.to,
                    points2(py, &e.xy),
                    PyArray1::from_vec(py, e.radius.clone()),
                )
            })
            .collect()
    }

    /// The axis as a DXF file's bytes, as `curvekit medial --dxf` writes it (R2010: edges as
    /// splines when fitted, else polylines; nodes as points on a layer per kind).
    fn dxf<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        dxf_bytes(
            py,
            dxf_file::medial_dxf(&self.found, self.units().as_deref()),
        )
    }

    /// The axis as plain SVG paths in the input's coordinates, as `--svg-paths` writes it.
    fn svg_paths(&self) -> PyResult<String> {
        svg_paths::medial_svg(&self.found, self.units().as_deref()).map_err(export_error)
    }

    fn __repr__(&self) -> String {
        let counts = format!(
            "{} nodes, {} edges",
            self.found.nodes.len(),
            self.found.edges.len()
        );
        verdict_repr("MedialAxis", &counts, &self.found)
    }
});

result_class!(PyOffsets, "Offsets", Offsets, verdict, {
    /// The distances, in the order asked, an `(m,)` array.
    #[getter]
    fn distances<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, self.found.offsets.iter().map(|o| o.distance).collect())
    }

    /// The loops at the `k`-th distance as closed polylines, `(n, 2)` arrays (arcs drawn with
    /// `arc_points` chords; lines and the splines' vertices as they are).
    #[pyo3(signature = (k, arc_points = 32))]
    fn polylines<'py>(
        &self,
        py: Python<'py>,
        k: usize,
        arc_points: usize,
    ) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
        let offset = self
            .found
            .offsets
            .get(k)
            .ok_or_else(|| pyo3::exceptions::PyIndexError::new_err(format!("no offset {k}")))?;
        Ok(offset
            .loops
            .iter()
            .map(|l| points2(py, &l.polyline(arc_points)))
            .collect())
    }

    /// The part of a multi-part input each loop at the `k`-th distance belongs to (all 0 for
    /// one part), in the order of `polylines(k)`.
    fn parts(&self, k: usize) -> PyResult<Vec<usize>> {
        let offset = self
            .found
            .offsets
            .get(k)
            .ok_or_else(|| pyo3::exceptions::PyIndexError::new_err(format!("no offset {k}")))?;
        Ok(offset.loops.iter().map(|l| l.part.unwrap_or(0)).collect())
    }

    fn __len__(&self) -> usize {
        self.found.offsets.len()
    }

    /// The loops at the `k`-th distance grouped into the regions they bound, each a region
    /// (`kind` `"region"`: an outer loop and the holes inside it) that the commands take again.
    fn regions(&self, k: usize) -> PyResult<Vec<crate::curves::PyCurve>> {
        let (offset, regions) = self.regions_at(k)?;
        regions
            .iter()
            .enumerate()
            .map(|(j, r)| {
                crate::curves::PyCurve::from_document(
                    format!("offset {} region {j}", offset.distance),
                    curvekit::io::region_document(r).to_string(),
                )
                .map_err(crate::to_py_err)
            })
            .collect()
    }

    /// GeoJSON geometry of the region inside the loops at the `k`-th distance (a
    /// `MultiPolygon`, empty where the region vanished), flattened within 1e-3 of its size.
    fn geometry<'py>(&self, py: Python<'py>, k: usize) -> PyResult<Bound<'py, PyAny>> {
        let (_, regions) = self.regions_at(k)?;
        let refs: Vec<&curve::Region> = regions.iter().collect();
        let geometry = match refs.as_slice() {
            [] => serde_json::json!({"type": "MultiPolygon", "coordinates": []}),
            _ => {
                let mut g =
                    curvekit::io::regions_geometry(&refs, crate::curves::geo_flatness(&refs));
                g["type"] = "MultiPolygon".into();
                if refs.len() == 1 {
                    g["coordinates"] = serde_json::json!([g["coordinates"].clone()]);
                }
                g
            }
        };
        py.import("json")?
            .call_method1("loads", (geometry.to_string(),))
    }

    /// GeoJSON geometry (as shapely's `shape()` takes it): the one distance's `MultiPolygon`,
    /// or a `GeometryCollection` of one for each distance.
    #[getter]
    fn __geo_interface__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        if self.found.offsets.len() == 1 {
            return self.geometry(py, 0);
        }
        let all = pyo3::types::PyDict::new(py);
        all.set_item("type", "GeometryCollection")?;
        let members = (0..self.found.offsets.len())
            .map(|k| self.geometry(py, k))
            .collect::<PyResult<Vec<_>>>()?;
        all.set_item("geometries", members)?;
        Ok(all.into_any())
    }

    /// The offsets as a DXF file's bytes, as `curvekit offset --dxf` writes it (R2010: lines,
    /// arcs and splines as computed, a layer per distance).
    fn dxf<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        dxf_bytes(
            py,
            dxf_file::offsets_dxf(&self.found, self.units().as_deref()),
        )
    }

    /// The offsets as plain SVG paths in the input's coordinates, as `--svg-paths` writes it.
    fn svg_paths(&self) -> PyResult<String> {
        svg_paths::offsets_svg(&self.found, self.units().as_deref()).map_err(export_error)
    }

    fn __repr__(&self) -> String {
        let counts = format!("{} distances", self.found.offsets.len());
        verdict_repr("Offsets", &counts, &self.found)
    }
});

result_class!(PyVCarve, "VCarve", VCarve, verdict, {
    /// The bit's included angle (degrees).
    #[getter]
    fn angle(&self) -> f64 {
        self.found.angle
    }

    /// The deepest cut asked for (`None`: as deep as the axis goes).
    #[getter]
    fn max_depth(&self) -> Option<f64> {
        self.found.max_depth
    }

    /// The tool paths, each an `(n, 3)` array of points `(x, y, z)`, `z ≤ 0` the depth.
    #[getter]
    fn paths<'py>(&self, py: Python<'py>) -> Vec<Bound<'py, PyArray2<f64>>> {
        self.found
            .paths
            .iter()
            .map(|p| {
                let n = p.xyz.len();
                let flat: Vec<f64> = p.xyz.iter().flatten().copied().collect();
                PyArray1::from_vec(py, flat)
                    .reshape([n, 3])
                    .unwrap_or_else(|_| PyArray2::zeros(py, [0, 3], false))
            })
            .collect()
    }

    /// The part of a multi-part input each path belongs to.
    #[getter]
    fn path_parts(&self) -> Vec<usize> {
        self.found.paths.iter().map(|p| p.part).collect()
    }

    /// The flat passes at depth `−max_depth` as closed polylines, `(n, 2)` arrays (arcs drawn
    /// with `arc_points` chords).
    #[pyo3(signature = (arc_points = 32))]
    fn flats<'py>(&self, py: Python<'py>, arc_points: usize) -> Vec<Bound<'py, PyArray2<f64>>> {
        self.found
            .flats
            .iter()
            .map(|l| points2(py, &l.polyline(arc_points)))
            .collect()
    }

    /// The paths as a DXF file's bytes, as `curvekit vcarve --dxf` writes it (3D polylines,
    /// the flat passes at their depth).
    fn dxf<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        dxf_bytes(
            py,
            dxf_file::vcarve_dxf(&self.found, self.units().as_deref()),
        )
    }

    fn __len__(&self) -> usize {
        self.found.paths.len()
    }

    fn __repr__(&self) -> String {
        let counts = format!(
            "{} paths, {} flats",
            self.found.paths.len(),
            self.found.flats.len()
        );
        verdict_repr("VCarve", &counts, &self.found)
    }
});

impl PyOffsets {
    /// The `k`-th offset and the regions its loops bound (each outer loop with the holes
    /// inside it).
    fn regions_at(&self, k: usize) -> PyResult<(&offset::Offset, Vec<curve::Region>)> {
        let offset = self
            .found
            .offsets
            .get(k)
            .ok_or_else(|| pyo3::exceptions::PyIndexError::new_err(format!("no offset {k}")))?;
        let profiles = offset
            .loops
            .iter()
            .map(|l| l.profile())
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| crate::CurvekitError::new_err(format!("an offset loop: {e}")))?;
        let regions = curve::Region::nested(profiles)
            .map_err(|e| crate::CurvekitError::new_err(format!("the offset loops: {e}")))?;
        Ok((offset, regions))
    }
}
