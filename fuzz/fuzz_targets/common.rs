//! What the fuzz targets share: curve files built from structured random input (so that most
//! inputs are valid curves, at every scale and offset a user may give), and the check that a
//! result holds only finite numbers.
#![allow(dead_code)]

use arbitrary::Arbitrary;
use curvekit::io::{parse_curve, Curve};
use serde_json::{json, Value};

/// The most control points a fuzzed curve has: the commands' cost grows with it, and the
/// fuzzer needs many short runs more than a few long ones.
pub const MAX_POINTS: usize = 14;

/// A curve file's content, drawn so that most draws are valid curves.
#[derive(Arbitrary, Debug)]
pub enum ArbShape {
    Bezier {
        points: Vec<(i8, i8)>,
        weights: Option<Vec<u8>>,
    },
    Bspline {
        degree: u8,
        points: Vec<(i8, i8)>,
        weights: Option<Vec<u8>>,
        periodic: bool,
        knots: Option<Vec<u8>>,
    },
    Circle {
        r: u8,
    },
    Ellipse {
        a: u8,
        b: u8,
    },
    Limacon {
        a: u8,
        b: u8,
    },
    Lemniscate {
        a: u8,
        b: u8,
    },
    Convexities {
        p: u8,
        eps: u8,
        m: u8,
    },
}

/// A shape placed somewhere in the plane at some size.
#[derive(Arbitrary, Debug)]
pub struct ArbCurve {
    pub shape: ArbShape,
    /// Scale by 2^(scale mod 1201 − 600) times (1 + stretch/256): powers of two and others.
    pub scale: i16,
    pub stretch: u8,
    /// Offset by (ox, oy) · 2^(offset_exp mod 64), in units of the scaled shape.
    pub offset: (i8, i8),
    pub offset_exp: u8,
}

impl ArbCurve {
    /// The size factor and the offset in units of it.
    fn frame(&self) -> (f64, [f64; 2]) {
        let e = (self.scale as i32).rem_euclid(1201) - 600;
        let k = 2f64.powi(e) * (1.0 + self.stretch as f64 / 256.0);
        let far = 2f64.powi((self.offset_exp % 64) as i32);
        (k, [self.offset.0 as f64 * far, self.offset.1 as f64 * far])
    }

    fn points(&self, pts: &[(i8, i8)]) -> Vec<[f64; 2]> {
        let (k, o) = self.frame();
        pts.iter()
            .take(MAX_POINTS)
            .map(|&(x, y)| [(x as f64 + o[0]) * k, (y as f64 + o[1]) * k])
            .collect()
    }

    /// The curve file's text.
    pub fn text(&self) -> String {
        let (k, o) = self.frame();
        let center = [o[0] * k, o[1] * k];
        let len = |u: u8| (1.0 + u as f64) * k;
        let weights = |w: &Option<Vec<u8>>, n: usize| {
            w.as_ref().map(|w| {
                (0..n)
                    // From 2^-32 to 2^31.75: extreme weights, all positive.
                    .map(|i| 2f64.powf((*w.get(i).unwrap_or(&128) as f64 - 128.0) / 4.0))
                    .collect::<Vec<_>>()
            })
        };
        let doc = match &self.shape {
            ArbShape::Bezier { points, weights: w } => {
                let pts = self.points(points);
                let mut d = json!({"kind": "bezier", "points": pts});
                if let Some(w) = weights(w, pts.len()) {
                    d["weights"] = json!(w);
                }
                d
            }
            ArbShape::Bspline {
                degree,
                points,
                weights: w,
                periodic,
                knots,
            } => {
                let pts = self.points(points);
                // Mostly low degrees; now and then one the reader must judge.
                let p = if *degree >= 240 {
                    *degree as usize - 230
                } else {
                    1 + *degree as usize % 5
                };
                let mut d = json!({"kind": "bspline", "degree": p, "points": pts});
                if *periodic {
                    d["periodic"] = json!(true);
                } else if let Some(steps) = knots {
                    // Non-decreasing knots from cumulative steps, of the length the reader
                    // expects (short draws repeat their last step).
                    let count = pts.len() + p + 1;
                    let mut u = 0.0;
                    let ks: Vec<f64> = (0..count)
                        .map(|i| {
                            u += *steps.get(i).or(steps.last()).unwrap_or(&1) as f64 / 16.0;
                            u
                        })
                        .collect();
                    d["knots"] = json!(ks);
                }
                if let Some(w) = weights(w, pts.len()) {
                    d["weights"] = json!(w);
                }
                d
            }
            ArbShape::Circle { r } => json!({"kind": "circle", "r": len(*r), "center": center}),
            ArbShape::Ellipse { a, b } => {
                json!({"kind": "ellipse", "a": len(*a), "b": len(*b), "center": center})
            }
            ArbShape::Limacon { a, b } => {
                json!({"kind": "limacon", "a": len(*a), "b": len(*b)})
            }
            ArbShape::Lemniscate { a, b } => {
                json!({"kind": "elliptic_lemniscate", "a": len(*a), "b": len(*b)})
            }
            ArbShape::Convexities { p, eps, m } => json!({
                "kind": "convexities",
                "p": len(*p),
                "eps": (*eps as f64 + 0.5) / 256.0,
                "m": 2 + *m as u32 % 11,
            }),
        };
        doc.to_string()
    }

    /// The curve, if the reader accepts it.
    pub fn curve(&self) -> Option<Curve> {
        parse_curve("fuzz.json", &self.text()).ok()
    }
}

/// A tolerance in the accepted range, or now and then any number (which must be refused
/// where the settings are made).
pub fn tolerance(code: u8, raw: f64) -> f64 {
    if code == 255 {
        raw
    } else {
        10f64.powi(-3 - (code % 13) as i32)
    }
}

/// Every number in a serialized result is finite (serde_json writes a non-finite one as
/// `null`, and the results write no other null).
/// Asserts what every answer of the curve commands holds: its options were valid (an answer to
/// a tolerance out of range is a defect) and its document has only finite numbers.
pub fn accepted_and_finite<R: serde::Serialize + std::fmt::Debug>(
    opts: &curvekit::antipodal::Options,
    r: &R,
) {
    assert!(
        opts.validate().is_ok(),
        "tol {} accepted",
        opts.settings.tol.get()
    );
    assert!(all_finite(&serde_json::to_value(r).unwrap()), "{r:?}");
}

/// A drawing read as the commands read it: as regions (an error, or regions with finite
/// points), then as its first profile, an error (`None`) or a curve with finite points.
pub fn read_drawing(name: &str, format: curvekit::io::DrawingFormat, data: &[u8]) -> Option<Curve> {
    // As the regions `medial` and `offset` read (outlines nested, filled, checked for
    // crossings): an error or regions with finite points.
    if let Ok(region) = curvekit::io::parse_region(name, Some(format), data, None) {
        for p in region.polyline(16) {
            assert!(p[0].is_finite() && p[1].is_finite(), "region point {p:?}");
        }
    }
    let curve = curvekit::io::parse_drawing(name, format, data, Some(0)).ok()?;
    for p in curve.polyline(16) {
        assert!(p[0].is_finite() && p[1].is_finite(), "point {p:?}");
    }
    Some(curve)
}

pub fn all_finite(v: &Value) -> bool {
    match v {
        Value::Null => false,
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(a) => a.iter().all(all_finite),
        Value::Object(m) => m.values().all(all_finite),
        _ => true,
    }
}

/// `x` lies in the closed interval `[a, b]`.
pub fn within(x: f64, (a, b): (f64, f64)) -> bool {
    a <= x && x <= b
}

/// The checks every medial axis passes: finite numbers, edges between nodes, and every
/// vertex at its radius from both its feet (to `room`).
pub fn check_axis(
    region: &curvekit::curve::Region,
    axis: &curvekit::medial::MedialAxis,
    room: f64,
) {
    let value = serde_json::to_value(axis).unwrap();
    assert!(all_finite(&value), "{axis:?}");
    let boundaries: Vec<_> = std::iter::once(region.outer())
        .chain(region.holes())
        .collect();
    for e in &axis.edges {
        assert!(e.from < axis.nodes.len() && e.to < axis.nodes.len());
        for i in 0..e.xy.len() {
            for s in 0..2 {
                let f =
                    curvekit::curve::ParamCurve::jet(boundaries[e.boundary[i][s]], e.feet[i][s]).p;
                let d = (f.x - e.xy[i][0]).hypot(f.y - e.xy[i][1]);
                assert!((d - e.radius[i]).abs() <= room, "{e:?}");
            }
        }
    }
}

/// The region a region document holds, if the reader takes it.
pub fn read_region(doc: &Value) -> Option<curvekit::curve::Region> {
    let curve =
        curvekit::io::parse_region("fuzz.json", None, doc.to_string().as_bytes(), None).ok()?;
    match curve.shape {
        curvekit::io::CurveKind::Region(r) => Some(*r),
        _ => None,
    }
}

/// The most sides: the axis's cost grows with the square of the sites.
pub const MAX_SIDES: usize = 8;

/// One side of a fuzzed region's outline.
#[derive(Arbitrary, Debug)]
pub struct Side {
    pub to: (i8, i8),
    /// Bend the side into a quadratic Bézier through a control point this far off (0: a line).
    pub bend: i8,
}

/// A region: a polygon of at most [`MAX_SIDES`] sides (some bent into quadratic Béziers)
/// with up to 3 round holes, at every scale and offset.
#[derive(Arbitrary, Debug)]
pub struct ArbRegion {
    pub start: (i8, i8),
    pub sides: Vec<Side>,
    pub holes: Vec<((i8, i8), u8)>,
    /// Scale by 2^(scale mod 121 − 60).
    pub scale: u8,
    /// Offset by 2^(offset mod 48) sizes.
    pub offset: u8,
    pub chord: u8,
}

impl ArbRegion {
    /// The region's document, the scale factor `k` and the offset `far` (in units of it).
    pub fn document(&self) -> (Value, f64, f64) {
        let k = 2f64.powi((self.scale % 121) as i32 - 60);
        let far = 2f64.powi((self.offset % 48) as i32) * 256.0;
        let at = |p: (i8, i8)| [(p.0 as f64 + far) * k, (p.1 as f64 + far) * k];
        let mut from = self.start;
        let mut segments = Vec::new();
        let n = self.sides.len().min(MAX_SIDES);
        for (i, s) in self.sides.iter().take(n).enumerate() {
            let to = if i + 1 == n { self.start } else { s.to };
            if s.bend == 0 {
                segments.push(json!({"kind": "line", "from": at(from), "to": at(to)}));
            } else {
                let mid = (
                    ((from.0 as i16 + to.0 as i16) / 2
                        - (to.1 as i16 - from.1 as i16) * s.bend as i16 / 64)
                        as f64,
                    ((from.1 as i16 + to.1 as i16) / 2
                        + (to.0 as i16 - from.0 as i16) * s.bend as i16 / 64)
                        as f64,
                );
                let c = [(mid.0 + far) * k, (mid.1 + far) * k];
                segments.push(json!({"kind": "bezier", "points": [at(from), c, at(to)]}));
            }
            from = to;
        }
        let holes: Vec<_> = self
            .holes
            .iter()
            .take(3)
            .map(|&(c, r)| json!({"kind": "circle", "center": at(c), "r": (1.0 + r as f64 / 16.0) * k}))
            .collect();
        let doc = json!({"kind": "region", "outer": {"kind": "profile", "segments": segments}, "holes": holes});
        (doc, k, far)
    }

    /// The chord tolerance drawn: 1/256 … 1/2.
    pub fn chord_tol(&self) -> f64 {
        0.5 / 2f64.powi((self.chord % 8) as i32)
    }
}
