//! The derivative piece by piece (the hodograph), with the bound on its error and its
//! continuity one order lower at every break.

use super::Piecewise;
use crate::rounding;

impl Piecewise {
    /// The derivative, piece by piece: degree `p − 1` with control points `p/h · Δc` (the
    /// hodograph). A constant function gives a zero of degree 0.
    pub fn derivative(&self) -> Piecewise {
        let (p, d, n) = (self.degree, self.dim, self.pieces());
        let q = p.max(1) - 1;
        let mut coefs = Vec::with_capacity(n * (q + 1) * d);
        let mut err = Vec::with_capacity(n * d);
        for i in 0..n {
            let (c, (a, b)) = (self.piece(i), self.piece_span(i));
            if p == 0 {
                coefs.extend(std::iter::repeat_n(0.0, d));
                err.extend(std::iter::repeat_n(0.0, d));
                continue;
            }
            let f = p as f64 / (b - a);
            coefs.extend(
                (0..q + 1)
                    .flat_map(|j| (0..d).map(move |k| f * (c[(j + 1) * d + k] - c[j * d + k]))),
            );
            err.extend((0..d).map(|k| {
                rounding::derivative(p, a, b, self.coordinate_magnitude(i, k), self.errors(i)[k])
            }));
        }
        self.with_pieces(
            q,
            coefs,
            err,
            self.smooth.iter().map(|&s| lower(s)).collect(),
        )
    }
}

/// The continuity order of a derivative: one lower (a jump stays a jump).
fn lower(s: i32) -> i32 {
    if s == i32::MAX || s < 0 {
        s
    } else {
        s - 1
    }
}
