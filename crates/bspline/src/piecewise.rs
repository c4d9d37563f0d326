//! Piecewise Bézier form: a function as its Bernstein pieces on consecutive breakpoints, each
//! piece with a bound on the error of its coefficients, and the order of continuity at each
//! break. This is the form every certified decision reads: the products of the symbolic forms
//! are taken piece by piece (no blossom extrapolation, whose rounding grows without bound with
//! the degree), the control points of any stretch come from de Casteljau's algorithm on the few
//! pieces it overlaps, and [`crate::rounding`] bounds every step, in terms of the magnitudes
//! involved.
//!
//! The error bounds of a piece are per coordinate: the exact function's coefficient lies within
//! `errors(i)[c]` of the stored one in coordinate `c` (a slender curve's coordinates differ in
//! size by orders of magnitude, and so do their errors).

mod algebra;
mod casteljau;
mod derivative;
mod eval;
mod reparametrise;
mod stretches;

pub use eval::ValueSlope;

pub(crate) use casteljau::{split_left, split_right};

use crate::error::{Error, Result};
use crate::knots::{find_span, multiplicity};
use crate::rounding;
use crate::spline::BSpline;

/// Order of continuity at a break where the function may jump.
pub const JUMP: i32 = -1;

/// Order of continuity where nothing is known (the seam of a function that is not periodic).
const UNKNOWN: i32 = JUMP;

/// A function `[a, b] → R^dim` as Bézier pieces of one degree on consecutive breakpoints.
///
/// ```
/// use bspline::{BSpline, Piecewise};
/// // A periodic cubic: four pieces, C² at every break and at the seam.
/// let f = BSpline::periodic(3, 1, vec![0., 1., 3., 2.]).unwrap();
/// let pw = Piecewise::from_bspline(&f).with_periodic_seam(2);
/// assert_eq!(pw.pieces(), 4);
/// assert_eq!(pw.continuity(0), 2);
/// let mut v = [0.0];
/// pw.eval_derivs(1.3, 0, &mut v);
/// assert!((v[0] - f.eval_scalar(1.3)).abs() <= pw.eval_error(1, 0));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Piecewise {
    breaks: Vec<f64>,
    degree: usize,
    dim: usize,
    /// Piece-major, then point-major: `(degree + 1) · dim` values per piece.
    coefs: Vec<f64>,
    /// Per piece and coordinate (`pieces · dim` entries), the bound on the error of the
    /// piece's coefficients in that coordinate.
    err: Vec<f64>,
    /// Per break (`breaks.len()` entries), the order of continuity there: at interior breaks
    /// that of the function; at the two ends that of the periodic function across its seam
    /// ([`JUMP`] where it is not periodic).
    smooth: Vec<i32>,
    /// The binomial coefficients `C(degree, j)`.
    binoms: Vec<f64>,
}

fn binomials(p: usize) -> Vec<f64> {
    let mut out = Vec::with_capacity(p + 1);
    let mut b = 1.0;
    for j in 0..=p {
        out.push(b);
        b = b * (p - j) as f64 / (j + 1) as f64;
    }
    out
}

impl Piecewise {
    /// The Bézier pieces of `f`, one per non-empty knot span, with the error of the knot
    /// insertion that extracts them (the coefficients of `f` taken as exact).
    pub fn from_bspline(f: &BSpline) -> Self {
        Self::from_bspline_with_error(f, 0.0)
    }

    /// [`Piecewise::from_bspline`] for coefficients that are themselves in error by up to
    /// `err` (a computed spline).
    pub fn from_bspline_with_error(f: &BSpline, err: f64) -> Self {
        let (p, d) = (f.degree(), f.dim());
        let (lo, hi) = f.domain();
        let breaks = f.breakpoints();
        // Every interior break to multiplicity p, the ends to p + 1 (the clamped form): then
        // the p + 1 basis functions alive on a span are its Bernstein polynomials.
        let knots = f.knots();
        let mut x: Vec<f64> = Vec::new();
        x.extend(std::iter::repeat_n(
            lo,
            (p + 1).saturating_sub(multiplicity(knots, lo)),
        ));
        for &bk in &breaks[1..breaks.len() - 1] {
            x.extend(std::iter::repeat_n(
                bk,
                p.saturating_sub(multiplicity(knots, bk)),
            ));
        }
        x.extend(std::iter::repeat_n(
            hi,
            (p + 1).saturating_sub(multiplicity(knots, hi)),
        ));
        let mut errors = vec![err; f.coefs().len()];
        let r = f.refine_tracked(&x, Some(&mut errors));
        let mut coefs = Vec::with_capacity((breaks.len() - 1) * (p + 1) * d);
        let mut err_out = Vec::with_capacity((breaks.len() - 1) * d);
        for w in breaks.windows(2) {
            let span = find_span(p, r.n_ctrl(), r.knots(), 0.5 * (w[0] + w[1]));
            coefs.extend_from_slice(&r.coefs()[(span - p) * d..(span + 1) * d]);
            let piece = &errors[(span - p) * d..(span + 1) * d];
            err_out.extend((0..d).map(|c| {
                piece
                    .iter()
                    .skip(c)
                    .step_by(d)
                    .fold(0.0f64, |m, &e| m.max(e))
            }));
        }
        let mut smooth: Vec<i32> = breaks
            .iter()
            .map(|&bk| p as i32 - multiplicity(knots, bk) as i32)
            .collect();
        let last = smooth.len() - 1;
        smooth[0] = UNKNOWN;
        smooth[last] = UNKNOWN;
        Self {
            breaks,
            degree: p,
            dim: d,
            coefs,
            err: err_out,
            smooth,
            binoms: binomials(p),
        }
    }

    /// A function from its pieces: `breaks` increasing (`n + 1` values for `n` pieces),
    /// `coefs` the `n · (degree + 1) · dim` control point coordinates (piece-major), `err` one
    /// bound per piece and coordinate (`n · dim`, piece-major), `smooth` one order of
    /// continuity per break (ends: across the seam).
    pub fn from_parts(
        degree: usize,
        dim: usize,
        breaks: Vec<f64>,
        coefs: Vec<f64>,
        err: Vec<f64>,
        smooth: Vec<i32>,
    ) -> Result<Self> {
        if dim == 0 {
            return Err(Error::ZeroDimension);
        }
        let n = breaks.len().saturating_sub(1);
        if n == 0 {
            return Err(Error::TooFewPoints {
                degree,
                needed: 2,
                got: breaks.len(),
            });
        }
        for (what, expected, got) in [
            ("coefficients", n * (degree + 1) * dim, coefs.len()),
            (
                "error bounds (one per piece and coordinate)",
                n * dim,
                err.len(),
            ),
            ("continuity orders (one per break)", n + 1, smooth.len()),
        ] {
            if expected != got {
                return Err(Error::CountMismatch {
                    what,
                    expected,
                    got,
                });
            }
        }
        crate::error::check_finite("breaks", &breaks)?;
        crate::error::check_finite("coefs", &coefs)?;
        if let Some(i) = (1..breaks.len()).find(|&i| breaks[i] <= breaks[i - 1]) {
            return Err(Error::DecreasingKnots {
                index: i,
                value: breaks[i],
                previous: breaks[i - 1],
            });
        }
        if let Some(index) = err.iter().position(|e| e.is_nan() || *e < 0.0) {
            return Err(Error::NotFinite {
                what: "error bounds",
                index,
                value: err[index],
            });
        }
        Ok(Self {
            breaks,
            degree,
            dim,
            coefs,
            err,
            smooth,
            binoms: binomials(degree),
        })
    }

    /// A function of the same breaks and dimension as `self` with other pieces, of `degree`
    /// (what a piece-by-piece operation builds: a raised degree, a derivative).
    #[inline]
    fn with_pieces(&self, degree: usize, coefs: Vec<f64>, err: Vec<f64>, smooth: Vec<i32>) -> Self {
        Self {
            breaks: self.breaks.clone(),
            degree,
            dim: self.dim,
            coefs,
            err,
            smooth,
            binoms: binomials(degree),
        }
    }

    /// The same function declared periodic: its derivatives up to `order` agree across the
    /// seam (a periodic B-spline of degree p is `C^(p−1)` there). The caller vouches for it.
    pub fn with_periodic_seam(mut self, order: i32) -> Self {
        let last = self.smooth.len() - 1;
        self.smooth[0] = order;
        self.smooth[last] = order;
        self
    }

    /// The same function with coordinate `k` set to the constant `value` everywhere, which the
    /// caller knows to be its exact value there (the weight of a polynomial curve).
    pub fn with_coordinate(mut self, k: usize, value: f64) -> Self {
        if k < self.dim {
            let d = self.dim;
            for pt in self.coefs.chunks_exact_mut(d) {
                pt[k] = value;
            }
        }
        self
    }

    /// The same function declared continuous to `order` at every interior break (and across
    /// the seam when it is periodic), where it is not known to be more: the caller knows more
    /// than the pieces' structure shows (the numerators of a curve on the rational circle are
    /// continuous where its homogeneous form is only `C⁰`).
    pub fn with_continuity(mut self, order: i32) -> Self {
        let last = self.smooth.len() - 1;
        let periodic = self.is_periodic();
        for (k, s) in self.smooth.iter_mut().enumerate() {
            if (k > 0 && k < last) || periodic {
                *s = (*s).max(order);
            }
        }
        self
    }

    /// The scalar function `Σ weights[c] f_c`, with the bound on its error.
    pub fn weighted(&self, weights: &[f64]) -> Piecewise {
        let (p, d, n) = (self.degree, self.dim, self.pieces());
        let mut coefs = Vec::with_capacity(n * (p + 1));
        let mut err = Vec::with_capacity(n);
        for i in 0..n {
            let mut scale = 0.0f64;
            for pt in self.piece(i).chunks_exact(d) {
                let (mut v, mut mag) = (0.0, 0.0);
                for (w, x) in weights.iter().zip(pt) {
                    v += w * x;
                    mag += (w * x).abs();
                }
                coefs.push(v);
                scale = scale.max(mag);
            }
            err.push(rounding::linear(d, scale, self.carried(i, weights)));
        }
        Piecewise {
            breaks: self.breaks.clone(),
            degree: p,
            dim: 1,
            coefs,
            err,
            smooth: self.smooth.clone(),
            binoms: self.binoms.clone(),
        }
    }

    /// Polynomial degree of the pieces.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// Dimension of the control points.
    pub fn dim(&self) -> usize {
        self.dim
    }
    /// The breakpoints, from the domain's start to its end.
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }
    /// The domain `[a, b]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.breaks[0], self.breaks[self.breaks.len() - 1])
    }
    /// The number of pieces.
    pub fn pieces(&self) -> usize {
        self.breaks.len() - 1
    }
    /// The interval of piece `i`.
    pub fn piece_span(&self, i: usize) -> (f64, f64) {
        (self.breaks[i], self.breaks[i + 1])
    }
    /// The control points of piece `i` (point-major).
    pub fn piece(&self, i: usize) -> &[f64] {
        let w = (self.degree + 1) * self.dim;
        &self.coefs[i * w..(i + 1) * w]
    }
    /// The bounds on the error of piece `i`'s coefficients, one per coordinate.
    pub fn errors(&self, i: usize) -> &[f64] {
        &self.err[i * self.dim..(i + 1) * self.dim]
    }
    /// The largest bound on the error of piece `i`'s coefficients (over its coordinates).
    pub fn error(&self, i: usize) -> f64 {
        self.errors(i).iter().fold(0.0, |m, &e| m.max(e))
    }
    /// `Σ |weights[c]| errors(i)[c]`: the error piece `i`'s coefficients carry into the
    /// combination `Σ weights[c] f_c`.
    fn carried(&self, i: usize, weights: &[f64]) -> f64 {
        self.errors(i)
            .iter()
            .zip(weights)
            .map(|(e, w)| e * w.abs())
            .sum()
    }
    /// The largest magnitude of coordinate `c` among the control points of piece `i`.
    pub fn coordinate_magnitude(&self, i: usize, c: usize) -> f64 {
        self.piece(i)
            .iter()
            .skip(c)
            .step_by(self.dim)
            .fold(0.0, |m, x| m.max(x.abs()))
    }
    /// The largest error bound of any piece.
    pub fn max_error(&self) -> f64 {
        self.err.iter().fold(0.0, |m, &e| m.max(e))
    }
    /// The order of continuity at break `k` (`0 ≤ k ≤ pieces`; the ends: across the seam,
    /// [`JUMP`] unless periodic).
    pub fn continuity(&self, k: usize) -> i32 {
        self.smooth[k]
    }
    /// True when the function was declared periodic ([`Piecewise::with_periodic_seam`]).
    pub fn is_periodic(&self) -> bool {
        self.smooth[0] >= 0
    }
    /// Index of the piece holding `u` (the right one at a break, the last one at the end).
    pub fn piece_at(&self, u: f64) -> usize {
        let n = self.breaks.len() - 1;
        self.breaks.partition_point(|&x| x <= u).clamp(1, n) - 1
    }
    /// The largest magnitude among the control points of piece `i`.
    pub fn piece_magnitude(&self, i: usize) -> f64 {
        self.piece(i).iter().fold(0.0, |m, x| m.max(x.abs()))
    }
    /// Per piece, a bound on the Euclidean norm of the function there (its largest control
    /// point's length, plus the error in every coordinate).
    pub fn norm_bounds(&self) -> Vec<f64> {
        let d = self.dim;
        (0..self.pieces())
            .map(|i| {
                let e = self.errors(i).iter().map(|e| e * e).sum::<f64>().sqrt();
                self.piece(i)
                    .chunks_exact(d)
                    .map(|pt| pt.iter().map(|x| x * x).sum::<f64>().sqrt())
                    .fold(0.0, f64::max)
                    + e
            })
            .collect()
    }

    /// The pieces overlapping `[lo, hi]`: `(index, x0, x1)` with the overlap.
    pub fn overlaps(&self, lo: f64, hi: f64) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
        let (first, last) = (self.piece_at(lo), self.piece_at(hi));
        (first..=last).filter_map(move |i| {
            let (x0, x1) = (lo.max(self.breaks[i]), hi.min(self.breaks[i + 1]));
            (x1 >= x0).then_some((i, x0, x1))
        })
    }
}
