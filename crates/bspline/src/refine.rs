//! Knot insertion and everything built on it: refinement, restriction to a sub-interval,
//! splitting, clamping a periodic curve, and extraction of Bézier pieces.

use crate::error::{check_finite, Error, Result};
use crate::knots::{find_span, multiplicity};
use crate::spline::BSpline;

impl BSpline {
    /// Inserts every value of `new_knots` (sorted or not, repeats allowed) into the knot vector.
    /// The function is unchanged; only its representation grows (The NURBS Book, A5.4).
    ///
    /// ```
    /// use bspline::BSpline;
    /// let f = BSpline::clamped_uniform(3, 2, vec![0., 0., 1., 2., 3., 1., 4., 0., 5., 2.]).unwrap();
    /// let g = f.refine(&[0.3, 0.3, 0.7]).unwrap();
    /// assert_eq!(g.n_ctrl(), f.n_ctrl() + 3);
    /// let (p, q) = (f.eval(0.42), g.eval(0.42));
    /// assert!((p[0] - q[0]).abs() < 1e-14 && (p[1] - q[1]).abs() < 1e-14);
    /// // A knot may not repeat more often than the degree inside the domain.
    /// assert!(f.refine(&[0.5; 4]).is_err());
    /// ```
    pub fn refine(&self, new_knots: &[f64]) -> Result<BSpline> {
        check_finite("new knots", new_knots)?;
        let (lo, hi) = self.domain();
        let mut x: Vec<f64> = new_knots.to_vec();
        x.sort_by(f64::total_cmp);
        if let (Some(&a), Some(&b)) = (x.first(), x.last()) {
            if a < lo || b > hi {
                return Err(Error::OutOfDomain {
                    a,
                    b,
                    domain: (lo, hi),
                });
            }
        } else {
            return Ok(self.clone());
        }
        // No value may end up more often than the degree allows (p inside, p + 1 at the ends).
        let p = self.degree();
        for run in x.chunk_by(|a, b| a == b) {
            let v = run[0];
            let max = if v == lo || v == hi { p + 1 } else { p };
            let total = multiplicity(self.knots(), v) + run.len();
            if total > max {
                return Err(Error::KnotMultiplicity {
                    value: v,
                    multiplicity: total,
                    max,
                });
            }
        }
        Ok(self.refine_sorted(&x))
    }

    /// Refinement by a sorted list of values inside the domain (no checks).
    pub(crate) fn refine_sorted(&self, x: &[f64]) -> BSpline {
        self.refine_tracked(x, None)
    }

    /// [`BSpline::refine_sorted`] carrying a bound on each coefficient's error along (`errors`:
    /// one per coefficient, as `coefs`, on entry and for the result on return): every new point
    /// is a convex combination of two old ones, whose errors it combines alike, plus the
    /// rounding of the step ([`crate::rounding::insertion`]), coordinate by coordinate.
    pub(crate) fn refine_tracked(&self, x: &[f64], errors: Option<&mut Vec<f64>>) -> BSpline {
        if x.is_empty() {
            return self.clone();
        }
        let (p, d, n) = (self.degree(), self.dim(), self.n_ctrl());
        let u = self.knots();
        let pw = self.coefs();
        let r = x.len();
        let a = find_span(p, n, u, x[0]);
        let b = find_span(p, n, u, x[r - 1]) + 1;
        let mut ub = vec![0.0; u.len() + r];
        let mut q = vec![0.0; (n + r) * d];
        q[..(a + 1 - p) * d].copy_from_slice(&pw[..(a + 1 - p) * d]);
        for j in b - 1..n {
            q[(j + r) * d..(j + r + 1) * d].copy_from_slice(&pw[j * d..(j + 1) * d]);
        }
        // The errors move with their coefficients (an empty vector when not tracked).
        let old: &[f64] = errors.as_deref().map_or(&[], |v| v.as_slice());
        let tracked = !old.is_empty();
        let mut e = vec![0.0; if tracked { (n + r) * d } else { 0 }];
        if tracked {
            e[..(a + 1 - p) * d].copy_from_slice(&old[..(a + 1 - p) * d]);
            e[(b - 1 + r) * d..(n + r) * d].copy_from_slice(&old[(b - 1) * d..n * d]);
        }
        ub[..=a].copy_from_slice(&u[..=a]);
        ub[b + p + r..].copy_from_slice(&u[b + p..]);
        let mut i = b + p - 1;
        let mut k = b + p + r - 1;
        for j in (0..r).rev() {
            while x[j] <= u[i] && i > a {
                q[(k - p - 1) * d..(k - p) * d].copy_from_slice(&pw[(i - p - 1) * d..(i - p) * d]);
                if tracked {
                    e[(k - p - 1) * d..(k - p) * d]
                        .copy_from_slice(&old[(i - p - 1) * d..(i - p) * d]);
                }
                ub[k] = u[i];
                k -= 1;
                i -= 1;
            }
            q.copy_within((k - p) * d..(k - p + 1) * d, (k - p - 1) * d);
            if tracked {
                e.copy_within((k - p) * d..(k - p + 1) * d, (k - p - 1) * d);
            }
            for l in 1..=p {
                let ind = k - p + l;
                let alpha = ub[k + l] - x[j];
                if alpha == 0.0 {
                    q.copy_within(ind * d..(ind + 1) * d, (ind - 1) * d);
                    if tracked {
                        e.copy_within(ind * d..(ind + 1) * d, (ind - 1) * d);
                    }
                } else {
                    let alpha = alpha / (ub[k + l] - u[i + l - p]);
                    for c in 0..d {
                        let (lo, hi) = ((ind - 1) * d + c, ind * d + c);
                        if tracked {
                            let worst = e[lo].max(e[hi]);
                            let m = q[lo].abs().max(q[hi].abs()) + worst;
                            e[lo] = worst + crate::rounding::insertion(m);
                        }
                        q[lo] = alpha * q[lo] + (1.0 - alpha) * q[hi];
                    }
                }
            }
            ub[k] = x[j];
            k = k.wrapping_sub(1);
        }
        if let Some(out) = errors {
            *out = e;
        }
        BSpline::from_raw(p, d, ub, q)
    }

    /// Inserts the knot `u` `times` times (capped so that no multiplicity exceeds the degree
    /// inside the domain).
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<BSpline> {
        let have = multiplicity(self.knots(), u);
        let times = times.min(self.degree().saturating_sub(have));
        self.refine(&vec![u; times])
    }

    /// The same function restricted to `[a, b]`, as a clamped B-spline on that interval.
    ///
    /// ```
    /// use bspline::BSpline;
    /// let f = BSpline::periodic(3, 1, vec![0., 1., 3., 2., 5.]).unwrap();
    /// let g = f.restrict(0.5, 2.25).unwrap();
    /// assert_eq!(g.domain(), (0.5, 2.25));
    /// assert!((g.eval_scalar(1.7) - f.eval_scalar(1.7)).abs() < 1e-14);
    /// ```
    pub fn restrict(&self, a: f64, b: f64) -> Result<BSpline> {
        self.restrict_tracked(a, b, None)
    }

    /// [`BSpline::restrict`] for coefficients in error by up to `err` (`Some`), which returns
    /// the bound for the result's (see [`BSpline::refine_tracked`]) in its place.
    pub(crate) fn restrict_tracked(
        &self,
        a: f64,
        b: f64,
        err: Option<&mut f64>,
    ) -> Result<BSpline> {
        let (lo, hi) = self.domain();
        if !(a.is_finite() && b.is_finite() && lo <= a && a < b && b <= hi) {
            return Err(Error::OutOfDomain {
                a,
                b,
                domain: (lo, hi),
            });
        }
        let p = self.degree();
        let mut x = vec![a; (p + 1).saturating_sub(multiplicity(self.knots(), a))];
        x.extend(std::iter::repeat_n(
            b,
            (p + 1).saturating_sub(multiplicity(self.knots(), b)),
        ));
        let mut errors = err.as_ref().map(|&&mut e| vec![e; self.coefs().len()]);
        let r = self.refine_tracked(&x, errors.as_mut());
        let (deg, d, knots, coefs) = r.into_parts();
        // The last p+1 copies of `a` and the first p+1 copies of `b` bound the sub-spline.
        let ia = knots.partition_point(|&k| k <= a) - (p + 1);
        let ib = knots.partition_point(|&k| k < b) + p;
        if let (Some(out), Some(errors)) = (err, errors) {
            *out = errors[ia * d..(ib - p) * d]
                .iter()
                .fold(0.0, |m: f64, &e| m.max(e));
        }
        let new_knots = knots[ia..=ib].to_vec();
        let new_coefs = coefs[ia * d..(ib - p) * d].to_vec();
        Ok(BSpline::from_raw(deg, d, new_knots, new_coefs))
    }

    /// Splits the function at `u` (strictly inside the domain) into two clamped B-splines.
    ///
    /// ```
    /// use bspline::BSpline;
    /// let f = BSpline::bezier(1, vec![1., -2., 3.]).unwrap();
    /// let (l, r) = f.split_at(0.25).unwrap();
    /// assert_eq!((l.domain(), r.domain()), ((0.0, 0.25), (0.25, 1.0)));
    /// assert!((l.eval_scalar(0.1) - f.eval_scalar(0.1)).abs() < 1e-15);
    /// ```
    pub fn split_at(&self, u: f64) -> Result<(BSpline, BSpline)> {
        let (lo, hi) = self.domain();
        if !(u > lo && u < hi) {
            return Err(Error::OutOfDomain {
                a: u,
                b: u,
                domain: (lo, hi),
            });
        }
        Ok((self.restrict(lo, u)?, self.restrict(u, hi)?))
    }

    /// The equivalent clamped B-spline on the same domain (a no-op for clamped input).
    pub fn clamped(&self) -> BSpline {
        if self.is_clamped() && self.knots().len() == self.n_ctrl() + self.degree() + 1 {
            return self.clone();
        }
        let (a, b) = self.domain();
        // The domain of a valid spline is non-empty, so restriction cannot fail.
        self.restrict(a, b).unwrap_or_else(|_| self.clone())
    }

    /// The Bézier pieces of the function, one per non-empty knot span.
    pub fn bezier_pieces(&self) -> Vec<Bezier> {
        let bps = self.breakpoints();
        self.bezier_pieces_at(&bps)
    }

    /// Bézier pieces on the intervals between consecutive `breaks` (sorted, ends equal to the
    /// domain, including at least every interior knot of the function).
    pub(crate) fn bezier_pieces_at(&self, breaks: &[f64]) -> Vec<Bezier> {
        let f = self.clamped();
        let p = f.degree();
        let d = f.dim();
        let mut x = Vec::new();
        for &bk in &breaks[1..breaks.len() - 1] {
            let have = multiplicity(f.knots(), bk);
            x.extend(std::iter::repeat_n(bk, p.saturating_sub(have)));
        }
        let r = f.refine_sorted(&x);
        // With every break of multiplicity ≥ p, the p + 1 basis functions alive on a span are
        // the Bernstein polynomials of that span (any multiplicity, degree 0 included).
        breaks
            .windows(2)
            .map(|w| {
                let span = find_span(p, r.n_ctrl(), r.knots(), 0.5 * (w[0] + w[1]));
                Bezier {
                    a: w[0],
                    b: w[1],
                    degree: p,
                    dim: d,
                    coefs: r.coefs()[(span - p) * d..(span + 1) * d].to_vec(),
                }
            })
            .collect()
    }
}

/// One polynomial piece in Bernstein form on `[a, b]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Bezier {
    /// Interval start.
    pub a: f64,
    /// Interval end.
    pub b: f64,
    /// Degree.
    pub degree: usize,
    /// Dimension of the control points.
    pub dim: usize,
    /// `degree + 1` control points, point-major.
    pub coefs: Vec<f64>,
}

impl Bezier {
    /// Evaluates the blossom at the parameters `args` (global parameters, `degree` of them):
    /// de Casteljau with a different parameter at each level. With all arguments equal to `u`
    /// this is the value at `u`; with knots as arguments it gives B-spline coefficients.
    pub fn blossom(&self, args: &[f64], out: &mut [f64]) {
        let d = self.dim;
        let (a, b) = (self.a, self.b);
        // An argument at an end of the interval acts by index alone (de Casteljau's step with
        // s = 0 keeps the points and drops the last, with s = 1 drops the first), and these
        // steps commute with the others exactly: applied first, they leave a shorter de
        // Casteljau on the other arguments, with the same result. (B-spline coefficients of a
        // product are blossoms at knots, most of them at the ends of the piece.)
        let (at_a, at_b) = match a < b {
            true => (
                args.iter().filter(|&&u| u == a).count(),
                args.iter().filter(|&&u| u == b).count(),
            ),
            false => (0, 0),
        };
        let (first, last) = (at_b, self.degree - at_a);
        let mut w: smallvec::SmallVec<[f64; 64]> = self.coefs[first * d..(last + 1) * d]
            .iter()
            .copied()
            .collect();
        let h = b - a;
        let inner = args.iter().filter(|&&u| !(a < b && (u == a || u == b)));
        for (level, &u) in inner.enumerate() {
            let s = (u - a) / h;
            for k in 0..last - first - level {
                for c in 0..d {
                    w[k * d + c] = (1.0 - s) * w[k * d + c] + s * w[(k + 1) * d + c];
                }
            }
        }
        out[..d].copy_from_slice(&w[..d]);
    }

    /// Value at `u`.
    pub fn eval(&self, u: f64, out: &mut [f64]) {
        let args: smallvec::SmallVec<[f64; 32]> = smallvec::smallvec![u; self.degree];
        self.blossom(&args, out);
    }

    /// Splits at `u` by de Casteljau subdivision into the pieces on `[a, u]` and `[u, b]`.
    pub fn split(&self, u: f64) -> (Bezier, Bezier) {
        let (p, d) = (self.degree, self.dim);
        let s = (u - self.a) / (self.b - self.a);
        let mut w = self.coefs.clone();
        let mut left = vec![0.0; (p + 1) * d];
        let mut right = vec![0.0; (p + 1) * d];
        left[..d].copy_from_slice(&w[..d]);
        right[p * d..].copy_from_slice(&w[p * d..]);
        for level in 1..=p {
            for k in 0..=p - level {
                for c in 0..d {
                    w[k * d + c] = (1.0 - s) * w[k * d + c] + s * w[(k + 1) * d + c];
                }
            }
            left[level * d..(level + 1) * d].copy_from_slice(&w[..d]);
            right[(p - level) * d..(p - level + 1) * d]
                .copy_from_slice(&w[(p - level) * d..(p - level + 1) * d]);
        }
        let mk = |a, b, coefs| Bezier {
            a,
            b,
            degree: p,
            dim: d,
            coefs,
        };
        (mk(self.a, u, left), mk(u, self.b, right))
    }

    /// The piece as a clamped B-spline on `[a, b]`.
    pub fn to_bspline(&self) -> BSpline {
        let p = self.degree;
        let mut knots = vec![self.a; p + 1];
        knots.extend(std::iter::repeat_n(self.b, p + 1));
        BSpline::from_raw(p, self.dim, knots, self.coefs.clone())
    }
}
