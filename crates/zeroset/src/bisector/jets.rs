//! Points and derivatives of the two curves, evaluated where the bisector's vertices are
//! placed and checked: thousands of times per bisector, so by de Casteljau on the curves'
//! Bézier pieces (extracted once) rather than by de Boor's recurrence on the knots.

use bspline::{Piecewise, Rational};

/// A planar rational curve prepared for repeated evaluation.
pub(super) struct Jets {
    /// The homogeneous form `(w·x, w·y, w)` as Bézier pieces.
    hom: Piecewise,
}

impl Jets {
    /// `curve` must be planar (the bisector's curves are checked to be).
    pub(super) fn of(curve: &Rational) -> Self {
        Self {
            hom: Piecewise::from_bspline(curve.homogeneous()),
        }
    }

    /// Point and derivatives up to order `k ≤ 3` at `u` (clamped into the domain):
    /// `out[2j..2j + 2]` is the j-th derivative; the right-hand ones at a knot.
    pub(super) fn derivs(&self, u: f64, k: usize) -> [f64; 8] {
        let mut out = [0.0; 8];
        curve::rational_derivs(&self.hom, u, k, &mut out);
        out
    }

    /// The homogeneous form's Bézier pieces.
    pub(super) fn pieces(&self) -> &Piecewise {
        &self.hom
    }

    /// Point and first derivative at `u`.
    pub(super) fn point_tangent(&self, u: f64) -> ([f64; 2], [f64; 2]) {
        let o = self.derivs(u, 1);
        ([o[0], o[1]], [o[2], o[3]])
    }
}
