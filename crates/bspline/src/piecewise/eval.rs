//! Evaluation of a piecewise Bézier function: value and derivatives by de Casteljau's
//! algorithm (with fixed-size instances for homogeneous planar curves, whose jets are most of
//! the cost of a run), value and slope by Horner's scheme, and the bounds on their rounding.

use super::Piecewise;
use crate::rounding;

impl Piecewise {
    /// Value and derivatives up to order `k ≤ 3` at `u` (clamped into the domain), in any
    /// dimension: `out[j·dim + c]` is the j-th derivative of component `c`. Derivatives above the degree
    /// are zero. De Casteljau: the j-th derivative is `p!/(p−j)! Δʲ` of the points of level
    /// `p − j`, over `hʲ`.
    #[inline]
    pub fn eval_derivs(&self, u: f64, k: usize, out: &mut [f64]) {
        if self.dim == 3 && self.degree <= 7 && k <= 3 {
            self.eval_derivs3(u, k, out)
        } else {
            self.eval_derivs_any(u, k, out)
        }
    }

    /// The piece `i` holding `u` (clamped to the domain), the local parameter `s` in `[0, 1]`
    /// there and the piece's length `h`.
    #[inline]
    fn local(&self, u: f64) -> (usize, f64, f64) {
        let i = self.piece_at(u);
        let (a, b) = (self.breaks[i], self.breaks[i + 1]);
        let h = b - a;
        let s =
            ((u.clamp(self.breaks[0], self.breaks[self.breaks.len() - 1]) - a) / h).clamp(0.0, 1.0);
        (i, s, h)
    }

    /// [`Piecewise::eval_derivs`] for any dimension and degree (kept out of line: the planar
    /// curves' jets take the fixed-size path).
    #[inline(never)]
    fn eval_derivs_any(&self, u: f64, k: usize, out: &mut [f64]) {
        let (p, d) = (self.degree, self.dim);
        let (i, s, h) = self.local(u);
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
        // Levels p, p−1, p−2, p−3 hold 1, 2, 3, 4 points: level j at `j·4·d` (on the stack
        // up to dimension 3).
        let mut lv_stack = [0.0f64; 48];
        let mut lv_heap = Vec::new();
        let lv: &mut [f64] = if 16 * d <= lv_stack.len() {
            &mut lv_stack[..16 * d]
        } else {
            lv_heap.resize(16 * d, 0.0);
            &mut lv_heap
        };
        let keep = |lv: &mut [f64], w: &[f64], pts: usize| {
            // pts = number of points left (p − level + 1); keep the last four levels.
            if pts <= 4 {
                let at = (pts - 1) * 4 * d;
                lv[at..at + pts * d].copy_from_slice(&w[..pts * d]);
            }
        };
        keep(lv, w, p + 1);
        // (As `(1 − s) x + s y`: exact at both ends, where `x + s(y − x)` cancels at s = 1,
        // as with weights 1e82 and 1 side by side.)
        let t = 1.0 - s;
        for level in 1..=p {
            for j in 0..=p - level {
                for c in 0..d {
                    w[j * d + c] = w[j * d + c] * t + w[(j + 1) * d + c] * s;
                }
            }
            keep(lv, w, p - level + 1);
        }
        out[..d].copy_from_slice(&lv[..d]);
        let mut fact = 1.0;
        for j in 1..=k.min(p) {
            fact *= (p + 1 - j) as f64 / h;
            // j-th forward difference of the j + 1 points of level p − j.
            let pts = &lv[j * 4 * d..(j + 1) * 4 * d];
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

    /// [`Piecewise::eval_derivs`] for points of dimension 3 and degree ≤ 7 (homogeneous planar
    /// curves): de Casteljau on fixed-size arrays, one instance per degree so that the
    /// loops unroll (jets are most of the cost of a spline's run).
    #[inline]
    fn eval_derivs3(&self, u: f64, k: usize, out: &mut [f64]) {
        let (i, s, h) = self.local(u);
        let src = self.piece(i);
        match self.degree {
            1 => casteljau3::<2>(src, s, h, k, out),
            2 => casteljau3::<3>(src, s, h, k, out),
            3 => casteljau3::<4>(src, s, h, k, out),
            4 => casteljau3::<5>(src, s, h, k, out),
            5 => casteljau3::<6>(src, s, h, k, out),
            6 => casteljau3::<7>(src, s, h, k, out),
            _ => casteljau3::<8>(src, s, h, k, out),
        }
    }

    /// The value at `u` (clamped into the domain), into `out` (`dim` values).
    pub fn eval(&self, u: f64, out: &mut [f64]) {
        self.eval_derivs(u, 0, out)
    }

    /// A bound on the error of the `order`-th derivative as [`Piecewise::eval_derivs`] computes
    /// it anywhere in piece `i`, against the exact function: the pieces' own error and the
    /// rounding of de Casteljau's levels, through the forward difference (whose weights sum to
    /// `2^order`) and the factor `p!/(p − order)!/h^order`.
    pub fn eval_error(&self, i: usize, order: usize) -> f64 {
        (0..self.dim)
            .map(|c| self.eval_error_of(i, order, c))
            .fold(0.0, f64::max)
    }

    /// [`Piecewise::eval_error`] in coordinate `c`.
    pub fn eval_error_of(&self, i: usize, order: usize, c: usize) -> f64 {
        let p = self.degree;
        if order > p {
            return 0.0;
        }
        let e = self.errors(i)[c];
        let m = self.coordinate_magnitude(i, c) + e;
        let level = e + rounding::casteljau(p, m);
        if order == 0 {
            return level;
        }
        let (a, b) = self.piece_span(i);
        let h = b - a;
        let fact: f64 = (0..order).map(|j| (p - j) as f64 / h).product();
        let spread = (1u64 << order.min(62)) as f64;
        fact * spread
            * (level + numeric::rounding::gamma(order + 2) * m)
            * (1.0 + numeric::rounding::gamma(2 * order + 2))
    }
}

/// Value and first derivative of a piecewise Bézier function of dimension 1 or 2 in one
/// `O(degree)` pass per piece: Horner's scheme on `s/(1 − s)` (or on its inverse beyond the
/// middle, so that the ratio stays below 1) over control points premultiplied by their
/// binomial weights. Its rounding is bounded by [`rounding::horner`] (a few units of the
/// largest control point per degree) beside the function's own error.
#[derive(Debug, Clone)]
pub struct ValueSlope {
    degree: usize,
    /// 1 or 2.
    dim: usize,
    /// Per piece, the `degree + 1` points `C(degree, j) · c_j` (the second component 0 in dimension 1).
    value: Vec<[f64; 2]>,
    /// Per piece, the `degree` points `C(degree − 1, j) · degree/h · (c_{j+1} − c_j)` of the derivative.
    slope: Vec<[f64; 2]>,
}

impl ValueSlope {
    /// From a function and its [`Piecewise::derivative`]; `None` in dimensions other than 1 and 2.
    pub fn new(f: &Piecewise, deriv: &Piecewise) -> Option<Self> {
        let d = f.dim;
        if !(1..=2).contains(&d) || deriv.dim != d || deriv.breaks != f.breaks {
            return None;
        }
        // Premultiplied by the binomial weights, the second component 0 in dimension 1.
        let scaled = |g: &Piecewise| -> Vec<[f64; 2]> {
            (0..g.pieces())
                .flat_map(|i| {
                    let c = g.piece(i);
                    g.binoms.iter().enumerate().map(move |(j, bj)| {
                        [c[j * d] * bj, if d == 2 { c[j * d + 1] * bj } else { 0.0 }]
                    })
                })
                .collect()
        };
        let slope = if f.degree == 0 {
            Vec::new()
        } else {
            scaled(deriv)
        };
        Some(Self {
            degree: f.degree,
            dim: d,
            value: scaled(f),
            slope,
        })
    }

    /// Value and derivative (in the function's parameter) of piece `i` at its local parameter
    /// `s ∈ [0, 1]` (the pieces' breakpoints are the caller's, as for the [`Piecewise`] it came from).
    pub fn eval(&self, i: usize, s: f64) -> ([f64; 2], [f64; 2]) {
        let p = self.degree;
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
    // (Each step as `(1 − s) x + s y`, exact at both ends: see `Piecewise::eval_derivs_any`.)
    let t = 1.0 - s;
    for level in 1..=p {
        let left = p - level;
        for j in 0..=left {
            let next = w[j + 1];
            for (x, y) in w[j].iter_mut().zip(next) {
                *x = *x * t + y * s;
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
