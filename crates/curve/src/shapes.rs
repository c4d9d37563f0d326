//! The analytic shapes of the curve files, defined once: their parameters (validated), their
//! jets in the angle φ, their formulas in the cosine and sine of the rational circle's angle,
//! and their exact rational forms on that circle, with bounds on the forms' coefficients. All
//! run counterclockwise over `φ ∈ [0, 2π)`.

mod jets;
mod kinds;
mod rational_form;

pub use jets::CircleShape;
pub use kinds::{Circle, Convexities, Ellipse, EllipticLemniscate, Limacon};

use crate::frame::Frame;
use crate::geom::{Jet, V2};
use crate::param::ParamCurve;
use bspline::symbolic::CurvePieces;
use rational_form::circle_form;
pub(crate) use rational_form::circle_form_spline;
use std::f64::consts::TAU;

/// The most slender elliptic lemniscate (`a/b` or `b/a`) run on its circle form. Beyond, the
/// lobes are so nearly circular (θ of order `(b/a)⁴` across them) that no stretch of them is
/// proven monotone: the march crawls and the sampled width settles them on either path (from
/// `a/b = 6` on). The form would only cost precision there: its parameter runs up to `a/b`
/// times slower than φ, and the lobes' nearly singular pairs come out that much coarser (at
/// `a/b = 200`, 2e-5 in φ against 6e-8; at 300, families at the default tolerance).
const MAX_SQUEEZE: f64 = 5.0;

/// One of the analytic shapes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A circle.
    Circle(Circle),
    /// An ellipse.
    Ellipse(Ellipse),
    /// A limaçon.
    Limacon(Limacon),
    /// An elliptic lemniscate.
    EllipticLemniscate(EllipticLemniscate),
    /// A curve with convexities.
    Convexities(Convexities),
}

impl Shape {
    /// The `kind` of the curve files.
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Circle(_) => "circle",
            Shape::Ellipse(_) => "ellipse",
            Shape::Limacon(_) => "limacon",
            Shape::EllipticLemniscate(_) => "elliptic_lemniscate",
            Shape::Convexities(_) => "convexities",
        }
    }

    /// How many times the shape's curvature oscillates around it (the lobes of a curve with
    /// convexities; 1 for the others): what a sampled search must resolve.
    pub fn lobes(&self) -> u32 {
        match self {
            Shape::Convexities(c) => c.m,
            _ => 1,
        }
    }

    /// Two corners of a box holding the shape.
    pub fn extent(&self) -> [[f64; 2]; 2] {
        let boxed = |c: V2, rx: f64, ry: f64| [[c.x - rx, c.y - ry], [c.x + rx, c.y + ry]];
        let origin = V2::new(0.0, 0.0);
        match *self {
            Shape::Circle(c) => boxed(c.center, c.r, c.r),
            Shape::Ellipse(e) => boxed(e.center, e.a, e.b),
            Shape::Limacon(l) => boxed(origin, l.a + l.b, l.a + l.b),
            Shape::EllipticLemniscate(l) => boxed(origin, l.a.max(l.b), l.a.max(l.b)),
            Shape::Convexities(c) => {
                let r = c.p / (1.0 - c.eps);
                boxed(origin, r, r)
            }
        }
    }

    /// The same shape in `frame`: lengths scaled by its power of two (exact), the center
    /// moved (exact for the frame chosen for the shape's extent). The shapes without a center
    /// lie about the origin, which such a frame keeps.
    pub fn in_frame(&self, frame: &Frame) -> Shape {
        let len = |x: f64| frame.length_to_local(x);
        let at = |c: V2| V2::from_arr(frame.to_local(c.arr()));
        match *self {
            Shape::Circle(c) => Shape::Circle(Circle {
                r: len(c.r),
                center: at(c.center),
            }),
            Shape::Ellipse(e) => Shape::Ellipse(Ellipse {
                a: len(e.a),
                b: len(e.b),
                center: at(e.center),
            }),
            Shape::Limacon(l) => Shape::Limacon(Limacon {
                a: len(l.a),
                b: len(l.b),
            }),
            Shape::EllipticLemniscate(l) => Shape::EllipticLemniscate(EllipticLemniscate {
                a: len(l.a),
                b: len(l.b),
            }),
            Shape::Convexities(c) => Shape::Convexities(Convexities { p: len(c.p), ..c }),
        }
    }

    /// The shape's formula in the cosine and sine of the rational circle's angle, when it has
    /// an exact form on that circle (all but the slender lemniscates; a circle is an ellipse
    /// with equal axes).
    pub fn circle_shape(&self) -> Option<CircleShape> {
        match *self {
            Shape::Circle(c) => Some(CircleShape::Ellipse {
                a: c.r,
                b: c.r,
                center: c.center,
            }),
            Shape::Ellipse(e) => Some(CircleShape::Ellipse {
                a: e.a,
                b: e.b,
                center: e.center,
            }),
            Shape::Limacon(l) => Some(CircleShape::Limacon { a: l.a, b: l.b }),
            Shape::EllipticLemniscate(l) => ((l.a / l.b).max(l.b / l.a) <= MAX_SQUEEZE)
                .then_some(CircleShape::Lemniscate { a: l.a, b: l.b }),
            Shape::Convexities(c) => Some(CircleShape::Convexities {
                p: c.p,
                eps: c.eps,
                m: c.m,
            }),
        }
    }

    /// True when the shape is exactly a circle by its parameters (a circle, an ellipse with
    /// equal axes): every pair of its opposite points is antipodal, one continuous family,
    /// which no computation in rounded arithmetic can tell from a curve that is nearly a
    /// circle.
    pub fn is_exact_circle(&self) -> bool {
        match *self {
            Shape::Circle(_) => true,
            Shape::Ellipse(e) => e.a == e.b,
            _ => false,
        }
    }

    /// The exact rational form on the rational circle (see [`crate::circle`]) in pieces, with
    /// bounds on its coefficients, when the shape has one ([`Shape::circle_shape`]).
    pub fn exact_pieces(&self) -> Option<CurvePieces> {
        let form = self.circle_shape()?;
        let hom = circle_form(form).ok()?;
        let pieces = CurvePieces::new(hom, false).ok()?;
        Some(pieces.periodic(0).numerators_continuous())
    }

    fn as_curve(&self) -> &dyn ParamCurve {
        match self {
            Shape::Circle(c) => c,
            Shape::Ellipse(c) => c,
            Shape::Limacon(c) => c,
            Shape::EllipticLemniscate(c) => c,
            Shape::Convexities(c) => c,
        }
    }
}

impl ParamCurve for Shape {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        self.as_curve().jet_to(u, order)
    }
}
