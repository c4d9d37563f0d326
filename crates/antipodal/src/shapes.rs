//! The analytic shapes of the interfaces file, with exact derivatives. All run counterclockwise
//! over `φ ∈ [0, 2π)`.

use crate::curve::PlaneCurve;
use crate::error::{Error, Result};
use crate::forms::{kept_circle, KeptForms, SymbolicForms};
use crate::geom::{Jet, V2};
use bspline::Rational;
use std::f64::consts::TAU;

fn check(field: &'static str, value: f64, ok: bool, why: &'static str) -> Result<()> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidShape { field, value, why })
    }
}

/// A polar curve `r(φ)(cos φ, sin φ)` from `r` and its first three derivatives.
fn polar_jet(phi: f64, r: [f64; 4]) -> Jet {
    let (s, c) = phi.sin_cos();
    polar_jet_cs(s, c, r)
}

/// [`polar_jet`] from the sine and cosine of φ.
fn polar_jet_cs(s: f64, c: f64, r: [f64; 4]) -> Jet {
    polar_jet_to(s, c, r, 3)
}

/// [`polar_jet_cs`] up to derivative `order` (higher ones left zero).
fn polar_jet_to(s: f64, c: f64, r: [f64; 4], order: usize) -> Jet {
    let [r0, r1, r2, r3] = r;
    let mut j = Jet {
        p: V2::new(r0 * c, r0 * s),
        d1: V2::new(r1 * c - r0 * s, r1 * s + r0 * c),
        ..Jet::default()
    };
    if order >= 2 {
        j.d2 = V2::new(
            r2 * c - 2.0 * r1 * s - r0 * c,
            r2 * s + 2.0 * r1 * c - r0 * s,
        );
    }
    if order >= 3 {
        j.d3 = V2::new(
            r3 * c - 3.0 * r2 * s - 3.0 * r1 * c + r0 * s,
            r3 * s + 3.0 * r2 * c - 3.0 * r1 * s - r0 * c,
        );
    }
    j
}

/// The shapes with a rational-circle form, as formulas in `(cos φ, sin φ)` (jets in φ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum CircleShape {
    Ellipse { a: f64, b: f64, center: V2 },
    Limacon { a: f64, b: f64 },
    Convexities { p: f64, eps: f64, m: u32 },
}

impl CircleShape {
    /// Point and derivatives in φ up to `order` at the angle with cosine `c` and sine `s`.
    pub(crate) fn jet(self, c: f64, s: f64, order: usize) -> Jet {
        match self {
            CircleShape::Ellipse { a, b, center } => ellipse_jet(a, b, center, s, c),
            CircleShape::Limacon { a, b } => {
                polar_jet_to(s, c, [a + b * c, -b * s, -b * c, b * s], order)
            }
            CircleShape::Convexities { p, eps, m } => {
                // cos mφ + i sin mφ = (c + i s)ᵐ.
                let (mut cm, mut sm) = (1.0, 0.0);
                for _ in 0..m {
                    (cm, sm) = (cm * c - sm * s, cm * s + sm * c);
                }
                convexities_jet(p, eps, m, s, c, sm, cm, order)
            }
        }
    }
}

fn ellipse_jet(a: f64, b: f64, center: V2, s: f64, c: f64) -> Jet {
    Jet {
        p: center + V2::new(a * c, b * s),
        d1: V2::new(-a * s, b * c),
        d2: V2::new(-a * c, -b * s),
        d3: V2::new(a * s, -b * c),
    }
}

/// `r(φ) = p / (1 + ε cos mφ)` from the sines and cosines of φ and mφ.
#[allow(clippy::too_many_arguments)] // the shape's three parameters and two angles
fn convexities_jet(p: f64, e: f64, m: u32, s: f64, c: f64, sm: f64, cm: f64, order: usize) -> Jet {
    let m = m as f64;
    let h = 1.0 + e * cm;
    let h1 = -e * m * sm;
    let h2 = -e * m * m * cm;
    let h3 = e * m * m * m * sm;
    let (i1, i2, i3, i4) = (
        1.0 / h,
        1.0 / (h * h),
        1.0 / (h * h * h),
        1.0 / (h * h * h * h),
    );
    let r = p * i1;
    let r1 = -p * h1 * i2;
    let r2 = p * (2.0 * h1 * h1 * i3 - h2 * i2);
    let r3 = p * (-6.0 * h1 * h1 * h1 * i4 + 6.0 * h1 * h2 * i3 - h3 * i2);
    polar_jet_to(s, c, [r, r1, r2, r3], order)
}

/// Circle `(cx + r cos φ, cy + r sin φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    r: f64,
    center: V2,
}

impl Circle {
    /// A circle of radius `r > 0`.
    pub fn new(r: f64, center: [f64; 2]) -> Result<Self> {
        check("r", r, r > 0.0, "must be > 0")?;
        Ok(Self {
            r,
            center: V2::from_arr(center),
        })
    }
}

impl PlaneCurve for Circle {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn known_simple(&self) -> bool {
        // Star-shaped about the origin (r > 0) or an ellipse: never self-crossing.
        true
    }
    fn jet(&self, u: f64) -> Jet {
        let (s, c) = u.sin_cos();
        let r = self.r;
        Jet {
            p: self.center + V2::new(r * c, r * s),
            d1: V2::new(-r * s, r * c),
            d2: V2::new(-r * c, -r * s),
            d3: V2::new(r * s, -r * c),
        }
    }
}

/// Ellipse `(cx + a cos φ, cy + b sin φ)`.
#[derive(Debug, Clone)]
pub struct Ellipse {
    a: f64,
    b: f64,
    center: V2,
    forms: KeptForms,
}

impl PartialEq for Ellipse {
    fn eq(&self, o: &Self) -> bool {
        (self.a, self.b, self.center) == (o.a, o.b, o.center)
    }
}

impl Ellipse {
    /// An ellipse with semi-axes `a, b > 0`.
    pub fn new(a: f64, b: f64, center: [f64; 2]) -> Result<Self> {
        check("a", a, a > 0.0, "must be > 0")?;
        check("b", b, b > 0.0, "must be > 0")?;
        Ok(Self {
            a,
            b,
            center: V2::from_arr(center),
            forms: KeptForms::new(),
        })
    }
}

impl PlaneCurve for Ellipse {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn known_simple(&self) -> bool {
        // Star-shaped about the origin (r > 0) or an ellipse: never self-crossing.
        true
    }
    fn circle_form(&self) -> Option<Rational> {
        bspline::shapes::ellipse(self.center.arr(), self.a, self.b).ok()
    }
    fn circle_forms(&self) -> Option<&SymbolicForms> {
        let shape = CircleShape::Ellipse {
            a: self.a,
            b: self.b,
            center: self.center,
        };
        kept_circle(&self.forms, || self.circle_form(), shape)
    }
    fn jet(&self, u: f64) -> Jet {
        let (s, c) = u.sin_cos();
        ellipse_jet(self.a, self.b, self.center, s, c)
    }
}

/// Limaçon `r(φ) = a + b cos φ`.
#[derive(Debug, Clone)]
pub struct Limacon {
    a: f64,
    b: f64,
    forms: KeptForms,
}

impl PartialEq for Limacon {
    fn eq(&self, o: &Self) -> bool {
        (self.a, self.b) == (o.a, o.b)
    }
}

impl Limacon {
    /// A simple limaçon: `a > b ≥ 0`.
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check("b", b, b >= 0.0, "must be ≥ 0")?;
        check("a", a, a > b, "must be > b for a simple curve")?;
        Ok(Self {
            a,
            b,
            forms: KeptForms::new(),
        })
    }
}

impl PlaneCurve for Limacon {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn known_simple(&self) -> bool {
        // Star-shaped about the origin (r > 0) or an ellipse: never self-crossing.
        true
    }
    fn circle_form(&self) -> Option<Rational> {
        bspline::shapes::limacon(self.a, self.b).ok()
    }
    fn circle_forms(&self) -> Option<&SymbolicForms> {
        let shape = CircleShape::Limacon {
            a: self.a,
            b: self.b,
        };
        kept_circle(&self.forms, || self.circle_form(), shape)
    }
    fn jet(&self, u: f64) -> Jet {
        let (s, c) = u.sin_cos();
        let (a, b) = (self.a, self.b);
        polar_jet(u, [a + b * c, -b * s, -b * c, b * s])
    }
}

/// Elliptic lemniscate `r(φ) = sqrt(a² cos² φ + b² sin² φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticLemniscate {
    a: f64,
    b: f64,
}

impl EllipticLemniscate {
    /// An elliptic lemniscate with `a, b > 0`.
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check("a", a, a > 0.0, "must be > 0")?;
        check("b", b, b > 0.0, "must be > 0")?;
        Ok(Self { a, b })
    }
}

impl PlaneCurve for EllipticLemniscate {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn known_simple(&self) -> bool {
        // Star-shaped about the origin (r > 0) or an ellipse: never self-crossing.
        true
    }
    fn jet(&self, u: f64) -> Jet {
        // r² = g = A + B cos 2φ; differentiate r² = g three times. The value itself as
        // a² cos² φ + b² sin² φ: the form with cos 2φ cancels near the waist (φ = π/2) of a
        // slender lemniscate, where g ≈ b² ≪ a².
        let (aa, bb) = (self.a * self.a, self.b * self.b);
        let big_b = 0.5 * (aa - bb);
        let (s, c) = u.sin_cos();
        let (s2, c2) = (2.0 * u).sin_cos();
        let g = aa * c * c + bb * s * s;
        let g1 = -2.0 * big_b * s2;
        let g2 = -4.0 * big_b * c2;
        let g3 = 8.0 * big_b * s2;
        let r = g.sqrt();
        let r1 = g1 / (2.0 * r);
        let r2 = (0.5 * g2 - r1 * r1) / r;
        let r3 = (0.5 * g3 - 3.0 * r1 * r2) / r;
        polar_jet(u, [r, r1, r2, r3])
    }
}

/// Curve with convexities `r(φ) = p / (1 + ε cos mφ)`.
#[derive(Debug, Clone)]
pub struct Convexities {
    p: f64,
    eps: f64,
    m: u32,
    forms: KeptForms,
}

impl PartialEq for Convexities {
    fn eq(&self, o: &Self) -> bool {
        (self.p, self.eps, self.m) == (o.p, o.eps, o.m)
    }
}

impl Convexities {
    /// `p > 0`, `0 < ε < 1`, integer `m ≥ 2`.
    pub fn new(p: f64, eps: f64, m: u32) -> Result<Self> {
        check("p", p, p > 0.0, "must be > 0")?;
        check("eps", eps, eps > 0.0 && eps < 1.0, "must be in (0, 1)")?;
        check("m", m as f64, m >= 2, "must be an integer ≥ 2")?;
        Ok(Self {
            p,
            eps,
            m,
            forms: KeptForms::new(),
        })
    }
}

impl PlaneCurve for Convexities {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn known_simple(&self) -> bool {
        // Star-shaped about the origin (r > 0) or an ellipse: never self-crossing.
        true
    }
    fn circle_form(&self) -> Option<Rational> {
        bspline::shapes::convexities(self.p, self.eps, self.m as usize).ok()
    }
    fn circle_forms(&self) -> Option<&SymbolicForms> {
        let shape = CircleShape::Convexities {
            p: self.p,
            eps: self.eps,
            m: self.m,
        };
        kept_circle(&self.forms, || self.circle_form(), shape)
    }
    fn jet(&self, u: f64) -> Jet {
        let (sm, cm) = (self.m as f64 * u).sin_cos();
        let (s, c) = u.sin_cos();
        convexities_jet(self.p, self.eps, self.m, s, c, sm, cm, 3)
    }
}
