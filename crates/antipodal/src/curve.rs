//! The plane-curve trait the algorithms run on, and its B-spline/NURBS implementation.

use crate::error::{Error, Result};
use crate::forms::{kept, KeptForms, Seam, SymbolicForms};
use crate::geom::{Jet, V2};
use bspline::{BSpline, Piecewise, Rational};

/// A regular parametric plane curve with three continuous derivatives (piecewise for splines).
///
/// Analytic shapes implement it with exact derivatives; B-spline and NURBS curves
/// ([`SplineCurve`]) also expose their exact rational form, which lets the algorithms certify
/// their decisions by sign tests on symbolic B-splines.
pub trait PlaneCurve {
    /// The parameter domain `[a, b]`; a closed curve has period `b − a`.
    fn domain(&self) -> (f64, f64);
    /// True when the curve is closed (`C(a) = C(b)` with matching tangents).
    fn is_closed(&self) -> bool;
    /// Point and first three derivatives at `u ∈ [a, b]`.
    fn jet(&self, u: f64) -> Jet;
    /// Point and derivatives up to `order` (≤ 3) at `u`; higher entries may be left zero.
    /// Curves whose derivatives cost extra (splines) override it.
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        let _ = order;
        self.jet(u)
    }
    /// The exact rational B-spline form, when the curve has one.
    fn rational(&self) -> Option<&Rational> {
        None
    }
    /// The exact rational B-spline form of the curve in the parameter `u ∈ [0, 4]` of the
    /// rational unit circle of [`bspline::shapes`], for curves whose own parameter is that
    /// circle's angle `φ = bspline::shapes::circle_angle(u)` (the ellipse, the limaçon and the
    /// curves with convexities). With it the algorithms decide by sign tests on its symbolic
    /// B-splines (certified results) and still report parameters `φ`.
    fn circle_form(&self) -> Option<Rational> {
        None
    }
    /// The [`SymbolicForms`] of [`PlaneCurve::rational`], when the curve keeps them (the
    /// curve types of this crate build them on first use). `None` makes the algorithms build
    /// them for each run.
    fn symbolic_forms(&self) -> Option<&SymbolicForms> {
        None
    }
    /// The [`SymbolicForms`] of the curve's exact rational form in the parameter of the
    /// rational unit circle, when the curve keeps them: those of [`PlaneCurve::circle_form`],
    /// or, for a shape whose angle is not the circle's (the elliptic lemniscate), forms that
    /// carry the shape's own formula and angle.
    fn circle_forms(&self) -> Option<&SymbolicForms> {
        None
    }
    /// True when the curve is simple by construction (the analytic shapes with valid
    /// parameters), which skips the self-intersection check.
    fn known_simple(&self) -> bool {
        false
    }
}

/// A B-spline or NURBS plane curve, closed (periodic or clamped with equal end points) or open.
#[derive(Debug, Clone)]
pub struct SplineCurve {
    curve: Rational,
    closed: bool,
    /// How the curve continues across its seam.
    seam: Seam,
    /// The homogeneous curve as Bézier pieces (fast evaluation).
    fast: Piecewise,
    /// Symbolic forms, built on first use.
    forms: KeptForms,
}

impl PartialEq for SplineCurve {
    fn eq(&self, other: &Self) -> bool {
        self.curve == other.curve && self.closed == other.closed
    }
}

impl SplineCurve {
    /// Wraps a planar rational curve; it counts as closed when its end points coincide (within
    /// `1e-12` of its size).
    pub fn new(curve: Rational) -> Result<Self> {
        if curve.dim() != 2 {
            return Err(Error::Spline(bspline::Error::DimensionMismatch {
                expected: 2,
                got: curve.dim(),
            }));
        }
        let (a, b) = curve.domain();
        let (pa, pb) = (curve.point(a), curve.point(b));
        let size = control_size(&curve);
        let gap = (pa[0] - pb[0]).hypot(pa[1] - pb[1]);
        let closed = gap <= 1e-12 * size.max(f64::MIN_POSITIVE);
        let fast = Piecewise::from_bspline(curve.homogeneous());
        Ok(Self {
            curve,
            closed,
            seam: Seam::Unknown,
            fast,
            forms: KeptForms::new(),
        })
    }

    /// A closed uniform periodic B-spline (optionally rational) through `points`: domain
    /// `[0, n)`, the piece on `[i, i+1]` shaped by points `i..=i+p` (indices mod `n`).
    pub fn periodic(degree: usize, points: &[[f64; 2]], weights: Option<&[f64]>) -> Result<Self> {
        if let Some(w) = weights {
            if w.len() != points.len() {
                return Err(Error::Spline(bspline::Error::CountMismatch {
                    what: "weights (one per control point)",
                    expected: points.len(),
                    got: w.len(),
                }));
            }
        }
        let flat: Vec<f64> = points.iter().flat_map(|p| p.iter().copied()).collect();
        let spline = BSpline::periodic(degree, 2, flat)?;
        // The wrapped control points repeat the first `degree` ones, weights alike.
        let wrapped: Option<Vec<f64>> =
            weights.map(|w| w.iter().chain(&w[..degree.min(w.len())]).copied().collect());
        let curve = Rational::new(spline, wrapped.as_deref())?;
        let fast = Piecewise::from_bspline(curve.homogeneous());
        Ok(Self {
            curve,
            closed: true,
            seam: Seam::Periodic(degree as i32 - 1),
            fast,
            forms: KeptForms::new(),
        })
    }

    /// A clamped B-spline (optionally rational) with the given knots, or uniform ones on
    /// `[0, 1]`. It is closed when its first and last points coincide.
    pub fn clamped(
        degree: usize,
        points: &[[f64; 2]],
        weights: Option<&[f64]>,
        knots: Option<Vec<f64>>,
    ) -> Result<Self> {
        let flat: Vec<f64> = points.iter().flat_map(|p| p.iter().copied()).collect();
        let spline = match knots {
            Some(k) => BSpline::new(degree, k, 2, flat)?,
            None => BSpline::clamped_uniform(degree, 2, flat)?,
        };
        Self::new(Rational::new(spline, weights)?)
    }

    /// The underlying rational curve.
    pub fn curve(&self) -> &Rational {
        &self.curve
    }
}

/// Point and derivatives up to order `k ≤ 3` of the planar rational curve with homogeneous
/// form `h` (`out[2j..2j+2]` the j-th derivative), by the quotient rule
/// `C⁽ʲ⁾ = (X⁽ʲ⁾ − Σᵢ C(j,i) w⁽ⁱ⁾ C⁽ʲ⁻ⁱ⁾) / w`.
pub(crate) fn rational_derivs(h: &Piecewise, u: f64, k: usize, out: &mut [f64; 8]) {
    let mut hv = [0.0; 12];
    let k = k.min(3);
    h.eval_derivs(u, k, &mut hv[..3 * (k + 1)]);
    // Written out per order (the binomials of the rule are 1; 1, 2, 1; 1, 3, 3, 1).
    let inv = 1.0 / hv[2];
    let (w1, w2, w3) = (hv[5], hv[8], hv[11]);
    for c in 0..2 {
        let c0 = hv[c] * inv;
        out[c] = c0;
        if k >= 1 {
            let c1 = (hv[3 + c] - w1 * c0) * inv;
            out[2 + c] = c1;
            if k >= 2 {
                let c2 = (hv[6 + c] - 2.0 * w1 * c1 - w2 * c0) * inv;
                out[4 + c] = c2;
                if k >= 3 {
                    out[6 + c] = (hv[9 + c] - 3.0 * w1 * c2 - 3.0 * w2 * c1 - w3 * c0) * inv;
                }
            }
        }
    }
}

/// Diagonal of the control points' bounding box.
pub(crate) fn control_size(c: &Rational) -> f64 {
    let pts = c.control_points();
    let (mut lo, mut hi) = (V2::new(f64::MAX, f64::MAX), V2::new(f64::MIN, f64::MIN));
    for p in &pts {
        lo = V2::new(lo.x.min(p[0]), lo.y.min(p[1]));
        hi = V2::new(hi.x.max(p[0]), hi.y.max(p[1]));
    }
    (hi - lo).norm()
}

impl PlaneCurve for SplineCurve {
    fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn jet(&self, u: f64) -> Jet {
        self.jet_to(u, 3)
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        let mut o = [0.0; 8];
        let k = order.min(3);
        rational_derivs(&self.fast, u, k, &mut o);
        Jet {
            p: V2::new(o[0], o[1]),
            d1: V2::new(o[2], o[3]),
            d2: V2::new(o[4], o[5]),
            d3: V2::new(o[6], o[7]),
        }
    }
    fn rational(&self) -> Option<&Rational> {
        Some(&self.curve)
    }
    fn symbolic_forms(&self) -> Option<&SymbolicForms> {
        kept(&self.forms, || Some((self.curve.clone(), self.seam)))
    }
}

#[cfg(test)]
pub(crate) mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// A random star-shaped closed B-spline from `2n` numbers in `[0, 1)` (angle jitter and
    /// radius per control point), rational with the first `n` of `weights` when given.
    pub(crate) fn star_curve(deg: usize, seed: &[f64], weights: Option<&[f64]>) -> SplineCurve {
        star_curve_at(deg, seed, weights, [0.0, 0.0])
    }

    /// [`star_curve`] about `center` instead of the origin.
    pub(crate) fn star_curve_at(
        deg: usize,
        seed: &[f64],
        weights: Option<&[f64]>,
        center: [f64; 2],
    ) -> SplineCurve {
        let n = seed.len() / 2;
        let pts: Vec<[f64; 2]> = (0..n)
            .map(|i| {
                let ang = std::f64::consts::TAU * (i as f64 + 0.8 * (seed[2 * i] - 0.5)) / n as f64;
                let r = 0.35 + 0.65 * seed[2 * i + 1];
                [center[0] + r * ang.cos(), center[1] + r * ang.sin()]
            })
            .collect();
        SplineCurve::periodic(deg, &pts, weights.map(|w| &w[..n])).unwrap()
    }

    proptest::proptest! {
        /// Jets of random NURBS of degrees 1–9 (the fixed-size evaluation of degrees 1–7 and
        /// the general one) against `bspline`'s de Boor evaluation and quotient rule, at
        /// every order asked for.
        #[test]
        fn spline_jets_match_de_boor(
            deg in 1usize..=9,
            seed in proptest::collection::vec(0.0f64..1.0, 24),
            w in proptest::collection::vec(0.5f64..2.0, 12),
            xs in proptest::collection::vec(0.0f64..1.0, 10),
            order in 0usize..=3,
        ) {
            let c = star_curve(deg, &seed, Some(&w));
            let (a, b) = c.domain();
            for x in xs {
                let u = a + (b - a) * x;
                let mut want = [0.0; 8];
                c.curve.eval_derivs(u, 3, &mut want);
                let j = c.jet_to(u, order);
                let got = [j.p, j.d1, j.d2, j.d3];
                for (k, v) in got.iter().enumerate().take(order + 1) {
                    let (wx, wy) = (want[2 * k], want[2 * k + 1]);
                    let scale = 1.0 + wx.abs().max(wy.abs());
                    proptest::prop_assert!(
                        (v.x - wx).abs() <= 1e-9 * scale && (v.y - wy).abs() <= 1e-9 * scale,
                        "degree {deg}, order {k} at {u}: {v:?} vs ({wx}, {wy})"
                    );
                }
            }
        }
    }
}
