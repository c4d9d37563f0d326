//! What a command takes ([`Boundary`]): a smooth curve or a profile, one argument for both.
//!
//! A smooth closed curve is a closed profile of one segment, and the commands answer both
//! alike. The caller says which form it holds so that a curve is answered on its own exact
//! form and reported in its own parameter, and a profile segment by segment, at its corners.

use crate::error::Result;
use crate::on_circle::OnCircle;
use crate::plane::{Exact, ExactCurve, PlaneCurve};
use crate::profile::Profile;
use crate::segment::{Segment, SegmentKind};
use crate::shapes::{Circle, Convexities, Ellipse, EllipticLemniscate, Limacon, Shape};
use crate::spline::SplineCurve;
use std::borrow::Cow;

/// A boundary a command runs on: a smooth curve, or a profile of segments joined at corners
/// or smoothly. Made by `From` of a reference to either (`antipodal(&ellipse, …)`,
/// `antipodal(&profile, …)`).
///
/// ```
/// use curve::{shapes::Ellipse, Boundary, Profile, Segment};
/// let e = Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap();
/// assert!(matches!(Boundary::from(&e), Boundary::Curve(_)));
/// let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let sides = (0..4).map(|i| Segment::line(corners[i], corners[(i + 1) % 4]).unwrap());
/// let square = Profile::new(sides.collect(), Some(true)).unwrap();
/// assert!(matches!(Boundary::from(&square), Boundary::Profile(_)));
/// // A curve of this crate's kinds is also a profile of one segment, in its own parameter.
/// let one = Boundary::from(&e).to_profile().unwrap().unwrap();
/// assert_eq!(one.segments().len(), 1);
/// ```
#[derive(Clone, Copy)]
pub enum Boundary<'a> {
    /// A smooth curve: one of this crate's exact kinds (a spline, an analytic shape) or a
    /// curve known by evaluation only. Answered by the smooth curves' methods, in its own
    /// parameter. (A profile put here is read by evaluation only, as a smooth curve.)
    Curve(&'a dyn PlaneCurve),
    /// A profile: answered segment by segment, its corners taking part.
    Profile(&'a Profile),
}

impl<'a> Boundary<'a> {
    /// The boundary as a profile: a profile as it is; a curve of this crate's kinds as the
    /// profile of its one segment (cut at its corner knots, a periodic spline or an analytic
    /// shape as its whole curve), in the curve's own parameter. `None` for a curve known by
    /// evaluation only, which has no segment.
    pub fn to_profile(&self) -> Result<Option<Cow<'a, Profile>>> {
        let curve = match self {
            Boundary::Profile(p) => return Ok(Some(Cow::Borrowed(*p))),
            Boundary::Curve(c) => *c,
        };
        let segment = match curve.exact() {
            None => return Ok(None),
            Some(Exact::Shape(shape)) => Segment::of_shape(shape)?,
            Some(Exact::Spline(s)) if s.periodic_order().is_some() => {
                Segment::periodic_spline(SegmentKind::BSpline, s)?
            }
            Some(Exact::Spline(s)) => Segment::spline(SegmentKind::BSpline, s.clone())?,
        };
        Profile::of_curve(segment, curve.domain()).map(|p| Some(Cow::Owned(p)))
    }
}

impl std::fmt::Debug for Boundary<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Boundary::Curve(c) => write!(f, "Boundary::Curve(on {:?})", c.domain()),
            Boundary::Profile(p) => f.debug_tuple("Boundary::Profile").field(p).finish(),
        }
    }
}

impl<'a> From<&'a Profile> for Boundary<'a> {
    fn from(p: &'a Profile) -> Self {
        Boundary::Profile(p)
    }
}

impl<'a> From<&'a dyn PlaneCurve> for Boundary<'a> {
    fn from(c: &'a dyn PlaneCurve) -> Self {
        Boundary::Curve(c)
    }
}

impl<'a> From<&'a ExactCurve> for Boundary<'a> {
    fn from(c: &'a ExactCurve) -> Self {
        Boundary::Curve(c.curve())
    }
}

/// Each smooth curve kind of this crate is a boundary as a curve.
macro_rules! curve_boundary {
    ($($kind:ty),*) => {
        $(impl<'a> From<&'a $kind> for Boundary<'a> {
            fn from(c: &'a $kind) -> Self {
                Boundary::Curve(c)
            }
        })*
    };
}
curve_boundary!(
    SplineCurve,
    Shape,
    Circle,
    Ellipse,
    Limacon,
    EllipticLemniscate,
    Convexities,
    OnCircle
);

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::param::ParamCurve;

    #[test]
    fn a_curve_as_a_profile_keeps_its_own_parameter() {
        let s = SplineCurve::clamped(
            3,
            &[[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]],
            None,
            Some(vec![0.5, 0.5, 0.5, 0.5, 2.5, 2.5, 2.5, 2.5]),
        )
        .unwrap();
        let p = Boundary::from(&s).to_profile().unwrap().unwrap();
        assert_eq!(p.segments().len(), 1);
        for u in [0.5, 1.0, 1.7, 2.5] {
            let at = p.jet(p.internal_param(u)).p;
            assert!((at - s.jet(u).p).norm() < 1e-14, "{u}");
        }
    }

    #[test]
    fn a_curve_known_by_evaluation_has_no_profile() {
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let sides = (0..4).map(|i| Segment::line(corners[i], corners[(i + 1) % 4]).unwrap());
        let square = Profile::new(sides.collect(), Some(true)).unwrap();
        let as_curve: &dyn PlaneCurve = &square;
        assert!(Boundary::from(as_curve).to_profile().unwrap().is_none());
        assert!(matches!(Boundary::from(&square), Boundary::Profile(_)));
    }
}
