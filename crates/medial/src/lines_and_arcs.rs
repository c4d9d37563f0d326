//! A region's boundaries as lines and circular arcs in closed form, and what the closed-form
//! paths do on them: solve a node from its equations by Newton's method (and prove a
//! junction's place), and trace an edge between two solved nodes. The seed's diagram
//! ([`crate::traced_axis`]) and the trimmed bisectors of every pair of sites
//! ([`crate::pairwise_axis`]) give the topology; both hand their nodes and edges here.
//!
//! The bisector of two lines or two points is straight, any other a conic, whose points come
//! in closed form from the feet on one of its sites ([`Shape::radius_on_ray`]). Every disk
//! of an edge is tested for emptiness and every foot for lying on its segment, as on the
//! other paths.

use crate::candidates::Candidate;
use crate::candidates::Vertex;
use crate::certificate::JUNCTION_ROOM;
use crate::corners::entered_across_corner;
use crate::junction_proof::{proven_within, ClosedSite};
use crate::sites::{Disk, Sites, EMPTY_SLACK};
use crate::stretches::Stretch;
use crate::true_sites::{ArcSite, LineSite, Shape, TrueSite};
use curve::{wrap_pi, JointKind, SegmentKind, V2};
use numeric::rounding::ulps;
use std::collections::HashSet;
use std::f64::consts::PI;

/// Most distance (a share of the size) between the vertices of an edge: the disks between
/// its ends are tested at that step (as the bisectors of two corners are on the other paths).
const EDGE_STEP: f64 = 1e-2;

/// Ends of edges within this share of the size are one node. The ends of the edges at one
/// node are solved to a few ulps (from one vertex of the seed's diagram, one point to the
/// bit), so only nodes that snapping or nearly cocircular sites put this close count as one:
/// the seed's grid spacing. (The other paths find each junction once per branch, and merge
/// within 1e-6.)
pub(crate) const SAME_SEED_NODE: f64 = 1e-9;

/// How far (a share of the size) an arc's exact form may stray from its circle for the
/// closed-form disk test to measure it on the circle: far below the disks' slack.
const ON_CIRCLE: f64 = 1e-11;

/// Whether the exact form of arc `s` is its circle, to [`ON_CIRCLE`] of `size`: each rational
/// quadratic piece's end control points on the circle, its middle one at the radius over
/// the cosine of its half-angle on the bisector, with that cosine its weight relative to the
/// ends' (as the arc's pieces are built). Those make the piece the circle exactly; so near
/// them, it strays by about as much.
fn on_its_circle(s: &curve::Segment, size: f64) -> bool {
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

/// The foot parameter on `along` strictly between `t0` and `t1` (a share of their span
/// inside) where the radius of the bisector with `other` is least or greatest, if any: where
/// the feet on both sites are on one normal (a line's foot below the other's centre; a
/// circle's foot towards the other's centre or straight across to the line). Two lines'
/// radius is affine along their bisector.
fn radius_extremum(along: Shape, other: Shape, t0: f64, t1: f64) -> Option<f64> {
    let inside = |t: f64| {
        let margin = 1e-9 * (t1 - t0).abs();
        (t - t0.min(t1) > margin && t0.max(t1) - t > margin).then_some(t)
    };
    match (along, other) {
        (Shape::Line(_), Shape::Line(_)) => None,
        (Shape::Line(l), Shape::Round { centre, .. }) => inside(l.along.dot(centre - l.start)),
        (Shape::Round { centre, side, .. }, other) => {
            let towards = match other {
                Shape::Line(l) => l.inward * -side,
                Shape::Round { centre: c, .. } => c - centre,
            };
            let angle = towards.angle();
            // (Either way along the line through the centres; the turn nearest the span.)
            [angle, angle + PI].into_iter().find_map(|a| {
                let a = t0 + wrap_pi(a - t0);
                inside(a)
            })
        }
    }
}

/// Up to this many segments a disk is tested for emptiness on every segment in closed form:
/// a test of each costs less than the walk of the boundaries' box tree that finds the few
/// near it (about as much at 64).
const CLOSED_FORM_DISK_SEGMENTS: usize = 64;

/// Most vertices of one edge, and halvings of its foot parameter while it is traced: a
/// parabola's to the finest chord tolerance (1e-9 of the size) takes ~2e4 on a region's
/// width; beyond this the input is refused to the other paths.
const MAX_EDGE_VERTICES: usize = 1 << 16;
const MAX_EDGE_HALVINGS: usize = 16;

/// Newton steps that place a node: from a start ~2e-9 of the size off, the equations
/// (linear for lines, a norm for points and circles) converge in two or three.
const NODE_NEWTON_STEPS: usize = 16;

/// The equations of a node not used to solve it (a fourth site of nearly cocircular ones)
/// must hold to this share of the size: within the reach in which ends are one node.
const OTHER_EQUATIONS: f64 = 1e-6;

/// The least sine of the angle between the gradients of two equations a node is solved
/// on: below, they are one equation to rounding (two lines of one line, after snapping), and
/// Newton's method would slide along their common zero.
const MIN_SINE: f64 = 1e-9;

/// A foot may stray this share of the size beyond its segment's ends (rounding).
const FOOT_SLACK: f64 = 1e-9;

/// The least distance (a share of the size) from a round site's centre at which its feet
/// parametrise a conic edge: at the centre every point of the circle is a foot.
const FOOT_ROOM: f64 = 1e-6;

/// The three sites of two equations of equal distance that share one, the shared first.
pub(crate) fn three_sites(p: [TrueSite; 2], q: [TrueSite; 2]) -> Option<[TrueSite; 3]> {
    let shared = p.into_iter().find(|s| q.contains(s))?;
    let other = |e: [TrueSite; 2]| if e[0] == shared { e[1] } else { e[0] };
    let (b, c) = (other(p), other(q));
    (b != c).then_some([shared, b, c])
}

/// What holds at a vertex of the diagram: two sites at one distance (a primary edge), or the
/// foot on `segment` at its end point `end`, where its tangent is `tangent` (a secondary
/// edge, between a segment and its own end; or the normal at a smooth joint).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Equation {
    Equal(TrueSite, TrueSite),
    FootAtEnd {
        segment: TrueSite,
        tangent: V2,
        end: V2,
    },
}

/// One segment of a boundary, in closed form.
#[derive(Debug, Clone, Copy)]
enum Piece {
    Line(LineSite),
    Arc { arc: ArcSite, start: V2, end: V2 },
}

impl Piece {
    /// Whether the foot of `x` on the piece's line or circle falls on the piece (else the
    /// piece's nearest point to `x` is one of its ends).
    fn falls_on(&self, x: V2) -> bool {
        match self {
            Piece::Line(l) => (0.0..=l.length).contains(&l.along.dot(x - l.start)),
            Piece::Arc { arc, .. } => arc.spans(x - arc.centre),
        }
    }
}

/// A node of the axis solved from a vertex of the diagram (its disk tested empty), and
/// whether its place is proven in closed form (a junction of three sites).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Solved {
    pub(crate) xy: V2,
    pub(crate) radius: f64,
    pub(crate) proven: bool,
}

/// What the tracer makes: a candidate per edge, each its own stretch, and the places of the
/// junctions it proved (bits of their coordinates; see [`crate::certificate::doubt`]).
pub(crate) struct Traced {
    pub(crate) candidates: Vec<Candidate>,
    pub(crate) stretches: Vec<Stretch>,
    pub(crate) proven: HashSet<[u64; 2]>,
}

/// A convex polygon (its corners in turning order) that covers the band between the points
/// of tangency of two disks with lines `a` and `b`: centres `c` on the bisector of the lines
/// (`c[0]` nearer their meeting point, if any), radii `r` their distances to the lines, each
/// disk less `slack`. Its corners are the centres and, on each line's side and for each
/// centre, the point on the ray from the centre to its foot at half the slack from the line,
/// moved a quarter of the slack either way along the line: the tangency points of the
/// smaller disks lie on those rays, a further half of the slack in, and the room covers
/// their rounding. Every corner stays at least a quarter of the slack off both lines.
fn sweep_polygon(c: [V2; 2], r: [f64; 2], lines: [LineSite; 2], slack: f64) -> [V2; 10] {
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

/// The boundaries of a region whose segments are all lines and circular arcs, each in
/// closed form.
pub(crate) struct LinesAndArcs<'s, 'a> {
    pub(crate) sites: &'s Sites<'a>,
    pieces: Vec<Vec<Piece>>,
    /// The chord tolerance of the edges (a length).
    chord_tol: f64,
    /// Whether the boundaries have so few segments that a disk is tested on each in closed
    /// form ([`CLOSED_FORM_DISK_SEGMENTS`]).
    few: bool,
}

impl<'s, 'a> LinesAndArcs<'s, 'a> {
    /// The boundaries of `sites` in closed form, the edges to be traced within `chord_tol`
    /// of the size; `None` where some segment is neither a line nor a circular arc.
    pub(crate) fn new(sites: &'s Sites<'a>, chord_tol: f64) -> Option<Self> {
        let pieces = sites
            .boundaries
            .iter()
            .enumerate()
            .map(|(k, b)| {
                let inside_left = sites.inside_left(k);
                (0..b.segments().len())
                    .map(|i| {
                        let s = &b.segments()[i];
                        Some(match s.kind() {
                            SegmentKind::Line => {
                                Piece::Line(LineSite::new(s.start(), s.end(), inside_left))
                            }
                            SegmentKind::Arc => Piece::Arc {
                                arc: ArcSite::new(b, i, inside_left)?,
                                start: s.start(),
                                end: s.end(),
                            },
                            _ => return None,
                        })
                    })
                    .collect::<Option<Vec<Piece>>>()
            })
            .collect::<Option<Vec<_>>>()?;
        let segments: usize = pieces.iter().map(Vec::len).sum();
        // (The closed-form disk test measures each arc's circle: only where every arc's
        // exact form is that circle, to far below the disks' slack.)
        let circular = sites.boundaries.iter().all(|b| {
            b.segments()
                .iter()
                .all(|s| s.kind() != SegmentKind::Arc || on_its_circle(s, sites.size))
        });
        Some(Self {
            sites,
            pieces,
            chord_tol: chord_tol * sites.size,
            few: segments <= CLOSED_FORM_DISK_SEGMENTS && circular,
        })
    }

    /// The node where `equations` hold near `start` (within `reach` of it), its disk tested
    /// empty, and whether its place is proven (a junction of three sites); `about` are the
    /// true sites the node touches. The centre of an arc about the axis is the node where it
    /// is within reach and the equations hold there: the arc's distance has no gradient there
    /// for Newton's method, but the place is exact. `None` where Newton's method fails or
    /// leaves the reach, the equations disagree, or the disk is entered.
    pub(crate) fn solve_node(
        &self,
        start: V2,
        equations: &[Equation],
        about: &[TrueSite],
        reach: f64,
    ) -> Option<Solved> {
        let size = self.sites.size;
        let agree = |x: V2| {
            equations
                .iter()
                .all(|&e| self.equation(e, x).0.abs() <= OTHER_EQUATIONS * size)
        };
        let centre = about.iter().find_map(|&s| {
            let arc = self.arc(s).filter(|a| a.side < 0.0)?;
            ((arc.centre - start).norm() <= reach && agree(arc.centre))
                .then_some((arc.centre, arc.radius))
        });
        if let Some((xy, radius)) = centre {
            return self.disk_is_empty(xy, radius).then_some(Solved {
                xy,
                radius,
                proven: false,
            });
        }
        let (e0, e1) = self.best_pair(equations, start)?;
        let mut x = start;
        for _ in 0..NODE_NEWTON_STEPS {
            let ((f0, g0), (f1, g1)) = (self.equation(e0, x), self.equation(e1, x));
            let det = g0.cross(g1);
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            // (Cramer's rule on the 2 × 2 Jacobian.)
            let step = V2::new(f0 * g1.y - f1 * g0.y, g0.x * f1 - g1.x * f0) * (1.0 / det);
            x = x - step;
            if step.norm() <= ulps(4.0) * (x.norm() + size) {
                break;
            }
        }
        let moved = (x - start).norm();
        if moved.is_nan() || moved > reach {
            return None;
        }
        let site = match e0 {
            Equation::Equal(a, _) => a,
            Equation::FootAtEnd { segment, .. } => segment,
        };
        let radius = self.shape(site).distance(x).0;
        if !(agree(x) && radius > 0.0 && self.disk_is_empty(x, radius)) {
            return None;
        }
        // (Proven on the best conditioned two equations of equal distance: those Newton's
        // method used may hold a foot at a segment's end, which is no junction's.)
        let equal: Vec<Equation> = equations
            .iter()
            .copied()
            .filter(|e| matches!(e, Equation::Equal(..)))
            .collect();
        let proven = match self.best_pair(&equal, x) {
            Some((Equation::Equal(a, b), Equation::Equal(c, d))) => {
                self.prove_junction(x, three_sites([a, b], [c, d]))
            }
            _ => false,
        };
        Some(Solved {
            xy: x,
            radius,
            proven,
        })
    }

    /// What holds where the disks of true sites `a` and `b` meet at a node (the equation
    /// of an edge between them): their distances equal; or, across a smooth joint or
    /// between a segment and its own end, the foot at the joint, where the edge is the
    /// normal there.
    pub(crate) fn equation_between(&self, a: TrueSite, b: TrueSite) -> Equation {
        if let Some(end) = self.smooth_joint_between(a, b) {
            // (Their distances are one function: the edge is the normal at the joint.)
            Equation::FootAtEnd {
                segment: a,
                tangent: self.tangent_at(a, end),
                end,
            }
        } else if let Some((segment, end)) = self.own_end(a, b) {
            Equation::FootAtEnd {
                segment,
                tangent: self.tangent_at(segment, end),
                end,
            }
        } else {
            Equation::Equal(a.min(b), a.max(b))
        }
    }

    /// The candidates and vertices of the edge of sites `[a, b]` between its solved ends:
    /// one, or two where its feet pass the joint of a whole circle; none where its ends are
    /// one node (the edge of nearly cocircular sites that snapping made); `None` where the
    /// true coordinates refuse it (a corner site off the axis's side, a foot off its
    /// segment, an entered disk).
    pub(crate) fn trace_edge(
        &self,
        [a, b]: [TrueSite; 2],
        [p, q]: [Solved; 2],
    ) -> Option<Vec<(Candidate, Vec<Vertex>)>> {
        if (q.xy - p.xy).norm() <= SAME_SEED_NODE * self.sites.size {
            return Some(Vec::new());
        }
        // (A point site on the axis's side is a reflex corner.)
        for s in [a, b].into_iter().filter(|s| s.corner) {
            let u = s.segment as f64;
            if !self
                .sites
                .inside_of(s.boundary, s.segment, u, true, p.xy.arr())
            {
                return None;
            }
        }
        let sites = [a, b];
        let ends = [p, q];
        let straight = a.corner == b.corner && self.arc(a).is_none() && self.arc(b).is_none();
        let points = if straight {
            self.straight(p.xy, q.xy)?
        } else {
            self.conic(sites, p.xy, q.xy)?
        };
        let affine = straight && !a.corner && ends.iter().all(|e| self.on_bisector(sites, e));
        let last = points.len() - 1;
        let vertices = points
            .iter()
            .enumerate()
            .map(|(k, &x)| {
                // (Between two lines the radius is affine along the edge: the ends' radii
                // interpolated, where they are the lines' distances, so that the disks
                // between are the sweep of the end disks.)
                let radius = match k {
                    0 => p.radius,
                    k if k == last => q.radius,
                    _ if affine => p.radius + (q.radius - p.radius) * (k as f64 / last as f64),
                    _ => self.shape(sites[0]).distance(x).0,
                };
                let tr = [self.foot(sites[0], x)?, self.foot(sites[1], x)?];
                (radius >= 0.0).then_some(Vertex {
                    tr,
                    xy: x.arr(),
                    radius,
                })
            })
            .collect::<Option<Vec<Vertex>>>()?;
        let candidate = |vertices: &[Vertex]| Candidate {
            boundary: sites.map(|s| s.boundary),
            segment: sites.map(|s| s.segment),
            corner: sites.map(|s| s.corner),
            tr: vertices.iter().map(|v| v.tr).collect(),
            xy: vertices.iter().map(|v| v.xy).collect(),
        };
        // (The ends' disks were tested when they were solved; those between, all at once
        // where the edge is two lines' and the sweep of its disks is proven empty.)
        let swept = last > 1 && affine && self.sweep_is_empty(sites, ends);
        let whole = candidate(&vertices);
        for (k, v) in vertices.iter().enumerate() {
            let tested = k == 0 || k == last || swept;
            if !(tested || self.empty(v)) || entered_across_corner(self.sites, &whole, v).is_some()
            {
                return None;
            }
        }
        Some(
            self.cut_at_joints(sites, vertices)?
                .into_iter()
                .map(|v| (candidate(&v), v))
                .collect(),
        )
    }

    /// The vertices of an edge cut where the feet on a whole circle pass its joint (where
    /// their parameter runs on from 1 to 0, or back): at the point of the edge whose foot is
    /// the joint, in closed form.
    fn cut_at_joints(
        &self,
        sites: [TrueSite; 2],
        vertices: Vec<Vertex>,
    ) -> Option<Vec<Vec<Vertex>>> {
        let mut pieces = vec![vertices];
        for (k, &s) in sites.iter().enumerate() {
            let Some(arc) = self.arc(s).filter(|a| a.full()) else {
                continue;
            };
            let other = self.shape(sites[1 - k]);
            let mut out = Vec::new();
            for piece in pieces {
                let angle = |v: &Vertex| arc.angle_from_start(V2::from_arr(v.xy));
                let Some(cut) = piece
                    .windows(2)
                    .position(|w| (angle(&w[0]) - angle(&w[1])).abs() > PI)
                else {
                    out.push(piece);
                    continue;
                };
                let joint = arc.point_at(0.0);
                let normal = (joint - arc.centre) * (arc.side / arc.radius);
                let radius = other.radius_on_ray(joint, normal)?;
                let x = joint + normal * radius;
                let base = s.segment as f64;
                // (The feet run up to the joint's end of the arc, then on from its start.)
                let rising = angle(&piece[cut]) > PI;
                let at = |share: f64| {
                    let mut tr = piece[cut].tr;
                    tr[k] = base + share;
                    tr[1 - k] = self.foot(sites[1 - k], x)?;
                    Some(Vertex {
                        tr,
                        xy: x.arr(),
                        radius,
                    })
                };
                let (before, after) = if rising { (1.0, 0.0) } else { (0.0, 1.0) };
                let (end, start) = (at(before)?, at(after)?);
                if !self.empty(&end) {
                    return None;
                }
                // (A vertex at the cut itself, the radius's extremum where the joint faces
                // the other site, is the cut's: kept once in each piece.)
                let at_cut = |v: &Vertex| {
                    (V2::from_arr(v.xy) - x).norm() <= SAME_SEED_NODE * self.sites.size
                };
                let mut first = piece[..=cut].to_vec();
                if first.len() > 1 && first.last().is_some_and(at_cut) {
                    first.pop();
                }
                first.push(end);
                let rest = &piece[cut + 1..];
                let rest = match rest {
                    [v, more @ ..] if !more.is_empty() && at_cut(v) => more,
                    _ => rest,
                };
                let mut second = vec![start];
                second.extend_from_slice(rest);
                out.push(first);
                out.push(second);
            }
            pieces = out;
        }
        Some(pieces)
    }

    /// Whether the disk of `v` is empty, as the other paths test it (beside a convex corner
    /// that turns by little, the other side's distance is measured too: see
    /// [`entered_across_corner`]). A disk of radius nil (at a convex corner) holds nothing.
    fn empty(&self, v: &Vertex) -> bool {
        v.radius == 0.0 || self.disk_is_empty(V2::from_arr(v.xy), v.radius)
    }

    /// Whether the disk about `x` of radius `radius` (less the slack) holds no boundary
    /// point: proven in closed form where the boundaries are few, else (or where that proof
    /// fails) on the boundaries' control hulls as the other paths test it.
    fn disk_is_empty(&self, x: V2, radius: f64) -> bool {
        (self.few && self.clear_in_closed_form(x, radius))
            || self.sites.disk(x.arr(), radius) == Disk::Empty
    }

    /// Whether every point of the boundaries is at least `radius` less the slack from `x`,
    /// by its distance in closed form with a bound on its rounding: each segment's ends',
    /// and each line's or arc's where the foot of `x` falls on it (else its nearest point
    /// is an end). A foot misjudged on or off near an end moves the distance by rounding
    /// only: the end there is as far, to rounding, as the nearest point. (Each segment's
    /// own ends: a joint may leave a gap of up to 1e-9 of the size.)
    fn clear_in_closed_form(&self, x: V2, radius: f64) -> bool {
        let slack = EMPTY_SLACK * self.sites.size;
        let magnitude = |p: V2| p.x.abs().max(p.y.abs());
        let scale = magnitude(x) + radius;
        // (Each distance to within 16 ulps of the magnitudes in it.)
        let clear = |d: f64, at: f64| d >= radius - slack + ulps(16.0) * (scale + at);
        self.pieces.iter().flatten().all(|piece| match *piece {
            Piece::Line(l) => {
                let at = magnitude(l.start) + l.length;
                let end = l.start + l.along * l.length;
                clear((x - l.start).norm(), at)
                    && clear((x - end).norm(), at)
                    && (!piece.falls_on(x) || clear(l.inward.dot(x - l.start).abs(), at))
            }
            Piece::Arc { arc, start, end } => {
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
    fn sweep_is_empty(&self, sites: [TrueSite; 2], ends: [Solved; 2]) -> bool {
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
    fn on_bisector(&self, sites: [TrueSite; 2], e: &Solved) -> bool {
        let x = e.xy;
        let room = ulps(64.0) * (x.x.abs().max(x.y.abs()) + e.radius);
        sites.iter().all(|&s| {
            self.line(s)
                .is_some_and(|l| (l.inward.dot(x - l.start) - e.radius).abs() <= room)
        })
    }

    /// The joint of two segments of one boundary that meet there smoothly (tangent, to the
    /// joints' classification), if `a` and `b` are such.
    pub(crate) fn smooth_joint_between(&self, a: TrueSite, b: TrueSite) -> Option<V2> {
        let after = self.joint_between(a, b)?;
        self.smooth_at((after.boundary, after.segment))
            .then(|| self.start(after))
    }

    /// Of two segments (not corners) next to each other on one boundary, the later: the
    /// joint between them is where it starts. `None` where `a` and `b` are not such.
    pub(crate) fn joint_between(&self, a: TrueSite, b: TrueSite) -> Option<TrueSite> {
        if a.corner || b.corner || a.boundary != b.boundary {
            return None;
        }
        // (A region's boundaries are closed.)
        let n = self.pieces[a.boundary].len();
        if (a.segment + 1) % n == b.segment {
            Some(b)
        } else if (b.segment + 1) % n == a.segment {
            Some(a)
        } else {
            None
        }
    }

    /// Whether the foot of `x` on segment `s` (not a corner) falls on it.
    pub(crate) fn falls_on(&self, s: TrueSite, x: V2) -> bool {
        self.piece(s).falls_on(x)
    }

    /// The segment and the corner at one of its ends, if `a` and `b` are such (either
    /// way round), and where that end is.
    pub(crate) fn own_end(&self, a: TrueSite, b: TrueSite) -> Option<(TrueSite, V2)> {
        let (segment, corner) = match (a.corner, b.corner) {
            (false, true) => (a, b),
            (true, false) => (b, a),
            _ => return None,
        };
        let n = self.pieces[segment.boundary].len();
        (segment.boundary == corner.boundary
            && (corner.segment == segment.segment || corner.segment == (segment.segment + 1) % n))
            .then(|| (segment, self.start(corner)))
    }

    /// Whether the joint where segment `after` starts is smooth.
    pub(crate) fn smooth_at(&self, (boundary, segment): (usize, usize)) -> bool {
        let profile = self.sites.boundaries[boundary];
        let u = segment as f64;
        profile
            .joints()
            .binary_search_by(|j| j.u.total_cmp(&u))
            .is_ok_and(|at| profile.joints()[at].kind == JointKind::Smooth)
    }

    fn piece(&self, s: TrueSite) -> &Piece {
        &self.pieces[s.boundary][s.segment]
    }

    /// The line of site `s`, if it is one (not a corner).
    pub(crate) fn line(&self, s: TrueSite) -> Option<&LineSite> {
        match self.piece(s) {
            Piece::Line(l) if !s.corner => Some(l),
            _ => None,
        }
    }

    /// The arc of site `s`, if it is one (not a corner).
    pub(crate) fn arc(&self, s: TrueSite) -> Option<ArcSite> {
        match self.piece(s) {
            Piece::Arc { arc, .. } if !s.corner => Some(*arc),
            _ => None,
        }
    }

    /// Where the segment of `s` starts (a corner's point).
    pub(crate) fn start(&self, s: TrueSite) -> V2 {
        match self.piece(s) {
            Piece::Line(l) => l.start,
            Piece::Arc { start, .. } => *start,
        }
    }

    /// The unit tangent of the segment of `s` at `at`, one of its points.
    pub(crate) fn tangent_at(&self, s: TrueSite, at: V2) -> V2 {
        match self.piece(s) {
            Piece::Line(l) => l.along,
            Piece::Arc { arc, .. } => (at - arc.centre).perp() * (1.0 / arc.radius),
        }
    }

    /// The shape of site `s`.
    pub(crate) fn shape(&self, s: TrueSite) -> Shape {
        if s.corner {
            return Shape::point(self.start(s));
        }
        match self.piece(s) {
            Piece::Line(l) => Shape::Line(*l),
            Piece::Arc { arc, .. } => Shape::Round {
                centre: arc.centre,
                radius: arc.radius,
                side: arc.side,
            },
        }
    }

    /// The value of an equation at `x`, and its gradient.
    pub(crate) fn equation(&self, e: Equation, x: V2) -> (f64, V2) {
        match e {
            Equation::Equal(a, b) => {
                let ((da, ga), (db, gb)) = (self.shape(a).distance(x), self.shape(b).distance(x));
                (da - db, ga - gb)
            }
            Equation::FootAtEnd { tangent, end, .. } => (tangent.dot(x - end), tangent),
        }
    }

    /// Whether a point within [`JUNCTION_ROOM`] of `x` is equidistant from the three sites
    /// ([`proven_within`]).
    pub(crate) fn prove_junction(&self, x: V2, sites: Option<[TrueSite; 3]>) -> bool {
        let Some(sites) = sites else {
            return false;
        };
        let closed = sites.map(|s| match self.shape(s) {
            Shape::Line(l) => Some(ClosedSite::Line {
                start: l.start,
                inward: l.inward,
            }),
            Shape::Round {
                centre,
                radius,
                side,
            } => Some(if radius == 0.0 {
                ClosedSite::Point(centre)
            } else {
                ClosedSite::Circle {
                    centre,
                    radius,
                    side,
                }
            }),
        });
        let [Some(a), Some(b), Some(c)] = closed else {
            return false;
        };
        // (The box's half-width: its corners within the room of its centre.)
        JUNCTION_ROOM.iter().any(|&room| {
            proven_within(
                [a, b, c],
                x,
                room * self.sites.size / std::f64::consts::SQRT_2,
            )
        })
    }

    /// The two equations whose gradients at `x` are nearest perpendicular (the best
    /// conditioned system), if any two are independent.
    pub(crate) fn best_pair(&self, equations: &[Equation], x: V2) -> Option<(Equation, Equation)> {
        let unit = |e: Equation| {
            let g = self.equation(e, x).1;
            g * (1.0 / g.norm())
        };
        let mut best: Option<(f64, Equation, Equation)> = None;
        for (i, &a) in equations.iter().enumerate() {
            for &b in &equations[i + 1..] {
                let det = unit(a).cross(unit(b)).abs();
                if det > MIN_SINE && best.is_none_or(|(d, _, _)| det > d) {
                    best = Some((det, a, b));
                }
            }
        }
        best.map(|(_, a, b)| (a, b))
    }

    /// The vertices of the straight bisector (of two lines or two points) from `p` to `q`,
    /// [`EDGE_STEP`] apart.
    fn straight(&self, p: V2, q: V2) -> Option<Vec<V2>> {
        let steps = ((q - p).norm() / (EDGE_STEP * self.sites.size))
            .ceil()
            .max(1.0);
        (steps <= MAX_EDGE_VERTICES as f64).then(|| {
            let n = steps as usize;
            // (The ends exactly: they are the nodes.)
            (0..=n)
                .map(|k| match k {
                    0 => p,
                    k if k == n => q,
                    k => p + (q - p) * (k as f64 / n as f64),
                })
                .collect()
        })
    }

    /// The vertices of the conic bisector of `sites` from `p` to `q`, within the chord
    /// tolerance and [`EDGE_STEP`] apart. Its points come from the feet on one site (a line if
    /// there is one, else the round site whose centre is farther from the ends): along the
    /// normal ray at each foot, the other site is as far as the foot where
    /// [`Shape::radius_on_ray`] says. The foot parameter's span is halved until each chord
    /// is within the tolerance of the point halfway along it.
    fn conic(&self, sites: [TrueSite; 2], p: V2, q: V2) -> Option<Vec<V2>> {
        let shapes = sites.map(|s| self.shape(s));
        let room = |k: usize| shapes[k].param_room(p).min(shapes[k].param_room(q));
        let by = if room(1) > room(0) { 1 } else { 0 };
        // (Not a number too refuses.)
        if room(by).partial_cmp(&(FOOT_ROOM * self.sites.size)) != Some(std::cmp::Ordering::Greater)
        {
            return None;
        }
        let (along, other) = (shapes[by], shapes[1 - by]);
        let t0 = along.param_of(p);
        let t1 = match along {
            Shape::Line(_) => along.param_of(q),
            // (A foot turns by less than half a turn along one edge.)
            Shape::Round { .. } => t0 + wrap_pi(along.param_of(q) - t0),
        };
        let at = |t: f64| {
            let (foot, normal) = along.ray(t);
            other.radius_on_ray(foot, normal).map(|r| foot + normal * r)
        };
        let step = EDGE_STEP * self.sites.size;
        let mut out = vec![p];
        let (mut t_lo, mut x_lo) = (t0, p);
        // (The right ends still to reach, the nearest last; the point where the radius is
        // least or greatest among them, a vertex: the offsets find where a pass touches
        // itself there.)
        let mut stack = vec![(t1, q, 0usize)];
        if let Some(t) = radius_extremum(along, other, t0, t1) {
            stack.push((t, at(t)?, 0));
        }
        while let Some(&(t_hi, x_hi, depth)) = stack.last() {
            let t_mid = 0.5 * (t_lo + t_hi);
            let x_mid = at(t_mid)?;
            let sag = curve::distance_to_segment(x_mid.arr(), x_lo.arr(), x_hi.arr());
            if (x_hi - x_lo).norm() > step || sag > self.chord_tol {
                if depth == MAX_EDGE_HALVINGS {
                    return None; // (finer than the tracer goes: the other paths decide)
                }
                stack.push((t_mid, x_mid, depth + 1));
            } else {
                stack.pop();
                out.push(x_hi);
                (t_lo, x_lo) = (t_hi, x_hi);
                if out.len() > MAX_EDGE_VERTICES {
                    return None;
                }
            }
        }
        Some(out)
    }

    /// The profile parameter of the foot of `x` on site `s` (a corner's own); `None` where
    /// the foot falls off its segment.
    pub(crate) fn foot(&self, s: TrueSite, x: V2) -> Option<f64> {
        if s.corner {
            return Some(s.segment as f64);
        }
        let slack = FOOT_SLACK * self.sites.size;
        let base = s.segment as f64;
        match self.piece(s) {
            Piece::Line(l) => {
                let along = l.along.dot(x - l.start);
                (along >= -slack && along <= l.length + slack)
                    .then(|| base + (along / l.length).clamp(0.0, 1.0))
            }
            Piece::Arc { arc, .. } => {
                let angle = arc.angle_from_start(x);
                let slack = slack / arc.radius;
                (angle >= -slack && angle <= arc.sweep() + slack)
                    .then(|| base + arc.share_at(angle))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::LinesAndArcs;
    use crate::sites::{Sites, EMPTY_SLACK};
    use crate::test_shapes::random_rounded;
    use curve::V2;
    use testkit::rng;

    /// The closed-form disk test is sound and sharp against the boundary's nearest point (found
    /// on the exact forms): on 200 random rounded stars with round holes, at random points of
    /// their box (inside and out) and at their arcs' centres, with radii within five slacks
    /// of the distance to the boundary and within a thousandth of the size below it, it never
    /// calls a disk clear that holds a point nearer than its radius less the slack, and calls
    /// clear every disk a thousandth of the size smaller than that distance.
    #[test]
    fn the_closed_form_disk_test_agrees_with_the_nearest_point() {
        let mut rnd = rng(4003);
        let (mut tested, mut clear) = (0, 0);
        for _ in 0..200 {
            let Some(region) = random_rounded(&mut rnd) else {
                continue;
            };
            let sites = Sites::new(&region, false);
            let model = LinesAndArcs::new(&sites, 1e-3).unwrap();
            assert!(model.few);
            let size = sites.size;
            let slack = EMPTY_SLACK * size;
            let centres = sites
                .boundaries
                .iter()
                .flat_map(|b| b.segments().iter().filter_map(|s| s.circle()))
                .map(|(c, _)| V2::from_arr(c));
            let random: Vec<V2> = (0..20)
                .map(|_| V2::new(4.0 * rnd() - 2.0, 4.0 * rnd() - 2.0))
                .collect();
            for x in centres.chain(random) {
                let nearest = sites.nearest(x.arr(), 0.0).0;
                for radius in [
                    nearest + slack * (10.0 * rnd() - 5.0),
                    nearest - 1e-3 * size * rnd(),
                ] {
                    let said = model.clear_in_closed_form(x, radius);
                    tested += 1;
                    clear += usize::from(said);
                    // (The nearest point is found to ~1e-15 of the size.)
                    assert!(
                        !said || nearest >= radius - slack - 1e-14 * size,
                        "{x:?}: clear at {radius}, the nearest at {nearest}"
                    );
                    if radius <= nearest - slack {
                        assert!(
                            said,
                            "{x:?}: not clear at {radius}, the nearest at {nearest}"
                        );
                    }
                }
            }
        }
        assert!(
            tested > 6000 && clear > tested / 2,
            "{clear} clear of {tested}"
        );
    }

    /// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
    fn hull(mut points: Vec<V2>) -> Vec<V2> {
        points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        let mut out: Vec<V2> = Vec::new();
        for pass in 0..2 {
            let start = out.len();
            for &p in &points {
                while out.len() >= start + 2
                    && (out[out.len() - 1] - out[out.len() - 2]).cross(p - out[out.len() - 2])
                        <= 0.0
                {
                    out.pop();
                }
                out.push(p);
            }
            out.pop();
            if pass == 0 {
                points.reverse();
            }
        }
        out
    }

    proptest::proptest! {
        /// The disks along a bisector of two lines (each less the slack) lie in the end disks
        /// and the polygon of [`super::sweep_polygon`], checked on dense points of their rims:
        /// for lines meeting at any angle and for parallel ones.
        #[test]
        fn the_sweep_polygon_covers_the_disks_between(
            apex in proptest::array::uniform2(-10.0f64..10.0),
            turn in 0.0f64..6.3,
            half_angle in 0.0f64..1.5,
            s in proptest::array::uniform2(0.01f64..5.0),
        ) {
            use super::sweep_polygon;
            use crate::true_sites::LineSite;
            let slack = 1e-3;
            let (o, u) = (V2::from_arr(apex), V2::polar(turn));
            let parallel = half_angle < 0.05;
            let rotate = |v: V2, a: f64| V2::new(v.x * a.cos() - v.y * a.sin(), v.x * a.sin() + v.y * a.cos());
            let (da, db) = if parallel { (u, u) } else { (rotate(u, half_angle), rotate(u, -half_angle)) };
            let (na, nb) = (rotate(da, -std::f64::consts::FRAC_PI_2), rotate(db, std::f64::consts::FRAC_PI_2));
            // (Parallel lines: 1 on either side of the line through the apex along u.)
            let (sa, sb) = if parallel { (o - na, o - nb) } else { (o, o) };
            let line = |start: V2, along: V2, inward: V2| LineSite { start, along, length: 100.0, inward };
            let lines = [line(sa, da, na), line(sb, db, nb)];
            let (s0, s1) = (s[0].min(s[1]), s[0].max(s[1]));
            let c = [o + u * s0, o + u * (s1 + 0.01)];
            let r = c.map(|x| lines[0].inward.dot(x - lines[0].start));
            proptest::prop_assume!(r[0] > slack);
            let poly = hull(sweep_polygon(c, r, lines, slack).to_vec());
            let inside = |x: V2| {
                (0..poly.len()).all(|k| {
                    let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
                    (b - a).cross(x - a) >= -1e-12 * (b - a).norm()
                })
            };
            for i in 0..=40 {
                let t = i as f64 / 40.0;
                let (ct, rt) = (c[0] + (c[1] - c[0]) * t, r[0] + (r[1] - r[0]) * t - slack);
                for k in 0..720 {
                    let x = ct + V2::polar(std::f64::consts::TAU * k as f64 / 720.0) * rt;
                    let in_disk = |j: usize| (x - c[j]).norm() <= r[j] - slack + 1e-12;
                    proptest::prop_assert!(in_disk(0) || in_disk(1) || inside(x), "t {t} at {x:?}");
                }
            }
            // (And the polygon keeps clear of both lines.)
            for l in &lines {
                for x in &poly {
                    proptest::prop_assert!(l.inward.dot(*x - l.start) >= 0.2 * slack);
                }
            }
        }
    }
}
