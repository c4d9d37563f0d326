//! The function on stretches of its domain: every piece cut into equal parts, or the pieces
//! over `[lo, hi]` handed out one by one, cut to it, with their error bounds (what certified
//! decisions read).

use super::casteljau::{split_left, split_left_points, split_right, split_right_points};
use super::Piecewise;
use crate::rounding;
use smallvec::SmallVec;

impl Piecewise {
    /// The same function with every piece cut into `k` equal pieces (de Casteljau), the cuts
    /// `C^∞`.
    pub fn subdivided(&self, k: usize) -> Piecewise {
        let k = k.max(1);
        let (d, n, p) = (self.dim, self.pieces(), self.degree);
        let mut breaks = vec![self.breaks[0]];
        let mut coefs = Vec::with_capacity(self.coefs.len() * k);
        let mut err = Vec::with_capacity(n * k * d);
        let mut smooth = vec![self.smooth[0]];
        for i in 0..n {
            let (a, b) = self.piece_span(i);
            for j in 0..k {
                let (r0, r1) = (j as f64 / k as f64, (j + 1) as f64 / k as f64);
                let mut pts: SmallVec<[f64; 48]> = SmallVec::from_slice(self.piece(i));
                let mut e: SmallVec<[f64; 4]> = SmallVec::from_slice(self.errors(i));
                if r1 < 1.0 {
                    self.cut_errors(i, &mut e);
                    split_left_points(&mut pts, d, r1);
                }
                if r0 > 0.0 {
                    self.cut_errors(i, &mut e);
                    split_right_points(&mut pts, d, r0 / r1);
                }
                coefs.extend_from_slice(&pts);
                err.extend_from_slice(&e);
                breaks.push(if j + 1 == k { b } else { a + (b - a) * r1 });
                smooth.push(if j + 1 == k {
                    self.smooth[i + 1]
                } else {
                    i32::MAX
                });
            }
        }
        Piecewise {
            breaks,
            degree: p,
            dim: d,
            coefs,
            err,
            smooth,
            binoms: self.binoms.clone(),
        }
    }

    /// The Bernstein coefficients of the scalar function `g = Σ_c weights[c] · f_c` on
    /// `[lo, hi]` (clamped into the domain), piece by piece in order, handed to
    /// `visit(i, x0, x1, coefs, err)` (`i` the piece) with `err` the bound on their error (the pieces' own,
    /// carried through the sum, and the rounding of the sum and of the cuts at `lo` and `hi`);
    /// stops early when `visit` returns false. The cuts are made at the rounded local
    /// parameters, so the pieces at the ends span `[lo, hi]` to within a few units of rounding
    /// of the piece's width.
    pub fn for_each_restricted(
        &self,
        weights: &[f64],
        lo: f64,
        hi: f64,
        mut visit: impl FnMut(usize, f64, f64, &[f64], f64) -> bool,
    ) {
        let (p, d) = (self.degree, self.dim);
        for (i, x0, x1) in self.overlaps(lo, hi) {
            if x1 <= x0 {
                continue;
            }
            let (a, b) = self.piece_span(i);
            let src = self.piece(i);
            let mut g: SmallVec<[f64; 32]> = SmallVec::new();
            let mut scale = 0.0f64;
            for j in 0..=p {
                let mut v = 0.0;
                let mut mag = 0.0;
                for c in 0..d {
                    let t = weights[c] * src[j * d + c];
                    v += t;
                    mag += t.abs();
                }
                g.push(v);
                scale = scale.max(mag);
            }
            let mut err = rounding::linear(d, scale, self.carried(i, weights));
            let m = scale + err;
            let h = b - a;
            let (r0, r1) = ((x0 - a) / h, (x1 - a) / h);
            if r1 < 1.0 {
                split_left(&mut g, r1);
                err += rounding::casteljau(p, m);
            }
            if r0 > 0.0 {
                let r = if r1 < 1.0 { r0 / r1 } else { r0 };
                split_right(&mut g, r);
                err += rounding::casteljau(p, m + err);
            }
            if !visit(i, x0, x1, &g, err) {
                return;
            }
        }
    }

    /// The control points (dimension `dim`) of the function on `[lo, hi]`, piece by piece in
    /// order, to `visit(points, errors)` (one bound per coordinate); stops when it returns
    /// false.
    pub fn for_each_restricted_points(
        &self,
        lo: f64,
        hi: f64,
        mut visit: impl FnMut(&[f64], &[f64]) -> bool,
    ) {
        let d = self.dim;
        for (i, x0, x1) in self.overlaps(lo, hi) {
            if x1 <= x0 {
                continue;
            }
            let (a, b) = self.piece_span(i);
            let mut pts: SmallVec<[f64; 48]> = SmallVec::from_slice(self.piece(i));
            let mut e: SmallVec<[f64; 4]> = SmallVec::from_slice(self.errors(i));
            let h = b - a;
            let (r0, r1) = ((x0 - a) / h, (x1 - a) / h);
            if r1 < 1.0 {
                self.cut_errors(i, &mut e);
                split_left_points(&mut pts, d, r1);
            }
            if r0 > 0.0 {
                self.cut_errors(i, &mut e);
                split_right_points(&mut pts, d, if r1 < 1.0 { r0 / r1 } else { r0 });
            }
            if !visit(&pts, &e) {
                return;
            }
        }
    }
}
