//! The prepared curve: what every run on one curve shares, built once, the way a compiled
//! regular expression is: the frame the curve is computed in, the curve moved into it (an
//! analytic shape on its rational circle), its symbolic forms and the enclosures later runs
//! build on them. Results come back in the curve's own coordinates and parameters.

use crate::driver::{antipodal_of, inflections_of, tangents_of};
use crate::error::{Error, Result};
use crate::forms::SymbolicForms;
use crate::types::{Antipodal, Inflections, Options, Provenance, Tangents};
use crate::view::Source;
use curve::circle::Angle;
use curve::{ExactCurve, Frame, OnCircle, ParamCurve, PlaneCurve, StraightSpan};
use numeric::certificate::{Certified, Doubt, Doubts};
use std::sync::Arc;

/// A curve prepared for the algorithms of this crate (see [`prepare`]).
pub struct Prepared<'c> {
    /// The curve as given.
    given: Given<'c>,
    /// The frame the curve is computed in.
    frame: Frame,
    /// The curve moved into the frame (`None`: a curve known only by evaluation, used as
    /// given).
    local: Option<ExactCurve>,
    /// An analytic shape in the parameter of its rational-circle form, where its symbolic
    /// forms live.
    circle: Option<OnCircle>,
    /// The symbolic forms, when the curve has an exact form.
    forms: Option<SymbolicForms>,
    /// Simple and regular by construction (an analytic shape).
    simple: bool,
    /// How often the curvature oscillates around the curve, as far as known (a shape's lobes).
    lobes: usize,
    /// The stretches proven exactly straight, from the curve's data.
    straight: Vec<StraightSpan>,
    /// Exactly a circle by its definition.
    exact_circle: bool,
}

/// The curve as given: borrowed for the prepared curve's life, or shared with it (a prepared
/// curve kept beyond its caller's borrow, as a Python object keeps it).
#[derive(Clone)]
enum Given<'c> {
    Borrowed(&'c dyn PlaneCurve),
    Shared(Arc<dyn PlaneCurve>),
}

impl Given<'_> {
    fn curve(&self) -> &dyn PlaneCurve {
        match self {
            Given::Borrowed(c) => *c,
            Given::Shared(c) => c.as_ref(),
        }
    }
}

/// Samples of a sampled track per oscillation of the curvature: Jia's sampling of the
/// inflections resolves a few per lobe (96 for the papers' shapes, as in the paper).
const SAMPLES_PER_LOBE: usize = 96;

impl<'c> Prepared<'c> {
    /// The curve in `frame` (one of this crate's kinds; any other curve stays as given).
    fn new(given: Given<'c>, frame: Frame) -> Self {
        let curve = given.curve();
        let Some(exact) = curve.exact() else {
            return Self {
                given,
                frame: Frame::IDENTITY,
                local: None,
                circle: None,
                forms: None,
                simple: false,
                lobes: 1,
                straight: Vec::new(),
                exact_circle: false,
            };
        };
        let local = exact.in_frame(&frame);
        let lobes = match &local {
            ExactCurve::Shape(s) => s.lobes() as usize,
            ExactCurve::Spline(_) => 1,
        };
        // (Straightness is proven on the data as given: the frame moves the curve, not its
        // parameters.)
        let (straight, exact_circle) = match &exact {
            curve::Exact::Spline(s) => (s.straight_spans(), false),
            curve::Exact::Shape(s) => (Vec::new(), s.is_exact_circle()),
        };
        let (circle, pieces, simple) = match &local {
            ExactCurve::Spline(s) => (None, Some(s.exact_pieces()), false),
            ExactCurve::Shape(shape) => match (shape.circle_shape(), shape.exact_pieces()) {
                (Some(form), Some(pieces)) => (Some(OnCircle::new(form)), Some(pieces), true),
                _ => (None, None, true),
            },
        };
        Self {
            given,
            frame,
            local: Some(local),
            circle,
            forms: pieces.and_then(|p| SymbolicForms::new(p).ok()),
            simple,
            lobes,
            straight,
            exact_circle,
        }
    }

    /// What the runs look at: the curve with its symbolic forms (an analytic shape on its
    /// rational circle) when `certify` and it has them, else the curve alone (a shape in its
    /// own angle).
    pub(crate) fn source(&self, certify: bool) -> Source<'_> {
        let forms = self.forms.as_ref().filter(|_| certify);
        let (curve, report): (&dyn ParamCurve, Option<Angle>) =
            match (&self.circle, forms, &self.local) {
                (Some(c), Some(_), _) => (c, Some(c.angle())),
                (_, _, Some(l)) => (l.curve(), None),
                (_, _, None) => (self.given.curve(), None),
            };
        Source {
            curve,
            forms,
            simple: self.simple,
            report,
            samples: SAMPLES_PER_LOBE * self.lobes,
            straight: &self.straight,
            exact_circle: self.exact_circle,
        }
    }

    /// Runs `run` certified where the curve allows; where an analytic shape (regular by
    /// construction) is refused as singular, its exact form lost the precision its proofs
    /// need (a curve with many convexities: the form's degree grows with them), and it runs
    /// again sampled, in its own angle, uncertified with that reason (before the doubts the
    /// sampled run meets).
    fn certified_or_sampled<T>(
        &self,
        opts: &Options,
        run: impl Fn(Source<'_>) -> Result<Certified<T>>,
    ) -> Result<Certified<T>> {
        // (Options first: a usage error is reported before anything about the curve.)
        opts.validate()?;
        // (A length in an error is the frame's: given back in the curve's units.)
        let run = |src: Source<'_>| {
            run(src).map_err(|e| match e {
                Error::NotClosed { gap } => Error::NotClosed {
                    gap: self.frame.length_to_global(gap),
                },
                e => e,
            })
        };
        // A shape of many lobes refused as singular by the sampled search hit its bound on
        // samples; a shape of one lobe has no oscillation to blame: it is within rounding of a
        // cusp (a limaçon with b within 1e-13 of a), and the refusal stands.
        let sampled = || {
            run(self.source(false)).map_err(|e| match e {
                Error::Cusp { .. } if self.simple && self.lobes > 1 => {
                    Error::TooComplex { lobes: self.lobes }
                }
                e => e,
            })
        };
        let sampled_for = |doubt: Doubt| {
            let (value, run_doubts) = sampled()?.into_parts();
            let mut doubts = Doubts::from(doubt);
            doubts.join(run_doubts);
            Ok(Certified { value, doubts })
        };
        if !opts.certify {
            return sampled_for(Doubt::CertificationOff);
        }
        // An analytic shape has no straight stretch: one taken as straight is its exact
        // form's precision running out, as a refusal as singular is.
        let lost = |r: &Result<Certified<T>>| match r {
            Err(Error::Cusp { .. }) => true,
            Ok(r) => r.doubts.first() == Some(&Doubt::FlatWithinRounding),
            Err(_) => false,
        };
        match run(self.source(true)) {
            r if self.simple && lost(&r) => {
                let degree = self.forms.as_ref().map_or(0, |f| f.hom.degree());
                sampled_for(Doubt::ExactFormPrecision { degree })
            }
            r => r,
        }
    }

    /// The frame the curve is computed in.
    pub fn frame(&self) -> Frame {
        self.frame
    }

    /// Every pair of antipodal points of the simple closed curve (Jia 2004); see
    /// [`crate::antipodal`].
    pub fn antipodal(&self, opts: &Options) -> Result<Antipodal> {
        let run = self.certified_or_sampled(opts, |src| antipodal_of(src, opts))?;
        let mut r: Antipodal = Provenance::finished(run);
        let f = &self.frame;
        for p in &mut r.pairs {
            p.p = f.to_global(p.p);
            p.q = f.to_global(p.q);
            p.distance = f.length_to_global(p.distance);
        }
        for i in &mut r.inflections {
            i.p = f.to_global(i.p);
        }
        Ok(r)
    }

    /// Every line tangent to this curve and `other` (Jia §2.5), in one frame for both (see
    /// [`prepare_pair`]; a curve prepared in another frame is prepared again in this one's).
    pub fn common_tangents(&self, other: &Prepared<'_>, opts: &Options) -> Result<Tangents> {
        Ok(Provenance::finished(self.tangents_run(other, opts)?))
    }

    /// [`Prepared::common_tangents`] with the doubts met, not yet stated.
    fn tangents_run(&self, other: &Prepared<'_>, opts: &Options) -> Result<Certified<Tangents>> {
        opts.validate()?;
        let again;
        let other = if other.frame == self.frame {
            other
        } else {
            again = Prepared::new(other.given.clone(), self.frame);
            &again
        };
        let same = std::ptr::addr_eq(self.given.curve(), other.given.curve());
        let mut run = tangents_of(
            self.source(opts.certify),
            other.source(opts.certify),
            same,
            opts,
        )?;
        for l in &mut run.value.lines {
            l.p = self.frame.to_global(l.p);
            l.q = self.frame.to_global(l.q);
        }
        Ok(run)
    }

    /// The simple inflections of the curve (Jia §5.1); see [`crate::inflections`].
    pub fn inflections(&self, opts: &Options) -> Result<Inflections> {
        Ok(Provenance::finished(self.inflections_run(opts)?))
    }

    /// [`Prepared::inflections`] with the doubts met, not yet stated.
    fn inflections_run(&self, opts: &Options) -> Result<Certified<Inflections>> {
        let mut run = self.certified_or_sampled(opts, |src| inflections_of(src, opts))?;
        for i in &mut run.value.inflections {
            i.p = self.frame.to_global(i.p);
        }
        Ok(run)
    }
}

/// Prepares a curve for repeated runs: the frame it is computed in (see [`Frame`]), the curve
/// moved there, its symbolic forms. A user asking once per curve may call the one-shot
/// functions instead ([`crate::antipodal`], [`crate::inflections`]), which prepare and run.
///
/// ```
/// use antipodal::{prepare, shapes::Ellipse, Options, Verdict};
/// let e = Ellipse::new(3.0, 2.0, [1e8, -1e8]).unwrap();
/// let p = prepare(&e);
/// let r = p.antipodal(&Options::default()).unwrap();
/// assert_eq!(r.pairs.len(), 2);
/// assert!(r.certified());
/// ```
pub fn prepare(curve: &dyn PlaneCurve) -> Prepared<'_> {
    let frame = frame_of(curve);
    Prepared::new(Given::Borrowed(curve), frame)
}

/// [`prepare`] on a curve shared with the prepared curve, which then borrows nothing: it can be
/// kept as long as needed and moved between threads (as a Python object keeps it).
///
/// ```
/// use antipodal::{prepare_shared, shapes::Ellipse, Options};
/// use std::sync::Arc;
/// let e = Arc::new(Ellipse::new(3.0, 2.0, [1.0, 2.0]).unwrap());
/// let p = std::thread::spawn(move || prepare_shared(e)).join().unwrap();
/// assert_eq!(p.antipodal(&Options::default()).unwrap().pairs.len(), 2);
/// ```
pub fn prepare_shared(curve: Arc<dyn PlaneCurve>) -> Prepared<'static> {
    let frame = frame_of(curve.as_ref());
    Prepared::new(Given::Shared(curve), frame)
}

/// The frame a curve is prepared in: one fitted to its control points, or the identity for
/// a curve known only by evaluation.
fn frame_of(curve: &dyn PlaneCurve) -> Frame {
    curve
        .exact()
        .map_or(Frame::IDENTITY, |e| Frame::for_points(&e.extent()))
}

/// [`crate::inflections`] on a curve, with the doubts met, not yet stated: for the runs that
/// join them into their own (a profile's segments).
pub(crate) fn inflections_run(
    curve: &dyn PlaneCurve,
    opts: &Options,
) -> Result<Certified<Inflections>> {
    prepare(curve).inflections_run(opts)
}

/// Two curves prepared in one frame (the identity when either is known only by evaluation),
/// for their common tangents.
///
/// ```
/// use antipodal::{prepare_pair, shapes::Circle, Options};
/// // Two unit circles side by side, prepared once, asked twice.
/// let (a, b) = (Circle::new(1.0, [0.0, 0.0]).unwrap(), Circle::new(1.0, [4.0, 0.0]).unwrap());
/// let (pa, pb) = prepare_pair(&a, &b);
/// assert_eq!(pa.frame(), pb.frame());
/// let first = pa.common_tangents(&pb, &Options::default()).unwrap();
/// assert_eq!(first, pa.common_tangents(&pb, &Options::default()).unwrap());
/// ```
pub fn prepare_pair<'c>(
    c1: &'c dyn PlaneCurve,
    c2: &'c dyn PlaneCurve,
) -> (Prepared<'c>, Prepared<'c>) {
    let frame = match (c1.exact(), c2.exact()) {
        (Some(a), Some(b)) => Frame::for_all(&[&a.extent(), &b.extent()]),
        _ => Frame::IDENTITY,
    };
    (
        Prepared::new(Given::Borrowed(c1), frame),
        Prepared::new(Given::Borrowed(c2), frame),
    )
}

/// [`crate::common_tangents`] of two curves, with the doubts met, not yet stated: for the runs
/// that join them into their own (a profile's segments).
pub(crate) fn common_tangents_run(
    c1: &dyn PlaneCurve,
    c2: &dyn PlaneCurve,
    opts: &Options,
) -> Result<Certified<Tangents>> {
    let (p1, p2) = prepare_pair(c1, c2);
    p1.tangents_run(&p2, opts)
}

#[cfg(test)]
pub(crate) mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    pub(crate) use testkit::stars::star_curve;

    /// `curve` prepared as it is (the identity frame: the views evaluate the curve itself).
    pub(crate) fn as_given(curve: &dyn PlaneCurve) -> Prepared<'_> {
        Prepared::new(super::Given::Borrowed(curve), Frame::IDENTITY)
    }
}
