//! The symbolic forms the certified algorithms need, computed once per curve, in the piecewise
//! Bézier form of `bspline` with bounds on their rounding.

use crate::bounds::BoundForms;
use crate::error::Result;
use crate::shapes::CircleShape;
use bspline::roots::{sign_changes_in, RootOptions, SignChanges};
use bspline::{Piecewise, Rational};
use std::sync::OnceLock;

/// How the homogeneous form of a curve continues across breaks and the seam, beyond what its
/// knots say.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Seam {
    /// Open, or closed with nothing known across the seam (a clamped closed spline).
    Unknown,
    /// A periodic curve whose homogeneous form is `C^order` across the seam.
    Periodic(i32),
    /// A shape on the rational circle: `C⁰` across the seam, numerators continuous at every
    /// break (see `CurvePieces::numerators_continuous`).
    Circle,
}

/// Symbolic forms of a rational plane curve, for the certified algorithms: its homogeneous
/// form, its tangent and tangency numerators and its curvature numerator, each with bounds on
/// its rounding. The curve types of this crate build them once, on first use, and keep them,
/// so that repeated runs on the same curve skip the symbolic products. Opaque.
#[derive(Debug, Clone)]
pub struct SymbolicForms {
    /// The curve itself.
    pub(crate) curve: Rational,
    /// How the forms continue across breaks and the seam.
    seam: Seam,
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
    /// For the shapes of this crate on their circle form: the formula in `(cos φ, sin φ)`.
    pub(crate) shape: Option<CircleShape>,
    /// The forms of the curve run backwards (a clockwise curve is viewed reversed).
    reversed: OnceLock<Option<Box<SymbolicForms>>>,
}

impl SymbolicForms {
    /// The forms of `curve` (planar), continued across its seam as `seam` says.
    pub(crate) fn new(curve: Rational, seam: Seam) -> Result<Self> {
        let mut pieces = bspline::symbolic::homogeneous_pieces(&curve);
        pieces = match seam {
            Seam::Unknown => pieces,
            Seam::Periodic(order) => pieces.periodic(order),
            Seam::Circle => pieces.periodic(0).numerators_continuous(),
        };
        Ok(Self {
            tangent: pieces.tangent()?,
            tangency: pieces.tangency()?,
            curvature: pieces.curvature()?,
            hom: pieces.hom,
            curve,
            seam,
            bounds: OnceLock::new(),
            size: OnceLock::new(),
            sign_changes: OnceLock::new(),
            shape: None,
            reversed: OnceLock::new(),
        })
    }

    /// The forms of the curve run backwards over the same domain, built on first use.
    pub(crate) fn reversed(&self) -> Option<&SymbolicForms> {
        self.reversed
            .get_or_init(|| {
                let r = crate::view::reverse(&self.curve).ok()?;
                SymbolicForms::new(r, self.seam).ok().map(Box::new)
            })
            .as_deref()
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

/// The kept circle forms of one of this crate's shapes, with its formula in `(cos φ, sin φ)`.
pub(crate) fn kept_circle(
    kept: &KeptForms,
    make: impl FnOnce() -> Option<Rational>,
    shape: CircleShape,
) -> Option<&SymbolicForms> {
    kept.get_or_init(|| {
        let mut f = SymbolicForms::new(make()?, Seam::Circle).ok()?;
        f.shape = Some(shape);
        Some(f)
    })
    .as_ref()
}

/// Forms kept by a curve, or built for one run.
pub(crate) enum Forms<'a> {
    Kept(&'a SymbolicForms),
    Built(Box<SymbolicForms>),
}

impl std::ops::Deref for Forms<'_> {
    type Target = SymbolicForms;
    fn deref(&self) -> &SymbolicForms {
        match self {
            Forms::Kept(f) => f,
            Forms::Built(f) => f,
        }
    }
}

/// A lazily built, kept set of forms (`None` inside when they cannot be built).
pub(crate) type KeptForms = OnceLock<Option<SymbolicForms>>;

/// The kept forms of `kept`, building them from `make` (the curve and how it continues across
/// its seam) on first use.
pub(crate) fn kept(
    kept: &KeptForms,
    make: impl FnOnce() -> Option<(Rational, Seam)>,
) -> Option<&SymbolicForms> {
    kept.get_or_init(|| make().and_then(|(r, seam)| SymbolicForms::new(r, seam).ok()))
        .as_ref()
}
