//! Exact rational B-spline forms of the analytic shapes, through the rational unit circle.
//!
//! The unit circle is the classic degree-2 NURBS with nine control points on the parameter
//! domain `[0, 4]` (one quarter per unit). A shape whose polar or Cartesian form is a
//! polynomial in `(cos φ, sin φ)`, or a quotient of such polynomials, is the composition with
//! that circle: with the circle in homogeneous form `(X, Y, W)`, a polynomial of degree `k`
//! becomes `Wᵏ · P(X/W, Y/W)`, computed with the exact products of this crate. The shapes are
//! therefore *exactly* the analytic curves (up to rounding), and every sign test on them is a
//! certified one. Their parameter `u` is not the angle φ: [`circle_angle`] and
//! [`circle_param`] convert between the two.

use crate::error::{Error, Result};
use crate::rational::Rational;
use crate::spline::BSpline;
use std::f64::consts::{FRAC_1_SQRT_2, PI, TAU};

/// The homogeneous unit circle `(X, Y, W)` as three scalar splines on `[0, 4]`.
fn circle_parts() -> (BSpline, BSpline, BSpline) {
    let knots = vec![0., 0., 0., 1., 1., 2., 2., 3., 3., 4., 4., 4.];
    let pts = [
        (1., 0.),
        (1., 1.),
        (0., 1.),
        (-1., 1.),
        (-1., 0.),
        (-1., -1.),
        (0., -1.),
        (1., -1.),
        (1., 0.),
    ];
    let w: Vec<f64> = (0..9)
        .map(|i| if i % 2 == 1 { FRAC_1_SQRT_2 } else { 1.0 })
        .collect();
    let mk =
        |f: &dyn Fn(usize) -> f64| BSpline::from_raw(2, 1, knots.clone(), (0..9).map(f).collect());
    (
        mk(&|i| pts[i].0 * w[i]),
        mk(&|i| pts[i].1 * w[i]),
        mk(&|i| w[i]),
    )
}

fn assemble(x: &BSpline, y: &BSpline, w: &BSpline) -> Result<Rational> {
    Rational::from_homogeneous(BSpline::stack(&[x, y, w])?)
}

fn positive(what: &'static str, v: f64) -> Result<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::NotFinite {
            what,
            index: 0,
            value: v,
        })
    }
}

/// The circle of radius `r` about `center`, counterclockwise from φ = 0.
///
/// ```
/// let c = bspline::shapes::circle([1.0, 2.0], 3.0).unwrap();
/// let p = c.point(1.3);
/// assert!(((p[0] - 1.0).hypot(p[1] - 2.0) - 3.0).abs() < 1e-14);
/// ```
pub fn circle(center: [f64; 2], r: f64) -> Result<Rational> {
    ellipse(center, r, r)
}

/// The ellipse `(cx + a cos φ, cy + b sin φ)`.
pub fn ellipse(center: [f64; 2], a: f64, b: f64) -> Result<Rational> {
    positive("a", a)?;
    positive("b", b)?;
    let (x, y, w) = circle_parts();
    let x = x.scale(a).add(&w.scale(center[0]))?;
    let y = y.scale(b).add(&w.scale(center[1]))?;
    assemble(&x, &y, &w)
}

/// The limaçon `r(φ) = a + b cos φ`: `x = r cos φ`, `y = r sin φ` (degree 4).
pub fn limacon(a: f64, b: f64) -> Result<Rational> {
    if !(a.is_finite() && b.is_finite()) {
        return Err(Error::NotFinite {
            what: "limacon",
            index: 0,
            value: a + b,
        });
    }
    let (x, y, w) = circle_parts();
    // W²·r·cos φ = X(aW + bX), W²·r·sin φ = Y(aW + bX).
    let rw = w.scale(a).add(&x.scale(b))?;
    assemble(&x.mul(&rw)?, &y.mul(&rw)?, &w.mul(&w)?)
}

/// The curve with `m` convexities, `r(φ) = p / (1 + ε cos mφ)` (degree `2m`).
pub fn convexities(p: f64, eps: f64, m: usize) -> Result<Rational> {
    positive("p", p)?;
    if !(eps.is_finite() && eps > 0.0 && eps < 1.0) {
        return Err(Error::NotFinite {
            what: "eps",
            index: 0,
            value: eps,
        });
    }
    let (x, y, w) = circle_parts();
    // Wᵐ cos mφ = Re (X + iY)ᵐ, by repeated complex multiplication.
    let (mut re, mut im, mut wm) = (x.clone(), y.clone(), w.clone());
    for _ in 1..m {
        let nre = re.mul(&x)?.sub(&im.mul(&y)?)?;
        let nim = re.mul(&y)?.add(&im.mul(&x)?)?;
        re = nre;
        im = nim;
        wm = wm.mul(&w)?;
    }
    // r cos φ = p X W^(m−1) / (Wᵐ + ε Re(X+iY)ᵐ), and likewise with Y.
    let den = wm.add(&re.scale(eps))?;
    let wmm1 = if m >= 2 {
        power(&w, m - 1)?
    } else {
        BSpline::constant(&[1.0], 0, 0.0, 4.0)?
    };
    let nx = x.mul(&wmm1)?.scale(p);
    let ny = y.mul(&wmm1)?.scale(p);
    assemble(&nx, &ny, &den)
}

/// The elliptic lemniscate `r(φ) = √(a² cos² φ + b² sin² φ)` (degree 4): the inverse, in the
/// unit circle about the origin, of the ellipse `a²X² + b²Y² = 1`, whose points `(cos ψ / a,
/// sin ψ / b)` come from the rational circle. Inversion `V ↦ V / |V|²` keeps the polar angle
/// and inverts the radius, so the point of parameter `u` lies at the polar angle φ with
/// `tan φ = (a/b) tan ψ`, where `ψ = circle_angle(u)` (not at `φ = circle_angle(u)` as for the
/// other shapes of this module).
///
/// ```
/// let (a, b) = (6.0, 3.0);
/// let c = bspline::shapes::elliptic_lemniscate(a, b).unwrap();
/// let p = c.point(0.7);
/// let phi = p[1].atan2(p[0]);
/// let r = (a * a * phi.cos().powi(2) + b * b * phi.sin().powi(2)).sqrt();
/// assert!((p[0].hypot(p[1]) - r).abs() < 1e-12 * a);
/// ```
pub fn elliptic_lemniscate(a: f64, b: f64) -> Result<Rational> {
    positive("a", a)?;
    positive("b", b)?;
    let (x, y, w) = circle_parts();
    // With X = x/(aw), Y = y/(bw): V/|V|² = (xw/a, yw/b) / (x²/a² + y²/b²), scaled by a²b²
    // (a homogeneous factor) to keep the divisions out.
    let den = x.mul(&x)?.scale(b * b).add(&y.mul(&y)?.scale(a * a))?;
    assemble(
        &x.mul(&w)?.scale(a * b * b),
        &y.mul(&w)?.scale(a * a * b),
        &den,
    )
}

fn power(f: &BSpline, k: usize) -> Result<BSpline> {
    let mut acc = f.clone();
    for _ in 1..k {
        acc = acc.mul(f)?;
    }
    Ok(acc)
}

/// The polar angle φ ∈ [0, 2π) of the parameter `u ∈ [0, 4]` of the shapes of this module.
pub fn circle_angle(u: f64) -> f64 {
    let (x, y, _) = circle_parts();
    // The weight is positive, so the homogeneous point has the angle of the Euclidean one.
    let phi = y.eval_scalar(u).atan2(x.eval_scalar(u));
    if phi < 0.0 {
        phi + TAU
    } else {
        phi
    }
}

/// The parameter `u ∈ [0, 4)` of the polar angle φ (inverse of [`circle_angle`]).
///
/// On each quarter the rational quadratic is a Möbius reparametrisation of the half-angle:
/// `tan(φ_local / 2) = s / (√2 (1 − s) + s)`, so `s = √2 t / (1 − t + √2 t)` with
/// `t = tan(φ_local / 2)`.
pub fn circle_param(phi: f64) -> f64 {
    let phi = phi.rem_euclid(TAU);
    let quarter = (phi / (PI / 2.0)).floor().min(3.0);
    let local = phi - quarter * PI / 2.0;
    let t = (0.5 * local).tan();
    let s = std::f64::consts::SQRT_2 * t / (1.0 - t + std::f64::consts::SQRT_2 * t);
    quarter + s
}
