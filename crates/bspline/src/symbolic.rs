//! Exact symbolic building blocks for planar curves, as scalar functions.
//!
//! Each function returns a *numerator*: a function with the same sign as the geometric quantity
//! (for a rational curve the quantity equals the numerator divided by a positive power of the
//! weight). Sign decisions, and so root isolation, can therefore be made on the numerator.
//!
//! The numerators are written once, over the operations both forms of a function share: the
//! smooth B-spline (exact algebra with the least knots, [`tangent_numerator`],
//! [`curvature_numerator`]) and the piecewise Bézier form with error bounds that certified
//! decisions read ([`homogeneous_pieces`], [`CurvePieces`]).

use crate::error::{Error, Result};
use crate::piecewise::Piecewise;
use crate::rational::Rational;
use crate::spline::BSpline;

/// The operations the numerators are built from.
trait Algebra: Sized {
    fn derivative(&self) -> Self;
    /// Product of a scalar function with a function of any dimension.
    fn times(&self, other: &Self) -> Result<Self>;
    fn minus(&self, other: &Self) -> Result<Self>;
    fn cross2(&self, other: &Self) -> Result<Self>;
    fn cross3d(&self, other: &Self) -> Result<Self>;
    fn dotted(&self, other: &Self) -> Result<Self>;
    fn scaled(&self, s: f64) -> Self;
    /// The coordinates `which`, as a function of that dimension.
    fn parts(&self, which: &[usize]) -> Result<Self>;
}

/// The operations both forms have under the same names (`mul`, `sub`, `cross`, `cross3`,
/// `dot`, `scale`): one forwarding written for the two impls.
macro_rules! same_named_operations {
    () => {
        fn times(&self, other: &Self) -> Result<Self> {
            self.mul(other)
        }
        fn minus(&self, other: &Self) -> Result<Self> {
            self.sub(other)
        }
        fn cross2(&self, other: &Self) -> Result<Self> {
            self.cross(other)
        }
        fn cross3d(&self, other: &Self) -> Result<Self> {
            self.cross3(other)
        }
        fn dotted(&self, other: &Self) -> Result<Self> {
            self.dot(other)
        }
        fn scaled(&self, s: f64) -> Self {
            self.scale(s)
        }
    };
}

impl Algebra for BSpline {
    fn derivative(&self) -> Self {
        self.deriv()
    }
    same_named_operations!();
    fn parts(&self, which: &[usize]) -> Result<Self> {
        let dim = self.dim();
        if let Some(&k) = which.iter().find(|&&k| k >= dim) {
            return Err(Error::DimensionMismatch {
                expected: dim,
                got: k + 1,
            });
        }
        Ok(self.map_points(which.len(), |src, dst| {
            for (d, &k) in dst.iter_mut().zip(which) {
                *d = src[k];
            }
        }))
    }
}

impl Algebra for Piecewise {
    fn derivative(&self) -> Self {
        Piecewise::derivative(self)
    }
    same_named_operations!();
    fn parts(&self, which: &[usize]) -> Result<Self> {
        self.components(which)
    }
}

/// The homogeneous planar curve `H = (X, Y, w)` with its weight: constant (`Some(w₀)`, a
/// polynomial curve) or not.
struct Homogeneous<'a, F> {
    h: &'a F,
    constant_weight: Option<f64>,
}

impl<F: Algebra> Homogeneous<'_, F> {
    fn euclidean(&self) -> Result<F> {
        self.h.parts(&[0, 1])
    }

    /// `D = wX′ − w′X`: `C′ = D / w²` (for a constant weight `w₀ X′`).
    fn tangent(&self) -> Result<F> {
        let x = self.euclidean()?;
        match self.constant_weight {
            Some(1.0) => Ok(x.derivative()),
            Some(w0) => Ok(x.derivative().scaled(w0)),
            None => {
                let w = self.h.parts(&[2])?;
                w.times(&x.derivative())?.minus(&w.derivative().times(&x)?)
            }
        }
    }

    /// `K = det[H, H′, H″] = w³ (C′ × C″)` (for a constant weight `w₀ (X′ × X″)`).
    fn curvature(&self) -> Result<F> {
        match self.constant_weight {
            Some(w0) => {
                let d1 = self.euclidean()?.derivative();
                let k = d1.cross2(&d1.derivative())?;
                Ok(if w0 == 1.0 { k } else { k.scaled(w0) })
            }
            None => {
                let d1 = self.h.derivative();
                self.h.dotted(&d1.cross3d(&d1.derivative())?)
            }
        }
    }
}

fn planar(c: &Rational) -> Result<()> {
    if c.dim() != 2 {
        return Err(Error::DimensionMismatch {
            expected: 2,
            got: c.dim(),
        });
    }
    Ok(())
}

/// The weight of a polynomial curve (all weight coefficients equal), if it is one.
fn constant_weight(c: &Rational) -> Option<f64> {
    (!c.is_rational()).then(|| c.homogeneous().ctrl(0)[2])
}

/// `D = X′w − Xw′`, the numerator of the tangent: `C′ = D / w²`. For a polynomial curve
/// (weight 1) `D = C′`.
pub fn tangent_numerator(c: &Rational) -> Result<BSpline> {
    planar(c)?;
    Homogeneous {
        h: c.homogeneous(),
        constant_weight: constant_weight(c),
    }
    .tangent()
}

/// The curvature numerator `K = det[H, H′, H″]`, which equals `w³ (x′y″ − x″y′)`: degree
/// `3p − 3` for a rational curve, `x′y″ − x″y′` of degree `2p − 3` for a polynomial one
/// (weight 1). Its roots are the inflections; its sign is the side the curve turns to.
///
/// ```
/// use bspline::{symbolic, BSpline, Rational};
/// // y = x³ on [-1, 1] has its inflection at the parameter 0.5.
/// let c = BSpline::bezier(2, vec![-1., -1., -1. / 3., 1., 1. / 3., -1., 1., 1.]).unwrap();
/// let k = symbolic::curvature_numerator(&Rational::polynomial(&c)).unwrap();
/// assert!(k.eval_scalar(0.5).abs() < 1e-14);
/// assert!(k.eval_scalar(0.2) < 0.0 && k.eval_scalar(0.8) > 0.0);
/// ```
pub fn curvature_numerator(c: &Rational) -> Result<BSpline> {
    planar(c)?;
    if c.degree() < 2 {
        let (a, b) = c.domain();
        return BSpline::constant(&[0.0], 0, a, b);
    }
    Homogeneous {
        h: c.homogeneous(),
        constant_weight: constant_weight(c),
    }
    .curvature()
}

/// A planar curve in pieces: its homogeneous form `(X, Y, w)` with error bounds, and whether
/// its weight is exactly 1 (a polynomial curve: the numerators then take their lower-degree
/// forms). Built by [`homogeneous_pieces`].
#[derive(Debug, Clone, PartialEq)]
pub struct CurvePieces {
    /// The homogeneous form (dimension 3).
    pub hom: Piecewise,
    /// The weight is exactly 1 everywhere.
    pub polynomial: bool,
    /// The numerators are continuous at every break (and across a periodic seam) whatever
    /// the form's knots say ([`CurvePieces::numerators_continuous`]).
    continuous: bool,
}

/// The curve's homogeneous form in pieces, with the error of the curve's own homogeneous
/// coefficients ([`Rational::coefficient_error`]) and of the extraction. A polynomial curve
/// keeps its weight at exactly 1 (the knot insertion may round `α + (1 − α)` off it; the exact
/// weight is 1).
pub fn homogeneous_pieces(c: &Rational) -> CurvePieces {
    let mut hom = Piecewise::from_bspline_with_error(c.homogeneous(), c.coefficient_error());
    let polynomial = constant_weight(c) == Some(1.0);
    if polynomial {
        hom = hom.with_coordinate(2, 1.0);
    }
    CurvePieces {
        hom,
        polynomial,
        continuous: false,
    }
}

impl CurvePieces {
    /// A curve from its homogeneous pieces (dimension 3); `polynomial` vouches that the weight
    /// is exactly 1.
    pub fn new(hom: Piecewise, polynomial: bool) -> Result<Self> {
        if hom.dim() != 3 {
            return Err(Error::DimensionMismatch {
                expected: 3,
                got: hom.dim(),
            });
        }
        let hom = if polynomial {
            hom.with_coordinate(2, 1.0)
        } else {
            hom
        };
        Ok(Self {
            hom,
            polynomial,
            continuous: false,
        })
    }

    /// The curve declared periodic, its homogeneous form continuous to `order` across the
    /// seam (`p − 1` for a periodic B-spline of degree p).
    pub fn periodic(mut self, order: i32) -> Self {
        self.hom = self.hom.with_periodic_seam(order);
        self
    }

    /// The same curve run backwards over the same domain (see [`Piecewise::reversed`]).
    pub fn reversed(&self) -> Option<Self> {
        Some(Self {
            hom: self.hom.reversed()?,
            ..*self
        })
    }

    /// Declares the tangent, tangency and curvature numerators continuous at every break
    /// (and across the seam of a periodic curve), as they are for a curve `C¹` in its
    /// parameter with a continuous curvature numerator: the shapes on the rational circle,
    /// whose homogeneous form is only `C⁰` at the quarters, are such curves (the Möbius
    /// reparametrisations of the quarters match speeds, and `C′ × C″` loses the jump of
    /// `C″` along `C′`). The caller vouches for it.
    pub fn numerators_continuous(mut self) -> Self {
        self.continuous = true;
        self
    }

    /// A numerator with the continuity the caller declared.
    fn declared(&self, f: Piecewise) -> Piecewise {
        if self.continuous {
            f.with_continuity(0)
        } else {
            f
        }
    }

    fn forms(&self) -> Homogeneous<'_, Piecewise> {
        Homogeneous {
            h: &self.hom,
            constant_weight: self.polynomial.then_some(1.0),
        }
    }

    /// [`tangent_numerator`] with its error bounds: `D = wX′ − w′X` (dimension 2; `X′` for a
    /// polynomial curve).
    pub fn tangent(&self) -> Result<Piecewise> {
        Ok(self.declared(self.forms().tangent()?))
    }

    /// [`curvature_numerator`] with its error bounds.
    pub fn curvature(&self) -> Result<Piecewise> {
        Ok(self.declared(self.forms().curvature()?))
    }

    /// `(A, Dₓ, D_y)`: `A = X × X′` and the tangent numerator `D` of the general formula
    /// (raised to one degree), so that for every point `q` the combination
    /// `A + q_y Dₓ − qₓ D_y = (X − qw) × (X − qw)′` is the numerator of `(C − q) × C′`: zero
    /// where the tangent line passes through `q` (weights `[1, q_y, −qₓ]`).
    pub fn tangency(&self) -> Result<Piecewise> {
        let x = self.hom.components(&[0, 1])?;
        let a = x.cross(&Piecewise::derivative(&x))?;
        let d = Homogeneous {
            h: &self.hom,
            constant_weight: None,
        }
        .tangent()?;
        Ok(self.declared(Piecewise::stack(&[&a, &d])?))
    }

    /// Proves that the curve is regular (its tangent never vanishes): `Ok(None)` when `|D|²`
    /// is proven positive on the whole domain, else `Ok(Some(u))` with a parameter near which
    /// the speed is within rounding of zero (a cusp or a stationary point), to the parameter
    /// tolerance `tol`.
    pub fn singular_point(&self, tol: f64) -> Result<Option<f64>> {
        let d = self.tangent()?;
        let speed2 = d.dot(&d)?;
        let (a, b) = speed2.domain();
        let opts = crate::roots::RootOptions::default().tolerance(tol);
        crate::roots::prove_positive_in(&speed2, a, b, &opts)
    }
}

/// [`CurvePieces::singular_point`] of a curve.
///
/// ```
/// use bspline::{symbolic, BSpline, Rational};
/// // (u², u³) on [-1, 1], as a cubic Bézier on [0, 1]: a cusp at the parameter 0.5.
/// let cusp = BSpline::bezier(2, vec![1., -1., -1. / 3., 1., -1. / 3., -1., 1., 1.]).unwrap();
/// let u = symbolic::singular_point(&Rational::polynomial(&cusp), 1e-12).unwrap().unwrap();
/// assert!((u - 0.5).abs() < 1e-6);
/// let arc = BSpline::bezier(2, vec![1., 0., 1., 1., 0., 1.]).unwrap();
/// assert_eq!(symbolic::singular_point(&Rational::polynomial(&arc), 1e-12).unwrap(), None);
/// ```
pub fn singular_point(c: &Rational, tol: f64) -> Result<Option<f64>> {
    planar(c)?;
    homogeneous_pieces(c).singular_point(tol)
}

/// Numerator of `C′(u) · v`: zero where the tangent is perpendicular to `v` (so the normal is
/// parallel to `v`).
pub fn tangent_dot(c: &Rational, v: [f64; 2]) -> Result<BSpline> {
    let d = tangent_numerator(c)?;
    Ok(d.map_points(1, |p, o| o[0] = p[0] * v[0] + p[1] * v[1]))
}

/// Numerator of `(C(u) − q) × C′(u)`: zero where the tangent line at `u` passes through `q`.
pub fn tangency_from(c: &Rational, q: [f64; 2]) -> Result<BSpline> {
    planar(c)?;
    let rel = c.homogeneous().map_points(2, |h, o| {
        o[0] = h[0] - q[0] * h[2];
        o[1] = h[1] - q[1] * h[2];
    });
    if !c.is_rational() {
        let w = c.homogeneous().ctrl(0)[2];
        return rel.cross(&rel.deriv()).map(|f| f.scale(1.0 / (w * w)));
    }
    // With R = X − q w: (C − q) × C′ = (R × R′) / w², and w > 0, so R × R′ has the sign.
    rel.cross(&rel.deriv())
}

/// Numerator of `(C(u) − q) · v`: zero where the curve crosses the line through `q`
/// perpendicular to `v`.
pub fn offset_dot(c: &Rational, q: [f64; 2], v: [f64; 2]) -> Result<BSpline> {
    planar(c)?;
    Ok(c.homogeneous().map_points(1, |h, o| {
        o[0] = (h[0] - q[0] * h[2]) * v[0] + (h[1] - q[1] * h[2]) * v[1];
    }))
}
