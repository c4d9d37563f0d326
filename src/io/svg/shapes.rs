//! SVG's shape elements as chains of exact segments in their own coordinates: `<path>` (its
//! data, [`path_data`](super::path_data)), `<rect>` with rounded corners, `<circle>`,
//! `<ellipse>`, `<polygon>`, `<polyline>` and `<line>`.

use super::path_data::{self, Precision};
use super::user_length;
use crate::io::MAX_SEGMENTS;
use curve::Segment;
use roxmltree::Node;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Chains, each with whether it is closed.
pub(super) type Shapes = Vec<(Vec<Segment>, bool)>;

/// What went wrong, and in which attribute.
type ShapeError = (&'static str, String);

/// The element's chains in its own coordinates; `filled`: an open chain is closed by a line,
/// as SVG fills it.
pub(super) fn chains(node: &Node<'_, '_>, tag: &str, filled: bool) -> Result<Shapes, ShapeError> {
    let num = |attr: &'static str, default: Option<f64>| -> Result<f64, ShapeError> {
        match node.attribute(attr) {
            None => default.ok_or((attr, "missing".to_string())),
            Some(v) => user_length(v).map_err(|e| (attr, e)),
        }
    };
    let geometry = |r: curve::Result<Segment>| r.map_err(|e| ("geometry", e.to_string()));
    let from_path = |subs: Vec<path_data::Subpath>| {
        subs.into_iter()
            .map(|s| (s.segments, s.closed))
            .collect::<Shapes>()
    };
    match tag {
        "path" => {
            let d = node.attribute("d").unwrap_or("");
            let subs = path_data::subpaths(d, filled, MAX_SEGMENTS).map_err(|e| ("d", e))?;
            Ok(from_path(subs))
        }
        "circle" => {
            let (cx, cy, r) = (
                num("cx", Some(0.0))?,
                num("cy", Some(0.0))?,
                num("r", None)?,
            );
            Ok(vec![(
                vec![geometry(Segment::arc([cx, cy], r, 0.0, TAU))?],
                true,
            )])
        }
        "ellipse" => {
            let (cx, cy) = (num("cx", Some(0.0))?, num("cy", Some(0.0))?);
            let (rx, ry) = (num("rx", None)?, num("ry", None)?);
            let e = Segment::elliptic_arc([cx, cy], rx, ry, 0.0, 0.0, TAU);
            Ok(vec![(vec![geometry(e)?], true)])
        }
        "line" => {
            let from = [num("x1", Some(0.0))?, num("y1", Some(0.0))?];
            let to = [num("x2", Some(0.0))?, num("y2", Some(0.0))?];
            if from == to {
                return Ok(Vec::new());
            }
            // (A line encloses nothing: it is never filled.)
            Ok(vec![(vec![geometry(Segment::line(from, to))?], false)])
        }
        "polygon" | "polyline" => {
            // As path data (`M`, `L`…, and `Z` for a polygon), with the precision of the
            // numbers as written: closing and degenerate pieces are decided as for a path.
            let written = node.attribute("points").unwrap_or("");
            let pts: Vec<(f64, f64)> = svgtypes::PointsParser::from(written).collect();
            if pts.iter().any(|p| !(p.0.is_finite() && p.1.is_finite())) {
                return Err(("points", "coordinates must be finite".into()));
            }
            let mut d = String::new();
            for (k, (x, y)) in pts.iter().enumerate() {
                d.push_str(if k == 0 { "M" } else { "L" });
                d.push_str(&format!("{x:e},{y:e} "));
            }
            if tag == "polygon" && !pts.is_empty() {
                d.push('Z');
            }
            let subs =
                path_data::subpaths_written(&d, Precision::of(written), filled, MAX_SEGMENTS)
                    .map_err(|e| ("points", e))?;
            Ok(from_path(subs))
        }
        _ => rect(node, &num),
    }
}

/// A `<rect>`, its corners rounded by quarter ellipses where `rx`/`ry` say (SVG's rules: one
/// given stands for both, each at most half the side).
fn rect(
    node: &Node<'_, '_>,
    num: &dyn Fn(&'static str, Option<f64>) -> Result<f64, ShapeError>,
) -> Result<Shapes, ShapeError> {
    let (x, y) = (num("x", Some(0.0))?, num("y", Some(0.0))?);
    let (w, h) = (num("width", None)?, num("height", None)?);
    if !(w > 0.0 && h > 0.0) {
        return Err((
            "width",
            format!("a rectangle needs a positive size, got {w} × {h}"),
        ));
    }
    let given = |a: &'static str| node.attribute(a).map(|_| num(a, None)).transpose();
    let (rx, ry) = match (given("rx")?, given("ry")?) {
        (None, None) => (0.0, 0.0),
        (Some(r), None) | (None, Some(r)) => (r, r),
        (Some(a), Some(b)) => (a, b),
    };
    let (rx, ry) = (rx.abs().min(0.5 * w), ry.abs().min(0.5 * h));
    let g = |r: curve::Result<Segment>| r.map_err(|e| ("geometry", e.to_string()));
    let mut segs = Vec::with_capacity(8);
    let line = |a: [f64; 2], b: [f64; 2], segs: &mut Vec<Segment>| -> Result<(), ShapeError> {
        if a != b {
            segs.push(g(Segment::line(a, b))?);
        }
        Ok(())
    };
    let corner = |c: [f64; 2], from: f64, segs: &mut Vec<Segment>| -> Result<(), ShapeError> {
        if rx > 0.0 && ry > 0.0 {
            segs.push(g(Segment::elliptic_arc(
                c,
                rx,
                ry,
                0.0,
                from,
                from + FRAC_PI_2,
            ))?);
        }
        Ok(())
    };
    // Clockwise on the screen (y down): along the top, down the right side, and so on.
    line([x + rx, y], [x + w - rx, y], &mut segs)?;
    corner([x + w - rx, y + ry], -FRAC_PI_2, &mut segs)?;
    line([x + w, y + ry], [x + w, y + h - ry], &mut segs)?;
    corner([x + w - rx, y + h - ry], 0.0, &mut segs)?;
    line([x + w - rx, y + h], [x + rx, y + h], &mut segs)?;
    corner([x + rx, y + h - ry], FRAC_PI_2, &mut segs)?;
    line([x, y + h - ry], [x, y + ry], &mut segs)?;
    corner([x + rx, y + ry], PI, &mut segs)?;
    Ok(vec![(segs, true)])
}
