//! Bivariate tensor-product scalar B-spline functions `F(t, r)`.
//!
//! The coefficient grid is `n_t × n_r`, row-major: `coefs[i * n_r + j]` multiplies
//! `N_i(t) M_j(r)`. Such a function *is* a univariate B-spline in `t` whose control points are
//! whole rows (dimension `n_r`), and, transposed, one in `r` with dimension `n_t`. Knot
//! insertion, subdivision, derivatives and degree elevation in either direction are therefore
//! the univariate operations on the right view; nothing is re-implemented here.
//!
//! By the convex-hull property `F` lies between its smallest and largest coefficient on the
//! whole domain ([`TensorBSpline::coef_range`]), which is what subdivision solvers build on.

mod arithmetic;
mod eval;
#[cfg(test)]
mod strategies;
mod subdivision;

use crate::error::{check_finite, Error, Result};
use crate::knots::validate_knots;
use crate::spline::BSpline;
use std::borrow::Borrow;

/// A scalar tensor-product B-spline `F(t, r) = Σ c_ij N_i(t) M_j(r)`.
#[derive(Debug, Clone, PartialEq)]
pub struct TensorBSpline {
    deg_t: usize,
    deg_r: usize,
    knots_t: Vec<f64>,
    knots_r: Vec<f64>,
    coefs: Vec<f64>,
}

/// One polynomial piece of a tensor-product function in Bernstein form on
/// `[t0, t1] × [r0, r1]`; `coefs[i * (deg_r + 1) + j]` multiplies `B_i(t) B_j(r)`.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPatch {
    /// Start of the `t` interval.
    pub t0: f64,
    /// End of the `t` interval.
    pub t1: f64,
    /// Start of the `r` interval.
    pub r0: f64,
    /// End of the `r` interval.
    pub r1: f64,
    /// Degree in `t`.
    pub deg_t: usize,
    /// Degree in `r`.
    pub deg_r: usize,
    /// `(deg_t + 1) (deg_r + 1)` coefficients, row-major (rows are `t` indices).
    pub coefs: Vec<f64>,
}

impl TensorBSpline {
    /// A tensor-product function from its degrees, knot vectors and row-major coefficient grid.
    pub fn new(
        deg_t: usize,
        knots_t: Vec<f64>,
        deg_r: usize,
        knots_r: Vec<f64>,
        coefs: Vec<f64>,
    ) -> Result<Self> {
        let n_t = knots_t.len().saturating_sub(deg_t + 1);
        let n_r = knots_r.len().saturating_sub(deg_r + 1);
        validate_knots(deg_t, n_t, &knots_t)?;
        validate_knots(deg_r, n_r, &knots_r)?;
        if coefs.len() != n_t * n_r {
            return Err(Error::CountMismatch {
                what: "tensor coefficients (n_t × n_r)",
                expected: n_t * n_r,
                got: coefs.len(),
            });
        }
        check_finite("coefs", &coefs)?;
        Ok(Self {
            deg_t,
            deg_r,
            knots_t,
            knots_r,
            coefs,
        })
    }

    /// The outer product `f(t) · g(r)` of two scalar functions.
    pub fn outer(f: &BSpline, g: &BSpline) -> Result<Self> {
        check_scalar(f)?;
        check_scalar(g)?;
        let coefs = f
            .coefs()
            .iter()
            .flat_map(|a| g.coefs().iter().map(move |b| a * b))
            .collect();
        Ok(Self::on_spaces_of(f, g, coefs))
    }

    /// `Σ_k f_k(t) g_k(r)`, exactly: every `f_k` (every `g_k`) is brought into one common
    /// spline space, then the grid is a matrix product. All `f_k` must share a domain, and all
    /// `g_k`; all must be scalar. The terms are pairs of splines or of references to them.
    pub fn sum_of_outer<F: Borrow<BSpline>, G: Borrow<BSpline>>(terms: &[(F, G)]) -> Result<Self> {
        if terms.is_empty() {
            return Err(Error::ZeroDimension);
        }
        let fs: Vec<&BSpline> = terms.iter().map(|(f, _)| f.borrow()).collect();
        let gs: Vec<&BSpline> = terms.iter().map(|(_, g)| g.borrow()).collect();
        for (f, g) in fs.iter().zip(&gs) {
            check_scalar(f)?;
            check_scalar(g)?;
        }
        let k = terms.len();
        // (Factors in one space already, as callers keep them, are read where they are.)
        if fs.iter().all(|f| fs[0].same_space(f)) && gs.iter().all(|g| gs[0].same_space(g)) {
            let coefs = outer_grid(
                fs[0].n_ctrl(),
                gs[0].n_ctrl(),
                k,
                |i, m| fs[m].ctrl(i)[0],
                |j, m| gs[m].ctrl(j)[0],
            );
            return Ok(Self::on_spaces_of(fs[0], gs[0], coefs));
        }
        // `stack` harmonises its parts: column k of the stacked spline is f_k in the common space.
        let ft = BSpline::stack(&fs)?;
        let gr = BSpline::stack(&gs)?;
        let coefs = outer_grid(
            ft.n_ctrl(),
            gr.n_ctrl(),
            k,
            |i, m| ft.ctrl(i)[m],
            |j, m| gr.ctrl(j)[m],
        );
        Ok(Self::on_spaces_of(&ft, &gr, coefs))
    }

    /// The function of grid `coefs` on the spline space of `f` in `t` and of `g` in `r`.
    fn on_spaces_of(f: &BSpline, g: &BSpline, coefs: Vec<f64>) -> Self {
        Self {
            deg_t: f.degree(),
            deg_r: g.degree(),
            knots_t: f.knots().to_vec(),
            knots_r: g.knots().to_vec(),
            coefs,
        }
    }

    /// Degree in `t`.
    pub fn deg_t(&self) -> usize {
        self.deg_t
    }
    /// Degree in `r`.
    pub fn deg_r(&self) -> usize {
        self.deg_r
    }
    /// Number of coefficients in the `t` direction (rows).
    pub fn n_t(&self) -> usize {
        self.knots_t.len() - self.deg_t - 1
    }
    /// Number of coefficients in the `r` direction (columns).
    pub fn n_r(&self) -> usize {
        self.knots_r.len() - self.deg_r - 1
    }
    /// Knot vector in `t`.
    pub fn knots_t(&self) -> &[f64] {
        &self.knots_t
    }
    /// Knot vector in `r`.
    pub fn knots_r(&self) -> &[f64] {
        &self.knots_r
    }
    /// The row-major coefficient grid.
    pub fn coefs(&self) -> &[f64] {
        &self.coefs
    }
    /// Coefficient `(i, j)`.
    pub fn coef(&self, i: usize, j: usize) -> f64 {
        self.coefs[i * self.n_r() + j]
    }
    /// Domain in `t`.
    pub fn domain_t(&self) -> (f64, f64) {
        (self.knots_t[self.deg_t], self.knots_t[self.n_t()])
    }
    /// Domain in `r`.
    pub fn domain_r(&self) -> (f64, f64) {
        (self.knots_r[self.deg_r], self.knots_r[self.n_r()])
    }

    /// Smallest and largest coefficient: `F` lies in this interval on its whole domain.
    pub fn coef_range(&self) -> (f64, f64) {
        self.coefs
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &c| {
                (lo.min(c), hi.max(c))
            })
    }

    /// Largest absolute coefficient, a bound on `sup |F|`.
    pub fn max_abs_coef(&self) -> f64 {
        self.coefs.iter().fold(0.0, |m, c| m.max(c.abs()))
    }

    /// The function as a univariate B-spline in `t` whose control points are rows (dim `n_r`).
    pub fn t_view(&self) -> BSpline {
        BSpline::from_raw(
            self.deg_t,
            self.n_r(),
            self.knots_t.clone(),
            self.coefs.clone(),
        )
    }

    /// The function as a univariate B-spline in `r` whose control points are columns (dim `n_t`).
    pub fn r_view(&self) -> BSpline {
        let t = self.transpose();
        BSpline::from_raw(t.deg_t, t.n_r(), t.knots_t, t.coefs)
    }

    /// Rebuilds a tensor from a `t` view and the unchanged `r` space.
    fn from_t_view(v: BSpline, deg_r: usize, knots_r: Vec<f64>) -> Self {
        let (deg_t, _, knots_t, coefs) = v.into_parts();
        Self {
            deg_t,
            deg_r,
            knots_t,
            knots_r,
            coefs,
        }
    }

    /// Rebuilds a tensor from an `r` view and the unchanged `t` space.
    fn from_r_view(v: BSpline, deg_t: usize, knots_t: Vec<f64>) -> Self {
        let (deg_r, _, knots_r, coefs) = v.into_parts();
        Self {
            deg_t: deg_r,
            deg_r: deg_t,
            knots_t: knots_r,
            knots_r: knots_t,
            coefs,
        }
        .transpose()
    }

    /// `G(t, r) = F(r, t)`.
    pub fn transpose(&self) -> Self {
        let (n_t, n_r) = (self.n_t(), self.n_r());
        let mut coefs = vec![0.0; n_t * n_r];
        for i in 0..n_t {
            for j in 0..n_r {
                coefs[j * n_t + i] = self.coefs[i * n_r + j];
            }
        }
        Self {
            deg_t: self.deg_r,
            deg_r: self.deg_t,
            knots_t: self.knots_r.clone(),
            knots_r: self.knots_t.clone(),
            coefs,
        }
    }
}

impl BezierPatch {
    /// The same polynomial on `[t0, t1] × [r0, r1]`, a box inside the patch's (beyond it the
    /// extrapolation's rounding grows with the distance), by de Casteljau subdivision along
    /// each direction.
    ///
    /// ```
    /// use bspline::tensor::BezierPatch;
    /// // F(t, r) = t r on [0, 1]²: on [0.5, 1] × [0, 0.5] its corner values are 0, 0.25, 0, 0.5.
    /// let p = BezierPatch { t0: 0.0, t1: 1.0, r0: 0.0, r1: 1.0, deg_t: 1, deg_r: 1,
    ///     coefs: vec![0.0, 0.0, 0.0, 1.0] };
    /// let q = p.restrict([0.5, 1.0], [0.0, 0.5]);
    /// assert_eq!(q.coefs, vec![0.0, 0.25, 0.0, 0.5]);
    /// ```
    pub fn restrict(&self, t: [f64; 2], r: [f64; 2]) -> BezierPatch {
        let (wt, wr) = (self.t1 - self.t0, self.r1 - self.r0);
        let local = |x: f64, a: f64, w: f64| if w > 0.0 { (x - a) / w } else { 0.0 };
        let mut coefs = self.coefs.clone();
        restrict_bernstein(
            &mut coefs,
            [self.deg_t, self.deg_r],
            [local(t[0], self.t0, wt), local(t[1], self.t0, wt)],
            [local(r[0], self.r0, wr), local(r[1], self.r0, wr)],
        );
        BezierPatch {
            t0: t[0],
            t1: t[1],
            r0: r[0],
            r1: r[1],
            deg_t: self.deg_t,
            deg_r: self.deg_r,
            coefs,
        }
    }

    /// The patch as a clamped tensor-product B-spline on its box.
    pub fn to_tensor(&self) -> TensorBSpline {
        let mut kt = vec![self.t0; self.deg_t + 1];
        kt.extend(std::iter::repeat_n(self.t1, self.deg_t + 1));
        let mut kr = vec![self.r0; self.deg_r + 1];
        kr.extend(std::iter::repeat_n(self.r1, self.deg_r + 1));
        TensorBSpline {
            deg_t: self.deg_t,
            deg_r: self.deg_r,
            knots_t: kt,
            knots_r: kr,
            coefs: self.coefs.clone(),
        }
    }
}

/// Tensor Bernstein coefficients on the unit square (row-major, `(deg_t + 1) × (deg_r + 1)`,
/// rows along `t`) replaced in place by those of the same polynomial on `[t0, t1] × [r0, r1]`,
/// a box of the unit square: two de Casteljau subdivisions along each direction, with no
/// allocation (the zero-set tracer restricts patches in its innermost loop).
///
/// ```
/// use bspline::tensor::restrict_bernstein;
/// // F(t, r) = t r: on [0.5, 1] × [0, 0.5] its corner values are 0, 0.25, 0, 0.5.
/// let mut c = vec![0.0, 0.0, 0.0, 1.0];
/// restrict_bernstein(&mut c, [1, 1], [0.5, 1.0], [0.0, 0.5]);
/// assert_eq!(c, vec![0.0, 0.25, 0.0, 0.5]);
/// ```
pub fn restrict_bernstein(coefs: &mut [f64], [deg_t, deg_r]: [usize; 2], t: [f64; 2], r: [f64; 2]) {
    let w = deg_r + 1;
    if (r[0], r[1]) != (0.0, 1.0) {
        for row in coefs.chunks_exact_mut(w).take(deg_t + 1) {
            restrict_run(row, r[0], r[1]);
        }
    }
    if (t[0], t[1]) != (0.0, 1.0) {
        restrict_rows(&mut coefs[..(deg_t + 1) * w], w, deg_t, t[0], t[1]);
    }
}

/// The Bernstein coefficients `b` of a polynomial on `[0, 1]` replaced by those on `[a, z]`
/// ([`restrict_rows`] for one polynomial, stored contiguously).
fn restrict_run(b: &mut [f64], a: f64, z: f64) {
    let n = b.len().saturating_sub(1);
    if n == 0 {
        return;
    }
    if z == 0.0 {
        let first = b[0];
        b.fill(first);
        return;
    }
    // (A pass at the end it keeps, z = 1 or x = 0, would leave every coefficient as it is.)
    if z != 1.0 {
        for level in 1..=n {
            for m in (level..=n).rev() {
                b[m] = (1.0 - z) * b[m - 1] + z * b[m];
            }
        }
    }
    let x = a / z;
    if x != 0.0 {
        for level in 1..=n {
            for m in 0..=n - level {
                b[m] = (1.0 - x) * b[m] + x * b[m + 1];
            }
        }
    }
}

/// The Bernstein coefficients of degree `n` of `w` polynomials on `[0, 1]`, stored as `n + 1`
/// rows of `w` (row `k` holds every polynomial's `k`-th coefficient), replaced by those on
/// `[a, z]`: the part left of `z` by one de Casteljau subdivision, then the part of that right
/// of `a` (at `a / z` of it) by another. (Whole rows at a time: a column of a tensor is
/// restricted with the others, in contiguous memory.)
fn restrict_rows(b: &mut [f64], w: usize, n: usize, a: f64, z: f64) {
    if z == 0.0 {
        // Everything at the parameter 0: the first row, n + 1 times.
        let (first, rest) = b.split_at_mut(w);
        rest.chunks_exact_mut(w)
            .for_each(|row| row.copy_from_slice(first));
        return;
    }
    // Row k ← (1 − x) row k + x row k + 1 (`lead`: row k is the one written) or row k + 1 ←
    // (1 − x) row k + x row k + 1 (trailing).
    let lerp = |b: &mut [f64], k: usize, x: f64, lead: bool| {
        let (lo, hi) = b.split_at_mut((k + 1) * w);
        let (p, q) = (&mut lo[k * w..], &mut hi[..w]);
        if lead {
            p.iter_mut()
                .zip(q.iter())
                .for_each(|(p, &q)| *p = (1.0 - x) * *p + x * q);
        } else {
            q.iter_mut()
                .zip(p.iter())
                .for_each(|(q, &p)| *q = (1.0 - x) * p + x * *q);
        }
    };
    // Left part at z: row k ← the first point of level k (computed in place from the right).
    if z != 1.0 {
        for level in 1..=n {
            for m in (level..=n).rev() {
                lerp(b, m - 1, z, false);
            }
        }
    }
    // Right part at x = a / z: row k ← the last point of level n − k (in place from the left).
    let x = a / z;
    if x != 0.0 {
        for level in 1..=n {
            for m in 0..=n - level {
                lerp(b, m, x, true);
            }
        }
    }
}

/// Refuses a factor that is not a scalar function.
fn check_scalar(h: &BSpline) -> Result<()> {
    if h.dim() == 1 {
        Ok(())
    } else {
        Err(Error::DimensionMismatch {
            expected: 1,
            got: h.dim(),
        })
    }
}

/// The grid `Σ_m f(i, m) g(j, m)` over `m < k`, row by row: the coefficients of a sum of `k`
/// outer products of factors with `n_t` and `n_r` coefficients.
fn outer_grid(
    n_t: usize,
    n_r: usize,
    k: usize,
    f: impl Fn(usize, usize) -> f64,
    g: impl Fn(usize, usize) -> f64,
) -> Vec<f64> {
    let mut coefs = vec![0.0; n_t * n_r];
    for i in 0..n_t {
        for j in 0..n_r {
            coefs[i * n_r + j] = (0..k).map(|m| f(i, m) * g(j, m)).sum();
        }
    }
    coefs
}
