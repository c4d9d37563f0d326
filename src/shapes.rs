//! The analytic curve kinds of the file format, as plain parameter structs.
//!
//! These record what a curve file says (for reports); the algorithms run on the `antipodal`
//! shape types they convert into. Every shape runs counterclockwise over `φ ∈ [0, 2π)`.

use antipodal::{shapes, PlaneCurve};

/// A circle `(cx + r cos φ, cy + r sin φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Center.
    pub center: [f64; 2],
    /// Radius (> 0).
    pub r: f64,
}

/// An axis-parallel ellipse `(cx + a cos φ, cy + b sin φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    /// Center.
    pub center: [f64; 2],
    /// Semi-axis along x (> 0).
    pub a: f64,
    /// Semi-axis along y (> 0).
    pub b: f64,
}

/// The limaçon `r(φ) = a + b cos φ` (a > b ≥ 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limacon {
    /// Constant term.
    pub a: f64,
    /// Cosine amplitude.
    pub b: f64,
}

/// The elliptic lemniscate `r(φ) = sqrt(a² cos² φ + b² sin² φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticLemniscate {
    /// Radius at φ = 0.
    pub a: f64,
    /// Radius at φ = π/2.
    pub b: f64,
}

/// The curve with convexities `r(φ) = p / (1 + eps cos(m φ))`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Convexities {
    /// Scale (> 0).
    pub p: f64,
    /// Eccentricity, in (0, 1).
    pub eps: f64,
    /// Number of lobes (≥ 2).
    pub m: u32,
}

/// One of the analytic kinds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Analytic {
    /// `circle`.
    Circle(Circle),
    /// `ellipse`.
    Ellipse(Ellipse),
    /// `limacon`.
    Limacon(Limacon),
    /// `elliptic_lemniscate`.
    EllipticLemniscate(EllipticLemniscate),
    /// `convexities`.
    Convexities(Convexities),
}

impl Analytic {
    /// The `kind` name used in curve files.
    pub fn kind(&self) -> &'static str {
        match self {
            Analytic::Circle(_) => "circle",
            Analytic::Ellipse(_) => "ellipse",
            Analytic::Limacon(_) => "limacon",
            Analytic::EllipticLemniscate(_) => "elliptic_lemniscate",
            Analytic::Convexities(_) => "convexities",
        }
    }

    /// The shape as an `antipodal` curve (exact derivatives; the algorithms run on this).
    ///
    /// The parameters were validated when the file was read, so the constructors cannot
    /// refuse them; their error is passed on all the same rather than unwrapped.
    pub fn to_plane_curve(&self) -> antipodal::Result<Box<dyn PlaneCurve>> {
        Ok(match *self {
            Analytic::Circle(Circle { center, r }) => Box::new(shapes::Circle::new(r, center)?),
            Analytic::Ellipse(Ellipse { center, a, b }) => {
                Box::new(shapes::Ellipse::new(a, b, center)?)
            }
            Analytic::Limacon(Limacon { a, b }) => Box::new(shapes::Limacon::new(a, b)?),
            Analytic::EllipticLemniscate(EllipticLemniscate { a, b }) => {
                Box::new(shapes::EllipticLemniscate::new(a, b)?)
            }
            Analytic::Convexities(Convexities { p, eps, m }) => {
                Box::new(shapes::Convexities::new(p, eps, m)?)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every kind converts, and the converted curve starts where the file's formula says.
    #[test]
    fn converts_to_plane_curves() {
        let cases = [
            (
                Analytic::Circle(Circle {
                    center: [1.0, 2.0],
                    r: 2.0,
                }),
                [3.0, 2.0],
            ),
            (
                Analytic::Ellipse(Ellipse {
                    center: [0.0, 1.0],
                    a: 3.0,
                    b: 1.0,
                }),
                [3.0, 1.0],
            ),
            (Analytic::Limacon(Limacon { a: 4.0, b: 2.5 }), [6.5, 0.0]),
            (
                Analytic::EllipticLemniscate(EllipticLemniscate { a: 6.0, b: 3.0 }),
                [6.0, 0.0],
            ),
            (
                Analytic::Convexities(Convexities {
                    p: 3.0,
                    eps: 0.5,
                    m: 3,
                }),
                [2.0, 0.0],
            ),
        ];
        for (shape, start) in cases {
            let c = shape.to_plane_curve().unwrap();
            let p = c.jet(0.0).p;
            assert!(
                (p.x - start[0]).abs() < 1e-12 && (p.y - start[1]).abs() < 1e-12,
                "{shape:?}"
            );
            assert!(c.is_closed());
        }
    }
}
