//! DXF files (R2010) of offsets, medial axes and V-carving tool paths, written with the `dxf`
//! crate and read back by CAD programs, ezdxf and curvekit.
//!
//! - **Offsets**: one layer per distance, `offset_<D>`; each loop's pieces in order, as
//!   `LINE`s (from → to along the loop), `ARC`s (counterclockwise, as DXF draws them: a
//!   clockwise arc is written from its end to its start), `CIRCLE`s (a loop of one full turn)
//!   and `SPLINE`s (degree, clamped knots, control points in the loop's direction).
//! - **Medial axes**: edges on `medial_edges`, as `SPLINE`s when fitted (`--fit`) or 2D
//!   `POLYLINE`s; nodes as `POINT`s on a layer per kind (`medial_junction`, `medial_end`,
//!   `medial_corner`, `medial_joint`, `medial_clip`).
//! - **V-carving**: the paths as 3D `POLYLINE`s on `vcarve_paths` (a path of one point, a
//!   plunge, as a `POINT`); the flat passes on `vcarve_flats`, as the offsets' pieces at depth
//!   `−max_depth`.
//!
//! Coordinates are written with 12 decimals (the crate's fixed format): within 1e-9 of the size
//! for drawings of size 1e-3 units and more. `$INSUNITS` is the input's unit where it has one.
//! ezdxf reads the files as written; its audit repairs two things the crate writes (a
//! transparency group of 0 on every entity, the tables' head handles), neither geometry.

use super::{distance_name, sweeps_nothing, ExportError};
use dxf::entities::{Arc, Circle, Entity, EntityType, Line, ModelPoint, Polyline, Spline, Vertex};
use dxf::enums::{AcadVersion, Units};
use dxf::tables::Layer;
use dxf::{Color, Drawing, Point};
use medial::{MedialAxis, NodeKind};
use offset::{OffsetSegment, Offsets, VCarve};
use std::f64::consts::TAU;

/// The `$INSUNITS` units by the names the readers give them ([`crate::io`]). Not `pc`: the DXF
/// reader names parsecs so, the SVG reader picas, and a unit written must be the one meant
/// (a drawing in either is written unitless).
const DXF_UNITS: [(&str, Units); 23] = [
    ("in", Units::Inches),
    ("ft", Units::Feet),
    ("mi", Units::Miles),
    ("mm", Units::Millimeters),
    ("cm", Units::Centimeters),
    ("m", Units::Meters),
    ("km", Units::Kilometers),
    ("uin", Units::Microinches),
    ("mil", Units::Mils),
    ("yd", Units::Yards),
    ("angstrom", Units::Angstroms),
    ("nm", Units::Nanometers),
    ("um", Units::Microns),
    ("dm", Units::Decimeters),
    ("dam", Units::Decameters),
    ("hm", Units::Hectometers),
    ("Gm", Units::Gigameters),
    ("au", Units::AstronomicalUnits),
    ("ly", Units::LightYears),
    ("us_ft", Units::USSurveyFeet),
    ("us_in", Units::USSurveyInch),
    ("us_yd", Units::USSurveyYard),
    ("us_mi", Units::USSurveyMile),
];

/// A sweep this close to a full turn (radians) is a whole circle: the offsets' full arcs are
/// `2π` apart up to the rounding of their angles.
const FULL_TURN: f64 = 1e-12;

/// The layer of the medial axis's edges.
pub const MEDIAL_EDGES: &str = "medial_edges";
/// The layer of the V-carving paths.
pub const VCARVE_PATHS: &str = "vcarve_paths";
/// The layer of the V-carving flat passes.
pub const VCARVE_FLATS: &str = "vcarve_flats";

/// A drawing being written: its layers in the order first used.
struct Writer {
    drawing: Drawing,
    layers: Vec<String>,
}

impl Writer {
    fn new(units: Option<&str>) -> Self {
        let mut drawing = Drawing::new();
        drawing.header.version = AcadVersion::R2010;
        drawing.header.default_drawing_units = units
            .and_then(|u| DXF_UNITS.iter().find(|(name, _)| *name == u))
            .map_or(Units::Unitless, |(_, code)| *code);
        Self {
            drawing,
            layers: Vec::new(),
        }
    }

    /// Adds `specific` on `layer` (made on first use, in the ACI colour `color`).
    fn add(&mut self, layer: &str, color: u8, specific: EntityType) {
        if !self.layers.iter().any(|l| l == layer) {
            self.layers.push(layer.to_string());
            self.drawing.add_layer(Layer {
                name: layer.to_string(),
                color: Color::from_index(color),
                ..Default::default()
            });
        }
        let mut entity = Entity::new(specific);
        entity.common.layer = layer.to_string();
        self.drawing.add_entity(entity);
    }

    /// A polyline through `points` (3D where `three_d`: its vertices flagged so).
    fn polyline(&mut self, points: impl Iterator<Item = Point>, three_d: bool) -> Polyline {
        let mut line = Polyline::default();
        line.set_is_3d_polyline(three_d);
        for p in points {
            let mut v = Vertex::new(p);
            v.set_is_3d_polyline_vertex(three_d);
            line.add_vertex(&mut self.drawing, v);
        }
        line
    }

    fn bytes(self) -> Result<Vec<u8>, ExportError> {
        let mut out = Vec::new();
        self.drawing
            .save(&mut out)
            .map_err(|e| ExportError::Dxf(e.to_string()))?;
        Ok(out)
    }
}

/// The entity of one offset piece, at height `z`; none for an arc that sweeps nothing (a
/// corner's arc where the offset meets it head on), which DXF would draw as a whole circle.
fn piece(s: &OffsetSegment, z: f64) -> Option<EntityType> {
    if sweeps_nothing(s) {
        return None;
    }
    let at = |p: [f64; 2]| Point::new(p[0], p[1], z);
    match s {
        OffsetSegment::Line { from, to } => Some(EntityType::Line(Line::new(at(*from), at(*to)))),
        OffsetSegment::Arc {
            center,
            r,
            start,
            end,
        } => {
            if ((end - start).abs() - TAU).abs() <= FULL_TURN * TAU {
                return Some(EntityType::Circle(Circle::new(at(*center), *r)));
            }
            // (DXF arcs run counterclockwise: a clockwise one is written end first.)
            let (a, b) = if end > start {
                (*start, *end)
            } else {
                (*end, *start)
            };
            let degrees = |x: f64| x.to_degrees().rem_euclid(360.0);
            Some(EntityType::Arc(Arc::new(
                at(*center),
                *r,
                degrees(a),
                degrees(b),
            )))
        }
        OffsetSegment::BSpline {
            degree,
            knots,
            points,
        } => Some(EntityType::Spline(spline(
            *degree,
            knots,
            points.iter().map(|p| at(*p)),
        ))),
    }
}

/// A planar non-rational spline.
fn spline(degree: usize, knots: &[f64], points: impl Iterator<Item = Point>) -> Spline {
    let mut s = Spline {
        degree_of_curve: degree as i32,
        knot_values: knots.to_vec(),
        control_points: points.collect(),
        ..Default::default()
    };
    s.set_is_planar(true);
    s
}

/// The DXF of offsets: a layer per distance (`offset_<D>`).
///
/// ```
/// use curvekit::export::dxf_file::offsets_dxf;
/// use offset::{Doubts, Offset, OffsetLoop, OffsetSegment, Offsets};
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let segments = (0..4)
///     .map(|i| OffsetSegment::Line { from: square[i], to: square[(i + 1) % 4] })
///     .collect();
/// let found = Offsets {
///     offsets: vec![Offset { distance: 0.5, loops: vec![OffsetLoop { segments, part: None }], error: 0.0 }],
///     doubts: Doubts::none(),
///     complete: true,
/// };
/// let text = String::from_utf8(offsets_dxf(&found, Some("mm")).unwrap()).unwrap();
/// assert!(text.contains("offset_0.5") && text.contains("LINE"));
/// ```
pub fn offsets_dxf(found: &Offsets, units: Option<&str>) -> Result<Vec<u8>, ExportError> {
    let mut w = Writer::new(units);
    for (k, o) in found.offsets.iter().enumerate() {
        let layer = distance_name(o.distance);
        // (Layers take the ACI colours 1 to 6 in turn: red, yellow, green, cyan, blue, magenta.)
        let color = 1 + (k % 6) as u8;
        for l in &o.loops {
            for e in l.segments.iter().filter_map(|s| piece(s, 0.0)) {
                w.add(&layer, color, e);
            }
        }
    }
    w.bytes()
}

/// The layer of a node kind (`medial_junction`, …).
pub fn node_layer(kind: NodeKind) -> &'static str {
    match kind {
        NodeKind::Junction => "medial_junction",
        NodeKind::End => "medial_end",
        NodeKind::Corner => "medial_corner",
        NodeKind::Joint => "medial_joint",
        NodeKind::Clip => "medial_clip",
    }
}

/// The DXF of a medial axis: edges on `medial_edges` (fitted splines, or polylines), nodes as
/// points on a layer per kind.
pub fn medial_dxf(axis: &MedialAxis, units: Option<&str>) -> Result<Vec<u8>, ExportError> {
    let mut w = Writer::new(units);
    for e in &axis.edges {
        let entity = match &e.bspline {
            Some(b) => EntityType::Spline(spline(
                b.degree,
                &b.knots,
                b.points.iter().map(|p| Point::new(p[0], p[1], 0.0)),
            )),
            None => EntityType::Polyline(
                w.polyline(e.xy.iter().map(|p| Point::new(p[0], p[1], 0.0)), false),
            ),
        };
        w.add(MEDIAL_EDGES, 5, entity);
    }
    for n in &axis.nodes {
        let point = ModelPoint::new(Point::new(n.xy[0], n.xy[1], 0.0));
        w.add(node_layer(n.kind), 1, EntityType::ModelPoint(point));
    }
    w.bytes()
}

/// The DXF of V-carving tool paths: 3D polylines on `vcarve_paths` (a plunge as a point), the
/// flat passes' pieces on `vcarve_flats` at depth `−max_depth`.
pub fn vcarve_dxf(carve: &VCarve, units: Option<&str>) -> Result<Vec<u8>, ExportError> {
    let mut w = Writer::new(units);
    for p in &carve.paths {
        let point = |q: &[f64; 3]| Point::new(q[0], q[1], q[2]);
        let entity = match p.xyz.as_slice() {
            [q] => EntityType::ModelPoint(ModelPoint::new(point(q))),
            all => EntityType::Polyline(w.polyline(all.iter().map(point), true)),
        };
        w.add(VCARVE_PATHS, 5, entity);
    }
    let z = -carve.max_depth.unwrap_or(0.0);
    for l in &carve.flats {
        for e in l.segments.iter().filter_map(|s| piece(s, z)) {
            w.add(VCARVE_FLATS, 3, e);
        }
    }
    w.bytes()
}
