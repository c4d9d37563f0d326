//! Beyond the papers' smooth curves: the commands on profiles (chains of segments joined at
//! corners or smoothly, [`Profile`]). Jia (2004, §9.2) notes that the method extends to
//! piecewise C² curves; this module runs it segment by segment and decides at the joints.

use crate::error::{Error, Result};
use crate::prepare::inflections_run;
use crate::types::{
    Corner, CornerKind, Inflection, InflectionKind, Inflections, Options, Provenance,
};
use curve::{JointKind, ParamCurve, Profile, SegmentKind};
use numeric::certificate::{Certified, Doubt, Doubts};
use numeric::rounding::ulps;

/// The turn of a smooth joint's tangents above which the segments' searches may miss a pair
/// or a common tangent whose direction lies between them, its root just beyond the end of
/// each segment (the floor of the noise they take the antipodal angle to have,
/// [`crate::pairs::Pair::theta_noise`]): such a joint's fan is searched as a corner's cone is,
/// and what is found there is smooth. (Near the origin a smooth joint turns by less; a drawing
/// far from it, by the rounding of its coordinates.)
pub(crate) const FAN_NOISE: f64 = ulps(64.0);

/// The curvature (times the profile's size) beside a smooth joint below which its sign is
/// not clear of the rounding of the jets it is computed from.
const JOINT_CURVATURE_NOISE: f64 = 1e-9;

/// The inflections of a profile: inside each curved segment (certified where the segment's
/// are), and at smooth joints where the curvature changes sign across the joint (an arc joined
/// tangentially to an arc bent the other way); and its corners, which are not inflections.
/// A straight segment has no single inflection: none is reported on it.
pub(crate) fn profile_inflections(profile: &Profile, opts: &Options) -> Result<Inflections> {
    Ok(Provenance::finished(profile_inflections_run(
        profile, opts,
    )?))
}

/// [`profile_inflections`] with the doubts met, in order (the segments', each at its turn,
/// and the joints'), not yet stated.
pub(crate) fn profile_inflections_run(
    profile: &Profile,
    opts: &Options,
) -> Result<Certified<Inflections>> {
    opts.validate()?;
    if let Some(whole) = crate::whole_curve::whole_curve(profile) {
        return crate::whole_curve::inflections_run(&whole, opts);
    }
    let mut corners = Vec::new();
    let mut out = Inflections {
        inflections: Vec::new(),
        corners: None,
        doubts: Doubts::none(),
    };
    let mut doubts = Doubts::none();
    for (i, seg) in profile.segments().iter().enumerate() {
        if seg.kind() == SegmentKind::Line {
            continue;
        }
        let found = inflections_run(seg.curve(), opts).map_err(|e| Error::InSegment {
            segment: i,
            source: Box::new(e),
        })?;
        let found = doubts.absorb(found);
        let (a, b) = seg.curve().domain();
        for f in found.inflections {
            // At a segment's end the joint decides (a corner is no inflection). So it does
            // where the sign change's bracket reaches the end: the curvature there is within
            // rounding of zero, and the change may be the end's own rounding (a Bézier whose
            // first three control points are collinear as written in decimals).
            let [lo, hi] = f.bracket.unwrap_or([f.u, f.u]);
            if lo <= a || hi >= b {
                let end = if lo <= a { a } else { b };
                let u = profile.profile_param(i, end);
                let last = profile.segments().len() - 1;
                let open_end =
                    !profile.is_closed() && ((i == 0 && end == a) || (i == last && end == b));
                let undecided = f.u > a && f.u < b && (open_end || at_corner(profile, i, end));
                if undecided {
                    doubts.add(Doubt::CurvatureAtSegmentEnd { u, segment: i });
                }
                continue;
            }
            out.inflections.push(Inflection {
                u: profile.profile_param(i, f.u),
                bracket: f
                    .bracket
                    .map(|[lo, hi]| [profile.profile_param(i, lo), profile.profile_param(i, hi)]),
                segment: Some(i),
                ..f
            });
        }
    }
    let size = profile.scale();
    let n = profile.segments().len();
    for joint in profile.joints() {
        let i = joint.u as usize;
        let p = profile.jet_to(joint.u, 0).p.arr();
        if joint.kind != JointKind::Smooth {
            corners.push(Corner {
                u: joint.u,
                p,
                turn: joint.turn,
                kind: match joint.kind {
                    JointKind::Reflex => CornerKind::Reflex,
                    _ => CornerKind::Convex,
                },
            });
            continue;
        }
        let (before, after) = (&profile.segments()[(i + n - 1) % n], &profile.segments()[i]);
        if before.kind() == SegmentKind::Line || after.kind() == SegmentKind::Line {
            continue;
        }
        let k_before = before.jet(before.curve().domain().1).curvature();
        let k_after = after.jet(after.curve().domain().0).curvature();
        let clear = |k: f64| (k * size).abs() > JOINT_CURVATURE_NOISE;
        if !(clear(k_before) && clear(k_after)) {
            // A segment ending in a zero of its curvature: whether the profile inflects
            // there is not decided.
            doubts.add(Doubt::CurvatureAtJoint { u: joint.u });
            continue;
        }
        if (k_before > 0.0) != (k_after > 0.0) {
            out.inflections.push(Inflection {
                u: joint.u,
                p,
                certified: true,
                kind: InflectionKind::Simple,
                bracket: Some([joint.u, joint.u]),
                segment: Some(i),
            });
        }
    }
    out.inflections.sort_by(|a, b| a.u.total_cmp(&b.u));
    out.corners = Some(corners);
    Ok(Certified { value: out, doubts })
}

/// How close (relative to a segment's domain) to its end a point lies at the joint there:
/// far below any feature, far above the rounding of a parameter solved to the tolerance.
const AT_JOINT: f64 = 1e-9;

/// The kind of the joint where segment `i` is at the share `share ∈ [0, 1]` of its domain, if
/// that is one of its ends (`None` inside, or at an open profile's end).
pub(crate) fn joint_at(profile: &Profile, i: usize, share: f64) -> Option<JointKind> {
    let n = profile.segments().len();
    let at = if share <= AT_JOINT {
        i
    } else if share >= 1.0 - AT_JOINT {
        (i + 1) % n
    } else {
        return None;
    };
    profile
        .joints()
        .iter()
        .find(|j| j.u as usize == at)
        .map(|j| j.kind)
}

/// Whether segment `i`'s own parameter `v` is at one of its ends where the profile has a
/// corner.
pub(crate) fn at_corner(profile: &Profile, i: usize, v: f64) -> bool {
    let (a, b) = profile.segments()[i].curve().domain();
    joint_at(profile, i, (v - a) / (b - a)).is_some_and(|k| k != JointKind::Smooth)
}
