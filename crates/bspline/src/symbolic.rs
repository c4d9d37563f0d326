//! Exact symbolic building blocks for planar curves, as scalar B-splines.
//!
//! Each function returns a *numerator*: a B-spline with the same sign as the geometric quantity
//! (for a rational curve the quantity equals the numerator divided by a positive power of the
//! weight). Sign decisions, and so root isolation, can therefore be made on the numerator.

use crate::error::{Error, Result};
use crate::rational::Rational;
use crate::spline::BSpline;

fn planar(c: &Rational) -> Result<()> {
    if c.dim() != 2 {
        return Err(Error::DimensionMismatch {
            expected: 2,
            got: c.dim(),
        });
    }
    Ok(())
}

/// The curve's Euclidean part `X` (the homogeneous coordinates without the weight).
fn euclidean_part(c: &Rational) -> BSpline {
    c.homogeneous()
        .map_points(2, |h, o| o.copy_from_slice(&h[..2]))
}

/// `D = X′w − Xw′`, the numerator of the tangent: `C′ = D / w²`. For a polynomial curve `D = C′`.
pub fn tangent_numerator(c: &Rational) -> Result<BSpline> {
    planar(c)?;
    if !c.is_rational() {
        let w = c.homogeneous().ctrl(0)[2];
        return Ok(euclidean_part(c).deriv().scale(1.0 / w));
    }
    let h = c.homogeneous();
    let x = euclidean_part(c);
    let w = h.component(2)?;
    w.mul(&x.deriv())?.sub(&w.deriv().mul(&x)?)
}

/// Proves that the curve is regular (its tangent never vanishes): `Ok(None)` when
/// `|D|² = D · D` of the [`tangent_numerator`] `D` is proven positive on the whole domain, else
/// `Ok(Some(u))` with a parameter near which the speed is within rounding of zero (a cusp or a
/// stationary point), to the parameter tolerance `tol`.
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
    let d = tangent_numerator(c)?;
    let speed2 = d.dot(&d)?;
    let (a, b) = speed2.domain();
    let opts = crate::roots::RootOptions::default().tolerance(tol);
    crate::roots::prove_positive(&speed2, a, b, &opts)
}

/// The curvature numerator: `x′y″ − x″y′` for a polynomial curve (degree `2p − 3`), and
/// `det[H, H′, H″]` (degree `3p − 3`) for a rational one, which equals `w³ (x′y″ − x″y′)`.
/// Its roots are the inflections; its sign is the side the curve turns to.
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
    if !c.is_rational() {
        let w = c.homogeneous().ctrl(0)[2];
        let x = euclidean_part(c).scale(1.0 / w);
        let d1 = x.deriv();
        return d1.cross(&d1.deriv());
    }
    let h = c.homogeneous();
    let d1 = h.deriv();
    h.dot(&d1.cross3(&d1.deriv())?)
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
