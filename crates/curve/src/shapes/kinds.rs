//! The five shape kinds of the curve files as parameter types, validated when built, with
//! their evaluation in φ ([`ParamCurve`]): each kind's parameters and jets read together.

use super::jets::{convexities_jet, ellipse_jet, polar_jet_cs, polar_jet_to};
use crate::error::{Error, Result};
use crate::geom::{Jet, V2};
use crate::param::ParamCurve;
use std::f64::consts::TAU;

fn check(field: &'static str, value: f64, ok: bool, why: &'static str) -> Result<()> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidShape { field, value, why })
    }
}

/// The accessors of a kind's plain parameters, each the field of its name.
macro_rules! parameters {
    ($kind:ident { $($(#[doc = $doc:literal])* $field:ident: $t:ty,)* }) => {
        impl $kind {
            $(
                $(#[doc = $doc])*
                pub fn $field(&self) -> $t {
                    self.$field
                }
            )*
        }
    };
}

/// [`ParamCurve`] for kinds that run once round, closed, over φ ∈ `[0, 2π)`: their jets
/// from their own `jet_in_angle`.
macro_rules! closed_over_the_angle {
    ($($kind:ident),*) => {
        $(impl ParamCurve for $kind {
            fn domain(&self) -> (f64, f64) {
                (0.0, TAU)
            }
            fn is_closed(&self) -> bool {
                true
            }
            #[inline]
            fn jet_to(&self, u: f64, order: usize) -> Jet {
                self.jet_in_angle(u, order)
            }
        })*
    };
}

closed_over_the_angle!(Circle, Ellipse, Limacon, EllipticLemniscate, Convexities);

/// Circle `(cx + r cos φ, cy + r sin φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    pub(super) r: f64,
    pub(super) center: V2,
}

impl Circle {
    /// A circle of radius `r > 0`.
    pub fn new(r: f64, center: [f64; 2]) -> Result<Self> {
        check("r", r, r > 0.0, "must be > 0")?;
        check("center", center[0], center[1].is_finite(), "must be finite")?;
        Ok(Self {
            r,
            center: V2::from_arr(center),
        })
    }
    /// The center.
    pub fn center(&self) -> [f64; 2] {
        self.center.arr()
    }
}

parameters!(Circle {
    /// The radius.
    r: f64,
});

/// Ellipse `(cx + a cos φ, cy + b sin φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    pub(super) a: f64,
    pub(super) b: f64,
    pub(super) center: V2,
}

impl Ellipse {
    /// An ellipse with semi-axes `a, b > 0`.
    pub fn new(a: f64, b: f64, center: [f64; 2]) -> Result<Self> {
        check("a", a, a > 0.0, "must be > 0")?;
        check("b", b, b > 0.0, "must be > 0")?;
        check("center", center[0], center[1].is_finite(), "must be finite")?;
        Ok(Self {
            a,
            b,
            center: V2::from_arr(center),
        })
    }
    /// The center.
    pub fn center(&self) -> [f64; 2] {
        self.center.arr()
    }
}

parameters!(Ellipse {
    /// Semi-axis along x.
    a: f64,
    /// Semi-axis along y.
    b: f64,
});

/// Limaçon `r(φ) = a + b cos φ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limacon {
    pub(super) a: f64,
    pub(super) b: f64,
}

impl Limacon {
    /// A simple limaçon: `a > b ≥ 0`.
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check("b", b, b >= 0.0, "must be ≥ 0")?;
        check("a", a, a > b, "must be > b for a simple curve")?;
        Ok(Self { a, b })
    }
}

parameters!(Limacon {
    /// Constant term.
    a: f64,
    /// Cosine amplitude.
    b: f64,
});

/// Elliptic lemniscate `r(φ) = sqrt(a² cos² φ + b² sin² φ)`: certified on its exact rational
/// form (the inverse of an ellipse) up to `a/b = 5` (either way round), sampled beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticLemniscate {
    pub(super) a: f64,
    pub(super) b: f64,
}

impl EllipticLemniscate {
    /// An elliptic lemniscate with `a, b > 0`.
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check("a", a, a > 0.0, "must be > 0")?;
        check("b", b, b > 0.0, "must be > 0")?;
        Ok(Self { a, b })
    }
}

parameters!(EllipticLemniscate {
    /// Radius at φ = 0.
    a: f64,
    /// Radius at φ = π/2.
    b: f64,
});

/// Curve with convexities `r(φ) = p / (1 + ε cos mφ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Convexities {
    pub(super) p: f64,
    pub(super) eps: f64,
    pub(super) m: u32,
}

impl Convexities {
    /// `p > 0`, `0 < ε < 1`, integer `m ≥ 2`.
    pub fn new(p: f64, eps: f64, m: u32) -> Result<Self> {
        check("p", p, p > 0.0, "must be > 0")?;
        check("eps", eps, eps > 0.0 && eps < 1.0, "must be in (0, 1)")?;
        check("m", m as f64, m >= 2, "must be an integer ≥ 2")?;
        Ok(Self { p, eps, m })
    }
}

parameters!(Convexities {
    /// Scale.
    p: f64,
    /// Eccentricity.
    eps: f64,
    /// Number of lobes.
    m: u32,
});

impl Circle {
    /// The point and its derivatives up to `order` (≤ 3) at the angle `u`.
    #[inline]
    fn jet_in_angle(&self, u: f64, _order: usize) -> Jet {
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

impl Ellipse {
    /// The point and its derivatives up to `order` (≤ 3) at the angle `u`.
    #[inline]
    fn jet_in_angle(&self, u: f64, _order: usize) -> Jet {
        let (s, c) = u.sin_cos();
        ellipse_jet(self.a, self.b, self.center, s, c)
    }
}

impl Limacon {
    /// The point and its derivatives up to `order` (≤ 3) at the angle `u`.
    #[inline]
    fn jet_in_angle(&self, u: f64, _order: usize) -> Jet {
        let (s, c) = u.sin_cos();
        let (a, b) = (self.a, self.b);
        polar_jet_cs(s, c, [a + b * c, -b * s, -b * c, b * s])
    }
}

impl EllipticLemniscate {
    /// The point and its derivatives up to `order` (≤ 3) at the angle `u`.
    #[inline]
    fn jet_in_angle(&self, u: f64, order: usize) -> Jet {
        // r² = g = A + B cos 2φ; differentiate r² = g three times. The value itself as
        // a² cos² φ + b² sin² φ: the form with cos 2φ cancels near the waist (φ = π/2) of a
        // slender lemniscate, where g ≈ b² ≪ a².
        // (In units of the larger radius: the squares of radii of 1e-180 or 1e180 would
        // underflow or overflow.)
        let unit = self.a.max(self.b);
        let (a, b) = (self.a / unit, self.b / unit);
        let (aa, bb) = (a * a, b * b);
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
        polar_jet_to(s, c, [r, r1, r2, r3].map(|x| x * unit), order)
    }
}

impl Convexities {
    /// The point and its derivatives up to `order` (≤ 3) at the angle `u`.
    #[inline]
    fn jet_in_angle(&self, u: f64, order: usize) -> Jet {
        let (sm, cm) = (self.m as f64 * u).sin_cos();
        let (s, c) = u.sin_cos();
        convexities_jet(self.p, self.eps, self.m, s, c, sm, cm, order.max(1))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::super::jets::CircleShape;
    use super::*;
    use crate::PlaneCurve;

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
