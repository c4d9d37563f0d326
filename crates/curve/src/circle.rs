//! The rational unit circle the analytic shapes are exact on: nine control points, degree 2,
//! on the parameter domain `[0, 4]` (one quarter per unit), weights `1, 1/√2, 1` per quarter.
//! A shape whose polar or Cartesian form is a polynomial in `(cos φ, sin φ)`, or a quotient of
//! such polynomials, is exactly a rational B-spline in the circle's parameter `u` (see
//! [`crate::shapes`]). The parameter is not the angle: [`angle`] and [`circle_param`] convert.
//!
//! The weight `1/√2` is rounded to a double: the homogeneous coefficients carry that rounding
//! as their error, so the certified decisions cover the exact circle.

use bspline::Piecewise;
use numeric::rounding::UNIT_ROUNDOFF;
use std::f64::consts::{FRAC_1_SQRT_2, PI, SQRT_2, TAU};

/// The homogeneous unit circle `(X, Y, W)` in pieces (one per quarter, C⁰ at the quarters,
/// periodic), with the rounding of `1/√2` as the error of every coefficient.
pub fn circle_pieces() -> bspline::Result<Piecewise> {
    let w = FRAC_1_SQRT_2;
    // Quarter 0 from (1, 0) through (1, 1) to (0, 1); each next one rotated by a right angle.
    let mut coefs = Vec::with_capacity(4 * 9);
    let rot = |(x, y): (f64, f64), q: u32| match q {
        0 => (x, y),
        1 => (-y, x),
        2 => (-x, -y),
        _ => (y, -x),
    };
    for q in 0..4 {
        for (pt, wt) in [((1.0, 0.0), 1.0), ((1.0, 1.0), w), ((0.0, 1.0), 1.0)] {
            let (x, y) = rot(pt, q);
            coefs.extend([x * wt, y * wt, wt]);
        }
    }
    let err = vec![UNIT_ROUNDOFF; 4 * 3];
    let smooth = vec![0, 0, 0, 0, 0];
    Piecewise::from_parts(2, 3, vec![0.0, 1.0, 2.0, 3.0, 4.0], coefs, err, smooth)
}

/// The polar angle φ ∈ [0, 2π) of the parameter `u ∈ [0, 4]` of the rational circle.
pub fn circle_angle(u: f64) -> f64 {
    angle(u)[0]
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
    let s = SQRT_2 * t / (1.0 - t + SQRT_2 * t);
    quarter + s
}

/// How a parameter `u` of a circle form maps back to the shape's own angle `φ ∈ [0, 2π)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Angle {
    /// `φ` is the circle's angle ψ itself.
    Circle,
    /// `φ` is the polar angle of `(cos ψ / a, sin ψ / b)` (the ellipse an elliptic lemniscate
    /// inverts).
    Squeezed {
        /// The lemniscate's `a`.
        a: f64,
        /// The lemniscate's `b`.
        b: f64,
    },
}

impl Angle {
    /// The shape's angle φ of the form's parameter `u`.
    pub fn phi(self, u: f64) -> f64 {
        match self {
            Angle::Circle => angle(u)[0],
            Angle::Squeezed { a, b } => {
                // Per quarter, from the local cosine and sine (no cancellation near the
                // quarter's ends); the rotation by qπ/2 swaps the roles of a and b on odd
                // quarters.
                let f = frame_cs(u);
                let [x, y] = f.local;
                let (sx, sy) = if f.q.is_multiple_of(2) {
                    (a, b)
                } else {
                    (b, a)
                };
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
pub fn angle(u: f64) -> [f64; 4] {
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
pub(crate) struct CirclePoint {
    /// `(cos φ, sin φ)`.
    pub(crate) cs: [f64; 2],
    /// `φ′, φ″, φ‴`.
    pub(crate) d: [f64; 3],
    /// The quarter, `φ ∈ [qπ/2, (q + 1)π/2]`.
    pub(crate) q: u32,
    /// Cosine and sine of `φ − qπ/2`.
    pub(crate) local: [f64; 2],
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
/// reparametrisation of the half-angle (see [`circle_param`]), whence
/// `φ′ = √2 / W`.
pub(crate) fn frame_cs(u: f64) -> CirclePoint {
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
    CirclePoint {
        cs,
        d: [d1, d2, d3],
        q,
        local: [x, y],
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use numeric::rounding::ulps;

    /// The closed form of the angle against the rational circle's pieces, and its derivatives
    /// against central differences; the parameter of an angle inverts it.
    #[test]
    fn angle_matches_the_rational_circle() {
        for i in 0..=400 {
            let u = 4.0 * i as f64 / 400.0;
            let [phi, d1, d2, d3] = angle(u);
            // The angle of the homogeneous point of the circle's pieces.
            let mut h = [0.0; 3];
            circle_pieces().unwrap().eval(u.min(4.0 - 1e-15), &mut h);
            let want = h[1].atan2(h[0]).rem_euclid(TAU);
            let diff = (phi - want).rem_euclid(TAU);
            assert!(diff.min(TAU - diff) < 1e-13, "{u}: {phi} vs {want}");
            let back = circle_param(phi);
            assert!(
                (back - u).abs() < 1e-12 || (u > 4.0 - 1e-12 && back < 1e-12),
                "{u}: {back}"
            );
            // Derivatives against central differences (inside a quarter).
            let s = u.fract();
            if s > 0.01 && s < 0.99 {
                let h = 1e-5;
                let f = |v: f64| angle(v);
                let num1 = (f(u + h)[0] - f(u - h)[0]) / (2.0 * h);
                let num2 = (f(u + h)[1] - f(u - h)[1]) / (2.0 * h);
                let num3 = (f(u + h)[2] - f(u - h)[2]) / (2.0 * h);
                testkit::assert_near!(num1, d1, 1e-7, "{u}");
                testkit::assert_near!(num2, d2, 1e-6, "{u}");
                testkit::assert_near!(num3, d3, 1e-5, "{u}");
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
                testkit::assert_near!(f.cs[k], cs[k], 4e-16, "{u}: {:?} vs {cs:?}", f.cs);
            }
            // The reference cancels in φ″ and φ‴ (the closed form does not): a bound relative
            // to the derivatives' size.
            let size = d[0].abs() + d[1].abs() + d[2].abs();
            for k in 0..3 {
                let tol = ulps(16.0) * size;
                testkit::assert_near!(f.d[k], d[k], tol, "{u}: {:?} vs {d:?}", f.d);
            }
            // The rotation by quarters lands on the unit circle.
            testkit::assert_near!(f.cs[0].hypot(f.cs[1]), 1.0, 4e-16, "{u}");
        }
    }
}
