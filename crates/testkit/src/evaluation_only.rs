//! A curve known by evaluation only: the same points and derivatives as the curve it wraps,
//! without its exact form ([`curve::PlaneCurve::exact`] is `None`), for the tests of what the
//! commands do with such a curve (Jia's sampled method, refusals where an exact form is
//! needed).

use curve::{Jet, ParamCurve, PlaneCurve};

/// `C` known by evaluation only.
///
/// ```
/// use curve::{shapes::Circle, ParamCurve, PlaneCurve};
/// use testkit::evaluation_only::EvaluationOnly;
/// let c = Circle::new(1.0, [0.0, 0.0]).unwrap();
/// let sampled = EvaluationOnly(c);
/// assert!(sampled.exact().is_none() && c.exact().is_some());
/// assert_eq!(sampled.jet(0.5).p, c.jet(0.5).p);
/// ```
pub struct EvaluationOnly<C>(pub C);

impl<C: ParamCurve> ParamCurve for EvaluationOnly<C> {
    fn domain(&self) -> (f64, f64) {
        self.0.domain()
    }
    fn is_closed(&self) -> bool {
        self.0.is_closed()
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        self.0.jet_to(u, order)
    }
}

impl<C: ParamCurve + Send + Sync> PlaneCurve for EvaluationOnly<C> {}
