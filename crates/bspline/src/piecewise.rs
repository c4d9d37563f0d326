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
mod eval;

pub use eval::ValueSlope;

use crate::error::{Error, Result};
use crate::knots::{find_span, multiplicity};
use crate::rounding;
use crate::spline::BSpline;
use smallvec::SmallVec;

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

    /// Adds to the per-coordinate errors `e` of a stretch of piece `i` (whose coefficients lie
    /// within the piece's magnitudes and `e`) the rounding of one more de Casteljau cut.
    fn cut_errors(&self, i: usize, e: &mut [f64]) {
        for (c, ec) in e.iter_mut().enumerate() {
            *ec += rounding::casteljau(self.degree, self.coordinate_magnitude(i, c) + *ec);
        }
    }

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
        Piecewise {
            breaks: self.breaks.clone(),
            degree: q,
            dim: d,
            coefs,
            err,
            smooth: self.smooth.iter().map(|&s| lower(s)).collect(),
            binoms: binomials(q),
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

/// The continuity order of a derivative: one lower (a jump stays a jump).
fn lower(s: i32) -> i32 {
    if s == i32::MAX || s < 0 {
        s
    } else {
        s - 1
    }
}

/// [`split_left`] on points of dimension `d` stored point-major, all coordinates at once.
pub(crate) fn split_left_points(g: &mut [f64], d: usize, r: f64) {
    if d == 1 {
        return split_left(g, r);
    }
    let p = g.len() / d - 1;
    for level in 1..=p {
        for j in (level..=p).rev() {
            let (head, tail) = g.split_at_mut(j * d);
            let prev = &head[(j - 1) * d..];
            for (x, &y) in tail[..d].iter_mut().zip(prev) {
                *x = y + r * (*x - y);
            }
        }
    }
}

/// [`split_right`] on points of dimension `d` stored point-major, all coordinates at once.
pub(crate) fn split_right_points(g: &mut [f64], d: usize, r: f64) {
    if d == 1 {
        return split_right(g, r);
    }
    let p = g.len() / d - 1;
    for level in 1..=p {
        for j in 0..=p - level {
            let (head, tail) = g.split_at_mut((j + 1) * d);
            let cur = &mut head[j * d..];
            for (x, &y) in cur.iter_mut().zip(&tail[..d]) {
                *x += r * (y - *x);
            }
        }
    }
}

/// Replaces the Bernstein coefficients on `[0, 1]` by those of the part on `[0, r]`.
pub(crate) fn split_left(g: &mut [f64], r: f64) {
    let p = g.len() - 1;
    // After level k, g[k] is the k-th left coefficient; the tail is updated in place.
    for level in 1..=p {
        for j in (level..=p).rev() {
            g[j] = g[j - 1] + r * (g[j] - g[j - 1]);
        }
    }
}

/// Replaces the Bernstein coefficients on `[0, 1]` by those of the part on `[r, 1]`.
pub(crate) fn split_right(g: &mut [f64], r: f64) {
    let p = g.len() - 1;
    for level in 1..=p {
        for j in 0..=p - level {
            g[j] += r * (g[j + 1] - g[j]);
        }
    }
}
