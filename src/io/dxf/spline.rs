//! `SPLINE` entities, read from their group codes as written (the `dxf` crate drops the
//! control points of a spline written without z groups).

use super::entities::{curve_error, geometry, number, plane, unlevel, EntityError, Plane};
use crate::io::{Problem, MAX_DEGREE};
use bspline::{BSpline, Rational};
use curve::{Segment, SegmentKind, SplineCurve};
use std::borrow::Cow;

/// Most control points (or knots) of one `SPLINE`: the knot insertion that clamps a spline,
/// and every command after it, work on each point; part outlines use tens.
pub(super) const MAX_SPLINE_POINTS: usize = 10_000;

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

/// A `SPLINE` read.
#[derive(Debug)]
pub(super) enum Spline {
    /// Its segment, and whether it is flagged closed or periodic (70 bits 1, 2).
    Read {
        segment: Box<Segment>,
        flagged: bool,
    },
    /// Not in the drawing's plane (or one parallel to it): why, after its name.
    Off(String),
}

/// A `SPLINE` from its groups as written (see the module documentation).
///
/// The curve's derivatives are checked as a `bspline` curve file's are: knots packed far too
/// tightly for the coordinates overflow them, and nothing after could be trusted.
pub(super) fn spline(groups: &[(i32, Cow<'_, str>)]) -> Result<Spline, EntityError> {
    let mut flags = 0i64;
    let mut degree = None;
    let mut knots = Vec::new();
    let mut weights = Vec::new();
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut has_y = Vec::new();
    // The control points' heights (30), where written.
    let mut heights = Vec::new();
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
            // (One per control point at most: the bound on points bounds them.)
            30 if heights.len() < points.len() => heights.push(float("control points")?),
            11 => fit_points += 1,
            210 => normal[0] = float("extrusion")?,
            220 => normal[1] = float("extrusion")?,
            230 => normal[2] = float("extrusion")?,
            _ => {}
        }
    }
    // (World coordinates: a planar spline's normal only says which plane it lies in.)
    if let Plane::Off(why) = plane(normal)? {
        return Ok(Spline::Off(why));
    }
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
    let (lo, hi) = points.iter().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    );
    if let Some((lo, hi)) = unlevel(&heights, (hi[0] - lo[0]).hypot(hi[1] - lo[1]))? {
        return Ok(Spline::Off(format!(
            "has control points off the drawing's plane (z from {lo} to {hi})"
        )));
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
    Ok(Spline::Read {
        segment: Box::new(seg),
        flagged: flags & 3 != 0,
    })
}
