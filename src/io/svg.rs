//! SVG drawings: every `<path>` element's data (each subpath a chain), and the basic shapes
//! design tools also write (`<rect>` with rounded corners, `<circle>`, `<ellipse>`,
//! `<polygon>`, `<polyline>`, `<line>`), with the `transform` attributes of the element and
//! its ancestors applied exactly (affine maps carry every segment's exact form). Elements
//! that are not drawn (inside `<defs>`, `<clipPath>`, `<mask>`, `<symbol>`, `<marker>`,
//! `<pattern>`) are skipped. Coordinates are the file's user units, `y` pointing down as SVG
//! draws it. The XML is `roxmltree`'s, the transform and path syntax `svgtypes`'.

mod path_data;

use super::drawing::{error, Chain};
use super::{CurveFileError, Problem, MAX_ABS, MAX_SEGMENTS};
use curve::{Affine, Segment, V2};
use roxmltree::Node;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Containers whose content is not drawn where it stands.
const NOT_DRAWN: [&str; 6] = ["defs", "clipPath", "mask", "symbol", "marker", "pattern"];

/// The chains of an SVG drawing, in document order.
pub(super) fn chains(file: &str, text: &str) -> Result<Vec<Chain>, CurveFileError> {
    let doc = roxmltree::Document::parse(text).map_err(|e| {
        error(
            file,
            "document",
            Problem::Syntax(format!("invalid SVG (XML): {e}")),
        )
    })?;
    if doc.root_element().tag_name().name() != "svg" {
        return Err(error(
            file,
            "document",
            Problem::Syntax(format!(
                "the root element is <{}>, not <svg>",
                doc.root_element().tag_name().name()
            )),
        ));
    }
    let mut out = Vec::new();
    let mut index = 0usize;
    let mut total = 0usize;
    for node in doc.descendants().filter(Node::is_element) {
        let tag = node.tag_name().name();
        if !matches!(
            tag,
            "path" | "rect" | "circle" | "ellipse" | "polygon" | "polyline" | "line"
        ) || hidden(&node)
        {
            continue;
        }
        let name = match node.attribute("id") {
            Some(id) => format!("{tag}#{id}"),
            None => format!("{tag}[{index}]"),
        };
        index += 1;
        let fail = |field: &str, why: String| {
            error(file, &format!("{name} {field}"), Problem::Syntax(why))
        };
        let map = transform_of(&node).map_err(|why| fail("transform", why))?;
        let pieces = shape_chains(&node, tag).map_err(|(field, why)| fail(field, why))?;
        for (k, (segments, closed)) in pieces.into_iter().enumerate() {
            total += segments.len();
            if total > MAX_SEGMENTS * 10 {
                return Err(error(
                    file,
                    "document",
                    Problem::OutOfRange {
                        rule: format!("at most {} segments in all", MAX_SEGMENTS * 10),
                        value: total as f64,
                    },
                ));
            }
            let segments = segments
                .iter()
                .map(|s| s.transformed(&map))
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| fail("transform", e.to_string()))?;
            for s in &segments {
                check_size(s).map_err(|why| fail("d", why))?;
            }
            out.push(Chain {
                name: if tag == "path" {
                    format!("{name} subpath {k}")
                } else {
                    name.clone()
                },
                segments,
                closed: Some(closed),
            });
        }
    }
    Ok(out)
}

/// Inside a container that is not drawn.
fn hidden(node: &Node<'_, '_>) -> bool {
    node.ancestors()
        .skip(1)
        .any(|a| NOT_DRAWN.contains(&a.tag_name().name()))
}

/// The map from the element's coordinates to the document's: its own `transform` after its
/// ancestors'.
fn transform_of(node: &Node<'_, '_>) -> Result<Affine, String> {
    let mut map = Affine::IDENTITY;
    for n in node.ancestors().filter(Node::is_element) {
        if let Some(t) = n.attribute("transform") {
            let t: svgtypes::Transform = t
                .parse()
                .map_err(|e| format!("invalid transform `{t}`: {e}"))?;
            let inner = Affine([t.a, t.b, t.c, t.d, t.e, t.f]);
            if !inner.is_valid() {
                return Err(format!("transform `{t:?}` is not invertible"));
            }
            // (Walking outwards: each ancestor's map applies after what is inside it.)
            map = inner.after(&map);
        }
    }
    Ok(map)
}

type Shapes = Vec<(Vec<Segment>, bool)>;

/// The element's chains (segments, closed) in its own coordinates.
fn shape_chains(node: &Node<'_, '_>, tag: &str) -> Result<Shapes, (&'static str, String)> {
    let num = |attr: &'static str, default: Option<f64>| -> Result<f64, (&'static str, String)> {
        match node.attribute(attr) {
            None => default.ok_or((attr, "missing".to_string())),
            Some(v) => {
                let len: svgtypes::Length = v
                    .trim()
                    .parse()
                    .map_err(|e| (attr, format!("`{v}` is not a length: {e}")))?;
                // (Other units would need the document's viewport to convert.)
                if !matches!(
                    len.unit,
                    svgtypes::LengthUnit::None | svgtypes::LengthUnit::Px
                ) {
                    return Err((attr, format!("`{v}`: only user units (or px) are read")));
                }
                let x = len.number;
                if x.is_finite() && x.abs() <= MAX_ABS {
                    Ok(x)
                } else {
                    Err((attr, format!("{x} is out of range")))
                }
            }
        }
    };
    let geometry = |r: curve::Result<Segment>| r.map_err(|e| ("geometry", e.to_string()));
    match tag {
        "path" => {
            let d = node.attribute("d").unwrap_or("");
            let subs = path_data::subpaths(d, MAX_SEGMENTS).map_err(|e| ("d", e))?;
            Ok(subs.into_iter().map(|s| (s.segments, s.closed)).collect())
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
            Ok(vec![(vec![geometry(Segment::line(from, to))?], false)])
        }
        "polygon" | "polyline" => {
            let pts: Vec<V2> = svgtypes::PointsParser::from(node.attribute("points").unwrap_or(""))
                .map(|(x, y)| V2::new(x, y))
                .collect();
            if pts.iter().any(|p| !(p.x.is_finite() && p.y.is_finite())) {
                return Err(("points", "coordinates must be finite".into()));
            }
            let closed = tag == "polygon";
            let mut segs = Vec::with_capacity(pts.len());
            let n = pts.len();
            let last = if closed { n } else { n.saturating_sub(1) };
            for i in 0..last {
                let (a, b) = (pts[i], pts[(i + 1) % n]);
                if a != b {
                    segs.push(geometry(Segment::line(a.arr(), b.arr()))?);
                }
            }
            Ok(vec![(segs, closed)])
        }
        _ => rect(node, &num),
    }
}

/// A `<rect>`, its corners rounded by quarter ellipses where `rx`/`ry` say (SVG's rules: one
/// given stands for both, each at most half the side).
fn rect(
    node: &Node<'_, '_>,
    num: &dyn Fn(&'static str, Option<f64>) -> Result<f64, (&'static str, String)>,
) -> Result<Shapes, (&'static str, String)> {
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
    let line =
        |a: [f64; 2], b: [f64; 2], segs: &mut Vec<Segment>| -> Result<(), (&'static str, String)> {
            if a != b {
                segs.push(g(Segment::line(a, b))?);
            }
            Ok(())
        };
    let corner =
        |c: [f64; 2], from: f64, segs: &mut Vec<Segment>| -> Result<(), (&'static str, String)> {
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

/// Coordinates within the range every reader accepts.
fn check_size(s: &Segment) -> Result<(), String> {
    match s
        .curve()
        .control_points()
        .iter()
        .flatten()
        .find(|x| !(x.is_finite() && x.abs() <= MAX_ABS))
    {
        Some(x) => Err(format!("coordinate {x:e} is too large (at most 1e100)")),
        None => Ok(()),
    }
}
