//! Bézier patches in flat arrays: the hot data of the subdivision solvers.
//!
//! A patch is one polynomial piece of `F(t, r)` in tensor Bernstein form on a box. Splitting is
//! de Casteljau along one direction; the sign facts the solvers need (all coefficients of one
//! sign, monotone in a direction, sign changes along an edge) are read off the coefficients.

use bspline::tensor::{restrict_bernstein, BezierPatch};
use numeric::rounding::UNIT_ROUNDOFF;
use numeric::Rect;

/// A tensor Bernstein polynomial on `[t0, t1] × [r0, r1]`, row-major (`c[i * (pr + 1) + j]`).
#[derive(Debug, Clone)]
pub(crate) struct Patch {
    pub(crate) t0: f64,
    pub(crate) t1: f64,
    pub(crate) r0: f64,
    pub(crate) r1: f64,
    pub(crate) pt: usize,
    pub(crate) pr: usize,
    pub(crate) c: Vec<f64>,
}

/// A trusted sign: `+1`, `-1`, or `0` when the value is within its rounding bound of zero.
pub(crate) fn tsign(x: f64, err: f64) -> i8 {
    if x > err {
        1
    } else if x < -err {
        -1
    } else {
        0
    }
}

/// Sign of all values if every one is trusted and they agree, else 0.
pub(crate) fn common_sign(vals: impl Iterator<Item = f64>, err: f64) -> i8 {
    let mut s = 0i8;
    for v in vals {
        let x = tsign(v, err);
        if x == 0 || (s != 0 && x != s) {
            return 0;
        }
        s = x;
    }
    s
}

/// Sign variations of a sequence. A value within its rounding bound of zero counts as
/// positive: patches that share a corner or edge then agree on its sign (their values differ
/// only by rounding), so a zero exactly on a corner is seen once, just beside it.
pub(crate) fn variations(vals: impl Iterator<Item = f64>, err: f64) -> usize {
    let mut last = 0i8;
    let mut n = 0;
    for v in vals {
        let s = if v < -err { -1 } else { 1 };
        if last != 0 && s != last {
            n += 1;
        }
        last = s;
    }
    n
}

/// The sign convention of [`variations`] for one value.
pub(crate) fn vsign(v: f64, err: f64) -> f64 {
    if v < -err {
        -1.0
    } else {
        1.0
    }
}

impl Patch {
    pub(crate) fn from_bezier(b: &BezierPatch) -> Self {
        Self {
            t0: b.t0,
            t1: b.t1,
            r0: b.r0,
            r1: b.r1,
            pt: b.deg_t,
            pr: b.deg_r,
            c: b.coefs.clone(),
        }
    }

    pub(crate) fn w(&self) -> usize {
        self.pr + 1
    }

    pub(crate) fn max_abs(&self) -> f64 {
        self.c.iter().fold(0.0, |m, x| m.max(x.abs()))
    }

    /// Splits at the local parameter `s` of `t` (the split value is computed once, so both
    /// children share it exactly).
    pub(crate) fn split_t(&self, s: f64) -> (Patch, Patch) {
        let (p, w) = (self.pt, self.w());
        let tm = self.t0 + s * (self.t1 - self.t0);
        let mut lo = self.c.clone();
        let mut hi = self.c.clone();
        // Column-wise de Casteljau: `hi` is worked in place; `lo` collects the left edges.
        for level in 1..=p {
            for k in 0..=p - level {
                for j in 0..w {
                    hi[k * w + j] = (1.0 - s) * hi[k * w + j] + s * hi[(k + 1) * w + j];
                }
            }
            lo[level * w..(level + 1) * w].copy_from_slice(&hi[..w]);
        }
        let a = Patch {
            t1: tm,
            c: lo,
            ..self.clone_box()
        };
        let b = Patch {
            t0: tm,
            c: hi,
            ..self.clone_box()
        };
        (a, b)
    }

    /// Splits at the local parameter `s` of `r`.
    pub(crate) fn split_r(&self, s: f64) -> (Patch, Patch) {
        let (q, w) = (self.pr, self.w());
        let rm = self.r0 + s * (self.r1 - self.r0);
        let mut lo = self.c.clone();
        let mut hi = self.c.clone();
        for i in 0..=self.pt {
            let row = &mut hi[i * w..(i + 1) * w];
            for level in 1..=q {
                for k in 0..=q - level {
                    row[k] = (1.0 - s) * row[k] + s * row[k + 1];
                }
                lo[i * w + level] = row[0];
            }
        }
        let a = Patch {
            r1: rm,
            c: lo,
            ..self.clone_box()
        };
        let b = Patch {
            r0: rm,
            c: hi,
            ..self.clone_box()
        };
        (a, b)
    }

    fn clone_box(&self) -> Patch {
        Patch {
            c: Vec::new(),
            ..*self
        }
    }

    /// Differences of coefficients in `t` (a positive multiple of `∂F/∂t`'s coefficients).
    pub(crate) fn dt_coefs(&self) -> impl Iterator<Item = f64> + '_ {
        let w = self.w();
        (0..self.pt * w).map(move |k| self.c[k + w] - self.c[k])
    }

    /// Differences of coefficients in `r`.
    pub(crate) fn dr_coefs(&self) -> impl Iterator<Item = f64> + '_ {
        let w = self.w();
        (0..=self.pt)
            .flat_map(move |i| (0..self.pr).map(move |j| self.c[i * w + j + 1] - self.c[i * w + j]))
    }

    /// The patch's box.
    pub(crate) fn rect(&self) -> Rect {
        Rect::of((self.t0, self.t1), (self.r0, self.r1))
    }

    /// The same polynomial on the part of the patch's box inside `bx` (`None` when they do
    /// not overlap), by de Casteljau subdivision in place.
    pub(crate) fn restrict(&self, bx: Rect) -> Option<Patch> {
        let (a, b) = (bx.t.lo.max(self.t0), bx.t.hi.min(self.t1));
        let (c, d) = (bx.r.lo.max(self.r0), bx.r.hi.min(self.r1));
        if !(a <= b && c <= d) {
            return None;
        }
        let local = |x: f64, lo: f64, hi: f64| if hi > lo { (x - lo) / (hi - lo) } else { 0.0 };
        let mut coefs = self.c.clone();
        restrict_bernstein(
            &mut coefs,
            [self.pt, self.pr],
            [local(a, self.t0, self.t1), local(b, self.t0, self.t1)],
            [local(c, self.r0, self.r1), local(d, self.r0, self.r1)],
        );
        Some(Patch {
            t0: a,
            t1: b,
            r0: c,
            r1: d,
            pt: self.pt,
            pr: self.pr,
            c: coefs,
        })
    }

    /// The trusted sign of the partial derivative in `t` (`k = 0`) or `r` (`k = 1`) on the
    /// part of the patch's box inside `bx`: `+1` or `−1` when all its Bernstein coefficients
    /// there have that sign beyond their rounding bound, else 0. `err` bounds the error of
    /// this patch's coefficients. `None` when the boxes do not overlap.
    pub(crate) fn partial_sign(&self, k: usize, bx: Rect, err: f64) -> Option<i8> {
        let deg = if k == 0 { self.pt } else { self.pr };
        if deg == 0 {
            // Constant in that direction: the partial vanishes.
            return self.restrict(bx).map(|_| 0);
        }
        // The hodograph (coefficient differences: a positive multiple of the partial).
        let d = Patch {
            pt: if k == 0 { self.pt - 1 } else { self.pt },
            pr: if k == 0 { self.pr } else { self.pr - 1 },
            c: if k == 0 {
                self.dt_coefs().collect()
            } else {
                self.dr_coefs().collect()
            },
            ..self.clone_box()
        };
        let d = d.restrict(bx)?;
        // Each difference carries twice the coefficients' error; the (at most four) splits
        // of `restrict` add rounding of the order of the degree per split.
        let e = 2.0 * err + 8.0 * (d.pt + d.pr + 2) as f64 * UNIT_ROUNDOFF * d.max_abs();
        Some(common_sign(d.c.iter().copied(), e))
    }

    /// Coefficients along edge `e`: 0 bottom (`r = r0`, along t), 1 right (`t = t1`, along r),
    /// 2 top (`r = r1`), 3 left (`t = t0`).
    pub(crate) fn edge(&self, e: usize) -> Vec<f64> {
        let w = self.w();
        match e {
            0 => (0..=self.pt).map(|i| self.c[i * w]).collect(),
            1 => self.c[self.pt * w..].to_vec(),
            2 => (0..=self.pt).map(|i| self.c[i * w + self.pr]).collect(),
            _ => self.c[..w].to_vec(),
        }
    }

    /// Value and the partial `k` of [`Patch::eval_grad`] (1: in `t`, 2: in `r`) at global
    /// `(t, r)`: what a bracketed solve along a line of the patch reads.
    #[inline]
    pub(crate) fn value_and_partial(&self, [t, r]: [f64; 2], k: usize) -> (f64, f64) {
        let g = self.eval_grad(t, r);
        (g[0], g[k])
    }

    /// Value and first partials (with respect to the global `t`, `r`) at global `(t, r)`.
    pub(crate) fn eval_grad(&self, t: f64, r: f64) -> [f64; 3] {
        let (ht, hr) = (self.t1 - self.t0, self.r1 - self.r0);
        let u = (t - self.t0) / ht;
        let v = (r - self.r0) / hr;
        // Sized for F3 of two cubics or of one rational cubic (degrees ≤ 11): zeroing a larger
        // buffer on every call showed up in profiles.
        let mut buf = [0.0f64; 48];
        let mut heap = Vec::new();
        let need = 2 * (self.pt + self.pr + 2);
        let all: &mut [f64] = if need <= buf.len() {
            &mut buf[..need]
        } else {
            heap.resize(need, 0.0);
            &mut heap
        };
        let (bu, rest) = all.split_at_mut(self.pt + 1);
        let (du, rest) = rest.split_at_mut(self.pt + 1);
        let (bv, dv) = rest.split_at_mut(self.pr + 1);
        bernstein(u, bu, du);
        bernstein(v, bv, dv);
        let (mut f, mut ft, mut fr) = (0.0, 0.0, 0.0);
        for ((row, &b), &d) in self.c.chunks_exact(self.w()).zip(&*bu).zip(&*du) {
            let (mut s, mut sd) = (0.0, 0.0);
            for ((&c, &x), &dx) in row.iter().zip(&*bv).zip(&*dv) {
                s += c * x;
                sd += c * dx;
            }
            f += b * s;
            ft += d * s;
            fr += b * sd;
        }
        [f, ft / ht, fr / hr]
    }

    /// Value at global `(t, r)`.
    pub(crate) fn eval(&self, t: f64, r: f64) -> f64 {
        self.eval_grad(t, r)[0]
    }

    /// Divides by `(t − r)` on a square patch on the diagonal (`[a, b]²`, equal degrees) when
    /// the patch is divisible to within `rel` of its scale; `None` otherwise.
    ///
    /// With local `u, v` the relation `F = (u − v) Q` reads, coefficient by coefficient,
    /// `n² F_kl = k (n − l) Q_(k−1)l − l (n − k) Q_k(l−1)`. It couples one anti-diagonal
    /// `k + l = s` of `F` (m + 1 values) with one anti-diagonal of `Q` (m unknowns): a
    /// bidiagonal system with one equation to spare. Solving it from one end only (a plain
    /// recurrence) multiplies rounding errors by up to `(n − 1)²` per step, which made
    /// high-degree cells look indivisible. Here each anti-diagonal is solved from both ends
    /// toward its middle, where every step has a factor ≤ 1 (as in stable polynomial
    /// deflation), and the spare equation in the middle measures the divisibility.
    pub(crate) fn divide_diagonal(&self, rel: f64) -> Option<Patch> {
        let n = self.pt;
        if n == 0 || self.pr != n || self.t0 != self.r0 || self.t1 != self.r1 {
            return None;
        }
        let w = n + 1;
        let f = |k: usize, l: usize| self.c[k * w + l];
        let nn = (n * n) as f64;
        let mut q = vec![0.0; n * n];
        let scale = self.max_abs().max(f64::MIN_POSITIVE);
        let mut resid: f64 = 0.0;
        for s in 0..=2 * n {
            let (kmin, kmax) = (s.saturating_sub(n), s.min(n));
            // Equation k: n² F(k, s−k) = a(k) Q(k−1, s−k) − b(k) Q(k, s−1−k), with a(kmin) =
            // b(kmax) = 0; the unknowns are Q(k, s−1−k) for kmin ≤ k < kmax.
            let a = |k: usize| (k * (n + k - s)) as f64;
            let b = |k: usize| ((s - k) * (n - k)) as f64;
            if kmin == kmax {
                // A corner of F (s = 0 or 2n): no unknown, F must vanish there.
                resid = resid.max(nn * f(kmin, s - kmin).abs());
                continue;
            }
            // Forward while a(k) ≤ b(k) (then |a/b| ≤ 1), backward from the other end.
            let mut mid = kmin;
            while mid < kmax && a(mid) <= b(mid) {
                mid += 1;
            }
            // Equations kmin..mid−1 give Q(kmin..mid−1) forward; equations kmax..mid+1 give
            // Q(kmax−1..mid) backward; equation `mid` is the spare one.
            let mut prev = 0.0;
            for k in kmin..mid {
                let qk = (a(k) * prev - nn * f(k, s - k)) / b(k);
                q[k * n + (s - 1 - k)] = qk;
                prev = qk;
            }
            let mut next = 0.0;
            for k in (mid + 1..=kmax).rev() {
                let qk1 = (nn * f(k, s - k) + b(k) * next) / a(k);
                q[(k - 1) * n + (s - k)] = qk1;
                next = qk1;
            }
            let lhs = nn * f(mid, s - mid);
            let left = if mid > kmin {
                q[(mid - 1) * n + (s - mid)]
            } else {
                0.0
            };
            let right = if mid < kmax {
                q[mid * n + (s - 1 - mid)]
            } else {
                0.0
            };
            resid = resid.max((lhs - a(mid) * left + b(mid) * right).abs());
        }
        if resid > rel * nn * scale {
            return None;
        }
        // F = (t − r) G with t − r = h (u − v): G = Q / h.
        let h = self.t1 - self.t0;
        q.iter_mut().for_each(|x| *x /= h);
        Some(Patch {
            pt: n - 1,
            pr: n - 1,
            c: q,
            ..self.clone_box()
        })
    }
}

/// Degrees up to which [`bernstein`] reads binomial coefficients from a table.
const BINOM_MAX: usize = 40;

/// Binomial coefficients `C(n, i)` for `n ≤ BINOM_MAX` (exact: all below 2⁵³).
static BINOM: [[f64; BINOM_MAX + 1]; BINOM_MAX + 1] = binomials();

const fn binomials() -> [[f64; BINOM_MAX + 1]; BINOM_MAX + 1] {
    let mut t = [[0.0; BINOM_MAX + 1]; BINOM_MAX + 1];
    let mut n = 0;
    while n <= BINOM_MAX {
        t[n][0] = 1.0;
        let mut i = 1;
        while i <= n {
            t[n][i] = t[n - 1][i - 1] + if i < n { t[n - 1][i] } else { 0.0 };
            i += 1;
        }
        n += 1;
    }
    t
}

/// `C(n, i)`: from the table, or by the product formula beyond it.
fn binom(n: usize, i: usize) -> f64 {
    if n <= BINOM_MAX {
        BINOM[n][i]
    } else {
        (0..i).fold(1.0, |c, k| c * (n - k) as f64 / (k + 1) as f64)
    }
}

/// Bernstein basis values `b` and derivatives `d` (with respect to the local parameter) of
/// degree `b.len() − 1` at `u`: the basis of one degree less as products of powers (every
/// term positive, so no cancellation), then one de Casteljau step up to this degree, whose
/// differences are the derivatives. Filled in place (returning arrays by value showed up as
/// copies in profiles).
pub(crate) fn bernstein(u: f64, b: &mut [f64], d: &mut [f64]) {
    let n = b.len() - 1;
    let d = &mut d[..=n];
    if n == 0 {
        b[0] = 1.0;
        d[0] = 0.0;
        return;
    }
    let v = 1.0 - u;
    // b[i] = C(n − 1, i) u^i v^(n−1−i) for i < n: first the powers of v, from the right.
    let lower = &mut b[..n];
    let mut pv = 1.0;
    for x in lower.iter_mut().rev() {
        *x = pv;
        pv *= v;
    }
    let mut pu = 1.0;
    for (i, x) in lower.iter_mut().enumerate() {
        *x *= binom(n - 1, i) * pu;
        pu *= u;
    }
    // B^n_i = v B^{n−1}_i + u B^{n−1}_{i−1}; (B^n_i)' = n (B^{n−1}_{i−1} − B^{n−1}_i).
    let nf = n as f64;
    let mut prev = 0.0;
    for (x, dx) in b[..n].iter_mut().zip(d.iter_mut()) {
        let cur = *x;
        *x = v * cur + u * prev;
        *dx = nf * (prev - cur);
        prev = cur;
    }
    b[n] = u * prev;
    d[n] = nf * prev;
}

#[cfg(test)]
mod tests;
