//! Values and partial derivatives: evaluation at a point from the two bases, and the
//! derivative tensors from the univariate views.

use super::TensorBSpline;
use crate::knots::{basis_derivs, find_span, Scratch};

impl TensorBSpline {
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
    use super::super::strategies::{arb_spline, close};
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(1000))]

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
    }
}
