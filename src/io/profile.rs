//! The kinds profiles are made of in curve files: `line` and `arc` (also curves on their own),
//! and `profile`, a chain of segments (see `docs/interfaces.md`, "Profiles, regions and
//! drawing files").

use super::{spline, wrong_type, FieldError, Fields, Problem};
use curve::{Profile, Segment, SegmentKind};
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
    made.map_err(|e| match e {
        curve::Error::InvalidShape { field, value, why } => (
            field.to_string(),
            Problem::OutOfRange {
                rule: why.to_string(),
                value,
            },
        ),
        e => ("kind".to_string(), Problem::Geometry(e.to_string())),
    })
}

/// A `profile` object (unknown fields were already rejected).
pub(super) fn parse_profile(f: &Fields<'_>) -> Result<Profile, FieldError> {
    let items = match f.require("segments")? {
        Value::Array(items) => items,
        v => return Err(wrong_type("segments", "an array of segment objects", v)),
    };
    if items.len() > MAX_SEGMENTS {
        return Err((
            "segments".into(),
            Problem::OutOfRange {
                rule: format!("at most {MAX_SEGMENTS} segments"),
                value: items.len() as f64,
            },
        ));
    }
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
        let field = match e {
            curve::Error::Gap { segment, .. }
            | curve::Error::ZeroLength { segment }
            | curve::Error::Cusp { segment, .. }
            | curve::Error::SelfCrossing {
                second: segment, ..
            } => format!("segments[{segment}]"),
            _ => "segments".to_string(),
        };
        (field, Problem::Geometry(e.to_string()))
    })
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
    if let Some(key) =
        f.0.keys()
            .find(|k| k.as_str() != "kind" && !allowed.contains(&k.as_str()))
    {
        return Err((
            key.clone(),
            Problem::UnknownField {
                kind: kind.to_string(),
                allowed: allowed.join(", "),
            },
        ));
    }
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
