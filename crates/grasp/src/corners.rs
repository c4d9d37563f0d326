//! Grasps with a finger at a convex corner: the pairs `(corner, t)` whose chord lies inside
//! the corner's cone of inward normals widened by the friction angle, and inside the friction
//! cone at `t`. They lie on the line of the corner's parameter in the square of pairs, a set of
//! intervals found by certified root isolation of functions of one variable.

use crate::cones::{corner_functions, straight_corner_ends, Form};
use crate::error::Result;
use crate::model::{Cone, Model};
use crate::quality::slip_angle;
use bspline::roots::{find_roots, RootOptions};
use bspline::BSpline;
use numeric::certificate::{Doubt, Doubts};
use std::f64::consts::PI;

/// The pairs with one finger at a convex corner: the other finger's profile parameters.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CornerLine {
    /// The joint (the segment starting there).
    pub(crate) joint: usize,
    /// The intervals of the other finger's profile parameter, sorted (a single value: the
    /// other finger at another corner).
    pub(crate) pieces: Vec<[f64; 2]>,
}

/// Rotates `v` by `angle`.
fn rotate(v: [f64; 2], angle: f64) -> [f64; 2] {
    let (s, c) = angle.sin_cos();
    [c * v[0] - s * v[1], s * v[0] + c * v[1]]
}

/// A box of pairs `s ≤ t` in the profile's parameter: the corner lines are sought only
/// where they may meet it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PairBox {
    /// The interval of `s`.
    pub(crate) s: [f64; 2],
    /// The interval of `t`.
    pub(crate) t: [f64; 2],
}

impl PairBox {
    /// Whether a pair of a finger at `u` and the other on `[v0, v1]` may lie in the box, in
    /// either order.
    fn meets(&self, u: f64, [v0, v1]: [f64; 2]) -> bool {
        let within = |x: [f64; 2], lo: f64, hi: f64| x[0] <= hi && lo <= x[1];
        (within(self.s, u, u) && within(self.t, v0, v1))
            || (within(self.t, u, u) && within(self.s, v0, v1))
    }
}

/// The corner lines of every convex corner of `model`, for friction `mu` (widths in the
/// frame's units); where `only` is given, just their stretches that may meet it (a corner
/// whose line cannot is left out).
pub(crate) fn corner_lines(
    model: &Model<'_>,
    mu: f64,
    widths: [Option<f64>; 2],
    only: Option<PairBox>,
    doubts: &mut Doubts,
) -> Result<Vec<CornerLine>> {
    let alpha = mu.atan();
    let n = model.n() as f64;
    let wanted = |u: f64, v: [f64; 2]| only.is_none_or(|b| b.meets(u, v));
    let mut out = Vec::new();
    for joint in &model.joints {
        let Cone::Convex { before, after } = joint.cone else {
            continue;
        };
        let k = joint.segment as f64;
        if !wanted(k, [0.0, n]) {
            continue;
        }
        let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
        let turn = cross(before, after).signum();
        let span = (before[0] * after[0] + before[1] * after[1])
            .clamp(-1.0, 1.0)
            .acos();
        // The widened cone's edges, and whether it is wider than a half-plane (then a chord
        // need only be on the inner side of one edge).
        let (lo, hi) = (rotate(before, -turn * alpha), rotate(after, turn * alpha));
        let wide = span + 2.0 * alpha > PI;
        let at_reflex = |c: f64| {
            let k = c.round();
            (c - k).abs() <= SHARED_END * (1.0 + k.abs())
                && model.joint_at(k).is_some_and(|j| j.cone == Cone::Reflex)
        };
        let mut pieces = Vec::new();
        for (j, form) in model.forms.iter().enumerate() {
            if !wanted(k, [j as f64, (j + 1) as f64]) {
                continue;
            }
            let conditions = Conditions::of(form, joint.point, [lo, hi], mu, widths)?;
            let (a, b) = form.domain();
            let mut cuts = vec![a, b];
            conditions.cuts(a, b, &mut cuts, doubts)?;
            cuts.sort_by(f64::total_cmp);
            cuts.dedup();
            let inside = |v: f64| {
                let [side_lo, side_hi] = conditions.sides(v);
                let lo_ok = turn * side_lo >= 0.0;
                let hi_ok = -turn * side_hi >= 0.0;
                let cone = if wide { lo_ok || hi_ok } else { lo_ok && hi_ok };
                cone && conditions.holds(v)
            };
            for w in cuts.windows(2) {
                if w[1] > w[0] && inside(0.5 * (w[0] + w[1])) {
                    let piece = [model.profile_param(j, w[0]), model.profile_param(j, w[1])];
                    // (Intervals meeting at a joint of the other finger are one, but at a
                    // reflex corner, whose pair with this corner is no grasp: the line is
                    // cut there.)
                    match pieces.last_mut() {
                        Some(last) if piece_touches(last, &piece) && !at_reflex(last[1]) => {
                            last[1] = piece[1]
                        }
                        _ => pieces.push(piece),
                    }
                }
            }
        }
        // The other finger at another convex corner: its cone holds the limits of both its
        // segments, so the pair is force closure where the angles to both cones are within α.
        for other in &model.joints {
            let u = other.segment as f64;
            if other.segment != joint.segment
                && matches!(other.cone, Cone::Convex { .. })
                && slip_angle(model, k, u) <= alpha
                && !pieces.iter().any(|p| p[0] <= u && u <= p[1])
            {
                pieces.push([u, u]);
            }
        }
        // A piece no longer than rounding at a reflex corner is the other finger at that
        // corner, which takes no part: a segment's condition touching zero at its end (the
        // reflex corner's pair exactly at the cone's edge, as round numbers make it) leaves
        // such a sliver.
        pieces.retain(|p| !(p[1] - p[0] <= SHARED_END * (1.0 + p[1].abs()) && at_reflex(p[0])));
        pieces.sort_by(|x, y| x[0].total_cmp(&y[0]));
        out.push(CornerLine {
            joint: joint.segment,
            pieces,
        });
    }
    Ok(out)
}

/// The conditions on the other finger, on one segment: the cone conditions at it (and the
/// widths), and on which side of each edge of the corner's widened cone it lies.
enum Conditions {
    /// As functions of the segment's parameter ([`corner_functions`]).
    Splines {
        holds: Vec<BSpline>,
        sides: [BSpline; 2],
    },
    /// On a straight segment without width limits, all affine: each one's values at the
    /// segment's ends `[lo, hi]`, with their rounding ([`straight_corner_ends`]), in the order
    /// of the cone conditions then the sides.
    Affine {
        ends: [[(f64, f64); 2]; 4],
        lo: f64,
        hi: f64,
    },
}

impl Conditions {
    fn of(
        form: &Form,
        corner: [f64; 2],
        edges: [[f64; 2]; 2],
        mu: f64,
        widths: [Option<f64>; 2],
    ) -> Result<Self> {
        if widths.iter().all(Option::is_none) {
            if let Some(ends) = straight_corner_ends(form, corner, edges, mu) {
                let (lo, hi) = form.domain();
                return Ok(Self::Affine { ends, lo, hi });
            }
        }
        let (holds, sides) = corner_functions(form, corner, edges, mu, widths)?;
        Ok(Self::Splines { holds, sides })
    }

    /// Adds to `cuts` where a condition changes sign on `[a, b]` (the segment's domain).
    fn cuts(&self, a: f64, b: f64, cuts: &mut Vec<f64>, doubts: &mut Doubts) -> Result<()> {
        match self {
            Self::Splines { holds, sides } => {
                for f in holds.iter().chain(sides) {
                    for r in find_roots(f, a, b, &RootOptions::default())? {
                        // Every function vanishes where the segment meets the corner (d = 0):
                        // that root is known, proven or not. So is one at either end of any
                        // segment (a cone's edge through another joint, as round numbers put
                        // it): the other finger is at that joint there, a pair of joints
                        // decided apart, and the ends are cuts already.
                        let at_end = r.bracket.0 <= a || r.bracket.1 >= b;
                        if !r.certified && !at_end {
                            doubts.add(Doubt::RootsUnresolved);
                        }
                        cuts.push(r.u.clamp(a, b));
                    }
                }
            }
            // An affine function with trusted values of opposite signs at the ends has its
            // one root between them; one within rounding of zero at an end has its roots at
            // that end, a cut already (or, within rounding at both, on no side of zero).
            Self::Affine { ends, lo, hi } => {
                for [(f0, e0), (f1, e1)] in ends {
                    if f0.abs() > *e0 && f1.abs() > *e1 && (*f0 > 0.0) != (*f1 > 0.0) {
                        cuts.push((lo + (hi - lo) * (f0 / (f0 - f1))).clamp(*lo, *hi));
                    }
                }
            }
        }
        Ok(())
    }

    /// The values at `v` of the functions of the sides of the corner's cone.
    fn sides(&self, v: f64) -> [f64; 2] {
        match self {
            Self::Splines { sides, .. } => [sides[0].eval_scalar(v), sides[1].eval_scalar(v)],
            Self::Affine { ends, lo, hi } => {
                let r = (v - lo) / (hi - lo);
                let at = |[(f0, _), (f1, _)]: [(f64, f64); 2]| f0 + r * (f1 - f0);
                [at(ends[2]), at(ends[3])]
            }
        }
    }

    /// Whether every cone (and width) condition at the other finger holds at `v`.
    fn holds(&self, v: f64) -> bool {
        match self {
            Self::Splines { holds, .. } => holds.iter().all(|f| f.eval_scalar(v) >= 0.0),
            Self::Affine { ends, lo, hi } => {
                let r = (v - lo) / (hi - lo);
                ends[..2]
                    .iter()
                    .all(|[(f0, _), (f1, _)]| f0 + r * (f1 - f0) >= 0.0)
            }
        }
    }
}

/// Two intervals of the line meet when the second starts this close (relative) to the end
/// of the first: consecutive segments' intervals share the joint between them.
const SHARED_END: f64 = 1e-12;

/// Whether two intervals in order meet (the second starts where the first ends).
fn piece_touches(first: &[f64; 2], second: &[f64; 2]) -> bool {
    second[0] <= first[1] + SHARED_END * (1.0 + first[1].abs())
}
