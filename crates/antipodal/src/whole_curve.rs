//! A closed profile of one segment without a corner is a smooth closed curve: the segment's
//! whole curve where it was made from one (an analytic shape, a periodic spline:
//! [`curve::Segment::whole_curve`]), or the segment's own spline closed by its points. The
//! commands on profiles run on it the way they run on that curve (see [`crate::prepare`]),
//! and report their results on the profile, with no corners. So a curve gives the same
//! answer whether it comes as a curve or as a profile: a shape on its exact form on the
//! rational circle (sampled where that form loses precision), its seam smooth by definition;
//! a spline with its straight stretches proven on its data as given.

use crate::error::Result;
use crate::prepare::{common_tangents_run, prepare};
use crate::types::{
    Antipodal, AntipodalPair, Family, Inflection, Inflections, Options, Provenance, TangentLine,
    Tangents,
};
use curve::{ParamCurve, PlaneCurve, Profile, SegmentKind};
use numeric::certificate::{Certified, Doubts};

/// The smooth closed curve a closed profile of one segment is, with how its parameters map to
/// the profile's.
pub(crate) struct WholeCurve<'p> {
    profile: &'p Profile,
    /// The curve the commands run on: the segment's whole curve as defined, or the segment's
    /// own spline.
    curve: &'p dyn PlaneCurve,
    /// Its domain.
    domain: (f64, f64),
}

/// The smooth closed curve `profile` is, where it is one segment without a corner: the
/// segment's whole curve, where it was made from one, or a spline segment closed by its
/// points, its seam smooth (a closed arc stays a profile's: its circle is proven by its
/// definition there).
pub(crate) fn whole_curve(profile: &Profile) -> Option<WholeCurve<'_>> {
    let [only] = profile.segments() else {
        return None;
    };
    if !profile.is_closed() || profile.corners().next().is_some() {
        return None;
    }
    let curve: &dyn PlaneCurve = match (only.whole_curve(), only.kind()) {
        (Some(whole), _) => whole.curve(),
        (None, SegmentKind::Bezier | SegmentKind::BSpline) => only.curve(),
        (None, _) => return None,
    };
    Some(WholeCurve {
        profile,
        curve,
        domain: curve.domain(),
    })
}

impl WholeCurve<'_> {
    /// The profile parameter at the curve's `x`; a parameter beyond the domain's end (an
    /// inflection's bracket across the seam) stays beyond the profile's, unwrapped.
    fn param(&self, x: f64) -> f64 {
        let (a, b) = self.domain;
        let (turns, x) = if x > b {
            (1.0, x - (b - a))
        } else if x < a {
            (-1.0, x + (b - a))
        } else {
            (0.0, x)
        };
        // (A spline segment is its own curve: its parameter is the form's.)
        let segment = &self.profile.segments()[0];
        let v = segment.form_param_of_whole(x).unwrap_or(x);
        self.profile.profile_param(0, v) + turns
    }

    /// The curve's inflections on the profile (on segment 0).
    fn inflections(&self, found: Vec<Inflection>) -> Vec<Inflection> {
        found
            .into_iter()
            .map(|f| Inflection {
                u: self.param(f.u),
                bracket: f.bracket.map(|[lo, hi]| [self.param(lo), self.param(hi)]),
                segment: Some(0),
                ..f
            })
            .collect()
    }
}

/// [`crate::profile_pairs::profile_antipodal`] on the profile of a whole curve.
pub(crate) fn antipodal(on: &WholeCurve<'_>, opts: &Options) -> Result<Antipodal> {
    let found = prepare(on.curve).antipodal(opts)?;
    let at = |x: f64| on.curve.jet(x).p.arr();
    Ok(Antipodal {
        pairs: found
            .pairs
            .iter()
            .map(|&p| AntipodalPair {
                s: on.param(p.s),
                t: on.param(p.t),
                ..p.on_one_segment()
            })
            .collect(),
        inflections: on.inflections(found.inflections),
        corners: Some(Vec::new()),
        families: found
            .families
            .iter()
            .map(|f| Family {
                s: f.s.map(|x| on.param(x)),
                t: f.t.map(|x| on.param(x)),
                p: Some(f.s.map(at)),
                q: Some(f.t.map(at)),
            })
            .collect(),
        doubts: found.doubts,
        complete: found.complete,
    })
}

/// [`crate::profiles::profile_inflections`] on the profile of a whole curve, its doubts not
/// yet stated.
pub(crate) fn inflections_run(
    on: &WholeCurve<'_>,
    opts: &Options,
) -> Result<Certified<Inflections>> {
    let (found, doubts) = crate::prepare::inflections_run(on.curve, opts)?.into_parts();
    Ok(Certified {
        value: Inflections {
            inflections: on.inflections(found.inflections),
            corners: Some(Vec::new()),
            doubts: Doubts::none(),
        },
        doubts,
    })
}

/// [`crate::profile_tangents::profile_tangents`] on the profiles of two whole curves.
pub(crate) fn tangents(
    on_a: &WholeCurve<'_>,
    on_b: &WholeCurve<'_>,
    opts: &Options,
) -> Result<Tangents> {
    let found: Tangents = Provenance::finished(common_tangents_run(on_a.curve, on_b.curve, opts)?);
    Ok(Tangents {
        lines: found
            .lines
            .iter()
            .map(|l| TangentLine {
                s: on_a.param(l.s),
                t: on_b.param(l.t),
                corner: Some([false; 2]),
                segment: Some([0; 2]),
                ..*l
            })
            .collect(),
        doubts: found.doubts,
    })
}
