//! An analytic shape seen in the parameter `u ∈ [0, 4]` of the rational circle (circle angle
//! `ψ = angle(u)`): the parameter of its exact rational form, in which the algorithms decide
//! by sign tests. Its jets come from the shape's formula in `(cos ψ, sin ψ)` through the chain
//! rule through `ψ(u)`; parameters map back to the shape's own angle φ by [`Angle`] (`φ = ψ`,
//! except for the elliptic lemniscate, the inverse of an ellipse, where
//! `tan φ = (a/b) tan ψ`).

use crate::circle::{frame_cs, Angle};
use crate::geom::Jet;
use crate::param::ParamCurve;
use crate::shapes::CircleShape;

/// A shape in the rational circle's parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OnCircle {
    shape: CircleShape,
}

impl OnCircle {
    /// The shape given by its formula on the circle.
    pub fn new(shape: CircleShape) -> Self {
        Self { shape }
    }

    /// The formula.
    pub fn shape(&self) -> CircleShape {
        self.shape
    }

    /// How this parameter maps back to the shape's angle.
    pub fn angle(&self) -> Angle {
        self.shape.angle()
    }
}

impl ParamCurve for OnCircle {
    fn domain(&self) -> (f64, f64) {
        (0.0, 4.0)
    }
    fn is_closed(&self) -> bool {
        true
    }
    #[inline]
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        // The shape's own formula from (cos φ, sin φ): no angle, no sine or cosine.
        let f = frame_cs(u);
        let [a1, a2, a3] = f.d;
        let j = self.shape.jet(f.cs[0], f.cs[1], order);
        // Chain rule, up to the order asked for (the rest is left zero).
        let mut out = Jet {
            p: j.p,
            d1: j.d1 * a1,
            ..Jet::default()
        };
        if order >= 2 {
            out.d2 = j.d2 * (a1 * a1) + j.d1 * a2;
        }
        if order >= 3 {
            out.d3 = j.d3 * (a1 * a1 * a1) + j.d2 * (3.0 * a1 * a2) + j.d1 * a3;
        }
        out
    }
}
