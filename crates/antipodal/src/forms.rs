//! The symbolic B-spline forms the certified algorithms need, computed once per curve.

use crate::bounds::BoundForms;
use crate::error::Result;
use crate::fast::Pw;
use crate::shapes::CircleShape;
use bspline::roots::{sign_changes, RootOptions, SignChanges};
use bspline::{BSpline, Rational};
use std::sync::OnceLock;

/// Symbolic B-spline forms of a rational plane curve, for the certified algorithms: its tangent
/// and tangency numerators, its curvature numerator, and their Bézier pieces. The curve types
/// of this crate build them once, on first use, and keep them, so that repeated runs on the
/// same curve skip the symbolic products. Opaque.
#[derive(Debug, Clone)]
pub struct SymbolicForms {
    /// The curve itself.
    pub(crate) curve: Rational,
    /// Tangent numerator `D` (dim 2): `C′ = D / w²`.
    pub(crate) tangent: BSpline,
    /// `D` as Bézier pieces: `D · n` is the sign function of point-with-normal.
    pub(crate) tangent_pw: Pw,
    /// `(A, Dₓ, D_y)` with `A = X × X′`, `D = wX′ − w′X`, as Bézier pieces:
    /// `A − q × D = (X − qw) × (X − qw)′` is the sign function of point-of-tangency from `q`
    /// (`None` if the two do not share their pieces).
    pub(crate) tangency_pw: Option<Pw>,
    /// The homogeneous curve `(X, w)` as Bézier pieces: `(X − qw) · v` is the sign function of
    /// point-on-ray.
    pub(crate) hom_pw: Pw,
    /// The curvature numerator (its roots are the inflections).
    pub(crate) curvature: BSpline,
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
    /// The forms of `curve` (planar).
    pub(crate) fn new(curve: Rational) -> Result<Self> {
        let tangent = bspline::symbolic::tangent_numerator(&curve)?;
        let tangent_pw = Pw::new(&tangent);
        let tangency_pw = tangency_parts(&curve).map(|b| Pw::new(&b));
        let hom_pw = Pw::new(curve.homogeneous());
        let curvature = bspline::symbolic::curvature_numerator(&curve)?;
        Ok(Self {
            curve,
            tangent,
            tangent_pw,
            tangency_pw,
            hom_pw,
            curvature,
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
                SymbolicForms::new(r).ok().map(Box::new)
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
            .get_or_init(|| BoundForms::new(&self.curve, &self.tangent, &self.curvature))
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
        let found = sign_changes(&self.curvature, closed, opts)?;
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
        let mut f = SymbolicForms::new(make()?).ok()?;
        f.shape = Some(shape);
        Some(f)
    })
    .as_ref()
}

/// `(A, D)` stacked (dim 3): `A = X × X′` and `D = wX′ − w′X`, both of degree `2p − 1` on the
/// curve's knots, so that `(X − qw) × (X − qw)′ = A − q × D` for every point `q`.
fn tangency_parts(c: &Rational) -> Option<BSpline> {
    let h = c.homogeneous();
    let x = h.map_points(2, |p, o| o.copy_from_slice(&p[..2]));
    let xd = x.deriv();
    let a = x.cross(&xd).ok()?;
    let w = h.component(2).ok()?;
    let d = w.mul(&xd).ok()?.sub(&w.deriv().mul(&x).ok()?).ok()?;
    if a.degree() != d.degree() || a.knots() != d.knots() {
        return None;
    }
    BSpline::stack(&[&a, &d]).ok()
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

/// The kept forms of `kept`, building them from `make` on first use.
pub(crate) fn kept(
    kept: &KeptForms,
    make: impl FnOnce() -> Option<Rational>,
) -> Option<&SymbolicForms> {
    kept.get_or_init(|| make().and_then(|r| SymbolicForms::new(r).ok()))
        .as_ref()
}
