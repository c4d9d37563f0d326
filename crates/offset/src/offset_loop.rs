//! The offset's loops as they are handed out: pieces that are lines, arcs or fitted
//! B-splines, and their views as polylines and profiles.

use bspline::knots::basis_at;
use curve::{Profile, Segment, SegmentKind, SplineCurve};
use geometry::Flatten;
use serde::{Deserialize, Serialize};

/// One piece of an offset loop.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum OffsetSegment {
    /// A straight line.
    Line {
        /// Start.
        from: [f64; 2],
        /// End.
        to: [f64; 2],
    },
    /// A circular arc, counterclockwise when `end > start`.
    Arc {
        /// Centre.
        center: [f64; 2],
        /// Radius.
        r: f64,
        /// Start angle (radians).
        start: f64,
        /// End angle.
        end: f64,
    },
    /// The offset of a spline, as a B-spline within the chord tolerance of it where
    /// measured: a fitted cubic, or where none fits, the polyline (degree 1) of points on the
    /// exact offset.
    #[serde(rename = "bspline")]
    BSpline {
        /// The degree.
        degree: usize,
        /// The knots on `[0, 1]`, clamped: `points.len() + degree + 1` of them.
        knots: Vec<f64>,
        /// The control points.
        points: Vec<[f64; 2]>,
    },
}

/// A closed loop of an offset: counterclockwise round an outer part, clockwise round a hole.
/// In JSON, a closed `profile` document.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename = "profile")]
pub struct OffsetLoop {
    /// The pieces, each starting where the one before ends.
    pub segments: Vec<OffsetSegment>,
    /// The part of a multi-part input it belongs to (absent for one part).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub part: Option<usize>,
}

impl OffsetLoop {
    /// The loop as a closed polyline for drawing: lines as they are, each arc by `arc_points`
    /// chords, each B-spline by `arc_points` chords a knot span (a polyline's by its points);
    /// the first point again at the end.
    pub fn polyline(&self, arc_points: usize) -> Vec<[f64; 2]> {
        let arc_points = arc_points.max(1);
        let mut points = Vec::new();
        for s in &self.segments {
            match s {
                OffsetSegment::Line { from, to } => points.extend([*from, *to]),
                OffsetSegment::Arc {
                    center,
                    r,
                    start,
                    end,
                } => points.extend((0..=arc_points).map(|k| {
                    let a = start + (end - start) * k as f64 / arc_points as f64;
                    [center[0] + r * a.cos(), center[1] + r * a.sin()]
                })),
                OffsetSegment::BSpline {
                    degree: 1,
                    points: p,
                    ..
                } => points.extend(p.iter().copied()),
                OffsetSegment::BSpline {
                    degree,
                    knots,
                    points: p,
                } => {
                    let n = arc_points * (p.len() - degree);
                    points.extend((0..=n).map(|k| {
                        let (first, basis) = basis_at(*degree, knots, k as f64 / n as f64);
                        basis.iter().enumerate().fold([0.0; 2], |acc, (j, b)| {
                            [acc[0] + b * p[first + j][0], acc[1] + b * p[first + j][1]]
                        })
                    }));
                }
            }
        }
        if let Some(&first) = points.first() {
            points.push(first);
        }
        points
    }

    /// The loop as a closed profile, to be measured, drawn or offset again (with
    /// [`curve::Region::nested`] for the regions the loops bound).
    pub fn profile(&self) -> Result<Profile, curve::Error> {
        Profile::new(self.exact_segments()?, Some(true))
    }

    /// The loop as a closed polyline within `tol` of it, every vertex on it (a loop that
    /// touches itself at a neck, which no profile may, included).
    pub fn flattened(&self, tol: f64) -> Result<Vec<[f64; 2]>, curve::Error> {
        let mut points: Vec<[f64; 2]> = Vec::new();
        for s in self.exact_segments()? {
            let piece = s.flattened(tol);
            let skip = usize::from(points.last() == piece.first());
            points.extend(piece.into_iter().skip(skip));
        }
        // (Closed exactly: the last piece ends where the first starts, up to rounding.)
        if let Some(&first) = points.first() {
            let end = points.len() - 1;
            points[end] = first;
        }
        Ok(points)
    }

    /// The pieces as the curve model's segments.
    fn exact_segments(&self) -> Result<Vec<Segment>, curve::Error> {
        let mut segments = Vec::new();
        for s in &self.segments {
            match s {
                OffsetSegment::Line { from, to } => segments.push(Segment::line(*from, *to)?),
                OffsetSegment::Arc {
                    center,
                    r,
                    start,
                    end,
                } => segments.push(Segment::arc(*center, *r, *start, *end)?),
                OffsetSegment::BSpline {
                    degree,
                    knots,
                    points,
                } => segments.push(Segment::spline(
                    SegmentKind::BSpline,
                    SplineCurve::clamped(*degree, points, None, Some(knots.clone()))?,
                )?),
            }
        }
        Ok(segments)
    }
}
