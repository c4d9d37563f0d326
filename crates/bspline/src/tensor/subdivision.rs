//! The same function in a finer or smaller form: knot insertion, degree elevation, restriction,
//! splitting, and its Bézier patches, each done on the univariate view in one direction.

use super::{BezierPatch, TensorBSpline};
use crate::error::Result;
use crate::spline::BSpline;

impl TensorBSpline {
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

    /// The Bézier patches of the function, one per pair of non-empty knot spans, ordered by
    /// `t` cell then `r` cell.
    pub fn bezier_patches(&self) -> Vec<BezierPatch> {
        let bt = breakpoints(self.domain_t(), &self.knots_t);
        let br = breakpoints(self.domain_r(), &self.knots_r);
        self.patches_at(&bt, &br)
    }

    /// Bézier patches on the grid of `bt × br` (sorted, ends equal to the domain, containing
    /// every interior knot).
    pub(super) fn patches_at(&self, bt: &[f64], br: &[f64]) -> Vec<BezierPatch> {
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

pub(super) fn breakpoints(dom: (f64, f64), knots: &[f64]) -> Vec<f64> {
    let mut out = vec![dom.0];
    for &k in knots {
        if k > dom.0 && k < dom.1 && out.last() != Some(&k) {
            out.push(k);
        }
    }
    out.push(dom.1);
    out
}

#[cfg(test)]
mod tests {
    use super::super::strategies::{arb_spline, close};
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(1000))]

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
