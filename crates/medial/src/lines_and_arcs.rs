//! A region's boundaries as lines and circular arcs in closed form, and what the closed-form
//! paths do on them: solve a node from its equations by Newton's method (and prove a
//! junction's place), and trace an edge between two solved nodes. The seed's diagram
//! ([`crate::traced_axis`]) and the trimmed bisectors of every pair of sites
//! ([`crate::pairwise_axis`]) give the topology; both hand their nodes and edges here.
//!
//! The bisector of two lines or two points is straight, any other a conic, whose points come
//! in closed form from the feet on one of its sites ([`SiteShape::radius_on_ray`]). Every disk
//! of an edge is tested for emptiness and every foot for lying on its segment, as on the
//! other paths.

mod edges;
mod empty_disks;
mod nodes;

use crate::candidates::Candidate;
use crate::sites::Sites;
use crate::stretches::Stretch;
use crate::true_sites::{ArcSite, LineSite, SiteShape, TrueSite};
use curve::{JointKind, SegmentKind, V2};
use empty_disks::on_its_circle;
use std::collections::HashSet;

/// Ends of edges within this share of the size are one node. The ends of the edges at one
/// node are solved to a few ulps (from one vertex of the seed's diagram, one point to the
/// bit), so only nodes that snapping or nearly cocircular sites put this close count as one:
/// the seed's grid spacing. (The other paths find each junction once per branch, and merge
/// within 1e-6.)
pub(crate) const SAME_SEED_NODE: f64 = 1e-9;

/// Up to this many segments a disk is tested for emptiness on every segment in closed form:
/// a test of each costs less than the walk of the boundaries' box tree that finds the few
/// near it (about as much at 64).
const CLOSED_FORM_DISK_SEGMENTS: usize = 64;

/// A foot may stray this share of the size beyond its segment's ends (rounding).
const FOOT_SLACK: f64 = 1e-9;

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
enum ClosedFormSegment {
    Line(LineSite),
    Arc { arc: ArcSite, start: V2, end: V2 },
}

impl ClosedFormSegment {
    /// Whether the foot of `x` on the piece's line or circle falls on the piece (else the
    /// piece's nearest point to `x` is one of its ends).
    fn falls_on(&self, x: V2) -> bool {
        match self {
            ClosedFormSegment::Line(l) => (0.0..=l.length).contains(&l.along.dot(x - l.start)),
            ClosedFormSegment::Arc { arc, .. } => arc.spans(x - arc.centre),
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

/// The boundaries of a region whose segments are all lines and circular arcs, each in
/// closed form.
pub(crate) struct LinesAndArcs<'s, 'a> {
    pub(crate) sites: &'s Sites<'a>,
    pieces: Vec<Vec<ClosedFormSegment>>,
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
                            SegmentKind::Line => ClosedFormSegment::Line(LineSite::new(
                                s.start(),
                                s.end(),
                                inside_left,
                            )),
                            SegmentKind::Arc => ClosedFormSegment::Arc {
                                arc: ArcSite::new(b, i, inside_left)?,
                                start: s.start(),
                                end: s.end(),
                            },
                            _ => return None,
                        })
                    })
                    .collect::<Option<Vec<ClosedFormSegment>>>()
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

    fn piece(&self, s: TrueSite) -> &ClosedFormSegment {
        &self.pieces[s.boundary][s.segment]
    }

    /// The line of site `s`, if it is one (not a corner).
    pub(crate) fn line(&self, s: TrueSite) -> Option<&LineSite> {
        match self.piece(s) {
            ClosedFormSegment::Line(l) if !s.corner => Some(l),
            _ => None,
        }
    }

    /// The arc of site `s`, if it is one (not a corner).
    pub(crate) fn arc(&self, s: TrueSite) -> Option<ArcSite> {
        match self.piece(s) {
            ClosedFormSegment::Arc { arc, .. } if !s.corner => Some(*arc),
            _ => None,
        }
    }

    /// Where the segment of `s` starts (a corner's point).
    pub(crate) fn start(&self, s: TrueSite) -> V2 {
        match self.piece(s) {
            ClosedFormSegment::Line(l) => l.start,
            ClosedFormSegment::Arc { start, .. } => *start,
        }
    }

    /// The unit tangent of the segment of `s` at `at`, one of its points.
    pub(crate) fn tangent_at(&self, s: TrueSite, at: V2) -> V2 {
        match self.piece(s) {
            ClosedFormSegment::Line(l) => l.along,
            ClosedFormSegment::Arc { arc, .. } => (at - arc.centre).perp() * (1.0 / arc.radius),
        }
    }

    /// The shape of site `s`.
    pub(crate) fn shape(&self, s: TrueSite) -> SiteShape {
        if s.corner {
            return SiteShape::point(self.start(s));
        }
        match self.piece(s) {
            ClosedFormSegment::Line(l) => SiteShape::Line(*l),
            ClosedFormSegment::Arc { arc, .. } => SiteShape::Round {
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

    /// The profile parameter of the foot of `x` on site `s` (a corner's own); `None` where
    /// the foot falls off its segment.
    pub(crate) fn foot(&self, s: TrueSite, x: V2) -> Option<f64> {
        if s.corner {
            return Some(s.segment as f64);
        }
        let slack = FOOT_SLACK * self.sites.size;
        let base = s.segment as f64;
        match self.piece(s) {
            ClosedFormSegment::Line(l) => {
                let along = l.along.dot(x - l.start);
                (along >= -slack && along <= l.length + slack)
                    .then(|| base + (along / l.length).clamp(0.0, 1.0))
            }
            ClosedFormSegment::Arc { arc, .. } => {
                let angle = arc.angle_from_start(x);
                let slack = slack / arc.radius;
                (angle >= -slack && angle <= arc.sweep() + slack)
                    .then(|| base + arc.share_at(angle))
            }
        }
    }
}

#[cfg(test)]
mod tests;
