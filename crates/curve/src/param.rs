//! What a curve offers the algorithms: evaluation ([`ParamCurve`]), and, for the curve kinds
//! of this crate, an exact description ([`Exact`]) from which certified decisions and exact
//! changes of frame are made.

use crate::frame::Frame;
use crate::geom::Jet;
use crate::shapes::Shape;
use crate::spline::SplineCurve;

/// A regular parametric plane curve with three continuous derivatives (piecewise for splines).
pub trait ParamCurve {
    /// The parameter domain `[a, b]`; a closed curve has period `b − a`.
    fn domain(&self) -> (f64, f64);
    /// True when the curve is closed (`C(a) = C(b)` with matching tangents).
    fn is_closed(&self) -> bool;
    /// Point and derivatives up to `order` (≤ 3) at `u ∈ [a, b]`; higher entries may be left
    /// zero.
    fn jet_to(&self, u: f64, order: usize) -> Jet;
    /// Point and first three derivatives at `u`.
    fn jet(&self, u: f64) -> Jet {
        self.jet_to(u, 3)
    }
}

/// A curve the algorithms take: evaluation, and what else it offers.
pub trait PlaneCurve: ParamCurve {
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
    pub fn in_frame(&self, frame: &Frame) -> Local {
        match self {
            Exact::Spline(s) => Local::Spline(Box::new(s.in_frame(frame))),
            Exact::Shape(s) => Local::Shape(s.in_frame(frame)),
        }
    }
}

/// A curve of this crate moved into a frame (see [`Exact::in_frame`]).
#[derive(Debug, Clone)]
pub enum Local {
    /// A B-spline or NURBS curve.
    Spline(Box<SplineCurve>),
    /// An analytic shape.
    Shape(Shape),
}

impl Local {
    /// The curve as the algorithms evaluate it.
    pub fn curve(&self) -> &dyn PlaneCurve {
        match self {
            Local::Spline(s) => s.as_ref(),
            Local::Shape(s) => s,
        }
    }
}
