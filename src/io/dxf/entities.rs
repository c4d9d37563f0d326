//! Entities → shapes: each read entity's geometry in world coordinates (see the module
//! documentation for what each type means).

use super::spline::spline;
use super::text::Record;
use crate::io::{Problem, MAX_ABS, MAX_SEGMENTS};
use curve::{Affine, Segment};
use dxf::entities::{Entity, EntityType};
use std::f64::consts::TAU;

/// How far from (0, 0, ±1) an extrusion direction may be (each of its x and y relative to its
/// length): the rounding of a unit vector written with 15 or more digits, no tilt.
const PLAN_NORMAL: f64 = 1e-12;

/// How near (radians) a sweep may come to nothing or to a full turn and be a full turn: writers
/// round angles (the `dxf` crate's writer to 12 decimals, putting 2π at 6.28318530718, past
/// it by 4e-13), so an arc or ellipse from 0 to 2π may come out a sliver or a turn short. An
/// arc of a billionth of a radian is not drawn on purpose.
pub(super) const ANGLE_ROUNDING: f64 = 1e-9;

/// The mirror `x ↦ −x`: the object coordinate system of extrusion direction (0, 0, −1).
pub(super) const MIRROR: Affine = Affine([-1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);

// Entities → shapes.

/// An entity's geometry, before the drawing's tolerance is known.
#[derive(Debug)]
pub(super) enum Shape {
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
pub(super) struct Item {
    pub(super) order: usize,
    pub(super) name: String,
    pub(super) shape: Shape,
}

/// The error of a field of the entity being read: (what, problem); `what` is empty for the
/// entity as a whole.
pub(super) type EntityError = (String, Problem);

pub(super) fn geometry(what: &str, message: impl Into<String>) -> EntityError {
    (what.to_string(), Problem::Geometry(message.into()))
}

/// A number read from the file: finite and at most [`MAX_ABS`].
pub(super) fn number(what: &str, x: f64) -> Result<f64, EntityError> {
    if x.is_finite() && x.abs() <= MAX_ABS {
        Ok(x)
    } else {
        Err((what.to_string(), Problem::TooLarge(x)))
    }
}

pub(super) fn point(what: &str, x: f64, y: f64) -> Result<[f64; 2], EntityError> {
    Ok([number(what, x)?, number(what, y)?])
}

pub(super) fn positive(what: &str, x: f64) -> Result<f64, EntityError> {
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
pub(super) fn curve_error(what: &str, e: curve::Error) -> EntityError {
    match e {
        curve::Error::Spline(e) => (what.to_string(), Problem::Spline(e)),
        e => geometry(what, e.to_string()),
    }
}

/// Whether an entity with extrusion direction `n` lies in the drawing's plane mirrored
/// (`n = (0, 0, −1)`) or not (`(0, 0, 1)`); any other direction is refused.
pub(super) fn mirrored(n: [f64; 3]) -> Result<bool, EntityError> {
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
pub(super) fn placed(seg: Segment, mirror: bool) -> Result<Segment, EntityError> {
    if mirror {
        seg.transformed(&MIRROR).map_err(|e| curve_error("", e))
    } else {
        Ok(seg)
    }
}

/// The shape of one entity, or `None` for one that holds no curve (a zero-length line is
/// decided later, a mesh here).
pub(super) fn shape_of(entity: &Entity, record: &Record<'_>) -> Result<Option<Shape>, EntityError> {
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

/// A counterclockwise sweep in `[0, 2π)` (radians), or the full turn where it is within
/// [`ANGLE_ROUNDING`] of nothing or of a full turn.
pub(super) fn full_turn(sweep: f64) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
