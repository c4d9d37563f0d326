//! Plain SVG paths of offsets and medial axes, in the input's own coordinates (not turned to
//! SVG's y-down: a y-up input shows mirrored in a browser, and reads back as it was).
//!
//! Each offset loop is a closed `<path>` in a group per distance (`<g id="offset_0.25">`),
//! each medial edge an open one in `<g id="medial_edges">`, all stroked and unfilled (read back
//! as outlines). Lines are `L`, arcs `A` (in pieces of at most a quarter turn, so that no flag
//! is ambiguous), splines their Bézier pieces (`Q`, `C`; a degree-1 spline its lines); numbers
//! are written in Rust's shortest form that reads back as the same `f64`.

use super::{distance_name, sweeps_nothing, ExportError};
use medial::MedialAxis;
use offset::{OffsetSegment, Offsets};
use std::f64::consts::FRAC_PI_2;
use std::fmt::Write as _;

/// The units an SVG root's `width` can carry (as the reader takes them). Not `pc`: picas to
/// SVG, parsecs to the DXF reader, which names them alike.
const SVG_UNITS: [&str; 4] = ["mm", "cm", "in", "pt"];

/// A document being written: its path elements and the box they cover.
struct Document {
    body: String,
    bounds: [f64; 4],
}

impl Document {
    fn new() -> Self {
        Self {
            body: String::new(),
            bounds: [f64::INFINITY, f64::INFINITY, -f64::INFINITY, -f64::INFINITY],
        }
    }

    fn cover(&mut self, p: [f64; 2]) {
        self.bounds[0] = self.bounds[0].min(p[0]);
        self.bounds[1] = self.bounds[1].min(p[1]);
        self.bounds[2] = self.bounds[2].max(p[0]);
        self.bounds[3] = self.bounds[3].max(p[1]);
    }

    /// `x y` of a point (and the box grown to it).
    fn point(&mut self, p: [f64; 2]) -> String {
        self.cover(p);
        format!("{} {}", p[0], p[1])
    }

    /// The SVG document: its `viewBox` the box of the paths with a margin of 2 % of its size,
    /// its `width` and `height` in `units` where SVG has that unit.
    fn finish(self, units: Option<&str>) -> String {
        let [x0, y0, x1, y1] = if self.bounds[0] <= self.bounds[2] {
            self.bounds
        } else {
            [0.0, 0.0, 1.0, 1.0]
        };
        let size = (x1 - x0).max(y1 - y0).max(f64::MIN_POSITIVE);
        let margin = 0.02 * size;
        let (w, h) = (x1 - x0 + 2.0 * margin, y1 - y0 + 2.0 * margin);
        let dimensions = match units.filter(|u| SVG_UNITS.contains(u)) {
            Some(u) => format!(r#" width="{w}{u}" height="{h}{u}""#),
            None => String::new(),
        };
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {w} {h}\"{dimensions} \
             fill=\"none\" stroke=\"black\" stroke-width=\"{}\">\n{}</svg>\n",
            x0 - margin,
            y0 - margin,
            size / 500.0,
            self.body
        )
    }
}

/// The path data of one offset piece from where the last ended.
fn piece_data(doc: &mut Document, s: &OffsetSegment, d: &mut String) -> Result<(), ExportError> {
    if sweeps_nothing(s) {
        return Ok(());
    }
    match s {
        OffsetSegment::Line { to, .. } => {
            let _ = write!(d, " L {}", doc.point(*to));
        }
        OffsetSegment::Arc {
            center,
            r,
            start,
            end,
        } => {
            let pieces = ((end - start).abs() / FRAC_PI_2).ceil().max(1.0) as usize;
            let sweep = u8::from(end > start);
            for k in 1..=pieces {
                let a = start + (end - start) * k as f64 / pieces as f64;
                let p = [center[0] + r * a.cos(), center[1] + r * a.sin()];
                let _ = write!(d, " A {r} {r} 0 0 {sweep} {}", doc.point(p));
            }
        }
        OffsetSegment::BSpline {
            degree,
            knots,
            points,
        } => spline_data(doc, *degree, knots, points, d)?,
    }
    Ok(())
}

/// The path data of a clamped spline from its first point: its Bézier pieces.
fn spline_data(
    doc: &mut Document,
    degree: usize,
    knots: &[f64],
    points: &[[f64; 2]],
    d: &mut String,
) -> Result<(), ExportError> {
    if degree == 1 {
        for p in points.iter().skip(1) {
            let _ = write!(d, " L {}", doc.point(*p));
        }
        return Ok(());
    }
    let letter = match degree {
        2 => "Q",
        3 => "C",
        _ => {
            return Err(ExportError::NotRepresentable(format!(
                "a spline of degree {degree}: SVG paths hold degrees 1 to 3"
            )))
        }
    };
    let coefs = points.iter().flat_map(|p| *p).collect();
    let spline = bspline::BSpline::new(degree, knots.to_vec(), 2, coefs)
        .map_err(|e| ExportError::NotRepresentable(format!("a spline that is not one: {e}")))?;
    for b in spline.bezier_pieces() {
        let _ = write!(d, " {letter}");
        for p in b.coefs.chunks_exact(2).skip(1) {
            let _ = write!(d, " {}", doc.point([p[0], p[1]]));
        }
    }
    Ok(())
}

/// The start of an offset piece.
fn piece_start(s: &OffsetSegment) -> [f64; 2] {
    match s {
        OffsetSegment::Line { from, .. } => *from,
        OffsetSegment::Arc {
            center, r, start, ..
        } => [center[0] + r * start.cos(), center[1] + r * start.sin()],
        OffsetSegment::BSpline { points, .. } => points.first().copied().unwrap_or([0.0; 2]),
    }
}

/// The SVG paths of offsets: a group per distance, a closed path per loop.
///
/// ```
/// use curvekit::export::svg_paths::offsets_svg;
/// use offset::{Doubts, Offset, OffsetLoop, OffsetSegment, Offsets};
/// let circle = OffsetSegment::Arc { center: [0.0, 0.0], r: 2.0, start: 0.0, end: std::f64::consts::TAU };
/// let found = Offsets {
///     offsets: vec![Offset { distance: 1.0, loops: vec![OffsetLoop { segments: vec![circle], part: None }], error: 0.0 }],
///     doubts: Doubts::none(),
///     complete: true,
/// };
/// let svg = offsets_svg(&found, None).unwrap();
/// assert!(svg.contains(r#"<g id="offset_1">"#) && svg.contains("M 2 0 A 2 2 0 0 1"));
/// ```
pub fn offsets_svg(found: &Offsets, units: Option<&str>) -> Result<String, ExportError> {
    let mut doc = Document::new();
    let mut body = String::new();
    for o in &found.offsets {
        let _ = writeln!(body, "<g id=\"{}\">", distance_name(o.distance));
        for l in &o.loops {
            let Some(first) = l.segments.first() else {
                continue;
            };
            let mut d = format!("M {}", doc.point(piece_start(first)));
            for s in &l.segments {
                piece_data(&mut doc, s, &mut d)?;
            }
            let _ = writeln!(body, "<path d=\"{d} Z\"/>");
        }
        body.push_str("</g>\n");
    }
    doc.body = body;
    Ok(doc.finish(units))
}

/// The SVG paths of a medial axis: an open path per edge (its fitted spline's Bézier pieces
/// where fitted, else its polyline) in `<g id="medial_edges">`.
pub fn medial_svg(axis: &MedialAxis, units: Option<&str>) -> Result<String, ExportError> {
    let mut doc = Document::new();
    let mut body = String::from("<g id=\"medial_edges\">\n");
    for e in &axis.edges {
        let mut d = String::new();
        match &e.bspline {
            Some(b) => {
                let Some(first) = b.points.first() else {
                    continue;
                };
                d = format!("M {}", doc.point(*first));
                spline_data(&mut doc, b.degree, &b.knots, &b.points, &mut d)?;
            }
            None => {
                for (i, p) in e.xy.iter().enumerate() {
                    let _ = write!(d, "{}{}", if i == 0 { "M " } else { " L " }, doc.point(*p));
                }
            }
        }
        if !d.is_empty() {
            let _ = writeln!(body, "<path d=\"{d}\"/>");
        }
    }
    body.push_str("</g>\n");
    doc.body = body;
    Ok(doc.finish(units))
}
