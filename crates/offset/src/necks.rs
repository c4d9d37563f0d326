//! Necks between the axis's vertices: where the radius falls below the distance between two
//! vertices both above it, the offset pinches off there, though no seam is found. The axis
//! between two equal round bosses is straight, with vertices only at its ends; its radius is
//! least at the middle. A step whose radius falls from one end and rises to the other, and
//! whose ends are not far enough above the distance for the radius's slope (at most 1) to
//! keep it above, is sampled: points of it moved onto the axis bound the radius between them.

use crate::seams::{sided_feet, TOUCHING};
use crate::walk::Walk;
use curve::V2;
use medial::{Edge, MedialAxis};

/// Most points taken across a step to show its radius stays above the distance; a neck
/// nearer the distance than that resolves is taken as possible (the result not certified).
const MOST_SAMPLES: usize = 256;

/// Newton steps that put a point of the step on the axis (where the distances to both sides
/// agree): from a chord within the axis's chord tolerance, a few suffice.
const ONTO_AXIS_STEPS: usize = 8;

/// The distances to both sides agree to this, relative to the size, on the axis.
const ON_AXIS: f64 = 1e-12;

/// A foot within this of a joint (relative to the parameter's period) is at the joint.
const JOINT: f64 = 1e-12;

/// How much longer than its chord the axis between two neighbouring points on it may be
/// (an arc of a circle of radius `r` over a chord `r / 8` is 0.03 % longer): the radius,
/// 1-Lipschitz along the axis, is bounded between them by its values at both ends.
const ARC_OVER_CHORD: f64 = 1.001;

/// Whether the radius may fall to `d` between two vertices both above it, on any edge.
pub(crate) fn may_dip_between(axis: &MedialAxis, walks: &[Walk<'_>], d: f64, size: f64) -> bool {
    let floor = d + TOUCHING * size;
    axis.edges.iter().any(|edge| {
        (1..edge.xy.len()).any(|k| {
            let (r0, r1) = (edge.radius[k - 1], edge.radius[k]);
            if !(r0 > floor && r1 > floor) {
                return false;
            }
            let (x0, x1) = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
            // (1-Lipschitz along the chord: no point of it is nearer the boundary.)
            let step = x1 - x0;
            if (r0 + r1 - step.norm()) * 0.5 > floor {
                return false;
            }
            // A neck falls at one end of the step and rises at the other: the radius's slope
            // along the step at each end is the step's direction on the way from the foot.
            let slope = |j: usize, x: V2| {
                let b = edge.boundary[j][0];
                walks
                    .get(b)
                    .map_or(0.0, |w| step.dot(x - w.point(edge.feet[j][0])))
            };
            if slope(k - 1, x0) > 0.0 || slope(k, x1) < 0.0 {
                return false;
            }
            !stays_above(edge, k, walks, floor, size)
        })
    })
}

/// Whether the radius stays above `floor` on the axis between vertices `k − 1` and `k` of
/// `edge`: at points along the step, each moved onto the axis (where the distances to the
/// two sides, from Newton's method on each side's foot, agree), the radius bounded between
/// neighbours by its values there (it is 1-Lipschitz), with points added until the bound
/// holds or [`MOST_SAMPLES`] do not show it.
fn stays_above(edge: &Edge, k: usize, walks: &[Walk<'_>], floor: f64, size: f64) -> bool {
    let (x0, x1) = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
    let step = x1 - x0;
    let (Some(before), Some(after)) = (
        sided_feet(edge, k - 1, step, walks),
        sided_feet(edge, k, step, walks),
    ) else {
        return false;
    };
    if before[0].0 != after[0].0 || before[1].0 != after[1].0 {
        return false;
    }
    let mut samples = 4;
    while samples <= MOST_SAMPLES {
        let mut last = (x0, edge.radius[k - 1]);
        let mut holds = true;
        for i in 1..=samples {
            let t = i as f64 / samples as f64;
            let here = if i == samples {
                Some((x1, edge.radius[k]))
            } else {
                onto_axis(walks, before, after, x0 + step * t, step, t, size)
            };
            let Some(here) = here else {
                return false;
            };
            let apart = (here.0 - last.0).norm() * ARC_OVER_CHORD;
            if (last.1 + here.1 - apart) * 0.5 <= floor {
                holds = false;
                break;
            }
            last = here;
        }
        if holds {
            return true;
        }
        samples *= 2;
    }
    false
}

/// The point of the axis near `x` (a point of the step, `t` of the way), moved across the
/// step until the distances to both sides agree, and its radius; `None` where Newton's
/// method does not get there.
fn onto_axis(
    walks: &[Walk<'_>],
    before: [(usize, f64); 2],
    after: [(usize, f64); 2],
    mut x: V2,
    step: V2,
    t: f64,
    size: f64,
) -> Option<(V2, f64)> {
    let across = V2::new(-step.y, step.x).unit();
    let mut feet = [0, 1].map(|side| {
        let walk = &walks[before[side].0];
        let (u0, u1) = (before[side].1, after[side].1);
        // (The short way round a closed boundary.)
        let span = (u1 - u0 + 0.5 * walk.period).rem_euclid(walk.period) - 0.5 * walk.period;
        (u0 + span * t).rem_euclid(walk.period)
    });
    for _ in 0..ONTO_AXIS_STEPS {
        let near = [0, 1].map(|side| local_nearest(&walks[before[side].0], x, feet[side]));
        feet = [near[0].u, near[1].u];
        let gap = near[0].distance - near[1].distance;
        if gap.abs() <= ON_AXIS * size {
            return Some((x, near[0].distance.min(near[1].distance)));
        }
        // The gradient of each distance is the unit vector from its foot.
        let from_foot = |side: usize| {
            let foot = walks[before[side].0].point(feet[side]);
            (x - foot) * (1.0 / near[side].distance)
        };
        let slope = across.dot(from_foot(0) - from_foot(1));
        if slope.is_nan() || slope.abs() <= f64::EPSILON {
            return None;
        }
        x = x - across * (gap / slope);
    }
    None
}

/// The nearest point of `walk`'s boundary to `x` near the parameter `u`, by Newton's method
/// on its segment; a foot that ends at a segment's end is sought on the neighbouring segment
/// too (past a smooth joint it goes on there), the nearer kept.
fn local_nearest(walk: &Walk<'_>, x: V2, u: f64) -> curve::Nearest {
    let found = walk.profile.nearest_near(x.arr(), u);
    let joint = found.u.round();
    if (found.u - joint).abs() > JOINT * walk.period {
        return found;
    }
    [joint - JOINT, joint + JOINT]
        .map(|v| {
            walk.profile
                .nearest_near(x.arr(), v.rem_euclid(walk.period))
        })
        .into_iter()
        .fold(found, |a, b| if b.distance < a.distance { b } else { a })
}
