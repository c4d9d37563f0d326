//! Piecewise Bézier forms of B-splines, built once per curve: allocation-free evaluation with
//! derivatives, and the control polygon of any sub-interval (for the sign tests of the
//! primitives) by de Casteljau subdivision of the few pieces it overlaps.
//!
//! The coefficients are those of `bspline` (knot insertion up to full multiplicity), so the
//! forms are exactly the splines they come from, up to rounding.

use bspline::BSpline;
use smallvec::SmallVec;

/// Scratch space for one piece (on the stack up to degree 15 in dimension 3).
type Buf = SmallVec<[f64; 48]>;

/// A spline as its Bézier pieces on consecutive breakpoints.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Pw {
    breaks: Vec<f64>,
    deg: usize,
    dim: usize,
    /// Piece-major, then point-major: `(deg + 1) · dim` values per piece.
    coefs: Vec<f64>,
    /// The binomial coefficients `C(deg, j)` (for evaluation in the Bernstein basis).
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

impl Pw {
    /// The Bézier pieces of `f`, one per non-empty knot span.
    pub(crate) fn new(f: &BSpline) -> Self {
        let pieces = f.bezier_pieces();
        let mut breaks = Vec::with_capacity(pieces.len() + 1);
        let mut coefs = Vec::with_capacity(pieces.len() * (f.degree() + 1) * f.dim());
        for (i, b) in pieces.iter().enumerate() {
            if i == 0 {
                breaks.push(b.a);
            }
            breaks.push(b.b);
            coefs.extend_from_slice(&b.coefs);
        }
        Self {
            breaks,
            deg: f.degree(),
            dim: f.dim(),
            coefs,
            binoms: binomials(f.degree()),
        }
    }

    pub(crate) fn degree(&self) -> usize {
        self.deg
    }

    pub(crate) fn dim(&self) -> usize {
        self.dim
    }

    /// Index of the piece holding `u` (the right one at a break, the last one at the end).
    pub(crate) fn piece_at(&self, u: f64) -> usize {
        let n = self.breaks.len() - 1;
        self.breaks.partition_point(|&x| x <= u).clamp(1, n) - 1
    }

    /// The breakpoints, from the domain's start to its end.
    pub(crate) fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// The number of pieces.
    pub(crate) fn pieces(&self) -> usize {
        self.breaks.len() - 1
    }

    /// The interval of piece `i`.
    pub(crate) fn piece_span(&self, i: usize) -> (f64, f64) {
        (self.breaks[i], self.breaks[i + 1])
    }

    /// The control points of piece `i` (point-major).
    pub(crate) fn piece(&self, i: usize) -> &[f64] {
        let w = (self.deg + 1) * self.dim;
        &self.coefs[i * w..(i + 1) * w]
    }

    /// Value and derivatives up to order `k ≤ 3` at `u` (clamped into the domain):
    /// `out[j·dim + c]` is the j-th derivative of component `c`. Derivatives above the degree
    /// are zero. De Casteljau: the j-th derivative is `p!/(p−j)! Δʲ` of the points of level
    /// `p − j`, over `hʲ`.
    #[inline]
    pub(crate) fn eval_derivs(&self, u: f64, k: usize, out: &mut [f64]) {
        if self.dim == 3 && self.deg <= 7 && k <= 3 {
            self.eval_derivs3(u, k, out)
        } else {
            self.eval_derivs_any(u, k, out)
        }
    }

    /// [`Pw::eval_derivs`] for any dimension and degree (kept out of line: the planar
    /// curves' jets take the fixed-size path).
    #[inline(never)]
    fn eval_derivs_any(&self, u: f64, k: usize, out: &mut [f64]) {
        let (p, d) = (self.deg, self.dim);
        let i = self.piece_at(u);
        let (a, b) = (self.breaks[i], self.breaks[i + 1]);
        let h = b - a;
        let s =
            ((u.clamp(self.breaks[0], self.breaks[self.breaks.len() - 1]) - a) / h).clamp(0.0, 1.0);
        // Scratch on the stack (degree ≤ 15 in dimension 3), else on the heap.
        let src = self.piece(i);
        let mut stack = [0.0f64; 48];
        let mut heap = Vec::new();
        let w: &mut [f64] = if src.len() <= stack.len() {
            stack[..src.len()].copy_from_slice(src);
            &mut stack[..src.len()]
        } else {
            heap.extend_from_slice(src);
            &mut heap
        };
        for v in out[..(k + 1) * d].iter_mut() {
            *v = 0.0;
        }
        // Levels p, p−1, p−2, p−3 hold 1, 2, 3, 4 points.
        let mut lv: [[f64; 12]; 4] = [[0.0; 12]; 4];
        let keep = |lv: &mut [[f64; 12]; 4], w: &[f64], pts: usize| {
            // pts = number of points left (p − level + 1); keep the last four levels.
            if pts <= 4 {
                lv[pts - 1][..pts * d].copy_from_slice(&w[..pts * d]);
            }
        };
        keep(&mut lv, w, p + 1);
        for level in 1..=p {
            for j in 0..=p - level {
                for c in 0..d {
                    w[j * d + c] += s * (w[(j + 1) * d + c] - w[j * d + c]);
                }
            }
            keep(&mut lv, w, p - level + 1);
        }
        out[..d].copy_from_slice(&lv[0][..d]);
        let mut fact = 1.0;
        for j in 1..=k.min(p) {
            fact *= (p + 1 - j) as f64 / h;
            // j-th forward difference of the j + 1 points of level p − j.
            let pts = &lv[j];
            for c in 0..d {
                let mut acc = 0.0;
                let mut binom = 1.0;
                for m in 0..=j {
                    let sign = if (j - m) % 2 == 0 { 1.0 } else { -1.0 };
                    acc += sign * binom * pts[m * d + c];
                    binom = binom * (j - m) as f64 / (m + 1) as f64;
                }
                out[j * d + c] = fact * acc;
            }
        }
    }

    /// [`Pw::eval_derivs`] for points of dimension 3 and degree ≤ 7 (homogeneous planar
    /// curves): de Casteljau on fixed-size arrays, one instance per degree so that the
    /// loops unroll (jets are most of the cost of a spline's run).
    #[inline]
    fn eval_derivs3(&self, u: f64, k: usize, out: &mut [f64]) {
        let i = self.piece_at(u);
        let (a, b) = (self.breaks[i], self.breaks[i + 1]);
        let h = b - a;
        let s =
            ((u.clamp(self.breaks[0], self.breaks[self.breaks.len() - 1]) - a) / h).clamp(0.0, 1.0);
        let src = self.piece(i);
        match self.deg {
            1 => casteljau3::<2>(src, s, h, k, out),
            2 => casteljau3::<3>(src, s, h, k, out),
            3 => casteljau3::<4>(src, s, h, k, out),
            4 => casteljau3::<5>(src, s, h, k, out),
            5 => casteljau3::<6>(src, s, h, k, out),
            6 => casteljau3::<7>(src, s, h, k, out),
            _ => casteljau3::<8>(src, s, h, k, out),
        }
    }

    /// The Bernstein coefficients of the scalar function `g(u) = Σ_c weights[c] · f_c(u)` on
    /// `[lo, hi]` (inside one piece's closure or spanning several), piece by piece, handed to
    /// `visit(x0, x1, coefs, scale)` in order; `scale` bounds `Σ_c |weights[c] f_c|` over the
    /// coefficients (for rounding bounds). Stops early when `visit` returns false.
    pub(crate) fn for_each_restricted(
        &self,
        weights: &[f64],
        lo: f64,
        hi: f64,
        mut visit: impl FnMut(f64, f64, &[f64], f64) -> bool,
    ) {
        let (p, d) = (self.deg, self.dim);
        let first = self.piece_at(lo);
        let last = self.piece_at(hi);
        for i in first..=last {
            let (a, b) = (self.breaks[i], self.breaks[i + 1]);
            let (x0, x1) = (lo.max(a), hi.min(b));
            if x1 <= x0 {
                continue;
            }
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
            let h = b - a;
            let (r0, r1) = ((x0 - a) / h, (x1 - a) / h);
            if r1 < 1.0 {
                // Keep the left part [0, r1].
                split_left(&mut g, r1);
            }
            if r0 > 0.0 {
                // Keep the right part [r0/r1, 1] of what is left.
                let r = if r1 < 1.0 { r0 / r1 } else { r0 };
                split_right(&mut g, r);
            }
            if !visit(x0, x1, &g, scale) {
                return;
            }
        }
    }

    /// The same function with every piece cut into `k` equal pieces (de Casteljau: exact up
    /// to rounding).
    pub(crate) fn subdivided(&self, k: usize) -> Pw {
        let (d, n) = (self.dim, self.breaks.len() - 1);
        let mut breaks = vec![self.breaks[0]];
        let mut coefs = Vec::with_capacity(self.coefs.len() * k);
        for i in 0..n {
            let (a, b) = (self.breaks[i], self.breaks[i + 1]);
            for j in 0..k {
                let (r0, r1) = (j as f64 / k as f64, (j + 1) as f64 / k as f64);
                let mut pts = Buf::from_slice(self.piece(i));
                if r1 < 1.0 {
                    split_left_points(&mut pts, d, r1);
                }
                if r0 > 0.0 {
                    split_right_points(&mut pts, d, r0 / r1);
                }
                coefs.extend_from_slice(&pts);
                breaks.push(if j + 1 == k { b } else { a + (b - a) * r1 });
            }
        }
        Pw {
            breaks,
            deg: self.deg,
            dim: d,
            coefs,
            binoms: self.binoms.clone(),
        }
    }

    /// The derivative, piece by piece: degree `p − 1` with control points `p/h · Δc` (the
    /// hodograph), exact up to rounding. A constant function gives a zero of degree 0.
    pub(crate) fn derivative(&self) -> Pw {
        let (p, d, n) = (self.deg, self.dim, self.breaks.len() - 1);
        let q = p.max(1) - 1;
        let mut coefs = Vec::with_capacity(n * (q + 1) * d);
        for i in 0..n {
            let (c, h) = (self.piece(i), self.breaks[i + 1] - self.breaks[i]);
            if p == 0 {
                coefs.extend(std::iter::repeat_n(0.0, d));
                continue;
            }
            let f = p as f64 / h;
            coefs.extend(
                (0..q + 1)
                    .flat_map(|j| (0..d).map(move |k| f * (c[(j + 1) * d + k] - c[j * d + k]))),
            );
        }
        Pw {
            breaks: self.breaks.clone(),
            deg: q,
            dim: d,
            coefs,
            binoms: binomials(q),
        }
    }

    /// Per piece, a bound on `|f|` there (Euclidean norm): its largest control point.
    pub(crate) fn norm_bounds(&self) -> Vec<f64> {
        let d = self.dim;
        (0..self.pieces())
            .map(|i| {
                self.piece(i)
                    .chunks_exact(d)
                    .map(|pt| pt.iter().map(|x| x * x).sum::<f64>().sqrt())
                    .fold(0.0, f64::max)
            })
            .collect()
    }

    /// The pieces overlapping `[lo, hi]`: `(index, x0, x1)` with the overlap.
    pub(crate) fn overlaps(
        &self,
        lo: f64,
        hi: f64,
    ) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
        self.overlaps_of(lo, hi, (self.piece_at(lo), self.piece_at(hi)))
    }

    /// [`Pw::overlaps`], given the pieces holding `lo` and `hi`.
    pub(crate) fn overlaps_of(
        &self,
        lo: f64,
        hi: f64,
        (first, last): (usize, usize),
    ) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
        (first..=last).filter_map(move |i| {
            let (x0, x1) = (lo.max(self.breaks[i]), hi.min(self.breaks[i + 1]));
            (x1 >= x0).then_some((i, x0, x1))
        })
    }

    /// The largest magnitude among the control points of piece `i`.
    pub(crate) fn piece_magnitude(&self, i: usize) -> f64 {
        self.piece(i).iter().fold(0.0, |m, x| m.max(x.abs()))
    }

    /// The control points (dimension `dim`) of the vector function on `[lo, hi]`, piece by
    /// piece, to `visit(points)`; stops when it returns false.
    pub(crate) fn for_each_restricted_points(
        &self,
        lo: f64,
        hi: f64,
        mut visit: impl FnMut(&[f64]) -> bool,
    ) {
        let d = self.dim;
        let first = self.piece_at(lo);
        let last = self.piece_at(hi);
        for i in first..=last {
            let (a, b) = (self.breaks[i], self.breaks[i + 1]);
            let (x0, x1) = (lo.max(a), hi.min(b));
            if x1 <= x0 {
                continue;
            }
            let mut pts = Buf::new();
            pts.extend_from_slice(self.piece(i));
            let h = b - a;
            let (r0, r1) = ((x0 - a) / h, (x1 - a) / h);
            if r1 < 1.0 {
                split_left_points(&mut pts, d, r1);
            }
            if r0 > 0.0 {
                split_right_points(&mut pts, d, if r1 < 1.0 { r0 / r1 } else { r0 });
            }
            if !visit(&pts) {
                return;
            }
        }
    }
}

/// [`split_left`] on points of dimension `d` stored point-major, all coordinates at once.
fn split_left_points(g: &mut [f64], d: usize, r: f64) {
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
fn split_right_points(g: &mut [f64], d: usize, r: f64) {
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
fn split_left(g: &mut [f64], r: f64) {
    let p = g.len() - 1;
    // After level k, g[k] is the k-th left coefficient; the tail is updated in place.
    for level in 1..=p {
        for j in (level..=p).rev() {
            g[j] = g[j - 1] + r * (g[j] - g[j - 1]);
        }
    }
}

/// Replaces the Bernstein coefficients on `[0, 1]` by those of the part on `[r, 1]`.
fn split_right(g: &mut [f64], r: f64) {
    let p = g.len() - 1;
    for level in 1..=p {
        for j in 0..=p - level {
            g[j] += r * (g[j + 1] - g[j]);
        }
    }
}

/// Value and first derivative of a piecewise Bézier function of dimension 1 or 2 in one
/// `O(degree)` pass per piece: Horner's scheme on `s/(1 − s)` (or on its inverse beyond the
/// middle, so that the ratio stays below 1) over control points premultiplied by their
/// binomial weights. The rounding is a few units of the largest control point times the degree.
#[derive(Debug, Clone)]
pub(crate) struct ValueSlope {
    deg: usize,
    /// 1 or 2.
    dim: usize,
    /// Per piece, the `deg + 1` points `C(deg, j) · c_j` (the second component 0 in dimension 1).
    value: Vec<[f64; 2]>,
    /// Per piece, the `deg` points `C(deg − 1, j) · deg/h · (c_{j+1} − c_j)` of the derivative.
    slope: Vec<[f64; 2]>,
}

impl ValueSlope {
    /// From a function and its [`Pw::derivative`]; `None` in dimensions other than 1 and 2.
    pub(crate) fn new(f: &Pw, deriv: &Pw) -> Option<Self> {
        let d = f.dim;
        if !(1..=2).contains(&d) || deriv.dim != d || deriv.breaks != f.breaks {
            return None;
        }
        // Premultiplied by the binomial weights, the second component 0 in dimension 1.
        let scaled = |g: &Pw| -> Vec<[f64; 2]> {
            (0..g.pieces())
                .flat_map(|i| {
                    let c = g.piece(i);
                    g.binoms.iter().enumerate().map(move |(j, bj)| {
                        [c[j * d] * bj, if d == 2 { c[j * d + 1] * bj } else { 0.0 }]
                    })
                })
                .collect()
        };
        let slope = if f.deg == 0 {
            Vec::new()
        } else {
            scaled(deriv)
        };
        Some(Self {
            deg: f.deg,
            dim: d,
            value: scaled(f),
            slope,
        })
    }

    /// Value and derivative (in the function's parameter) of piece `i` at its local parameter
    /// `s ∈ [0, 1]` (the pieces' breakpoints are the caller's, as for the [`Pw`] it came from).
    pub(crate) fn eval(&self, i: usize, s: f64) -> ([f64; 2], [f64; 2]) {
        let p = self.deg;
        let s = s.clamp(0.0, 1.0);
        let mirror = s > 0.5;
        let (t, base) = if mirror { (1.0 - s, s) } else { (s, 1.0 - s) };
        let ratio = t / base;
        // Σ c_j C(p, j) s^j (1 − s)^(p−j) = base^p Σ c_j C(p, j) ratio^(j or p − j).
        let horner = |cs: &[[f64; 2]]| {
            let step = |acc: [f64; 2], c: &[f64; 2]| [acc[0] * ratio + c[0], acc[1] * ratio + c[1]];
            if mirror {
                cs.iter().fold([0.0; 2], step)
            } else {
                cs.iter().rev().fold([0.0; 2], step)
            }
        };
        // A scalar skips the second component (a third fewer operations for the
        // curvature numerator and the weight).
        let scalar = |cs: &[[f64; 2]]| {
            let step = |acc: f64, c: &[f64; 2]| acc * ratio + c[0];
            let x = if mirror {
                cs.iter().fold(0.0, step)
            } else {
                cs.iter().rev().fold(0.0, step)
            };
            [x, 0.0]
        };
        let (values, slopes) = (
            &self.value[i * (p + 1)..(i + 1) * (p + 1)],
            &self.slope[i * p..(i + 1) * p],
        );
        let (v, g) = if self.dim == 1 {
            (scalar(values), scalar(slopes))
        } else {
            (horner(values), horner(slopes))
        };
        let pow = if p == 0 { 1.0 } else { base.powi(p as i32 - 1) };
        (
            [v[0] * pow * base, v[1] * pow * base],
            [g[0] * pow, g[1] * pow],
        )
    }
}

/// Value and derivatives up to order `k ≤ 3` of the Bézier piece with the `N` points `src`
/// (dimension 3) at local parameter `s`, the piece spanning `h`: the j-th derivative is
/// `p!/(p−j)!` times the j-th forward difference of the `j + 1` points of de Casteljau's
/// level `p − j`, over `hʲ` (`p = N − 1`).
#[inline(always)]
fn casteljau3<const N: usize>(src: &[f64], s: f64, h: f64, k: usize, out: &mut [f64]) {
    let p = N - 1;
    let mut w = [[0.0f64; 3]; N];
    for (j, pt) in w.iter_mut().enumerate() {
        *pt = [src[3 * j], src[3 * j + 1], src[3 * j + 2]];
    }
    let top = k.min(p);
    let diff = |w: &[[f64; 3]; N], j: usize| -> [f64; 3] {
        let mut d = [0.0; 3];
        for (c, v) in d.iter_mut().enumerate() {
            *v = match j {
                0 => w[0][c],
                1 => w[1][c] - w[0][c],
                2 => w[2][c] - 2.0 * w[1][c] + w[0][c],
                _ => w[3][c] - 3.0 * w[2][c] + 3.0 * w[1][c] - w[0][c],
            };
        }
        d
    };
    // d[j]: the difference for the j-th derivative, taken when its level is reached.
    let mut d = [[0.0f64; 3]; 4];
    if p <= top {
        d[p] = diff(&w, p);
    }
    for level in 1..=p {
        let left = p - level;
        for j in 0..=left {
            let next = w[j + 1];
            for (x, y) in w[j].iter_mut().zip(next) {
                *x += s * (y - *x);
            }
        }
        if left <= top {
            d[left] = diff(&w, left);
        }
    }
    out[..3].copy_from_slice(&d[0]);
    let mut fact = 1.0;
    for j in 1..=top {
        fact *= (p + 1 - j) as f64 / h;
        for c in 0..3 {
            out[3 * j + c] = fact * d[j][c];
        }
    }
    for v in out[3 * (top + 1)..3 * (k + 1)].iter_mut() {
        *v = 0.0;
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn spline() -> BSpline {
        let knots = vec![0., 0., 0., 0., 0.3, 0.5, 0.5, 0.8, 1., 1., 1., 1.];
        let coefs: Vec<f64> = (0..16).map(|i| ((i as f64) * 1.7).sin() * 2.0).collect();
        BSpline::new(3, knots, 2, coefs).unwrap()
    }

    /// Value and three derivatives of the pieces against de Boor's, at `n + 1` samples of
    /// [0, 1], each within `tol · (1 + |value|)`.
    fn assert_derivs_match(f: &BSpline, n: usize, tol: f64) {
        let pw = Pw::new(f);
        let len = 4 * f.dim();
        for i in 0..=n {
            let u = i as f64 / n as f64;
            let (mut a, mut b) = ([0.0; 12], [0.0; 12]);
            f.eval_derivs(u, 3, &mut a[..len]);
            pw.eval_derivs(u, 3, &mut b[..len]);
            for j in 0..len {
                assert!(
                    (a[j] - b[j]).abs() <= tol * (1.0 + a[j].abs()),
                    "degree {} u {u} j {j}: {a:?} {b:?}",
                    f.degree()
                );
            }
        }
    }

    proptest::proptest! {
        /// Value and slope of random splines (degrees 1–12, dimensions 1 and 2, subdivided)
        /// against de Boor's evaluation, anywhere in every piece.
        #[test]
        fn value_slope_matches_bspline(
            deg in 1usize..=12,
            dim in 1usize..=2,
            coefs in proptest::collection::vec(-3.0f64..3.0, 60),
            fine in 1usize..=8,
            xs in proptest::collection::vec(0.0f64..=1.0, 20),
        ) {
            let n = (coefs.len() / dim).min(deg + 1 + 5);
            let f = BSpline::clamped_uniform(deg, dim, coefs[..n * dim].to_vec()).unwrap();
            let pw = Pw::new(&f).subdivided(fine);
            let vs = ValueSlope::new(&pw, &pw.derivative()).unwrap();
            for &x in &xs {
                let i = pw.piece_at(x);
                let (a, b) = pw.piece_span(i);
                let (v, g) = vs.eval(i, (x - a) / (b - a));
                let mut want = [0.0; 4];
                f.eval_derivs(x, 1, &mut want[..2 * dim]);
                for c in 0..dim {
                    let (wv, wg) = (want[c], want[dim + c]);
                    proptest::prop_assert!((v[c] - wv).abs() <= 1e-11 * (1.0 + wv.abs()), "value {c} at {x}: {} vs {wv}", v[c]);
                    proptest::prop_assert!((g[c] - wg).abs() <= 1e-9 * (1.0 + wg.abs()), "slope {c} at {x}: {} vs {wg}", g[c]);
                }
            }
        }
    }

    #[test]
    fn derivatives_match_bspline() {
        assert_derivs_match(&spline(), 50, 1e-11);
    }

    #[test]
    fn derivatives_match_bspline_in_dimension_3() {
        // Every instance of the fixed-size path (degrees 1–7) and the general one (8).
        for p in 1..=8usize {
            let n = p + 4;
            let coefs: Vec<f64> = (0..3 * n)
                .map(|i| ((i as f64) * 0.77).cos() + 2.0)
                .collect();
            let f = BSpline::clamped_uniform(p, 3, coefs).unwrap();
            assert_derivs_match(&f, 40, 1e-9);
        }
    }

    #[test]
    fn restriction_matches_bspline() {
        let f = spline();
        let pw = Pw::new(&f);
        for (lo, hi) in [(0.1, 0.2), (0.25, 0.7), (0.0, 1.0), (0.5, 0.9), (0.3, 0.5)] {
            let mut got: Vec<(f64, f64, Vec<f64>)> = Vec::new();
            pw.for_each_restricted(&[1.0, -0.5], lo, hi, |x0, x1, c, _| {
                got.push((x0, x1, c.to_vec()));
                true
            });
            for (x0, x1, c) in got {
                // The Bernstein coefficients reproduce the function at the piece's ends.
                let g = |u: f64| {
                    let v = f.eval(u);
                    v[0] - 0.5 * v[1]
                };
                let n = c.len() - 1;
                assert!((c[0] - g(x0)).abs() < 1e-12);
                // Evaluate the right end from the left (c[n] is the left limit at x1).
                let eps = 1e-9;
                assert!((c[n] - g(x1 - eps)).abs() < 1e-7, "{lo} {hi} {x1}");
            }
        }
    }
}
