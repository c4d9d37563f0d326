//! The profile as the grasp computations see it: each segment's exact form in one frame, the
//! joints with their cones of inward normals, and the profile parameter `u ∈ [0, n)` (segment
//! `i` on `[i, i + 1]`, its form's parameter mapped linearly).

use crate::cones::Form;
use crate::error::Result;
use curve::{Frame, JointKind, Profile};
use std::borrow::Cow;

/// What a joint contributes as a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Cone {
    /// A smooth joint: the normal is continuous, the joint is a point of both segments.
    Smooth,
    /// A convex corner: any inward normal between those of the two segments (unit vectors).
    Convex {
        /// The incoming segment's inward normal at the corner.
        before: [f64; 2],
        /// The outgoing segment's.
        after: [f64; 2],
    },
    /// A reflex corner: it takes no part (the contract's antipodal pairs leave it out).
    Reflex,
}

/// A joint: where segment `segment` starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Joint {
    /// The segment that starts there (the joint's profile parameter).
    pub(crate) segment: usize,
    /// The point, in the frame.
    pub(crate) point: [f64; 2],
    pub(crate) cone: Cone,
}

/// A closed profile in its frame.
pub(crate) struct Model<'p> {
    pub(crate) profile: Cow<'p, Profile>,
    pub(crate) frame: Frame,
    pub(crate) forms: Vec<Form>,
    /// Per segment, the joint where it starts.
    pub(crate) joints: Vec<Joint>,
}

impl<'p> Model<'p> {
    /// The model of the closed profile `profile`.
    pub(crate) fn new(profile: Cow<'p, Profile>) -> Result<Self> {
        let points: Vec<[f64; 2]> = profile
            .segments()
            .iter()
            .flat_map(|s| s.curve().control_points())
            .collect();
        let frame = Frame::for_points(&points);
        let o = profile.orientation();
        let forms = profile
            .segments()
            .iter()
            .map(|s| Form::new(s.curve().in_frame(&frame).curve(), o))
            .collect::<Result<Vec<_>>>()?;
        let n = forms.len();
        let inward = |t: [f64; 2]| {
            let l = t[0].hypot(t[1]);
            [-o * t[1] / l, o * t[0] / l]
        };
        let joints = (0..n)
            .map(|k| {
                let after = &forms[k];
                let before = &forms[(k + n - 1) % n];
                let (p, t_after) = after.point_tangent(after.domain().0);
                let (_, t_before) = before.point_tangent(before.domain().1);
                let kind = profile
                    .joints()
                    .iter()
                    .find(|j| j.u == k as f64)
                    .map_or(JointKind::Smooth, |j| j.kind);
                let cone = match kind {
                    JointKind::Smooth => Cone::Smooth,
                    JointKind::Convex => Cone::Convex {
                        before: inward(t_before),
                        after: inward(t_after),
                    },
                    JointKind::Reflex => Cone::Reflex,
                };
                Joint {
                    segment: k,
                    point: p,
                    cone,
                }
            })
            .collect();
        Ok(Self {
            profile,
            frame,
            forms,
            joints,
        })
    }

    /// The number of segments.
    pub(crate) fn n(&self) -> usize {
        self.forms.len()
    }

    /// The profile parameter at form parameter `v` of segment `i`.
    pub(crate) fn profile_param(&self, i: usize, v: f64) -> f64 {
        let (a, b) = self.forms[i].domain();
        i as f64 + (v - a) / (b - a)
    }

    /// The segment and its form's parameter at the profile parameter `u` (read modulo `n`).
    pub(crate) fn locate(&self, u: f64) -> (usize, f64) {
        let n = self.n();
        let u = wrap(u, n as f64);
        // (Truncation is the floor in [0, n), without the library call.)
        let i = (u as usize).min(n - 1);
        let (a, b) = self.forms[i].domain();
        (i, a + (u - i as f64).clamp(0.0, 1.0) * (b - a))
    }

    /// The point and the tangent (in the form's parameter) at the profile parameter `u`.
    pub(crate) fn point_tangent(&self, u: f64) -> ([f64; 2], [f64; 2]) {
        let (i, v) = self.locate(u);
        self.forms[i].point_tangent(v)
    }

    /// The joint at the profile parameter `u`, if `u` is one (modulo `n`).
    pub(crate) fn joint_at(&self, u: f64) -> Option<&Joint> {
        let n = self.n() as f64;
        let k = wrap(u, n);
        (k == (k as usize) as f64).then(|| &self.joints[(k as usize) % self.n()])
    }

    /// The document's parameter per segment, on average: the unit in which a cell's chord
    /// tolerance is measured where the regions are reported.
    pub(crate) fn document_cell(&self) -> f64 {
        let (da, db) = self.profile.document_domain();
        (db - da) / self.n() as f64
    }

    /// The document's parameter at the profile parameter `u`, unwrapped by whole turns.
    pub(crate) fn document_param(&self, u: f64) -> f64 {
        let n = self.n() as f64;
        let turns = (u / n).floor();
        let (da, db) = self.profile.document_domain();
        let (i, v) = self.locate(u - turns * n);
        let (a, b) = self.forms[i].domain();
        self.profile.document_param_on(i, (v - a) / (b - a)) + turns * (db - da)
    }

    /// The point at the profile parameter `u`, in the profile's own coordinates.
    pub(crate) fn global_point(&self, u: f64) -> [f64; 2] {
        self.frame.to_global(self.point_tangent(u).0)
    }
}

/// `u` modulo `n` in `[0, n)`: most parameters asked for are there already, and the general
/// remainder is a slow library call (the searches ask millions of times).
pub(crate) fn wrap(u: f64, n: f64) -> f64 {
    if (0.0..n).contains(&u) {
        u
    } else {
        u.rem_euclid(n)
    }
}
