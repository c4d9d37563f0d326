//! Analytic shapes on the rational unit circle: the curve seen in the parameter `u ∈ [0, 4]` of
//! the rational circle of `bspline::shapes` (circle angle `ψ = angle(u)`), together with its
//! exact rational B-spline form in that parameter. The algorithms then decide everything by
//! sign tests on the form's symbolic B-splines (certified), evaluate jets from the analytic
//! formula in `(cos ψ, sin ψ)` (chain rule through `ψ(u)`), and report parameters mapped back
//! to the shape's own angle φ ([`Angle`]: `φ = ψ`, except for the elliptic lemniscate, the
//! inverse of an ellipse, where `tan φ = (a/b) tan ψ`).

use crate::curve::PlaneCurve;
use crate::forms::{Forms, Seam, SymbolicForms};
use crate::geom::Jet;
use crate::shapes::CircleShape;
use bspline::Rational;
use std::f64::consts::{PI, SQRT_2, TAU};

/// An analytic curve in the rational-circle parameter.
pub(crate) struct OnCircle<'a> {
    inner: &'a dyn PlaneCurve,
    forms: Forms<'a>,
}

impl<'a> OnCircle<'a> {
    /// The curve on its circle form, when it has one: the forms it keeps, or built for this
    /// run. `None` when it has none (or they cannot be built).
    pub(crate) fn new(inner: &'a dyn PlaneCurve) -> Option<Self> {
        let forms = match inner.circle_forms() {
            Some(f) => Forms::Kept(f),
            None => Forms::Built(Box::new(
                SymbolicForms::new(inner.circle_form()?, Seam::Circle).ok()?,
            )),
        };
        Some(Self { inner, forms })
    }

    /// How this form's parameter maps back to the shape's angle.
    pub(crate) fn angle(&self) -> Angle {
        match self.forms.shape {
            Some(CircleShape::Lemniscate { a, b }) => Angle::Squeezed { a, b },
            _ => Angle::Circle,
        }
    }
}

/// How a parameter `u` of a circle form maps back to the shape's own angle `φ ∈ [0, 2π)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Angle {
    /// `φ` is the circle's angle ψ itself.
    Circle,
    /// `φ` is the polar angle of `(cos ψ / a, sin ψ / b)` (the ellipse an elliptic lemniscate
    /// inverts).
    Squeezed { a: f64, b: f64 },
}

impl Angle {
    /// The shape's angle φ of the form's parameter `u`.
    pub(crate) fn phi(self, u: f64) -> f64 {
        match self {
            Angle::Circle => angle(u)[0],
            Angle::Squeezed { a, b } => {
                // Per quarter, from the local cosine and sine (no cancellation near the
                // quarter's ends); the rotation by qπ/2 swaps the roles of a and b on odd
                // quarters.
                let f = frame_cs(u);
                let [x, y] = f.local;
                let (sx, sy) = if f.q % 2 == 0 { (a, b) } else { (b, a) };
                let phi = f.q as f64 * (PI / 2.0) + (y / sy).atan2(x / sx);
                if phi >= TAU {
                    0.0
                } else {
                    phi
                }
            }
        }
    }
}

/// The angle `φ(u) ∈ [0, 2π)` of the rational circle and its first three derivatives.
pub(crate) fn angle(u: f64) -> [f64; 4] {
    let (phi, _, d) = frame(u);
    [phi, d[0], d[1], d[2]]
}

/// The angle `φ(u)`, its cosine and sine, and its first three derivatives.
fn frame(u: f64) -> (f64, [f64; 2], [f64; 3]) {
    let f = frame_cs(u);
    let phi = f.q as f64 * (PI / 2.0) + f.local[1].atan2(f.local[0]);
    (if phi >= TAU { 0.0 } else { phi }, f.cs, f.d)
}

/// The rational circle at one parameter, without the angle itself.
struct Frame {
    /// `(cos φ, sin φ)`.
    cs: [f64; 2],
    /// `φ′, φ″, φ‴`.
    d: [f64; 3],
    /// The quarter, `φ ∈ [qπ/2, (q + 1)π/2]`.
    q: u32,
    /// Cosine and sine of `φ − qπ/2`.
    local: [f64; 2],
}

/// `√2 − 1`.
const SQRT2_M1: f64 = SQRT_2 - 1.0;
/// `2 − √2`.
const TWO_M_SQRT2: f64 = 2.0 - SQRT_2;

/// `(cos φ, sin φ)` and the derivatives of φ at `u`, in closed form (no angle, no square root,
/// one division).
///
/// On quarter `q` (`u = q + s`) the rational quadratic with control points `(1, 0), (1, 1),
/// (0, 1)` and weights `1, 1/√2, 1` is `(X, Y) / W` with
/// `X = (1 − s)(1 + (√2 − 1)s)`, `Y = s(√2 − (√2 − 1)s)` and `W = 1 − (2 − √2)s(1 − s)`
/// (factored: no cancellation near either end), rotated by `qπ/2`. It is a Möbius
/// reparametrisation of the half-angle (see `bspline::shapes::circle_param`), whence
/// `φ′ = √2 / W`.
fn frame_cs(u: f64) -> Frame {
    let u = if (0.0..4.0).contains(&u) {
        u
    } else {
        u.rem_euclid(4.0)
    };
    // u ≥ 0 here: truncation is the floor (to u32: a cheaper conversion than to usize).
    let q = (u as u32).min(3);
    let s = u - q as f64;
    let t = 1.0 - s;
    let inv = 1.0 / (1.0 - TWO_M_SQRT2 * (s * t));
    let (x, y) = (
        t * (1.0 + SQRT2_M1 * s) * inv,
        s * (SQRT_2 - SQRT2_M1 * s) * inv,
    );
    // φ′ = √2/W, φ″ = −√2 W′/W², φ‴ = −√2 (W″ − 2W′²/W)/W², with W′ = (2 − √2)(2s − 1)
    // and W″ = 2(2 − √2).
    let w1 = TWO_M_SQRT2 * (s - t);
    let d1 = SQRT_2 * inv;
    let d2 = -d1 * w1 * inv;
    let d3 = 2.0 * d1 * inv * (w1 * w1 * inv - TWO_M_SQRT2);
    let cs = match q {
        0 => [x, y],
        1 => [-y, x],
        2 => [-x, -y],
        _ => [y, -x],
    };
    Frame {
        cs,
        d: [d1, d2, d3],
        q,
        local: [x, y],
    }
}

impl PlaneCurve for OnCircle<'_> {
    fn domain(&self) -> (f64, f64) {
        (0.0, 4.0)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet(&self, u: f64) -> Jet {
        self.jet_to(u, 3)
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        let j;
        let (a1, a2, a3);
        if let Some(shape) = self.forms.shape {
            // The shape's own formula from (cos φ, sin φ): no angle, no sine or cosine.
            let f = frame_cs(u);
            [a1, a2, a3] = f.d;
            j = shape.jet(f.cs[0], f.cs[1], order);
        } else {
            let (phi, _, d) = frame(u);
            [a1, a2, a3] = d;
            j = self.inner.jet_to(phi, order);
        }
        // Chain rule, up to the order asked for (the rest is left zero).
        let mut out = Jet {
            p: j.p,
            d1: j.d1 * a1,
            ..Jet::default()
        };
        if order >= 2 {
            out.d2 = j.d2 * (a1 * a1) + j.d1 * a2;
        }
        if order >= 3 {
            out.d3 = j.d3 * (a1 * a1 * a1) + j.d2 * (3.0 * a1 * a2) + j.d1 * a3;
        }
        out
    }
    fn rational(&self) -> Option<&Rational> {
        Some(&self.forms.curve)
    }
    fn symbolic_forms(&self) -> Option<&SymbolicForms> {
        Some(&self.forms)
    }
    fn known_simple(&self) -> bool {
        self.inner.known_simple()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::geom::V2;

    #[test]
    fn angle_matches_the_rational_circle() {
        for i in 0..=400 {
            let u = 4.0 * i as f64 / 400.0;
            let [phi, d1, d2, d3] = angle(u);
            let want = bspline::shapes::circle_angle(u.min(4.0 - 1e-15));
            let diff = (phi - want).rem_euclid(TAU);
            assert!(diff.min(TAU - diff) < 1e-13, "{u}: {phi} vs {want}");
            // Derivatives against central differences (inside a quarter).
            let s = u.fract();
            if s > 0.01 && s < 0.99 {
                let h = 1e-5;
                let f = |v: f64| angle(v);
                let num1 = (f(u + h)[0] - f(u - h)[0]) / (2.0 * h);
                let num2 = (f(u + h)[1] - f(u - h)[1]) / (2.0 * h);
                let num3 = (f(u + h)[2] - f(u - h)[2]) / (2.0 * h);
                assert!((num1 - d1).abs() < 1e-7, "{u}");
                assert!((num2 - d2).abs() < 1e-6, "{u}");
                assert!((num3 - d3).abs() < 1e-5, "{u}");
            }
        }
    }

    /// `(cos φ, sin φ)` and `φ′, φ″, φ‴` the long way: the homogeneous quadratic Bézier
    /// quarters, normalised by `√(X² + Y²)`, and the quotient rule on `φ′ = (XY′ − YX′)/(X² + Y²)`.
    fn bernstein_frame(u: f64) -> ([f64; 2], [f64; 3]) {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let u = u.rem_euclid(4.0);
        let q = (u as usize).min(3);
        let s = u - q as f64;
        let [p0, p1, p2] = match q {
            0 => [[1.0, 0.0], [w, w], [0.0, 1.0]],
            1 => [[0.0, 1.0], [-w, w], [-1.0, 0.0]],
            2 => [[-1.0, 0.0], [-w, -w], [0.0, -1.0]],
            _ => [[0.0, -1.0], [w, -w], [1.0, 0.0]],
        };
        let b = [(1.0 - s) * (1.0 - s), 2.0 * s * (1.0 - s), s * s];
        let b1 = [-2.0 * (1.0 - s), 2.0 - 4.0 * s, 2.0 * s];
        let b2 = [2.0, -4.0, 2.0];
        let comb = |c: &[f64; 3], k: usize| c[0] * p0[k] + c[1] * p1[k] + c[2] * p2[k];
        let (x, y) = (comb(&b, 0), comb(&b, 1));
        let (x1, y1) = (comb(&b1, 0), comb(&b1, 1));
        let (x2, y2) = (comb(&b2, 0), comb(&b2, 1));
        let n = x * y1 - y * x1;
        let n1 = x * y2 - y * x2;
        let n2 = x1 * y2 - y1 * x2;
        let m = x * x + y * y;
        let m1 = 2.0 * (x * x1 + y * y1);
        let m2 = 2.0 * (x1 * x1 + x * x2 + y1 * y1 + y * y2);
        let g = n1 * m - n * m1;
        let d = [
            n / m,
            g / (m * m),
            (n2 * m - n * m2) / (m * m) - 2.0 * m1 * g / (m * m * m),
        ];
        let r = m.sqrt();
        ([x / r, y / r], d)
    }

    #[test]
    fn closed_form_frame_matches_the_bernstein_form() {
        // Dense over the four quarters, their ends, and wrapped parameters.
        let mut us: Vec<f64> = (0..=4000).map(|i| 4.0 * i as f64 / 4000.0).collect();
        us.extend([
            -0.3,
            -4.0,
            4.0 - 1e-16,
            5.25,
            1e-300,
            1.0 - 1e-15,
            3.999_999,
        ]);
        for u in us {
            let f = frame_cs(u);
            let (cs, d) = bernstein_frame(u);
            for k in 0..2 {
                assert!(
                    (f.cs[k] - cs[k]).abs() <= 4e-16,
                    "{u}: {:?} vs {cs:?}",
                    f.cs
                );
            }
            // The reference cancels in φ″ and φ‴ (the closed form does not): a bound relative
            // to the derivatives' size.
            let size = d[0].abs() + d[1].abs() + d[2].abs();
            for k in 0..3 {
                let tol = 16.0 * f64::EPSILON * size;
                assert!((f.d[k] - d[k]).abs() <= tol, "{u}: {:?} vs {d:?}", f.d);
            }
            // The rotation by quarters lands on the unit circle.
            assert!((f.cs[0].hypot(f.cs[1]) - 1.0).abs() <= 4e-16, "{u}");
        }
    }

    /// The shapes' formulas on the circle (`CircleShape`) against the generic path: the angle
    /// `φ(u)` and the shape's own jet in φ (sines and cosines), through the chain rule.
    #[test]
    fn shape_jets_match_the_generic_path() {
        use crate::shapes::{Convexities, Ellipse, Limacon};
        let shapes: Vec<Box<dyn PlaneCurve>> = vec![
            Box::new(Ellipse::new(3.0, 2.0, [0.5, -1.0]).unwrap()),
            Box::new(Limacon::new(4.0, 2.5).unwrap()),
            Box::new(Convexities::new(3.0, 0.5, 3).unwrap()),
            Box::new(Convexities::new(4.5, 0.2, 4).unwrap()),
            Box::new(Convexities::new(1.0, 0.9, 2).unwrap()),
            Box::new(Convexities::new(2.0, 0.3, 7).unwrap()),
        ];
        for inner in &shapes {
            let fast = OnCircle::new(inner.as_ref()).unwrap();
            assert!(fast.forms.shape.is_some());
            let generic = OnCircle {
                inner: inner.as_ref(),
                forms: Forms::Built(Box::new(
                    SymbolicForms::new(inner.circle_form().unwrap(), Seam::Circle).unwrap(),
                )),
            };
            for i in 0..=1000 {
                let u = 4.0 * i as f64 / 1000.0 - 0.002;
                let (a, b) = (fast.jet_to(u, 3), generic.jet_to(u, 3));
                let scale = b.p.norm() + b.d1.norm() + b.d2.norm() + b.d3.norm();
                for (x, y) in [(a.p, b.p), (a.d1, b.d1), (a.d2, b.d2), (a.d3, b.d3)] {
                    assert!((x - y).norm() <= 1e-13 * scale, "{u}: {a:?} vs {b:?}");
                }
                // Lower orders: the same leading entries, the rest left zero.
                for order in 0..3 {
                    let j = fast.jet_to(u, order);
                    let full = [a.p, a.d1, a.d2, a.d3];
                    for (k, v) in [j.p, j.d1, j.d2, j.d3].into_iter().enumerate() {
                        if k <= order.max(1) {
                            assert_eq!(v, full[k], "{u} order {order}");
                        } else {
                            assert_eq!(v, V2::default(), "{u} order {order}");
                        }
                    }
                }
            }
        }
    }

    /// The elliptic lemniscate on its circle form (the inverse of an ellipse): the jets from
    /// `(cos ψ, sin ψ)` against the exact rational form's own derivatives, and the reported
    /// angle against the point's polar angle and the shape's formula in φ.
    #[test]
    fn lemniscate_form_matches_its_rational_form_and_angle() {
        use crate::shapes::EllipticLemniscate;
        for (a, b) in [(6.0, 3.0), (2.0, 1.0), (1.0, 4.0), (5.0, 1.0), (1.0, 1.0)] {
            let inner = EllipticLemniscate::new(a, b).unwrap();
            let c = OnCircle::new(&inner).unwrap();
            let angle = c.angle();
            assert_eq!(angle, Angle::Squeezed { a, b });
            let mut out = [0.0; 8];
            // (u = 4 is the seam: the jet wraps to u = 0, where ψ″ jumps.)
            for i in 0..2000 {
                let u = 4.0 * i as f64 / 2000.0;
                let j = c.jet_to(u, 3);
                c.forms.curve.eval_derivs(u, 3, &mut out);
                let exact = [0, 1, 2, 3].map(|k| V2::new(out[2 * k], out[2 * k + 1]));
                let scale = exact.iter().map(|v| v.norm()).sum::<f64>();
                for (k, (x, y)) in [j.p, j.d1, j.d2, j.d3].into_iter().zip(exact).enumerate() {
                    assert!(
                        (x - y).norm() <= 1e-12 * scale,
                        "{a}/{b} u = {u} d{k}: {x:?} vs {y:?}"
                    );
                }
                let phi = angle.phi(u);
                assert!((0.0..TAU).contains(&phi), "{u}: {phi}");
                let polar = j.p.y.atan2(j.p.x).rem_euclid(TAU);
                let d = (phi - polar).abs();
                assert!(
                    d.min(TAU - d) <= 1e-14 * TAU,
                    "{a}/{b} u = {u}: {phi} vs {polar}"
                );
                let own = inner.jet(phi).p;
                assert!(
                    (own - j.p).norm() <= 1e-13 * a.max(b),
                    "{u}: {own:?} vs {:?}",
                    j.p
                );
            }
            // The angle runs up monotonically from 0 (no jump inside the domain).
            let mut last = -1.0;
            for i in 0..4000 {
                let phi = angle.phi(4.0 * i as f64 / 4000.0);
                assert!(phi > last, "{a}/{b}: φ not increasing at {i}");
                last = phi;
            }
        }
        // Too slender a lemniscate keeps the sampled path.
        assert!(OnCircle::new(&EllipticLemniscate::new(6.0, 1.0).unwrap()).is_none());
    }
}
