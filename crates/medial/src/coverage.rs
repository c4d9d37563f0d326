//! Completeness by the feet: every point of a boundary is the foot of exactly one point of
//! the axis (the centre of the one largest disk inside that touches the boundary there), and
//! at a reflex corner every direction between the two sides' normals is. So the feet of the
//! axis's edges, side by side, must cover each boundary once round, in order, each corner's
//! fan whole; together with the disks proven empty this shows that no piece of the axis is
//! missing, whatever pairs of sites its candidates came from.
//!
//! Each boundary is laid out on one line: its profile parameter, with every reflex corner
//! blown up into the angle its fan spans. The feet of one side of an edge run along that line
//! one way; their stretches, sorted, must follow one another with no gap and no overlap
//! beyond [`COVER_GAP`] of the size (nodes within a millionth of the size are one node, and
//! the feet of the edges meeting there agree only to that). The whole arc a disk at its
//! centre touches (a fillet's, where the axis has a point and no edge) is covered by that
//! node.

use crate::sites::Sites;
use crate::{MedialAxis, NodeKind};
use curve::{JointKind, ParamCurve, V2};
use numeric::rounding::ulps;

/// How far apart the ends of two stretches of feet that follow one another may lie (as a
/// share of the size, measured on the boundary and, in a fan, along the disk's rim): twice
/// the distance within which ends of the axis are one node.
const COVER_GAP: f64 = 2e-6;

/// A foot whose profile parameter lies this near a reflex corner's is at the corner (the
/// bisectors of a corner give its parameter exactly; a foot merely near it has moved on).
pub(crate) const FOOT_AT_REFLEX_CORNER: f64 = 1e-12;

/// Steps of the feet against the run of a side smaller than this (in the line's units) are
/// rounding, not a turn back.
const BACK_STEP: f64 = 1e-9;

/// A reflex corner's fan: where it sits on the line, the angle it spans, and the normal it
/// starts from (towards the axis), with the way it turns.
struct Fan {
    start: f64,
    angle: f64,
    from: V2,
    turn: f64,
}

/// One boundary laid out on a line.
struct Line {
    /// The boundary's index.
    boundary: usize,
    /// Segments.
    n: usize,
    /// Per segment, the fans' angles before it (its start on the line is `i + shift[i]`).
    shift: Vec<f64>,
    fans: Vec<Fan>,
    /// Where each segment starts on the line (`i + shift[i]`, increasing).
    starts: Vec<f64>,
    /// Per joint (the start of each segment), its fan's index in `fans`.
    fan_at: Vec<Option<usize>>,
    /// Where the convex corners (towards the axis) sit on the line: each the end of a leaf,
    /// which no side of an edge passes.
    convex: Vec<f64>,
    /// The line's length: segments and fans.
    length: f64,
}

impl Line {
    fn new(sites: &Sites<'_>, k: usize) -> Self {
        let b = sites.boundaries[k];
        let n = b.segments().len();
        let side = sites.inside_left(k);
        let mut shift = vec![0.0; n];
        let mut fans = Vec::new();
        let mut total = 0.0;
        let mut reflex = vec![None; n];
        let mut convex_at = Vec::new();
        for j in b.joints() {
            if j.kind != JointKind::Smooth {
                if j.turn * side < 0.0 {
                    reflex[j.u as usize % n] = Some(j.turn);
                } else {
                    convex_at.push(j.u as usize % n);
                }
            }
        }
        let mut fan_at = vec![None; n];
        for i in 0..n {
            if let Some(turn) = reflex[i] {
                fan_at[i] = Some(fans.len());
                let before = &b.segments()[(i + n - 1) % n];
                let d = before.end_direction().unwrap_or(V2::new(1.0, 0.0));
                fans.push(Fan {
                    start: i as f64 + total,
                    angle: turn.abs(),
                    from: d.perp() * side,
                    turn: turn.signum(),
                });
                total += turn.abs();
            }
            shift[i] = total;
        }
        let convex = convex_at.into_iter().map(|i| i as f64 + shift[i]).collect();
        let starts = (0..n).map(|i| i as f64 + shift[i]).collect();
        Self {
            boundary: k,
            n,
            starts,
            shift,
            fans,
            fan_at,
            convex,
            length: n as f64 + total,
        }
    }

    /// Whether a convex corner lies strictly between `lo` and `hi` past position `start` of
    /// the line, round it ([`marks_within`]).
    fn convex_within(&self, start: f64, lo: f64, hi: f64) -> bool {
        marks_within(&self.convex, self.length, start, lo, hi)
    }

    /// Where the foot at profile parameter `u`, seen from the axis point `x`, lies on the line
    /// (the foot's point is asked for only at a joint, where the direction from it tells the
    /// place in the joint's fan).
    fn place(&self, u: f64, foot: impl FnOnce() -> V2, x: V2) -> f64 {
        let n = self.n as f64;
        let u = u.rem_euclid(n);
        // (The nearest joint: one of a closed boundary's is at both 0 and n.)
        let joint = u.round();
        if (u - joint).abs() <= FOOT_AT_REFLEX_CORNER * n {
            if let Some(fan) = self.fan_at[joint as usize % self.n].map(|f| &self.fans[f]) {
                let d = x - foot();
                let phi = (fan.turn * fan.from.cross(d)).atan2(fan.from.dot(d));
                return fan.start + phi.clamp(0.0, fan.angle);
            }
        }
        let i = (u.floor() as usize).min(self.n - 1);
        u + self.shift[i]
    }

    /// The profile parameter at position `p` of the line (a fan's joint within its fan).
    fn param_at(&self, p: f64) -> f64 {
        let p = p.rem_euclid(self.length);
        // (Segment `i` starts at `i + shift[i]`, increasing with `i`.)
        let after = self.starts.partition_point(|&start| start <= p);
        let Some(i) = after.checked_sub(1) else {
            return 0.0; // in the fan of the first joint
        };
        (p - self.shift[i]).min((i + 1) as f64)
    }
}

/// One side of an edge (or a node's arc): the stretch of the line its feet cover.
struct CoveredRun {
    start: f64,
    length: f64,
    /// At each end: the foot, and the axis point's radius and direction from it.
    ends: [(V2, f64, V2); 2],
}

/// Whether the feet of `axis` cover every boundary of `sites` once round (see the module's
/// documentation); `Err` names what does not.
pub(crate) fn feet_cover(sites: &Sites<'_>, axis: &MedialAxis) -> Result<(), &'static str> {
    if axis.edges.is_empty() {
        return Err("the axis has no edge whose feet could cover the boundary");
    }
    let lines: Vec<Line> = (0..sites.boundaries.len())
        .map(|k| Line::new(sites, k))
        .collect();
    let mut stretches: Vec<Vec<CoveredRun>> = lines.iter().map(|_| Vec::new()).collect();
    for e in &axis.edges {
        for side in 0..2 {
            let k = e.boundary[0][side];
            if e.boundary.iter().any(|b| b[side] != k) {
                return Err("a side of an edge has feet on two boundaries");
            }
            side_stretches(sites, &lines[k], e, side, &mut stretches[k])?;
        }
    }
    arcs_at_nodes(sites, axis, &lines, &mut stretches);
    let gap = COVER_GAP * sites.size;
    for (line, mut s) in lines.iter().zip(stretches) {
        if s.is_empty() {
            return Err("a boundary is the foot of no edge");
        }
        for t in &mut s {
            t.start = t.start.rem_euclid(line.length);
            if line.convex_within(t.start, BACK_STEP, t.length - BACK_STEP) {
                return Err(
                    "the feet of a side of an edge pass a convex corner, whose leaf is missing",
                );
            }
        }
        s.sort_by(|a, b| a.start.total_cmp(&b.start));
        let mut covered = 0.0;
        for i in 0..s.len() {
            let (a, b) = (&s[i], &s[(i + 1) % s.len()]);
            let mut jump = b.start - (a.start + a.length);
            if i + 1 == s.len() {
                jump += line.length;
            }
            covered += a.length;
            if jump.abs() > BACK_STEP
                && !(ends_meet(a.ends[1], b.ends[0], gap)
                    && short_between(sites, line, a, b, gap)
                    && !convex_between(line, a, b))
            {
                return Err(if jump > 0.0 {
                    "the feet of the axis leave a stretch of the boundary uncovered"
                } else {
                    "the feet of the axis cover a stretch of the boundary twice"
                });
            }
        }
        // (Ends that meet, every one, and stretches once round: the length is the line's.)
        if (covered - line.length).abs() > 0.5 * line.length {
            return Err("the feet of the axis run round a boundary more than once");
        }
    }
    Ok(())
}

/// The stretch of the line the feet of side `side` of edge `e` cover, pushed on `out`.
/// (Feet that jump where the axis point stays, two stretches of the axis joined where a
/// third site touched the disk, are not joined: [`crate::assemble`] leaves the node, and
/// the gap shows here.)
fn side_stretches(
    sites: &Sites<'_>,
    line: &Line,
    e: &crate::Edge,
    side: usize,
    out: &mut Vec<CoveredRun>,
) -> Result<(), &'static str> {
    let k = e.boundary[0][side];
    let foot = |v: usize| V2::from_arr(sites.foot(k, e.feet[v][side]));
    let at = |v: usize| line.place(e.feet[v][side], || foot(v), V2::from_arr(e.xy[v]));
    let end = |v: usize| (foot(v), e.radius[v], V2::from_arr(e.xy[v]) - foot(v));
    let wrap = |d: f64| d - line.length * (d / line.length).round();
    let start = at(0);
    let (mut last, mut run, mut way) = (start, 0.0, 0.0f64);
    for v in 1..e.xy.len() {
        let here = at(v);
        let step = wrap(here - last);
        if step.abs() > BACK_STEP {
            if way != 0.0 && step.signum() != way {
                return Err("the feet of a side of an edge turn back");
            }
            way = step.signum();
        }
        run += step;
        last = here;
    }
    let ends = [end(0), end(e.xy.len() - 1)];
    out.push(if run >= 0.0 {
        CoveredRun {
            start,
            length: run,
            ends,
        }
    } else {
        CoveredRun {
            start: start + run,
            length: -run,
            ends: [ends[1], ends[0]],
        }
    });
    Ok(())
}

/// Whether a convex corner (towards the axis) of boundary `k` lies strictly between profile
/// parameters `a` and `b` (the short way round): the end of a leaf of the axis.
pub(crate) fn convex_corner_between(sites: &Sites<'_>, k: usize, a: f64, b: f64) -> bool {
    let boundary = sites.boundaries[k];
    let n = boundary.domain().1;
    let (lo, d) = short_way(boundary.is_closed(), n, a, b);
    let side = sites.inside_left(k);
    let length = if boundary.is_closed() {
        n
    } else {
        f64::INFINITY
    };
    any_between(
        boundary.joints(),
        |j| j.u,
        |j| j.kind != JointKind::Smooth && j.turn * side > 0.0,
        length,
        lo,
        FOOT_AT_REFLEX_CORNER * n,
        d - FOOT_AT_REFLEX_CORNER * n,
    )
}

/// The items of `sorted` (in increasing x of their points, `at`) whose x lies within `room`
/// of `x`'s: the candidates for a point within `room` of `x`.
pub(crate) fn within_in_x<'a, T>(
    sorted: &'a [T],
    at: impl Fn(&T) -> [f64; 2] + 'a,
    x: [f64; 2],
    room: f64,
) -> impl Iterator<Item = &'a T> + 'a {
    let first = sorted.partition_point(|c| at(c)[0] < x[0] - room);
    sorted[first..]
        .iter()
        .take_while(move |c| at(c)[0] <= x[0] + room)
}

/// A convex corner (towards the axis) that no corner node of an axis is at: the end of a
/// leaf of the true axis that the axis lacks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct UnreachedCorner {
    pub(crate) xy: [f64; 2],
    pub(crate) boundary: usize,
    /// The angle the boundary turns by there (radians).
    pub(crate) turn: f64,
}

/// The convex corners of the boundaries (towards the axis) that no corner node of `axis`
/// is at, to the merge distance of nodes.
pub(crate) fn unreached_convex_corners(
    sites: &Sites<'_>,
    axis: &MedialAxis,
) -> Vec<UnreachedCorner> {
    let near = crate::SAME_NODE * sites.size;
    let mut leaves: Vec<[f64; 2]> = axis
        .nodes
        .iter()
        .filter(|n| n.kind == NodeKind::Corner)
        .map(|n| n.xy)
        .collect();
    leaves.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let reached = |x: V2| {
        within_in_x(&leaves, |p| *p, x.arr(), near).any(|p| (V2::from_arr(*p) - x).norm() <= near)
    };
    let mut out = Vec::new();
    for (k, b) in sites.boundaries.iter().enumerate() {
        let side = sites.inside_left(k);
        let n = b.segments().len();
        for j in b.corners().filter(|j| j.turn * side > 0.0) {
            let at = b.segments()[j.u as usize % n].start();
            if !reached(at) {
                out.push(UnreachedCorner {
                    xy: at.arr(),
                    boundary: k,
                    turn: j.turn.abs(),
                });
            }
        }
    }
    out
}

/// Whether one of `marks` (increasing, in `[0, length)`) lies strictly between `lo` and
/// `hi` past `start` round a loop of `length` (`0 <= hi - lo` below the length).
fn marks_within(marks: &[f64], length: f64, start: f64, lo: f64, hi: f64) -> bool {
    any_between(marks, |&c| c, |_| true, length, start, lo, hi)
}

/// Whether an item that `hit`s, of `items` in increasing order of `at` (in `[0, length)`),
/// lies strictly between `lo` and `hi` past `start` round a loop of `length` (infinite: an
/// open line), `0 <= hi - lo` below the length: found by bisection, on either side of the
/// seam.
fn any_between<T>(
    items: &[T],
    at: impl Fn(&T) -> f64,
    hit: impl Fn(&T) -> bool,
    length: f64,
    start: f64,
    lo: f64,
    hi: f64,
) -> bool {
    let mut start = start.rem_euclid(length);
    if start >= length {
        start = 0.0; // (a shade below zero rounds to the length itself)
    }
    let (from, to) = (start + lo, start + hi);
    let any_in = |a: f64, b: f64| {
        let first = items.partition_point(|c| at(c) <= a);
        items[first..].iter().take_while(|c| at(c) < b).any(&hit)
    };
    from < to
        && (any_in(from, to.min(length)) || (to > length && any_in(from - length, to - length)))
}

/// The stretch between profile parameters `a` and `b` the short way round (on a closed
/// boundary of parameter length `n`): where it starts, and its length.
fn short_way(closed: bool, n: f64, a: f64, b: f64) -> (f64, f64) {
    if closed {
        let d = (b - a) - n * ((b - a) / n).round();
        ((if d >= 0.0 { a } else { a + d }).rem_euclid(n), d.abs())
    } else {
        (a.min(b), (a - b).abs())
    }
}

/// Whether boundary `k` between profile parameters `a` and `b` (the short way round) is a
/// piece of one arc about `x` of radius `r` (to [`crate::SAME_NODE`] of the size): the disk there then
/// touches all of it, and it is the foot of no other point of the axis. (A disk merely near
/// the boundary between two feet is not enough: beside a nearly flat convex corner the disk
/// at a junction lies within 1e-7 of the corner, whose leaf is a long edge of the axis.)
pub(crate) fn arc_between(sites: &Sites<'_>, k: usize, a: f64, b: f64, x: V2, r: f64) -> bool {
    let boundary = sites.boundaries[k];
    let n = boundary.domain().1;
    let (lo, d) = short_way(boundary.is_closed(), n, a, b);
    let hi = lo + d;
    // (The segment holding the middle; both feet must lie on it, its ends included.)
    let i = ((0.5 * (lo + hi)).floor() as usize) % boundary.segments().len();
    let on = |u: f64| u >= i as f64 - ulps(n) && u <= (i + 1) as f64 + ulps(n);
    let merge = crate::SAME_NODE * sites.size;
    on(lo)
        && on(hi)
        && boundary.segments()[i].circle().is_some_and(|(c, radius)| {
            (V2::from_arr(c) - x).norm() <= merge && (radius - r).abs() <= merge
        })
}

/// The stretch of the line between the end of stretch `a` and the start of `b`, either way
/// round (where they overlap, the overlap), as `(lo, hi)`.
fn between(line: &Line, a: &CoveredRun, b: &CoveredRun) -> (f64, f64) {
    let (from, mut to) = (a.start + a.length, b.start);
    if to < from - 0.5 * line.length {
        to += line.length;
    }
    (from.min(to), from.max(to))
}

/// Samples of the boundary between two ends of stretches that meet.
const BETWEEN_SAMPLES: usize = 8;

/// Whether the boundary between the end of stretch `a` and the start of `b` (or, where they
/// overlap, between the start of `b` and the end of `a`) stays within `gap` of those ends: two
/// ends that meet across a slit of the boundary (its sides within `gap`) leave the slit
/// uncovered all the same.
fn short_between(sites: &Sites<'_>, line: &Line, a: &CoveredRun, b: &CoveredRun, gap: f64) -> bool {
    let (lo, hi) = between(line, a, b);
    (1..BETWEEN_SAMPLES).all(|j| {
        let u = line.param_at(lo + (hi - lo) * j as f64 / BETWEEN_SAMPLES as f64);
        let p = V2::from_arr(sites.foot(line.boundary, u));
        (p - a.ends[1].0).norm().min((p - b.ends[0].0).norm()) <= gap
    })
}

/// Whether a convex corner lies strictly between the end of stretch `a` and the start of
/// `b` (either way round): the end of a leaf, which two ends meeting there would hide.
fn convex_between(line: &Line, a: &CoveredRun, b: &CoveredRun) -> bool {
    let (lo, hi) = between(line, a, b);
    line.convex_within(lo, 0.0, hi - lo)
}

/// Whether two ends of stretches of feet are one point of the line, to `gap`: their feet
/// that near, and at one foot (a fan) their disks' rims that near.
fn ends_meet(a: (V2, f64, V2), b: (V2, f64, V2), gap: f64) -> bool {
    let apart = (a.0 - b.0).norm();
    let turn = a.2.cross(b.2).atan2(a.2.dot(b.2)).abs();
    apart + turn * a.1.min(b.1) <= gap
}

/// The arcs whose centre is a node of the axis at their radius (on the axis's side): the
/// disk there touches the whole arc, and the edges meeting there start at its ends.
fn arcs_at_nodes(
    sites: &Sites<'_>,
    axis: &MedialAxis,
    lines: &[Line],
    out: &mut [Vec<CoveredRun>],
) {
    let gap = COVER_GAP * sites.size;
    for (k, b) in sites.boundaries.iter().enumerate() {
        for (i, seg) in b.segments().iter().enumerate() {
            let Some((c, r)) = seg.circle() else { continue };
            let c = V2::from_arr(c);
            let Some(node) = axis.nodes.iter().find(|n| {
                n.kind != NodeKind::Corner
                    && (V2::from_arr(n.xy) - c).norm() <= gap
                    && (n.radius - r).abs() <= gap
            }) else {
                continue;
            };
            let (p, q) = (seg.start(), seg.end());
            let x = V2::from_arr(node.xy);
            out[k].push(CoveredRun {
                start: i as f64 + lines[k].shift[i],
                length: 1.0,
                ends: [(p, node.radius, x - p), (q, node.radius, x - q)],
            });
        }
    }
}

#[cfg(test)]
mod tests;
