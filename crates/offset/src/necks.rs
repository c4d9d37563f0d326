//! Necks between the axis's vertices: where the radius falls below the distance between two
//! vertices both above it, the offset pinches off there, though no seam is found. The axis
//! between two equal round bosses is straight, with vertices only at its ends; its radius is
//! least at the middle. A step whose radius falls from one end and rises to the other, and
//! whose ends are not far enough above the distance for the radius's slope (at most 1) to
//! keep it above, is sampled: points of it moved onto the axis bound the radius between them.

use crate::seams::{sided_feet, TOUCHING};
use crate::walk::Walk;
use curve::V2;
use medial::Edge;

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

/// What the radius does between two vertices of an edge, both above the distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Between {
    /// It stays above.
    Above,
    /// It falls below at this share of the step (a point of the axis moved across it): the
    /// offset pinches off there, at two seams either side.
    Dips(f64),
    /// Neither is shown with [`MOST_SAMPLES`] points.
    Unknown,
}

/// What the radius does between vertices `k − 1` and `k` of `edge` when both are above `d`.
/// Otherwise [`Between::Above`], meaning nothing is looked for: where the vertices are on
/// either side, the crossing is a seam of its own; where both are below, a bump above `d`
/// between them is not looked for (a known gap, not yet handled).
pub(crate) fn between(edge: &Edge, k: usize, walks: &[Walk<'_>], d: f64, size: f64) -> Between {
    let floor = d + TOUCHING * size;
    let (r0, r1) = (edge.radius[k - 1], edge.radius[k]);
    if !(r0 > floor && r1 > floor) {
        return Between::Above;
    }
    let (x0, x1) = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
    // (1-Lipschitz along the chord: no point of it is nearer the boundary.)
    let step = x1 - x0;
    if (r0 + r1 - step.norm()) * 0.5 > floor {
        return Between::Above;
    }
    // A neck falls at one end of the step and rises at the other. The radius's slope along
    // the axis at a vertex is the axis's direction (across the chord between the two feet,
    // the way the step goes) on the way from either foot; along the chord of a curved axis
    // it would differ from one foot to the other.
    let slope = |j: usize, x: V2| {
        let foot = |side: usize| {
            walks
                .get(edge.boundary[j][side])
                .map(|w| w.point(edge.feet[j][side]))
        };
        let (Some(f0), Some(f1)) = (foot(0), foot(1)) else {
            return 0.0;
        };
        let between_feet = f1 - f0;
        let mut along = V2::new(-between_feet.y, between_feet.x);
        if along.dot(step) < 0.0 {
            along = along * -1.0;
        }
        along.dot(x - f0)
    };
    if slope(k - 1, x0) > 0.0 || slope(k, x1) < 0.0 {
        return Between::Above;
    }
    sampled(edge, k, walks, floor, size)
}

/// The feet of a step's ends on each side (left first), on one boundary per side; `None`
/// where a side's feet are on two boundaries.
pub(crate) fn step_feet(edge: &Edge, k: usize, walks: &[Walk<'_>]) -> Option<StepFeet> {
    let step = V2::from_arr(edge.xy[k]) - V2::from_arr(edge.xy[k - 1]);
    let before = sided_feet(edge, k - 1, step, walks)?;
    let after = sided_feet(edge, k, step, walks)?;
    (before[0].0 == after[0].0 && before[1].0 == after[1].0).then_some([before, after])
}

/// Per end of a step, per side: the boundary and the foot's parameter.
pub(crate) type StepFeet = [[(usize, f64); 2]; 2];

/// Points along the step moved onto the axis (where the distances to the two sides, from
/// Newton's method on each side's foot, agree): a point below `floor` shows a dip; the
/// radius bounded between neighbours by its values there (it is 1-Lipschitz) shows it stays
/// above; points are added (twice as many each time, the earlier kept) until one of them is
/// shown or [`MOST_SAMPLES`] show neither.
fn sampled(edge: &Edge, k: usize, walks: &[Walk<'_>], floor: f64, size: f64) -> Between {
    let Some(feet) = step_feet(edge, k, walks) else {
        return Between::Unknown;
    };
    // The points of the axis at shares 0, 1/n, …, 1 of the step; doubling n keeps them and
    // fills in the odd ones.
    let mut points = vec![
        (V2::from_arr(edge.xy[k - 1]), edge.radius[k - 1]),
        (V2::from_arr(edge.xy[k]), edge.radius[k]),
    ];
    while points.len() <= MOST_SAMPLES {
        let n = 2 * (points.len() - 1);
        let mut finer = Vec::with_capacity(n + 1);
        for (i, &p) in points.iter().enumerate() {
            if i > 0 {
                let t = (2 * i - 1) as f64 / n as f64;
                let Some(here) = onto_axis(edge, k, walks, &feet, t, size) else {
                    return Between::Unknown;
                };
                if here.radius < floor {
                    return Between::Dips(t);
                }
                finer.push((here.x, here.radius));
            }
            finer.push(p);
        }
        points = finer;
        let holds = points.windows(2).all(|w| {
            let apart = (w[1].0 - w[0].0).norm() * ARC_OVER_CHORD;
            (w[0].1 + w[1].1 - apart) * 0.5 > floor
        });
        if holds {
            return Between::Above;
        }
    }
    Between::Unknown
}

/// A point of the axis: where, its radius, and its feet's parameters per side.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AxisPoint {
    pub(crate) x: V2,
    pub(crate) radius: f64,
    pub(crate) feet: [f64; 2],
}

/// The point of the axis near the point `t` of the way along step `k` of `edge`, moved
/// across the step until the distances to both sides agree; `None` where Newton's method
/// does not get there.
pub(crate) fn onto_axis(
    edge: &Edge,
    k: usize,
    walks: &[Walk<'_>],
    [before, after]: &StepFeet,
    t: f64,
    size: f64,
) -> Option<AxisPoint> {
    let (x0, x1) = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
    let step = x1 - x0;
    let mut x = x0 + step * t;
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
            return Some(AxisPoint {
                x,
                radius: near[0].distance.min(near[1].distance),
                feet,
            });
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
