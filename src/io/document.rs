//! Profiles and regions written back as the contract's documents (what a drawing was read as,
//! for Python's `to_dict()` and for tools that take JSON): lines, circular arcs, Bézier curves
//! and B-splines as their own kinds; an elliptic arc (known only by its exact form) as the
//! rational B-spline it is. Read back, the document is the same curve; an elliptic arc's
//! parameter becomes its spline's.

use super::CurveKind;
use curve::{OwnParam, ParamCurve, Profile, Region, Segment, SegmentKind};
use geometry::Flatten;
use serde_json::{json, Value};

/// The document of a shape read from a drawing (a profile, a region, several regions, a line
/// or an arc); `None` for the shapes only a curve file gives (a spline, an analytic shape),
/// whose document is that file's.
pub fn shape_document(shape: &CurveKind) -> Option<Value> {
    match shape {
        CurveKind::Segment(s) => Some(segment_document(s)),
        CurveKind::Profile(p) => Some(profile_document(p)),
        CurveKind::Region(r) => Some(region_document(r)),
        CurveKind::Regions(parts) => Some(json!({
            "kind": "regions",
            "parts": parts.iter().map(region_document).collect::<Vec<_>>(),
        })),
        CurveKind::Spline(_) | CurveKind::Analytic(_) => None,
    }
}

/// A region's document: its outer profile and its holes.
pub fn region_document(r: &Region) -> Value {
    json!({
        "kind": "region",
        "outer": profile_document(r.outer()),
        "holes": r.holes().iter().map(profile_document).collect::<Vec<_>>(),
    })
}

/// A profile's document: its segments in order, and whether it is closed.
pub fn profile_document(p: &Profile) -> Value {
    json!({
        "kind": "profile",
        "segments": p.segments().iter().map(segment_document).collect::<Vec<_>>(),
        "closed": p.is_closed(),
    })
}

/// One segment's document.
pub fn segment_document(s: &Segment) -> Value {
    let form = s.curve().curve();
    let points = s.curve().control_points();
    let weights = form.is_rational().then(|| form.weights());
    match (s.kind(), s.circle(), s.own_param()) {
        (SegmentKind::Line, ..) => json!({
            "kind": "line",
            "from": s.start().arr(),
            "to": s.end().arr(),
        }),
        (
            SegmentKind::Arc,
            Some((center, r)),
            OwnParam::Arc {
                pieces,
                piece_sweep,
            },
        ) => {
            let start = s.start().arr();
            let from = (start[1] - center[1]).atan2(start[0] - center[0]);
            // (The turn's size is the pieces'; its sense the curve's own, which a mirrored
            // arc, read from a drawing, has the other way round.)
            let radial = [start[0] - center[0], start[1] - center[1]];
            let counterclockwise = s
                .start_direction()
                .is_none_or(|d| radial[0] * d.y - radial[1] * d.x >= 0.0);
            let sweep = pieces as f64 * piece_sweep.abs();
            json!({
                "kind": "arc",
                "center": center,
                "r": r,
                "start": from,
                "end": if counterclockwise { from + sweep } else { from - sweep },
            })
        }
        (SegmentKind::Bezier, ..) => {
            let mut doc = json!({"kind": "bezier", "points": points});
            if let Some(w) = weights {
                doc["weights"] = json!(w);
            }
            doc
        }
        // (B-splines, and elliptic arcs as the rational splines they are.)
        _ => {
            let mut doc = json!({
                "kind": "bspline",
                "degree": form.degree(),
                "knots": form.homogeneous().knots(),
                "points": points,
            });
            if let Some(w) = weights {
                doc["weights"] = json!(w);
            }
            doc
        }
    }
}

/// A closed ring of `tol`-flattened points turned to run counterclockwise (`outer`) or
/// clockwise, as GeoJSON (RFC 7946) orders a polygon's rings.
fn ring(p: &Profile, tol: f64, outer: bool) -> Vec<[f64; 2]> {
    let mut points = p.flattened(tol);
    let twice_area: f64 = points
        .windows(2)
        .map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1])
        .sum();
    if (twice_area > 0.0) != outer {
        points.reverse();
    }
    points
}

/// A region's rings: its outer boundary counterclockwise, then its holes clockwise.
fn polygon(r: &Region, tol: f64) -> Vec<Vec<[f64; 2]>> {
    std::iter::once(ring(r.outer(), tol, true))
        .chain(r.holes().iter().map(|h| ring(h, tol, false)))
        .collect()
}

/// GeoJSON geometry (RFC 7946) of regions, their boundaries flattened within `tol`: a
/// `Polygon` for one, a `MultiPolygon` for several.
pub fn regions_geometry(parts: &[&Region], tol: f64) -> Value {
    match parts {
        [one] => json!({"type": "Polygon", "coordinates": polygon(one, tol)}),
        _ => json!({
            "type": "MultiPolygon",
            "coordinates": parts.iter().map(|r| polygon(r, tol)).collect::<Vec<_>>(),
        }),
    }
}

/// GeoJSON geometry of an open profile: a `LineString` within `tol` of it.
pub fn line_geometry(p: &Profile, tol: f64) -> Value {
    json!({"type": "LineString", "coordinates": p.flattened(tol)})
}
