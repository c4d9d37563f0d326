//! The seams of an offset: the points of the medial axis whose radius is the distance. There
//! the offsets of the two sides of the axis meet, and each side's kept stretch of boundary
//! begins or ends.

use crate::necks::{self, Between, TOUCHING};
use crate::walk::{incoming_segment, outgoing_segment, sided_feet, OffsetSource, Walk};
use curve::V2;
use medial::{Edge, MedialAxis};
use numeric::newton2::{newton2, Matrix2, Newton2, Outcome, StepVerdict, Vector2};
use numeric::rounding::ulps;
use std::f64::consts::TAU;

/// Newton steps for a seam's feet: each doubles the digits; more means a degenerate seam
/// (the axis grazing the distance), which keeps its interpolated feet.
const SEAM_NEWTON_STEPS: usize = 30;

/// A seam's two offset points agree to this, relative to the region's size: a few roundings
/// of the coordinates.
const SEAM_CLOSURE: f64 = 1e-13;

/// The shares of a step between two vertices from which Newton's method starts again when it
/// left the step from the radius's linear share.
const RESTARTS: [f64; 6] = [0.5, 0.25, 0.75, 0.1, 0.9, 0.02];

/// A foot's parameter within its vertices' feet beyond the span between them, relative to
/// the boundary's period: rounding.
const BRACKET_ROUNDING: f64 = 1e-9;

/// Where the offset at one distance meets itself across the axis.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Seam {
    /// Per side of the axis: the boundary and the foot.
    pub(crate) feet: [(usize, OffsetSource); 2],
    /// Per side: whether the stretch of boundary kept on that side begins at the foot (else it
    /// ends there), in the direction the boundary is walked.
    pub(crate) begins: [bool; 2],
    /// Whether Newton's method closed the seam (else its feet are interpolated).
    pub(crate) refined: bool,
}

/// The seams of the offset at distance `d` and whether every step of the axis was resolved:
/// seams where an edge's radius crosses `d` between two vertices (a vertex within
/// [`TOUCHING`] of `d` counts as below it), and either side of a dip below `d` between two
/// vertices above it (a neck) or of a rise above `d` between two vertices below it (a bump);
/// a step whose extremum was not found on the axis is unresolved. `None` where a crossing
/// gave no seam (its feet on two boundaries, or on none), so the loops cannot be trusted.
pub(crate) fn seams(
    axis: &MedialAxis,
    walks: &[Walk<'_>],
    d: f64,
    size: f64,
) -> Option<(Vec<Seam>, bool)> {
    let above = |r: f64| r > d + TOUCHING * size;
    let mut found = Vec::new();
    let mut resolved = true;
    for edge in &axis.edges {
        for k in 1..edge.xy.len() {
            let (r0, r1) = (edge.radius[k - 1], edge.radius[k]);
            if above(r0) != above(r1) {
                found.push(seam_between(edge, k, walks, d, size)?);
                continue;
            }
            match necks::between(edge, k, walks, d, size) {
                Between::Clear => {}
                Between::Crosses(t) => {
                    found.extend(crossing_seams(edge, k, walks, d, size, t, above(r0))?)
                }
                Between::Touches(point) => {
                    found.extend(touching_seams(edge, k, walks, point, d, size)?)
                }
                Between::Unknown => resolved = false,
            }
        }
    }
    Some((found, resolved))
}

/// The seam on `edge` between vertices `k − 1` and `k`.
fn seam_between(edge: &Edge, k: usize, walks: &[Walk<'_>], d: f64, size: f64) -> Option<Seam> {
    let (r0, r1) = (edge.radius[k - 1], edge.radius[k]);
    let share = ((d - r0) / (r1 - r0)).clamp(0.0, 1.0);
    let (x0, x1) = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
    let toward_wider = if r1 > r0 { x1 - x0 } else { x0 - x1 };
    let step = x1 - x0;
    let [before, after] = [k - 1, k].map(|j| sided_feet(edge, j, step, walks));
    let (before, after) = (before?, after?);
    let boundary_of = |side: usize| (before[side].0 == after[side].0).then_some(before[side].0);
    let boundaries = [boundary_of(0)?, boundary_of(1)?];
    let feet_at = |share: f64| -> Option<[(usize, OffsetSource); 2]> {
        let guess = x0 + (x1 - x0) * share;
        let foot = |side: usize| -> Option<(usize, OffsetSource)> {
            let b = boundaries[side];
            let walk = walks.get(b)?;
            Some((
                b,
                foot_between(walk, before[side].1, after[side].1, share, guess),
            ))
        };
        Some([foot(0)?, foot(1)?])
    };
    if let Some(leaf) = leaf_seam(edge, k, walks, d, size, [before, after], toward_wider) {
        return Some(Seam {
            feet: feet_at(leaf.0)?,
            begins: leaf.1,
            refined: true,
        });
    }
    // A vertex where the radius is least, within TOUCHING of `d`: the offset touches itself
    // there, taken as closed (see `touching_feet`).
    let end = usize::from(r1 <= r0);
    if let Some(feet) = touching_vertex(edge, k - 1 + end, walks, d, size) {
        return Some(seam_of(walks, feet, true, toward_wider, d, size));
    }
    // Newton's method from the radius's linear share of the step; near a dip of the radius
    // the two offsets run nearly parallel, the equations are nearly singular, and a first
    // step may leap to the seam on the dip's far side: a solution with a foot outside its
    // vertices' feet is that one, and Newton's method starts again from other shares.
    let bracketed = |found: &[(usize, OffsetSource); 2]| {
        (0..2).all(|side| {
            foot_within(
                &walks[boundaries[side]],
                (before[side].1, after[side].1),
                (x0, x1),
                found[side].1,
            )
        })
    };
    let interpolated = feet_at(share)?;
    let mut solved = None;
    for start in std::iter::once(share).chain(RESTARTS) {
        let (found, closed) = refine(walks, feet_at(start)?, d, size);
        if closed && bracketed(&found) {
            solved = Some(found);
            break;
        }
    }
    let (refined_feet, refined) = match solved {
        Some(found) => (found, true),
        None => (interpolated, false),
    };
    Some(seam_of(walks, refined_feet, refined, toward_wider, d, size))
}

/// The two seams either side of share `t` of step `k` of `edge`, where the radius is on the
/// other side of `d` than at both vertices (`above` it or not: a neck, or a bump): where the
/// radius of points moved onto the axis crosses `d`, by bisection on the share, each closed
/// by Newton's method within its part of the step.
fn crossing_seams(
    edge: &Edge,
    k: usize,
    walks: &[Walk<'_>],
    d: f64,
    size: f64,
    t: f64,
    above: bool,
) -> Option<[Seam; 2]> {
    let feet = necks::step_feet(edge, k, walks)?;
    let floor = d + TOUCHING * size;
    let at = |share: f64| necks::onto_axis(edge, k, walks, &feet, share, size);
    let step = V2::from_arr(edge.xy[k]) - V2::from_arr(edge.xy[k - 1]);
    // (From each vertex to the share across.)
    let seam = |vertex_share: f64, toward_wider: V2| -> Option<Seam> {
        let (mut near, mut across) = (vertex_share, t);
        for _ in 0..CROSSING_HALVINGS {
            let middle = 0.5 * (near + across);
            if (at(middle)?.radius > floor) == above {
                near = middle;
            } else {
                across = middle;
            }
        }
        let point = at(if above { across } else { near })?;
        let [before, after] = feet;
        let start = [0, 1].map(|side| {
            let b = before[side].0;
            let u = point.feet[side];
            (b, foot_between(&walks[b], u, u, 0.0, point.x))
        });
        let (found, closed) = refine(walks, start, d, size);
        let ends = (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k]));
        let inside = (0..2).all(|side| {
            foot_within(
                &walks[before[side].0],
                (before[side].1, after[side].1),
                ends,
                found[side].1,
            )
        });
        let refined = closed && inside;
        Some(seam_of(
            walks,
            if refined { found } else { start },
            refined,
            toward_wider,
            d,
            size,
        ))
    };
    // (The radius widens toward the vertices from a neck, toward the middle of a bump.)
    let outward = if above { -1.0 } else { 1.0 };
    Some([seam(0.0, step * outward)?, seam(1.0, step * -outward)?])
}

/// The feet of the seam at vertex `j` of `edge` where the radius is least there (its
/// neighbours both above the distance, so not at an end of the edge) and within [`TOUCHING`]
/// of `d`: see [`touching_feet`], from the vertex's own feet, within its neighbours'.
fn touching_vertex(
    edge: &Edge,
    j: usize,
    walks: &[Walk<'_>],
    d: f64,
    size: f64,
) -> Option<[(usize, OffsetSource); 2]> {
    let above = |r: f64| r > d + TOUCHING * size;
    let least = j > 0
        && j + 1 < edge.xy.len()
        && above(edge.radius[j - 1])
        && above(edge.radius[j + 1])
        && (edge.radius[j] - d).abs() <= TOUCHING * size;
    if !least {
        return None;
    }
    // (Sided by the way from one neighbour to the other: the same for both steps.)
    let across = V2::from_arr(edge.xy[j + 1]) - V2::from_arr(edge.xy[j - 1]);
    let [before, here, after] = [j - 1, j, j + 1].map(|i| sided_feet(edge, i, across, walks));
    let (before, here, after) = (before?, here?, after?);
    if (0..2).any(|side| before[side].0 != here[side].0 || after[side].0 != here[side].0) {
        return None;
    }
    let x = V2::from_arr(edge.xy[j]);
    let bracket = Bracket {
        feet: [0, 1].map(|side| (before[side].1, after[side].1)),
        ends: (V2::from_arr(edge.xy[j - 1]), V2::from_arr(edge.xy[j + 1])),
    };
    Some(touching_feet(walks, here, x, &bracket, d, size))
}

/// The feet of a seam where the offset touches itself (the axis's radius least there, within
/// [`TOUCHING`] of `d`: a passage taken as closed), from the feet `start` (per side, the
/// boundary and the parameter) of the axis point `x`: one seam for both of the kept stretches
/// that end and begin there on each side, so that they are at one place on each boundary,
/// where a stretch ending is put before one beginning. (Two seams solved apart, one either
/// side, meet the double root of two tangent offsets, where Newton's method stops anywhere
/// within about the square root of SEAM_CLOSURE of the size from the touching point, either
/// side: they fell in either order along a boundary, and the loops joined the wrong stretches,
/// an arc the long way round a hole, a chord across the region.) Newton's method closes the
/// seam where the offsets meet within the `bracket` of the axis; where they do not
/// (a radius a little above `d`), the feet stay those of `x`, whose offsets are on the normals
/// through it, 2 |r - d| apart, within twice TOUCHING of the size: the loop turns back there,
/// and the horn's cut closes it.
fn touching_feet(
    walks: &[Walk<'_>],
    start: [(usize, f64); 2],
    x: V2,
    bracket: &Bracket,
    d: f64,
    size: f64,
) -> [(usize, OffsetSource); 2] {
    let feet = start.map(|(b, u)| (b, foot_between(&walks[b], u, u, 0.0, x)));
    let (found, closed) = refine(walks, feet, d, size);
    let inside = (0..2).all(|side| {
        let walk = &walks[feet[side].0];
        foot_within(walk, bracket.feet[side], bracket.ends, found[side].1)
    });
    if closed && inside {
        found
    } else {
        feet
    }
}

/// The two seams where the radius between vertices `k - 1` and `k` of `edge`, both above the
/// distance, falls to within [`TOUCHING`] of it at `point` (a neck that only touches): the
/// offset touches itself there, taken as closed, and both seams have the feet
/// [`touching_feet`] finds from that point's, the kept stretches widening toward either
/// vertex. (Bisection to where the radius crosses `d + TOUCHING` and Newton's method from
/// there, as for a neck, would meet the double root of two tangent offsets either side.)
fn touching_seams(
    edge: &Edge,
    k: usize,
    walks: &[Walk<'_>],
    point: necks::AxisPoint,
    d: f64,
    size: f64,
) -> Option<[Seam; 2]> {
    let [before, after] = necks::step_feet(edge, k, walks)?;
    let start = [0, 1].map(|side| (before[side].0, point.feet[side]));
    let bracket = Bracket {
        feet: [0, 1].map(|side| (before[side].1, after[side].1)),
        ends: (V2::from_arr(edge.xy[k - 1]), V2::from_arr(edge.xy[k])),
    };
    let feet = touching_feet(walks, start, point.x, &bracket, d, size);
    let step = V2::from_arr(edge.xy[k]) - V2::from_arr(edge.xy[k - 1]);
    Some([step * -1.0, step].map(|toward_wider| seam_of(walks, feet, true, toward_wider, d, size)))
}

/// A seam at an end of step `k` of `edge` that is a leaf of the axis (a centre of curvature,
/// both feet at one point) whose radius is `d` (within [`TOUCHING`]): the offset's swallowtail
/// shrinks to a point there, and so does the seam, both its feet at the leaf's one foot
/// (Newton's method would refuse it as the trivial solution of a seam's equations). The share
/// of the step it is at, and per side whether the kept stretch begins there: as it does at
/// the other end of the step, where the feet are apart.
fn leaf_seam(
    edge: &Edge,
    k: usize,
    walks: &[Walk<'_>],
    d: f64,
    size: f64,
    sided: [[(usize, f64); 2]; 2],
    toward_wider: V2,
) -> Option<(f64, [bool; 2])> {
    let at_leaf = |end: usize| {
        let [(b0, u0), (b1, u1)] = sided[end];
        let (Some(w0), Some(w1)) = (walks.get(b0), walks.get(b1)) else {
            return false;
        };
        (edge.radius[k - 1 + end] - d).abs() <= TOUCHING * size
            && b0 == b1
            && (w0.point(u0) - w1.point(u1)).norm() <= SEAM_CLOSURE * size
    };
    let end = (0..2).find(|&end| at_leaf(end))?;
    let other = 1 - end;
    let x = V2::from_arr(edge.xy[k - 1 + other]);
    let begins = sided[other].map(|(b, u)| begins_at(x, walks[b].point(u), toward_wider));
    Some((end as f64, begins))
}

/// Whether the stretch of boundary kept beside a seam at `x` begins at its foot `foot` (else
/// it ends there), the radius widening `toward_wider` along the axis.
fn begins_at(x: V2, foot: V2, toward_wider: V2) -> bool {
    let normal = (x - foot).unit();
    // (The walk's tangent has the region, and so the normal, on its left.)
    let tangent = V2::new(normal.y, -normal.x);
    toward_wider.dot(tangent) > 0.0
}

/// Bisections of the share of a step that find where the radius crosses the distance
/// either side of a neck or a bump: to 2^-24 of the step, within reach of Newton's method.
const CROSSING_HALVINGS: usize = 24;

/// The seam with these feet (`refined`: closed by Newton's method), the kept stretch on each
/// side beginning or ending there as the radius widens `toward_wider` along the axis.
fn seam_of(
    walks: &[Walk<'_>],
    feet: [(usize, OffsetSource); 2],
    mut refined: bool,
    toward_wider: V2,
    d: f64,
    size: f64,
) -> Seam {
    // (Both feet at one point of one boundary solve the equations trivially: no seam.)
    if feet[0].0 == feet[1].0 {
        let walk = &walks[feet[0].0];
        let gap = foot_point(walk, feet[0].1) - foot_point(walk, feet[1].1);
        refined &= gap.norm() > SEAM_CLOSURE * size;
    }
    let point = walks[feet[0].0].offset(feet[0].1, d).0;
    let begins = feet.map(|(b, foot)| begins_at(point, foot_point(&walks[b], foot), toward_wider));
    Seam {
        feet,
        begins,
        refined,
    }
}

/// The foot between two vertices' feet `u0`, `u1` at `share` of the way: the fan of a reflex
/// corner both feet sit on, else a point of the segment the way between them crosses.
fn foot_between(walk: &Walk<'_>, u0: f64, u1: f64, share: f64, guess: V2) -> OffsetSource {
    let period = walk.period;
    // (The short way round a closed boundary.)
    let step = (u1 - u0 + 0.5 * period).rem_euclid(period) - 0.5 * period;
    if let (Some(c0), Some(c1)) = (walk.reflex_corner_at(u0), walk.reflex_corner_at(u1)) {
        if c0 == c1 {
            let c = walk.point(c0);
            return OffsetSource::Fan {
                u: c0,
                angle: (guess - c).angle(),
            };
        }
    }
    let u = (u0 + step * share).rem_euclid(period);
    let middle = (u0 + 0.5 * step).rem_euclid(period);
    let segment = walk.profile.locate(middle).0;
    OffsetSource::OnSegment {
        segment,
        u: u.clamp(segment as f64, segment as f64 + 1.0),
    }
}

/// Whether the boundary parameter `u` lies between `u0` and `u1`, the short way round the
/// boundary (within rounding).
fn within(walk: &Walk<'_>, u0: f64, u1: f64, u: f64) -> bool {
    let period = walk.period;
    let short = |v: f64| (v - u0 + 0.5 * period).rem_euclid(period) - 0.5 * period;
    let (span, at) = (short(u1), short(u));
    let margin = BRACKET_ROUNDING * period;
    at >= span.min(0.0) - margin && at <= span.max(0.0) + margin
}

/// A stretch of the axis a seam is sought in: per side, the feet's parameters at its ends,
/// and the ends.
struct Bracket {
    feet: [(f64, f64); 2],
    ends: (V2, V2),
}

/// A fan's direction may lie outside the directions from its corner to a step's ends by this
/// share of the turn between them (and a rounding): a seam a little past the step is still
/// its own, while the seam Newton's method may leap to across a neck between two corners
/// (the other crossing of their two circles) is across the step's chord.
const FAN_MARGIN: f64 = 0.01;

/// Whether the foot `found` lies within a step of the axis from `x0` to `x1`, whose vertices'
/// feet on its side are `u0` and `u1`: its parameter between theirs ([`within`]), and where
/// all three are on one reflex corner's fan, its direction between the directions from the
/// corner to the step's ends. (By the parameter alone, a fan's foot is always within: both
/// seams either side of a neck between two corners, as between the two holes of a glyph
/// '8', were solved at one crossing of the corners' circles, and the loops joined wrongly.)
fn foot_within(
    walk: &Walk<'_>,
    (u0, u1): (f64, f64),
    (x0, x1): (V2, V2),
    found: OffsetSource,
) -> bool {
    let OffsetSource::Fan { u, angle } = found else {
        return within(walk, u0, u1, param(found));
    };
    let same = |v: f64| walk.reflex_corner_at(v).is_some_and(|c| c == u);
    if !(same(u0) && same(u1)) {
        return within(walk, u0, u1, u);
    }
    let c = walk.point(u);
    let from = (x0 - c).angle();
    let span = curve::wrap_pi((x1 - c).angle() - from);
    let at = curve::wrap_pi(angle - from);
    let margin = FAN_MARGIN * span.abs() + BRACKET_ROUNDING * TAU;
    at >= span.min(0.0) - margin && at <= span.max(0.0) + margin
}

/// A foot's boundary parameter (a corner's, for a fan).
fn param(foot: OffsetSource) -> f64 {
    match foot {
        OffsetSource::OnSegment { u, .. } | OffsetSource::Fan { u, .. } => u,
    }
}

/// The point a foot stands on.
pub(crate) fn foot_point(walk: &Walk<'_>, foot: OffsetSource) -> V2 {
    match foot {
        OffsetSource::OnSegment { segment, u } => walk.profile.jet_on(segment, u, 0).p,
        OffsetSource::Fan { u, .. } => walk.point(u),
    }
}

/// Newton's method on the two feet, so that their offset points coincide (numeric's
/// [`newton2`] on the gap between them, each foot moved its own way by [`moved`]).
fn refine(
    walks: &[Walk<'_>],
    feet: [(usize, OffsetSource); 2],
    d: f64,
    size: f64,
) -> ([(usize, OffsetSource); 2], bool) {
    // [da −db] (δa, δb) = gap, and the feet move by −δ.
    let linearize = |current: &[(usize, OffsetSource); 2]| {
        let (qa, da) = walks[current[0].0].offset(current[0].1, d);
        let (qb, db) = walks[current[1].0].offset(current[1].1, d);
        let gap = qa - qb;
        (
            Vector2::new(gap.x, gap.y),
            Matrix2::new(da.x, -db.x, da.y, -db.y),
        )
    };
    let advance = |current: &[(usize, OffsetSource); 2], step: Vector2<f64>| {
        let mut next = *current;
        next[0].1 = moved(&walks[current[0].0], current[0].1, -step[0]);
        next[1].1 = moved(&walks[current[1].0], current[1].1, -step[1]);
        next
    };
    let limits = Newton2 {
        residual: SEAM_CLOSURE * size,
        singular: ulps(1.0),
        ..Newton2::steps(SEAM_NEWTON_STEPS)
    };
    match newton2(feet, limits, linearize, advance, |_| StepVerdict::Continue) {
        Outcome::Converged(found) => (found, true),
        _ => (feet, false),
    }
}

/// A foot moved by `step` in its variable. A foot leaving its segment goes on to the next one
/// past a smooth joint, or into the fan of a reflex corner; one leaving a fan goes on to the
/// segment on that side (so a seam whose bracketing feet straddle a corner is still found).
fn moved(walk: &Walk<'_>, foot: OffsetSource, step: f64) -> OffsetSource {
    let n = walk.profile.segments().len();
    match foot {
        OffsetSource::OnSegment { segment, u } => {
            let (lo, hi) = (segment as f64, segment as f64 + 1.0);
            let v = u + step;
            if (lo..=hi).contains(&v) {
                return OffsetSource::OnSegment { segment, u: v };
            }
            let joint = if v < lo { lo } else { hi };
            let at = joint.rem_euclid(walk.period);
            if walk.reflex_corner_at(at).is_some() {
                return OffsetSource::Fan {
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
                return OffsetSource::OnSegment {
                    segment: next,
                    u: entry,
                };
            }
            OffsetSource::OnSegment {
                segment,
                u: v.clamp(lo, hi),
            }
        }
        OffsetSource::Fan { u, angle } => {
            let angle = angle + step;
            let incoming = incoming_segment(walk, u);
            let outgoing = outgoing_segment(walk, u);
            let start = walk.normal_leaving(incoming).angle();
            let sweep = (start - walk.normal_entering(outgoing).angle()).rem_euclid(TAU);
            let into = (start - angle).rem_euclid(TAU);
            if into <= sweep {
                return OffsetSource::Fan { u, angle };
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
            OffsetSource::OnSegment { segment, u: end }
        }
    }
}
