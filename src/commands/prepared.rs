//! The one-curve commands (`inflections`, `antipodal`): a curve prepared once for them, and
//! the route each takes by the curve's shape.

use super::errors::antipodal_error;
use super::found::Doubted;
use super::params::{DocMap, InDocument};
use super::{one_curve, validate_options, AntipodalFound, CommandError, Found, InflectionsFound};
use crate::io::{Curve, CurveKind};
use curve::{ParamCurve, PlaneCurve, Profile};
use std::sync::Arc;

/// A curve made ready for the one-curve commands: a spline or an analytic shape is prepared
/// once (its frame, symbolic forms and enclosures; [`antipodal::prepare`]), so that later
/// calls answer warm; a profile needs no preparation, and a spline with corners (a degree-1
/// spline, knots of full multiplicity) is taken as the profile of its pieces. A region is
/// refused: the one-curve commands take curves. It shares the curve, so it can be kept and
/// sent between threads.
pub struct PreparedCurve {
    curve: Arc<Curve>,
    smooth: Option<antipodal::Prepared<'static>>,
    /// The spline taken as a profile, where it has corners.
    cut: Option<Profile>,
}

impl PreparedCurve {
    /// Prepares `curve` for `command` (named in the refusal of a region).
    pub fn new(curve: Arc<Curve>, command: &str) -> Result<Self, CommandError> {
        one_curve(&[&curve], command)?;
        let cut = spline_with_corners(&curve)?;
        let smooth = match (&curve.shape, &cut) {
            (CurveKind::Profile(_), _) | (_, Some(_)) => None,
            _ => Some(antipodal::prepare_shared(Arc::new(Shared(curve.clone())))),
        };
        Ok(Self { curve, smooth, cut })
    }

    /// The curve prepared.
    pub fn curve(&self) -> &Curve {
        &self.curve
    }

    /// The inflections (and a profile's corners).
    pub fn inflections(&self, opts: &antipodal::Options) -> Result<InflectionsFound, CommandError> {
        INFLECTIONS_BY_ROUTE.on_route(&self.curve, self.route(), opts)
    }

    /// The antipodal pairs, inflections and families (and a profile's corners).
    pub fn antipodal(&self, opts: &antipodal::Options) -> Result<AntipodalFound, CommandError> {
        ANTIPODAL_BY_ROUTE.on_route(&self.curve, self.route(), opts)
    }

    fn route(&self) -> Route<'_> {
        match (&self.curve.shape, &self.cut, &self.smooth) {
            (CurveKind::Profile(p), _, _) => Route::Profile(p),
            (_, Some(p), _) => Route::Profile(p),
            (_, None, Some(s)) => Route::Smooth(s),
            (_, None, None) => unreachable!("a curve that is no profile is prepared"),
        }
    }
}

/// Which algorithms a one-curve command runs: a profile's, or a smooth curve's (prepared).
enum Route<'a> {
    Profile(&'a Profile),
    Smooth(&'a antipodal::Prepared<'a>),
}

/// A spline with corners (a degree-1 spline, a knot of full multiplicity where it turns, a
/// clamped closed spline with a corner where its ends meet) as the profile of its pieces, in
/// its own parameter; `None` for a smooth spline and for every other kind.
pub(super) fn spline_with_corners(c: &Curve) -> Result<Option<Profile>, CommandError> {
    if !matches!(c.shape, CurveKind::Spline(_)) {
        return Ok(None);
    }
    match crate::io::curve_profile(c) {
        Some(Ok(p)) if p.segments().len() > 1 || p.corners().next().is_some() => Ok(Some(p)),
        Some(Ok(_)) | None => Ok(None),
        Some(Err(e)) => Err(CommandError::Input(e)),
    }
}

/// How `curve`'s exact form's parameters map to its document's on the smooth path.
pub(super) fn smooth_map(curve: &Curve) -> DocMap<'_> {
    match &curve.shape {
        CurveKind::Segment(s) => DocMap::Segment(s),
        _ => DocMap::Own,
    }
}

/// A one-curve command: its name (in a refusal), and what it computes on a profile and on a
/// smooth curve prepared (one result type for both).
struct OneCurveCommand<T> {
    name: &'static str,
    on_profile: fn(&Profile, &antipodal::Options) -> antipodal::Result<T>,
    on_smooth: fn(&antipodal::Prepared<'_>, &antipodal::Options) -> antipodal::Result<T>,
}

const INFLECTIONS_BY_ROUTE: OneCurveCommand<antipodal::Inflections> = OneCurveCommand {
    name: "inflections",
    on_profile: |profile, opts| antipodal::inflections(profile, opts),
    on_smooth: |prepared, opts| prepared.inflections(opts),
};

const ANTIPODAL_BY_ROUTE: OneCurveCommand<antipodal::Antipodal> = OneCurveCommand {
    name: "antipodal",
    on_profile: |profile, opts| antipodal::antipodal(profile, opts),
    on_smooth: |prepared, opts| prepared.antipodal(opts),
};

impl<T: InDocument + Doubted> OneCurveCommand<T> {
    /// The command on `curve` by `route`, in the curve's own parameter; the result is doubted
    /// where the drawing's outline is.
    fn on_route(
        &self,
        curve: &Curve,
        route: Route<'_>,
        opts: &antipodal::Options,
    ) -> Result<Found<T>, CommandError> {
        let found = match route {
            Route::Profile(p) => (self.on_profile)(p, opts)
                .map(|f| Found::Profile(f.into_document(&[DocMap::Profile(p)]))),
            Route::Smooth(prepared) => (self.on_smooth)(prepared, opts)
                .map(|f| Found::Curve(f.into_document(&[smooth_map(curve)]))),
        };
        found
            .map(|f| f.doubted(curve.drawing_outline_doubt()))
            .map_err(|e| antipodal_error(e, &[curve]))
    }

    /// The command on `curve` read, by the route its shape takes, a smooth curve freshly
    /// prepared.
    fn on_fresh(&self, curve: &Curve, opts: &antipodal::Options) -> Result<Found<T>, CommandError> {
        validate_options(opts)?;
        one_curve(&[curve], self.name)?;
        match (&curve.shape, spline_with_corners(curve)?) {
            (CurveKind::Profile(p), _) => self.on_route(curve, Route::Profile(p), opts),
            (_, Some(p)) => self.on_route(curve, Route::Profile(&p), opts),
            _ => self.on_route(
                curve,
                Route::Smooth(&antipodal::prepare(curve.plane_curve())),
                opts,
            ),
        }
    }
}

/// A curve read, shared with its prepared form: the plane curve of its shape.
struct Shared(Arc<Curve>);

impl ParamCurve for Shared {
    fn domain(&self) -> (f64, f64) {
        self.0.plane_curve().domain()
    }
    fn is_closed(&self) -> bool {
        self.0.plane_curve().is_closed()
    }
    fn jet_to(&self, u: f64, order: usize) -> curve::Jet {
        self.0.plane_curve().jet_to(u, order)
    }
    fn jet(&self, u: f64) -> curve::Jet {
        self.0.plane_curve().jet(u)
    }
}

impl PlaneCurve for Shared {
    fn exact(&self) -> Option<curve::Exact<'_>> {
        self.0.plane_curve().exact()
    }
}

/// `inflections` of a curve read: [`PreparedCurve::inflections`] on a freshly prepared curve.
pub fn inflections(
    curve: &Curve,
    opts: &antipodal::Options,
) -> Result<InflectionsFound, CommandError> {
    INFLECTIONS_BY_ROUTE.on_fresh(curve, opts)
}

/// `antipodal` of a curve read: [`PreparedCurve::antipodal`] on a freshly prepared curve.
pub fn antipodal(curve: &Curve, opts: &antipodal::Options) -> Result<AntipodalFound, CommandError> {
    ANTIPODAL_BY_ROUTE.on_fresh(curve, opts)
}
