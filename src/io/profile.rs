//! The kinds profiles are made of in curve files: `line` and `arc` (also curves on their own),
//! and `profile`, a chain of segments (see `docs/interfaces.md`, "Profiles, regions and
//! drawing files").

use super::{spline, wrong_type, FieldError, Fields, Problem};
use curve::{ParamCurve, Profile, Region, Segment, SegmentKind};
use serde_json::Value;

/// Most segments a profile may have: keeps every command's work (quadratic in the pieces for
/// `antipodal`) bounded; a part outline of a DXF drawing has hundreds.
pub const MAX_SEGMENTS: usize = 10_000;

/// A `line` or `arc` object (unknown fields were already rejected).
pub(super) fn parse_segment_kind(kind: &str, f: &Fields<'_>) -> Result<Segment, FieldError> {
    let made = if kind == "line" {
        let (from, to) = (point(f, "from")?, point(f, "to")?);
        Segment::line(from, to)
    } else {
        let center = point(f, "center")?;
        let r = f.positive("r")?;
        let (start, end) = (f.number("start")?, f.number("end")?);
        Segment::arc(center, r, start, end)
    };
    super::shape("kind", made)
}

/// A count of a profile's `pieces` (its segments, a polyline's vertices) within
/// [`MAX_SEGMENTS`], or the problem it is.
pub(crate) fn at_most_max_segments(count: usize, pieces: &str) -> Result<(), Problem> {
    if count > MAX_SEGMENTS {
        return Err(Problem::OutOfRange {
            rule: format!("at most {MAX_SEGMENTS} {pieces}"),
            value: count as f64,
        });
    }
    Ok(())
}

/// A `profile` object (unknown fields were already rejected).
pub(super) fn parse_profile(f: &Fields<'_>) -> Result<Profile, FieldError> {
    let items = match f.require("segments")? {
        Value::Array(items) => items,
        v => return Err(wrong_type("segments", "an array of segment objects", v)),
    };
    at_most_max_segments(items.len(), "segments").map_err(|p| ("segments".into(), p))?;
    let closed = f.opt_bool("closed")?;
    let segments = items
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let at = |(field, problem): FieldError| (format!("segments[{i}].{field}"), problem);
            match v {
                Value::Object(map) => parse_segment(&Fields(map)).map_err(at),
                v => Err(wrong_type(&format!("segments[{i}]"), "a segment object", v)),
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    Profile::new(segments, closed).map_err(|e| {
        let field = match segment_at_fault(&e) {
            Some(segment) => format!("segments[{segment}]"),
            None => "segments".to_string(),
        };
        (field, Problem::Geometry(e.to_string()))
    })
}

/// The segment a profile was refused for (the later of two that cross), where the refusal
/// names one.
pub(crate) fn segment_at_fault(e: &curve::Error) -> Option<usize> {
    match *e {
        curve::Error::Gap { segment, .. }
        | curve::Error::ZeroLength { segment }
        | curve::Error::Cusp { segment, .. }
        | curve::Error::SelfCrossing {
            second: segment, ..
        } => Some(segment),
        _ => None,
    }
}

/// One segment object of a profile: a `line`, `arc`, `bezier` or open `bspline`.
fn parse_segment(f: &Fields<'_>) -> Result<Segment, FieldError> {
    let kind = match f.require("kind")? {
        Value::String(s) => s.as_str(),
        v => return Err(wrong_type("kind", "a string", v)),
    };
    let allowed: &[&str] = match kind {
        "line" => &["from", "to"],
        "arc" => &["center", "r", "start", "end"],
        "bezier" => &["points", "weights"],
        "bspline" => &["degree", "points", "weights", "knots"],
        other => {
            return Err((
                "kind".into(),
                Problem::Unsupported(format!(
                    "a profile's segments are line, arc, bezier or bspline (open), got `{other}`"
                )),
            ))
        }
    };
    super::reject_unknown(f.0, kind, allowed)?;
    match kind {
        "line" | "arc" => parse_segment_kind(kind, f),
        _ => {
            let s = spline::parse_spline(kind, f)?;
            let kind = match kind {
                "bezier" => SegmentKind::Bezier,
                _ => SegmentKind::BSpline,
            };
            Segment::spline(kind, s.plane)
                .map_err(|e| ("kind".to_string(), Problem::Geometry(e.to_string())))
        }
    }
}

fn point(f: &Fields<'_>, key: &str) -> Result<[f64; 2], FieldError> {
    f.opt_point(key)?
        .ok_or_else(|| (key.to_string(), Problem::Missing))
}

/// Most holes a region may have (each is a boundary the commands visit).
pub const MAX_HOLES: usize = 10_000;

/// A `region` object (unknown fields were already rejected): `outer` and `holes`, each a
/// closed `profile`, a closed `bezier` or `bspline`, a `circle` or a full-turn `arc`.
pub(super) fn parse_region(f: &Fields<'_>) -> Result<Region, FieldError> {
    let outer = boundary("outer", f.require("outer")?)?;
    let holes = match f.get("holes") {
        None => Vec::new(),
        Some(Value::Array(items)) if items.len() <= MAX_HOLES => items
            .iter()
            .enumerate()
            .map(|(i, v)| boundary(&format!("holes[{i}]"), v))
            .collect::<Result<Vec<_>, _>>()?,
        Some(Value::Array(items)) => {
            return Err((
                "holes".into(),
                Problem::OutOfRange {
                    rule: format!("at most {MAX_HOLES} holes"),
                    value: items.len() as f64,
                },
            ))
        }
        Some(v) => return Err(wrong_type("holes", "an array of closed curves", v)),
    };
    Region::new(outer, holes).map_err(|e| {
        let name = |b: usize| match b {
            0 => "outer".to_string(),
            b => format!("holes[{}]", b - 1),
        };
        let field = match e {
            curve::Error::OpenBoundary { boundary } => name(boundary),
            curve::Error::BoundariesCross { second, .. } => name(second),
            curve::Error::HoleOutside { hole } | curve::Error::HoleInHole { hole, .. } => {
                format!("holes[{hole}]")
            }
            _ => "outer".to_string(),
        };
        (field, Problem::Geometry(e.to_string()))
    })
}

/// Most parts a `regions` document may have (each a region the commands visit).
pub const MAX_PARTS: usize = 10_000;

/// A `regions` object (unknown fields were already rejected): `parts`, each a `region` (or a
/// closed curve), disjoint (a part may lie in another's hole). One part is a region.
pub(super) fn parse_regions(f: &Fields<'_>) -> Result<super::CurveKind, FieldError> {
    let items = match f.require("parts")? {
        Value::Array(items) if !items.is_empty() && items.len() <= MAX_PARTS => items,
        Value::Array(items) => {
            return Err((
                "parts".into(),
                Problem::OutOfRange {
                    rule: format!("1 to {MAX_PARTS} parts"),
                    value: items.len() as f64,
                },
            ))
        }
        v => return Err(wrong_type("parts", "an array of regions", v)),
    };
    let mut parts = Vec::with_capacity(items.len());
    for (k, v) in items.iter().enumerate() {
        let key = format!("parts[{k}]");
        let at = |(field, problem): FieldError| (format!("{key}.{field}"), problem);
        let Value::Object(map) = v else {
            return Err(wrong_type(&key, "a region object", v));
        };
        let region = match super::parse_shape(map).map_err(at)? {
            super::CurveKind::Region(r) => *r,
            shape => {
                let outer = boundary_of(&key, shape)?;
                Region::new(outer, Vec::new())
                    .map_err(|e| (key.clone(), Problem::Geometry(e.to_string())))?
            }
        };
        parts.push(region);
    }
    disjoint(&parts)?;
    Ok(match parts.len() {
        1 => super::CurveKind::Region(Box::new(parts.swap_remove(0))),
        _ => super::CurveKind::Regions(parts),
    })
}

/// Checks that parts are disjoint: their boundaries, nested even-odd, give back the parts.
fn disjoint(parts: &[Region]) -> Result<(), FieldError> {
    let mut owner = Vec::new();
    let outlines: Vec<curve::FilledOutline> = parts
        .iter()
        .enumerate()
        .flat_map(|(k, r)| {
            std::iter::once(r.outer())
                .chain(r.holes())
                .map(move |b| (k, b.clone()))
        })
        .map(|(k, profile)| {
            owner.push(k);
            curve::FilledOutline {
                profile,
                group: 0,
                rule: curve::FillRule::EvenOdd,
            }
        })
        .collect();
    let nested = Region::filled(outlines).map_err(|e| {
        let named = match e {
            curve::Error::OutlinesCross { first, second, at } => format!(
                "parts {} and {} meet at ({}, {})",
                owner[first], owner[second], at[0], at[1]
            ),
            e => e.to_string(),
        };
        ("parts".to_string(), Problem::Geometry(named))
    })?;
    let holes = |rs: &[Region]| rs.iter().map(|r| r.holes().len()).sum::<usize>();
    if nested.len() != parts.len() || holes(&nested) != holes(parts) {
        return Err((
            "parts".into(),
            Problem::Geometry(
                "the parts overlap: a part lies inside another (outside its holes)".into(),
            ),
        ));
    }
    Ok(())
}

/// One boundary of a region, as a closed profile; `key` names it in errors.
fn boundary(key: &str, v: &Value) -> Result<Profile, FieldError> {
    let at = |(field, problem): FieldError| (format!("{key}.{field}"), problem);
    let Value::Object(map) = v else {
        return Err(wrong_type(key, "a closed curve object", v));
    };
    let shape = super::parse_shape(map).map_err(at)?;
    boundary_of(key, shape)
}

/// A closed curve of any kind as one boundary of a region: a closed profile as it is; any
/// other closed curve as the profile of one segment whose parameter is the curve's own
/// ([`curve::Profile::of_curve`]: a spline's knots, `[0, 2π)` for the analytic shapes), cut at
/// its corners (a degree-1 spline, knots of full multiplicity, a clamped spline closed by its
/// points with a corner there). `key` names it in errors.
pub(super) fn boundary_of(key: &str, shape: super::CurveKind) -> Result<Profile, FieldError> {
    let not_closed = || {
        (
            key.to_string(),
            Problem::Geometry("a region's boundaries are closed curves".into()),
        )
    };
    let profile = match shape {
        super::CurveKind::Profile(p) => *p,
        super::CurveKind::Region(_) | super::CurveKind::Regions(_) => return Err(not_closed()),
        shape => match curve_profile(&shape) {
            Some(made) => made.map_err(|(field, problem)| (format!("{key}.{field}"), problem))?,
            None => return Err(not_closed()),
        },
    };
    if !profile.is_closed() {
        return Err(not_closed());
    }
    Ok(profile)
}

/// A curve that is not a profile (a spline, an analytic shape, a line or an arc) as the
/// profile of one segment in the curve's own parameter, cut at its corners; `None` for a
/// profile or a region. A periodic spline is taken clamped over its domain (the same curve).
pub(crate) fn curve_profile(shape: &super::CurveKind) -> Option<Result<Profile, FieldError>> {
    let geometry =
        |field: &str, e: curve::Error| (field.to_string(), Problem::Geometry(e.to_string()));
    let made = match shape {
        super::CurveKind::Profile(_)
        | super::CurveKind::Region(_)
        | super::CurveKind::Regions(_) => return None,
        super::CurveKind::Segment(s) => {
            let s = s.as_ref().clone();
            let domain = s.own_domain();
            Profile::of_curve(s, domain).map_err(|e| geometry("kind", e))
        }
        super::CurveKind::Spline(s) => {
            let (a, b) = s.curve.domain();
            let kind = match s.kind {
                super::SplineKind::Bezier => SegmentKind::Bezier,
                super::SplineKind::BSpline => SegmentKind::BSpline,
            };
            let segment = if s.periodic {
                Segment::periodic_spline(kind, &s.plane)
            } else {
                Segment::spline(kind, s.plane.clone())
            };
            segment
                .and_then(|seg| Profile::of_curve(seg, (a, b)))
                .map_err(|e| geometry("points", e))
        }
        super::CurveKind::Analytic(a) => Segment::of_shape(*a)
            .and_then(|seg| Profile::of_curve(seg, (0.0, std::f64::consts::TAU)))
            .map_err(|e| geometry("kind", e)),
    };
    Some(made)
}
