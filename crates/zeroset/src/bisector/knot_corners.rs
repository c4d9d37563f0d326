//! Self-bisector branches that end beside a knot corner `(k, k)` of the diagonal, traced on
//! to the corner in polar coordinates about it.
//!
//! Where the curvature has an extremum exactly at a knot (its derivative changes sign there,
//! common for B-splines), a branch ends at the corner `(k, k)`, reached through the cell
//! `t ≤ k < r`. That cell is not divided by `(t − r)⁴` (its two foot points lie on different
//! polynomial pieces), so `F` is flat to fourth order about the corner: below its rounding
//! within a distance of the corner that goes as the fourth root of that rounding over `F`'s
//! size, from 1e-5 to beyond 1e-3 of the domain. The zero set stops where that flat region
//! begins, which in the plane can be 1e-2 of the size short of the branch's end, the centre
//! of curvature at the knot.
//!
//! Near the corner the branch is a graph `θ(ρ)` in polar coordinates about it, tending to a
//! fixed angle. So the branch is followed by halving `ρ` and solving the bisector condition
//! ψ (whose rounding shrinks with the distances, unlike `F`'s) for the angle, by Newton from
//! the angle before. Each point must stay in step: its image converges, moving at most twice
//! as far as the step before (the first, as far as the centres of curvature at the feet
//! allow, unless ψ decides its angle). Between two points the branch is sampled at the
//! middle radius: where it strays from the chord by more than the chord tolerance, that
//! point is kept too.

use super::output::Branch;
use super::point::psi;
use super::vertices::Ctx;
use crate::patch::Patch;
use curve::distance_to_segment;
use numeric::Rect;

/// A self-bisector branch ending this close (relative to the domain) to a knot corner of the
/// diagonal, on the cell across it, is traced on to the corner. The flat region of `F`
/// about a corner has reached 2e-3 of the domain, and the zero set has lost a branch
/// 1.05e-2 from a corner (of a curve at 3e7 sizes from the origin, in its frame); the trace
/// solves ψ and checks every step, so where no branch heads for the corner it adds nothing.
const CORNER_REACH: f64 = 5e-2;

/// A branch ending this close to a knot corner (relative to the domain) on a cell beside
/// the one across it is traced on too: the flat region's extent (its end strays there).
const FLAT_REACH: f64 = 2e-3;

/// ... unless it ends this close to the diagonal (relative to the domain): a branch ending
/// at a curvature extremum is traced to within [`super::vertices::DIAGONAL_MARGIN`] of it.
const OFF_DIAGONAL: f64 = 1e-8;

/// Halvings of the distance to the corner at most (from 5e-2 of the domain to ~1e-11).
const MAX_CORNER_STEPS: usize = 32;

/// Slack on "in step", relative to the bounding-box diagonal: the bisector points carry
/// rounding of ~1e-16 of the size, so steps that have shrunk to that noise still count as in
/// step.
const STEP_SLACK: f64 = 1e-12;

/// The first point may move this many times as far as the image's speed would carry it over
/// the same change of parameters (the branch need not be straight there).
const FIRST_STEP: f64 = 4.0;

/// Newton steps on the angle at one radius, and how far it may turn from the angle before
/// (radians): farther, it heads for another zero of ψ (ψ has three near the corner).
const ANGLE_STEPS: usize = 12;
const MAX_TURN: f64 = 0.2;

/// Newton on the angle has converged when its step moves the point by this share of the
/// domain (ρ times the step). ψ's rounding leaves the angle uncertain, the more so the
/// nearer the corner (~1e-10 rad at ρ = 3e-3, ~1e-7 at 4e-4), where Newton wanders instead
/// of converging; the polish of every accepted point (up to 1e-6 of the domain) puts it on
/// the bisector.
const ANGLE_CONVERGED: f64 = 1e-10;

/// Mid-radius samples between two points at most, nested (each halves the radial step).
const MAX_MIDDLES: usize = 8;

/// The angles of the cell `t ≤ k < r` about its corner.
const QUARTER: f64 = std::f64::consts::FRAC_PI_2;
const HALF: f64 = std::f64::consts::PI;

/// A point of the branch near the corner: its radius about the corner, feet and image.
#[derive(Clone, Copy)]
struct Polar {
    rho: f64,
    theta: f64,
    /// Whether ψ decided the angle (by Newton from the angle before, turning little).
    solved: bool,
    tr: [f64; 2],
    xy: [f64; 2],
}

impl Ctx<'_> {
    /// Extends self-bisector branches that end beside a knot corner of the diagonal up to it.
    pub(super) fn reach_knot_corners(&self, branches: &mut [Branch], cells: &[Patch], dom: Rect) {
        let mut knots: Vec<f64> = cells
            .iter()
            .filter(|p| p.t0 == p.r0 && p.t0 > dom.t.lo)
            .map(|p| p.t0)
            .collect();
        knots.sort_by(f64::total_cmp);
        knots.dedup();
        for b in branches.iter_mut() {
            // Each end in turn as the last vertex.
            self.reach_corner_from_end(b, &knots, dom);
            b.tr.reverse();
            b.xy.reverse();
            self.reach_corner_from_end(b, &knots, dom);
            b.tr.reverse();
            b.xy.reverse();
        }
    }

    /// Extends the branch from its last vertex up to a knot corner it heads for.
    fn reach_corner_from_end(&self, b: &mut Branch, knots: &[f64], dom: Rect) {
        let ext = dom.t.width();
        let (reach, flat) = (CORNER_REACH * ext, FLAT_REACH * ext);
        let n = b.tr.len();
        if n < 2 {
            return;
        }
        let q = b.tr[n - 1];
        let across =
            |q: [f64; 2], k: f64| q[0] <= k && k < q[1] && k - q[0] <= reach && q[1] - k <= reach;
        let in_flat = |q: [f64; 2], k: f64| (q[0] - k).abs() <= flat && (q[1] - k).abs() <= flat;
        // On the cell across the corner, or beside the corner within the flat region, where
        // the zero set's end strays across the cells' borders (but not at the diagonal,
        // where branches end at curvature extrema).
        let heads_for = |k: f64| across(q, k) || in_flat(q, k) && q[1] - q[0] > OFF_DIAGONAL * ext;
        let Some(j) = knots.iter().position(|&k| heads_for(k)) else {
            return;
        };
        // On the corner's cell: between the knots on either side.
        let k = knots[j];
        let before_knot = if j > 0 { knots[j - 1] } else { dom.t.lo };
        let after_knot = knots.get(j + 1).copied().unwrap_or(dom.t.hi);
        if q[0] < before_knot || q[1] > after_knot {
            return;
        }
        let q1 = b.tr[n - 2];
        let (p0, p1) = (b.xy[n - 1], b.xy[n - 2]);
        // How far the image moves per unit of parameters: on the last segment, and with the
        // centres of curvature at the feet, which it nears at the corner (the branch's end
        // may lie in the flat region, its last segment far slower than the image moves
        // there).
        let moved = (p0[0] - p1[0]).hypot(p0[1] - p1[1]);
        let evolute = |u: f64| Some(self.evolute_speed(u)).filter(|v| v.is_finite());
        let rate = (moved / (q[0] - q1[0]).hypot(q[1] - q1[1]).max(f64::MIN_POSITIVE))
            .max(evolute(q[0]).unwrap_or(0.0))
            .max(evolute(q[1]).unwrap_or(0.0));
        for (tr, xy) in self.trace_to_corner(k, q, p0, rate) {
            b.tr.push(tr);
            b.xy.push(xy);
        }
    }

    /// The points of the branch from its end `q` (image `from`) toward the corner `(k, k)`,
    /// in order; `rate` bounds the image's speed there per unit of parameters.
    fn trace_to_corner(
        &self,
        k: f64,
        q: [f64; 2],
        from: [f64; 2],
        rate: f64,
    ) -> Vec<([f64; 2], [f64; 2])> {
        let (dt, dr) = (q[0] - k, q[1] - k);
        let mut last = Polar {
            rho: dt.hypot(dr),
            // (From an end beside the cell across, the first step heads into it.)
            theta: dr.atan2(dt).clamp(QUARTER, HALF),
            solved: false,
            tr: q,
            xy: from,
        };
        // The first point halves the distance to the corner. Its image may move farther
        // than the rate allows where ψ decides its angle: the branch, followed in
        // parameters, is then continuous (away from the corner the image can move far faster
        // than the centres of curvature at the feet).
        let mut allowed = FIRST_STEP * rate * 0.5 * last.rho;
        let mut out = Vec::new();
        for step in 0..MAX_CORNER_STEPS {
            let Some(next) = self.polar_point(k, 0.5 * last.rho, last.theta) else {
                break;
            };
            let moved = (next.xy[0] - last.xy[0]).hypot(next.xy[1] - last.xy[1]);
            if moved > allowed + STEP_SLACK * self.diag && !(step == 0 && next.solved) {
                break;
            }
            self.middles(k, &last, &next, MAX_MIDDLES, &mut out);
            out.push((next.tr, next.xy));
            (last, allowed) = (next, 2.0 * moved);
        }
        out
    }

    /// The points between `a` and `b` (outer first) where the branch strays from the chord
    /// by more than the chord tolerance: sampled at the middle radius, nested.
    fn middles(
        &self,
        k: f64,
        a: &Polar,
        b: &Polar,
        depth: usize,
        out: &mut Vec<([f64; 2], [f64; 2])>,
    ) {
        if depth == 0 {
            return;
        }
        let Some(m) = self.polar_point(k, 0.5 * (a.rho + b.rho), a.theta) else {
            return;
        };
        if distance_to_segment(m.xy, a.xy, b.xy) <= self.chord {
            return;
        }
        self.middles(k, a, &m, depth - 1, out);
        out.push((m.tr, m.xy));
        self.middles(k, &m, b, depth - 1, out);
    }

    /// The branch's point at distance `rho` from the corner `(k, k)`, when it is an
    /// accepted bisector point on the cell `t < k < r`: its angle solved for from `theta`
    /// where ψ decides it, else at `theta`. (Close to the corner ψ is as small as its
    /// rounding; there the normals at both feet meet near the centre of curvature whatever
    /// their parameters' ratio, within the distance it moves as the feet move.)
    fn polar_point(&self, k: f64, rho: f64, theta: f64) -> Option<Polar> {
        let solved = self.corner_angle(k, rho, theta);
        let th = solved.unwrap_or(theta);
        let (s, c) = th.sin_cos();
        // (On the cell's border t = k, cos θ rounds to a hair above 0.)
        let g = [(k + rho * c).min(k), k + rho * s];
        if g[1] <= k {
            return None;
        }
        let (tr, xy) = self.accept(g[0], g[1])?;
        Some(Polar {
            rho,
            theta: th,
            solved: solved.is_some(),
            tr,
            xy,
        })
    }

    /// The angle near `theta` at which ψ vanishes at distance `rho` from the corner, by
    /// Newton; `None` where it does not converge without turning too far.
    fn corner_angle(&self, k: f64, rho: f64, theta: f64) -> Option<f64> {
        let ext = self.c1.domain().1 - self.c1.domain().0;
        let mut th = theta;
        for _ in 0..ANGLE_STEPS {
            let (s, c) = th.sin_cos();
            let (v, gt, gr) = psi(&self.jets1, &self.jets2, k + rho * c, k + rho * s);
            let turn = v / (rho * (gr * c - gt * s));
            if !turn.is_finite() || (th - turn - theta).abs() > MAX_TURN {
                return None;
            }
            th -= turn;
            if !(QUARTER..=HALF).contains(&th) {
                return None; // off the cell t ≤ k < r
            }
            if rho * turn.abs() <= ANGLE_CONVERGED * ext {
                return Some(th);
            }
        }
        None
    }
}

impl Ctx<'_> {
    /// How fast the centre of curvature of the curve moves at `u`, per unit of its
    /// parameter: `|dρ/du|` for the radius of curvature `ρ` (the centre moves along the
    /// normal); infinite at an inflection.
    fn evolute_speed(&self, u: f64) -> f64 {
        let o = self.jets1.derivs(u, 3);
        let (a, b, c) = ([o[2], o[3]], [o[4], o[5]], [o[6], o[7]]);
        let g = a[0] * a[0] + a[1] * a[1];
        let w = a[0] * b[1] - a[1] * b[0];
        let w_dot = a[0] * c[1] - a[1] * c[0];
        let ab = a[0] * b[0] + a[1] * b[1];
        // ρ = g^{3/2} / w, so ρ' = (3 g^{1/2} (a·b) w − g^{3/2} w') / w².
        (3.0 * g.sqrt() * ab * w - g * g.sqrt() * w_dot).abs() / (w * w)
    }
}
