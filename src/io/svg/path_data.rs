//! SVG path data (`d`) as subpaths of exact segments: lines, quadratic and cubic Béziers, and
//! elliptical arcs converted from SVG's endpoint form to their centre form (SVG 1.1, Appendix
//! F.6.5, with the out-of-range radii corrected as F.6.6 says) and made exact rational
//! quadratic pieces. The syntax is `svgtypes`'; the geometry is ours.
//!
//! **Closing.** A subpath whose end comes back to its start within the drawing's tolerance is
//! closed, with or without `Z` (the contract's "Closed chains in drawings"): its last segment
//! is made to end exactly there. The tolerance is what the numbers as written can hide: a
//! writer that rounds to `k` decimals leaves each coordinate within half a unit of the last
//! place, and relative commands add those roundings up, one per command since the last
//! absolute one ([`Precision`]). It never exceeds [`MOST_GAP`] of the subpath's size, nor
//! falls below a few units of rounding of its coordinates. Beyond it, `Z` draws the closing
//! line, and so does a filled element's open subpath (SVG fills it as closed); a subpath of an
//! element drawn without fill stays open.
//!
//! **Degenerate pieces.** Zero-length pieces are dropped (design tools write them), and a
//! quadratic whose control point repeats an end, or a cubic with three points at one place,
//! is the straight line it draws (its speed vanishes at that end, which no curvature-based
//! method can take). A cubic whose inner control point repeats an end has that point moved
//! off it by half a unit in the last place written (see `bezier`).

use curve::{Segment, SegmentKind, SplineCurve, V2};
use numeric::rounding::ulps;
use std::f64::consts::{PI, TAU};
use svgtypes::{PathParser, PathSegment};

/// Room for rounding (in units of the largest coordinate) in any gap: relative commands
/// accumulate a rounding per command even where the numbers are written in full.
const CLOSING_ROUNDING: f64 = ulps(1024.0);

/// The largest gap closed, relative to the subpath's size: rounding of the written numbers
/// beyond a thousandth of the outline is not rounding but a gap drawn.
const MOST_GAP: f64 = 1e-3;

/// How close to 1 (relative) SVG's radius ratio `Λ` must be for the arc to be taken as
/// reaching just across its chord (F.6.6): the centre is then the chord's middle exactly.
/// Below that, the centre's offset `√(1/Λ − 1)` of the radius magnifies the rounding of `Λ`
/// (a few units) into a tangent off by ~1e-8 rad at the ends, which would read as a corner.
const HALF_ELLIPSE: f64 = ulps(64.0);

/// The largest share of the way to the next control point that a handle on a cubic's end is
/// moved off it (see `Builder::bezier`).
const HANDLE_OFF_END: f64 = 1e-2;

/// One subpath: its segments, and whether it is closed.
#[derive(Debug)]
pub(super) struct Subpath {
    pub(super) segments: Vec<Segment>,
    pub(super) closed: bool,
}

/// Why path data could not be used: a message for the reader's error.
pub(super) type PathError = String;

/// The subpaths of path data `d`, in the element's own coordinates; `filled`: the element is
/// filled, so an open subpath is closed by a line as SVG fills it. `max_segments` bounds the
/// work.
pub(super) fn subpaths(
    d: &str,
    filled: bool,
    max_segments: usize,
) -> Result<Vec<Subpath>, PathError> {
    subpaths_written(d, Precision::of(d), filled, max_segments)
}

/// [`subpaths`] of path data made from numbers written with `precision` (a shape's
/// attributes, as path data).
pub(super) fn subpaths_written(
    d: &str,
    precision: Precision,
    filled: bool,
    max_segments: usize,
) -> Result<Vec<Subpath>, PathError> {
    let mut b = Builder {
        quantum: precision.quantum,
        filled,
        ..Builder::default()
    };
    for (k, item) in PathParser::from(d).enumerate() {
        let seg = item.map_err(|e| format!("invalid path data: {e}"))?;
        b.command(seg).map_err(|e| format!("command {k}: {e}"))?;
        if b.count > max_segments {
            return Err(format!("more than {max_segments} segments"));
        }
    }
    b.finish_subpath(false)?;
    Ok(b.out)
}

/// How finely the numbers of path data are written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Precision {
    /// A unit in the last decimal place written, over all the numbers (`10^−k` for `k`
    /// decimals at most; 1 when all are integers).
    pub(super) quantum: f64,
}

impl Precision {
    /// The precision of the numbers in `text` (their decimals, less their exponents).
    pub(super) fn of(text: &str) -> Self {
        let bytes = text.as_bytes();
        let mut places = 0i32;
        let mut i = 0;
        while i < bytes.len() {
            if !(bytes[i].is_ascii_digit() || bytes[i] == b'.') {
                i += 1;
                continue;
            }
            // One number: digits, a point, digits, an exponent.
            let mut decimals = 0i32;
            let mut seen_point = false;
            while i < bytes.len()
                && (bytes[i].is_ascii_digit() || (bytes[i] == b'.' && !seen_point))
            {
                if bytes[i] == b'.' {
                    seen_point = true;
                } else if seen_point {
                    decimals += 1;
                }
                i += 1;
            }
            if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
                let start = i + 1;
                let mut j = start;
                if j < bytes.len() && (bytes[j] == b'-' || bytes[j] == b'+') {
                    j += 1;
                }
                while j < bytes.len() && bytes[j].is_ascii_digit() {
                    j += 1;
                }
                let exponent: i32 = text[start..j].parse().unwrap_or(0);
                decimals -= exponent;
                i = j;
            }
            places = places.max(decimals.clamp(0, 300));
        }
        Self {
            quantum: 10f64.powi(-places),
        }
    }
}

/// The state of the path data walk.
#[derive(Default)]
struct Builder {
    out: Vec<Subpath>,
    current: Vec<Segment>,
    /// The current point and the current subpath's start.
    at: V2,
    start: V2,
    /// The last control point of a previous cubic (for `S`) or quadratic (for `T`).
    last_cubic: Option<V2>,
    last_quad: Option<V2>,
    count: usize,
    /// A unit in the last place of the numbers written.
    quantum: f64,
    /// Relative commands since the current point was last written absolutely.
    relative: usize,
    /// Whether the element is filled.
    filled: bool,
}

impl Builder {
    fn command(&mut self, seg: PathSegment) -> Result<(), String> {
        let at = self.at;
        let pt = |abs: bool, x: f64, y: f64| -> Result<V2, String> {
            let p = if abs {
                V2::new(x, y)
            } else {
                V2::new(at.x + x, at.y + y)
            };
            finite(p)
        };
        let (mut cubic, mut quad) = (None, None);
        // (Each relative command adds a rounding of the numbers to the current point; an
        // absolute one sets it as written.)
        let relative = match seg {
            PathSegment::MoveTo { abs, .. }
            | PathSegment::LineTo { abs, .. }
            | PathSegment::HorizontalLineTo { abs, .. }
            | PathSegment::VerticalLineTo { abs, .. }
            | PathSegment::CurveTo { abs, .. }
            | PathSegment::SmoothCurveTo { abs, .. }
            | PathSegment::Quadratic { abs, .. }
            | PathSegment::SmoothQuadratic { abs, .. }
            | PathSegment::EllipticalArc { abs, .. } => !abs,
            PathSegment::ClosePath { .. } => false,
        };
        match seg {
            PathSegment::MoveTo { abs, x, y } => {
                self.finish_subpath(false)?;
                let p = pt(abs, x, y)?;
                self.at = p;
                self.start = p;
            }
            PathSegment::LineTo { abs, x, y } => self.line(pt(abs, x, y)?)?,
            PathSegment::HorizontalLineTo { abs, x } => {
                let to = if abs { x } else { at.x + x };
                self.line(finite(V2::new(to, at.y))?)?;
            }
            PathSegment::VerticalLineTo { abs, y } => {
                let to = if abs { y } else { at.y + y };
                self.line(finite(V2::new(at.x, to))?)?;
            }
            PathSegment::CurveTo {
                abs,
                x1,
                y1,
                x2,
                y2,
                x,
                y,
            } => {
                let (c1, c2, to) = (pt(abs, x1, y1)?, pt(abs, x2, y2)?, pt(abs, x, y)?);
                self.bezier(&[at, c1, c2, to])?;
                cubic = Some(c2);
            }
            PathSegment::SmoothCurveTo { abs, x2, y2, x, y } => {
                // The first control point mirrors the previous cubic's second one.
                let c1 = self.last_cubic.map_or(at, |c| at * 2.0 - c);
                let (c2, to) = (pt(abs, x2, y2)?, pt(abs, x, y)?);
                self.bezier(&[at, c1, c2, to])?;
                cubic = Some(c2);
            }
            PathSegment::Quadratic { abs, x1, y1, x, y } => {
                let (c, to) = (pt(abs, x1, y1)?, pt(abs, x, y)?);
                self.bezier(&[at, c, to])?;
                quad = Some(c);
            }
            PathSegment::SmoothQuadratic { abs, x, y } => {
                let c = self.last_quad.map_or(at, |c| at * 2.0 - c);
                let to = pt(abs, x, y)?;
                self.bezier(&[at, c, to])?;
                quad = Some(c);
            }
            PathSegment::EllipticalArc {
                abs,
                rx,
                ry,
                x_axis_rotation,
                large_arc,
                sweep,
                x,
                y,
            } => {
                let to = pt(abs, x, y)?;
                self.arc(to, rx, ry, x_axis_rotation, large_arc, sweep)?;
            }
            PathSegment::ClosePath { .. } => {
                let start = self.start;
                self.finish_subpath(true)?;
                self.at = start;
            }
        }
        match (relative, &seg) {
            // (After `Z` the current point is the start, as written before.)
            (_, PathSegment::ClosePath { .. }) => {}
            (true, _) => self.relative += 1,
            (false, _) => self.relative = 0,
        }
        self.last_cubic = cubic;
        self.last_quad = quad;
        Ok(())
    }

    fn push(&mut self, seg: Segment, to: V2) {
        self.current.push(seg);
        self.count += 1;
        self.at = to;
    }

    fn line(&mut self, to: V2) -> Result<(), String> {
        if to == self.at {
            return Ok(());
        }
        let seg = Segment::line(self.at.arr(), to.arr()).map_err(|e| e.to_string())?;
        self.push(seg, to);
        Ok(())
    }

    fn bezier(&mut self, pts: &[V2]) -> Result<(), String> {
        let to = pts[pts.len() - 1];
        // (All control points at one place: nothing drawn.)
        if pts.iter().all(|&p| p == self.at) {
            return Ok(());
        }
        // A control point on an end (a quadratic's), or three points at one place (a cubic's):
        // the piece is the straight line between its ends.
        let distinct = pts.windows(2).filter(|w| w[0] != w[1]).count();
        let straight = match pts.len() {
            3 => distinct < 2,
            _ => distinct < 2 && pts[0] != pts[pts.len() - 1],
        };
        if straight {
            return self.line(to);
        }
        // A cubic's control point on its end (a node drawn without a handle) leaves it no
        // speed there, and a curvature growing without bound: moved off the end towards the
        // next control point by half a unit in the last place written, a change the numbers
        // as written cannot tell from it, and never more than a hundredth of the way (the
        // curve then moves by less than half of that).
        let mut pts = pts.to_vec();
        if pts.len() == 4 {
            let half_unit = 0.5 * self.quantum;
            let off = |end: V2, toward: V2| {
                let d = toward - end;
                end + d * (half_unit / d.norm()).min(HANDLE_OFF_END)
            };
            if pts[1] == pts[0] {
                pts[1] = off(pts[0], pts[2]);
            }
            if pts[2] == pts[3] {
                pts[2] = off(pts[3], pts[1]);
            }
        }
        let arr: Vec<[f64; 2]> = pts.iter().map(|p| p.arr()).collect();
        let c = SplineCurve::clamped(arr.len() - 1, &arr, None, None).map_err(|e| e.to_string())?;
        let seg = Segment::spline(SegmentKind::Bezier, c).map_err(|e| e.to_string())?;
        self.push(seg, to);
        Ok(())
    }

    /// SVG's elliptical arc from the current point to `to` (F.6.5, F.6.6).
    fn arc(
        &mut self,
        to: V2,
        rx: f64,
        ry: f64,
        rotation_deg: f64,
        large: bool,
        sweep: bool,
    ) -> Result<(), String> {
        let from = self.at;
        if from == to {
            return Ok(());
        }
        let (mut rx, mut ry) = (rx.abs(), ry.abs());
        if !(rx.is_finite() && ry.is_finite() && rotation_deg.is_finite()) {
            return Err("an arc's radii and rotation must be finite".into());
        }
        // A zero radius makes the arc a straight line (F.6.6).
        if rx == 0.0 || ry == 0.0 {
            return self.line(to);
        }
        let phi = rotation_deg.to_radians();
        let (s, c) = phi.sin_cos();
        let half = (from - to) * 0.5;
        let x1 = c * half.x + s * half.y;
        let y1 = -s * half.x + c * half.y;
        // Radii too small to reach: scaled up until they just do.
        let lambda = (x1 / rx).powi(2) + (y1 / ry).powi(2);
        if lambda >= 1.0 - HALF_ELLIPSE {
            let k = lambda.sqrt();
            rx *= k;
            ry *= k;
        }
        let mid = (from + to) * 0.5;
        let angle = |ux: f64, uy: f64| uy.atan2(ux);
        let (center, theta1, delta) = if lambda >= 1.0 - HALF_ELLIPSE {
            // Just across the chord: half the ellipse about the chord's middle, exactly.
            let theta1 = angle(x1 / rx, y1 / ry);
            (mid, theta1, if sweep { PI } else { -PI })
        } else {
            let (rx2, ry2) = (rx * rx, ry * ry);
            let num = rx2 * ry2 - rx2 * y1 * y1 - ry2 * x1 * x1;
            let den = rx2 * y1 * y1 + ry2 * x1 * x1;
            let mut coef = (num / den).max(0.0).sqrt();
            if large == sweep {
                coef = -coef;
            }
            let (cx1, cy1) = (coef * rx * y1 / ry, -coef * ry * x1 / rx);
            let center = V2::new(c * cx1 - s * cy1 + mid.x, s * cx1 + c * cy1 + mid.y);
            let theta1 = angle((x1 - cx1) / rx, (y1 - cy1) / ry);
            let theta2 = angle((-x1 - cx1) / rx, (-y1 - cy1) / ry);
            let mut delta = (theta2 - theta1).rem_euclid(TAU);
            if !sweep && delta > 0.0 {
                delta -= TAU;
            }
            (center, theta1, delta)
        };
        let seg = Segment::elliptic_arc(center.arr(), rx, ry, phi, theta1, theta1 + delta)
            .map_err(|e| e.to_string())?;
        self.push(seg, to);
        Ok(())
    }

    /// The gap the current subpath may leave between its end and its start and still be
    /// closed (see the module documentation).
    fn closing_tolerance(&self) -> f64 {
        let (mut lo, mut hi) = (self.start, self.start);
        let mut magnitude = self.start.x.abs().max(self.start.y.abs());
        for p in self.current.iter().flat_map(|s| s.curve().control_points()) {
            lo = V2::new(lo.x.min(p[0]), lo.y.min(p[1]));
            hi = V2::new(hi.x.max(p[0]), hi.y.max(p[1]));
            magnitude = magnitude.max(p[0].abs()).max(p[1].abs());
        }
        let size = (hi.x - lo.x).max(hi.y - lo.y);
        let written = self.quantum * (self.relative + 1) as f64;
        written
            .min(MOST_GAP * size)
            .max(CLOSING_ROUNDING * magnitude)
    }

    /// Ends the current subpath: closed where `z` says so, where it comes back to its start
    /// within the tolerance (its last segment then ends exactly there), or where the element
    /// is filled (a closing line, as SVG fills it).
    fn finish_subpath(&mut self, z: bool) -> Result<(), String> {
        if self.current.is_empty() {
            return Ok(());
        }
        let gap = (self.at - self.start).norm();
        let closed = if gap == 0.0 {
            true
        } else if gap <= self.closing_tolerance() {
            self.snap_to_start()?;
            true
        } else if z || self.filled {
            self.line(self.start)?;
            true
        } else {
            false
        };
        self.out.push(Subpath {
            segments: std::mem::take(&mut self.current),
            closed,
        });
        Ok(())
    }

    /// Closes a gap within the tolerance: the last segment made to end at the start (or, where
    /// it is an arc and the first is not, the first made to start at the end: an arc whose end
    /// moves is no longer circular).
    fn snap_to_start(&mut self) -> Result<(), String> {
        let n = self.current.len();
        let is_arc = |s: &Segment| matches!(s.kind(), SegmentKind::Arc | SegmentKind::EllipticArc);
        let moved = if is_arc(&self.current[n - 1]) && !is_arc(&self.current[0]) {
            let at = self.at;
            (0, self.current[0].with_ends(Some(at), None))
        } else {
            let start = self.start;
            (n - 1, self.current[n - 1].with_ends(None, Some(start)))
        };
        match moved {
            (k, Ok(s)) => self.current[k] = s,
            // (A last line shorter than the gap, back to the start: it goes, and the one before
            // closes the gap.)
            (k, Err(_)) if n > 1 && k == n - 1 => {
                self.at = self.current[n - 1].start();
                self.current.pop();
                return self.snap_to_start();
            }
            (_, Err(e)) => return Err(e.to_string()),
        }
        Ok(())
    }
}

/// A point with finite coordinates.
fn finite(p: V2) -> Result<V2, String> {
    if p.x.is_finite() && p.y.is_finite() {
        Ok(p)
    } else {
        Err(format!(
            "coordinates must be finite, got ({}, {})",
            p.x, p.y
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use curve::ParamCurve;

    fn one(d: &str) -> Vec<Subpath> {
        subpaths(d, false, 1000).unwrap_or_else(|e| panic!("{d}: {e}"))
    }

    #[test]
    fn relative_and_absolute_commands_agree() {
        let abs = one(
            "M 10 10 L 20 10 H 30 V 20 C 30 30 20 30 20 20 S 10 10 10 15 Q 5 15 5 10 T 10 10 Z",
        );
        let rel = one(
            "m 10 10 l 10 0 h 10 v 10 c 0 10 -10 10 -10 0 s -10 -10 -10 -5 q -5 0 -5 -5 t 5 0 z",
        );
        assert_eq!(abs.len(), 1);
        assert!(abs[0].closed && rel[0].closed);
        assert_eq!(abs[0].segments.len(), rel[0].segments.len());
        for (a, r) in abs[0].segments.iter().zip(&rel[0].segments) {
            for k in 0..=4 {
                let x = k as f64 / 4.0;
                let (pa, pr) = (a.jet(x).p, r.jet(x).p);
                assert!((pa - pr).norm() < 1e-12, "{pa:?} {pr:?}");
            }
        }
    }

    #[test]
    fn smooth_commands_mirror_the_previous_control_point() {
        let s = one("M 0 0 C 0 1 1 1 1 0 S 2 -1 2 0");
        let second = s[0].segments[1].curve().control_points();
        assert_eq!(second[1], [1.0, -1.0]);
        // After a non-curve command the first control point is the current point: a handle on
        // the cubic's end, moved off it towards the next point by a hundredth of the way.
        let s = one("M 0 0 L 1 0 S 2 1 3 0");
        let first = V2::from_arr(s[0].segments[1].curve().control_points()[1]);
        assert!((first - V2::new(1.01, 0.01)).norm() < 1e-15, "{first:?}");
    }

    #[test]
    fn arcs_follow_the_flags_and_reach_their_end() {
        // A half circle of radius 1 from (0,0) to (2,0), each sweep, and the large-arc cases
        // of a radius-2 circle.
        for (d, y_mid) in [
            ("M 0 0 A 1 1 0 0 1 2 0", -1.0),
            ("M 0 0 A 1 1 0 0 0 2 0", 1.0),
        ] {
            let s = one(d);
            let arc = &s[0].segments[0];
            assert_eq!(arc.kind(), SegmentKind::Arc);
            let m = arc.jet(0.5).p;
            assert!(
                (m.x - 1.0).abs() < 1e-12 && (m.y - y_mid).abs() < 1e-12,
                "{d}: {m:?}"
            );
            assert!((arc.end() - V2::new(2.0, 0.0)).norm() < 1e-12);
        }
        let small = one("M 0 0 A 2 2 0 0 1 2 0");
        let large = one("M 0 0 A 2 2 0 1 1 2 0");
        let len = |s: &Segment| {
            (0..4096)
                .map(|k| (s.jet((k + 1) as f64 / 4096.0).p - s.jet(k as f64 / 4096.0).p).norm())
                .sum::<f64>()
        };
        let (a, b) = (len(&small[0].segments[0]), len(&large[0].segments[0]));
        assert!(
            (a + b - 2.0 * std::f64::consts::PI * 2.0).abs() < 1e-5,
            "{a} + {b}"
        );
        assert!((a - 2.0 * std::f64::consts::PI / 3.0).abs() < 1e-5, "{a}");
        // Radii too small are scaled up: a half circle.
        let s = one("M 0 0 A 0.1 0.1 0 0 1 2 0");
        assert!((s[0].segments[0].jet(0.5).p - V2::new(1.0, -1.0)).norm() < 1e-12);
        // Zero radius: a line.
        let s = one("M 0 0 A 0 1 0 0 1 2 0");
        assert_eq!(s[0].segments[0].kind(), SegmentKind::Line);
    }

    #[test]
    fn rotated_elliptic_arcs_pass_through_their_ends() {
        let s = one("M 3 1 A 4 2 30 1 0 -1 2");
        let e = &s[0].segments[0];
        assert_eq!(e.kind(), SegmentKind::EllipticArc);
        assert!((e.start() - V2::new(3.0, 1.0)).norm() < 1e-12);
        assert!((e.end() - V2::new(-1.0, 2.0)).norm() < 1e-12);
    }

    #[test]
    fn subpaths_split_at_moves_and_closes() {
        let s = one("M 0 0 L 1 0 L 1 1 Z M 5 5 L 6 5 L 6 6 z L 7 7");
        assert_eq!(s.len(), 3);
        assert!(s[0].closed && s[1].closed && !s[2].closed);
        // After Z the next command starts from the closed subpath's start.
        assert_eq!(s[2].segments[0].start(), V2::new(5.0, 5.0));
        // Zero-length pieces are dropped; the closing line is drawn only where needed.
        let s = one("M 0 0 L 0 0 L 1 0 L 0 1 L 0 0 Z");
        assert_eq!(s[0].segments.len(), 3);
    }

    #[test]
    fn bad_path_data_is_an_error_not_a_panic() {
        for d in [
            "L 1 1",
            "M 0 0 L",
            "M 0 0 X 1 1",
            "M 1e400 0 L 1 1",
            "M 0 0 A 1 1 0 2 0 1 1",
        ] {
            assert!(subpaths(d, false, 1000).is_err(), "{d}");
        }
        assert!(subpaths("M 0 0 L 1 0 L 2 0 L 3 0", false, 2).is_err());
    }
}
