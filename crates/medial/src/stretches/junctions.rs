//! Where a stretch ends inside its branch: bracketed by halving on the exact branch, then
//! solved (the bracketed solve's derivative-free step) for the tri-tangent disk that also touches the boundary point
//! entering beyond it; an exterior stretch ends on its clip box.

use super::Branch;
use crate::candidates::Vertex;
use crate::sites::Disk;
use curve::ParamCurve;
use geometry::NearestPoint;
use numeric::rounding::ulps;
use numeric::solve::Itp;

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

/// The width of the bracket (of the branch's parameter, in `[0, 1]` between two vertices)
/// the tri-tangent disk is solved to: a few units of rounding, where the distances' own
/// rounding decides the sign.
const TRI_TANGENT_WIDTH: f64 = ulps(4.0);

/// Further halvings that put the end of an exterior stretch on the box it is clipped to.
const CLIP_STEPS: usize = 30;

/// Where a stretch ends, bracketed on its branch: from `lo` (on the axis, at `last`) to `hi`
/// (off it, at `outside` when the branch has a point there).
struct Bracket {
    lo: f64,
    hi: f64,
    last: Vertex,
    outside: Option<Vertex>,
}

impl Branch<'_, '_> {
    /// The end of a stretch between its last vertex `from` (on the axis) and the next
    /// vertex's feet `beyond` (off it): bracketed by halving on the exact branch, then solved
    /// for the disk that also touches the boundary point that enters beyond it. A coarse
    /// bracket is tried first; its solution stands if its disk proves empty.
    pub(super) fn junction(
        &self,
        from: Vertex,
        beyond: [f64; 2],
        beyond_xy: [f64; 2],
    ) -> Option<Vertex> {
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
        // (Touching it within rounding, or exactly: that end is the junction.)
        if fa <= 0.0 {
            return Some(best);
        }
        // The derivative-free bracketed step (ITP), the end outside the disk kept: each step
        // a point of the branch, which may not be found.
        let mut solve = Itp::new((a, b), (fa, fb), TRI_TANGENT_WIDTH);
        while solve.width() > TRI_TANGENT_WIDTH {
            let Some(s) = solve.next() else { break };
            let Some(v) = at(s) else { break };
            let f = third(&v);
            if f >= 0.0 {
                best = v;
            }
            solve.update(s, f);
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
}
