//! The disk tests of the closed-form paths: a disk's emptiness in closed form where the
//! boundaries are few (and where each arc's exact form is its circle), and the disks along
//! two lines' bisector proven empty at once by the polygon that covers their sweep.

use super::{ClosedFormSegment, LinesAndArcs, Solved};
use crate::candidates::Vertex;
use crate::sites::{Disk, EMPTY_SLACK};
use crate::true_sites::{LineSite, TrueSite};
use curve::V2;
use geometry::ProfileClearance;
use numeric::rounding::ulps;

/// How far (a share of the size) an arc's exact form may stray from its circle for the
/// closed-form disk test to measure it on the circle: far below the disks' slack.
const ON_CIRCLE: f64 = 1e-11;

/// Whether the exact form of arc `s` is its circle, to [`ON_CIRCLE`] of `size`: each rational
/// quadratic piece's end control points on the circle, its middle one at the radius over
/// the cosine of its half-angle on the bisector, with that cosine its weight relative to the
/// ends' (as the arc's pieces are built). Those make the piece the circle exactly; so near
/// them, it strays by about as much.
pub(super) fn on_its_circle(s: &curve::Segment, size: f64) -> bool {
    let Some((centre, radius)) = s.circle() else {
        return false;
    };
    let centre = V2::from_arr(centre);
    let rational = s.curve().curve();
    let (points, weights) = (s.curve().control_points(), rational.weights());
    if points.len() < 3 || points.len() % 2 == 0 || weights.len() != points.len() {
        return false;
    }
    let room = ON_CIRCLE * size;
    points
        .windows(3)
        .step_by(2)
        .zip(weights.windows(3).step_by(2))
        .all(|(p, w)| {
            let [a, m, b] = [p[0], p[1], p[2]].map(V2::from_arr);
            let (ua, ub) = (a - centre, b - centre);
            let half = 0.5 * ua.cross(ub).atan2(ua.dot(ub));
            let bisector = (ua + ub) * (1.0 / (ua + ub).norm());
            let middle = centre + bisector * (radius / half.cos());
            let weight = w[1] / w[0];
            (ua.norm() - radius).abs() <= room
                && (ub.norm() - radius).abs() <= room
                && (m - middle).norm() <= room
                && (weight - half.cos()).abs() * radius <= room
                && (w[2] - w[0]).abs() <= 1e-12 * w[0].abs()
        })
}

/// A convex polygon (its corners in turning order) that covers the band between the points
/// of tangency of two disks with lines `a` and `b`: centres `c` on the bisector of the lines
/// (`c[0]` nearer their meeting point, if any), radii `r` their distances to the lines, each
/// disk less `slack`. Its corners are the centres and, on each line's side and for each
/// centre, the point on the ray from the centre to its foot at half the slack from the line,
/// moved a quarter of the slack either way along the line: the tangency points of the
/// smaller disks lie on those rays, a further half of the slack in, and the room covers
/// their rounding. Every corner stays at least a quarter of the slack off both lines.
pub(super) fn sweep_polygon(c: [V2; 2], r: [f64; 2], lines: [LineSite; 2], slack: f64) -> [V2; 10] {
    let towards = c[1] - c[0];
    let along = |l: &LineSite| l.along * l.along.dot(towards).signum();
    let (ta, tb) = (along(&lines[0]), along(&lines[1]));
    let at = |k: usize, l: &LineSite| c[k] - l.inward * (r[k] - 0.5 * slack);
    let (a0, a1) = (at(0, &lines[0]), at(1, &lines[0]));
    let (b0, b1) = (at(0, &lines[1]), at(1, &lines[1]));
    let g = 0.25 * slack;
    [
        a0 - ta * g,
        a0 + ta * g,
        a1 - ta * g,
        a1 + ta * g,
        c[1],
        b1 + tb * g,
        b1 - tb * g,
        b0 + tb * g,
        b0 - tb * g,
        c[0],
    ]
}

impl LinesAndArcs<'_, '_> {
    /// Whether the disk of `v` is empty, as the other paths test it (beside a convex corner
    /// that turns by little, the other side's distance is measured too: see
    /// [`entered_across_corner`](crate::corners::entered_across_corner)). A disk of radius
    /// nil (at a convex corner) holds nothing.
    pub(super) fn empty(&self, v: &Vertex) -> bool {
        v.radius == 0.0 || self.disk_is_empty(V2::from_arr(v.xy), v.radius)
    }

    /// Whether the disk about `x` of radius `radius` (less the slack) holds no boundary
    /// point: proven in closed form where the boundaries are few, else (or where that proof
    /// fails) on the boundaries' control hulls as the other paths test it.
    pub(super) fn disk_is_empty(&self, x: V2, radius: f64) -> bool {
        (self.few && self.clear_in_closed_form(x, radius))
            || self.sites.disk(x.arr(), radius) == Disk::Empty
    }

    /// Whether every point of the boundaries is at least `radius` less the slack from `x`,
    /// by its distance in closed form with a bound on its rounding: each segment's ends',
    /// and each line's or arc's where the foot of `x` falls on it (else its nearest point
    /// is an end). A foot misjudged on or off near an end moves the distance by rounding
    /// only: the end there is as far, to rounding, as the nearest point. (Each segment's
    /// own ends: a joint may leave a gap of up to 1e-9 of the size.)
    pub(super) fn clear_in_closed_form(&self, x: V2, radius: f64) -> bool {
        let slack = EMPTY_SLACK * self.sites.size;
        let magnitude = |p: V2| p.x.abs().max(p.y.abs());
        let scale = magnitude(x) + radius;
        // (Each distance to within 16 ulps of the magnitudes in it.)
        let clear = |d: f64, at: f64| d >= radius - slack + ulps(16.0) * (scale + at);
        self.pieces.iter().flatten().all(|piece| match *piece {
            ClosedFormSegment::Line(l) => {
                let at = magnitude(l.start) + l.length;
                let end = l.start + l.along * l.length;
                clear((x - l.start).norm(), at)
                    && clear((x - end).norm(), at)
                    && (!piece.falls_on(x) || clear(l.inward.dot(x - l.start).abs(), at))
            }
            ClosedFormSegment::Arc { arc, start, end } => {
                let at = magnitude(arc.centre) + arc.radius;
                clear((x - start).norm(), magnitude(start))
                    && clear((x - end).norm(), magnitude(end))
                    && (!piece.falls_on(x)
                        || clear(((x - arc.centre).norm() - arc.radius).abs(), at))
            }
        })
    }

    /// Whether the disks along the straight bisector of two lines between its ends (each
    /// less the slack of the disk tests) are all empty, proven at once. Their centres and
    /// radii move linearly (the radii interpolated from the ends'), so they sweep the convex
    /// hull of the two end disks: the end disks themselves (tested when the ends were solved)
    /// and the band between their points of tangency with the lines, which [`sweep_polygon`]
    /// covers. That polygon is tested against the boundary's lines by separating axes.
    /// `false` where not proven (ends off the bisector beyond rounding, a line near the
    /// polygon): its disks are then tested one by one.
    pub(super) fn sweep_is_empty(&self, sites: [TrueSite; 2], ends: [Solved; 2]) -> bool {
        let (Some(&l0), Some(&l1)) = (self.line(sites[0]), self.line(sites[1])) else {
            return false;
        };
        let slack = EMPTY_SLACK * self.sites.size;
        let [mut p, q] = ends;
        let q = if p.radius > q.radius {
            std::mem::replace(&mut p, q)
        } else {
            q
        };
        if q.radius <= slack {
            return true; // (every disk less the slack is empty: none has a point)
        }
        // (From where the disks less the slack begin to hold points.)
        if p.radius < slack {
            p.xy = p.xy + (q.xy - p.xy) * ((slack - p.radius) / (q.radius - p.radius));
            p.radius = slack;
        }
        let polygon =
            sweep_polygon([p.xy, q.xy], [p.radius, q.radius], [l0, l1], slack).map(V2::arr);
        self.sites
            .boundaries
            .iter()
            .all(|b| b.misses_convex_polygon(&polygon))
    }

    /// Whether `e` lies on the bisector of two lines with its radius their distance, to
    /// rounding. (An end solved on other equations may lie off it by their agreement.)
    pub(super) fn on_bisector(&self, sites: [TrueSite; 2], e: &Solved) -> bool {
        let x = e.xy;
        let room = ulps(64.0) * (x.x.abs().max(x.y.abs()) + e.radius);
        sites.iter().all(|&s| {
            self.line(s)
                .is_some_and(|l| (l.inward.dot(x - l.start) - e.radius).abs() <= room)
        })
    }
}
