//! The drawing's tolerance, and each entity's piece: its segments, closed by itself or with
//! open ends to join.

use super::entities::{curve_error, geometry, EntityError, EntityShape, Item};
use super::Failure;
use curve::{Affine, Segment, SegmentKind, JOIN_GAP, V2};
use numeric::rounding::ulps;

/// Relative to the drawing's largest coordinate, the rounding an end point carries (an arc's
/// ends are computed from its centre, radius and angles): a few units of the last place, the
/// join tolerance far from the origin where `JOIN_GAP` of a small part's size is below it.
pub(super) const COORDINATE_ROUNDING: f64 = ulps(16.0);

/// Ends of different pieces nearer than this (relative to the drawing's size) but beyond the
/// tolerance are a gap in an outline meant to close: a drawing error to report. Ends drawn
/// apart on purpose (an open profile) are far farther apart than 1e-4 of the drawing.
pub(super) const NEAR_MISS: f64 = 1e-4;

/// A bulge this small (in magnitude) is a straight piece: its arc strays from the chord by
/// `|b| c / 2`, below 1e-9 of the chord `c`, within the drawing's tolerance; as an arc its
/// radius `c (|b| + 1/|b|) / 4` would be so large that its computed ends miss the vertices.
const FLAT_BULGE: f64 = 1e-9;

// ---------------------------------------------------------------------------------------------
// Tolerance and pieces.

/// The drawing's scale and the tolerances derived from it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Tolerance {
    /// Ends within this distance join.
    pub(super) join: f64,
    /// Open ends within this distance (and beyond `join`) are a gap.
    pub(super) near: f64,
}

impl Tolerance {
    /// The tolerances of the drawing made of `items`.
    pub(super) fn of(items: &[Item]) -> Tolerance {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        let mut add = |p: [f64; 2]| {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        };
        for item in items {
            match &item.shape {
                EntityShape::Segment { segment, .. } => segment
                    .curve()
                    .control_points()
                    .into_iter()
                    .for_each(&mut add),
                EntityShape::Polyline { vertices, map, .. } => {
                    for (i, &(p, b)) in vertices.iter().enumerate() {
                        add(map.apply(p));
                        if let Some(&(q, _)) = vertices.get(i + 1).or(vertices.first()) {
                            add(map.apply(bulge_middle(p, q, b)));
                        }
                    }
                }
            }
        }
        if items.is_empty() {
            return Tolerance {
                join: f64::MIN_POSITIVE,
                near: f64::MIN_POSITIVE,
            };
        }
        let size = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
        let magnitude = lo.iter().chain(&hi).fold(0.0f64, |m, x| m.max(x.abs()));
        let join = (JOIN_GAP * size)
            .max(COORDINATE_ROUNDING * magnitude)
            .max(f64::MIN_POSITIVE);
        Tolerance {
            join,
            near: (NEAR_MISS * size).max(join),
        }
    }
}

/// The middle of the arc of bulge `b` from `p` to `q` (on the chord's right for `b > 0`).
pub(super) fn bulge_middle(p: [f64; 2], q: [f64; 2], b: f64) -> [f64; 2] {
    let (p, q) = (V2::from_arr(p), V2::from_arr(q));
    let m = (p + q) * 0.5;
    // (q − p)⊥ has the chord's length: the sagitta is b · c / 2.
    (m - (q - p).perp() * (0.5 * b)).arr()
}

/// A piece of the drawing: segments in order, closed by itself or with open ends.
#[derive(Debug)]
pub(super) struct DrawingPiece {
    pub(super) order: usize,
    pub(super) name: String,
    pub(super) segments: Vec<Segment>,
    /// The first segment's start and the last one's end.
    pub(super) start: V2,
    pub(super) end: V2,
    /// `Some(true)` closed (a profile by itself), `None` for a polyline that the profile
    /// decides, `Some(false)` for a piece whose ends join others.
    pub(super) closed: Option<bool>,
}

impl Item {
    /// The piece, with zero-length lines and polyline pieces (within `tol`) left out.
    pub(super) fn piece(self, tol: f64) -> Result<Option<DrawingPiece>, Failure> {
        let name = self.name;
        let at = |(what, p): EntityError| {
            let field = if what.is_empty() {
                name.clone()
            } else {
                format!("{name} {what}")
            };
            (field, p)
        };
        let (segments, closed) = match self.shape {
            EntityShape::Segment { segment, flagged } => {
                let gap = (segment.end() - segment.start()).norm();
                if segment.kind() == SegmentKind::Line && gap <= tol {
                    return Ok(None);
                }
                if flagged && gap > tol {
                    return Err(at(geometry(
                        "",
                        format!(
                            "flagged closed or periodic (70 bits 1, 2) but its ends are {gap:e} \
                             apart (the drawing's tolerance is {tol:e})"
                        ),
                    )));
                }
                (vec![*segment], Some(gap <= tol))
            }
            EntityShape::Polyline {
                vertices,
                map,
                closed,
            } => {
                let segs = polyline_segments(&vertices, &map, closed, tol).map_err(at)?;
                if segs.is_empty() {
                    return Ok(None);
                }
                let shut = closed
                    || (segs.len() > 1
                        && segs
                            .first()
                            .zip(segs.last())
                            .is_some_and(|(f, l)| (l.end() - f.start()).norm() <= tol));
                (segs, if shut { Some(true) } else { Some(false) })
            }
        };
        let (Some(first), Some(last)) = (segments.first(), segments.last()) else {
            return Ok(None);
        };
        let (start, end) = (first.start(), last.end());
        Ok(Some(DrawingPiece {
            order: self.order,
            name,
            segments,
            start,
            end,
            closed,
        }))
    }
}

/// The segments of a polyline, made in its object coordinates and moved by `map` into the
/// world's.
fn polyline_segments(
    vertices: &[([f64; 2], f64)],
    map: &Affine,
    closed: bool,
    tol: f64,
) -> Result<Vec<Segment>, EntityError> {
    let n = vertices.len();
    let pieces = if closed { n } else { n.saturating_sub(1) };
    let mut out = Vec::with_capacity(pieces);
    for i in 0..pieces {
        let (Some(&(p, b)), Some(&(q, _))) = (vertices.get(i), vertices.get((i + 1) % n)) else {
            break;
        };
        let what = format!("vertex {i}");
        if (V2::from_arr(map.apply(q)) - V2::from_arr(map.apply(p))).norm() <= tol {
            // A repeated vertex: no piece.
            continue;
        }
        let seg = if b.abs() <= FLAT_BULGE {
            Segment::line(p, q)
        } else {
            bulge_arc(p, q, b)
        };
        let seg = seg.and_then(|s| match *map == Affine::IDENTITY {
            true => Ok(s),
            false => s.transformed(map),
        });
        out.push(seg.map_err(|e| curve_error(&what, e))?);
    }
    Ok(out)
}

/// The arc from `p` to `q` of bulge `b = tan(θ/4)`, θ the included angle (counterclockwise
/// when positive).
fn bulge_arc(p: [f64; 2], q: [f64; 2], b: f64) -> curve::Result<Segment> {
    let (pv, qv) = (V2::from_arr(p), V2::from_arr(q));
    let chord = qv - pv;
    let c = chord.norm();
    // The centre lies on the chord's perpendicular bisector, at (c/4)(1/b − b) to its left
    // (chord ⊥ / c is the left unit normal); the radius is (c/4)(1/|b| + |b|). (Written so to
    // stay finite for large and small bulges alike.)
    let center = (pv + qv) * 0.5 + chord.perp() * (0.25 * (1.0 / b - b));
    let r = 0.25 * c * (1.0 / b.abs() + b.abs());
    let theta = 4.0 * b.atan();
    let start = (pv - center).angle();
    Segment::arc(center.arr(), r, start, start + theta)
}

#[cfg(test)]
mod tests {
    use super::*;
    use curve::ParamCurve;
    use std::f64::consts::PI;

    #[test]
    fn bulge_arcs() {
        // Bulge 1: the half circle from (1, 0) counterclockwise to (−1, 0), through (0, 1).
        let a = bulge_arc([1.0, 0.0], [-1.0, 0.0], 1.0).unwrap();
        let top = a.jet(0.5).p;
        assert!((top - V2::new(0.0, 1.0)).norm() < 1e-15, "{top:?}");
        // Its middle as the tolerance's box takes it, and the other sign.
        assert_eq!(bulge_middle([1.0, 0.0], [-1.0, 0.0], 1.0), [0.0, 1.0]);
        let b = bulge_arc([1.0, 0.0], [-1.0, 0.0], -1.0).unwrap();
        assert!((b.jet(0.5).p - V2::new(0.0, -1.0)).norm() < 1e-15);
        // A quarter circle (bulge tan(π/8)) from (1, 0) to (0, 1) about the origin.
        let q = bulge_arc([1.0, 0.0], [0.0, 1.0], (PI / 8.0).tan()).unwrap();
        for k in 0..=8 {
            assert!((q.jet(k as f64 / 8.0).p.norm() - 1.0).abs() < 1e-15);
        }
        // A large bulge: nearly the full circle, still through both ends.
        let big = bulge_arc([0.0, 0.0], [1e-3, 0.0], 1e6).unwrap();
        assert!((big.start() - V2::new(0.0, 0.0)).norm() < 1e-12);
        assert!((big.end() - V2::new(1e-3, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn the_tolerance_follows_the_drawing() {
        let item = |seg: Segment| Item {
            order: 0,
            name: String::new(),
            shape: EntityShape::Segment {
                segment: Box::new(seg),
                flagged: false,
            },
        };
        let items = vec![item(Segment::line([0.0, 0.0], [3.0, 4.0]).unwrap())];
        let t = Tolerance::of(&items);
        assert_eq!(t.join, 5e-9);
        assert_eq!(t.near, 5e-4);
        // Far from the origin the rounding of the coordinates rules.
        let items = vec![item(Segment::line([1e9, 0.0], [1e9 + 3.0, 4.0]).unwrap())];
        let t = Tolerance::of(&items);
        assert!(t.join > 1e-6, "{}", t.join);
    }
}
