//! Entities → shapes: each read entity's geometry in its block's coordinates (the world's,
//! for an entity of the ENTITIES section), or why it is not read (see the module
//! documentation for what each type means).

use super::spline::{spline, Spline};
use super::text::Record;
use crate::io::{Problem, MAX_ABS};
use curve::{Affine, Segment, JOIN_GAP};
use dxf::entities::{Entity, EntityType};
use numeric::rounding::ulps;
use std::f64::consts::TAU;

/// How far from (0, 0, ±1) an extrusion direction may be (each of its x and y relative to its
/// length): the rounding of a unit vector written with 15 or more digits, no tilt.
const PLAN_NORMAL: f64 = 1e-12;

/// How far the heights (z) of an entity's points may spread, relative to its size in the
/// plane, for it to lie in one plane parallel to the drawing: the drawing's join tolerance
/// ([`JOIN_GAP`]); heights that differ less than joined ends may are one height.
const LEVEL: f64 = JOIN_GAP;

/// How near (radians) a sweep may come to nothing or to a full turn and be a full turn: writers
/// round angles (the `dxf` crate's writer to 12 decimals, putting 2π at 6.28318530718, past
/// it by 4e-13), so an arc or ellipse from 0 to 2π may come out a sliver or a turn short. An
/// arc of a billionth of a radian is not drawn on purpose.
pub(super) const ANGLE_ROUNDING: f64 = 1e-9;

/// The mirror `x ↦ −x`: the object coordinate system of extrusion direction (0, 0, −1).
pub(super) const MIRROR: Affine = Affine([-1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);

/// An entity's geometry, before the drawing's tolerance is known.
#[derive(Debug)]
pub(super) enum EntityShape {
    /// One segment: open (joined to others) or closed (a profile by itself); `flagged`: a
    /// spline flagged closed or periodic, which must end where it starts.
    Segment {
        segment: Box<Segment>,
        flagged: bool,
    },
    /// A polyline's vertices `(point, bulge)` in its object coordinates, the map from them to
    /// the world's (the mirror of extrusion (0, 0, −1), block references' transforms), and
    /// whether it is closed.
    Polyline {
        vertices: Vec<([f64; 2], f64)>,
        map: Affine,
        closed: bool,
    },
}

impl EntityShape {
    /// The shape moved by `map` (a block reference's transform), its points checked to stay
    /// finite and at most [`MAX_ABS`].
    pub(super) fn moved(self, map: &Affine) -> Result<EntityShape, EntityError> {
        if *map == Affine::IDENTITY {
            return Ok(self);
        }
        Ok(match self {
            EntityShape::Segment { segment, flagged } => {
                let segment = segment.transformed(map).map_err(|e| curve_error("", e))?;
                for p in segment.curve().control_points() {
                    number("", p[0])?;
                    number("", p[1])?;
                }
                EntityShape::Segment {
                    segment: Box::new(segment),
                    flagged,
                }
            }
            EntityShape::Polyline {
                vertices,
                map: ocs,
                closed,
            } => {
                let map = map.after(&ocs);
                for &(p, _) in &vertices {
                    let [x, y] = map.apply(p);
                    number("", x)?;
                    number("", y)?;
                }
                EntityShape::Polyline {
                    vertices,
                    map,
                    closed,
                }
            }
        })
    }

    /// How many points it holds (vertices, control points): the work of placing it.
    pub(super) fn points(&self) -> usize {
        match self {
            EntityShape::Segment { segment, .. } => segment.curve().control_points().len(),
            EntityShape::Polyline { vertices, .. } => vertices.len(),
        }
    }
}

/// What reading an entity gives.
#[derive(Debug)]
pub(super) enum Outcome {
    /// Its shape.
    EntityShape(EntityShape),
    /// Nothing drawn: a line of no length, a polyline of one vertex.
    Nothing,
    /// Not read: `outline` if it could be part of an outline, and why (after its name: `is a
    /// polygon mesh`).
    Skip { outline: bool, why: String },
}

/// An entity read: its place among the entities, its name and its shape.
#[derive(Debug)]
pub(super) struct Item {
    pub(super) order: usize,
    pub(super) name: String,
    pub(super) shape: EntityShape,
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

/// Where an extrusion direction puts an entity.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Plane {
    /// In the drawing's plane, its object coordinates the world's (0, 0, 1) or mirrored in x
    /// (0, 0, −1).
    Level { mirrored: bool },
    /// Out of it: why, after the entity's name.
    Off(String),
}

/// Where an entity with extrusion direction `n` lies (a zero vector is taken for the
/// default, as an absent one); a direction that is not finite is refused.
pub(super) fn plane(n: [f64; 3]) -> Result<Plane, EntityError> {
    let len = n[0].hypot(n[1]).hypot(n[2]);
    if !len.is_finite() {
        return Err(geometry(
            "extrusion",
            "the extrusion direction is not finite",
        ));
    }
    if len == 0.0 || (n[0].abs() <= PLAN_NORMAL * len && n[1].abs() <= PLAN_NORMAL * len) {
        return Ok(Plane::Level {
            mirrored: n[2] < 0.0,
        });
    }
    Ok(Plane::Off(format!(
        "has extrusion direction ({}, {}, {}): it is not in the drawing's plane (only \
         (0, 0, 1) and (0, 0, -1) are read)",
        n[0], n[1], n[2]
    )))
}

/// Where heights `z` that should be one (an entity of size `size` in the plane) spread
/// farther than [`LEVEL`] allows: their lowest and highest; `None` when level.
pub(super) fn unlevel(z: &[f64], size: f64) -> Result<Option<(f64, f64)>, EntityError> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &h in z {
        number("z", h)?;
        lo = lo.min(h);
        hi = hi.max(h);
    }
    // (And the rounding of the heights themselves, far from z = 0.)
    let magnitude = lo.abs().max(hi.abs());
    let allowed = LEVEL * size + ulps(16.0) * magnitude;
    Ok((hi - lo > allowed).then_some((lo, hi)))
}

/// The side of the box of `points`: their size in the plane.
fn extent(points: impl Iterator<Item = [f64; 2]>) -> f64 {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in points {
        b = [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ];
    }
    (b[2] - b[0]).hypot(b[3] - b[1])
}

/// The segment moved into world coordinates (mirrored in x) when `mirror`.
fn placed(seg: Segment, mirror: bool) -> Result<Segment, EntityError> {
    if mirror {
        seg.transformed(&MIRROR).map_err(|e| curve_error("", e))
    } else {
        Ok(seg)
    }
}

fn segment(segment: Segment) -> Outcome {
    Outcome::EntityShape(EntityShape::Segment {
        segment: Box::new(segment),
        flagged: false,
    })
}

/// A curve of the entity's type that is not in the drawing's plane.
fn off(why: String) -> Outcome {
    Outcome::Skip { outline: true, why }
}

/// Whether an entity of extrusion direction `$normal` is mirrored in x (its object
/// coordinates the world's, or mirrored); an entity out of the drawing's plane is skipped:
/// the function returns its outcome.
macro_rules! level_or_skip {
    ($normal:expr) => {
        match plane($normal)? {
            Plane::Level { mirrored } => mirrored,
            Plane::Off(why) => return Ok(off(why)),
        }
    };
}

/// The shape of one entity (a zero-length line is decided later), or why it is not read.
pub(super) fn shape_of(entity: &Entity, record: &Record<'_>) -> Result<Outcome, EntityError> {
    let vec3 = |v: &dxf::Vector| [v.x, v.y, v.z];
    Ok(match &entity.specific {
        EntityType::Line(l) => {
            // (World coordinates: the extrusion direction only orients a thickness.)
            let from = point("start", l.p1.x, l.p1.y)?;
            let to = point("end", l.p2.x, l.p2.y)?;
            if let Some((lo, hi)) = unlevel(&[l.p1.z, l.p2.z], extent([from, to].into_iter()))? {
                return Ok(off(format!(
                    "runs off the drawing's plane (z from {lo} to {hi})"
                )));
            }
            if from == to {
                return Ok(Outcome::Nothing);
            }
            segment(Segment::line(from, to).map_err(|e| curve_error("", e))?)
        }
        EntityType::Arc(a) => {
            let mirrored = level_or_skip!(vec3(&a.normal));
            let center = point("center", a.center.x, a.center.y)?;
            let r = positive("radius", a.radius)?;
            let start = number("start angle", a.start_angle)?.rem_euclid(360.0);
            let end = number("end angle", a.end_angle)?;
            // Counterclockwise from start to end; equal angles are a full turn.
            let sweep = full_turn((end - a.start_angle).rem_euclid(360.0).to_radians());
            let start = start.to_radians();
            let seg =
                Segment::arc(center, r, start, start + sweep).map_err(|e| curve_error("", e))?;
            segment(placed(seg, mirrored)?)
        }
        EntityType::Circle(c) => {
            let mirrored = level_or_skip!(vec3(&c.normal));
            let center = point("center", c.center.x, c.center.y)?;
            let r = positive("radius", c.radius)?;
            let seg = Segment::arc(center, r, 0.0, TAU).map_err(|e| curve_error("", e))?;
            segment(placed(seg, mirrored)?)
        }
        EntityType::Ellipse(e) => ellipse(e)?,
        EntityType::LwPolyline(p) => {
            let mirrored = level_or_skip!(vec3(&p.extrusion_direction));
            let vertices = p
                .vertices
                .iter()
                .enumerate()
                .map(|(i, v)| vertex(i, v.x, v.y, v.bulge))
                .collect::<Result<Vec<_>, _>>()?;
            polyline(vertices, mirrored, p.flags & 1 != 0)?
        }
        EntityType::Polyline(p) => {
            // Meshes (16: polygon mesh, 64: polyface mesh) are surfaces, not curves.
            if p.flags & (16 | 64) != 0 {
                return Ok(Outcome::Skip {
                    outline: false,
                    why: "is a polygon or polyface mesh (a surface)".into(),
                });
            }
            // A 3D polyline (8) is in world coordinates, without bulges.
            let three_d = p.flags & 8 != 0;
            let mirrored = match three_d {
                true => false,
                false => level_or_skip!(vec3(&p.normal)),
            };
            // Spline-frame control vertices (16) are not on the curve drawn.
            let drawn = || p.vertices().filter(|v| v.flags & 16 == 0);
            let vertices = drawn()
                .enumerate()
                .map(|(i, v)| {
                    let bulge = if three_d { 0.0 } else { v.bulge };
                    vertex(i, v.location.x, v.location.y, bulge)
                })
                .collect::<Result<Vec<_>, _>>()?;
            if three_d {
                let z: Vec<f64> = drawn().map(|v| v.location.z).collect();
                let size = extent(vertices.iter().map(|&(p, _)| p));
                if let Some((lo, hi)) = unlevel(&z, size)? {
                    return Ok(off(format!(
                        "is a 3D polyline off the drawing's plane (z from {lo} to {hi})"
                    )));
                }
            }
            polyline(vertices, mirrored, p.flags & 1 != 0)?
        }
        EntityType::Spline(_) => match spline(&record.groups)? {
            Spline::Read { segment, flagged } => {
                Outcome::EntityShape(EntityShape::Segment { segment, flagged })
            }
            Spline::Off(why) => off(why),
        },
        // (Only the types read are given here.)
        _ => Outcome::Nothing,
    })
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
) -> Result<Outcome, EntityError> {
    crate::io::profile::at_most_max_segments(vertices.len(), "vertices")
        .map_err(|p| ("vertices".into(), p))?;
    if vertices.len() < 2 {
        // (A single vertex is a point: nothing drawn.)
        return Ok(Outcome::Nothing);
    }
    let map = if mirrored { MIRROR } else { Affine::IDENTITY };
    Ok(Outcome::EntityShape(EntityShape::Polyline {
        vertices,
        map,
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

/// An `ELLIPSE` in world coordinates, or why it is not read.
fn ellipse(e: &dxf::entities::Ellipse) -> Result<Outcome, EntityError> {
    let flip = level_or_skip!([e.normal.x, e.normal.y, e.normal.z]);
    let center = point("center", e.center.x, e.center.y)?;
    let axis = point("major axis", e.major_axis.x, e.major_axis.y)?;
    let rx = axis[0].hypot(axis[1]);
    if rx == 0.0 {
        return Err(geometry("major axis", "the major axis has zero length"));
    }
    // (The major axis lies in the plane of the extrusion direction: a z of its own tilts it.)
    let z = number("major axis", e.major_axis.z)?;
    if z.abs() > PLAN_NORMAL * rx.hypot(z) {
        return Ok(off(format!(
            "has a major axis out of the drawing's plane (z = {z})"
        )));
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
    let seg =
        Segment::elliptic_arc(center, rx, ry, rotation, a, b).map_err(|e| curve_error("", e))?;
    Ok(segment(seg))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extrusion_directions() {
        let level = |mirrored| Ok(Plane::Level { mirrored });
        assert_eq!(plane([0.0, 0.0, 1.0]), level(false));
        assert_eq!(plane([0.0, 0.0, -2.0]), level(true));
        assert_eq!(plane([1e-13, 0.0, -1.0]), level(true));
        assert_eq!(plane([0.0, 0.0, 0.0]), level(false));
        assert!(matches!(plane([0.0, 1e-9, 1.0]), Ok(Plane::Off(_))));
        assert!(plane([f64::NAN, 0.0, 1.0]).is_err());
    }

    #[test]
    fn heights_spread_within_the_join_tolerance_are_level() {
        assert_eq!(unlevel(&[5.0, 5.0, 5.0], 10.0), Ok(None));
        assert_eq!(unlevel(&[0.0, 5e-9], 10.0), Ok(None));
        assert_eq!(unlevel(&[0.0, 2e-8, 1e-8], 10.0), Ok(Some((0.0, 2e-8))));
        assert_eq!(unlevel(&[], 10.0), Ok(None));
        assert!(unlevel(&[f64::NAN], 1.0).is_err());
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
