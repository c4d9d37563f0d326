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
//! the angle before. Each point must stay in step (its image converges, moving at most twice
//! as far as the step before), and between two points the branch is sampled at the middle
//! radius: where it strays from the chord by more than the chord tolerance, that point is
//! kept too.

use super::output::Branch;
use super::point::psi;
use super::vertices::Ctx;
use crate::patch::Patch;

/// A self-bisector branch ending this close (relative to the domain) to a knot corner of the
/// diagonal, on the cell across it, is traced on to the corner. The flat region of `F`
/// about a corner has reached 2e-3 of the domain; beyond 1e-2 its branches are traced.
const CORNER_REACH: f64 = 1e-2;

/// Halvings of the distance to the corner at most (from 1e-2 of the domain to ~1e-11).
const MAX_CORNER_STEPS: usize = 30;

/// Slack on "in step", relative to the bounding-box diagonal: the bisector points carry
/// rounding of ~1e-16 of the size, so steps that have shrunk to that noise still count as in
/// step.
const STEP_SLACK: f64 = 1e-12;

/// The first point may move this many times as far as the branch's last segment would carry
/// it over the same change of parameters (the branch need not be straight there).
const FIRST_STEP: f64 = 4.0;

/// Newton steps on the angle at one radius, and how far it may turn from the angle before
/// (radians): farther, it heads for another zero of ψ (ψ has three near the corner).
const ANGLE_STEPS: usize = 12;
const MAX_TURN: f64 = 0.2;

/// Newton on the angle has converged when its step is this small (radians): the point then
/// moves by ρ times that, far below the chord tolerance.
const ANGLE_CONVERGED: f64 = 1e-12;

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
    tr: [f64; 2],
    xy: [f64; 2],
}

impl Ctx<'_> {
    /// Extends self-bisector branches that end beside a knot corner of the diagonal up to it.
    pub(super) fn reach_knot_corners(
        &self,
        branches: &mut [Branch],
        cells: &[Patch],
        dom: [f64; 4],
    ) {
        let ext = dom[1] - dom[0];
        let mut knots: Vec<f64> = cells
            .iter()
            .filter(|p| p.t0 == p.r0 && p.t0 > dom[0])
            .map(|p| p.t0)
            .collect();
        knots.sort_by(f64::total_cmp);
        knots.dedup();
        for b in branches.iter_mut() {
            for front in [false, true] {
                let n = b.tr.len();
                if n < 2 {
                    continue;
                }
                let (end, before) = if front { (0, 1) } else { (n - 1, n - 2) };
                let q = b.tr[end];
                let Some(&k) = knots.iter().find(|&&k| {
                    q[0] <= k
                        && k < q[1]
                        && k - q[0] <= CORNER_REACH * ext
                        && q[1] - k <= CORNER_REACH * ext
                }) else {
                    continue;
                };
                // How far the image moves per unit of parameters on the last segment.
                let (p0, p1) = (b.xy[end], b.xy[before]);
                let q1 = b.tr[before];
                let moved = (p0[0] - p1[0]).hypot(p0[1] - p1[1]);
                let rate = moved / (q[0] - q1[0]).hypot(q[1] - q1[1]).max(f64::MIN_POSITIVE);
                let extra = self.trace_to_corner(k, q, p0, rate);
                if front {
                    for (tr, xy) in extra {
                        b.tr.insert(0, tr);
                        b.xy.insert(0, xy);
                    }
                } else {
                    for (tr, xy) in extra {
                        b.tr.push(tr);
                        b.xy.push(xy);
                    }
                }
            }
        }
    }

    /// The points of the branch from its end `q` (image `from`) toward the corner `(k, k)`,
    /// in order; `rate` is the image's speed on the branch's last segment.
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
            theta: dr.atan2(dt),
            tr: q,
            xy: from,
        };
        // The first point halves the distance to the corner.
        let mut allowed = FIRST_STEP * rate * 0.5 * last.rho;
        let mut out = Vec::new();
        for _ in 0..MAX_CORNER_STEPS {
            let Some(next) = self.polar_point(k, 0.5 * last.rho, last.theta) else {
                break;
            };
            let moved = (next.xy[0] - last.xy[0]).hypot(next.xy[1] - last.xy[1]);
            if moved > allowed + STEP_SLACK * self.diag {
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
    /// rounding, but there the image hardly depends on the angle: the normals at both feet
    /// meet near the centre of curvature whatever their parameters' ratio.)
    fn polar_point(&self, k: f64, rho: f64, theta: f64) -> Option<Polar> {
        let th = self.corner_angle(k, rho, theta).unwrap_or(theta);
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
            tr,
            xy,
        })
    }

    /// The angle near `theta` at which ψ vanishes at distance `rho` from the corner, by
    /// Newton; `None` where it does not converge without turning too far.
    fn corner_angle(&self, k: f64, rho: f64, theta: f64) -> Option<f64> {
        let mut th = theta;
        for _ in 0..ANGLE_STEPS {
            let (s, c) = th.sin_cos();
            let (v, gt, gr) = psi(self.c1, self.c2, k + rho * c, k + rho * s);
            let turn = v / (rho * (gr * c - gt * s));
            if !turn.is_finite() || (th - turn - theta).abs() > MAX_TURN {
                return None;
            }
            th -= turn;
            if !(QUARTER..=HALF).contains(&th) {
                return None; // off the cell t ≤ k < r
            }
            if turn.abs() <= ANGLE_CONVERGED {
                return Some(th);
            }
        }
        None
    }
}

/// Distance of `z` from the segment `x`–`y`.
fn distance_to_segment(z: [f64; 2], x: [f64; 2], y: [f64; 2]) -> f64 {
    let (dx, dy) = (y[0] - x[0], y[1] - x[1]);
    let len2 = dx * dx + dy * dy;
    let s = if len2 > 0.0 {
        (((z[0] - x[0]) * dx + (z[1] - x[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (z[0] - x[0] - s * dx).hypot(z[1] - x[1] - s * dy)
}
