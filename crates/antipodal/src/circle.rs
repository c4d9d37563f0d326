//! Analytic shapes on the rational unit circle: the curve `C(φ)` seen in the parameter `u ∈
//! [0, 4]` of the rational circle of `bspline::shapes` (`φ = angle(u)`), together with its exact
//! rational B-spline form in that parameter. The algorithms then decide everything by sign
//! tests on the form's symbolic B-splines (certified), evaluate jets from the analytic formula
//! (chain rule through `φ(u)`), and report parameters mapped back to `φ`.

use crate::curve::PlaneCurve;
use crate::forms::{Forms, SymbolicForms};
use crate::geom::Jet;
use bspline::Rational;
use std::f64::consts::{FRAC_1_SQRT_2, PI, TAU};

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
            None => Forms::Built(Box::new(SymbolicForms::new(inner.circle_form()?).ok()?)),
        };
        Some(Self { inner, forms })
    }
}

/// Homogeneous control points `(X, Y)` of the quarter circles (the weights are `1, 1/√2, 1`);
/// quarter `q` runs from angle `qπ/2` to `(q + 1)π/2`.
fn quarter(q: usize) -> [[f64; 2]; 3] {
    let w = FRAC_1_SQRT_2;
    match q {
        0 => [[1.0, 0.0], [w, w], [0.0, 1.0]],
        1 => [[0.0, 1.0], [-w, w], [-1.0, 0.0]],
        2 => [[-1.0, 0.0], [-w, -w], [0.0, -1.0]],
        _ => [[0.0, -1.0], [w, -w], [1.0, 0.0]],
    }
}

/// The angle `φ(u) ∈ [0, 2π)` of the rational circle and its first three derivatives.
pub(crate) fn angle(u: f64) -> [f64; 4] {
    let (phi, _, d) = frame(u);
    [phi, d[0], d[1], d[2]]
}

/// The angle `φ(u)`, its cosine and sine, and its first three derivatives.
fn frame(u: f64) -> (f64, [f64; 2], [f64; 3]) {
    let (cs, d, q, x, y) = frame_cs(u, 3);
    let phi = q as f64 * (PI / 2.0) + local(q, x, y);
    (if phi >= TAU { 0.0 } else { phi }, cs, d)
}

/// `(cos φ, sin φ)`, the derivatives of φ, and the quarter and homogeneous point (no atan2).
fn frame_cs(u: f64, order: usize) -> ([f64; 2], [f64; 3], usize, f64, f64) {
    let u = if (0.0..4.0).contains(&u) {
        u
    } else {
        u.rem_euclid(4.0)
    };
    // u ≥ 0 here: truncation is the floor.
    let q = (u as usize).min(3);
    let s = u - q as f64;
    let [p0, p1, p2] = quarter(q);
    // Quadratic Bernstein basis and derivatives (the third derivative vanishes).
    let b = [(1.0 - s) * (1.0 - s), 2.0 * s * (1.0 - s), s * s];
    let b1 = [-2.0 * (1.0 - s), 2.0 - 4.0 * s, 2.0 * s];
    let b2 = [2.0, -4.0, 2.0];
    let comb = |c: &[f64; 3], k: usize| c[0] * p0[k] + c[1] * p1[k] + c[2] * p2[k];
    let (x, y) = (comb(&b, 0), comb(&b, 1));
    let (x1, y1) = (comb(&b1, 0), comb(&b1, 1));
    let (x2, y2) = (comb(&b2, 0), comb(&b2, 1));
    // φ = atan2(Y, X): φ′ = N/M with N = XY′ − YX′, M = X² + Y².
    let n = x * y1 - y * x1;
    let n1 = x * y2 - y * x2;
    let n2 = x1 * y2 - y1 * x2;
    let m = x * x + y * y;
    let m1 = 2.0 * (x * x1 + y * y1);
    let m2 = 2.0 * (x1 * x1 + x * x2 + y1 * y1 + y * y2);
    let d1 = n / m;
    let (mut d2, mut d3) = (0.0, 0.0);
    if order >= 2 {
        let g = n1 * m - n * m1;
        d2 = g / (m * m);
        if order >= 3 {
            d3 = (n2 * m - n * m2) / (m * m) - 2.0 * m1 * g / (m * m * m);
        }
    }
    let inv = 1.0 / m.sqrt();
    ([x * inv, y * inv], [d1, d2, d3], q, x, y)
}

/// Angle of `(x, y)` measured from the start of quarter `q`, in `[0, π/2]`.
fn local(q: usize, x: f64, y: f64) -> f64 {
    // Rotate back by qπ/2.
    let (rx, ry) = match q {
        0 => (x, y),
        1 => (y, -x),
        2 => (-x, -y),
        _ => (-y, x),
    };
    ry.atan2(rx)
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
            let (cs, d, ..) = frame_cs(u, order);
            [a1, a2, a3] = d;
            j = shape.jet(cs[0], cs[1], order);
        } else {
            let (phi, _, d) = frame(u);
            [a1, a2, a3] = d;
            j = self.inner.jet_to(phi, order);
        }
        Jet {
            p: j.p,
            d1: j.d1 * a1,
            d2: j.d2 * (a1 * a1) + j.d1 * a2,
            d3: j.d3 * (a1 * a1 * a1) + j.d2 * (3.0 * a1 * a2) + j.d1 * a3,
        }
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
}
