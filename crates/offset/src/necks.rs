//! Necks and bumps between the axis's vertices. Where the radius falls below the distance
//! between two vertices both above it (a neck), the offset pinches off there, though no seam
//! is found between vertices; where it rises above the distance between two vertices both
//! below it (a bump), a small loop of the offset stands there. The axis between two equal
//! round bosses is straight, with vertices only at its ends; its radius is least at the
//! middle.
//!
//! The radius's slope along the axis at a point is the axis's direction (across the chord
//! between its two feet) on the way from either foot. A step whose radius falls at one end
//! and rises at the other (a neck) or the other way round (a bump), and whose ends are not far
//! enough from the distance for the radius's slope (at most 1) to keep it on their side, has
//! its extremum found: by bisection on the slope's sign at points of the step moved onto the
//! axis, each of whose radius is compared with the distance as it goes. The slopes at the
//! ends are taken to mean one extremum between them: the axis's vertices lie a chord
//! tolerance apart, and between them its feet run along a small stretch of each side.

use crate::walk::{sided_feet, Walk};
use curve::V2;
use geometry::NearestPoint;
use medial::Edge;
use numeric::rounding::ulps;

/// An axis point keeps its boundary points at the distance only when its radius exceeds the
/// distance by this much, relative to the region's size: where they are within it, the region
/// left at the distance is narrower there than the axis's own accuracy (1e-9 of the size), a
/// point where two parts of the offset touch, and it is taken as closed.
pub(crate) const TOUCHING: f64 = 1e-9;

/// Halvings of the share of a step that find its radius's extremum: to 2^-40 of the step,
/// where the radius (1-Lipschitz) is within rounding of its value at the last point taken.
const EXTREMUM_HALVINGS: usize = 40;

/// Newton steps that put a point of the step on the axis (where the distances to both sides
/// agree): from a chord within the axis's chord tolerance, a few suffice.
const ONTO_AXIS_STEPS: usize = 8;

/// The distances to both sides agree to this, relative to the size, on the axis.
const ON_AXIS: f64 = 1e-12;

/// A foot within this of a joint (relative to the parameter's period) is at the joint.
const JOINT: f64 = 1e-12;

/// How much longer than its chord the axis between two vertices may be (an arc of a circle
/// of radius `r` over a chord `r / 8` is 0.03 % longer): the radius, 1-Lipschitz along the
/// axis, is bounded between them by its values at both ends.
const ARC_OVER_CHORD: f64 = 1.001;

/// What the radius does between two vertices of an edge on one side of the distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Between {
    /// It stays on their side.
    Clear,
    /// It crosses to the other side at this share of the step (a point of the axis moved
    /// across it): below, the offset pinches off there (a neck); above, a small loop of the
    /// offset stands there (a bump). Either way, at two seams either side.
    Crosses(f64),
    /// It falls to within [`TOUCHING`] of the distance at this point of the axis, and no
    /// lower (a neck that only touches it): the offset touches itself there, taken as closed.
    Touches(AxisPoint),
    /// A point of the step was not moved onto the axis.
    Unknown,
}

/// What the radius does between vertices `k − 1` and `k` of `edge` when both are on one side
/// of `d` (else [`Between::Clear`]: the crossing there is a seam of its own). A vertex within
/// [`TOUCHING`] of `d` counts as below it.
pub(crate) fn between(edge: &Edge, k: usize, walks: &[Walk<'_>], d: f64, size: f64) -> Between {
    let floor = d + TOUCHING * size;
    let (r0, r1) = (edge.radius[k - 1], edge.radius[k]);
    let above = r0 > floor;
    if above != (r1 > floor) {
        return Between::Clear;
    }
    let (x0, x1) = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
    let step = x1 - x0;
    // (1-Lipschitz along the axis: no point of it is nearer the boundary, or farther.)
    let (middle, reach) = (0.5 * (r0 + r1), 0.5 * step.norm() * ARC_OVER_CHORD);
    if (above && middle - reach > floor) || (!above && middle + reach <= floor) {
        return Between::Clear;
    }
    let foot = |j: usize, side: usize| {
        walks
            .get(edge.boundary[j][side])
            .map(|w| w.point(edge.feet[j][side]))
    };
    let slope_at = |j: usize, x: V2| match (foot(j, 0), foot(j, 1)) {
        (Some(f0), Some(f1)) => slope(x, f0, f1, step),
        _ => 0.0,
    };
    let (s0, s1) = (slope_at(k - 1, x0), slope_at(k, x1));
    // (A bump rises strictly from both ends: where the feet meet, at a corner or a centre
    // of curvature, the radius has no slope, and no bump stands beside it.)
    let (falls_first, rises_last) = (s0 <= 0.0, s1 >= 0.0);
    let extremum_inside = if above {
        falls_first && rises_last
    } else {
        !falls_first && !rises_last
    };
    if !extremum_inside {
        return Between::Clear;
    }
    extremum(edge, k, walks, d, size, above)
}

/// The radius's slope along the axis at `x`, whose feet are `f0` and `f1`, going the way of
/// `step`, times the radius.
fn slope(x: V2, f0: V2, f1: V2, step: V2) -> f64 {
    let between_feet = f1 - f0;
    let mut along = V2::new(-between_feet.y, between_feet.x);
    if along.dot(step) < 0.0 {
        along = along * -1.0;
    }
    along.dot(x - f0)
}

/// The extremum of the radius on step `k` of `edge` (a least one if its ends are `above`
/// `d` and its [`TOUCHING`] band, else a greatest one): the share of the step is halved
/// toward where the slope of points moved onto the axis changes sign, and a point on the
/// other side of the band than the ends shows a crossing there; if none does by the
/// extremum, the radius stays on their side, or (a least one) touches `d`, where a point fell
/// into the band.
fn extremum(edge: &Edge, k: usize, walks: &[Walk<'_>], d: f64, size: f64, above: bool) -> Between {
    let Some(feet) = step_feet(edge, k, walks) else {
        return Between::Unknown;
    };
    let (floor, below_band) = (d + TOUCHING * size, d - TOUCHING * size);
    let step = V2::from_arr(edge.xy[k]) - V2::from_arr(edge.xy[k - 1]);
    let (mut before, mut after) = (0.0, 1.0);
    let mut touches = None;
    for _ in 0..EXTREMUM_HALVINGS {
        let t = 0.5 * (before + after);
        let Some(here) = onto_axis(edge, k, walks, &feet, t, size) else {
            return Between::Unknown;
        };
        let across = if above {
            here.radius < below_band
        } else {
            here.radius > floor
        };
        if across {
            return Between::Crosses(t);
        }
        // (A least radius within the band: halved on to the extremum, where it may still
        // fall through the band; the least point found is the touching point.)
        if above && here.radius <= floor {
            let lower = touches.is_none_or(|p: AxisPoint| here.radius < p.radius);
            if lower {
                touches = Some(here);
            }
        }
        let [f0, f1] = [0, 1].map(|side| walks[feet[0][side].0].point(here.feet[side]));
        // (Before a least radius it falls; before a greatest one it rises.)
        if (slope(here.x, f0, f1, step) > 0.0) != above {
            before = t;
        } else {
            after = t;
        }
    }
    touches.map_or(Between::Clear, Between::Touches)
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

/// A point of the axis: where, its radius, and its feet's parameters per side.
#[derive(Debug, Clone, Copy, PartialEq)]
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
        if slope.is_nan() || slope.abs() <= ulps(1.0) {
            return None;
        }
        x = x - across * (gap / slope);
    }
    None
}

/// The nearest point of `walk`'s boundary to `x` near the parameter `u`, by Newton's method
/// on its segment; a foot that ends at a segment's end is sought on the neighbouring segment
/// too (past a smooth joint it goes on there), the nearer kept. A foot left within [`JOINT`]
/// of a joint is the joint, exactly: a parameter a rounding short of a closed boundary's
/// period (`1 - 1e-12` for `0`) would be walked to the long way round, and would not be
/// known for a reflex corner's.
pub(crate) fn local_nearest(walk: &Walk<'_>, x: V2, u: f64) -> geometry::Foot {
    let found = walk.profile.nearest_near(x.arr(), u);
    let joint = found.u.round();
    if (found.u - joint).abs() > JOINT * walk.period {
        return found;
    }
    let mut nearest = [joint - JOINT, joint + JOINT]
        .map(|v| {
            walk.profile
                .nearest_near(x.arr(), v.rem_euclid(walk.period))
        })
        .into_iter()
        .fold(found, |a, b| if b.distance < a.distance { b } else { a });
    let joint = nearest.u.round();
    if (nearest.u - joint).abs() <= 2.0 * JOINT * walk.period {
        nearest.u = joint.rem_euclid(walk.period);
    }
    nearest
}
