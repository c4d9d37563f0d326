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

/// A polar curve `r(φ)(cos φ, sin φ)` from the sine and cosine of φ, `r` and its first three
/// derivatives.
fn polar_jet_cs(s: f64, c: f64, r: [f64; 4]) -> Jet {
    polar_jet_to(s, c, r, 3)
}

/// [`polar_jet_cs`] up to derivative `order` (higher ones left zero).
#[inline]
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

/// The shapes with a rational-circle form, as formulas in `(cos ψ, sin ψ)` of the circle's
/// angle ψ (jets in ψ): the shape's own angle φ for all but the elliptic lemniscate, whose
/// form inverts an ellipse (`tan φ = (a/b) tan ψ`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum CircleShape {
    Ellipse { a: f64, b: f64, center: V2 },
    Limacon { a: f64, b: f64 },
    Convexities { p: f64, eps: f64, m: u32 },
    Lemniscate { a: f64, b: f64 },
}

impl CircleShape {
    /// Point and derivatives in ψ up to `order` at the angle with cosine `c` and sine `s`.
    /// (Inlined into the circle form's jets, the hottest path of a run: left to itself the
    /// compiler stopped doing so as the crate grew, at 3 % of a run.)
    #[inline]
    pub(crate) fn jet(self, c: f64, s: f64, order: usize) -> Jet {
        match self {
            CircleShape::Lemniscate { a, b } => inverted_ellipse_jet(a, b, s, c, order),
            CircleShape::Ellipse { a, b, center } => ellipse_jet(a, b, center, s, c),
            CircleShape::Limacon { a, b } => {
                polar_jet_to(s, c, [a + b * c, -b * s, -b * c, b * s], order)
            }
            CircleShape::Convexities { p, eps, m } => {
                // cos mφ + i sin mφ = (c + i s)ᵐ, by repeated complex products (m ≥ 2): the
                // error grows only linearly in m, unlike the Chebyshev three-term recurrence.
                let (mut cm, mut sm) = (c, s);
                for _ in 1..m {
                    (cm, sm) = (cm * c - sm * s, cm * s + sm * c);
                }
                convexities_jet(p, eps, m, s, c, sm, cm, order)
            }
        }
    }
}

/// The elliptic lemniscate as the inverse `P = V / |V|²` of the ellipse point
/// `V = (cos ψ / a, sin ψ / b)`, with derivatives in ψ up to `order`: `V″ = −V`, so with
/// `q = |V|²`: `q′ = 2V·V′`, `q″ = 2(|V′|² − q)`, `q‴ = −4q′`, and `Pq = V` differentiated
/// gives each derivative of `P` from the lower ones (one division).
#[inline]
fn inverted_ellipse_jet(a: f64, b: f64, s: f64, c: f64, order: usize) -> Jet {
    let v = V2::new(c / a, s / b);
    let v1 = V2::new(-s / a, c / b);
    let q = v.dot(v);
    let q1 = 2.0 * v.dot(v1);
    let inv = 1.0 / q;
    let p = v * inv;
    let p1 = (v1 - p * q1) * inv;
    let mut j = Jet {
        p,
        d1: p1,
        ..Jet::default()
    };
    if order >= 2 {
        let q2 = 2.0 * (v1.dot(v1) - q);
        j.d2 = (-v - p1 * (2.0 * q1) - p * q2) * inv;
        if order >= 3 {
            let q3 = -4.0 * q1;
            j.d3 = (-v1 - j.d2 * (3.0 * q1) - p1 * (3.0 * q2) - p * q3) * inv;
        }
    }
    j
}

fn ellipse_jet(a: f64, b: f64, center: V2, s: f64, c: f64) -> Jet {
    Jet {
        p: center + V2::new(a * c, b * s),
        d1: V2::new(-a * s, b * c),
        d2: V2::new(-a * c, -b * s),
        d3: V2::new(a * s, -b * c),
    }
}

/// `r(φ) = p / (1 + ε cos mφ)` from the sines and cosines of φ and mφ, up to `order`.
#[allow(clippy::too_many_arguments)] // the shape's three parameters and two angles
#[inline]
fn convexities_jet(p: f64, e: f64, m: u32, s: f64, c: f64, sm: f64, cm: f64, order: usize) -> Jet {
    let m = m as f64;
    // h = 1 + ε cos mφ and r = p/h: with k = h′/h and gⱼ = h⁽ʲ⁾/h (one division),
    // r′ = −rk, r″ = r(2k² − g₂), r‴ = r(6k(g₂ − k²) − g₃).
    let inv = 1.0 / (1.0 + e * cm);
    let r = p * inv;
    let em = e * m;
    let k = -em * sm * inv;
    let r1 = -r * k;
    let (mut r2, mut r3) = (0.0, 0.0);
    if order >= 2 {
        let g2 = -em * m * cm * inv;
        r2 = r * (2.0 * k * k - g2);
        if order >= 3 {
            let g3 = em * m * m * sm * inv;
            r3 = r * (6.0 * k * (g2 - k * k) - g3);
        }
    }
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
        polar_jet_cs(s, c, [a + b * c, -b * s, -b * c, b * s])
    }
}

/// The most slender elliptic lemniscate (`a/b` or `b/a`) run on its circle form. Beyond, the
/// lobes are so nearly circular (θ of order `(b/a)⁴` across them) that no stretch of them is
/// proven monotone: the march crawls and the sampled width settles them on either path (from
/// `a/b = 6` on). The form would only cost precision there: its parameter runs up to `a/b`
/// times slower than φ, and the lobes' nearly singular pairs come out that much coarser (at
/// `a/b = 200`, 2e-5 in φ against 6e-8; at 300, families at the default tolerance).
const MAX_SQUEEZE: f64 = 5.0;

/// Elliptic lemniscate `r(φ) = sqrt(a² cos² φ + b² sin² φ)`: certified on its exact rational
/// form (the inverse of an ellipse) up to `a/b = 5` (either way round), sampled beyond.
#[derive(Debug, Clone)]
pub struct EllipticLemniscate {
    a: f64,
    b: f64,
    forms: KeptForms,
}

impl PartialEq for EllipticLemniscate {
    fn eq(&self, o: &Self) -> bool {
        (self.a, self.b) == (o.a, o.b)
    }
}

impl EllipticLemniscate {
    /// An elliptic lemniscate with `a, b > 0`.
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check("a", a, a > 0.0, "must be > 0")?;
        check("b", b, b > 0.0, "must be > 0")?;
        Ok(Self {
            a,
            b,
            forms: KeptForms::new(),
        })
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
    fn circle_forms(&self) -> Option<&SymbolicForms> {
        // Exact (the inverse of an ellipse) but not in φ = circle_angle(u): no `circle_form`
        // for the generic path, only the kept forms with the shape's own jet and angle.
        let (a, b) = (self.a, self.b);
        if (a / b).max(b / a) > MAX_SQUEEZE {
            return None;
        }
        kept_circle(
            &self.forms,
            || bspline::shapes::elliptic_lemniscate(a, b).ok(),
            CircleShape::Lemniscate { a, b },
        )
    }
    fn jet(&self, u: f64) -> Jet {
        self.jet_to(u, 3)
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        // r² = g = A + B cos 2φ; differentiate r² = g three times. The value itself as
        // a² cos² φ + b² sin² φ: the form with cos 2φ cancels near the waist (φ = π/2) of a
        // slender lemniscate, where g ≈ b² ≪ a².
        let (aa, bb) = (self.a * self.a, self.b * self.b);
        let big_b = 0.5 * (aa - bb);
        // One sine and cosine: the double angle from them (sin 2φ = 2sc, cos 2φ = (c − s)(c + s),
        // the factored form exact near φ = π/4 up to the rounding of c and s themselves).
        let (s, c) = u.sin_cos();
        let (s2, c2) = (2.0 * s * c, (c - s) * (c + s));
        let g = aa * c * c + bb * s * s;
        let r = g.sqrt();
        let inv = 1.0 / r;
        // 2rr′ = g′, 2(rr″ + r′²) = g″, 2(rr‴ + 3r′r″) = g‴.
        let r1 = -big_b * s2 * inv;
        let (mut r2, mut r3) = (0.0, 0.0);
        if order >= 2 {
            r2 = (-2.0 * big_b * c2 - r1 * r1) * inv;
            if order >= 3 {
                r3 = (4.0 * big_b * s2 - 3.0 * r1 * r2) * inv;
            }
        }
        polar_jet_to(s, c, [r, r1, r2, r3], order)
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

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// Each derivative of `c`'s jet against central differences of the one below, at many φ.
    fn check_against_differences(c: &dyn PlaneCurve) {
        let h = 1e-5;
        for i in 0..=720 {
            let u = TAU * i as f64 / 720.0 + 1e-3;
            let j = c.jet(u);
            let (lo, hi) = (c.jet(u - h), c.jet(u + h));
            let scale = j.p.norm() + j.d1.norm() + j.d2.norm() + j.d3.norm();
            let pairs = [
                (j.d1, hi.p - lo.p),
                (j.d2, hi.d1 - lo.d1),
                (j.d3, hi.d2 - lo.d2),
            ];
            for (k, (d, diff)) in pairs.into_iter().enumerate() {
                let err = (d - diff * (0.5 / h)).norm();
                assert!(
                    err <= 1e-7 * scale,
                    "{u}: derivative {} off by {err}",
                    k + 1
                );
            }
            // Lower orders agree with the full jet.
            for order in 0..3 {
                let l = c.jet_to(u, order);
                assert_eq!((l.p, l.d1), (j.p, j.d1), "{u} order {order}");
                if order >= 2 {
                    assert_eq!(l.d2, j.d2, "{u} order {order}");
                }
            }
        }
    }

    #[test]
    fn jets_match_central_differences() {
        check_against_differences(&Circle::new(1.5, [1.0, 2.0]).unwrap());
        check_against_differences(&Ellipse::new(3.0, 2.0, [0.5, -1.0]).unwrap());
        check_against_differences(&Limacon::new(4.0, 2.5).unwrap());
        check_against_differences(&EllipticLemniscate::new(6.0, 3.0).unwrap());
        check_against_differences(&EllipticLemniscate::new(1.0, 0.05).unwrap());
        check_against_differences(&Convexities::new(3.0, 0.5, 3).unwrap());
        check_against_differences(&Convexities::new(4.5, 0.2, 4).unwrap());
        check_against_differences(&Convexities::new(2.0, 0.3, 7).unwrap());
    }

    /// The shapes' formulas in `(cos φ, sin φ)` against their jets from `sin mφ, cos mφ` by the
    /// library's sine and cosine.
    #[test]
    fn circle_shapes_match_the_angle_formulas() {
        for (p, eps, m) in [(3.0, 0.5, 3), (4.5, 0.2, 4), (1.0, 0.9, 2), (2.0, 0.3, 7)] {
            let c = Convexities::new(p, eps, m).unwrap();
            let shape = CircleShape::Convexities { p, eps, m };
            for i in 0..=2000 {
                let u = TAU * i as f64 / 2000.0;
                let (s, co) = u.sin_cos();
                let (a, b) = (shape.jet(co, s, 3), c.jet(u));
                let scale = b.p.norm() + b.d1.norm() + b.d2.norm() + b.d3.norm();
                for (x, y) in [(a.p, b.p), (a.d1, b.d1), (a.d2, b.d2), (a.d3, b.d3)] {
                    assert!((x - y).norm() <= 1e-13 * scale, "m={m} {u}: {a:?} vs {b:?}");
                }
            }
        }
    }

    /// The elliptic lemniscate's jet from one sine and cosine against the former evaluation
    /// (the double angle by its own sine and cosine, divisions by r).
    #[test]
    fn lemniscate_matches_the_double_angle_formula() {
        for (a, b) in [(6.0, 3.0), (1.0, 0.05), (2.0, 2.0), (0.3, 5.0)] {
            let c = EllipticLemniscate::new(a, b).unwrap();
            let (aa, bb) = (a * a, b * b);
            let big_b = 0.5 * (aa - bb);
            for i in 0..=4000 {
                let u = TAU * i as f64 / 4000.0;
                let (s, co) = u.sin_cos();
                let (s2, c2) = (2.0 * u).sin_cos();
                let r = (aa * co * co + bb * s * s).sqrt();
                let r1 = -2.0 * big_b * s2 / (2.0 * r);
                let r2 = (-2.0 * big_b * c2 - r1 * r1) / r;
                let r3 = (4.0 * big_b * s2 - 3.0 * r1 * r2) / r;
                let want = polar_jet_cs(s, co, [r, r1, r2, r3]);
                let got = c.jet(u);
                let scale = want.p.norm() + want.d1.norm() + want.d2.norm() + want.d3.norm();
                for (x, y) in [
                    (got.p, want.p),
                    (got.d1, want.d1),
                    (got.d2, want.d2),
                    (got.d3, want.d3),
                ] {
                    assert!(
                        (x - y).norm() <= 1e-14 * scale,
                        "{a},{b} {u}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }
}
