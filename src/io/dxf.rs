//! ASCII DXF drawings (see `docs/interfaces.md`, "Profiles, regions and drawing files"): the
//! model-space entities `LINE`, `ARC`, `CIRCLE`, `ELLIPSE`, `LWPOLYLINE`, `POLYLINE` (with
//! bulges) and `SPLINE` of the `ENTITIES` section, chained end to end into profiles.
//!
//! **What is read.** The `ENTITIES` section is parsed with the `dxf` crate, except `SPLINE`
//! entities, whose group codes are read here from the text: the crate drops every control
//! point of a spline written without `30` (z) groups, as 2D writers do, and keeps the rest
//! only up to the shortest of the `10`/`20`/`30` lists. A small tokenizer of the file's
//! code/value line pairs finds the section, gives the splines' groups and each entity's
//! handle (code `5`) as written, and checks that the crate read every entity: it silently
//! drops an entity interrupted by a malformed value or a blank line, which is refused here
//! instead. The rest of the file (header, tables, blocks, objects) is not read.
//!
//! - `LINE`: a line (zero-length lines, within the tolerance below, are skipped).
//! - `ARC`: angles in degrees, counterclockwise from start to end (an end below the start
//!   goes once more round; equal angles, or a sweep within [`ANGLE_ROUNDING`] of nothing or of
//!   a full turn, make a full circle). `CIRCLE`: a closed profile of one full-turn arc.
//! - `ELLIPSE`: centre, major axis end point (relative to the centre), ratio of the minor axis
//!   to the major, and start and end eccentric angles in radians, counterclockwise about the
//!   extrusion direction; a full turn is a closed profile by itself.
//! - `LWPOLYLINE` and 2D `POLYLINE` (its `VERTEX` entities; spline-frame control vertices are
//!   left out, the fitted vertices kept): a line between consecutive vertices, or an arc where
//!   the first has a bulge `b = tan(θ/4)` (θ the included angle, counterclockwise when
//!   positive); repeated vertices are skipped; the closed flag (bit 1 of code 70) adds the
//!   piece from the last vertex back to the first. A 3D `POLYLINE` is read in plan view;
//!   polygon and polyface meshes are surfaces, skipped.
//! - `SPLINE`: degree (71), knots (40, interior multiplicities kept), control points (10/20),
//!   weights (41: used whenever given, one per control point; the rational flag, bit 4 of
//!   code 70, without weights is refused). Fit points (11/21) are not control points: a spline
//!   given by fit points only is refused. A spline whose knots are not clamped (periodic
//!   splines are written so, with their first control points repeated at the end) is
//!   restricted to its domain by knot insertion, which is exact; one flagged closed or
//!   periodic (bits 1, 2) must then end where it starts.
//!
//! Entities in paper space (code 67) are left out; every layer is read. Block references
//! (`INSERT`) are skipped, not expanded, and so are all other entity types (`TEXT`,
//! `DIMENSION`, `HATCH`, `POINT`, …). Coordinates are read in plan view: z is ignored.
//!
//! **Extrusion direction** (210/220/230). `ARC`, `CIRCLE`, `LWPOLYLINE` and 2D `POLYLINE` are
//! given in their object coordinate system: with the extrusion direction (0, 0, −1), common in
//! mirrored CAD output, its x axis is the world's −x, so they are mirrored in x. `LINE`,
//! `ELLIPSE` and `SPLINE` are given in world coordinates (an ellipse with extrusion (0, 0, −1)
//! runs clockwise as seen from above). Any other extrusion direction puts the entity out of
//! the drawing's plane: refused, naming the entity.
//!
//! **Chaining.** Closed entities (circles, full ellipses, closed splines, closed polylines) are
//! profiles by themselves; every other piece (a line, an arc, a partial ellipse, an open
//! spline, an open polyline with its vertices in their order) is joined to others at its ends.
//! Two ends join when they are within the drawing's tolerance, [`JOIN_GAP`] (1e-9) of its size
//! (the diagonal of the box of all entities' end and control points, polyline vertices and
//! bulge middles), or a few units of rounding of its largest coordinate. A grid of cells of
//! half the tolerance finds each end's partners in constant time. Three or more ends at one
//! point are a branch: refused, naming the entities. A chain starts at the first unused piece
//! in file order and grows at its end, then at its start, taking each piece forwards or
//! reversed; it is closed when it comes back to its own start. Two open ends of the drawing
//! nearer than [`NEAR_MISS`] of its size (and [`NEAR_MISS_OWN`] of their chains' sizes) are a
//! gap in an outline that was meant to close: refused, naming the entity and where the gap
//! is. Profiles are ordered by the position of
//! their first entity in the file and named after it: its type and handle (`LINE 2F`), or its
//! place in the `ENTITIES` section when it has no handle (`LINE #3`, from 1).

use super::drawing::{error, Chain, DrawingRead};
use super::{CurveFileError, Problem, MAX_ABS, MAX_DEGREE, MAX_SEGMENTS};
use bspline::{BSpline, Rational};
use curve::{Affine, FillRule, Segment, SegmentKind, SplineCurve, JOIN_GAP, V2};
use dxf::entities::{Entity, EntityType};
use std::borrow::Cow;
use std::collections::VecDeque;
use std::f64::consts::TAU;

/// Most entity records the `ENTITIES` section may hold: bounds the reader's work and memory.
pub(super) const MAX_ENTITIES: usize = 100_000;

/// Most control points (or knots) of one `SPLINE`: the knot insertion that clamps a spline,
/// and every command after it, work on each point; part outlines use tens.
pub(super) const MAX_SPLINE_POINTS: usize = 10_000;

/// Relative to the drawing's largest coordinate, the rounding an end point carries (an arc's
/// ends are computed from its centre, radius and angles): a few units of the last place, the
/// join tolerance far from the origin where `JOIN_GAP` of a small part's size is below it.
const COORDINATE_ROUNDING: f64 = 16.0 * f64::EPSILON;

/// Ends of different pieces nearer than this (relative to the drawing's size) but beyond the
/// tolerance are a gap in an outline meant to close: a drawing error to report. Ends drawn
/// apart on purpose (an open profile) are far farther apart than 1e-4 of the drawing.
pub(super) const NEAR_MISS: f64 = 1e-4;

/// Open ends are a gap only when also nearer than this, relative to the size of the chains
/// they end: an outline that misses closing by a thousandth of itself is a gap; a short line
/// whose two ends are its whole length apart is not.
const NEAR_MISS_OWN: f64 = 1e-3;

/// How far from (0, 0, ±1) an extrusion direction may be (each of its x and y relative to its
/// length): the rounding of a unit vector written with 15 or more digits, no tilt.
const PLAN_NORMAL: f64 = 1e-12;

/// A bulge this small (in magnitude) is a straight piece: its arc strays from the chord by
/// `|b| c / 2`, below 1e-9 of the chord `c`, within the drawing's tolerance; as an arc its
/// radius `c (|b| + 1/|b|) / 4` would be so large that its computed ends miss the vertices.
const FLAT_BULGE: f64 = 1e-9;

/// How near (radians) a sweep may come to nothing or to a full turn and be a full turn: writers
/// round angles (the `dxf` crate's writer to 12 decimals, putting 2π at 6.28318530718, past
/// it by 4e-13), so an arc or ellipse from 0 to 2π may come out a sliver or a turn short. An
/// arc of a billionth of a radian is not drawn on purpose.
const ANGLE_ROUNDING: f64 = 1e-9;

/// The mirror `x ↦ −x`: the object coordinate system of extrusion direction (0, 0, −1).
const MIRROR: Affine = Affine([-1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);

/// The entity types read (all others are skipped).
const READ_TYPES: [&str; 7] = [
    "LINE",
    "ARC",
    "CIRCLE",
    "ELLIPSE",
    "LWPOLYLINE",
    "POLYLINE",
    "SPLINE",
];

/// The chains of segments of an ASCII DXF drawing, in the order of their first entities in the
/// file (see the module documentation); empty when it holds no geometry that is read. One
/// group, filled even-odd: outlines nested inside each other alternate between part and hole.
pub(super) fn read(file: &str, bytes: &[u8]) -> Result<DrawingRead, CurveFileError> {
    let fail = |field: &str, problem: Problem| error(file, field, problem);
    if bytes.starts_with(b"AutoCAD Binary DXF") || bytes.starts_with(b"AutoCAD DXB") {
        return Err(fail(
            "document",
            Problem::Unsupported("a binary DXF (or DXB) file: only ASCII DXF is read".into()),
        ));
    }
    let section = entity_records(bytes).map_err(|p| fail("document", p))?;
    let drawing = load_entities(bytes, &section).map_err(|p| fail("document", p))?;
    let entities = pair_up(&drawing, &section.records).map_err(|(field, p)| fail(&field, p))?;

    let mut shapes = Vec::with_capacity(entities.len());
    for (order, (entity, record)) in entities.iter().enumerate() {
        if entity.common.is_in_paper_space {
            continue;
        }
        let name = record.name();
        let shape = shape_of(entity, record).map_err(|(what, p)| {
            let field = if what.is_empty() {
                name.clone()
            } else {
                format!("{name} {what}")
            };
            fail(&field, p)
        })?;
        if let Some(shape) = shape {
            shapes.push(Item { order, name, shape });
        }
    }
    let tol = Tolerance::of(&shapes);
    let pieces = shapes
        .into_iter()
        .map(|item| item.piece(tol.join))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|(field, p)| fail(&field, p))?;
    let chains = chain_pieces(pieces, &tol).map_err(|(field, p)| fail(&field, p))?;
    Ok(DrawingRead {
        chains,
        ..DrawingRead::default()
    })
}

/// An error before the file name is attached: (field, problem).
type Failure = (String, Problem);

// ---------------------------------------------------------------------------------------------
// The ENTITIES section as text.

/// One entity record of the `ENTITIES` section, as written.
#[derive(Debug)]
struct Record<'a> {
    /// Its type (`LINE`).
    kind: Cow<'a, str>,
    /// Its handle (code 5), if given.
    handle: Option<Cow<'a, str>>,
    /// Its place among the section's records, from 1.
    place: usize,
    /// Its groups after the type, kept for `SPLINE` only (the crate loses some of them).
    groups: Vec<(i32, Cow<'a, str>)>,
}

impl Record<'_> {
    /// `LINE 2F`, or `LINE #3` without a handle.
    fn name(&self) -> String {
        match &self.handle {
            Some(h) => format!("{} {}", self.kind, h.trim()),
            None => format!("{} #{}", self.kind, self.place),
        }
    }
}

/// The `ENTITIES` section: its records, and where it lies in the file's bytes.
#[derive(Debug, Default)]
struct Section<'a> {
    records: Vec<Record<'a>>,
    /// From its `0 SECTION` to the end of its `0 ENDSEC` (or of the file).
    range: Option<(usize, Option<usize>)>,
}

/// Reads the `ENTITIES` section's records, in order (at most [`MAX_ENTITIES`]). The bytes
/// are read as code/value line pairs, as the `dxf` crate reads them (lines end at `\n`, less
/// one `\r` before it; codes trimmed; comments (999) skipped), up to the section's end.
fn entity_records(bytes: &[u8]) -> Result<Section<'_>, Problem> {
    let mut section = Section::default();
    let mut offset = 0;
    if bytes.starts_with(b"\xEF\xBB\xBF") {
        offset = 3;
    }
    let mut lines = bytes
        .get(offset..)
        .unwrap_or_default()
        .split(|&b| b == b'\n')
        .scan(offset, |at, line| {
            let start = *at;
            *at += line.len() + 1;
            Some((start, line.strip_suffix(b"\r").unwrap_or(line)))
        })
        .enumerate();
    // Where the last `0 SECTION` started, and whether its name is to come next.
    let mut opening: Option<usize> = None;
    let mut in_entities = false;
    let malformed = |line: usize, what: &str| {
        Problem::Unsupported(format!(
            "not a readable ASCII DXF file: line {line}: {what}"
        ))
    };
    // Each turn takes two lines: the loop ends with the bytes.
    while let Some((i, (at, code_line))) = lines.next() {
        let code_line = String::from_utf8_lossy(code_line);
        let code_line = code_line.trim();
        if code_line.is_empty() {
            // The crate stops at a blank code line as at the end of the file, and would
            // silently leave out whatever follows: only blank lines may.
            if bytes
                .get(at..)
                .unwrap_or_default()
                .iter()
                .all(u8::is_ascii_whitespace)
            {
                break;
            }
            return Err(malformed(
                i + 1,
                "an empty line where a group code should be",
            ));
        }
        let Ok(code) = code_line.parse::<i32>() else {
            return Err(malformed(
                i + 1,
                &format!("`{code_line}` is not a group code"),
            ));
        };
        let Some((_, (_, value))) = lines.next() else {
            return Err(malformed(i + 1, "the file ends after a group code"));
        };
        if code == 999 {
            continue;
        }
        if let Some(section_start) = opening.take() {
            if code == 2 {
                in_entities = value.trim_ascii() == b"ENTITIES";
                if in_entities {
                    section.range = Some((section_start, None));
                }
                continue;
            }
        }
        if code == 0 {
            match value {
                b"SECTION" => {
                    opening = Some(at);
                    in_entities = false;
                }
                b"ENDSEC" if in_entities => {
                    // The end of this value line: the next line's start.
                    let end = lines.clone().next().map(|(_, (next, _))| next);
                    if let Some((start, _)) = section.range {
                        section.range = Some((start, end.or(Some(bytes.len()))));
                    }
                    break;
                }
                b"ENDSEC" => in_entities = false,
                b"EOF" => break,
                kind if in_entities => {
                    if section.records.len() == MAX_ENTITIES {
                        return Err(Problem::OutOfRange {
                            rule: format!("at most {MAX_ENTITIES} entities"),
                            value: (MAX_ENTITIES + 1) as f64,
                        });
                    }
                    let place = section.records.len() + 1;
                    section.records.push(Record {
                        kind: String::from_utf8_lossy(kind),
                        handle: None,
                        place,
                        groups: Vec::new(),
                    });
                }
                _ => {}
            }
            continue;
        }
        if !in_entities {
            continue;
        }
        if let Some(r) = section.records.last_mut() {
            if code == 5 && r.handle.is_none() {
                r.handle = Some(String::from_utf8_lossy(value));
            }
            if r.kind == "SPLINE" {
                r.groups.push((code, String::from_utf8_lossy(value)));
            }
        }
    }
    Ok(section)
}

/// The `dxf` crate's reading of the `ENTITIES` section (the rest of the file is not the
/// reader's concern: its tables and objects are neither read nor checked).
fn load_entities(bytes: &[u8], section: &Section<'_>) -> Result<dxf::Drawing, Problem> {
    let Some((start, end)) = section.range else {
        return Ok(dxf::Drawing::new());
    };
    let mut text = bytes
        .get(start..end.unwrap_or(bytes.len()))
        .unwrap_or_default()
        .to_vec();
    if end.is_some() {
        text.extend_from_slice(b"0\nEOF\n");
    }
    dxf::Drawing::load(&mut &text[..]).map_err(|e| {
        Problem::Unsupported(format!(
            "not a readable ASCII DXF file: in its ENTITIES section: {e}"
        ))
    })
}

/// The crate's entities of the types read, each with its record; refused when the two
/// readings disagree (the crate skipped or merged an entity it could not read).
fn pair_up<'d, 'r>(
    drawing: &'d dxf::Drawing,
    records: &'r [Record<'r>],
) -> Result<Vec<(&'d Entity, &'r Record<'r>)>, Failure> {
    let ours: Vec<&Record<'_>> = records
        .iter()
        .filter(|r| READ_TYPES.contains(&r.kind.as_ref()))
        .collect();
    let theirs: Vec<&Entity> = drawing
        .entities()
        .filter(|e| type_name(&e.specific).is_some())
        .collect();
    let mut out = Vec::with_capacity(ours.len());
    for (k, record) in ours.iter().enumerate() {
        let Some(entity) = theirs.get(k) else {
            return Err(unreadable(record));
        };
        // (Handles are the records': the crate gives one of its own to an entity written
        // without, or with handle 0.)
        if type_name(&entity.specific) != Some(record.kind.as_ref()) {
            return Err(unreadable(record));
        }
        out.push((*entity, *record));
    }
    if theirs.len() != ours.len() {
        return Err((
            "document".into(),
            Problem::Unsupported(
                "the DXF reader found entities that are not in the ENTITIES section".into(),
            ),
        ));
    }
    Ok(out)
}

fn unreadable(record: &Record<'_>) -> Failure {
    (
        record.name(),
        Problem::Unsupported(
            "the entity could not be read (a malformed or missing group value)".into(),
        ),
    )
}

/// The DXF type of the entity kinds read.
fn type_name(e: &EntityType) -> Option<&'static str> {
    Some(match e {
        EntityType::Line(_) => "LINE",
        EntityType::Arc(_) => "ARC",
        EntityType::Circle(_) => "CIRCLE",
        EntityType::Ellipse(_) => "ELLIPSE",
        EntityType::LwPolyline(_) => "LWPOLYLINE",
        EntityType::Polyline(_) => "POLYLINE",
        EntityType::Spline(_) => "SPLINE",
        _ => return None,
    })
}

// ---------------------------------------------------------------------------------------------
// Entities → shapes.

/// An entity's geometry, before the drawing's tolerance is known.
#[derive(Debug)]
enum Shape {
    /// One segment: open (joined to others) or closed (a profile by itself); `flagged`: a
    /// spline flagged closed or periodic, which must end where it starts.
    Segment {
        segment: Box<Segment>,
        flagged: bool,
    },
    /// A polyline's vertices `(point, bulge)` in its object coordinates, mirrored in x or not,
    /// and whether it is closed.
    Polyline {
        vertices: Vec<([f64; 2], f64)>,
        mirrored: bool,
        closed: bool,
    },
}

/// An entity read: its place among the entities, its name and its shape.
#[derive(Debug)]
struct Item {
    order: usize,
    name: String,
    shape: Shape,
}

/// The error of a field of the entity being read: (what, problem); `what` is empty for the
/// entity as a whole.
type EntityError = (String, Problem);

fn geometry(what: &str, message: impl Into<String>) -> EntityError {
    (what.to_string(), Problem::Geometry(message.into()))
}

/// A number read from the file: finite and at most [`MAX_ABS`].
fn number(what: &str, x: f64) -> Result<f64, EntityError> {
    if x.is_finite() && x.abs() <= MAX_ABS {
        Ok(x)
    } else {
        Err((what.to_string(), Problem::TooLarge(x)))
    }
}

fn point(what: &str, x: f64, y: f64) -> Result<[f64; 2], EntityError> {
    Ok([number(what, x)?, number(what, y)?])
}

fn positive(what: &str, x: f64) -> Result<f64, EntityError> {
    let x = number(what, x)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err((
            what.to_string(),
            Problem::OutOfRange {
                rule: "> 0".into(),
                value: x,
            },
        ))
    }
}

/// A refusal by the curve model, for the entity's field `what`.
fn curve_error(what: &str, e: curve::Error) -> EntityError {
    match e {
        curve::Error::Spline(e) => (what.to_string(), Problem::Spline(e)),
        e => geometry(what, e.to_string()),
    }
}

/// Whether an entity with extrusion direction `n` lies in the drawing's plane mirrored
/// (`n = (0, 0, −1)`) or not (`(0, 0, 1)`); any other direction is refused.
fn mirrored(n: [f64; 3]) -> Result<bool, EntityError> {
    let len = n[0].hypot(n[1]).hypot(n[2]);
    if !len.is_finite() {
        return Err(geometry(
            "extrusion",
            "the extrusion direction is not finite",
        ));
    }
    if len == 0.0 {
        // (A zero vector is no direction: taken for the default, as an absent one.)
        return Ok(false);
    }
    if n[0].abs() <= PLAN_NORMAL * len && n[1].abs() <= PLAN_NORMAL * len {
        return Ok(n[2] < 0.0);
    }
    Err(geometry(
        "extrusion",
        format!(
            "extrusion direction ({}, {}, {}): the entity is not in the drawing's plane \
             (only (0, 0, 1) and (0, 0, -1) are read)",
            n[0], n[1], n[2]
        ),
    ))
}

/// The segment moved into world coordinates (mirrored in x) when `mirror`.
fn placed(seg: Segment, mirror: bool) -> Result<Segment, EntityError> {
    if mirror {
        seg.transformed(&MIRROR).map_err(|e| curve_error("", e))
    } else {
        Ok(seg)
    }
}

/// The shape of one entity, or `None` for one that holds no curve (a zero-length line is
/// decided later, a mesh here).
fn shape_of(entity: &Entity, record: &Record<'_>) -> Result<Option<Shape>, EntityError> {
    let vec3 = |v: &dxf::Vector| [v.x, v.y, v.z];
    let segment = match &entity.specific {
        EntityType::Line(l) => {
            // (World coordinates: the extrusion direction only orients a thickness.)
            let from = point("start", l.p1.x, l.p1.y)?;
            let to = point("end", l.p2.x, l.p2.y)?;
            if from == to {
                return Ok(None);
            }
            Segment::line(from, to).map_err(|e| curve_error("", e))?
        }
        EntityType::Arc(a) => {
            let mirror = mirrored(vec3(&a.normal))?;
            let center = point("center", a.center.x, a.center.y)?;
            let r = positive("radius", a.radius)?;
            let start = number("start angle", a.start_angle)?.rem_euclid(360.0);
            let end = number("end angle", a.end_angle)?;
            // Counterclockwise from start to end; equal angles are a full turn.
            let sweep = full_turn((end - a.start_angle).rem_euclid(360.0).to_radians());
            let start = start.to_radians();
            let seg =
                Segment::arc(center, r, start, start + sweep).map_err(|e| curve_error("", e))?;
            placed(seg, mirror)?
        }
        EntityType::Circle(c) => {
            let mirror = mirrored(vec3(&c.normal))?;
            let center = point("center", c.center.x, c.center.y)?;
            let r = positive("radius", c.radius)?;
            let seg = Segment::arc(center, r, 0.0, TAU).map_err(|e| curve_error("", e))?;
            placed(seg, mirror)?
        }
        EntityType::Ellipse(e) => ellipse(e)?,
        EntityType::LwPolyline(p) => {
            let mirror = mirrored(vec3(&p.extrusion_direction))?;
            let vertices = p
                .vertices
                .iter()
                .enumerate()
                .map(|(i, v)| vertex(i, v.x, v.y, v.bulge))
                .collect::<Result<Vec<_>, _>>()?;
            return polyline(vertices, mirror, p.flags & 1 != 0);
        }
        EntityType::Polyline(p) => {
            // Meshes (16: polygon mesh, 64: polyface mesh) are surfaces, not curves.
            if p.flags & (16 | 64) != 0 {
                return Ok(None);
            }
            // A 3D polyline (8) is in world coordinates, without bulges.
            let three_d = p.flags & 8 != 0;
            let mirror = !three_d && mirrored(vec3(&p.normal))?;
            let vertices = p
                .vertices()
                // Spline-frame control vertices (16) are not on the curve drawn.
                .filter(|v| v.flags & 16 == 0)
                .enumerate()
                .map(|(i, v)| {
                    let bulge = if three_d { 0.0 } else { v.bulge };
                    vertex(i, v.location.x, v.location.y, bulge)
                })
                .collect::<Result<Vec<_>, _>>()?;
            return polyline(vertices, mirror, p.flags & 1 != 0);
        }
        EntityType::Spline(_) => {
            let (segment, flagged) = spline(&record.groups)?;
            return Ok(Some(Shape::Segment {
                segment: Box::new(segment),
                flagged,
            }));
        }
        _ => return Ok(None),
    };
    Ok(Some(Shape::Segment {
        segment: Box::new(segment),
        flagged: false,
    }))
}

/// A polyline vertex `(point, bulge)`.
fn vertex(i: usize, x: f64, y: f64, bulge: f64) -> Result<([f64; 2], f64), EntityError> {
    let p = point(&format!("vertex {i}"), x, y)?;
    Ok((p, number(&format!("vertex {i} bulge"), bulge)?))
}

fn polyline(
    vertices: Vec<([f64; 2], f64)>,
    mirrored: bool,
    closed: bool,
) -> Result<Option<Shape>, EntityError> {
    if vertices.len() > MAX_SEGMENTS {
        return Err((
            "vertices".into(),
            Problem::OutOfRange {
                rule: format!("at most {MAX_SEGMENTS} vertices"),
                value: vertices.len() as f64,
            },
        ));
    }
    if vertices.len() < 2 {
        // (A single vertex is a point: nothing drawn.)
        return Ok(None);
    }
    Ok(Some(Shape::Polyline {
        vertices,
        mirrored,
        closed,
    }))
}

/// More than [`MAX_SPLINE_POINTS`] control points (or weights, or their knots).
fn too_many(what: &str, count: usize) -> EntityError {
    (
        what.to_string(),
        Problem::OutOfRange {
            rule: format!("at most {MAX_SPLINE_POINTS} control points"),
            value: count as f64,
        },
    )
}

/// A counterclockwise sweep in `[0, 2π)` (radians), or the full turn where it is within
/// [`ANGLE_ROUNDING`] of nothing or of a full turn.
fn full_turn(sweep: f64) -> f64 {
    if sweep <= ANGLE_ROUNDING || sweep >= TAU - ANGLE_ROUNDING {
        TAU
    } else {
        sweep
    }
}

/// An `ELLIPSE` in world coordinates.
fn ellipse(e: &dxf::entities::Ellipse) -> Result<Segment, EntityError> {
    let flip = mirrored([e.normal.x, e.normal.y, e.normal.z])?;
    let center = point("center", e.center.x, e.center.y)?;
    let axis = point("major axis", e.major_axis.x, e.major_axis.y)?;
    let rx = axis[0].hypot(axis[1]);
    if rx == 0.0 {
        return Err(geometry("major axis", "the major axis has zero length"));
    }
    let ratio = positive("ratio", e.minor_axis_ratio)?;
    let ry = rx * ratio;
    let rotation = axis[1].atan2(axis[0]);
    let start = number("start parameter", e.start_parameter)?;
    let end = number("end parameter", e.end_parameter)?;
    // Counterclockwise about the extrusion direction from start to end; equal parameters
    // (or a whole turn apart) are the full ellipse.
    let sweep = full_turn((end - start).rem_euclid(TAU));
    let start = start.rem_euclid(TAU);
    // With extrusion (0, 0, −1) the minor axis is (0, 0, −1) × major: the point at eccentric
    // angle t is the counterclockwise ellipse's at −t.
    let (a, b) = if flip {
        (-start, -(start + sweep))
    } else {
        (start, start + sweep)
    };
    Segment::elliptic_arc(center, rx, ry, rotation, a, b).map_err(|e| curve_error("", e))
}

/// A `SPLINE` from its groups as written (see the module documentation).
/// Returns the segment and whether it is flagged closed or periodic (70 bits 1, 2).
///
/// The curve's derivatives are checked as a `bspline` curve file's are: knots packed far too
/// tightly for the coordinates overflow them, and nothing after could be trusted.
fn spline(groups: &[(i32, Cow<'_, str>)]) -> Result<(Segment, bool), EntityError> {
    let mut flags = 0i64;
    let mut degree = None;
    let mut knots = Vec::new();
    let mut weights = Vec::new();
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut has_y = Vec::new();
    let mut fit_points = 0usize;
    let mut normal = [0.0, 0.0, 1.0];
    for (code, value) in groups {
        let (code, value) = (*code, value.as_ref());
        let float = |what: &str| {
            value
                .trim()
                .parse::<f64>()
                .map_err(|_| geometry(what, format!("`{}` is not a number", value.trim())))
                .and_then(|x| number(what, x))
        };
        let integer = |what: &str| {
            value
                .trim()
                .parse::<i64>()
                .map_err(|_| geometry(what, format!("`{}` is not an integer", value.trim())))
        };
        match code {
            70 => flags = integer("flags")?,
            71 => degree = Some(integer("degree")?),
            // (Bounded as they come: knots number the control points and the order at most.)
            40 if knots.len() > MAX_SPLINE_POINTS + MAX_DEGREE => {
                return Err(too_many("knots", knots.len() + 1))
            }
            41 if weights.len() >= MAX_SPLINE_POINTS => {
                return Err(too_many("weights", weights.len() + 1))
            }
            10 if points.len() >= MAX_SPLINE_POINTS => {
                return Err(too_many("control points", points.len() + 1))
            }
            40 => knots.push(float("knots")?),
            41 => weights.push(float("weights")?),
            10 => {
                points.push([float("control points")?, 0.0]);
                has_y.push(false);
            }
            20 => match (points.last_mut(), has_y.last_mut()) {
                (Some(p), Some(seen @ false)) => {
                    p[1] = float("control points")?;
                    *seen = true;
                }
                _ => {
                    return Err(geometry(
                        "control points",
                        "a y (20) without its x (10) before it",
                    ))
                }
            },
            11 => fit_points += 1,
            210 => normal[0] = float("extrusion")?,
            220 => normal[1] = float("extrusion")?,
            230 => normal[2] = float("extrusion")?,
            _ => {}
        }
    }
    // (World coordinates: a planar spline's normal only says which plane it lies in.)
    mirrored(normal)?;
    let n = points.len();
    if n == 0 {
        let why = if fit_points > 0 {
            "given by fit points (11/21) only, without control points (10/20): not read"
        } else {
            "no control points (10/20)"
        };
        return Err(geometry("control points", why));
    }
    if let Some(i) = has_y.iter().position(|&y| !y) {
        return Err(geometry(
            "control points",
            format!("control point {i} has an x (10) but no y (20)"),
        ));
    }
    let degree = match degree {
        None => return Err(("degree".into(), Problem::Missing)),
        Some(p) if p < 1 || p > MAX_DEGREE as i64 => {
            return Err((
                "degree".into(),
                Problem::OutOfRange {
                    rule: format!("an integer from 1 to {MAX_DEGREE}"),
                    value: p as f64,
                },
            ))
        }
        Some(p) => p as usize,
    };
    if n <= degree {
        return Err((
            "control points".into(),
            Problem::WrongCount {
                expected: format!("at least {} for degree {degree}", degree + 1),
                got: n,
            },
        ));
    }
    if knots.len() != n + degree + 1 {
        return Err((
            "knots".into(),
            Problem::WrongCount {
                expected: format!("{} (control points + degree + 1)", n + degree + 1),
                got: knots.len(),
            },
        ));
    }
    let rational = flags & 4 != 0;
    let weights = match (weights.len(), rational) {
        (0, false) => None,
        (0, true) => {
            return Err(geometry(
                "weights",
                "flagged rational (70 bit 4) but no weights (41) are given",
            ))
        }
        (k, _) if k != n => {
            return Err((
                "weights".into(),
                Problem::WrongCount {
                    expected: format!("{n} (one per control point)"),
                    got: k,
                },
            ))
        }
        _ => Some(weights),
    };
    let flat: Vec<f64> = points.iter().flatten().copied().collect();
    let b = BSpline::new(degree, knots.clone(), 2, flat)
        .map_err(|e| ("knots".to_string(), Problem::Spline(e)))?;
    let r = Rational::new(b, weights.as_deref())
        .map_err(|e| ("weights".to_string(), Problem::Spline(e)))?;
    let (a, z) = r.domain();
    // (The counts were checked: the slices are whole; an empty one would not be clamped.)
    let first = knots.get(..=degree).unwrap_or_default();
    let last = knots.get(n..).unwrap_or_default();
    let clamped = !first.is_empty()
        && !last.is_empty()
        && first.iter().all(|&k| k == a)
        && last.iter().all(|&k| k == z);
    let curve = if clamped {
        SplineCurve::clamped(degree, &points, weights.as_deref(), Some(knots))
    } else {
        // Knot insertion up to full multiplicity at the domain's ends: the same curve, clamped.
        let c = r
            .restrict(a, z)
            .map_err(|e| ("knots".to_string(), Problem::Spline(e)))?;
        let pts: Vec<[f64; 2]> = c
            .control_points()
            .iter()
            .map(|p| {
                [
                    p.first().copied().unwrap_or(0.0),
                    p.get(1).copied().unwrap_or(0.0),
                ]
            })
            .collect();
        let w = c.is_rational().then(|| c.weights());
        let k = c.homogeneous().knots().to_vec();
        SplineCurve::clamped(degree, &pts, w.as_deref(), Some(k))
    }
    .map_err(|e| curve_error("control points", e))?;
    if points.iter().all(|p| Some(p) == points.first()) {
        return Err(("control points".into(), Problem::Degenerate));
    }
    let hom = curve.curve().homogeneous();
    let d1 = hom.deriv();
    if !d1
        .coefs()
        .iter()
        .chain(d1.deriv().coefs())
        .all(|x| x.is_finite())
    {
        return Err(("knots".into(), Problem::Overflow));
    }
    let seg = Segment::spline(SegmentKind::BSpline, curve)
        .map_err(|e| curve_error("control points", e))?;
    // (Whether a spline flagged closed does close is judged with the drawing's tolerance.)
    Ok((seg, flags & 3 != 0))
}

// ---------------------------------------------------------------------------------------------
// Tolerance and pieces.

/// The drawing's scale and the tolerances derived from it.
#[derive(Debug, Clone, Copy)]
struct Tolerance {
    /// Ends within this distance join.
    join: f64,
    /// Open ends within this distance (and beyond `join`) are a gap.
    near: f64,
}

impl Tolerance {
    /// The tolerances of the drawing made of `items`.
    fn of(items: &[Item]) -> Tolerance {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        let mut add = |p: [f64; 2]| {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        };
        for item in items {
            match &item.shape {
                Shape::Segment { segment, .. } => segment
                    .curve()
                    .control_points()
                    .into_iter()
                    .for_each(&mut add),
                Shape::Polyline {
                    vertices, mirrored, ..
                } => {
                    let flip = |p: [f64; 2]| if *mirrored { MIRROR.apply(p) } else { p };
                    for (i, &(p, b)) in vertices.iter().enumerate() {
                        add(flip(p));
                        if let Some(&(q, _)) = vertices.get(i + 1).or(vertices.first()) {
                            add(flip(bulge_middle(p, q, b)));
                        }
                    }
                }
            }
        }
        if items.is_empty() {
            return Tolerance {
                join: f64::MIN_POSITIVE,
                near: f64::MIN_POSITIVE,
            };
        }
        let size = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
        let magnitude = lo.iter().chain(&hi).fold(0.0f64, |m, x| m.max(x.abs()));
        let join = (JOIN_GAP * size)
            .max(COORDINATE_ROUNDING * magnitude)
            .max(f64::MIN_POSITIVE);
        Tolerance {
            join,
            near: (NEAR_MISS * size).max(join),
        }
    }
}

/// The middle of the arc of bulge `b` from `p` to `q` (on the chord's right for `b > 0`).
fn bulge_middle(p: [f64; 2], q: [f64; 2], b: f64) -> [f64; 2] {
    let (p, q) = (V2::from_arr(p), V2::from_arr(q));
    let m = (p + q) * 0.5;
    // (q − p)⊥ has the chord's length: the sagitta is b · c / 2.
    (m - (q - p).perp() * (0.5 * b)).arr()
}

/// A piece of the drawing: segments in order, closed by itself or with open ends.
#[derive(Debug)]
struct Piece {
    order: usize,
    name: String,
    segments: Vec<Segment>,
    /// The first segment's start and the last one's end.
    start: V2,
    end: V2,
    /// `Some(true)` closed (a profile by itself), `None` for a polyline that the profile
    /// decides, `Some(false)` for a piece whose ends join others.
    closed: Option<bool>,
}

impl Item {
    /// The piece, with zero-length lines and polyline pieces (within `tol`) left out.
    fn piece(self, tol: f64) -> Result<Option<Piece>, Failure> {
        let name = self.name;
        let at = |(what, p): EntityError| {
            let field = if what.is_empty() {
                name.clone()
            } else {
                format!("{name} {what}")
            };
            (field, p)
        };
        let (segments, closed) = match self.shape {
            Shape::Segment { segment, flagged } => {
                let gap = (segment.end() - segment.start()).norm();
                if segment.kind() == SegmentKind::Line && gap <= tol {
                    return Ok(None);
                }
                if flagged && gap > tol {
                    return Err(at(geometry(
                        "",
                        format!(
                            "flagged closed or periodic (70 bits 1, 2) but its ends are {gap:e} \
                             apart (the drawing's tolerance is {tol:e})"
                        ),
                    )));
                }
                (vec![*segment], Some(gap <= tol))
            }
            Shape::Polyline {
                vertices,
                mirrored,
                closed,
            } => {
                let segs = polyline_segments(&vertices, closed, tol).map_err(at)?;
                let segs = segs
                    .into_iter()
                    .map(|s| placed(s, mirrored))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(at)?;
                if segs.is_empty() {
                    return Ok(None);
                }
                let shut = closed
                    || (segs.len() > 1
                        && segs
                            .first()
                            .zip(segs.last())
                            .is_some_and(|(f, l)| (l.end() - f.start()).norm() <= tol));
                (segs, if shut { Some(true) } else { Some(false) })
            }
        };
        let (Some(first), Some(last)) = (segments.first(), segments.last()) else {
            return Ok(None);
        };
        let (start, end) = (first.start(), last.end());
        Ok(Some(Piece {
            order: self.order,
            name,
            segments,
            start,
            end,
            closed,
        }))
    }
}

/// The segments of a polyline in its object coordinates.
fn polyline_segments(
    vertices: &[([f64; 2], f64)],
    closed: bool,
    tol: f64,
) -> Result<Vec<Segment>, EntityError> {
    let n = vertices.len();
    let pieces = if closed { n } else { n.saturating_sub(1) };
    let mut out = Vec::with_capacity(pieces);
    for i in 0..pieces {
        let (Some(&(p, b)), Some(&(q, _))) = (vertices.get(i), vertices.get((i + 1) % n)) else {
            break;
        };
        let what = format!("vertex {i}");
        if (V2::from_arr(q) - V2::from_arr(p)).norm() <= tol {
            // A repeated vertex: no piece.
            continue;
        }
        let seg = if b.abs() <= FLAT_BULGE {
            Segment::line(p, q)
        } else {
            bulge_arc(p, q, b)
        };
        out.push(seg.map_err(|e| curve_error(&what, e))?);
    }
    Ok(out)
}

/// The arc from `p` to `q` of bulge `b = tan(θ/4)`, θ the included angle (counterclockwise
/// when positive).
fn bulge_arc(p: [f64; 2], q: [f64; 2], b: f64) -> curve::Result<Segment> {
    let (pv, qv) = (V2::from_arr(p), V2::from_arr(q));
    let chord = qv - pv;
    let c = chord.norm();
    // The centre lies on the chord's perpendicular bisector, at (c/4)(1/b − b) to its left
    // (chord ⊥ / c is the left unit normal); the radius is (c/4)(1/|b| + |b|). (Written so to
    // stay finite for large and small bulges alike.)
    let center = (pv + qv) * 0.5 + chord.perp() * (0.25 * (1.0 / b - b));
    let r = 0.25 * c * (1.0 / b.abs() + b.abs());
    let theta = 4.0 * b.atan();
    let start = (pv - center).angle();
    Segment::arc(center.arr(), r, start, start + theta)
}

// ---------------------------------------------------------------------------------------------
// Chaining.

/// One end of an open piece: which piece, and whether it is its end (or its start).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct End {
    piece: usize,
    at_end: bool,
}

/// A chain of open pieces in order, each taken forwards (`true`) or reversed.
type Run = VecDeque<(usize, bool)>;

/// A grid of square cells over points: their cell keys, sorted (no hashing: the work is
/// `O(n log n)` whatever the coordinates).
struct Grid {
    cell: f64,
    /// `(cell key, point index)`, sorted.
    keys: Vec<((i64, i64), usize)>,
}

impl Grid {
    fn new(cell: f64, points: &[V2]) -> Self {
        let mut g = Self {
            cell,
            keys: Vec::with_capacity(points.len()),
        };
        g.keys = points
            .iter()
            .enumerate()
            .map(|(i, &p)| (g.key(p), i))
            .collect();
        g.keys.sort_unstable();
        g
    }

    fn key(&self, p: V2) -> (i64, i64) {
        // (Saturating casts: a key is only a place to look, every match is measured.)
        (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        )
    }

    /// The points of each cell that holds more than `most`.
    fn crowded(&self, most: usize) -> Option<Vec<usize>> {
        self.keys
            .chunk_by(|a, b| a.0 == b.0)
            .find(|run| run.len() > most)
            .map(|run| run.iter().map(|&(_, i)| i).collect())
    }

    /// The points in the cells within two of `p`'s (all points within `2 · cell` of `p`).
    fn around(&self, p: V2) -> impl Iterator<Item = usize> + '_ {
        let (kx, ky) = self.key(p);
        (-2i64..=2).flat_map(move |dx| {
            let row = kx.saturating_add(dx);
            let (lo, hi) = ((row, ky.saturating_sub(2)), (row, ky.saturating_add(2)));
            let a = self.keys.partition_point(|(k, _)| *k < lo);
            let b = self.keys.partition_point(|(k, _)| *k <= hi);
            self.keys
                .get(a..b.max(a))
                .unwrap_or_default()
                .iter()
                .map(|&(_, i)| i)
        })
    }
}

/// The box `[x0, y0, x1, y1]` of the segments' control points.
fn box_of(segments: &[Segment]) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in segments.iter().flat_map(|s| s.curve().control_points()) {
        b = [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ];
    }
    b
}

fn point_text(p: V2) -> String {
    format!("({}, {})", p.x, p.y)
}

/// The chains of the drawing's pieces (see the module documentation).
fn chain_pieces(pieces: Vec<Option<Piece>>, tol: &Tolerance) -> Result<Vec<Chain>, Failure> {
    let mut chains: Vec<(usize, Chain)> = Vec::new();
    let mut open: Vec<Piece> = Vec::new();
    for p in pieces.into_iter().flatten() {
        match p.closed {
            Some(false) => open.push(p),
            closed => chains.push((
                p.order,
                Chain {
                    name: p.name,
                    segments: p.segments,
                    closed,
                    group: 0,
                    rule: FillRule::EvenOdd,
                },
            )),
        }
    }
    // End 2k is piece k's start, 2k + 1 its end.
    let points: Vec<V2> = open.iter().flat_map(|p| [p.start, p.end]).collect();
    let end = |i: usize| End {
        piece: i / 2,
        at_end: i % 2 == 1,
    };
    let name_of = |i: usize| open.get(i / 2).map_or("", |p| p.name.as_str());

    // Cells of half the tolerance: two ends in one cell are within 0.71 of it, so a third end
    // in a cell is a branch, and every cell holds at most two.
    let branch = |ids: &[usize], at: V2| -> Failure {
        let mut ids = ids.to_vec();
        ids.sort_unstable();
        let names: Vec<&str> = ids.iter().map(|&i| name_of(i)).collect();
        (
            name_of(ids.first().copied().unwrap_or(0)).to_string(),
            Problem::Geometry(format!(
                "a branch point: {} meet at {} (a profile joins two entities at each point)",
                names.join(", "),
                point_text(at)
            )),
        )
    };
    let grid = Grid::new(tol.join * 0.5, &points);
    if let Some(ids) = grid.crowded(2) {
        let at = ids.first().and_then(|&i| points.get(i)).copied();
        return Err(branch(&ids, at.unwrap_or_default()));
    }
    let mut partner: Vec<Option<usize>> = vec![None; points.len()];
    for (i, &p) in points.iter().enumerate() {
        let mut found: Vec<usize> = grid
            .around(p)
            .filter(|&j| j != i && j / 2 != i / 2)
            .filter(|&j| points.get(j).is_some_and(|&q| (q - p).norm() <= tol.join))
            .take(2)
            .collect();
        match found.len() {
            0 => {}
            1 => {
                if let (Some(slot), Some(&j)) = (partner.get_mut(i), found.first()) {
                    *slot = Some(j);
                }
            }
            _ => {
                found.push(i);
                return Err(branch(&found, p));
            }
        }
    }

    let mut used = vec![false; open.len()];
    let mut loose_chains: Vec<(usize, Run, bool)> = Vec::new();
    for start in 0..open.len() {
        if used.get(start) != Some(&false) {
            continue;
        }
        if let Some(u) = used.get_mut(start) {
            *u = true;
        }
        let mut run: Run = VecDeque::from([(start, true)]);
        let mut closed = false;
        // Forwards from the start piece's end.
        let mut tip = 2 * start + 1;
        for _ in 0..open.len() {
            let Some(j) = partner.get(tip).copied().flatten() else {
                break;
            };
            if j == 2 * start {
                closed = true;
                break;
            }
            let e = end(j);
            if used.get(e.piece) != Some(&false) {
                break;
            }
            if let Some(u) = used.get_mut(e.piece) {
                *u = true;
            }
            // Entered at its start: taken forwards, leaving at its end; else reversed.
            run.push_back((e.piece, !e.at_end));
            tip = if e.at_end {
                2 * e.piece
            } else {
                2 * e.piece + 1
            };
        }
        if !closed {
            // Backwards from the start piece's start.
            let mut tip = 2 * start;
            for _ in 0..open.len() {
                let Some(j) = partner.get(tip).copied().flatten() else {
                    break;
                };
                let e = end(j);
                if used.get(e.piece) != Some(&false) {
                    break;
                }
                if let Some(u) = used.get_mut(e.piece) {
                    *u = true;
                }
                // Met at its end: taken forwards, arriving at the chain's start; else reversed.
                run.push_front((e.piece, e.at_end));
                tip = if e.at_end {
                    2 * e.piece
                } else {
                    2 * e.piece + 1
                };
            }
        }
        loose_chains.push((start, run, closed));
    }

    // Open ends nearer than the near-miss distance: a gap. (Each chain's own size bounds it
    // too: a short open line's two ends are not a gap.)
    let mut free: Vec<(usize, V2, f64)> = Vec::new();
    for (_, run, closed) in &loose_chains {
        if *closed {
            continue;
        }
        let b = run
            .iter()
            .filter_map(|&(k, _)| open.get(k).map(|p| box_of(&p.segments)))
            .fold(
                [
                    f64::INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                ],
                |a, b| {
                    [
                        a[0].min(b[0]),
                        a[1].min(b[1]),
                        a[2].max(b[2]),
                        a[3].max(b[3]),
                    ]
                },
            );
        let size = (b[2] - b[0]).hypot(b[3] - b[1]);
        if let (Some(&(first, fwd_first)), Some(&(last, fwd_last))) = (run.front(), run.back()) {
            let start_end = if fwd_first { 2 * first } else { 2 * first + 1 };
            let last_end = if fwd_last { 2 * last + 1 } else { 2 * last };
            for i in [start_end, last_end] {
                if let Some(&p) = points.get(i) {
                    free.push((i, p, size));
                }
            }
        }
    }
    let free_points: Vec<V2> = free.iter().map(|&(_, p, _)| p).collect();
    let near = Grid::new(tol.near * 0.5, &free_points);
    for (k, &(i, p, own)) in free.iter().enumerate() {
        let other = near
            .around(p)
            .filter(|&m| m != k)
            .filter_map(|m| free.get(m))
            .find(|(_, q, other)| (*q - p).norm() <= tol.near.min(NEAR_MISS_OWN * own.min(*other)))
            .map(|&(j, q, _)| (j, q));
        if let Some((j, q)) = other {
            let (a, b) = if i < j { (i, j) } else { (j, i) };
            let (pa, pb) = if i < j { (p, q) } else { (q, p) };
            let gap = (pb - pa).norm();
            let which = |x: usize| if x % 2 == 1 { "end" } else { "start" };
            return Err((
                name_of(a).to_string(),
                Problem::Geometry(format!(
                    "a gap of {gap:e} between the {} of {} at {} and the {} of {} at {}, \
                     beyond the drawing's tolerance of {:e}: the outline does not close",
                    which(a),
                    name_of(a),
                    point_text(pa),
                    which(b),
                    name_of(b),
                    point_text(pb),
                    tol.join,
                )),
            ));
        }
    }

    // (Each piece is in one chain: its segments move there.)
    let mut parts: Vec<(usize, String, Vec<Segment>)> = open
        .into_iter()
        .map(|p| (p.order, p.name, p.segments))
        .collect();
    for (start, run, closed) in loose_chains {
        let mut segments = Vec::new();
        for (k, forwards) in run {
            let Some((_, name, piece)) = parts.get_mut(k) else {
                continue;
            };
            let piece = std::mem::take(piece);
            if forwards {
                segments.extend(piece);
            } else {
                for s in piece.iter().rev() {
                    segments.push(
                        s.reversed()
                            .map_err(|e| (name.clone(), Problem::Geometry(e.to_string())))?,
                    );
                }
            }
        }
        let Some((order, name, _)) = parts.get(start) else {
            continue;
        };
        chains.push((
            *order,
            Chain {
                name: name.clone(),
                segments,
                closed: closed.then_some(true),
                group: 0,
                rule: FillRule::EvenOdd,
            },
        ));
    }
    chains.sort_by_key(|(order, _)| *order);
    Ok(chains.into_iter().map(|(_, c)| c).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use curve::ParamCurve;
    use std::f64::consts::PI;

    fn text(groups: &[(i32, &str)]) -> String {
        groups.iter().map(|(c, v)| format!("{c}\n{v}\n")).collect()
    }

    #[test]
    fn the_tokenizer_reads_the_entities_section_only() {
        let t = text(&[
            (999, "a comment"),
            (0, "SECTION"),
            (2, "HEADER"),
            (0, "LINE"), // (not an entity: the HEADER section)
            (0, "ENDSEC"),
            (0, "SECTION"),
            (2, "ENTITIES"),
            (0, "LINE"),
            (5, "2F"),
            (0, "SPLINE"),
            (71, "3"),
            (999, "skipped"),
            (10, "1.5"),
            (0, "TEXT"),
            (0, "ENDSEC"),
            (0, "SECTION"),
            (2, "OBJECTS"),
            (0, "LINE"),
        ])
        .replace('\n', "\r\n");
        let section = entity_records(t.as_bytes()).unwrap();
        let r = &section.records;
        let kinds: Vec<&str> = r.iter().map(|r| r.kind.as_ref()).collect();
        assert_eq!(kinds, ["LINE", "SPLINE", "TEXT"]);
        assert_eq!(r[0].name(), "LINE 2F");
        assert_eq!(r[1].name(), "SPLINE #2");
        let groups: Vec<(i32, &str)> = r[1].groups.iter().map(|(c, v)| (*c, v.as_ref())).collect();
        assert_eq!(groups, [(71, "3"), (10, "1.5")]);
        assert!(r[0].groups.is_empty(), "groups are kept for splines only");
        // The section's bytes, as the crate is given them.
        let (a, b) = section.range.unwrap();
        assert!(t[a..].starts_with("0\r\nSECTION\r\n2\r\nENTITIES\r\n"));
        assert!(t[..b.unwrap()].ends_with("0\r\nTEXT\r\n0\r\nENDSEC\r\n"));
        // A code line that is not a number, and a file ending after a code: refused.
        assert!(entity_records(b"0\nSECTION\nx\nENTITIES\n").is_err());
        assert!(entity_records(b"0\nSECTION\n2").is_err());
        // A blank code line ends the file only where nothing but blank lines follows it.
        assert!(entity_records(b"0\nSECTION\n2\nENTITIES\n\n0\nLINE\n").is_err());
        assert!(entity_records(b"0\nSECTION\n2\nENTITIES\n0\nLINE\n\n \r\n\n").is_ok());
    }

    #[test]
    fn extrusion_directions() {
        assert_eq!(mirrored([0.0, 0.0, 1.0]), Ok(false));
        assert_eq!(mirrored([0.0, 0.0, -2.0]), Ok(true));
        assert_eq!(mirrored([1e-13, 0.0, -1.0]), Ok(true));
        assert_eq!(mirrored([0.0, 0.0, 0.0]), Ok(false));
        assert!(mirrored([0.0, 1e-9, 1.0]).is_err());
        assert!(mirrored([f64::NAN, 0.0, 1.0]).is_err());
    }

    #[test]
    fn sweeps_within_rounding_of_a_turn_are_full() {
        assert_eq!(full_turn(0.0), TAU);
        assert_eq!(full_turn(4e-13), TAU);
        assert_eq!(full_turn(TAU - 4e-13), TAU);
        assert_eq!(full_turn(1.0), 1.0);
        assert_eq!(full_turn(2e-9), 2e-9);
    }

    #[test]
    fn bulge_arcs() {
        // Bulge 1: the half circle from (1, 0) counterclockwise to (−1, 0), through (0, 1).
        let a = bulge_arc([1.0, 0.0], [-1.0, 0.0], 1.0).unwrap();
        let top = a.jet(0.5).p;
        assert!((top - V2::new(0.0, 1.0)).norm() < 1e-15, "{top:?}");
        // Its middle as the tolerance's box takes it, and the other sign.
        assert_eq!(bulge_middle([1.0, 0.0], [-1.0, 0.0], 1.0), [0.0, 1.0]);
        let b = bulge_arc([1.0, 0.0], [-1.0, 0.0], -1.0).unwrap();
        assert!((b.jet(0.5).p - V2::new(0.0, -1.0)).norm() < 1e-15);
        // A quarter circle (bulge tan(π/8)) from (1, 0) to (0, 1) about the origin.
        let q = bulge_arc([1.0, 0.0], [0.0, 1.0], (PI / 8.0).tan()).unwrap();
        for k in 0..=8 {
            assert!((q.jet(k as f64 / 8.0).p.norm() - 1.0).abs() < 1e-15);
        }
        // A large bulge: nearly the full circle, still through both ends.
        let big = bulge_arc([0.0, 0.0], [1e-3, 0.0], 1e6).unwrap();
        assert!((big.start() - V2::new(0.0, 0.0)).norm() < 1e-12);
        assert!((big.end() - V2::new(1e-3, 0.0)).norm() < 1e-12);
    }

    /// A piece of one segment.
    fn piece(order: usize, seg: Segment) -> Option<Piece> {
        Some(Piece {
            order,
            name: format!("LINE #{}", order + 1),
            start: seg.start(),
            end: seg.end(),
            segments: vec![seg],
            closed: Some(false),
        })
    }

    fn tol(join: f64) -> Tolerance {
        Tolerance {
            join,
            near: join * 1e5,
        }
    }

    #[test]
    fn chaining_reverses_pieces_and_closes() {
        let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
        let pieces = vec![
            piece(0, l([0.0, 0.0], [1.0, 0.0])),
            piece(1, l([0.0, 1.0], [1.0, 1.0])), // backwards
            piece(2, l([1.0, 0.0], [1.0, 1.0])),
            piece(3, l([0.0, 0.0], [0.0, 1.0])), // backwards
        ];
        let chains = chain_pieces(pieces, &tol(1e-9)).unwrap();
        assert_eq!(chains.len(), 1);
        let c = &chains[0];
        assert_eq!((c.name.as_str(), c.closed), ("LINE #1", Some(true)));
        let ends: Vec<[f64; 2]> = c.segments.iter().map(|s| s.start().arr()).collect();
        assert_eq!(ends, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        // An open chain grows at both ends of its first piece.
        let pieces = vec![
            piece(0, l([1.0, 0.0], [2.0, 0.0])),
            piece(1, l([0.0, 0.0], [1.0, 0.0])),
            piece(2, l([3.0, 0.0], [2.0, 0.0])),
        ];
        let chains = chain_pieces(pieces, &tol(1e-9)).unwrap();
        assert_eq!(chains.len(), 1);
        assert_eq!(chains[0].closed, None);
        assert_eq!(chains[0].segments[0].start().arr(), [0.0, 0.0]);
        assert_eq!(chains[0].segments[2].end().arr(), [3.0, 0.0]);
    }

    #[test]
    fn three_ends_at_a_point_are_a_branch() {
        let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
        // Three ends in one cell of the grid, and three ends in neighbouring cells.
        for eps in [0.0, 0.9e-9] {
            let pieces = vec![
                piece(0, l([0.0, 0.0], [1.0, 0.0])),
                piece(1, l([1.0 + eps, 0.0], [2.0, 0.0])),
                piece(2, l([1.0, eps], [1.0, 1.0])),
            ];
            let (field, p) = chain_pieces(pieces, &tol(1e-9)).unwrap_err();
            assert_eq!(field, "LINE #1");
            assert!(p.to_string().contains("branch"), "{p}");
        }
    }

    #[test]
    fn near_misses_are_gaps_and_far_ends_are_open() {
        let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
        let open = || {
            vec![
                piece(0, l([0.0, 0.0], [1.0, 0.0])),
                piece(1, l([1.0, 0.0], [1.0, 1.0])),
                piece(2, l([1.0, 1.0], [0.0, 1e-6])),
            ]
        };
        let (field, p) = chain_pieces(open(), &tol(1e-9)).unwrap_err();
        assert_eq!(field, "LINE #1");
        assert!(p.to_string().contains("gap of 1e-6"), "{p}");
        // With a looser near-miss distance below the gap: an open chain.
        let t = Tolerance {
            join: 1e-9,
            near: 1e-7,
        };
        let chains = chain_pieces(open(), &t).unwrap();
        assert_eq!(chains.len(), 1);
        assert_eq!(chains[0].closed, None);
    }

    #[test]
    fn the_tolerance_follows_the_drawing() {
        let item = |seg: Segment| Item {
            order: 0,
            name: String::new(),
            shape: Shape::Segment {
                segment: Box::new(seg),
                flagged: false,
            },
        };
        let items = vec![item(Segment::line([0.0, 0.0], [3.0, 4.0]).unwrap())];
        let t = Tolerance::of(&items);
        assert_eq!(t.join, 5e-9);
        assert_eq!(t.near, 5e-4);
        // Far from the origin the rounding of the coordinates rules.
        let items = vec![item(Segment::line([1e9, 0.0], [1e9 + 3.0, 4.0]).unwrap())];
        let t = Tolerance::of(&items);
        assert!(t.join > 1e-6, "{}", t.join);
    }
}
