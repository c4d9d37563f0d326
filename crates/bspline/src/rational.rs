//! Rational (NURBS) curves in homogeneous form.

use crate::error::{check_finite, Error, Result};
use crate::spline::BSpline;
use smallvec::SmallVec;

/// A rational B-spline curve `C(u) = X(u) / w(u)` carried as the polynomial B-spline
/// `H = (w·x₁, …, w·x_d, w)` of dimension `d + 1`. A polynomial curve is the case `w ≡ 1`.
///
/// All exact operations (derivative numerators, products) work on `H`, so rational curves get the
/// same exact algebra as polynomial ones; only evaluation divides.
#[derive(Debug, Clone, PartialEq)]
pub struct Rational {
    hom: BSpline,
    rational: bool,
    /// Bound on the error of the homogeneous coefficients against the curve they stand for
    /// (the rounding of `w·x`).
    err: f64,
}

impl Rational {
    /// A curve from control points of dimension `dim` and optional positive weights. Weights
    /// that are all equal leave a polynomial curve (the same curve, with its points exact).
    ///
    /// ```
    /// use bspline::{BSpline, Rational};
    /// // A quarter circle as a rational quadratic Bézier.
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let pts = BSpline::bezier(2, vec![1., 0., 1., 1., 0., 1.]).unwrap();
    /// let c = Rational::new(pts, Some(&[1.0, w, 1.0])).unwrap();
    /// let p = c.point(0.3);
    /// assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15);
    /// ```
    pub fn new(points: BSpline, weights: Option<&[f64]>) -> Result<Self> {
        let Some(w) = weights else {
            return Ok(Self::polynomial(&points));
        };
        if w.len() != points.n_ctrl() {
            return Err(Error::CountMismatch {
                what: "weights (one per control point)",
                expected: points.n_ctrl(),
                got: w.len(),
            });
        }
        check_finite("weights", w)?;
        if let Some(index) = w.iter().position(|&x| x <= 0.0) {
            return Err(Error::NonPositiveWeight {
                index,
                value: w[index],
            });
        }
        if w.iter().all(|&x| x == w[0]) {
            return Ok(Self::polynomial(&points));
        }
        let d = points.dim();
        let mut i = 0;
        let hom = points.map_points(d + 1, |src, dst| {
            for (o, s) in dst.iter_mut().zip(src) {
                *o = s * w[i];
            }
            dst[d] = w[i];
            i += 1;
        });
        // Each w·x rounds once (by half an ulp of the largest; the weights are exact, and
        // of another size than the points: a curve of size 1e-50 has weights about 1).
        let largest = hom
            .coefs()
            .chunks_exact(d + 1)
            .flat_map(|p| &p[..d])
            .fold(0.0f64, |m, x| m.max(x.abs()));
        let err = numeric::rounding::UNIT_ROUNDOFF * largest;
        Ok(Self {
            hom,
            rational: true,
            err,
        })
    }

    /// A polynomial curve (all weights 1).
    pub fn polynomial(points: &BSpline) -> Self {
        let d = points.dim();
        let hom = points.map_points(d + 1, |src, dst| {
            dst[..d].copy_from_slice(src);
            dst[d] = 1.0;
        });
        Self {
            hom,
            rational: false,
            err: 0.0,
        }
    }

    /// From a homogeneous B-spline whose last coordinate (the weight) is a positive function.
    ///
    /// Positivity is proven, not assumed: where a weight coefficient is not positive, the spans
    /// around it are refined (the function is unchanged) until all weight coefficients are
    /// positive. If that does not happen within a few rounds the weight has a zero or is
    /// negative: [`Error::NonPositiveWeight`] names the first offending coefficient.
    pub fn from_homogeneous(hom: BSpline) -> Result<Self> {
        let d = hom.dim();
        if d < 2 {
            return Err(Error::DimensionMismatch {
                expected: 2,
                got: d,
            });
        }
        let mut hom = hom;
        for round in 0..=24 {
            let bad: Vec<usize> = (0..hom.n_ctrl())
                .filter(|&i| hom.ctrl(i)[d - 1] <= 0.0)
                .collect();
            let Some(&first) = bad.first() else { break };
            if round == 24 {
                return Err(Error::NonPositiveWeight {
                    index: first,
                    value: hom.ctrl(first)[d - 1],
                });
            }
            // Split every span in the support of an offending coefficient.
            let (p, k) = (hom.degree(), hom.knots());
            let mut mids = Vec::new();
            for &i in &bad {
                for j in i..=i + p {
                    if k[j + 1] > k[j] {
                        mids.push(0.5 * (k[j] + k[j + 1]));
                    }
                }
            }
            mids.sort_by(f64::total_cmp);
            mids.dedup();
            hom = hom.refine(&mids)?;
        }
        let w0 = hom.ctrl(0)[d - 1];
        let rational = (0..hom.n_ctrl()).any(|i| hom.ctrl(i)[d - 1] != w0);
        Ok(Self {
            hom,
            rational,
            err: 0.0,
        })
    }

    /// [`Rational::from_homogeneous`] for homogeneous coefficients that are themselves in
    /// error by up to `err` (computed ones), kept as [`Rational::coefficient_error`].
    pub fn from_homogeneous_with_error(hom: BSpline, err: f64) -> Result<Self> {
        let mut c = Self::from_homogeneous(hom)?;
        c.err = err;
        Ok(c)
    }

    /// Bound on the error of the homogeneous coefficients against the curve they stand for: 0
    /// for a polynomial curve from its points, the rounding of `w·x` for a rational one.
    pub fn coefficient_error(&self) -> f64 {
        self.err
    }

    /// The homogeneous B-spline `(w·x, w)`.
    pub fn homogeneous(&self) -> &BSpline {
        &self.hom
    }
    /// True when the weights are not all equal (the curve is not a polynomial one).
    pub fn is_rational(&self) -> bool {
        self.rational
    }
    /// Dimension of the curve's points.
    pub fn dim(&self) -> usize {
        self.hom.dim() - 1
    }
    /// Polynomial degree of the homogeneous form.
    pub fn degree(&self) -> usize {
        self.hom.degree()
    }
    /// Parameter domain.
    pub fn domain(&self) -> (f64, f64) {
        self.hom.domain()
    }
    /// The Euclidean control points (homogeneous points divided by their weights).
    pub fn control_points(&self) -> Vec<SmallVec<[f64; 4]>> {
        let d = self.dim();
        (0..self.hom.n_ctrl())
            .map(|i| {
                let h = self.hom.ctrl(i);
                h[..d].iter().map(|x| x / h[d]).collect()
            })
            .collect()
    }

    /// For a straight segment, a polynomial curve of degree one on one span, its start and
    /// end points (its two control points: on one span of degree one the basis is affine
    /// whatever the knots outside the domain); `None` for any other curve, a rational one
    /// included (a line, but not run at a constant speed). Closed forms on straight segments
    /// (nearest points, feet, cone conditions) ask this one question.
    ///
    /// ```
    /// use bspline::{BSpline, Rational};
    /// let line = Rational::polynomial(&BSpline::bezier(2, vec![0., 1., 4., 3.]).unwrap());
    /// let [p, q] = line.straight_ends().unwrap();
    /// assert_eq!((p.as_slice(), q.as_slice()), (&[0., 1.][..], &[4., 3.][..]));
    /// let bent = Rational::polynomial(&BSpline::bezier(2, vec![0., 0., 1., 1., 2., 0.]).unwrap());
    /// assert!(bent.straight_ends().is_none());
    /// // (A rational line: straight, but not at a constant speed.)
    /// let w = [1.0, 2.0];
    /// let uneven = Rational::new(BSpline::bezier(2, vec![1., 0., 1., 1.]).unwrap(), Some(&w)).unwrap();
    /// assert!(uneven.straight_ends().is_none());
    /// ```
    pub fn straight_ends(&self) -> Option<[SmallVec<[f64; 4]>; 2]> {
        if self.rational || self.degree() != 1 || self.hom.n_ctrl() != 2 {
            return None;
        }
        let d = self.dim();
        let end = |i: usize| {
            let h = self.hom.ctrl(i);
            h[..d].iter().map(|x| x / h[d]).collect()
        };
        Some([end(0), end(1)])
    }

    /// The weights.
    pub fn weights(&self) -> Vec<f64> {
        let d = self.dim();
        (0..self.hom.n_ctrl())
            .map(|i| self.hom.ctrl(i)[d])
            .collect()
    }
    /// The curve restricted to `[a, b]`.
    pub fn restrict(&self, a: f64, b: f64) -> Result<Self> {
        let mut err = self.err;
        let hom = self.hom.restrict_tracked(a, b, Some(&mut err))?;
        Ok(Self {
            hom,
            rational: self.rational,
            err,
        })
    }

    /// The point at `u`.
    pub fn point(&self, u: f64) -> SmallVec<[f64; 4]> {
        let h = self.hom.eval(u);
        let d = self.dim();
        h[..d].iter().map(|x| x / h[d]).collect()
    }

    /// The point and derivatives up to order `k` at `u` (`out[j*dim..]` the j-th derivative),
    /// by the quotient rule `C⁽ᵏ⁾ = (X⁽ᵏ⁾ − Σᵢ C(k,i) w⁽ⁱ⁾ C⁽ᵏ⁻ⁱ⁾) / w`.
    pub fn eval_derivs(&self, u: f64, k: usize, out: &mut [f64]) {
        let d = self.dim();
        let mut h: SmallVec<[f64; 16]> = smallvec::smallvec![0.0; (k + 1) * (d + 1)];
        // (The point and tangent, the most asked, by de Boor's algorithm stopped a level early:
        // a fraction of the work of every basis function's derivatives.)
        if k == 1 {
            self.hom.eval_d1(u, &mut h);
        } else {
            self.hom.eval_derivs(u, k, &mut h);
        }
        let w = |j: usize| h[j * (d + 1) + d];
        for j in 0..=k {
            let mut binom = 1.0;
            for c in 0..d {
                out[j * d + c] = h[j * (d + 1) + c];
            }
            for i in 1..=j {
                binom = binom * (j + 1 - i) as f64 / i as f64;
                for c in 0..d {
                    out[j * d + c] -= binom * w(i) * out[(j - i) * d + c];
                }
            }
            for c in 0..d {
                out[j * d + c] /= w(0);
            }
        }
    }
}

/// Products of rational functions: numerators and denominators multiply in homogeneous form,
/// `(X₁/w₁) ∘ (X₂/w₂) = (X₁ ∘ X₂) / (w₁ w₂)`, so the result is again exact.
impl Rational {
    fn euclidean(&self) -> BSpline {
        let d = self.dim();
        self.hom.map_points(d, |h, o| o.copy_from_slice(&h[..d]))
    }

    fn weight(&self) -> Result<BSpline> {
        self.hom.component(self.dim())
    }

    fn from_parts(num: &BSpline, den: &BSpline) -> Result<Self> {
        Self::from_homogeneous(BSpline::stack(&[num, den])?)
    }

    /// The product of a scalar rational function (`self`, dimension 1) and a rational curve.
    pub fn mul(&self, other: &Rational) -> Result<Rational> {
        if self.dim() != 1 {
            return Err(Error::DimensionMismatch {
                expected: 1,
                got: self.dim(),
            });
        }
        Self::from_parts(
            &self.euclidean().mul(&other.euclidean())?,
            &self.weight()?.mul(&other.weight()?)?,
        )
    }

    /// The dot product of two rational curves of one dimension, a scalar rational function.
    pub fn dot(&self, other: &Rational) -> Result<Rational> {
        Self::from_parts(
            &self.euclidean().dot(&other.euclidean())?,
            &self.weight()?.mul(&other.weight()?)?,
        )
    }

    /// The planar cross product of two rational planar curves, a scalar rational function.
    pub fn cross(&self, other: &Rational) -> Result<Rational> {
        Self::from_parts(
            &self.euclidean().cross(&other.euclidean())?,
            &self.weight()?.mul(&other.weight()?)?,
        )
    }
}
