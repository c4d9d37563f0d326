//! Knot spans of a curve that are straight, and which pairs of them lie on one line.
//!
//! The bisector function of two pieces of one line vanishes identically (every pair of
//! their points has parallel normals and no point on both at equal distance), so its cells
//! hold no bisector point, only rounding noise that the extractor would grind through until
//! its patch bound, and the whole bisector would say `complete: false`. A spline with a
//! straight span (a polyline drawn as a degree-1 B-spline, a slot's flat side inside one
//! NURBS) has such a cell on the diagonal of its self-bisector, and one for every other span
//! on the same line. Those cells are skipped.

use bspline::Rational;

/// A span whose control points lie within this share of the curves' size of the line
/// through its ends is straight: control points from data are exact or rounded to ~1e-16
/// of the coordinates, and the bisector of pieces that far from one line lies at ~1e12
/// sizes or within ~1e-12 of them, beyond or below any chord tolerance.
const STRAIGHT: f64 = 1e-12;

/// The line a straight span lies on: a point of it and its unit direction.
#[derive(Debug, Clone, Copy)]
struct Line {
    at: [f64; 2],
    along: [f64; 2],
}

impl Line {
    fn distance(&self, p: [f64; 2]) -> f64 {
        ((p[0] - self.at[0]) * self.along[1] - (p[1] - self.at[1]) * self.along[0]).abs()
    }
}

/// The knot spans of a curve, each with its line where it is straight.
pub(super) struct StraightSpans {
    breaks: Vec<f64>,
    lines: Vec<Option<(Line, [[f64; 2]; 2])>>,
    tol: f64,
}

impl StraightSpans {
    /// The spans of `c`, straight to `STRAIGHT` of `size`.
    pub(super) fn of(c: &Rational, size: f64) -> Self {
        let breaks = c.homogeneous().breakpoints();
        let tol = STRAIGHT * size;
        let lines = breaks
            .windows(2)
            .map(|w| {
                let span = c.restrict(w[0], w[1]).ok()?;
                if !span.weights().iter().all(|&w| w > 0.0) {
                    return None;
                }
                let pts: Vec<[f64; 2]> =
                    span.control_points().iter().map(|p| [p[0], p[1]]).collect();
                let (a, b) = (pts[0], pts[pts.len() - 1]);
                let len = (b[0] - a[0]).hypot(b[1] - a[1]);
                if len.is_nan() || len <= tol {
                    return None;
                }
                let line = Line {
                    at: a,
                    along: [(b[0] - a[0]) / len, (b[1] - a[1]) / len],
                };
                pts.iter()
                    .all(|&p| line.distance(p) <= tol)
                    .then_some((line, [a, b]))
            })
            .collect();
        Self { breaks, lines, tol }
    }

    /// The straight span holding parameters `[lo, hi]`, if any.
    fn span(&self, lo: f64, hi: f64) -> Option<(Line, [[f64; 2]; 2])> {
        let mid = 0.5 * (lo + hi);
        let k = self
            .breaks
            .windows(2)
            .position(|w| w[0] <= mid && mid <= w[1])?;
        self.lines[k]
    }

    /// Whether the span of these spans holding `[t0, t1]` and the span of `other` holding
    /// `[r0, r1]` are straight and on one line.
    pub(super) fn on_one_line(&self, t: [f64; 2], other: &Self, r: [f64; 2]) -> bool {
        match (self.span(t[0], t[1]), other.span(r[0], r[1])) {
            (Some((line, _)), Some((_, ends))) => {
                let tol = self.tol.max(other.tol);
                ends.iter().all(|&p| line.distance(p) <= tol)
            }
            _ => false,
        }
    }
}
