//! What every curve offers the algorithms: evaluation ([`ParamCurve`]). What the curve kinds
//! of this crate offer beside it is in [`crate::PlaneCurve`].

use crate::geom::Jet;

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
