//! The symbolic forms the certified algorithms need, computed once per curve, in the piecewise
//! Bézier form of `bspline` with bounds on their rounding.

use crate::bounds::BoundForms;
use crate::error::Result;
use bspline::roots::{sign_changes_in, RootOptions, SignChanges};
use bspline::symbolic::CurvePieces;
use bspline::Piecewise;
use std::sync::OnceLock;

/// Symbolic forms of a rational plane curve, for the certified algorithms: its homogeneous
/// form, its tangent and tangency numerators and its curvature numerator, each with bounds on
/// its rounding. A prepared curve builds them once and keeps them, with the enclosures and
/// sign changes later runs ask for. Opaque.
#[derive(Debug, Clone)]
pub struct SymbolicForms {
    /// The curve's exact form (kept for its reversal).
    pieces: CurvePieces,
    /// The homogeneous curve `(X, w)`: `(X − qw) · v` is the sign function of point-on-ray.
    pub(crate) hom: Piecewise,
    /// Tangent numerator `D` (dim 2): `C′ = D / w²`; `D · n` is the sign function of
    /// point-with-normal.
    pub(crate) tangent: Piecewise,
    /// `(A, Dₓ, D_y)` with `A = X × X′`: `A − q × D = (X − qw) × (X − qw)′` is the sign
    /// function of point-of-tangency from `q`.
    pub(crate) tangency: Piecewise,
    /// The curvature numerator (its roots are the inflections).
    pub(crate) curvature: Piecewise,
    /// Enclosures of the curvature over intervals, built on first use.
    bounds: OnceLock<Option<BoundForms>>,
    /// The curve's size (see `View::scale`), measured on first use.
    size: OnceLock<f64>,
    /// Its sign changes, with the options and closedness they were found with.
    sign_changes: OnceLock<(RootOptions, bool, SignChanges)>,
    /// The forms of the curve run backwards (a clockwise curve is viewed reversed).
    reversed: OnceLock<Option<Box<SymbolicForms>>>,
    /// The breaks where the curvature may jump, and whether it may across the seam.
    jumps: OnceLock<(Vec<f64>, bool)>,
}

impl SymbolicForms {
    /// The forms of a curve's exact form.
    pub(crate) fn new(pieces: CurvePieces) -> Result<Self> {
        Ok(Self {
            tangent: pieces.tangent()?,
            tangency: pieces.tangency()?,
            curvature: pieces.curvature()?,
            hom: pieces.hom.clone(),
            pieces,
            bounds: OnceLock::new(),
            size: OnceLock::new(),
            sign_changes: OnceLock::new(),
            reversed: OnceLock::new(),
            jumps: OnceLock::new(),
        })
    }

    /// The forms of the curve run backwards over the same domain, built on first use.
    pub(crate) fn reversed(&self) -> Option<&SymbolicForms> {
        self.reversed
            .get_or_init(|| {
                let r = self.pieces.reversed()?;
                SymbolicForms::new(r).ok().map(Box::new)
            })
            .as_deref()
    }

    /// Proves the curve regular (its tangent never vanishes): `None` when `|D|²` is proven
    /// positive on the whole domain, else a parameter near which the speed is within rounding
    /// of zero (a cusp or a stationary point), to the tolerance `tol`.
    pub(crate) fn singular_point(&self, tol: f64) -> Result<Option<f64>> {
        Ok(self.pieces.singular_point(tol)?)
    }

    /// The curve's size, measured by `measure` on first use.
    pub(crate) fn size(&self, measure: impl FnOnce() -> f64) -> f64 {
        *self.size.get_or_init(measure)
    }

    /// The enclosures of [`crate::view::View::arc_bounds`].
    pub(crate) fn bound_forms(&self) -> Option<&BoundForms> {
        self.bounds
            .get_or_init(|| BoundForms::new(&self.hom, &self.tangent, &self.curvature))
            .as_ref()
    }

    /// The breaks where the curvature may jump ([`BoundForms::curvature_jumps`]), and whether
    /// it may across the seam, found on first use; every break where the homogeneous form is
    /// less than `C²` where the enclosures cannot tell.
    pub(crate) fn curvature_jumps(&self) -> &(Vec<f64>, bool) {
        self.jumps.get_or_init(|| match self.bound_forms() {
            Some(b) => b.curvature_jumps(),
            None => {
                let breaks = self.hom.breaks();
                let last = breaks.len() - 1;
                let inner = (1..last)
                    .filter(|&k| self.hom.continuity(k) < 2)
                    .map(|k| breaks[k])
                    .collect();
                (inner, self.hom.continuity(0) < 2)
            }
        })
    }

    /// The sign changes of the curvature numerator over the domain (closed: a circle), kept
    /// for the next call with the same options.
    pub(crate) fn curvature_sign_changes(
        &self,
        opts: &RootOptions,
        closed: bool,
    ) -> Result<SignChanges> {
        if let Some((o, c, s)) = self.sign_changes.get() {
            if o == opts && *c == closed {
                return Ok(s.clone());
            }
        }
        let found = sign_changes_in(&self.curvature, closed, opts)?;
        let _ = self.sign_changes.set((*opts, closed, found.clone()));
        Ok(found)
    }
}
