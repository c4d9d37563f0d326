//! A curve file's JSON document checked and its kind's fields read into a [`CurveKind`].

use super::fields::{out_of_range, type_name, wrong_type, FieldError, Fields};
use super::{duplicates, profile, spline, Curve, CurveFileError, CurveKind, Problem, MAX_LOBES};
use curve::shapes::{Circle, Convexities, Ellipse, EllipticLemniscate, Limacon, Shape as Analytic};
use serde_json::{Map, Value};

/// Validates the text of a curve file; `file` names it in errors.
///
/// ```
/// use curvekit::io::{parse_curve, CurveKind};
/// let c = parse_curve("s.json", r#"{"kind":"bezier","points":[[0,0],[1,2],[2,-2],[3,0]]}"#).unwrap();
/// assert!(matches!(c.shape, CurveKind::Spline(_)) && !c.is_closed());
///
/// let e = parse_curve("c.json", r#"{"kind":"circle","r":1,"radius":2}"#).unwrap_err();
/// assert_eq!(e.field, "radius");
/// assert!(e.to_string().starts_with("c.json: radius: unknown field"));
/// ```
pub fn parse_curve(file: &str, text: &str) -> Result<Curve, CurveFileError> {
    let err = |field: &str, problem: Problem| CurveFileError {
        file: file.to_string(),
        field: field.to_string(),
        problem,
    };
    if text.trim().is_empty() {
        return Err(err("document", Problem::Json("the file is empty".into())));
    }
    let value: Value =
        serde_json::from_str(text).map_err(|e| err("document", Problem::Json(e.to_string())))?;
    let Value::Object(map) = value else {
        return Err(err(
            "document",
            Problem::WrongType {
                expected: "a JSON object",
                got: type_name(&value),
            },
        ));
    };
    if let Some(key) = duplicates::duplicate_key(text) {
        return Err(err(&key, Problem::Duplicate));
    }
    let shape = parse_shape(&map).map_err(|(field, problem)| err(&field, problem))?;
    Ok(Curve::new(file, shape))
}

pub(super) fn parse_shape(map: &Map<String, Value>) -> Result<CurveKind, FieldError> {
    let kind = match map.get("kind") {
        None => return Err(("kind".into(), Problem::Missing)),
        Some(Value::String(s)) => s.as_str(),
        Some(v) => return Err(wrong_type("kind", "a string", v)),
    };
    let allowed: &[&str] = match kind {
        "bezier" => &["points", "weights"],
        "bspline" => &["degree", "points", "weights", "knots", "periodic"],
        "circle" => &["r", "center"],
        "ellipse" => &["a", "b", "center"],
        "limacon" | "elliptic_lemniscate" => &["a", "b"],
        "convexities" => &["p", "eps", "m"],
        "line" => &["from", "to"],
        "arc" => &["center", "r", "start", "end"],
        // (`part`: which part of a multi-part input an offset loop belongs to.)
        "profile" => &["segments", "closed", "part"],
        "region" => &["outer", "holes"],
        "regions" => &["parts"],
        other => return Err(("kind".into(), Problem::UnknownKind(other.to_string()))),
    };
    // Reject unknown fields first: a typo'd optional field must not pass silently.
    reject_unknown(map, kind, allowed)?;
    let f = Fields(map);
    let analytic = match kind {
        "bezier" | "bspline" => {
            return spline::parse_spline(kind, &f).map(|s| CurveKind::Spline(Box::new(s)))
        }
        "line" | "arc" => {
            return profile::parse_segment_kind(kind, &f).map(|s| CurveKind::Segment(Box::new(s)))
        }
        "profile" => return profile::parse_profile(&f).map(|p| CurveKind::Profile(Box::new(p))),
        "region" => return profile::parse_region(&f).map(|r| CurveKind::Region(Box::new(r))),
        "regions" => return profile::parse_regions(&f),
        "circle" => {
            let center = f.opt_point("center")?.unwrap_or([0.0, 0.0]);
            Analytic::Circle(shape("r", Circle::new(f.positive("r")?, center))?)
        }
        "ellipse" => {
            let center = f.opt_point("center")?.unwrap_or([0.0, 0.0]);
            let (a, b) = (f.positive("a")?, f.positive("b")?);
            Analytic::Ellipse(shape("a", Ellipse::new(a, b, center))?)
        }
        "limacon" => {
            let a = f.number("a")?;
            let b = f.number("b")?;
            if b < 0.0 {
                return Err(out_of_range("b", ">= 0", b));
            }
            if a <= b {
                return Err(out_of_range(
                    "a",
                    "> b (a simple limaçon needs a > b >= 0)",
                    a,
                ));
            }
            Analytic::Limacon(shape("a", Limacon::new(a, b))?)
        }
        "elliptic_lemniscate" => {
            let (a, b) = (f.positive("a")?, f.positive("b")?);
            Analytic::EllipticLemniscate(shape("a", EllipticLemniscate::new(a, b))?)
        }
        _ => {
            let p = f.positive("p")?;
            let eps = f.number("eps")?;
            if !(eps > 0.0 && eps < 1.0) {
                return Err(out_of_range("eps", "in (0, 1)", eps));
            }
            let m = f.integer("m", 2, u64::from(MAX_LOBES))?;
            let m = u32::try_from(m).unwrap_or(MAX_LOBES);
            Analytic::Convexities(shape("p", Convexities::new(p, eps, m))?)
        }
    };
    Ok(CurveKind::Analytic(analytic))
}

/// The first field of `map` besides `kind` that `kind` does not have, as an error naming it.
pub(super) fn reject_unknown(
    map: &Map<String, Value>,
    kind: &str,
    allowed: &[&str],
) -> Result<(), FieldError> {
    match map
        .keys()
        .find(|k| k.as_str() != "kind" && !allowed.contains(&k.as_str()))
    {
        Some(key) => Err((
            key.clone(),
            Problem::UnknownField {
                kind: kind.to_string(),
                allowed: allowed.join(", "),
            },
        )),
        None => Ok(()),
    }
}

/// A shape the reader validated already: a refusal by the curve model (not expected) names its
/// field, or `default` where it names none.
pub(super) fn shape<T>(default: &str, made: curve::Result<T>) -> Result<T, FieldError> {
    made.map_err(|e| match e {
        curve::Error::InvalidShape { field, value, why } => (
            field.to_string(),
            Problem::OutOfRange {
                rule: why.to_string(),
                value,
            },
        ),
        curve::Error::Spline(e) => (default.to_string(), Problem::Spline(e)),
        e => (default.to_string(), Problem::Geometry(e.to_string())),
    })
}
