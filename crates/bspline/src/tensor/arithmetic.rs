//! Arithmetic of tensor-product functions: scaling, linear combinations, and the exact product
//! (patch by patch, reassembled with the minimal knot vectors the factors' continuity allows).

use super::subdivision::breakpoints;
use super::{BezierPatch, TensorBSpline};
use crate::algebra::from_pieces;
use crate::error::{Error, Result};
use crate::knots::multiplicity;
use crate::refine::Bezier;
use crate::spline::BSpline;

impl TensorBSpline {
    /// The same function with every coefficient multiplied by `s`.
    pub fn scale(&self, s: f64) -> Self {
        let mut out = self.clone();
        out.coefs.iter_mut().for_each(|c| *c *= s);
        out
    }

    /// `s·self + u·other` in the common spline space (both on the same domain).
    pub fn lincomb(&self, s: f64, other: &Self, u: f64) -> Result<Self> {
        let same_space = self.deg_t == other.deg_t
            && self.deg_r == other.deg_r
            && self.knots_t == other.knots_t
            && self.knots_r == other.knots_r;
        if same_space {
            let mut out = self.clone();
            for (c, d) in out.coefs.iter_mut().zip(&other.coefs) {
                *c = s * *c + u * d;
            }
            return Ok(out);
        }
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

#[cfg(test)]
mod tests {
    use super::super::strategies::{arb_spline, close};
    use super::*;
    use proptest::prelude::*;

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
    }
}
