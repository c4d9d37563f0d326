//! Ends of the axis at centres of curvature: where the feet of a branch close in, the centre
//! of curvature at the curvature's peak between them (or at a corner beside a foot).

use super::Branch;
use crate::candidates::Vertex;
use crate::curvature::curvature_peak;
use curve::ParamCurve;
use numeric::rounding::ulps;

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

impl Branch<'_, '_> {
    /// The end of the axis where the feet of `v` close in: the centre of curvature at the
    /// curvature's peak between them (the foot of larger curvature where no peak is found);
    /// `None` where the boundary is straight or the feet meet at a corner.
    pub(super) fn end_at_curvature_centre(&self, v: &Vertex) -> Option<Vertex> {
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
    pub(super) fn centre_closed_in_on(&self, last: &Vertex) -> Option<Vertex> {
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
}
