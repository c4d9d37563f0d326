//! A profile of one spline segment without a corner (open, or closed with a smooth seam) is
//! the curve it is: its bisectors are the curve engine's (`curve_bisector`,
//! `curve_self_bisector`), run on the segment's whole periodic spline where it was made
//! from one ([`curve::Segment::whole_curve`]), else on the segment's own spline, and reported
//! on the profile with no corners. So a spline gives the same bisector whether it comes as a
//! curve or as a profile.
//!
//! Analytic shapes (their whole curve is the shape, not a spline), lines and arcs (their
//! closed forms) keep the profile's path.

use crate::bisector::{
    curve_bisector, curve_self_bisector, Bisector, BisectorOptions, BisectorPoint, Branch,
};
use crate::error::Result;
use bspline::Rational;
use curve::{ExactCurve, Profile, SegmentKind};

/// The spline a profile of one smooth spline segment is, with how its parameters map to the
/// profile's.
pub(super) struct OneSpline<'p> {
    profile: &'p Profile,
    /// The curve the bisector runs on: the whole periodic spline, or the segment's own.
    curve: &'p Rational,
}

/// The spline `profile` is, where it is one Bézier or B-spline segment without a corner and
/// its whole curve, if any, is a spline.
pub(super) fn one_spline(profile: &Profile) -> Option<OneSpline<'_>> {
    let [only] = profile.segments() else {
        return None;
    };
    if !matches!(only.kind(), SegmentKind::Bezier | SegmentKind::BSpline)
        || profile.corners().next().is_some()
    {
        return None;
    }
    let curve = match only.whole_curve() {
        Some(ExactCurve::Spline(whole)) => whole.curve(),
        // (A shape's exact form on the rational circle is a B-spline segment too: its
        // bisector stays the profile's.)
        Some(ExactCurve::Shape(_)) => return None,
        None => only.curve().curve(),
    };
    Some(OneSpline { profile, curve })
}

impl OneSpline<'_> {
    /// The profile parameter at the curve's `x`.
    fn param(&self, x: f64) -> f64 {
        // (The segment's own spline has no whole curve: its parameter is the form's.)
        let segment = &self.profile.segments()[0];
        let v = segment.form_param_of_whole(x).unwrap_or(x);
        self.profile.profile_param(0, v)
    }

    /// The curve's bisector on the profiles of `self` (its `t`) and `other` (its `r`).
    fn on_profiles(&self, other: &OneSpline<'_>, found: Bisector) -> Bisector {
        let tr = |[t, r]: [f64; 2]| [self.param(t), other.param(r)];
        let point = |p: BisectorPoint| BisectorPoint {
            tr: tr(p.tr),
            xy: p.xy,
            segment: Some([0; 2]),
            corner: Some([false; 2]),
        };
        Bisector {
            branches: found
                .branches
                .into_iter()
                .map(|b| Branch {
                    tr: b.tr.into_iter().map(tr).collect(),
                    xy: b.xy,
                    segment: Some([0; 2]),
                    corner: Some([false; 2]),
                })
                .collect(),
            singular: found.singular.into_iter().map(point).collect(),
            isolated: found.isolated.into_iter().map(point).collect(),
            complete: found.complete,
        }
    }
}

/// [`crate::profile_bisector`] of two profiles that are each one spline.
pub(super) fn spline_bisector(
    a: &OneSpline<'_>,
    b: &OneSpline<'_>,
    opts: &BisectorOptions,
) -> Result<Bisector> {
    Ok(a.on_profiles(b, curve_bisector(a.curve, b.curve, opts)?))
}

/// [`crate::profile_self_bisector`] of a profile that is one spline.
pub(super) fn spline_self_bisector(p: &OneSpline<'_>, opts: &BisectorOptions) -> Result<Bisector> {
    Ok(p.on_profiles(p, curve_self_bisector(p.curve, opts)?))
}
