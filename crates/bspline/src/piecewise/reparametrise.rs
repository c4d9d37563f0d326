//! The same function in another parametrisation: a periodic function started at another
//! point of its period, or any function run backwards (pieces reordered, breaks moved).

use super::casteljau::{split_left_points, split_right_points};
use super::Piecewise;
use smallvec::SmallVec;

impl Piecewise {
    /// The periodic function (see [`Piecewise::with_periodic_seam`]) on one period starting at
    /// `u0` instead of the domain's start: `[u0, u0 + period]`, the piece holding `u0` cut
    /// there, the pieces before it moved up by the period. `None` when the function is not
    /// declared periodic, `u0` lies outside the domain, or the shifted breaks would not stay
    /// apart in floating point.
    pub fn rotated(&self, u0: f64) -> Option<Piecewise> {
        let (a, b) = self.domain();
        if !(self.is_periodic() && u0 >= a && u0 < b) {
            return None;
        }
        let period = b - a;
        let (p, d, n) = (self.degree, self.dim, self.pieces());
        let i = self.piece_at(u0);
        let (lo, hi) = self.piece_span(i);
        let mut out = Piecewise {
            breaks: vec![u0],
            degree: p,
            dim: d,
            coefs: Vec::with_capacity(self.coefs.len() + (p + 1) * d),
            err: Vec::with_capacity((n + 1) * d),
            smooth: vec![],
            binoms: self.binoms.clone(),
        };
        let mut push = |c: &[f64], e: &[f64], end: f64, joint: i32| {
            out.coefs.extend_from_slice(c);
            out.err.extend_from_slice(e);
            out.smooth.push(joint);
            out.breaks.push(end);
        };
        let cut = u0 > lo;
        let (left, right) = if cut {
            let mut e: SmallVec<[f64; 4]> = SmallVec::from_slice(self.errors(i));
            self.cut_errors(i, &mut e);
            let r = (u0 - lo) / (hi - lo);
            let mut l: SmallVec<[f64; 48]> = SmallVec::from_slice(self.piece(i));
            let mut rt = l.clone();
            split_left_points(&mut l, d, r);
            split_right_points(&mut rt, d, r);
            (Some((l, e.clone())), Some((rt, e)))
        } else {
            (None, None)
        };
        let seam = if cut { i32::MAX } else { self.smooth[i] };
        let first = if cut { i + 1 } else { i };
        if let Some((rt, e)) = &right {
            push(rt, e, hi, seam);
        }
        for j in first..n {
            // (Uncut, the first piece starts at the new seam.)
            let joint = if j == i { seam } else { self.smooth[j] };
            push(self.piece(j), self.errors(j), self.breaks[j + 1], joint);
        }
        for j in 0..i {
            push(
                self.piece(j),
                self.errors(j),
                self.breaks[j + 1] + period,
                self.smooth[j],
            );
        }
        if let Some((l, e)) = &left {
            push(l, e, u0 + period, self.smooth[i]);
        }
        out.smooth.push(seam);
        out.smooth[0] = seam;
        let increasing = out.breaks.windows(2).all(|w| w[1] > w[0]);
        increasing.then_some(out)
    }

    /// The same function run backwards over the same domain, `g(u) = f(a + b − u)`: the pieces
    /// in reverse order, each with its control points reversed (exactly), the breaks mirrored
    /// (`a + b − x`, rounded; the ends kept exactly). `None` when mirrored breaks would not
    /// stay apart in floating point.
    pub fn reversed(&self) -> Option<Piecewise> {
        let (a, b) = self.domain();
        let (n, d) = (self.pieces(), self.dim);
        let mut breaks: Vec<f64> = self.breaks.iter().rev().map(|&x| a + b - x).collect();
        breaks[0] = a;
        breaks[n] = b;
        if !breaks.windows(2).all(|w| w[1] > w[0]) {
            return None;
        }
        let mut coefs = Vec::with_capacity(self.coefs.len());
        let mut err = Vec::with_capacity(self.err.len());
        for i in (0..n).rev() {
            for pt in self.piece(i).chunks_exact(d).rev() {
                coefs.extend_from_slice(pt);
            }
            err.extend_from_slice(self.errors(i));
        }
        Some(Piecewise {
            breaks,
            degree: self.degree,
            dim: d,
            coefs,
            err,
            smooth: self.smooth.iter().rev().copied().collect(),
            binoms: self.binoms.clone(),
        })
    }
}
