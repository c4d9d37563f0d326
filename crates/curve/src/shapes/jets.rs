//! The shapes' jets from the sine and cosine of an angle, and [`CircleShape`], the shapes as
//! formulas in the rational circle's angle: shared by the evaluation in φ (`kinds`) and by the
//! circle forms, so kept apart from both.

use crate::circle::Angle;
use crate::geom::{Jet, V2};

/// A polar curve `r(φ)(cos φ, sin φ)` from the sine and cosine of φ, `r` and its first three
/// derivatives.
pub(super) fn polar_jet_cs(s: f64, c: f64, r: [f64; 4]) -> Jet {
    polar_jet_to(s, c, r, 3)
}

/// [`polar_jet_cs`] up to derivative `order` (higher ones left zero).
#[inline]
pub(super) fn polar_jet_to(s: f64, c: f64, r: [f64; 4], order: usize) -> Jet {
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
pub enum CircleShape {
    /// `(cx + a cos ψ, cy + b sin ψ)`.
    Ellipse {
        /// Semi-axis along x.
        a: f64,
        /// Semi-axis along y.
        b: f64,
        /// Center.
        center: V2,
    },
    /// `r = a + b cos ψ`.
    Limacon {
        /// Constant term.
        a: f64,
        /// Cosine amplitude.
        b: f64,
    },
    /// `r = p / (1 + ε cos mψ)`.
    Convexities {
        /// Scale.
        p: f64,
        /// Eccentricity.
        eps: f64,
        /// Lobes.
        m: u32,
    },
    /// The inverse of the ellipse point `(cos ψ / a, sin ψ / b)` in the unit circle.
    Lemniscate {
        /// Radius at φ = 0.
        a: f64,
        /// Radius at φ = π/2.
        b: f64,
    },
}

impl CircleShape {
    /// How the rational circle's angle ψ maps back to the shape's own angle φ: the same,
    /// except for the elliptic lemniscate (`tan φ = (a/b) tan ψ`).
    pub fn angle(&self) -> Angle {
        match *self {
            CircleShape::Lemniscate { a, b } => Angle::Squeezed { a, b },
            _ => Angle::Circle,
        }
    }

    /// Point and derivatives in ψ up to `order` at the angle with cosine `c` and sine `s`.
    /// (Inlined into the circle form's jets, the hottest path of a run: left to itself the
    /// compiler stopped doing so as the crate grew, at 3 % of a run.)
    #[inline]
    pub fn jet(self, c: f64, s: f64, order: usize) -> Jet {
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

pub(super) fn ellipse_jet(a: f64, b: f64, center: V2, s: f64, c: f64) -> Jet {
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
pub(super) fn convexities_jet(
    p: f64,
    e: f64,
    m: u32,
    s: f64,
    c: f64,
    sm: f64,
    cm: f64,
    order: usize,
) -> Jet {
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
