//! The regions from the pieces of their boundaries: in each cell, pieces joined into loops
//! where zero sets cross and along the cell's border; loops sorted into parts and holes;
//! parts glued into regions across the cells' borders.
//!
//! The borders of the cells are the lines where one finger sits at a joint `k`: the pairs
//! `{k, c}` for the other finger's parameter `c` (the line `s = k` above the diagonal, `t = k`
//! below it; the closing joint's line is both the left edge `s = 0` and the top edge `t = n`
//! of the square). Two parts touching one such line along overlapping stretches of `c` are one
//! region where the joint is smooth (the conditions are continuous across it); at a convex
//! corner the pairs on the line are the corner's own ([`crate::corners`]), and they join the
//! parts they touch; a reflex corner takes no part, and joins nothing.

use crate::cells::Traced;
use crate::corners::CornerLine;
use crate::model::{Cone, Model};
use crate::polyline::{bounds, inside, signed_area};
use curve::distance_to_segment;
use numeric::certificate::{Doubt, Doubts};
use zeroset::{BoundaryPiece, PieceEnd};

/// Two ends are one point when this close, relative to a cell (crossings are polished onto
/// both zero sets; an unpolished one lies within the chord tolerance, added to this).
const SAME_POINT: f64 = 1e-7;

/// Two places on a cell's border are one when this close (a cell's edge being 1): the ends
/// of pieces meeting at a corner of the cell come from subdivision to the size limit there,
/// a few units of the parameter tolerance apart, and may fall on either edge of it.
const SAME_PLACE: f64 = SAME_POINT;

/// Stretches of a line overlap when they share more than this (a cell's parameter being 1):
/// beyond the rounding of their ends, however small the regions (they shrink with μ).
const OVERLAP: f64 = 1e-13;

/// Ends are first matched this close (a cell being 1): crossings are polished onto both zero
/// sets, so the two pieces meeting at one agree to rounding; only where none is found are
/// ends up to the chord tolerance apart taken as one (a region may be smaller than that).
const TIGHT: f64 = 1e-10;

/// How far inside its first edge a cell no piece reaches is tested (a cell being 1): off the
/// joint's line, whose corner cone is not the segment's.
const INSIDE_EDGE: f64 = 1e-9;

/// Loops narrower than this (a cell's parameter being 1) at a point where the contacts meet
/// are the crumbs the subdivision leaves where all functions vanish (a corner too blunt for
/// any grasp near it), not regions.
const CRUMB: f64 = 1e-9;

/// Loops no wider than this many units of rounding of the square's coordinates are debris: a
/// zero set crossing a cell's edge leaves, beside its piece, a sliver a few ulps long where a
/// patch's corner cut it, closed along the border into a loop of nothing.
const DEBRIS_ULPS: f64 = 64.0;

/// A region as closed polylines in the triangle `s < t` of the profile's parameter.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct RawRegion {
    /// Its parts, each a closed polyline (first vertex repeated last) in one cell, the region
    /// on the left.
    pub(crate) parts: Vec<Vec<[f64; 2]>>,
    /// Holes in it, clockwise.
    pub(crate) holes: Vec<Vec<[f64; 2]>>,
    /// Stretches of corner lines (pairs with a finger at a corner): each from its first to
    /// its second point.
    pub(crate) lines: Vec<[[f64; 2]; 2]>,
    /// Single pairs.
    pub(crate) points: Vec<[f64; 2]>,
    /// What is not proven about its boundary.
    pub(crate) doubts: Doubts,
}

/// A walked stretch of a joint's line: the joint and the other finger's parameters.
type Stretch = (usize, [f64; 2]);

/// A closed loop in one cell with the stretches of joint lines it runs along.
struct Loop {
    pts: Vec<[f64; 2]>,
    stretches: Vec<Stretch>,
    doubts: Doubts,
}

/// The border of one cell, counterclockwise: its corners, and per edge the joint line it lies
/// on (`None`: the diagonal) and which coordinate runs along it.
struct Border {
    corners: Vec<[f64; 2]>,
    lines: Vec<Option<(usize, usize)>>,
}

impl Border {
    fn of(i: usize, j: usize, n: usize) -> Self {
        let (x0, x1, y0, y1) = (i as f64, (i + 1) as f64, j as f64, (j + 1) as f64);
        // Line `s = k` runs along t (coordinate 1), line `t = k` along s (coordinate 0).
        let s_line = |k: usize| Some((k % n, 1));
        let t_line = |k: usize| Some((k % n, 0));
        if i == j {
            Border {
                corners: vec![[x0, y0], [x1, y1], [x0, y1]],
                lines: vec![None, t_line(j + 1), s_line(i)],
            }
        } else {
            Border {
                corners: vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]],
                lines: vec![t_line(j), s_line(i + 1), t_line(j + 1), s_line(i)],
            }
        }
    }

    /// The distance from `p` to the border.
    fn off(&self, p: [f64; 2]) -> f64 {
        let m = self.corners.len();
        (0..m)
            .map(|e| distance_to_segment(p, self.corners[e], self.corners[(e + 1) % m]))
            .fold(f64::INFINITY, f64::min)
    }

    /// The place of a border point: edge `e` plus the share along it.
    fn place(&self, p: [f64; 2]) -> f64 {
        let m = self.corners.len();
        let mut best = (f64::INFINITY, 0.0);
        for e in 0..m {
            let (a, b) = (self.corners[e], self.corners[(e + 1) % m]);
            let d = [b[0] - a[0], b[1] - a[1]];
            let len2 = d[0] * d[0] + d[1] * d[1];
            let x = (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0);
            let off = (a[0] + x * d[0] - p[0]).hypot(a[1] + x * d[1] - p[1]);
            if off < best.0 {
                best = (off, e as f64 + x.min(1.0 - f64::EPSILON));
            }
        }
        best.1
    }

    /// The walk from place `from` to place `to` (counterclockwise, wrapping): the corners
    /// passed, and the stretches of joint lines walked.
    fn walk(&self, from: f64, to: f64, stretches: &mut Vec<Stretch>) -> Vec<[f64; 2]> {
        let m = self.corners.len() as f64;
        let to = if to < from { to + m } else { to };
        let mut corners = Vec::new();
        let mut at = from;
        while at < to {
            let e = at.floor();
            let end = (e + 1.0).min(to);
            let edge = (e as usize) % self.corners.len();
            if let Some((joint, coord)) = self.lines[edge] {
                let point = |x: f64| self.point(x)[coord];
                let (a, b) = (point(at), point(end));
                stretches.push((joint, [a.min(b), a.max(b)]));
            }
            if end < to {
                corners.push(self.corners[(edge + 1) % self.corners.len()]);
            }
            at = end;
        }
        corners
    }

    /// The point at place `x` (an edge's end is the next edge's start).
    fn point(&self, x: f64) -> [f64; 2] {
        let m = self.corners.len();
        let e = (x.floor() as usize) % m;
        let f = x - x.floor();
        let (a, b) = (self.corners[e], self.corners[(e + 1) % m]);
        [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
    }
}

/// The regions of `model` from its cells' pieces and its corner lines.
///
/// A cell whose border no piece reaches is inside the set all round its border or outside
/// all round: `holds` (force closure at a pair) decides which, just inside its first edge.
pub(crate) fn regions(
    model: &Model<'_>,
    traced: &[((usize, usize), Traced)],
    lines: &[CornerLine],
    chord: f64,
    holds: &dyn Fn([f64; 2]) -> bool,
) -> Vec<RawRegion> {
    let n = model.n();
    let mut loops: Vec<Loop> = Vec::new();
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut shared = Doubts::none();
    for ((i, j), t) in traced {
        let border = Border::of(*i, *j, n);
        let walk = Walk {
            open: t.pieces.iter().filter(|p| p.ends.is_some()).collect(),
            border: &border,
            tol: SAME_POINT + chord,
        };
        let mut used = vec![false; walk.open.len()];
        for first in 0..walk.open.len() {
            if !used[first] {
                loops.push(walk.trace(first, &mut used));
            }
        }
        if walk.open.is_empty() && *i != *j && holds([*i as f64 + 0.5, *j as f64 + INSIDE_EDGE]) {
            // (A diagonal cell's border holds the diagonal, which is never inside.)
            let mut stretches = Vec::new();
            let mut pts = border.walk(0.0, 4.0 - INSIDE_EDGE, &mut stretches);
            pts.insert(0, border.corners[0]);
            pts.push(border.corners[0]);
            loops.push(Loop {
                pts,
                stretches,
                doubts: Doubts::none(),
            });
        }
        for p in t.pieces.iter().filter(|p| p.ends.is_none()) {
            loops.push(Loop {
                pts: p.pts.clone(),
                stretches: Vec::new(),
                doubts: Doubts::none(),
            });
        }
        points.extend(&t.points);
        if t.unresolved {
            shared.add(Doubt::GraspBoundaryUnresolved);
        }
    }
    glue(model, loops, lines, points, chord, &shared)
}

/// Joins a cell's open pieces into loops.
struct Walk<'a> {
    open: Vec<&'a BoundaryPiece>,
    border: &'a Border,
    tol: f64,
}

impl Walk<'_> {
    fn ends(&self, i: usize) -> [PieceEnd; 2] {
        self.open[i].ends.unwrap_or([PieceEnd::Loose; 2])
    }

    fn first(&self, i: usize) -> [f64; 2] {
        self.open[i].pts[0]
    }

    fn last(&self, i: usize) -> [f64; 2] {
        let pts = &self.open[i].pts;
        pts[pts.len() - 1]
    }

    /// The piece that goes on from the end of piece `i`, with the border walked between.
    fn next(
        &self,
        i: usize,
        used: &[bool],
        start: usize,
        stretches: &mut Vec<Stretch>,
    ) -> Option<(usize, Vec<[f64; 2]>)> {
        let end = self.last(i);
        let available = |j: usize| !used[j] || j == start;
        // A piece starting where this one ends goes on from it, whatever the ends are called:
        // at a point where the contacts meet every function vanishes, and the pieces leaving
        // it are tagged by whichever function the cut met first.
        // Where several pieces meet at one point (a corner where the contacts meet, with a
        // wedge of grasps round it), the region goes on along the piece turning farthest
        // left: the region lies on the left of each piece, so that piece bounds the same
        // sector of it.
        let incoming = self.direction(i, false);
        let here = || {
            [TIGHT, self.tol].into_iter().find_map(|tol| {
                (0..self.open.len())
                    .filter(|&j| available(j) && j != i)
                    .filter(|&j| dist(self.first(j), end) <= tol)
                    .map(|j| (j, turn(incoming, self.direction(j, true))))
                    .max_by(|x, y| x.1.total_cmp(&y.1))
                    .map(|(j, _)| (j, Vec::new()))
            })
        };
        match self.ends(i)[1] {
            PieceEnd::Crossing(_) => {
                let partner = |tol: f64| self.partner(i, tol, &available).map(|j| (j, Vec::new()));
                // Where the contacts meet, every function vanishes: any piece leaving the
                // point goes on. Elsewhere a crossing on the cell's border with no piece of the
                // other zero set leaving it (that one meets the border there, its piece inside
                // a point) goes on along the border, as at a border end: the walk records the
                // stretch of the joint's line the region touches.
                let meeting = self.at_meeting(end);
                partner(TIGHT)
                    .or_else(|| {
                        here().filter(|(j, _)| meeting && dist(self.first(*j), end) <= TIGHT)
                    })
                    .or_else(|| partner(self.tol))
                    .or_else(|| {
                        (self.border.off(end) <= SAME_POINT)
                            .then(|| self.along_border(i, end, &available, stretches))
                            .flatten()
                    })
                    .or_else(here)
            }
            PieceEnd::Border => {
                // A piece leaving this very point (a corner of the cell where the contacts
                // meet) goes on from it: no walk round the border. (Elsewhere the walk is
                // taken however short: it records the stretch of the joint's line the region
                // touches, which glues it to its part across.)
                let tight = here().filter(|(j, _)| dist(self.first(*j), end) <= TIGHT);
                if self.at_meeting(end) && tight.is_some() {
                    return tight;
                }
                self.along_border(i, end, &available, stretches)
            }
            PieceEnd::Loose => here(),
        }
    }

    /// The piece starting next on the border counterclockwise from the end `end` of piece
    /// `i` (wrapping round; a start at the same place, to rounding, is next), with the border
    /// walked to it.
    ///
    /// A piece's own start at a crossing is not next at the same place (to `SAME_PLACE`): the
    /// piece only grazes the border there (a crossing within rounding of the edge, as where
    /// two zero sets that coincide in the next cell part at its edge), and closing it on
    /// itself made a loop of nothing and left the region open.
    fn along_border(
        &self,
        i: usize,
        end: [f64; 2],
        available: &dyn Fn(usize) -> bool,
        stretches: &mut Vec<Stretch>,
    ) -> Option<(usize, Vec<[f64; 2]>)> {
        let from = self.border.place(end);
        let m = self.border.corners.len() as f64;
        let ahead = |x: f64| {
            let d = x - from;
            if d >= -SAME_PLACE {
                d.max(0.0)
            } else {
                d + m
            }
        };
        let grazing = |j: usize, to: f64| {
            j == i && matches!(self.ends(j)[0], PieceEnd::Crossing(_)) && ahead(to) <= SAME_PLACE
        };
        // A piece no longer than rounding whose own start lies just behind its end (a zero set
        // through a corner of the cell, cutting it within rounding) closes the other way
        // round: the region on its left is the cell's bulk, not the nothing between its ends.
        let (lo, hi) = bounds(&self.open[i].pts);
        let speck = (hi[0] - lo[0]).max(hi[1] - lo[1]) <= SAME_POINT;
        let around = |j: usize, to: f64| {
            if j == i && speck && to < from {
                to - from + m
            } else {
                ahead(to)
            }
        };
        let (j, to) = (0..self.open.len())
            .filter(|&j| available(j))
            .filter(|&j| self.border.off(self.first(j)) <= SAME_POINT)
            .filter(|&j| !self.reached_by_crossing(j, available))
            .map(|j| (j, self.border.place(self.first(j))))
            .filter(|&(j, to)| !grazing(j, to))
            .min_by(|x, y| around(x.0, x.1).total_cmp(&around(y.0, y.1)))?;
        let to = if around(j, to) == 0.0 { from } else { to };
        Some((j, self.border.walk(from, to, stretches)))
    }

    /// The available piece that goes on from the crossing where piece `k` ends: the nearest
    /// within `tol` of that zero set starting at its crossing with `k`'s.
    fn partner(&self, k: usize, tol: f64, available: &dyn Fn(usize) -> bool) -> Option<usize> {
        let PieceEnd::Crossing(other) = self.ends(k)[1] else {
            return None;
        };
        let (mine, end) = (self.open[k].function, self.last(k));
        (0..self.open.len())
            .filter(|&j| available(j))
            .filter(|&j| {
                self.open[j].function == other && self.ends(j)[0] == PieceEnd::Crossing(mine)
            })
            .map(|j| (j, dist(self.first(j), end)))
            .filter(|&(_, d)| d <= tol)
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .map(|(j, _)| j)
    }

    /// Whether piece `j` is the partner of another available piece: the walk reaches it
    /// through that piece, not along the border, however near the border their crossing lies
    /// (two zero sets parting at a cell's edge cross there to rounding, and the piece from the
    /// edge to the crossing, a few ulps long, bounds the region too).
    fn reached_by_crossing(&self, j: usize, available: &dyn Fn(usize) -> bool) -> bool {
        matches!(self.ends(j)[0], PieceEnd::Crossing(_))
            && (0..self.open.len())
                .any(|k| k != j && available(k) && self.partner(k, self.tol, available) == Some(j))
    }

    /// Whether `p` is a point where the contacts meet: a corner of the cell, or on its
    /// diagonal edge.
    fn at_meeting(&self, p: [f64; 2]) -> bool {
        let m = self.border.corners.len();
        self.border
            .corners
            .iter()
            .any(|&c| dist(c, p) <= SAME_PLACE)
            || (0..m).any(|e| {
                self.border.lines[e].is_none()
                    && distance_to_segment(
                        p,
                        self.border.corners[e],
                        self.border.corners[(e + 1) % m],
                    ) <= SAME_PLACE
            })
    }

    /// The direction in which piece `i` leaves its start (`leaving`) or arrives at its end.
    fn direction(&self, i: usize, leaving: bool) -> [f64; 2] {
        let pts = &self.open[i].pts;
        let (a, b) = if leaving {
            let far = pts.iter().find(|p| dist(**p, pts[0]) > 0.0).copied();
            (pts[0], far.unwrap_or(pts[0]))
        } else {
            let last = pts[pts.len() - 1];
            let far = pts.iter().rev().find(|p| dist(**p, last) > 0.0).copied();
            (far.unwrap_or(last), last)
        };
        [b[0] - a[0], b[1] - a[1]]
    }

    /// The loop through piece `first`.
    fn trace(&self, first: usize, used: &mut [bool]) -> Loop {
        let mut l = Loop {
            pts: self.open[first].pts.clone(),
            stretches: Vec::new(),
            doubts: Doubts::none(),
        };
        used[first] = true;
        let mut at = first;
        for _ in 0..=self.open.len() {
            let Some((next, between)) = self.next(at, used, first, &mut l.stretches) else {
                // Nothing goes on: close the loop by a chord, and say so.
                l.doubts.add(Doubt::GraspBoundaryUnresolved);
                break;
            };
            append(&mut l.pts, &between);
            if next == first {
                break;
            }
            used[next] = true;
            append(&mut l.pts, &self.open[next].pts);
            at = next;
        }
        // (Closed on its first vertex, the last one if that is it to rounding.)
        let (p0, len) = (l.pts[0], l.pts.len());
        match l.pts.last_mut() {
            Some(last) if len > 1 && dist(*last, p0) <= TIGHT => *last = p0,
            _ => l.pts.push(p0),
        }
        l
    }
}

/// `pts` followed by `more`, a vertex where they meet once: the end of one piece and the
/// start of the next are one point to rounding (within [`TIGHT`]), computed in two places.
fn append(pts: &mut Vec<[f64; 2]>, more: &[[f64; 2]]) {
    let mut more = more;
    if let (Some(&last), Some(&first)) = (pts.last(), more.first()) {
        if dist(last, first) <= TIGHT {
            more = &more[1..];
        }
    }
    pts.extend_from_slice(more);
}

/// The signed angle from direction `a` to direction `b` (left turns positive).
fn turn(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] * b[1] - a[1] * b[0]).atan2(a[0] * b[0] + a[1] * b[1])
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// What a node of the gluing is.
enum Node {
    Part(usize),
    Line { joint: usize, piece: [f64; 2] },
    Point([f64; 2]),
}

/// The pair of the triangle `s < t` with one finger at joint `k` and the other at `c`.
fn on_line(k: usize, c: f64) -> [f64; 2] {
    let k = k as f64;
    if c > k {
        [k, c]
    } else {
        [c, k]
    }
}

/// Parts, holes, corner lines and points glued into regions.
fn glue(
    model: &Model<'_>,
    loops: Vec<Loop>,
    lines: &[CornerLine],
    points: Vec<[f64; 2]>,
    chord: f64,
    shared: &Doubts,
) -> Vec<RawRegion> {
    // The points where the contacts meet: a joint with itself (on the diagonal), and the
    // closing joint's corner of the square.
    let n = model.n() as f64;
    let meets: Vec<[f64; 2]> = (0..=model.n())
        .map(|k| [k as f64, k as f64])
        .chain([[0.0, n]])
        .collect();
    let crumb = |l: &Loop| {
        let (lo, hi) = bounds(&l.pts);
        (hi[0] - lo[0]).max(hi[1] - lo[1]) <= CRUMB
            && meets
                .iter()
                .any(|m| dist(*m, lo) <= CRUMB && dist(*m, hi) <= CRUMB)
    };
    let debris = |l: &Loop| {
        let (lo, hi) = bounds(&l.pts);
        (hi[0] - lo[0]).max(hi[1] - lo[1]) <= DEBRIS_ULPS * f64::EPSILON * n.max(1.0)
    };
    let (mut outer, holes): (Vec<Loop>, Vec<Loop>) = loops
        .into_iter()
        .filter(|l| !crumb(l) && !debris(l))
        .partition(|l| signed_area(&l.pts) >= 0.0);
    // A hole lies in a part of its cell. A clockwise loop no part holds that is thinner than
    // the polylines resolve (its area within a chord of its length) is a sliver of the set
    // whose two sides the polylines drew on one line, the sign of its area rounding's (the
    // pinch grasps of a corner just sharper than twice the friction angle): a part.
    let thin = |l: &Loop| {
        let length: f64 = l.pts.windows(2).map(|w| dist(w[0], w[1])).sum();
        signed_area(&l.pts).abs() <= chord * length
    };
    let (slivers, holes): (Vec<Loop>, Vec<Loop>) = holes
        .into_iter()
        .partition(|h| thin(h) && !outer.iter().any(|o| inside(&o.pts, h.pts[0])));
    for mut sliver in slivers {
        sliver.pts.reverse();
        outer.push(sliver);
    }
    let mut nodes: Vec<Node> = (0..outer.len()).map(Node::Part).collect();
    for line in lines {
        for &piece in &line.pieces {
            nodes.push(Node::Line {
                joint: line.joint,
                piece,
            });
        }
    }
    nodes.extend(points.iter().map(|&p| Node::Point(p)));
    // Per joint, the stretches of its line each node holds.
    let mut on_joint: Vec<Vec<(usize, [f64; 2])>> = vec![Vec::new(); model.n()];
    for (k, node) in nodes.iter().enumerate() {
        match node {
            Node::Part(p) => {
                for &(joint, c) in &outer[*p].stretches {
                    on_joint[joint].push((k, c));
                }
            }
            Node::Line { joint, piece } => {
                on_joint[*joint].push((k, *piece));
                // An end at another joint is a pair of two joints: on that joint's line too.
                for c in piece.iter().copied().filter(|c| c.fract() == 0.0) {
                    let other = (c as usize) % model.n();
                    on_joint[other].push((k, [*joint as f64; 2]));
                }
            }
            Node::Point(_) => {}
        }
    }
    let mut root: Vec<usize> = (0..nodes.len()).collect();
    fn find(root: &mut [usize], i: usize) -> usize {
        let mut i = i;
        while root[i] != i {
            root[i] = root[root[i]];
            i = root[i];
        }
        i
    }
    for (joint, held) in on_joint.iter().enumerate() {
        if model.joints[joint].cone == Cone::Reflex {
            continue;
        }
        for (x, &(a, ca)) in held.iter().enumerate() {
            for &(b, cb) in &held[x + 1..] {
                let overlap = ca[1].min(cb[1]) - ca[0].max(cb[0]);
                let point_in = (ca[0] == ca[1] || cb[0] == cb[1]) && overlap >= -OVERLAP;
                if overlap > OVERLAP || point_in {
                    let (ra, rb) = (find(&mut root, a), find(&mut root, b));
                    root[ra] = rb;
                }
            }
        }
    }
    let mut regions: Vec<(usize, RawRegion)> = Vec::new();
    let slot_of = |r: usize, regions: &mut Vec<(usize, RawRegion)>| match regions
        .iter()
        .position(|(k, _)| *k == r)
    {
        Some(k) => k,
        None => {
            regions.push((
                r,
                RawRegion {
                    doubts: shared.clone(),
                    ..RawRegion::default()
                },
            ));
            regions.len() - 1
        }
    };
    for (k, node) in nodes.iter().enumerate() {
        let r = find(&mut root, k);
        let slot = slot_of(r, &mut regions);
        let region = &mut regions[slot].1;
        match node {
            Node::Part(p) => {
                region.parts.push(outer[*p].pts.clone());
                region.doubts.join(outer[*p].doubts.clone());
            }
            Node::Line { joint, piece } => {
                region
                    .lines
                    .push([on_line(*joint, piece[0]), on_line(*joint, piece[1])]);
            }
            Node::Point(p) => {
                region.points.push(*p);
                region.doubts.add(Doubt::GraspPointRegion);
            }
        }
    }
    for h in holes {
        // The hole belongs to the smallest part around it.
        let home = regions
            .iter()
            .enumerate()
            .flat_map(|(k, (_, r))| r.parts.iter().map(move |p| (k, p)))
            .filter(|(_, p)| inside(p, h.pts[0]))
            .min_by(|x, y| signed_area(x.1).total_cmp(&signed_area(y.1)))
            .map(|(k, _)| k);
        match home {
            Some(k) => {
                regions[k].1.holes.push(h.pts);
                regions[k].1.doubts.join(h.doubts);
            }
            // A clockwise loop round nothing: the boundary was not resolved.
            None => {
                for (_, r) in regions.iter_mut() {
                    r.doubts.add(Doubt::GraspBoundaryUnresolved);
                }
            }
        }
    }
    regions.into_iter().map(|(_, r)| r).collect()
}
