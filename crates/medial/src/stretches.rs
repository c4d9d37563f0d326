//! The stretches of each candidate branch that belong to the axis: inside the region, with
//! empty disks. Where a stretch ends inside its branch, the end is refined on the exact
//! branch to the point where a third boundary point reaches the disk: a tri-tangent disk.

use crate::candidates::{Candidate, Vertex};
use crate::corners::entered_across_corner;
use crate::curvature::{curvature_peak, sign_change};
use crate::parallel::in_order;
use crate::sites::{Disk, Sites, EMPTY_SLACK};
use curve::watch::Stage;
use curve::ParamCurve;
use numeric::rounding::ulps;

/// Halvings that bracket where a stretch ends: to 2^-32 of a polyline step, which tells the
/// site entering beyond it; the tri-tangent disk is then solved for on that site (halving on
/// to rounding would test disks within rounding of touching it, which bounds cannot decide).
const BRACKET_STEPS: usize = 32;

/// Halvings of the first, coarse bracket (to 2^-12 of a polyline step): where its tri-tangent
/// disk proves empty, the junction is found without the rest.
const COARSE_STEPS: usize = 12;

/// Doublings of the step back from the bracket to where the entering point is outside the
/// disk (from 2^-32 of a polyline step to all of it).
const BACK_STEPS: usize = BRACKET_STEPS + 1;

/// Units of rounding of the coordinates a distance less a radius carries (the disk tests
/// allow 16 per comparison).
const DISTANCE_ULPS: f64 = 16.0;

/// Secant steps that solve for the tri-tangent disk inside the bracket.
const SECANT_STEPS: usize = 60;

/// Halvings that look for a stretch on the axis hidden between two polyline vertices off
/// it (down to 2^-20 of the step).
const HIDDEN_DEPTH: usize = 20;

/// What the site entering a disk is taken to be: boundary and segment, and how deep it
/// reaches into the disk (0 where no site enters: the nearest site then).
type Intruder = ((usize, usize), f64);

/// Further halvings that put the end of an exterior stretch on the box it is clipped to.
const CLIP_STEPS: usize = 30;

/// The "site" beyond the box the exterior axis is clipped to.
const CLIPPED: (usize, usize) = (usize::MAX, usize::MAX);

/// The "site" of a point on the wrong side of its own foot (outside the region, for the
/// inner axis): no site enters its disk that a search between two such points could follow.
const OUTSIDE: (usize, usize) = (usize::MAX, usize::MAX - 1);

/// How much longer than the chord between two of its points a stretch of a candidate
/// branch may be, when the search for a hidden stretch bounds what lies between them.
const LENGTH_SLACK: f64 = 1.5;

/// Feet closer than this share of the radius are one point: where they meet the axis ends,
/// at a centre of curvature (bisector points whose feet close in on a smooth joint, where the
/// bisector function vanishes to high order, are no part of the axis either).
const FEET_APART: f64 = 1e-4;

/// Most distance (a share of the region's size) between the points tested along the
/// bisector of two corners: a stretch of it on the axis between two junctions (at the
/// circumcentre of three reflex corners, the bisectors of two pairs of them run on from the
/// third's) is found where it is longer than that.
const CORNER_LINE_STEP: f64 = 1e-2;

/// A foot within this share of the radius of a corner at its segment's end is closing in on
/// it: the axis ends at the segment's centre of curvature there (the feet of the leaves of
/// the benchmark chains' reflex corners are ~1e-4 of the radius apart at their last vertex).
const CLOSING_IN: f64 = 0.05;

/// A curvature below this (times the size) is a straight boundary: no centre of curvature
/// within 1e12 sizes for the axis to end at.
const STRAIGHT: f64 = 1e-12;

/// Widest window (share of the boundary's parameter length) searched for the curvature
/// extremum where the axis ends, and how many times the window doubles to reach it.
const EXTREMUM_WINDOW: f64 = 1e-2;
const WIDENINGS: usize = 64;

/// Newton steps of a foot-point solve.
const FOOT_STEPS: usize = 30;

/// The secant of a foot-point solve starts from the guessed foot and one this share of the
/// bracket beside it.
const START_STEP: f64 = 1e-3;

/// Where a stretch ends, bracketed on its branch: from `lo` (on the axis, at `last`) to `hi`
/// (off it, at `outside` when the branch has a point there).
struct Bracket {
    lo: f64,
    hi: f64,
    last: Vertex,
    outside: Option<Vertex>,
}

/// A stretch of one candidate on the axis.
#[derive(Debug, Clone)]
pub(crate) struct Stretch {
    /// The candidate it lies on.
    pub(crate) candidate: usize,
    pub(crate) vertices: Vec<Vertex>,
}

/// The stretches of every candidate, in the candidates' order (on all cores with the
/// `parallel` feature).
pub(crate) fn stretches(sites: &Sites<'_>, found: &[Candidate]) -> Vec<Stretch> {
    // (A cancelled watch trims no candidate more: the caller answers "cancelled".)
    let stage = curve::watch::stage("medial axis: candidates trimmed to the axis");
    let order: Vec<usize> = (0..found.len()).collect();
    let per_candidate = in_order(&order, |&k| {
        if stage.go_on(1) {
            stretches_of(sites, k, &found[k], &stage)
        } else {
            Vec::new()
        }
    });
    per_candidate.into_iter().flatten().collect()
}

/// The stretches of candidate `k`.
fn stretches_of(sites: &Sites<'_>, k: usize, c: &Candidate, stage: &Stage) -> Vec<Stretch> {
    let mut out = Vec::new();
    let branch = Branch { sites, c, stage };
    let samples = branch.samples();
    let n = samples.len();
    let mut i = 0;
    while i < n {
        if samples[i].on_axis.is_none() {
            i += 1;
            continue;
        }
        let start = i;
        while i < n && samples[i].on_axis.is_some() {
            i += 1;
        }
        let mut vertices: Vec<Vertex> =
            samples[start..i].iter().filter_map(|s| s.on_axis).collect();
        if start > 0 {
            let before = &samples[start - 1];
            // (Not the vertex itself again: the junction may lie on it.)
            if let Some(v) = branch.junction(vertices[0], before.tr, before.xy) {
                if v != vertices[0] {
                    vertices.insert(0, v);
                }
            }
        }
        if i < n {
            let after = &samples[i];
            let last = vertices[vertices.len() - 1];
            if let Some(v) = branch.junction(last, after.tr, after.xy) {
                if v != last {
                    vertices.push(v);
                }
            }
        }
        if vertices.len() >= 2 || n == 1 {
            out.push(Stretch {
                candidate: k,
                vertices,
            });
        }
    }
    out
}

/// A point of a candidate branch: feet, point, and the vertex when it is on the axis.
struct Sample {
    tr: [f64; 2],
    xy: [f64; 2],
    on_axis: Option<Vertex>,
}

/// One candidate branch with the region: exact points on it, and the test of the axis.
struct Branch<'s, 'a> {
    sites: &'s Sites<'a>,
    c: &'s Candidate,
    /// The stage's watch, looked at for every point tested and every step of the searches:
    /// one candidate may have thousands of points, each a disk test.
    stage: &'s Stage,
}

impl Branch<'_, '_> {
    /// The candidate's vertices, tested; between two vertices off the axis whose disks are
    /// entered by different boundary sites, a stretch on the axis shorter than the polyline's
    /// step may lie (two junctions close together): it is searched for by halving.
    fn samples(&self) -> Vec<Sample> {
        let c = self.c;
        let mut out: Vec<Sample> = Vec::with_capacity(c.tr.len());
        let mut last_intruder: Option<Intruder> = None;
        for (tr, xy) in self.points() {
            // (Cancelled: what is tested so far is no answer, and the caller says so.)
            if self.stage.cancelled() {
                break;
            }
            let (on_axis, intruder) = match self.vertex(tr, xy) {
                Some(v) => match self.classify(&v) {
                    Ok(()) => (Some(v), None),
                    Err(site) => (None, Some(site)),
                },
                None => (None, Some((self.nearest_site(xy), 0.0))),
            };
            if let (Some(v), Some(prev)) = (on_axis, out.last().and_then(|p| p.on_axis)) {
                if let Some(m) = self.past_evolute(&prev, &v) {
                    out.push(Sample {
                        tr: m.tr,
                        xy: m.xy,
                        on_axis: None,
                    });
                }
            }
            if let (Some(a), Some(b), Some(prev)) = (last_intruder, intruder, out.last()) {
                if a.0 != b.0 {
                    let (ptr, pxy) = (prev.tr, prev.xy);
                    if let Some(v) = self.between((ptr, pxy, a), (tr, xy, b), HIDDEN_DEPTH) {
                        out.push(Sample {
                            tr: v.tr,
                            xy: v.xy,
                            on_axis: Some(v),
                        });
                    }
                }
            }
            last_intruder = intruder;
            out.push(Sample { tr, xy, on_axis });
        }
        out
    }

    /// The candidate's points to test: its vertices, but for the bisector of two corners
    /// (a line given by its two ends) points along it within the box the axis lies in, at
    /// most [`CORNER_LINE_STEP`] of the size apart: a stretch between two points whose disks
    /// one site enters is not searched for, and the line's ends lie far apart.
    fn points(&self) -> Vec<([f64; 2], [f64; 2])> {
        let c = self.c;
        let line = c.corner == [true, true] && c.xy.len() == 2;
        let clipped = line
            .then(|| clip_to_box(c.xy[0], c.xy[1], crate::candidates::root_box(self.sites)))
            .flatten();
        let Some((a, b)) = clipped else {
            return c.tr.iter().copied().zip(c.xy.iter().copied()).collect();
        };
        let length = (b[0] - a[0]).hypot(b[1] - a[1]);
        let steps = ((length / (CORNER_LINE_STEP * self.sites.size)).ceil() as usize).max(1);
        (0..=steps)
            .map(|k| {
                let s = k as f64 / steps as f64;
                (
                    c.tr[0],
                    [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])],
                )
            })
            .collect()
    }

    /// Between two vertices on the axis, a point of the branch off it where a foot passes a
    /// curvature maximum whose centre lies nearer the foot than the branch: there the
    /// boundary beside the foot enters the disk (the branch crosses the evolute and back,
    /// between two junctions with one disk), a window too narrow for the polyline's steps.
    /// The vertex with its foot at the maximum, if its disk is entered.
    fn past_evolute(&self, a: &Vertex, b: &Vertex) -> Option<Vertex> {
        let c = self.c;
        (0..2).filter(|&s| !c.corner[s]).find_map(|s| {
            let boundary = self.sites.boundaries[c.boundary[s]];
            let rate = |u: f64| boundary.jet_on(c.segment[s], u, 3).curvature_rate();
            let (lo, hi) = (a.tr[s].min(b.tr[s]), a.tr[s].max(b.tr[s]));
            // (Not across a closed boundary's seam, where the foot runs on from the end of
            // its parameter to the start: between the two lies the rest of the boundary.)
            let n = boundary.domain().1;
            if boundary.is_closed() && hi - lo > 0.5 * n {
                return None;
            }
            if !(rate(lo).signum() != rate(hi).signum() && hi > lo) {
                return None;
            }
            let u = sign_change(&rate, lo, hi);
            let share = (u - a.tr[s]) / (b.tr[s] - a.tr[s]);
            let lerp = |x: [f64; 2], y: [f64; 2]| {
                [x[0] + share * (y[0] - x[0]), x[1] + share * (y[1] - x[1])]
            };
            let mut guess = lerp(a.tr, b.tr);
            guess[s] = u;
            let v = self.snap_keeping(s, guess, lerp(a.xy, b.xy), a.tr, b.tr)?;
            self.classify(&v).is_err().then_some(v)
        })
    }

    /// A vertex on the axis strictly between two points of the branch off it (feet, point
    /// and the site entering their disks), by halving where the entering sites differ.
    fn between(
        &self,
        a: ([f64; 2], [f64; 2], Intruder),
        b: ([f64; 2], [f64; 2], Intruder),
        depth: usize,
    ) -> Option<Vertex> {
        if depth == 0 || a.2 .0 == b.2 .0 || self.stage.cancelled() {
            return None;
        }
        // How far the boundary is inside the disk less its radius changes at most twice as
        // fast as the point moves: where the two ends are too deep for their distance, no
        // disk between them is empty.
        let apart = (b.1[0] - a.1[0]).hypot(b.1[1] - a.1[1]);
        if 2.0 * LENGTH_SLACK * apart < a.2 .1 + b.2 .1 {
            return None;
        }
        let tr = [0.5 * (a.0[0] + b.0[0]), 0.5 * (a.0[1] + b.0[1])];
        let xy = [0.5 * (a.1[0] + b.1[0]), 0.5 * (a.1[1] + b.1[1])];
        let v = self.snap(tr, xy, a.0, b.0)?;
        let site = match self.classify(&v) {
            Ok(()) => return Some(v),
            Err(site) => site,
        };
        let m = (v.tr, v.xy, site);
        self.between(a, m, depth - 1)
            .or_else(|| self.between(m, b, depth - 1))
    }

    /// The boundary site nearest `x`: boundary and segment.
    fn nearest_site(&self, x: [f64; 2]) -> (usize, usize) {
        let (_, k, u) = self.sites.nearest(x, 0.0);
        self.site_of(k, u)
    }

    /// The site holding profile parameter `u` of boundary `k`: boundary and piece (a
    /// segment, or a knot span of a spline segment: on a boundary of one long spline, the
    /// sites entering two disks differ where their pieces do).
    fn site_of(&self, k: usize, u: f64) -> (usize, usize) {
        (k, self.sites.piece_of(k, u))
    }

    /// Whether a vertex lies on the axis, or else the site that keeps it off: one entering
    /// its disk, with how deep; for an empty disk with its feet together the nearest, at
    /// depth 0; outside the region (or the clip box) a mark of its own.
    fn classify(&self, v: &Vertex) -> Result<(), Intruder> {
        if !self.sites.in_clip(v.xy) {
            return Err((CLIPPED, 0.0));
        }
        if !self.inside(v) {
            return Err((OUTSIDE, 0.0));
        }
        match self.across_corner(v, self.sites.disk(v.xy, v.radius)) {
            Disk::Entered(k, u, depth) => Err((self.site_of(k, u), depth)),
            Disk::Empty if self.feet_part(v) => Ok(()),
            Disk::Empty => Err((self.nearest_site(v.xy), 0.0)),
        }
    }

    /// The end of the axis where the feet of `v` close in: the centre of curvature at the
    /// curvature's peak between them (the foot of larger curvature where no peak is found);
    /// `None` where the boundary is straight or the feet meet at a corner.
    fn end_at_curvature_centre(&self, v: &Vertex) -> Option<Vertex> {
        let c = self.c;
        let jet =
            |s: usize, u: f64| self.sites.boundaries[c.boundary[s]].jet_on(c.segment[s], u, 3);
        // (Along the boundary, across joints: the extremum may lie on either segment; on a
        // closed boundary across the seam too, the parameter taken modulo its length.)
        let boundary = self.sites.boundaries[c.boundary[0]];
        let n = boundary.domain().1;
        let kappa = |s: usize, u: f64| jet(s, u).curvature();
        // The peak between the feet, or just beside them: near the end of the axis the
        // feet found may both lie on one side of it (the feet of the trivial solution, both
        // at one point, are near), so the window widens until it holds the peak.
        let mut across_corner = false;
        let peak = (c.boundary[0] == c.boundary[1] && !c.corner.contains(&true))
            .then(|| {
                let (mut a, mut b) = (v.tr[0].min(v.tr[1]), v.tr[0].max(v.tr[1]));
                if boundary.is_closed() && b - a > 0.5 * n {
                    (a, b) = (b, a + n); // the short way round, across the seam
                }
                let widest = EXTREMUM_WINDOW * n;
                let mut w = (b - a).max(ulps(n));
                for _ in 0..WIDENINGS {
                    if let Some(peak) = curvature_peak(boundary, a, b) {
                        // A peak across a corner is no end: the feet meet at the corner,
                        // and the axis ends where the stretch does.
                        across_corner = boundary.corners().any(|j| {
                            (-1..=1).any(|k| {
                                let u = j.u + k as f64 * n;
                                u > a && u < b
                            })
                        });
                        return Some(peak);
                    }
                    if w > widest {
                        break;
                    }
                    (a, b) = (a - w, b + w);
                    if !boundary.is_closed() {
                        (a, b) = (a.max(0.0), b.min(n));
                    }
                    w *= 2.0;
                }
                None
            })
            .flatten();
        if across_corner {
            return None;
        }
        let (s, u, j) = if let Some((u, j)) = peak {
            (0, u, j)
        } else {
            let s = if c.corner[0] {
                1
            } else if c.corner[1] || kappa(0, v.tr[0]).abs() >= kappa(1, v.tr[1]).abs() {
                0
            } else {
                1
            };
            let u = self.corner_beside(s, v).unwrap_or(v.tr[s]);
            (s, u, jet(s, u))
        };
        let k = j.curvature();
        if k.is_nan() || k.abs() * self.sites.size <= STRAIGHT {
            return None;
        }
        let centre = j.p + j.d1.perp().unit() * (1.0 / k);
        let mut tr = v.tr;
        tr[0] = if s == 0 { u } else { tr[0] };
        tr[1] = if s == 1 { u } else { tr[1] };
        if c.boundary[0] == c.boundary[1] && !c.corner.contains(&true) {
            tr = [u, u];
        }
        Some(Vertex {
            tr,
            xy: centre.arr(),
            radius: 1.0 / k.abs(),
        })
    }

    /// The centre of curvature where the feet of `last`, the last vertex of a stretch on the
    /// axis before they meet, close in ([`Self::end_at_curvature_centre`]), if `last` is
    /// near it: within [`CLOSING_IN`] of its radius. (Where a branch's trace jumps from a
    /// corner, its feet's meeting, to far off, the feet beyond meet too, but the centre of
    /// curvature between them is no end of that stretch: pinterest-logo-fill's corner leaf
    /// ran to its arc's centre, 104 away across the drawing.)
    fn centre_closed_in_on(&self, last: &Vertex) -> Option<Vertex> {
        let end = self.end_at_curvature_centre(last)?;
        let apart = (end.xy[0] - last.xy[0]).hypot(end.xy[1] - last.xy[1]);
        (apart <= CLOSING_IN * end.radius).then_some(end)
    }

    /// Where the foot of site `s` on a segment closes in on the other site, a corner at one
    /// of that segment's ends: the corner's parameter (the bisector of a point and a curve
    /// ends, as the foot reaches the point, at the centre of curvature there).
    fn corner_beside(&self, s: usize, v: &Vertex) -> Option<f64> {
        let c = self.c;
        let o = 1 - s;
        if c.corner[s] || !c.corner[o] || c.boundary[0] != c.boundary[1] {
            return None;
        }
        let boundary = self.sites.boundaries[c.boundary[s]];
        let n = boundary.domain().1;
        let (start, corner) = (c.segment[s] as f64, v.tr[o]);
        // (The foot must be closing in on the corner: at the branch's other end, where its
        // disk shrinks to the corner's point, the axis does not end at the centre.)
        let (p, q) = (
            self.sites.foot(c.boundary[s], v.tr[s]),
            self.sites.foot(c.boundary[o], corner),
        );
        if (p[0] - q[0]).hypot(p[1] - q[1]) > CLOSING_IN * v.radius {
            return None;
        }
        if corner == start {
            Some(start)
        } else if corner == start + 1.0 || boundary.is_closed() && corner == 0.0 && start + 1.0 == n
        {
            Some(start + 1.0)
        } else {
            None
        }
    }

    /// How far apart the two feet of a vertex are.
    fn feet_apart(&self, v: &Vertex) -> f64 {
        let (p, q) = (
            self.sites.foot(self.c.boundary[0], v.tr[0]),
            self.sites.foot(self.c.boundary[1], v.tr[1]),
        );
        (p[0] - q[0]).hypot(p[1] - q[1])
    }

    /// The vertex of feet `tr` at `xy`, with its radius.
    fn vertex(&self, tr: [f64; 2], xy: [f64; 2]) -> Option<Vertex> {
        let f = self.sites.foot(self.c.boundary[0], tr[0]);
        let radius = (xy[0] - f[0]).hypot(xy[1] - f[1]);
        radius.is_finite().then_some(Vertex { tr, xy, radius })
    }

    /// Whether a vertex lies on the axis: inside the region, its disk empty, its two feet
    /// apart (else its point has one nearest point: the axis ends where the feet meet).
    fn on_axis(&self, v: &Vertex) -> bool {
        self.sites.in_clip(v.xy) && self.feet_part(v) && self.disk_empty(v)
    }

    /// (Only in the search for where a stretch ends: see [`Sites::probe`].)
    fn disk_empty(&self, v: &Vertex) -> bool {
        self.inside(v) && self.probe(v) == Disk::Empty
    }

    /// What the disk of `v` holds ([`Sites::probe`]), the side across a convex corner
    /// beside its foot included ([`Self::across_corner`]).
    fn probe(&self, v: &Vertex) -> Disk {
        self.across_corner(v, self.sites.probe(v.xy, v.radius))
    }

    /// `disk`, what the disk tests found in the disk of `v`, or, where they found it empty,
    /// the side across a convex corner beside a foot that enters it by less than their slack
    /// ([`crate::corners`]).
    fn across_corner(&self, v: &Vertex, disk: Disk) -> Disk {
        match disk {
            Disk::Empty => entered_across_corner(self.sites, self.c, v)
                .map_or(Disk::Empty, |(k, u, depth)| Disk::Entered(k, u, depth)),
            entered => entered,
        }
    }

    fn feet_part(&self, v: &Vertex) -> bool {
        self.at_corner(v)
            || self.feet_apart(v) > FEET_APART * v.radius
            || self.corner_between_feet(v)
    }

    /// Whether a corner of the boundary lies between the vertex's two feet, which are not one
    /// point: then they are two nearest points however close (the axis from a corner that
    /// turns by θ has its feet θ times the radius apart, below [`FEET_APART`] for a nearly
    /// flat corner, and does not end there).
    fn corner_between_feet(&self, v: &Vertex) -> bool {
        let c = self.c;
        if c.boundary[0] != c.boundary[1] || self.feet_apart(v) <= EMPTY_SLACK * self.sites.size {
            return false;
        }
        let boundary = self.sites.boundaries[c.boundary[0]];
        let period = boundary.domain().1;
        let (a, b) = (v.tr[0].min(v.tr[1]), v.tr[0].max(v.tr[1]));
        // (The short way round a closed boundary: feet so close are close along it.)
        let wraps = boundary.is_closed() && b - a > 0.5 * period;
        boundary.corners().any(|j| {
            if wraps {
                j.u > b || j.u < a
            } else {
                j.u > a && j.u < b
            }
        })
    }

    /// Whether a vertex is a corner of its boundary (an end of the axis there): of radius
    /// within the slack, at a joint that is no smooth one (where two segments meet smoothly,
    /// their bisector reaches the joint at radius 0 too, but the axis does not).
    fn at_corner(&self, v: &Vertex) -> bool {
        let slack = EMPTY_SLACK * self.sites.size;
        v.radius <= slack
            && self.c.boundary.iter().any(|&k| {
                let b = self.sites.boundaries[k];
                b.corners().any(|j| {
                    let p = b.jet(j.u).p;
                    (p.x - v.xy[0]).hypot(p.y - v.xy[1]) <= slack
                })
            })
    }

    fn inside(&self, v: &Vertex) -> bool {
        // A vertex on the boundary (a corner's end of the axis) is inside.
        if self.at_corner(v) {
            return true;
        }
        // The side of a segment's foot decides; two corners: their cones.
        let s = if self.c.corner[0] { 1 } else { 0 };
        let c = self.c;
        self.sites
            .inside_of(c.boundary[s], c.segment[s], v.tr[s], c.corner[s], v.xy)
    }

    /// The end of a stretch between its last vertex `from` (on the axis) and the next
    /// vertex's feet `beyond` (off it): bracketed by halving on the exact branch, then solved
    /// for the disk that also touches the boundary point that enters beyond it. A coarse
    /// bracket is tried first; its solution stands if its disk proves empty.
    fn junction(&self, from: Vertex, beyond: [f64; 2], beyond_xy: [f64; 2]) -> Option<Vertex> {
        let feet_meet_beyond = self
            .vertex(beyond, beyond_xy)
            .is_some_and(|v| !self.feet_part(&v));
        if feet_meet_beyond {
            // The branch runs into its feet's meeting: where the disk at the centre of
            // curvature between them is empty, the axis ends there. (The bracket's disks
            // osculate the boundary near that centre: the longest of all to prove empty.)
            if let Some(end) = self.end_at_curvature_centre(&from) {
                if self.sites.in_clip(end.xy) && self.disk_empty(&end) {
                    return Some(end);
                }
            }
        }
        let lerp =
            |a: [f64; 2], b: [f64; 2], s: f64| [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
        let at = |s: f64| -> Option<Vertex> {
            let guess = lerp(from.tr, beyond, s);
            self.snap(guess, lerp(from.xy, beyond_xy, s), from.tr, beyond)
        };
        let mut b = Bracket {
            lo: 0.0,
            hi: 1.0,
            last: from,
            outside: None,
        };
        self.halve(&mut b, COARSE_STEPS, &at);
        if let Some(out) = b.outside {
            let disk = self.probe(&out);
            let entered = self.sites.in_clip(out.xy) && self.feet_part(&out);
            if entered && !(self.inside(&out) && disk == Disk::Empty) {
                if let Some(v) = self.tri_tangent(from, &b, out, disk, &at) {
                    if v.tr != b.last.tr && self.on_axis(&v) {
                        return Some(v);
                    }
                }
            }
        }
        self.halve(&mut b, BRACKET_STEPS - COARSE_STEPS, &at);
        let Bracket {
            mut lo,
            mut hi,
            mut last,
            outside,
        } = b;
        if outside.is_some_and(|o| !self.sites.in_clip(o.xy)) {
            // The exterior axis leaves the box it is clipped to: it ends at the box, found by
            // halving on to rounding (the box test is exact; a step may be long, far out).
            for _ in 0..CLIP_STEPS {
                let m = 0.5 * (lo + hi);
                match at(m) {
                    Some(v) if self.sites.in_clip(v.xy) => {
                        lo = m;
                        last = v;
                    }
                    _ => hi = m,
                }
            }
            return (lo > 0.0).then_some(last);
        }
        let Some(out) = outside else {
            // No exact point beyond: where the branch runs into its feet's meeting (a
            // self-bisector's end on its diagonal), the axis ends at the centre of curvature.
            if feet_meet_beyond && lo > 0.0 {
                return Some(self.centre_closed_in_on(&last).unwrap_or(last));
            }
            return (lo > 0.0).then_some(last);
        };
        let disk = self.probe(&out);
        if !self.feet_part(&out) || (self.inside(&out) && disk == Disk::Empty) {
            // The feet met: the axis ends at the centre of curvature between them. (Beside
            // that centre the boundary may reach into the disk by more than the slack: the
            // circle osculates it there, so the feet, not the disk, decide.)
            return self
                .centre_closed_in_on(&last)
                .or_else(|| (lo > 0.0).then_some(last));
        }
        let b = Bracket {
            lo,
            hi,
            last,
            outside,
        };
        self.tri_tangent(from, &b, out, disk, &at)
            .or_else(|| (lo > 0.0).then_some(last))
    }

    /// Halves the bracket `steps` times: its low end stays on the axis, its high end off it.
    fn halve(&self, b: &mut Bracket, steps: usize, at: &dyn Fn(f64) -> Option<Vertex>) {
        for _ in 0..steps {
            // (Each step a disk test: a search of dozens may take tens of milliseconds beside
            // a boundary of tiny corners.)
            if self.stage.cancelled() {
                return;
            }
            let m = 0.5 * (b.lo + b.hi);
            match at(m) {
                Some(v) if self.on_axis(&v) => {
                    b.lo = m;
                    b.last = v;
                }
                other => {
                    b.hi = m;
                    if other.is_some() {
                        b.outside = other;
                    }
                }
            }
        }
    }

    /// The tri-tangent disk in bracket `b` (from the stretch's last vertex `from`; `out` its
    /// high end, entered, and `disk` what its disk holds): where the distance to the
    /// entering point equals the radius.
    fn tri_tangent(
        &self,
        from: Vertex,
        b: &Bracket,
        out: Vertex,
        disk: Disk,
        at: &dyn Fn(f64) -> Option<Vertex>,
    ) -> Option<Vertex> {
        let (lo, hi, last) = (b.lo, b.hi, b.last);
        // (The point the disk test proved inside, not the nearest point found: beside a
        // foot the search may return that foot, within rounding as near.)
        let (k, u) = match disk {
            Disk::Entered(k, u, _) => (k, u),
            Disk::Empty => {
                let (_, k, u) = self.sites.nearest(out.xy, 0.0);
                (k, u)
            }
        };
        let entering = self.sites.boundaries[k];
        // A corner of a foot's own segment entering the disk is a site of its own: the
        // distance to the boundary near it is that foot's, the radius itself, all along.
        let corner = self.own_corner_inside(k, &out);
        let third = |v: &Vertex| match corner {
            Some(p) => (v.xy[0] - p[0]).hypot(v.xy[1] - p[1]) - v.radius,
            None => entering.nearest_near(v.xy, u).distance - v.radius,
        };
        // The bracket's passing end holds the disk empty only to the slack: the root may lie
        // a little before it. Step back from it, doubling, until the third point is outside
        // the disk (not straight back to the stretch's last vertex: where the entering point
        // is on a foot's own segment, a search from there may find that foot instead).
        // (Outside within the rounding of the distances, which far from the origin is well
        // above 1e-16 of the size: a disk that touches the third point exactly, at the
        // junction, may seem entered by that much.)
        let outside = |v: &Vertex, f: f64| {
            f >= -ulps(DISTANCE_ULPS) * v.xy[0].abs().max(v.xy[1].abs()).max(v.radius)
        };
        let (mut a, mut fa, mut best) = (lo, third(&last), last);
        let (mut b, mut fb) = (hi, third(&out));
        let mut back = hi - lo;
        for _ in 0..BACK_STEPS {
            if outside(&best, fa) || a <= 0.0 {
                break;
            }
            (b, fb) = (a, fa);
            back *= 2.0;
            a = (lo - back).max(0.0);
            best = if a > 0.0 {
                match at(a) {
                    Some(v) => v,
                    None => break,
                }
            } else {
                from
            };
            fa = third(&best);
        }
        if !(outside(&best, fa) && fb < 0.0) {
            return None;
        }
        for _ in 0..SECANT_STEPS {
            // Regula falsi with the Illinois rule: the bracket always holds the root.
            let s = (a * fb - b * fa) / (fb - fa);
            if !(s > a && s < b) {
                break;
            }
            let Some(v) = at(s) else { break };
            let f = third(&v);
            if f >= 0.0 {
                (a, fa) = (s, f);
                best = v;
                fb *= 0.5;
            } else {
                (b, fb) = (s, f);
                fa *= 0.5;
            }
            if b - a <= ulps(4.0) {
                break;
            }
        }
        Some(best)
    }

    /// A corner at an end of the segment of one of the branch's (non-corner) feet on
    /// boundary `k`, pointing into the region and lying inside the disk of `out`: its point.
    fn own_corner_inside(&self, k: usize, out: &Vertex) -> Option<[f64; 2]> {
        let c = self.c;
        let boundary = self.sites.boundaries[k];
        let n = boundary.domain().1;
        (0..2)
            .filter(|&s| !c.corner[s] && c.boundary[s] == k)
            .flat_map(|s| [c.segment[s] as f64, c.segment[s] as f64 + 1.0])
            .map(|u| if boundary.is_closed() { u % n } else { u })
            // (A corner pointing into the region, not the branch's own corner site: a site of
            // its own for the axis.)
            .filter(|&u| {
                let own = (0..2).any(|s| c.corner[s] && c.boundary[s] == k && out.tr[s] == u);
                !own && boundary.corners().any(|j| j.u == u)
                    && self.sites.inside_of(k, 0, u, true, out.xy)
            })
            .map(|u| {
                let p = boundary.jet(u).p;
                [p.x, p.y]
            })
            .find(|p| (p[0] - out.xy[0]).hypot(p[1] - out.xy[1]) < out.radius)
    }

    /// The exact bisector vertex near the feet `guess` and point `near` (between the
    /// vertices with feet `p` and `q`): the foot on a segment that moves most between them is
    /// kept, the other solved for; two corners' bisector is the straight line through `near`.
    fn snap(&self, guess: [f64; 2], near: [f64; 2], p: [f64; 2], q: [f64; 2]) -> Option<Vertex> {
        let keep = match self.c.corner {
            [true, true] => return self.vertex(guess, near),
            [true, false] => 1,
            [false, true] => 0,
            [false, false] => usize::from((q[0] - p[0]).abs() < (q[1] - p[1]).abs()),
        };
        self.snap_keeping(keep, guess, near, p, q)
    }

    /// [`Self::snap`] with foot `keep` (not a corner's) kept at `guess[keep]`.
    fn snap_keeping(
        &self,
        keep: usize,
        guess: [f64; 2],
        near: [f64; 2],
        p: [f64; 2],
        q: [f64; 2],
    ) -> Option<Vertex> {
        let c = self.c;
        let jet =
            |s: usize, u: f64| self.sites.boundaries[c.boundary[s]].jet_on(c.segment[s], u, 2);
        if c.corner == [true, true] {
            return self.vertex(guess, near);
        }
        let other = 1 - keep;
        let jk = jet(keep, guess[keep]);
        let n = jk.d1.perp().unit();
        // On the normal at the kept foot, as far from it as from `o`.
        let point_for = |o: curve::V2| {
            let d = o - jk.p;
            jk.p + n * (d.dot(d) / (2.0 * n.dot(d)))
        };
        if c.corner[other] {
            return self.vertex(guess, point_for(jet(other, guess[other]).p).arr());
        }
        // The other foot: where the bisector point is on the normal there too (secant
        // steps from the two vertices' feet).
        let (lo, hi) = (p[other].min(q[other]), p[other].max(q[other]));
        let g = |u: f64| {
            let jo = jet(other, u);
            let x = point_for(jo.p);
            ((x - jo.p).dot(jo.d1) / jo.d1.norm(), x)
        };
        // Two feet on one boundary have the trivial solution too, both at one point (where
        // the point is the centre of curvature): beside the feet's meeting the secant falls
        // into it. Divided by the feet's gap, the function keeps only the other solutions.
        let one_boundary = c.boundary[0] == c.boundary[1];
        let reduced = |u: f64| {
            let v = g(u).0;
            if one_boundary {
                v / (u - guess[keep])
            } else {
                v
            }
        };
        // Secant steps from two feet; the foot they converge to, if it is one.
        let secant = |mut u0: f64, mut u1: f64| -> Option<Vertex> {
            let (mut g0, mut g1) = (reduced(u0), reduced(u1));
            // The iterate of least gap is the foot: at the gap's rounding floor (~1e-16 of
            // the coordinates, far from the origin well above 1e-16 of the size) the steps
            // divide noise by noise and may throw the next iterate anywhere.
            let mut best = (f64::INFINITY, u1);
            for (u, gu) in [(u0, g0), (u1, g1)] {
                if gu.abs() < best.0 {
                    best = (gu.abs(), u);
                }
            }
            for _ in 0..FOOT_STEPS {
                if g1 == 0.0 || g1 == g0 || (u1 - u0).abs() <= ulps(1.0) * u1.abs().max(1.0) {
                    break;
                }
                let next = u1 - g1 * (u1 - u0) / (g1 - g0);
                if !next.is_finite() {
                    break;
                }
                (u0, g0) = (u1, g1);
                u1 = next;
                g1 = reduced(u1);
                if !g1.is_finite() {
                    break;
                }
                if g1.abs() < best.0 {
                    best = (g1.abs(), u1);
                }
            }
            self.foot_solved(keep, guess, p, q, (lo, hi), best.1, &g)
        };
        // From the two vertices' feet; failing that, from the guess and a foot a little
        // beside it (beside a corner on the kept foot's own line the equidistant point of
        // the corner is at infinity, and a secant from there strays).
        secant(lo, hi).or_else(|| {
            let u = guess[other];
            secant(u, u + START_STEP * (hi - lo).max(ulps(1.0)))
        })
    }

    /// The vertex with foot `keep` at `guess[keep]` and the other at `u`, where the secant
    /// of [`Self::snap_keeping`] (bracketed by the feet `lo`, `hi` of the vertices `p`, `q`;
    /// `g` the equidistance's gap and point) left it: if that is a foot.
    #[allow(clippy::too_many_arguments)]
    fn foot_solved(
        &self,
        keep: usize,
        guess: [f64; 2],
        p: [f64; 2],
        q: [f64; 2],
        (lo, hi): (f64, f64),
        u: f64,
        g: &dyn Fn(f64) -> (f64, curve::V2),
    ) -> Option<Vertex> {
        let (c, other) = (self.c, 1 - keep);
        // The secant may leave the bracket (where the branch turns between its vertices,
        // the other foot goes past both of theirs and back); by no more than the kept foot
        // moves between them.
        let span = (hi - lo).max((q[keep] - p[keep]).abs()).max(ulps(1.0));
        if !(u >= lo - span && u <= hi + span) {
            return None;
        }
        // Two feet on one segment keep their order: beside the feet's meeting the secant
        // may find the trivial solution, both feet at one point, or pass it.
        if c.boundary[0] == c.boundary[1] && c.segment[0] == c.segment[1] {
            let before = p[other] - p[keep];
            if (u - guess[keep]) * before <= 0.0 {
                return None;
            }
        }
        // The secant converged to a foot: the point is as far from it as from the kept one
        // (else, beside a corner where the feet close in, it stopped short: no vertex).
        let (gap, x) = g(u);
        let mut tr = guess;
        tr[other] = u;
        let v = self.vertex(tr, x.arr())?;
        (gap.abs() <= EMPTY_SLACK * self.sites.size.max(v.radius)).then_some(v)
    }
}

/// The part of the segment `a`–`b` inside the box `[lo x, lo y, hi x, hi y]` (Liang and
/// Barsky), `None` where it misses the box.
fn clip_to_box(a: [f64; 2], b: [f64; 2], bx: [f64; 4]) -> Option<([f64; 2], [f64; 2])> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d[0], a[0] - bx[0]),
        (d[0], bx[2] - a[0]),
        (-d[1], a[1] - bx[1]),
        (d[1], bx[3] - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    let at = |t: f64| [a[0] + t * d[0], a[1] + t * d[1]];
    (t0 <= t1).then(|| (at(t0), at(t1)))
}

#[cfg(test)]
mod tests {
    use super::clip_to_box;

    #[test]
    fn a_segment_is_clipped_to_the_box() {
        let bx = [0.0, 0.0, 2.0, 1.0];
        // Across the box, inside it, and beside it.
        assert_eq!(
            clip_to_box([-1.0, 0.5], [3.0, 0.5], bx),
            Some(([0.0, 0.5], [2.0, 0.5]))
        );
        assert_eq!(
            clip_to_box([0.5, 0.5], [1.0, 0.75], bx),
            Some(([0.5, 0.5], [1.0, 0.75]))
        );
        assert_eq!(clip_to_box([-1.0, 2.0], [3.0, 2.0], bx), None);
        assert_eq!(clip_to_box([-1.0, -1.0], [-0.5, 3.0], bx), None);
        // A diagonal through a corner of the box.
        let (a, b) = clip_to_box([-1.0, -1.0], [3.0, 3.0], bx).unwrap();
        assert_eq!((a, b), ([0.0, 0.0], [1.0, 1.0]));
    }
}
