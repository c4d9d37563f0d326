//! The B-spline type: a piecewise polynomial with `f64` coefficients of any dimension.

use crate::error::{check_finite, Error, Result};
use crate::knots::{
    basis_derivs, clamped_uniform_knots, find_span, too_few_points, validate_knots, Scratch,
};
use smallvec::SmallVec;

/// A polynomial B-spline function `[a, b] → R^dim`.
///
/// Control point `i` is `coefs[i*dim .. (i+1)*dim]`. The knot vector may be clamped or not
/// (a periodic curve is unclamped); the domain is `[knots[p], knots[n]]`. Scalar functions are
/// `dim == 1`; a planar curve is `dim == 2`; a rational planar curve is carried in homogeneous
/// form with `dim == 3` (see [`crate::Rational`]). Because the dimension is a run-time value, a
/// tensor-product function is also a univariate B-spline whose "points" are whole coefficient rows.
#[derive(Debug, Clone, PartialEq)]
pub struct BSpline {
    degree: usize,
    dim: usize,
    knots: Vec<f64>,
    coefs: Vec<f64>,
}

impl BSpline {
    /// A B-spline from its degree, knot vector, dimension and control points (point-major).
    ///
    /// ```
    /// use bspline::BSpline;
    /// // A clamped quadratic with one interior knot: y = piecewise parabola.
    /// let f = BSpline::new(2, vec![0., 0., 0., 0.5, 1., 1., 1.], 1, vec![0., 1., 1., 0.]).unwrap();
    /// assert_eq!(f.eval(0.0)[0], 0.0);
    /// assert!((f.eval(0.5)[0] - 1.0).abs() < 1e-15);
    /// ```
    pub fn new(degree: usize, knots: Vec<f64>, dim: usize, coefs: Vec<f64>) -> Result<Self> {
        if dim == 0 {
            return Err(Error::ZeroDimension);
        }
        if !coefs.len().is_multiple_of(dim) {
            return Err(Error::CountMismatch {
                what: "coefficients (a multiple of the dimension)",
                expected: coefs.len() / dim * dim,
                got: coefs.len(),
            });
        }
        check_finite("coefs", &coefs)?;
        validate_knots(degree, coefs.len() / dim, &knots)?;
        Ok(Self::from_raw(degree, dim, knots, coefs))
    }

    /// Constructor without validation, for results of exact operations on valid splines.
    pub(crate) fn from_raw(degree: usize, dim: usize, knots: Vec<f64>, coefs: Vec<f64>) -> Self {
        debug_assert_eq!(knots.len(), coefs.len() / dim + degree + 1);
        Self {
            degree,
            dim,
            knots,
            coefs,
        }
    }

    /// A clamped B-spline on `[0, 1]` with uniformly spaced interior knots.
    pub fn clamped_uniform(degree: usize, dim: usize, coefs: Vec<f64>) -> Result<Self> {
        if dim == 0 {
            return Err(Error::ZeroDimension);
        }
        let n = coefs.len() / dim;
        if n < degree + 1 {
            return Err(too_few_points(degree, n));
        }
        Self::new(
            degree,
            clamped_uniform_knots(degree, n, 0.0, 1.0),
            dim,
            coefs,
        )
    }

    /// A Bézier curve (`n` points, degree `n − 1`) on `[0, 1]`.
    pub fn bezier(dim: usize, coefs: Vec<f64>) -> Result<Self> {
        if dim == 0 {
            return Err(Error::ZeroDimension);
        }
        let n = coefs.len() / dim;
        if n == 0 {
            return Err(Error::TooFewPoints {
                degree: 0,
                needed: 1,
                got: 0,
            });
        }
        Self::clamped_uniform(n - 1, dim, coefs)
    }

    /// A closed uniform periodic B-spline through `n` control points: `C^(p−1)` everywhere,
    /// domain `[0, n)`, the piece on `[i, i+1]` shaped by points `i, …, i+p` (mod `n`).
    ///
    /// The result is in unclamped form (knots `−p, …, n+p`); [`BSpline::clamped`] gives the
    /// equivalent clamped curve.
    pub fn periodic(degree: usize, dim: usize, coefs: Vec<f64>) -> Result<Self> {
        if dim == 0 {
            return Err(Error::ZeroDimension);
        }
        let n = coefs.len() / dim;
        if degree == 0 || n < degree + 1 {
            return Err(too_few_points(degree, n));
        }
        let mut wrapped = coefs.clone();
        wrapped.extend_from_slice(&coefs[..degree * dim]);
        let knots = (0..n + 2 * degree + 1)
            .map(|i| i as f64 - degree as f64)
            .collect();
        Self::new(degree, knots, dim, wrapped)
    }

    /// The constant function `value` of degree `degree` on `[a, b]` (a Bézier with equal points).
    pub fn constant(value: &[f64], degree: usize, a: f64, b: f64) -> Result<Self> {
        let coefs: Vec<f64> = (0..=degree).flat_map(|_| value.iter().copied()).collect();
        let mut knots = vec![a; degree + 1];
        knots.extend(std::iter::repeat_n(b, degree + 1));
        Self::new(degree, knots, value.len(), coefs)
    }

    /// Polynomial degree.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// Dimension of the control points.
    pub fn dim(&self) -> usize {
        self.dim
    }
    /// Number of control points.
    pub fn n_ctrl(&self) -> usize {
        self.coefs.len() / self.dim
    }
    /// The knot vector.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    /// All control point coordinates, point-major.
    pub fn coefs(&self) -> &[f64] {
        &self.coefs
    }
    /// The knot vector as a validated [`KnotVector`](crate::knots::KnotVector).
    pub fn knot_vector(&self) -> crate::knots::KnotVector {
        crate::knots::KnotVector::from_valid(self.degree, self.knots.clone())
    }
    /// Control point `i`.
    pub fn ctrl(&self, i: usize) -> &[f64] {
        &self.coefs[i * self.dim..(i + 1) * self.dim]
    }
    /// The parameter domain `[knots[p], knots[n]]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.n_ctrl()])
    }
    /// True when the first and last knots have multiplicity `p + 1` (end points interpolated).
    pub fn is_clamped(&self) -> bool {
        let p = self.degree;
        let k = &self.knots;
        k[0] == k[p] && k[k.len() - 1] == k[k.len() - 1 - p]
    }
    /// The distinct knot values inside the domain, ends included.
    pub fn breakpoints(&self) -> Vec<f64> {
        let (a, b) = self.domain();
        let mut out: Vec<f64> = Vec::new();
        for &k in &self.knots {
            if k >= a && k <= b && out.last() != Some(&k) {
                out.push(k);
            }
        }
        out
    }

    /// The value at `u` (clamped into the domain).
    pub fn eval(&self, u: f64) -> SmallVec<[f64; 4]> {
        let mut out = SmallVec::from_elem(0.0, self.dim);
        self.eval_derivs(u, 0, &mut out);
        out
    }

    /// The value of a scalar function at `u`.
    pub fn eval_scalar(&self, u: f64) -> f64 {
        let mut out = [0.0];
        self.eval_derivs(u, 0, &mut out);
        out[0]
    }

    /// Value and derivatives up to order `k` at `u`: `out[j*dim .. (j+1)*dim]` is the j-th
    /// derivative (`out` must hold `(k+1)*dim` values). Derivatives above the degree are zero;
    /// at a knot the one-sided derivative from the right is returned (from the left at the end).
    pub fn eval_derivs(&self, u: f64, k: usize, out: &mut [f64]) {
        let (p, d, n) = (self.degree, self.dim, self.n_ctrl());
        let (a, b) = self.domain();
        let u = u.clamp(a, b);
        let span = find_span(p, n, &self.knots, u);
        let mut ders = Scratch::new();
        basis_derivs(span, u, p, k.min(p), &self.knots, &mut ders);
        out[..(k + 1) * d].fill(0.0);
        for j in 0..=k.min(p) {
            for (r, &nb) in ders[j * (p + 1)..(j + 1) * (p + 1)].iter().enumerate() {
                let c = self.ctrl(span - p + r);
                for (o, &ci) in out[j * d..(j + 1) * d].iter_mut().zip(c) {
                    *o += nb * ci;
                }
            }
        }
    }

    /// Value and first derivative at `u` into `out` (`2*dim` values), by de Boor's algorithm
    /// stopped one level early: the two last points give the value and, scaled by
    /// `p / (t_{s+1} − t_s)`, the derivative. Cheaper than [`BSpline::eval_derivs`] and
    /// allocation-free for the degrees and dimensions met in practice.
    pub fn eval_d1(&self, u: f64, out: &mut [f64]) {
        let (p, d, n) = (self.degree, self.dim, self.n_ctrl());
        let (a, b) = self.domain();
        let u = u.clamp(a, b);
        let s = find_span(p, n, &self.knots, u);
        let t = &self.knots;
        let mut w: SmallVec<[f64; 64]> =
            SmallVec::from_slice(&self.coefs[(s - p) * d..(s + 1) * d]);
        if p == 0 {
            out[..d].copy_from_slice(&w[..d]);
            out[d..2 * d].fill(0.0);
            return;
        }
        // Levels 1..p−1: w[j] becomes the blossom b(u^level, knots…) of the points s−p+j.
        for level in 1..p {
            for j in (level..=p).rev() {
                let i = s - p + j;
                let alpha = (u - t[i]) / (t[i + p + 1 - level] - t[i]);
                for c in 0..d {
                    w[j * d + c] = (1.0 - alpha) * w[(j - 1) * d + c] + alpha * w[j * d + c];
                }
            }
        }
        let h = t[s + 1] - t[s];
        let alpha = (u - t[s]) / h;
        for c in 0..d {
            let (q0, q1) = (w[(p - 1) * d + c], w[p * d + c]);
            out[c] = (1.0 - alpha) * q0 + alpha * q1;
            out[d + c] = p as f64 * (q1 - q0) / h;
        }
    }

    /// The derivative as a B-spline of degree `p − 1` (the hodograph); the zero function of
    /// degree 0 when `p == 0`.
    ///
    /// ```
    /// use bspline::BSpline;
    /// let f = BSpline::bezier(1, vec![0., 0., 1.]).unwrap(); // u²
    /// let df = f.deriv();
    /// assert_eq!(df.degree(), 1);
    /// assert!((df.eval_scalar(0.3) - 0.6).abs() < 1e-15);
    /// ```
    pub fn deriv(&self) -> BSpline {
        let (p, d, n) = (self.degree, self.dim, self.n_ctrl());
        if p == 0 {
            return Self::from_raw(0, d, self.knots.clone(), vec![0.0; self.coefs.len()]);
        }
        let mut coefs = Vec::with_capacity((n - 1) * d);
        for i in 0..n - 1 {
            let den = self.knots[i + p + 1] - self.knots[i + 1];
            // A zero-length support means a basis function that vanishes identically.
            let f = if den > 0.0 { p as f64 / den } else { 0.0 };
            for c in 0..d {
                coefs.push(f * (self.coefs[(i + 1) * d + c] - self.coefs[i * d + c]));
            }
        }
        Self::from_raw(
            p - 1,
            d,
            self.knots[1..self.knots.len() - 1].to_vec(),
            coefs,
        )
    }

    /// The `k`-th derivative as a B-spline.
    pub fn deriv_n(&self, k: usize) -> BSpline {
        (0..k).fold(self.clone(), |f, _| f.deriv())
    }

    /// Coordinate `k` as a scalar B-spline.
    pub fn component(&self, k: usize) -> Result<BSpline> {
        if k >= self.dim {
            return Err(Error::DimensionMismatch {
                expected: self.dim,
                got: k + 1,
            });
        }
        let coefs = self
            .coefs
            .iter()
            .skip(k)
            .step_by(self.dim)
            .copied()
            .collect();
        Ok(Self::from_raw(self.degree, 1, self.knots.clone(), coefs))
    }

    /// Smallest and largest coefficient of each coordinate: by the convex-hull property the
    /// function's values lie in this box.
    pub fn coef_bounds(&self) -> Vec<(f64, f64)> {
        let mut out = vec![(f64::INFINITY, f64::NEG_INFINITY); self.dim];
        for pt in self.coefs.chunks_exact(self.dim) {
            for (b, &c) in out.iter_mut().zip(pt) {
                b.0 = b.0.min(c);
                b.1 = b.1.max(c);
            }
        }
        out
    }

    /// Largest absolute coefficient: a bound on the function's sup norm.
    pub fn max_abs_coef(&self) -> f64 {
        self.coefs.iter().fold(0.0, |m, c| m.max(c.abs()))
    }

    /// The same function with every coefficient multiplied by `s`.
    pub fn scale(&self, s: f64) -> BSpline {
        let coefs = self.coefs.iter().map(|c| c * s).collect();
        Self::from_raw(self.degree, self.dim, self.knots.clone(), coefs)
    }

    /// The same function with its coefficients mapped point by point to dimension `dim`.
    pub fn map_points(&self, dim: usize, mut f: impl FnMut(&[f64], &mut [f64])) -> BSpline {
        let mut coefs = vec![0.0; self.n_ctrl() * dim];
        for (src, dst) in self
            .coefs
            .chunks_exact(self.dim)
            .zip(coefs.chunks_exact_mut(dim))
        {
            f(src, dst);
        }
        Self::from_raw(self.degree, dim, self.knots.clone(), coefs)
    }

    /// Affine reparametrisation onto `[a, b]`: `g(v) = f(u)` with `u` mapped linearly.
    pub fn reparam(&self, a: f64, b: f64) -> Result<BSpline> {
        let (u0, u1) = self.domain();
        if !(a.is_finite() && b.is_finite() && a < b) {
            return Err(Error::EmptyDomain { start: a, end: b });
        }
        let s = (b - a) / (u1 - u0);
        // The domain ends map exactly, so that splines reparametrised onto one domain agree.
        let knots = self
            .knots
            .iter()
            .map(|&k| match k {
                k if k == u0 => a,
                k if k == u1 => b,
                k => a + (k - u0) * s,
            })
            .collect();
        Ok(Self::from_raw(
            self.degree,
            self.dim,
            knots,
            self.coefs.clone(),
        ))
    }

    pub(crate) fn into_parts(self) -> (usize, usize, Vec<f64>, Vec<f64>) {
        (self.degree, self.dim, self.knots, self.coefs)
    }
}
