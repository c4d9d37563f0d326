//! Exact points of a branch: the vertex of given feet with its radius, and a guess (feet
//! and point between two vertices) snapped onto the bisector, one foot kept and the other
//! solved for by secant steps.

use super::Branch;
use crate::candidates::Vertex;
use crate::sites::EMPTY_SLACK;
use numeric::rounding::ulps;
use numeric::solve::secant;

/// Secant steps of a foot-point solve.
const FOOT_STEPS: usize = 30;

/// The secant of a foot-point solve starts from the guessed foot and one this share of the
/// bracket beside it.
const START_STEP: f64 = 1e-3;

impl Branch<'_, '_> {
    /// The vertex of feet `tr` at `xy`, with its radius.
    pub(super) fn vertex(&self, tr: [f64; 2], xy: [f64; 2]) -> Option<Vertex> {
        let f = self.sites.foot(self.c.boundary[0], tr[0]);
        let radius = (xy[0] - f[0]).hypot(xy[1] - f[1]);
        radius.is_finite().then_some(Vertex { tr, xy, radius })
    }

    /// The exact bisector vertex near the feet `guess` and point `near` (between the
    /// vertices with feet `p` and `q`): the foot on a segment that moves most between them is
    /// kept, the other solved for; two corners' bisector is the straight line through `near`.
    pub(super) fn snap(
        &self,
        guess: [f64; 2],
        near: [f64; 2],
        p: [f64; 2],
        q: [f64; 2],
    ) -> Option<Vertex> {
        let keep = match self.c.corner {
            [true, true] => return self.vertex(guess, near),
            [true, false] => 1,
            [false, true] => 0,
            [false, false] => usize::from((q[0] - p[0]).abs() < (q[1] - p[1]).abs()),
        };
        self.snap_keeping(keep, guess, near, p, q)
    }

    /// [`Self::snap`] with foot `keep` (not a corner's) kept at `guess[keep]`.
    pub(super) fn snap_keeping(
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
        // The secant may leave the bracket (where the branch turns between its vertices,
        // the other foot goes past both of theirs and back); by no more than the kept foot
        // moves between them. (Its iterate of least gap is the foot: at the gap's rounding
        // floor, ~1e-16 of the coordinates, far from the origin well above 1e-16 of the
        // size, the steps divide noise by noise and may throw the next iterate anywhere.)
        let span = (hi - lo).max((q[keep] - p[keep]).abs()).max(ulps(1.0));
        let within = (lo - span, hi + span);
        let foot = |u0: f64, u1: f64| {
            secant(&reduced, (u0, u1), FOOT_STEPS, within)
                .and_then(|u| self.foot_solved(keep, guess, p, u, &g))
        };
        // From the two vertices' feet; failing that, from the guess and a foot a little
        // beside it (beside a corner on the kept foot's own line the equidistant point of
        // the corner is at infinity, and a secant from there strays).
        foot(lo, hi).or_else(|| {
            let u = guess[other];
            foot(u, u + START_STEP * (hi - lo).max(ulps(1.0)))
        })
    }

    /// The vertex with foot `keep` at `guess[keep]` and the other at `u`, where the secant
    /// of [`Self::snap_keeping`] (from the feet of the vertex `p`; `g` the equidistance's gap
    /// and point) left it: if that is a foot.
    fn foot_solved(
        &self,
        keep: usize,
        guess: [f64; 2],
        p: [f64; 2],
        u: f64,
        g: &dyn Fn(f64) -> (f64, curve::V2),
    ) -> Option<Vertex> {
        let (c, other) = (self.c, 1 - keep);
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
