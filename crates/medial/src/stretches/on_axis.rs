//! The test of a branch's points: whether one lies on the axis (inside the region, its disk
//! empty, its feet apart), or else the site that keeps it off.

use super::{Branch, Intruder};
use crate::candidates::Vertex;
use crate::corners::entered_across_corner;
use crate::sites::{Disk, EMPTY_SLACK};
use curve::ParamCurve;

/// The "site" beyond the box the exterior axis is clipped to.
const CLIPPED: (usize, usize) = (usize::MAX, usize::MAX);

/// The "site" of a point on the wrong side of its own foot (outside the region, for the
/// inner axis): no site enters its disk that a search between two such points could follow.
const OUTSIDE: (usize, usize) = (usize::MAX, usize::MAX - 1);

/// Feet closer than this share of the radius are one point: where they meet the axis ends,
/// at a centre of curvature (bisector points whose feet close in on a smooth joint, where the
/// bisector function vanishes to high order, are no part of the axis either).
const FEET_APART: f64 = 1e-4;

impl Branch<'_, '_> {
    /// The boundary site nearest `x`: boundary and segment.
    pub(super) fn nearest_site(&self, x: [f64; 2]) -> (usize, usize) {
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
    pub(super) fn classify(&self, v: &Vertex) -> Result<(), Intruder> {
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

    /// How far apart the two feet of a vertex are.
    fn feet_apart(&self, v: &Vertex) -> f64 {
        let (p, q) = (
            self.sites.foot(self.c.boundary[0], v.tr[0]),
            self.sites.foot(self.c.boundary[1], v.tr[1]),
        );
        (p[0] - q[0]).hypot(p[1] - q[1])
    }

    /// Whether a vertex lies on the axis: inside the region, its disk empty, its two feet
    /// apart (else its point has one nearest point: the axis ends where the feet meet).
    pub(super) fn on_axis(&self, v: &Vertex) -> bool {
        self.sites.in_clip(v.xy) && self.feet_part(v) && self.disk_empty(v)
    }

    /// (Only in the search for where a stretch ends: see
    /// [`Sites::probe`](crate::sites::Sites::probe).)
    pub(super) fn disk_empty(&self, v: &Vertex) -> bool {
        self.inside(v) && self.probe(v) == Disk::Empty
    }

    /// What the disk of `v` holds ([`Sites::probe`](crate::sites::Sites::probe)), the side
    /// across a convex corner beside its foot included ([`Self::across_corner`]).
    pub(super) fn probe(&self, v: &Vertex) -> Disk {
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

    pub(super) fn feet_part(&self, v: &Vertex) -> bool {
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

    pub(super) fn inside(&self, v: &Vertex) -> bool {
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
}
