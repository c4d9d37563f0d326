//! The seams of an offset: the points of the medial axis whose radius is the distance. There
//! the offsets of the two sides of the axis meet, and each side's kept stretch of boundary
//! begins or ends.

use crate::loops::{incoming_segment, outgoing_segment};
use crate::walk::{Foot, Walk};
use curve::V2;
use medial::{Edge, MedialAxis};
use std::f64::consts::TAU;

/// Newton steps for a seam's feet: each doubles the digits; more means a degenerate seam
/// (the axis grazing the distance), which keeps its interpolated feet.
const NEWTON_STEPS: usize = 30;

/// A seam's two offset points agree to this, relative to the region's size: a few roundings
/// of the coordinates.
const SEAM_CLOSURE: f64 = 1e-13;

/// An axis point keeps its boundary points at the distance only when its radius exceeds the
/// distance by this much, relative to the region's size: where they are within it, the region
/// left at the distance is narrower there than the axis's own accuracy (1e-9 of the size), a
/// point where two parts of the offset touch, and it is taken as closed.
pub(crate) const TOUCHING: f64 = 1e-9;

/// Where the offset at one distance meets itself across the axis.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Seam {
    /// Per side of the axis: the boundary and the foot.
    pub(crate) feet: [(usize, Foot); 2],
    /// Per side: whether the stretch of boundary kept on that side begins at the foot (else it
    /// ends there), in the direction the boundary is walked.
    pub(crate) begins: [bool; 2],
    /// Whether Newton's method closed the seam (else its feet are interpolated).
    pub(crate) refined: bool,
}

/// The seams of the offset at distance `d`: where an edge's radius crosses `d` between two
/// vertices (a vertex within [`TOUCHING`] of `d` counts as below it); `None` where a crossing
/// gave no seam (its feet on two boundaries, or on none), so the loops cannot be trusted.
pub(crate) fn seams(axis: &MedialAxis, walks: &[Walk<'_>], d: f64, size: f64) -> Option<Vec<Seam>> {
    let above = |r: f64| r > d + TOUCHING * size;
    let mut found = Vec::new();
    for edge in &axis.edges {
        for k in 1..edge.xy.len() {
            let (r0, r1) = (edge.radius[k - 1], edge.radius[k]);
            if above(r0) != above(r1) {
                found.push(seam_between(edge, k, walks, d, size)?);
            }
        }
    }
    Some(found)
}

/// The seam on `edge` between vertices `k − 1` and `k`.
fn seam_between(edge: &Edge, k: usize, walks: &[Walk<'_>], d: f64, size: f64) -> Option<Seam> {
    let (r0, r1) = (edge.radius[k - 1], edge.radius[k]);
    let share = ((d - r0) / (r1 - r0)).clamp(0.0, 1.0);
    let (x0, x1) = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
    let guess = x0 + (x1 - x0) * share;
    let toward_wider = if r1 > r0 { x1 - x0 } else { x0 - x1 };
    let step = x1 - x0;
    let [before, after] = [k - 1, k].map(|j| sided_feet(edge, j, step, walks));
    let (before, after) = (before?, after?);
    let foot_on = |side: usize| -> Option<(usize, Foot)> {
        let (b, u0) = before[side];
        let (b1, u1) = after[side];
        if b != b1 {
            return None;
        }
        Some((b, foot_between(walks.get(b)?, u0, u1, share, guess)))
    };
    let feet = [foot_on(0)?, foot_on(1)?];
    let (refined_feet, mut refined) = refine(walks, feet, d, size);
    // (Both feet at one point of one boundary solve the equations trivially: no seam.)
    if refined_feet[0].0 == refined_feet[1].0 {
        let walk = &walks[refined_feet[0].0];
        let gap = foot_point(walk, refined_feet[0].1) - foot_point(walk, refined_feet[1].1);
        refined &= gap.norm() > SEAM_CLOSURE * size;
    }
    let point = walks[refined_feet[0].0].offset(refined_feet[0].1, d).0;
    let begins = refined_feet.map(|(b, foot)| {
        let normal = (point - foot_point(&walks[b], foot)).unit();
        // (The walk's tangent has the region, and so the normal, on its left.)
        let tangent = V2::new(normal.y, -normal.x);
        toward_wider.dot(tangent) > 0.0
    });
    Some(Seam {
        feet: refined_feet,
        begins,
        refined,
    })
}

/// The feet of vertex `j` of `edge` paired by the side of `step` (along the edge) they lie
/// on, left first: the axis lists them in no fixed order.
pub(crate) fn sided_feet(
    edge: &Edge,
    j: usize,
    step: V2,
    walks: &[Walk<'_>],
) -> Option<[(usize, f64); 2]> {
    let feet = [0, 1].map(|i| (edge.boundary[j][i], edge.feet[j][i]));
    let left = |(b, u): (usize, f64)| -> Option<f64> {
        Some(step.cross(walks.get(b)?.point(u) - V2::from_arr(edge.xy[j])))
    };
    Some(if left(feet[0])? >= left(feet[1])? {
        feet
    } else {
        [feet[1], feet[0]]
    })
}

/// The foot between two vertices' feet `u0`, `u1` at `share` of the way: the fan of a reflex
/// corner both feet sit on, else a point of the segment the way between them crosses.
fn foot_between(walk: &Walk<'_>, u0: f64, u1: f64, share: f64, guess: V2) -> Foot {
    let period = walk.period;
    // (The short way round a closed boundary.)
    let step = (u1 - u0 + 0.5 * period).rem_euclid(period) - 0.5 * period;
    if let (Some(c0), Some(c1)) = (walk.reflex_corner_at(u0), walk.reflex_corner_at(u1)) {
        if c0 == c1 {
            let c = walk.point(c0);
            return Foot::Fan {
                u: c0,
                angle: (guess - c).angle(),
            };
        }
    }
    let u = (u0 + step * share).rem_euclid(period);
    let middle = (u0 + 0.5 * step).rem_euclid(period);
    let segment = walk.profile.locate(middle).0;
    Foot::OnSegment {
        segment,
        u: u.clamp(segment as f64, segment as f64 + 1.0),
    }
}

/// The point a foot stands on.
pub(crate) fn foot_point(walk: &Walk<'_>, foot: Foot) -> V2 {
    match foot {
        Foot::OnSegment { segment, u } => walk.profile.jet_on(segment, u, 0).p,
        Foot::Fan { u, .. } => walk.point(u),
    }
}

/// Newton's method on the two feet, so that their offset points coincide.
fn refine(
    walks: &[Walk<'_>],
    feet: [(usize, Foot); 2],
    d: f64,
    size: f64,
) -> ([(usize, Foot); 2], bool) {
    let mut current = feet;
    for _ in 0..NEWTON_STEPS {
        let (qa, da) = walks[current[0].0].offset(current[0].1, d);
        let (qb, db) = walks[current[1].0].offset(current[1].1, d);
        let gap = qa - qb;
        if gap.norm() <= SEAM_CLOSURE * size {
            return (current, true);
        }
        // [da −db] (δa, δb) = −gap.
        let det = -da.cross(db);
        if det.abs() <= f64::EPSILON * da.norm() * db.norm() {
            break;
        }
        let step_a = -(gap.x * -db.y - -db.x * gap.y) / det;
        let step_b = -(da.x * gap.y - gap.x * da.y) / det;
        current[0].1 = moved(&walks[current[0].0], current[0].1, step_a);
        current[1].1 = moved(&walks[current[1].0], current[1].1, step_b);
    }
    (feet, false)
}

/// A foot moved by `step` in its variable. A foot leaving its segment goes on to the next one
/// past a smooth joint, or into the fan of a reflex corner; one leaving a fan goes on to the
/// segment on that side (so a seam whose bracketing feet straddle a corner is still found).
fn moved(walk: &Walk<'_>, foot: Foot, step: f64) -> Foot {
    let n = walk.profile.segments().len();
    match foot {
        Foot::OnSegment { segment, u } => {
            let (lo, hi) = (segment as f64, segment as f64 + 1.0);
            let v = u + step;
            if (lo..=hi).contains(&v) {
                return Foot::OnSegment { segment, u: v };
            }
            let joint = if v < lo { lo } else { hi };
            let at = joint.rem_euclid(walk.period);
            if walk.reflex_corner_at(at).is_some() {
                return Foot::Fan {
                    u: at,
                    angle: walk.normal(segment, joint).angle(),
                };
            }
            if walk
                .joint_at(at)
                .is_some_and(|j| j.kind == curve::JointKind::Smooth)
            {
                let next = if v < lo {
                    (segment + n - 1) % n
                } else {
                    (segment + 1) % n
                };
                let entry = if v < lo {
                    next as f64 + 1.0
                } else {
                    next as f64
                };
                return Foot::OnSegment {
                    segment: next,
                    u: entry,
                };
            }
            Foot::OnSegment {
                segment,
                u: v.clamp(lo, hi),
            }
        }
        Foot::Fan { u, angle } => {
            let angle = angle + step;
            let incoming = incoming_segment(walk, u);
            let outgoing = outgoing_segment(walk, u);
            let start = walk.normal(incoming, u).angle();
            let sweep = (start - walk.normal(outgoing, u).angle()).rem_euclid(TAU);
            let into = (start - angle).rem_euclid(TAU);
            if into <= sweep {
                return Foot::Fan { u, angle };
            }
            // (Past the fan: on the side it left by, the nearer of its two edges.)
            let beyond_end = into - sweep < 0.5 * (TAU - sweep);
            let segment = if beyond_end { outgoing } else { incoming };
            // (The segment starting at the corner meets it at its start, the other at its end.)
            let end = if segment == (u.round() as usize) % n {
                segment as f64
            } else {
                segment as f64 + 1.0
            };
            Foot::OnSegment { segment, u: end }
        }
    }
}
