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

use crate::algebra::from_pieces;
use crate::error::{check_finite, Error, Result};
use crate::knots::{basis_derivs, find_span, multiplicity, validate_knots, Scratch};
use crate::refine::Bezier;
use crate::spline::BSpline;

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
        for h in [f, g] {
            if h.dim() != 1 {
                return Err(Error::DimensionMismatch {
                    expected: 1,
                    got: h.dim(),
                });
            }
        }
        let coefs = f
            .coefs()
            .iter()
            .flat_map(|a| g.coefs().iter().map(move |b| a * b))
            .collect();
        Ok(Self {
            deg_t: f.degree(),
            deg_r: g.degree(),
            knots_t: f.knots().to_vec(),
            knots_r: g.knots().to_vec(),
            coefs,
        })
    }

    /// `Σ_k f_k(t) g_k(r)`, exactly: every `f_k` (every `g_k`) is brought into one common
    /// spline space, then the grid is a matrix product. All `f_k` must share a domain, and all
    /// `g_k`; all must be scalar.
    pub fn sum_of_outer(terms: &[(BSpline, BSpline)]) -> Result<Self> {
        if terms.is_empty() {
            return Err(Error::ZeroDimension);
        }
        for (f, g) in terms {
            for h in [f, g] {
                if h.dim() != 1 {
                    return Err(Error::DimensionMismatch {
                        expected: 1,
                        got: h.dim(),
                    });
                }
            }
        }
        let fs: Vec<&BSpline> = terms.iter().map(|(f, _)| f).collect();
        let gs: Vec<&BSpline> = terms.iter().map(|(_, g)| g).collect();
        // `stack` harmonises its parts: column k of the stacked spline is f_k in the common space.
        let ft = BSpline::stack(&fs)?;
        let gr = BSpline::stack(&gs)?;
        let (n_t, n_r, k) = (ft.n_ctrl(), gr.n_ctrl(), terms.len());
        let mut coefs = vec![0.0; n_t * n_r];
        for i in 0..n_t {
            let fi = ft.ctrl(i);
            for j in 0..n_r {
                let gj = gr.ctrl(j);
                coefs[i * n_r + j] = (0..k).map(|m| fi[m] * gj[m]).sum();
            }
        }
        Ok(Self {
            deg_t: ft.degree(),
            deg_r: gr.degree(),
            knots_t: ft.knots().to_vec(),
            knots_r: gr.knots().to_vec(),
            coefs,
        })
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

    /// The value at `(t, r)` (each clamped into its domain).
    pub fn eval(&self, t: f64, r: f64) -> f64 {
        self.eval_derivs(t, r, 0, 0)[0]
    }

    /// Partial derivatives `∂^(a+b) F / ∂t^a ∂r^b` for `a ≤ kt`, `b ≤ kr`, at `(t, r)`:
    /// entry `a * (kr + 1) + b`. Orders above the degree are zero; at a knot the derivative
    /// from the right is returned (from the left at the domain end).
    pub fn eval_derivs(&self, t: f64, r: f64, kt: usize, kr: usize) -> Vec<f64> {
        let (bt, st) = basis(self.deg_t, &self.knots_t, t, kt);
        let (br, sr) = basis(self.deg_r, &self.knots_r, r, kr);
        let (pt, pr, n_r) = (self.deg_t, self.deg_r, self.n_r());
        let mut out = vec![0.0; (kt + 1) * (kr + 1)];
        for a in 0..=kt.min(pt) {
            for b in 0..=kr.min(pr) {
                let mut s = 0.0;
                for i in 0..=pt {
                    let row = (st - pt + i) * n_r + sr - pr;
                    let wi = bt[a * (pt + 1) + i];
                    if wi == 0.0 {
                        continue;
                    }
                    let inner: f64 = (0..=pr)
                        .map(|j| br[b * (pr + 1) + j] * self.coefs[row + j])
                        .sum();
                    s += wi * inner;
                }
                out[a * (kr + 1) + b] = s;
            }
        }
        out
    }

    /// `∂F/∂t` as a tensor of degree `(p_t − 1, p_r)`.
    pub fn deriv_t(&self) -> Self {
        Self::from_t_view(self.t_view().deriv(), self.deg_r, self.knots_r.clone())
    }

    /// `∂F/∂r` as a tensor of degree `(p_t, p_r − 1)`.
    pub fn deriv_r(&self) -> Self {
        Self::from_r_view(self.r_view().deriv(), self.deg_t, self.knots_t.clone())
    }

    /// Inserts the values `x` into the `t` knot vector (function unchanged).
    pub fn refine_t(&self, x: &[f64]) -> Result<Self> {
        Ok(Self::from_t_view(
            self.t_view().refine(x)?,
            self.deg_r,
            self.knots_r.clone(),
        ))
    }

    /// Inserts the values `x` into the `r` knot vector (function unchanged).
    pub fn refine_r(&self, x: &[f64]) -> Result<Self> {
        Ok(Self::from_r_view(
            self.r_view().refine(x)?,
            self.deg_t,
            self.knots_t.clone(),
        ))
    }

    /// Raises the degrees by `(dt, dr)` (function and continuity unchanged).
    pub fn elevate(&self, dt: usize, dr: usize) -> Self {
        let a = Self::from_t_view(self.t_view().elevate(dt), self.deg_r, self.knots_r.clone());
        Self::from_r_view(a.r_view().elevate(dr), a.deg_t, a.knots_t.clone())
    }

    /// The restriction to `[t0, t1] × [r0, r1]` as a clamped tensor on that box.
    pub fn restrict(&self, t0: f64, t1: f64, r0: f64, r1: f64) -> Result<Self> {
        let a = Self::from_t_view(
            self.t_view().restrict(t0, t1)?,
            self.deg_r,
            self.knots_r.clone(),
        );
        Ok(Self::from_r_view(
            a.r_view().restrict(r0, r1)?,
            a.deg_t,
            a.knots_t.clone(),
        ))
    }

    /// Splits at `t = u` (strictly inside) into the parts on `t ≤ u` and `t ≥ u`.
    pub fn split_t(&self, u: f64) -> Result<(Self, Self)> {
        let (a, b) = self.t_view().split_at(u)?;
        Ok((
            Self::from_t_view(a, self.deg_r, self.knots_r.clone()),
            Self::from_t_view(b, self.deg_r, self.knots_r.clone()),
        ))
    }

    /// Splits at `r = u` (strictly inside) into the parts on `r ≤ u` and `r ≥ u`.
    pub fn split_r(&self, u: f64) -> Result<(Self, Self)> {
        let (a, b) = self.r_view().split_at(u)?;
        Ok((
            Self::from_r_view(a, self.deg_t, self.knots_t.clone()),
            Self::from_r_view(b, self.deg_t, self.knots_t.clone()),
        ))
    }

    /// The same function with every coefficient multiplied by `s`.
    pub fn scale(&self, s: f64) -> Self {
        let mut out = self.clone();
        out.coefs.iter_mut().for_each(|c| *c *= s);
        out
    }

    /// `s·self + u·other` in the common spline space (both on the same domain).
    pub fn lincomb(&self, s: f64, other: &Self, u: f64) -> Result<Self> {
        // Common r space first (views of different dimension harmonise fine), then common t.
        let (ar, br) = self.r_view().harmonize(&other.r_view())?;
        let a = Self::from_r_view(ar, self.deg_t, self.knots_t.clone());
        let b = Self::from_r_view(br, other.deg_t, other.knots_t.clone());
        let (at, bt) = a.t_view().harmonize(&b.t_view())?;
        let mut out = Self::from_t_view(at, a.deg_r, a.knots_r.clone());
        for (c, d) in out.coefs.iter_mut().zip(bt.coefs()) {
            *c = s * *c + u * d;
        }
        Ok(out)
    }

    /// `self + other`.
    pub fn add(&self, other: &Self) -> Result<Self> {
        self.lincomb(1.0, other, 1.0)
    }

    /// `self − other`.
    pub fn sub(&self, other: &Self) -> Result<Self> {
        self.lincomb(1.0, other, -1.0)
    }

    /// The product `F·G`, exactly: degree `(p_t + q_t, p_r + q_r)`, with the minimal knot
    /// vectors that the factors' continuity allows in each direction.
    pub fn mul(&self, other: &Self) -> Result<Self> {
        let bt = union_breaks(
            self.domain_t(),
            &self.knots_t,
            &other.knots_t,
            other.domain_t(),
        )?;
        let br = union_breaks(
            self.domain_r(),
            &self.knots_r,
            &other.knots_r,
            other.domain_r(),
        )?;
        let pa = self.patches_at(&bt, &br);
        let pb = other.patches_at(&bt, &br);
        let (dt, dr) = (self.deg_t + other.deg_t, self.deg_r + other.deg_r);
        let prod: Vec<BezierPatch> = pa.iter().zip(&pb).map(|(a, b)| patch_mul(a, b)).collect();
        let kt = min_knots(dt, &bt, |x| {
            cont(self.deg_t, &self.knots_t, x).min(cont(other.deg_t, &other.knots_t, x))
        });
        let kr = min_knots(dr, &br, |x| {
            cont(self.deg_r, &self.knots_r, x).min(cont(other.deg_r, &other.knots_r, x))
        });
        // Assemble in t for every r cell (points: the r-Bernstein rows), then in r.
        let (ni, nj) = (bt.len() - 1, br.len() - 1);
        let mut per_rcell: Vec<BSpline> = Vec::with_capacity(nj);
        for j in 0..nj {
            let pieces: Vec<Bezier> = (0..ni)
                .map(|i| {
                    let p = &prod[i * nj + j];
                    Bezier {
                        a: p.t0,
                        b: p.t1,
                        degree: dt,
                        dim: dr + 1,
                        coefs: p.coefs.clone(),
                    }
                })
                .collect();
            per_rcell.push(from_pieces(dt, dr + 1, kt.clone(), &bt, &pieces));
        }
        let n_t = kt.len() - dt - 1;
        let rpieces: Vec<Bezier> = per_rcell
            .iter()
            .enumerate()
            .map(|(j, s)| {
                let mut coefs = vec![0.0; (dr + 1) * n_t];
                for i in 0..n_t {
                    for (b, &c) in s.ctrl(i).iter().enumerate() {
                        coefs[b * n_t + i] = c;
                    }
                }
                Bezier {
                    a: br[j],
                    b: br[j + 1],
                    degree: dr,
                    dim: n_t,
                    coefs,
                }
            })
            .collect();
        let rv = from_pieces(dr, n_t, kr, &br, &rpieces);
        Ok(Self::from_r_view(rv, dt, kt))
    }

    /// The Bézier patches of the function, one per pair of non-empty knot spans, ordered by
    /// `t` cell then `r` cell.
    pub fn bezier_patches(&self) -> Vec<BezierPatch> {
        let bt = breakpoints(self.domain_t(), &self.knots_t);
        let br = breakpoints(self.domain_r(), &self.knots_r);
        self.patches_at(&bt, &br)
    }

    /// Bézier patches on the grid of `bt × br` (sorted, ends equal to the domain, containing
    /// every interior knot).
    fn patches_at(&self, bt: &[f64], br: &[f64]) -> Vec<BezierPatch> {
        let (pt, pr) = (self.deg_t, self.deg_r);
        let tp = self.t_view().bezier_pieces_at(bt);
        let mut out = Vec::with_capacity(tp.len() * (br.len() - 1));
        for tpiece in &tp {
            // The t piece as an r spline whose points are its (pt + 1) Bernstein rows.
            let mut cols = vec![0.0; self.n_r() * (pt + 1)];
            for i in 0..=pt {
                for j in 0..self.n_r() {
                    cols[j * (pt + 1) + i] = tpiece.coefs[i * self.n_r() + j];
                }
            }
            let rs = BSpline::from_raw(pr, pt + 1, self.knots_r.clone(), cols);
            for rp in rs.bezier_pieces_at(br) {
                let mut coefs = vec![0.0; (pt + 1) * (pr + 1)];
                for j in 0..=pr {
                    for i in 0..=pt {
                        coefs[i * (pr + 1) + j] = rp.coefs[j * (pt + 1) + i];
                    }
                }
                out.push(BezierPatch {
                    t0: tpiece.a,
                    t1: tpiece.b,
                    r0: rp.a,
                    r1: rp.b,
                    deg_t: pt,
                    deg_r: pr,
                    coefs,
                });
            }
        }
        out
    }
}

impl BezierPatch {
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

/// Product of two Bézier patches on the same box: a binomial convolution in each direction.
fn patch_mul(a: &BezierPatch, b: &BezierPatch) -> BezierPatch {
    let (pa, qa, pb, qb) = (a.deg_t, a.deg_r, b.deg_t, b.deg_r);
    let (dt, dr) = (pa + pb, qa + qb);
    let (ca, cb, cd) = (binom(pa), binom(pb), binom(dt));
    let (ra, rb, rd) = (binom(qa), binom(qb), binom(dr));
    let mut coefs = vec![0.0; (dt + 1) * (dr + 1)];
    for i in 0..=pa {
        for k in 0..=pb {
            let wt = ca[i] * cb[k] / cd[i + k];
            for j in 0..=qa {
                let x = a.coefs[i * (qa + 1) + j] * wt;
                for l in 0..=qb {
                    let wr = ra[j] * rb[l] / rd[j + l];
                    coefs[(i + k) * (dr + 1) + j + l] += x * wr * b.coefs[k * (qb + 1) + l];
                }
            }
        }
    }
    BezierPatch {
        t0: a.t0,
        t1: a.t1,
        r0: a.r0,
        r1: a.r1,
        deg_t: dt,
        deg_r: dr,
        coefs,
    }
}

fn binom(n: usize) -> Vec<f64> {
    let mut row = vec![1.0; n + 1];
    for k in 1..n {
        row[k] = row[k - 1] * (n + 1 - k) as f64 / k as f64;
    }
    row
}

/// Continuity order at interior `x`: `p − multiplicity`, unbounded where `x` is no knot.
fn cont(p: usize, knots: &[f64], x: f64) -> usize {
    match multiplicity(knots, x) {
        0 => usize::MAX,
        m => p.saturating_sub(m),
    }
}

/// The minimal clamped knot vector of degree `deg` on the breakpoints, given the continuity
/// at each interior breakpoint.
fn min_knots(deg: usize, breaks: &[f64], cont_at: impl Fn(f64) -> usize) -> Vec<f64> {
    let mut k = vec![breaks[0]; deg + 1];
    for &x in &breaks[1..breaks.len() - 1] {
        k.extend(std::iter::repeat_n(x, deg.saturating_sub(cont_at(x))));
    }
    k.extend(std::iter::repeat_n(breaks[breaks.len() - 1], deg + 1));
    k
}

fn breakpoints(dom: (f64, f64), knots: &[f64]) -> Vec<f64> {
    let mut out = vec![dom.0];
    for &k in knots {
        if k > dom.0 && k < dom.1 && out.last() != Some(&k) {
            out.push(k);
        }
    }
    out.push(dom.1);
    out
}

/// Breakpoints of two knot vectors on the same domain (exact equality required).
fn union_breaks(da: (f64, f64), ka: &[f64], kb: &[f64], db: (f64, f64)) -> Result<Vec<f64>> {
    if da != db {
        return Err(Error::DomainMismatch {
            left: da,
            right: db,
        });
    }
    let mut v: Vec<f64> = breakpoints(da, ka);
    v.extend(breakpoints(da, kb));
    v.sort_by(f64::total_cmp);
    v.dedup();
    Ok(v)
}

/// Basis functions and derivatives up to `k` at `u` (clamped into the domain), and the span.
fn basis(p: usize, knots: &[f64], u: f64, k: usize) -> (Scratch, usize) {
    let n = knots.len() - p - 1;
    let u = u.clamp(knots[p], knots[n]);
    let span = find_span(p, n, knots, u);
    let mut ders = Scratch::new();
    basis_derivs(span, u, p, k.min(p), knots, &mut ders);
    // Rows above the degree are zero.
    ders.resize((k + 1) * (p + 1), 0.0);
    (ders, span)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A clamped scalar spline on [0, 1] of degree `p` with coefficients from `c` (at least p+1).
    fn spline(p: usize, c: &[f64]) -> BSpline {
        BSpline::clamped_uniform(p, 1, c.to_vec()).expect("valid spline")
    }

    fn close(a: f64, b: f64, scale: f64) -> bool {
        (a - b).abs() <= 1e-11 * scale.max(1.0)
    }

    prop_compose! {
        fn arb_spline()(p in 1usize..4, extra in 0usize..4)
            (c in prop::collection::vec(-2.0..2.0f64, p + 1 + extra), p in Just(p)) -> BSpline {
            spline(p, &c)
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(1000))]

        /// Outer products, sums and products evaluate to their defining formulas.
        #[test]
        fn algebra_matches_formula(f in arb_spline(), g in arb_spline(), h in arb_spline(), k in arb_spline(),
                                   t in 0.0..=1.0f64, r in 0.0..=1.0f64) {
            let a = TensorBSpline::outer(&f, &g).unwrap();
            let b = TensorBSpline::outer(&h, &k).unwrap();
            let (fv, gv, hv, kv) = (f.eval_scalar(t), g.eval_scalar(r), h.eval_scalar(t), k.eval_scalar(r));
            prop_assert!(close(a.eval(t, r), fv * gv, 4.0));
            let s = a.lincomb(2.0, &b, -0.5).unwrap();
            prop_assert!(close(s.eval(t, r), 2.0 * fv * gv - 0.5 * hv * kv, 16.0));
            let sum = TensorBSpline::sum_of_outer(&[(f.clone(), g.clone()), (h.clone(), k.clone())]).unwrap();
            prop_assert!(close(sum.eval(t, r), fv * gv + hv * kv, 16.0));
            let m = a.mul(&sum).unwrap();
            prop_assert_eq!((m.deg_t(), m.deg_r()), (a.deg_t() + sum.deg_t(), a.deg_r() + sum.deg_r()));
            prop_assert!(close(m.eval(t, r), fv * gv * (fv * gv + hv * kv), 64.0));
            // Convex hull: the value lies within the coefficient range.
            let (lo, hi) = m.coef_range();
            let v = m.eval(t, r);
            prop_assert!(v >= lo - 1e-12 && v <= hi + 1e-12);
        }

        /// Partial derivatives against finite differences and the derivative tensors.
        #[test]
        fn derivatives(f in arb_spline(), g in arb_spline(), h in arb_spline(), k in arb_spline(),
                       t in 0.05..0.95f64, r in 0.05..0.95f64) {
            let a = TensorBSpline::sum_of_outer(&[(f.clone(), g.clone()), (h.clone(), k.clone())]).unwrap();
            let d = a.eval_derivs(t, r, 1, 1);
            let mut o = [0.0; 2];
            let (mut fo, mut go, mut ho, mut ko) = ([0.0; 2], [0.0; 2], [0.0; 2], [0.0; 2]);
            f.eval_derivs(t, 1, &mut fo);
            g.eval_derivs(r, 1, &mut go);
            h.eval_derivs(t, 1, &mut ho);
            k.eval_derivs(r, 1, &mut ko);
            o[0] = fo[1] * go[0] + ho[1] * ko[0];
            o[1] = fo[0] * go[1] + ho[0] * ko[1];
            prop_assert!(close(d[2], o[0], 100.0), "{} {}", d[2], o[0]);
            prop_assert!(close(d[1], o[1], 100.0));
            prop_assert!(close(d[3], fo[1] * go[1] + ho[1] * ko[1], 100.0));
            prop_assert!(close(a.deriv_t().eval(t, r), o[0], 100.0));
            prop_assert!(close(a.deriv_r().eval(t, r), o[1], 100.0));
        }

        /// Subdivision, restriction, refinement and elevation do not change the function.
        #[test]
        fn subdivision_keeps_the_function(f in arb_spline(), g in arb_spline(), h in arb_spline(), k in arb_spline(),
                                          u in 0.1..0.9f64, t in 0.0..=1.0f64, r in 0.0..=1.0f64) {
            let a = TensorBSpline::sum_of_outer(&[(f, g), (h, k)]).unwrap();
            let v = a.eval(t, r);
            let (lo, hi) = a.split_t(u).unwrap();
            let part = if t <= u { &lo } else { &hi };
            prop_assert!(close(part.eval(t, r), v, 16.0));
            let (lo, hi) = a.split_r(u).unwrap();
            let part = if r <= u { &lo } else { &hi };
            prop_assert!(close(part.eval(t, r), v, 16.0));
            let sub = a.restrict(t.min(u) * 0.5, 1.0, 0.0, r.max(u)).unwrap();
            prop_assert!(close(sub.eval(t, r), v, 16.0));
            prop_assert!(close(a.refine_t(&[u]).unwrap().eval(t, r), v, 16.0));
            prop_assert!(close(a.refine_r(&[u]).unwrap().eval(t, r), v, 16.0));
            prop_assert!(close(a.elevate(1, 2).eval(t, r), v, 16.0));
            prop_assert!(close(a.transpose().eval(r, t), v, 16.0));
            for p in a.bezier_patches() {
                if (p.t0..=p.t1).contains(&t) && (p.r0..=p.r1).contains(&r) {
                    prop_assert!(close(p.to_tensor().eval(t, r), v, 16.0));
                }
            }
        }
    }
}
