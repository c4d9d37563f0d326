//! A boundary of the region as the offsets walk it: with the side offset into on the left (the
//! region for inward offsets, so that the outer boundary runs counterclockwise and each hole
//! clockwise whatever their parameters do; the outside for outward ones).

use curve::{JointKind, ParamCurve, Profile, V2};
use medial::Edge;

/// One boundary, walked with the region on its left.
pub(crate) struct Walk<'r> {
    /// The boundary.
    pub(crate) profile: &'r Profile,
    /// `+1` when the parameter runs with the region on its left, `−1` against it.
    pub(crate) side: f64,
    /// The parameter's period (the number of segments).
    pub(crate) period: f64,
}

/// Where an offset point comes from: a point of a segment, or the fan of directions at a
/// reflex corner (a corner turning away from the region, whose nearest points inside form a
/// sector about it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum OffsetSource {
    /// Segment `segment` at the profile parameter `u`.
    OnSegment { segment: usize, u: f64 },
    /// The reflex corner at the profile parameter `u` (a joint), in the direction `angle`.
    Fan { u: f64, angle: f64 },
}

impl<'r> Walk<'r> {
    /// The outer boundary (`hole` false) or a hole, walked for inward offsets or (`outward`)
    /// outward ones.
    pub(crate) fn new(profile: &'r Profile, hole: bool, outward: bool) -> Self {
        let side = if hole != outward {
            -profile.orientation()
        } else {
            profile.orientation()
        };
        Self {
            profile,
            side,
            period: profile.segments().len() as f64,
        }
    }

    /// How far ahead of `from` the walk reaches `to`, in parameter (in `[0, period)`).
    pub(crate) fn ahead(&self, from: f64, to: f64) -> f64 {
        ((to - from) * self.side).rem_euclid(self.period)
    }

    /// The reflex corner at the profile parameter `u`, if a joint there is one (for the
    /// region: the boundary turns right in the walk's direction).
    pub(crate) fn reflex_corner_at(&self, u: f64) -> Option<f64> {
        let joint = self.joint_at(u)?;
        (joint.kind != JointKind::Smooth && self.side * joint.turn < 0.0).then_some(joint.u)
    }

    /// The joint at `u` (within a parameter's rounding), if any.
    pub(crate) fn joint_at(&self, u: f64) -> Option<&curve::Joint> {
        // (Feet on a joint come from the same parameter the joint has, or its period's
        // other end.)
        const SAME_PARAMETER: f64 = 1e-12;
        self.profile.joints().iter().find(|j| {
            let d = (u - j.u).rem_euclid(self.period);
            d.min(self.period - d) <= SAME_PARAMETER * self.period.max(1.0)
        })
    }

    /// The point of the boundary at `u`.
    pub(crate) fn point(&self, u: f64) -> V2 {
        self.profile.jet_to(u, 0).p
    }

    /// The offset point at distance `d` from `foot` and its derivative in the foot's own
    /// variable (the parameter, or the fan's angle).
    pub(crate) fn offset(&self, foot: OffsetSource, d: f64) -> (V2, V2) {
        match foot {
            OffsetSource::OnSegment { segment, u } => {
                let jet = self.profile.jet_on(segment, u, 2);
                let speed = jet.d1.norm();
                let tangent = jet.d1 * (1.0 / speed);
                let turning = (jet.d2 - tangent * jet.d2.dot(tangent)) * (1.0 / speed);
                let normal = tangent.perp() * self.side;
                (
                    jet.p + normal * d,
                    jet.d1 + turning.perp() * (self.side * d),
                )
            }
            OffsetSource::Fan { u, angle } => {
                let c = self.point(u);
                let (s, co) = angle.sin_cos();
                (c + V2::new(co, s) * d, V2::new(-s, co) * d)
            }
        }
    }

    /// The unit normal where the walk leaves segment `segment` (at its end, walked with the
    /// parameter; at its start, against it), toward the side offset into: the incoming
    /// normal of the joint there. (By the segment's end, not the joint's parameter: a closed
    /// profile of one segment has its only joint at 0, which is both its ends.)
    pub(crate) fn normal_leaving(&self, segment: usize) -> V2 {
        let end = if self.side > 0.0 { 1.0 } else { 0.0 };
        self.normal(segment, segment as f64 + end)
    }

    /// The unit normal where the walk enters segment `segment`: the outgoing normal of the
    /// joint there.
    pub(crate) fn normal_entering(&self, segment: usize) -> V2 {
        let end = if self.side > 0.0 { 0.0 } else { 1.0 };
        self.normal(segment, segment as f64 + end)
    }

    /// The unit normal of segment `segment` at `u`, toward the side offset into (`u` may name
    /// the joint at 0 of the last segment).
    pub(crate) fn normal(&self, segment: usize, u: f64) -> V2 {
        // (The joint at 0 is the last segment's end, the period.)
        let u = if u < segment as f64 - 0.5 {
            u + self.period
        } else {
            u
        };
        self.profile.jet_on(segment, u, 1).d1.unit().perp() * self.side
    }
}

/// The segment the walk leaves the joint at `u` by.
pub(crate) fn outgoing_segment(walk: &Walk<'_>, u: f64) -> usize {
    let n = walk.profile.segments().len();
    let joint = (u.round() as usize) % n;
    if walk.side > 0.0 {
        joint
    } else {
        (joint + n - 1) % n
    }
}

/// The segment the walk reaches the joint at `u` by.
pub(crate) fn incoming_segment(walk: &Walk<'_>, u: f64) -> usize {
    let n = walk.profile.segments().len();
    let joint = (u.round() as usize) % n;
    if walk.side > 0.0 {
        (joint + n - 1) % n
    } else {
        joint
    }
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
