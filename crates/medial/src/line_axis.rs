//! The axis of a region bounded by lines alone, edge by edge from the seed's diagram.
//!
//! There the chords are the boundary itself (snapped to the seed's grid), so the diagram's
//! topology is the axis's up to the snapping: every primary edge on the axis's side is a
//! stretch of the bisector of two true sites (lines, and reflex corners as points), and every
//! vertex is a disk touching three of them. Each vertex is solved again on the true
//! coordinates by Newton's method from the diagram's (its equations in closed form), and each
//! edge traced in closed form between its ends: the bisector of two lines or two points is
//! straight, that of a line and a point a parabola. No bisector is traced beyond its stretch
//! and no stretch is searched for: the cost is O(n) beyond the diagram's, and the disk tests'.
//!
//! The seed still proves nothing. Every vertex's disk is tested for emptiness and every foot
//! for lying on its segment, as on the other paths; the axis is then certified and its feet's
//! coverage of the boundaries checked ([`crate::coverage`]) like the seeded candidates'. A
//! diagram that disagrees with the true coordinates anywhere (a vertex Newton cannot place
//! near the diagram's, a foot off its segment, an entered disk) yields `None`, and the axis is
//! built on the slower paths.

use crate::candidates::Candidate;
use crate::certificate::JUNCTION_ROOM;
use crate::corners::entered_across_corner;
use crate::junction_proof::{proven_within, ClosedSite};
use crate::parallel::in_order;
use crate::seed::{chord_diagram, edge_sites, on_side, Approximation, Owner, Site};
use crate::sites::{Disk, Sites, EMPTY_SLACK};
use crate::stretches::{Stretch, Vertex};
use boostvoronoi::prelude::{Diagram, EdgeIndex, VertexIndex};
use curve::{JointKind, SegmentKind, V2};
use std::collections::{HashMap, HashSet};

/// Most distance (a share of the size) between the vertices of a straight edge: the disks
/// between its ends are tested at that step (as the bisectors of two corners are on the other
/// paths).
const EDGE_STEP: f64 = 1e-2;

/// Ends of edges within this share of the size are one node. The ends of the edges at one
/// vertex of the diagram are one point to the bit, so only vertices that snapping or nearly
/// cocircular sites put this close count as one: the seed's grid spacing. (The other paths
/// find each junction once per branch, and merge within 1e-6.)
pub(crate) const MERGE: f64 = 1e-9;

/// Most vertices of one edge: a parabola's to the finest chord tolerance (1e-9 of the size)
/// takes ~2e4 on a region's width; beyond this the input is refused to the other paths.
const MAX_EDGE_VERTICES: usize = 1 << 16;

/// Newton steps that place a vertex: from the diagram's point, ~2e-9 of the size off, the
/// equations (linear for lines, a norm for points) converge in two or three.
const NEWTON_STEPS: usize = 16;

/// How far (a share of the size) a vertex may move from the diagram's point: the snapping
/// moves the sites by 1e-9 of the size, which a vertex follows magnified by its conditioning
/// (a junction of a side 1e-6 of the size long with far ones turns with that side, by
/// 2e-3 rad). A vertex Newton's method takes farther has left the diagram's neighbourhood
/// (another root of a point's equation): the other paths decide. (A vertex within reach but
/// wrong is refused by its disk's test, its feet's, or the coverage.)
const SEED_REACH: f64 = 1e-2;

/// The equations of a vertex not used to solve it (a fourth site of nearly cocircular ones)
/// must hold to this share of the size: within the reach in which ends are one node.
const OTHER_EQUATIONS: f64 = 1e-6;

/// The least sine of the angle between the gradients of two equations a vertex is solved
/// on: below, they are one equation to rounding (two lines of one line, after snapping), and
/// Newton's method would slide along their common zero.
const MIN_SINE: f64 = 1e-9;

/// Most edges round one vertex of the diagram (a bound on its walk round the vertex).
const MAX_DEGREE: usize = 64;

/// A foot may stray this share of the size beyond its segment's ends (rounding).
const FOOT_SLACK: f64 = 1e-9;

/// The three sites of two equations of equal distance that share one, the shared first.
fn three_sites(p: [TrueSite; 2], q: [TrueSite; 2]) -> Option<[TrueSite; 3]> {
    let shared = p.into_iter().find(|s| q.contains(s))?;
    let other = |e: [TrueSite; 2]| if e[0] == shared { e[1] } else { e[0] };
    let (b, c) = (other(p), other(q));
    (b != c).then_some([shared, b, c])
}

/// A true site: line `segment` of boundary `boundary`, or the corner where it starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
struct TrueSite {
    boundary: usize,
    segment: usize,
    corner: bool,
}

/// What holds at a vertex of the diagram: two sites at one distance (a primary edge), or the
/// foot on a line at its end point (a secondary edge, between a line and its own end).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Equation {
    Equal(TrueSite, TrueSite),
    FootAtEnd { line: TrueSite, end: V2 },
}

/// One line of a boundary: its start, unit direction, length and unit normal into the axis's
/// side.
#[derive(Debug, Clone, Copy)]
struct LineSite {
    start: V2,
    along: V2,
    length: f64,
    inward: V2,
}

/// A node of the axis solved from a vertex of the diagram (its disk tested empty), and
/// whether its place is proven in closed form (a junction of three sites).
#[derive(Debug, Clone, Copy)]
struct Solved {
    xy: V2,
    radius: f64,
    proven: bool,
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

/// A primary edge of the diagram to trace: its two true sites and its two vertices.
struct Job {
    sites: [TrueSite; 2],
    ends: [VertexIndex; 2],
}

/// The lines of the boundaries, the diagram, and the vertices solved.
struct Tracer<'s, 'a> {
    sites: &'s Sites<'a>,
    lines: Vec<Vec<LineSite>>,
    approx: Approximation,
    diagram: Diagram,
    solved: HashMap<usize, Option<Solved>>,
    chord_tol: f64,
}

/// The candidates and stretches of the axis of `sites`' region (inside), every boundary made
/// of lines: one candidate per edge, each its own stretch. `None` where some boundary is not
/// lines alone, no diagram can be made, or the diagram disagrees with the true coordinates.
pub(crate) fn trace(sites: &Sites<'_>, chord_tol: f64) -> Option<Traced> {
    let lines_only = sites
        .boundaries
        .iter()
        .all(|b| b.segments().iter().all(|s| s.kind() == SegmentKind::Line));
    if !lines_only || sites.clip.is_some() {
        return None;
    }
    let inside_left: Vec<f64> = (0..sites.boundaries.len())
        .map(|k| sites.inside_left(k))
        .collect();
    let (approx, diagram) = chord_diagram(
        &sites.boundaries,
        &inside_left,
        crate::candidates::root_box(sites),
        sites.size,
    )?;
    // Every joint kept its point through the snapping: each chord is then one line.
    let segments: usize = sites.boundaries.iter().map(|b| b.segments().len()).sum();
    if approx.points.len() != segments || approx.owner.iter().any(|o| matches!(o, Owner::Inside(_)))
    {
        return None;
    }
    let lines = sites
        .boundaries
        .iter()
        .enumerate()
        .map(|(k, b)| {
            b.segments()
                .iter()
                .map(|s| {
                    let (a, e) = (s.start(), s.end());
                    let length = (e - a).norm();
                    let along = (e - a) * (1.0 / length);
                    let inward = V2::new(-along.y, along.x) * inside_left[k];
                    LineSite {
                        start: a,
                        along,
                        length,
                        inward,
                    }
                })
                .collect()
        })
        .collect();
    let mut tracer = Tracer {
        sites,
        lines,
        approx,
        diagram,
        solved: HashMap::new(),
        chord_tol: chord_tol * sites.size,
    };
    tracer.edges(&inside_left)
}

impl Tracer<'_, '_> {
    /// Every primary edge on the axis's side, traced: the edges and the vertices they need
    /// listed in the diagram's order, every vertex solved once, then every edge traced
    /// (both in parallel where the feature is on; the output in the diagram's order, never
    /// the threads').
    fn edges(&mut self, inside_left: &[f64]) -> Option<Traced> {
        let stage = curve::watch::stage("medial axis: the seed's edges");
        let mut jobs: Vec<Job> = Vec::new();
        // (Each vertex solved from the first edge that reaches it, as a serial walk would.)
        let mut vertices: Vec<(VertexIndex, EdgeIndex)> = Vec::new();
        let mut listed = HashSet::new();
        for k in 0..self.diagram.edges().len() {
            let edge = &self.diagram.edges()[k];
            let id = edge.id();
            let twin = self.diagram.edge_get_twin(id).ok()?;
            if twin.usize() < id.usize() || !edge.is_primary() {
                continue;
            }
            let [a, b] = edge_sites(&self.approx, &self.diagram, id)?;
            let ends = [edge.vertex0(), self.diagram.edge_get_vertex1(id).ok()?];
            let grid = ends.map(|v| {
                v.and_then(|v| self.diagram.vertex(v).ok())
                    .map(|v| [v.x(), v.y()])
            });
            if !on_side(&self.approx, a, grid, inside_left) {
                continue;
            }
            // (Inside a closed boundary every edge is finite.)
            let [Some(v0), Some(v1)] = ends else {
                return None;
            };
            let (a, b) = (self.true_site(a)?, self.true_site(b)?);
            // (Two lines across a smooth joint have one foot there: no axis between them, and
            // no ends to solve for it.)
            if self.smooth_joint_between(a, b).is_some() {
                continue;
            }
            for (v, from) in [(v0, id), (v1, twin)] {
                if listed.insert(v.usize()) {
                    vertices.push((v, from));
                }
            }
            jobs.push(Job {
                sites: [a, b],
                ends: [v0, v1],
            });
        }
        let solved = in_order(&vertices, |&(v, from)| {
            stage.go_on(0).then(|| self.solve_vertex(v, from)).flatten()
        });
        self.solved = vertices
            .iter()
            .map(|(v, _)| v.usize())
            .zip(solved)
            .collect();
        let traced = in_order(&jobs, |job| {
            if !stage.go_on(1) {
                return None; // (the caller answers "cancelled")
            }
            self.trace_job(job)
        });
        let mut candidates = Vec::new();
        let mut stretches = Vec::new();
        for found in traced {
            if let Some((candidate, vertices)) = found? {
                stretches.push(Stretch {
                    candidate: candidates.len(),
                    vertices,
                });
                candidates.push(candidate);
            }
        }
        let proven = self
            .solved
            .values()
            .flatten()
            .filter(|s| s.proven)
            .map(|s| s.xy.arr().map(f64::to_bits))
            .collect();
        Some(Traced {
            candidates,
            stretches,
            proven,
        })
    }

    /// The candidate and vertices of one edge, its ends solved; `Some(None)` where its ends
    /// are one node (the edge of nearly cocircular sites that snapping made), `None` where
    /// the diagram disagrees with the true coordinates.
    fn trace_job(&self, job: &Job) -> Option<Option<(Candidate, Vec<Vertex>)>> {
        let [a, b] = job.sites;
        let solved = |v: VertexIndex| self.solved.get(&v.usize()).copied().flatten();
        let (p, q) = (solved(job.ends[0])?, solved(job.ends[1])?);
        if (q.xy - p.xy).norm() <= MERGE * self.sites.size {
            return Some(None);
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
        let (sites, ends) = if a <= b {
            ([a, b], [p, q])
        } else {
            ([b, a], [q, p])
        };
        let vertices = self.trace_edge(sites, ends)?;
        let candidate = Candidate {
            boundary: sites.map(|s| s.boundary),
            segment: sites.map(|s| s.segment),
            corner: sites.map(|s| s.corner),
            tr: vertices.iter().map(|v| v.tr).collect(),
            xy: vertices.iter().map(|v| v.xy).collect(),
        };
        // (The ends' disks were tested when they were solved; those between, all at once
        // where the edge is two lines' and the sweep of its disks is proven empty.)
        let last = vertices.len() - 1;
        let swept = last > 1 && self.sweep_is_empty(sites, ends);
        for (k, v) in vertices.iter().enumerate() {
            let tested = k == 0 || k == last || swept;
            if !(tested || self.empty(v))
                || entered_across_corner(self.sites, &candidate, v).is_some()
            {
                return None;
            }
        }
        Some(Some((candidate, vertices)))
    }

    /// Whether the disk of `v` is empty, as the other paths test it (beside a convex corner
    /// that turns by little, the other side's distance is measured too: see
    /// [`entered_across_corner`]). A disk of radius nil (at a convex corner) holds nothing.
    fn empty(&self, v: &Vertex) -> bool {
        v.radius == 0.0 || self.sites.disk(v.xy, v.radius) == Disk::Empty
    }

    /// Whether the disks along the straight bisector of two lines between its ends (each
    /// less the slack of the disk tests) are all empty, proven at once. Their centres and
    /// radii move linearly (the radii interpolated from the ends'), so they sweep the convex
    /// hull of the two end disks: the end disks themselves (tested when the ends were solved)
    /// and the band between their points of tangency with the lines, which [`sweep_polygon`]
    /// covers. That
    /// polygon is tested against the boundary's lines by separating axes. `false` where not
    /// proven (the edge of a corner, ends off the bisector beyond rounding, a line near the
    /// polygon): its disks are then tested one by one.
    fn sweep_is_empty(&self, sites: [TrueSite; 2], ends: [Solved; 2]) -> bool {
        if sites[0].corner || sites[1].corner {
            return false;
        }
        let slack = EMPTY_SLACK * self.sites.size;
        let lines = sites.map(|s| *self.line(s));
        if !ends.iter().all(|e| self.on_bisector(sites, e)) {
            return false;
        }
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
        let polygon = sweep_polygon([p.xy, q.xy], [p.radius, q.radius], lines, slack).map(V2::arr);
        self.sites
            .boundaries
            .iter()
            .all(|b| b.misses_convex_polygon(&polygon))
    }

    /// Whether `e` lies on the bisector of two lines with its radius their distance, to
    /// rounding. (An end solved on other equations may lie off it by their agreement.)
    fn on_bisector(&self, sites: [TrueSite; 2], e: &Solved) -> bool {
        let x = e.xy;
        let room = 64.0 * f64::EPSILON * (x.x.abs().max(x.y.abs()) + e.radius);
        sites.iter().all(|&s| {
            let l = self.line(s);
            (l.inward.dot(x - l.start) - e.radius).abs() <= room
        })
    }

    /// The true site of a site of the diagram.
    fn true_site(&self, s: Site) -> Option<TrueSite> {
        Some(match s {
            Site::Chord(c) => {
                let (boundary, segment) = self.approx.chord_segment(c);
                TrueSite {
                    boundary,
                    segment,
                    corner: false,
                }
            }
            Site::Point(p) => match self.approx.owner[p] {
                Owner::Joint { after, .. } => TrueSite {
                    boundary: after.0,
                    segment: after.1,
                    corner: true,
                },
                Owner::Inside(_) => return None,
            },
        })
    }

    /// The joint of two lines of one boundary that meet there smoothly (collinear, to the
    /// joints' classification), if `a` and `b` are such.
    fn smooth_joint_between(&self, a: TrueSite, b: TrueSite) -> Option<V2> {
        if a.corner || b.corner || a.boundary != b.boundary {
            return None;
        }
        let profile = self.sites.boundaries[a.boundary];
        // (A region's boundaries are closed.)
        let n = profile.segments().len();
        let after = if (a.segment + 1) % n == b.segment {
            b
        } else if (b.segment + 1) % n == a.segment {
            a
        } else {
            return None;
        };
        let u = after.segment as f64;
        let at = profile
            .joints()
            .binary_search_by(|j| j.u.total_cmp(&u))
            .ok()?;
        (profile.joints()[at].kind == JointKind::Smooth).then(|| self.line(after).start)
    }

    fn line(&self, s: TrueSite) -> &LineSite {
        &self.lines[s.boundary][s.segment]
    }

    /// The distance from `x` to site `s` (to a line's line, signed: positive on the axis's
    /// side) and its gradient.
    fn distance(&self, s: TrueSite, x: V2) -> (f64, V2) {
        let l = self.line(s);
        if s.corner {
            let d = x - l.start;
            let n = d.norm();
            (n, d * (1.0 / n))
        } else {
            (l.inward.dot(x - l.start), l.inward)
        }
    }

    /// The value of an equation at `x`, and its gradient.
    fn equation(&self, e: Equation, x: V2) -> (f64, V2) {
        match e {
            Equation::Equal(a, b) => {
                let ((da, ga), (db, gb)) = (self.distance(a, x), self.distance(b, x));
                (da - db, ga - gb)
            }
            Equation::FootAtEnd { line, end } => {
                let along = self.line(line).along;
                (along.dot(x - end), along)
            }
        }
    }

    /// The node at vertex `v` of the diagram (`from` one of its edges).
    fn solve_vertex(&self, v: VertexIndex, from: EdgeIndex) -> Option<Solved> {
        let vertex = self.diagram.vertex(v).ok()?;
        let grid = [vertex.x(), vertex.y()];
        let mut equations: Vec<Equation> = Vec::new();
        let mut corners: Vec<(usize, TrueSite)> = Vec::new();
        for e in self.diagram.edge_rot_next_iterator(from).take(MAX_DEGREE) {
            let edge = self.diagram.edge(e).ok()?;
            let [sa, sb] = edge_sites(&self.approx, &self.diagram, e)?;
            for s in [sa, sb] {
                if let Site::Point(p) = s {
                    corners.push((p, self.true_site(s)?));
                }
            }
            let (a, b) = (self.true_site(sa)?, self.true_site(sb)?);
            let eq = if let Some(end) = self.smooth_joint_between(a, b) {
                // (Their distances are one function: the edge is the normal at the joint.)
                Equation::FootAtEnd { line: a, end }
            } else if edge.is_primary() {
                Equation::Equal(a.min(b), a.max(b))
            } else {
                let (line, corner) = if a.corner { (b, a) } else { (a, b) };
                Equation::FootAtEnd {
                    line,
                    end: self.line(corner).start,
                }
            };
            if a != b && !equations.contains(&eq) {
                equations.push(eq);
            }
        }
        // A vertex at a point of the boundary: a convex corner, where its two lines' bisector
        // starts with a disk of radius nil.
        if vertex.is_site_point() {
            let at = |p: usize| {
                let q = self.approx.points[p];
                [f64::from(q[0]), f64::from(q[1])] == grid
            };
            let &(_, corner) = corners.iter().find(|(p, _)| at(*p))?;
            return Some(Solved {
                xy: self.line(corner).start,
                radius: 0.0,
                proven: false,
            });
        }
        let start = V2::from_arr(self.approx.unsnap(grid));
        let (e0, e1) = self.best_pair(&equations, start)?;
        let size = self.sites.size;
        let mut x = start;
        for _ in 0..NEWTON_STEPS {
            let ((f0, g0), (f1, g1)) = (self.equation(e0, x), self.equation(e1, x));
            let det = g0.cross(g1);
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            // (Cramer's rule on the 2 × 2 Jacobian.)
            let step = V2::new(f0 * g1.y - f1 * g0.y, g0.x * f1 - g1.x * f0) * (1.0 / det);
            x = x - step;
            if step.norm() <= 4.0 * f64::EPSILON * (x.norm() + size) {
                break;
            }
        }
        let moved = (x - start).norm();
        if moved.is_nan() || moved > SEED_REACH * size {
            return None;
        }
        let agree = equations
            .iter()
            .all(|&e| self.equation(e, x).0.abs() <= OTHER_EQUATIONS * size);
        let radius = match e0 {
            Equation::Equal(a, _) => self.distance(a, x).0,
            Equation::FootAtEnd { line, .. } => self.distance(line, x).0,
        };
        if !(agree && radius > 0.0 && self.sites.disk(x.arr(), radius) == Disk::Empty) {
            return None;
        }
        // (Proven on the best conditioned two equations of equal distance: those Newton's
        // method used may hold a foot at a line's end, which is no junction's.)
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

    /// Whether a point within [`JUNCTION_ROOM`] of `x` is equidistant from the three sites
    /// ([`proven_within`]).
    fn prove_junction(&self, x: V2, sites: Option<[TrueSite; 3]>) -> bool {
        let Some(sites) = sites else {
            return false;
        };
        let closed = sites.map(|s| {
            let l = self.line(s);
            if s.corner {
                ClosedSite::Point(l.start)
            } else {
                ClosedSite::Line {
                    start: l.start,
                    inward: l.inward,
                }
            }
        });
        // (The box's half-width: its corners within the room of its centre.)
        JUNCTION_ROOM.iter().any(|&room| {
            proven_within(closed, x, room * self.sites.size / std::f64::consts::SQRT_2)
        })
    }

    /// The two equations whose gradients at `x` are nearest perpendicular (the best
    /// conditioned system), if any two are independent.
    fn best_pair(&self, equations: &[Equation], x: V2) -> Option<(Equation, Equation)> {
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

    /// The vertices of the bisector of `sites` from one end to the other: straight for two
    /// lines or two points, a parabola for a line and a point (at the chord tolerance).
    fn trace_edge(&self, sites: [TrueSite; 2], ends: [Solved; 2]) -> Option<Vec<Vertex>> {
        let [p, q] = ends;
        let size = self.sites.size;
        let straight = || {
            let steps = ((q.xy - p.xy).norm() / (EDGE_STEP * size)).ceil().max(1.0);
            (steps <= MAX_EDGE_VERTICES as f64).then(|| {
                let n = steps as usize;
                // (The ends exactly: they are the nodes.)
                (0..=n)
                    .map(|k| match k {
                        0 => p.xy,
                        k if k == n => q.xy,
                        k => p.xy + (q.xy - p.xy) * (k as f64 / n as f64),
                    })
                    .collect::<Vec<V2>>()
            })
        };
        let affine =
            !sites[0].corner && !sites[1].corner && ends.iter().all(|e| self.on_bisector(sites, e));
        let points = match sites {
            [a, b] if a.corner == b.corner => straight()?,
            [a, b] => {
                let (line, point) = if a.corner { (b, a) } else { (a, b) };
                self.parabola(self.line(line), self.line(point).start, p.xy, q.xy)?
            }
        };
        let last = points.len() - 1;
        points
            .into_iter()
            .enumerate()
            .map(|(k, x)| {
                // (Between two lines the radius is affine along the edge: the ends' radii
                // interpolated, where they are the lines' distances, so that the disks
                // between are the sweep of the end disks.)
                let radius = match k {
                    0 => p.radius,
                    k if k == last => q.radius,
                    _ if affine => p.radius + (q.radius - p.radius) * (k as f64 / last as f64),
                    _ => self.distance(sites[0], x).0,
                };
                let tr = [self.foot(sites[0], x)?, self.foot(sites[1], x)?];
                (radius >= 0.0).then_some(Vertex {
                    tr,
                    xy: x.arr(),
                    radius,
                })
            })
            .collect()
    }

    /// The points of the parabola of the points as far from `line` as from `point` between
    /// its points `from` and `to`, within the chord tolerance (and [`EDGE_STEP`] apart).
    fn parabola(&self, line: &LineSite, point: V2, from: V2, to: V2) -> Option<Vec<V2>> {
        // By the foot's arc length s along the line, the point's radius is
        // |foot − point|² / 2h, h the point's height over the line: its second derivative
        // is 1/h, and a chord over a step Δ strays Δ² / 8h.
        let h = line.inward.dot(point - line.start);
        if h.is_nan() || h <= 0.0 {
            return None;
        }
        let (s0, s1) = (
            line.along.dot(from - line.start),
            line.along.dot(to - line.start),
        );
        let by_sag = (8.0 * h * self.chord_tol).sqrt();
        let step = by_sag.min(EDGE_STEP * self.sites.size);
        let steps = ((s1 - s0).abs() / step).ceil().max(1.0);
        if steps.is_nan() || steps > MAX_EDGE_VERTICES as f64 {
            return None;
        }
        let n = steps as usize;
        let mut out: Vec<V2> = (0..=n)
            .map(|k| {
                let s = s0 + (s1 - s0) * (k as f64 / n as f64);
                let foot = line.start + line.along * s;
                let d = foot - point;
                foot + line.inward * (d.dot(d) / (2.0 * h))
            })
            .collect();
        out[0] = from;
        out[n] = to;
        Some(out)
    }

    /// The profile parameter of the foot of `x` on site `s` (a corner's own); `None` where
    /// the foot on a line falls off its segment.
    fn foot(&self, s: TrueSite, x: V2) -> Option<f64> {
        if s.corner {
            return Some(s.segment as f64);
        }
        let l = self.line(s);
        let along = l.along.dot(x - l.start);
        let slack = FOOT_SLACK * self.sites.size;
        (along >= -slack && along <= l.length + slack)
            .then(|| s.segment as f64 + (along / l.length).clamp(0.0, 1.0))
    }
}

#[cfg(test)]
mod tests {
    use crate::bench_shapes::{polygon, rng, star_polygon};
    use crate::candidates::PairSource;
    use crate::test_shapes::{polygon_star_with_polygon_holes, stands_as_the_bounds};
    use crate::{axis_of, MedialAxis, MedialOptions};
    use curve::{Region, V2};

    /// The distance from `x` to the polyline `p`.
    fn to_polyline(x: [f64; 2], p: &[[f64; 2]]) -> f64 {
        if p.len() == 1 {
            return (V2::from_arr(x) - V2::from_arr(p[0])).norm();
        }
        p.windows(2)
            .map(|w| curve::distance_to_segment(x, w[0], w[1]))
            .fold(f64::INFINITY, f64::min)
    }

    /// Whether two axes are the same graph: nodes of one kind within `near` of each other
    /// (one to one), edges between matching nodes, each one's vertices within `near` of
    /// the other's polyline, with the same boundaries at their ends.
    fn same_graph(a: &MedialAxis, b: &MedialAxis, near: f64) -> Result<(), String> {
        if a.nodes.len() != b.nodes.len() || a.edges.len() != b.edges.len() {
            return Err(format!(
                "{} nodes, {} edges against {} and {}",
                a.nodes.len(),
                a.edges.len(),
                b.nodes.len(),
                b.edges.len()
            ));
        }
        let apart = |p: [f64; 2], q: [f64; 2]| (V2::from_arr(p) - V2::from_arr(q)).norm();
        let mut match_of = vec![usize::MAX; a.nodes.len()];
        let mut taken = vec![false; b.nodes.len()];
        for n in &a.nodes {
            let m = b
                .nodes
                .iter()
                .filter(|m| !taken[m.id] && m.kind == n.kind)
                .min_by(|p, q| apart(p.xy, n.xy).total_cmp(&apart(q.xy, n.xy)))
                .ok_or(format!("no node for {n:?}"))?;
            if apart(m.xy, n.xy) > near || (m.radius - n.radius).abs() > near {
                return Err(format!("node {n:?} against {m:?}"));
            }
            taken[m.id] = true;
            match_of[n.id] = m.id;
        }
        let mut used = vec![false; b.edges.len()];
        for e in &a.edges {
            let ends = [match_of[e.from], match_of[e.to]];
            let mut ends_sorted = ends;
            ends_sorted.sort_unstable();
            let boundaries = |x: &[[usize; 2]]| {
                let mut v = [x[0], x[x.len() - 1]].concat();
                v.sort_unstable();
                v
            };
            let found = b.edges.iter().enumerate().find(|(k, f)| {
                let mut f_ends = [f.from, f.to];
                f_ends.sort_unstable();
                !used[*k]
                    && f_ends == ends_sorted
                    && boundaries(&f.boundary) == boundaries(&e.boundary)
                    && e.xy.iter().all(|&x| to_polyline(x, &f.xy) <= near)
                    && f.xy.iter().all(|&x| to_polyline(x, &e.xy) <= near)
            });
            match found {
                Some((k, _)) => used[k] = true,
                None => return Err(format!("no edge for {} -> {} ({:?})", e.from, e.to, e.xy)),
            }
        }
        Ok(())
    }

    /// A random polygon round a star of 5 to 15 points (sides bent at their middles: convex
    /// and reflex corners), with up to two polygonal holes.
    fn random_polygon(rnd: &mut dyn FnMut() -> f64) -> Option<Region> {
        let n = 5 + (10.0 * rnd()) as usize;
        let radii: Vec<f64> = (0..n).map(|_| 1.0 + 0.6 * rnd()).collect();
        let wobble: Vec<f64> = (0..n).map(|_| 0.4 * rnd() - 0.2).collect();
        let holes: Vec<([f64; 2], f64, usize, f64)> = (0..(3.0 * rnd()) as usize)
            .map(|_| {
                let centre = [0.8 * rnd() - 0.4, 0.8 * rnd() - 0.4];
                (
                    centre,
                    0.05 + 0.15 * rnd(),
                    3 + (6.0 * rnd()) as usize,
                    rnd(),
                )
            })
            .collect();
        polygon_star_with_polygon_holes(&radii, &wobble, &holes)
    }

    /// The differential test of the traced path: on 1,000 random polygons with reflex and
    /// convex corners and polygonal holes, its axis, wherever it stands, is the axis built
    /// from every pair the bounds keep (the same nodes, the same edges between them within
    /// twice the chord tolerance, on the same boundaries); and it stands wherever that one is
    /// certified but for a few.
    #[test]
    fn the_traced_axis_is_the_bounds_axis() {
        let make = |rnd: &mut dyn FnMut() -> f64, _| random_polygon(rnd);
        let same = |traced: &MedialAxis, bounds: &MedialAxis, region: &Region| {
            let near = 2.0 * MedialOptions::default().chord_tol * region.size();
            same_graph(traced, bounds, near)
        };
        stands_as_the_bounds(&mut rng(3901), PairSource::SeedEdges, make, same);
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
            use super::{sweep_polygon, LineSite};
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

    /// A closed polygon through `points`, as a region.
    fn region_of(points: &[[f64; 2]]) -> Region {
        Region::new(polygon(points), vec![]).unwrap()
    }

    /// The traced path stands on the benchmarks' stars of 100 and 400 lines (certified, its
    /// feet covering the boundary), with the seed's pairs' axis.
    #[test]
    fn the_traced_path_stands_on_the_stars() {
        for n in [100usize, 400] {
            let region = region_of(&star_polygon(n));
            let opts = MedialOptions::default();
            let (traced, stands) = axis_of(&region, &opts, PairSource::SeedEdges).unwrap();
            assert!(stands && traced.certified, "star {n}: {:?}", traced.reason);
            let seeded = axis_of(&region, &opts, PairSource::Seed).unwrap().0;
            same_graph(&traced, &seeded, 2.0 * opts.chord_tol * region.size()).unwrap();
        }
    }
}
