//! What the algorithms take ([`PlaneCurve`]): evaluation, and, for the curve kinds of this
//! crate, an exact description ([`Exact`]) from which certified decisions and exact changes of
//! frame are made. (The kinds' evaluation lives with them; this module, above them, says which
//! are exact.)

use crate::frame::Frame;
use crate::on_circle::OnCircle;
use crate::param::ParamCurve;
use crate::shapes::{Circle, Convexities, Ellipse, EllipticLemniscate, Limacon, Shape};
use crate::spline::SplineCurve;

/// A curve the algorithms take: evaluation, and what else it offers. Curves are data, so they
/// are `Send` and `Sync`: a prepared curve may keep one and move between threads.
pub trait PlaneCurve: ParamCurve + Send + Sync {
    /// The curve's exact description, when it has one (the curve kinds of this crate do): the
    /// algorithms then decide by sign tests on its exact rational form, in a frame of their
    /// choosing. `None` (a curve known only by evaluation): Jia's sampled method, uncertified.
    fn exact(&self) -> Option<Exact<'_>> {
        None
    }
}

/// The exact description of one of this crate's curve kinds.
#[derive(Debug, Clone, Copy)]
pub enum Exact<'a> {
    /// A B-spline or NURBS curve.
    Spline(&'a SplineCurve),
    /// An analytic shape.
    Shape(Shape),
}

impl Exact<'_> {
    /// Points whose box holds the curve (control points; the shape's box), for choosing a
    /// frame.
    pub fn extent(&self) -> Vec<[f64; 2]> {
        match self {
            Exact::Spline(s) => s.control_points(),
            Exact::Shape(s) => s.extent().to_vec(),
        }
    }

    /// The same curve in `frame`, owned; exact where the frame was chosen for it (see
    /// [`Frame`]), with any rounding of the change carried as error of its coefficients.
    pub fn in_frame(&self, frame: &Frame) -> ExactCurve {
        match self {
            Exact::Spline(s) => ExactCurve::Spline(Box::new(s.in_frame(frame))),
            Exact::Shape(s) => ExactCurve::Shape(s.in_frame(frame)),
        }
    }
}

/// One of this crate's curve kinds, owned: a curve moved into a frame (see
/// [`Exact::in_frame`]), or the smooth closed curve a segment runs once round (see
/// [`crate::Segment::whole_curve`]).
#[derive(Debug, Clone, PartialEq)]
pub enum ExactCurve {
    /// A B-spline or NURBS curve.
    Spline(Box<SplineCurve>),
    /// An analytic shape.
    Shape(Shape),
}

impl ExactCurve {
    /// The curve as the algorithms evaluate it.
    pub fn curve(&self) -> &dyn PlaneCurve {
        match self {
            ExactCurve::Spline(s) => s.as_ref(),
            ExactCurve::Shape(s) => s,
        }
    }
}

impl PlaneCurve for Shape {
    fn exact(&self) -> Option<Exact<'_>> {
        Some(Exact::Shape(*self))
    }
}

/// Each shape is exact as itself.
macro_rules! exact_shape {
    ($t:ident) => {
        impl PlaneCurve for $t {
            fn exact(&self) -> Option<Exact<'_>> {
                Some(Exact::Shape(Shape::$t(*self)))
            }
        }
    };
}
exact_shape!(Circle);
exact_shape!(Ellipse);
exact_shape!(Limacon);
exact_shape!(EllipticLemniscate);
exact_shape!(Convexities);

impl PlaneCurve for SplineCurve {
    fn exact(&self) -> Option<Exact<'_>> {
        Some(Exact::Spline(self))
    }
}

/// A shape in the rational circle's parameter is known to the algorithms by evaluation: its
/// exact form is its shape's.
impl PlaneCurve for OnCircle {}
