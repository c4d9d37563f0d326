//! Exact algebra on piecewise Bézier forms, piece by piece: products (scalar, dot, planar and
//! 3D cross), linear combinations, degree elevation, components and stacks. Each result carries
//! the bound of [`crate::rounding`] for its coefficients, from the magnitudes and errors of its
//! operands' pieces; the continuity at a break is the lesser of the operands'.

use super::{binomials, Piecewise};
use crate::bilinear::Bilinear;
use crate::error::{Error, Result};
use crate::rounding;

impl Piecewise {
    fn same_breaks(&self, other: &Piecewise) -> Result<()> {
        if self.breaks == other.breaks {
            Ok(())
        } else {
            Err(Error::DomainMismatch {
                left: self.domain(),
                right: other.domain(),
            })
        }
    }

    fn product(&self, other: &Piecewise, form: &Bilinear) -> Result<Piecewise> {
        self.same_breaks(other)?;
        let (p, q) = (self.degree, other.degree);
        let deg = p + q;
        let (da, db, dout) = (self.dim, other.dim, form.out_dim);
        let (cp, cq, cd) = (binomials(p), binomials(q), binomials(deg));
        let n = self.pieces();
        let mut coefs = Vec::with_capacity(n * (deg + 1) * dout);
        let mut err = Vec::with_capacity(n * dout);
        for i in 0..n {
            let (fa, fb) = (self.piece(i), other.piece(i));
            // h_k = Σ_{i+j=k} C(p,i) C(q,j) / C(p+q,k) f_i g_j.
            let mut h = vec![0.0; (deg + 1) * dout];
            for (ia, ai) in fa.chunks_exact(da).enumerate() {
                for (jb, bj) in fb.chunks_exact(db).enumerate() {
                    let w = cp[ia] * cq[jb] / cd[ia + jb];
                    let hk = &mut h[(ia + jb) * dout..(ia + jb + 1) * dout];
                    for &(x, y, k, c) in form.terms.iter() {
                        hk[k] += w * c * ai[x] * bj[y];
                    }
                }
            }
            coefs.extend_from_slice(&h);
            // Each output coordinate: the bounds of its terms, from their factors' coordinates.
            let (ea, eb) = (self.errors(i), other.errors(i));
            for k in 0..dout {
                let sum = (p.min(q) + 1) * form.terms_of(k);
                let bound: f64 = form
                    .terms
                    .iter()
                    .filter(|t| t.2 == k)
                    .map(|&(x, y, _, c)| {
                        let m = (
                            self.coordinate_magnitude(i, x),
                            other.coordinate_magnitude(i, y),
                        );
                        rounding::product((p, q), sum, c.abs(), m, (ea[x], eb[y]))
                    })
                    .sum();
                err.push(bound);
            }
        }
        Ok(Piecewise {
            breaks: self.breaks.clone(),
            degree: deg,
            dim: dout,
            coefs,
            err,
            smooth: self.smooth_with(other),
            binoms: cd.to_vec(),
        })
    }

    /// The continuity orders of a combination of two functions on the same breaks.
    fn smooth_with(&self, other: &Piecewise) -> Vec<i32> {
        self.smooth
            .iter()
            .zip(&other.smooth)
            .map(|(&a, &b)| a.min(b))
            .collect()
    }

    /// The product of a scalar function (`self` or `other`) and a function of any dimension.
    ///
    /// ```
    /// use bspline::{BSpline, Piecewise};
    /// let f = Piecewise::from_bspline(&BSpline::bezier(1, vec![1., 2., 0.]).unwrap());
    /// let g = Piecewise::from_bspline(&BSpline::bezier(1, vec![3., -1.]).unwrap());
    /// let h = f.mul(&g).unwrap();
    /// assert_eq!(h.degree(), 3);
    /// let (mut a, mut b, mut c) = ([0.0], [0.0], [0.0]);
    /// f.eval(0.3, &mut a);
    /// g.eval(0.3, &mut b);
    /// h.eval(0.3, &mut c);
    /// assert!((c[0] - a[0] * b[0]).abs() <= 1e-15);
    /// ```
    pub fn mul(&self, other: &Piecewise) -> Result<Piecewise> {
        if self.dim != 1 {
            if other.dim == 1 {
                return other.mul(self);
            }
            return Err(Error::DimensionMismatch {
                expected: 1,
                got: self.dim,
            });
        }
        self.product(other, &Bilinear::scalar_times(other.dim))
    }

    /// The dot product of two functions of one dimension, a scalar function.
    pub fn dot(&self, other: &Piecewise) -> Result<Piecewise> {
        self.product(other, &Bilinear::dot([self.dim, other.dim])?)
    }

    /// The planar cross product `x_a y_b − y_a x_b` of two functions of dimension 2.
    pub fn cross(&self, other: &Piecewise) -> Result<Piecewise> {
        self.product(other, &Bilinear::cross([self.dim, other.dim])?)
    }

    /// The 3D cross product of two functions of dimension 3 (homogeneous planar curves).
    pub fn cross3(&self, other: &Piecewise) -> Result<Piecewise> {
        self.product(other, &Bilinear::cross3([self.dim, other.dim])?)
    }

    /// The degree raised by `times` (exactly the same function: each new coefficient a convex
    /// combination of two old ones).
    pub fn elevate(&self, times: usize) -> Piecewise {
        let mut f = self.clone();
        for _ in 0..times {
            f = f.elevate_once();
        }
        f
    }

    fn elevate_once(&self) -> Piecewise {
        let (p, d, n) = (self.degree, self.dim, self.pieces());
        let q = p + 1;
        let mut coefs = Vec::with_capacity(n * (q + 1) * d);
        let mut err = Vec::with_capacity(n * d);
        for i in 0..n {
            let c = self.piece(i);
            for j in 0..=q {
                let a = j as f64 / q as f64;
                for k in 0..d {
                    let left = if j > 0 { c[(j - 1) * d + k] } else { 0.0 };
                    let right = if j < q { c[j * d + k] } else { 0.0 };
                    coefs.push(a * left + (1.0 - a) * right);
                }
            }
            let e = self.errors(i);
            err.extend(
                (0..d).map(|k| e[k] + rounding::insertion(self.coordinate_magnitude(i, k) + e[k])),
            );
        }
        self.with_pieces(q, coefs, err, self.smooth.clone())
    }

    /// `s · self + t · other` (of one dimension; the lower degree is raised).
    pub fn lincomb(&self, s: f64, other: &Piecewise, t: f64) -> Result<Piecewise> {
        self.same_breaks(other)?;
        if self.dim != other.dim {
            return Err(Error::DimensionMismatch {
                expected: self.dim,
                got: other.dim,
            });
        }
        let deg = self.degree.max(other.degree);
        let a = self.elevate(deg - self.degree);
        let b = other.elevate(deg - other.degree);
        let mut coefs = a.coefs.clone();
        for (c, d) in coefs.iter_mut().zip(&b.coefs) {
            *c = s * *c + t * d;
        }
        let err = (0..a.pieces())
            .flat_map(|i| {
                let (a, b) = (&a, &b);
                (0..a.dim).map(move |k| {
                    let magnitude = s.abs() * a.coordinate_magnitude(i, k)
                        + t.abs() * b.coordinate_magnitude(i, k);
                    let carried = s.abs() * a.errors(i)[k] + t.abs() * b.errors(i)[k];
                    rounding::linear(2, magnitude, carried)
                })
            })
            .collect();
        Ok(Piecewise {
            breaks: a.breaks.clone(),
            degree: deg,
            dim: a.dim,
            coefs,
            err,
            smooth: a.smooth_with(&b),
            binoms: a.binoms,
        })
    }

    /// `self − other`.
    pub fn sub(&self, other: &Piecewise) -> Result<Piecewise> {
        self.lincomb(1.0, other, -1.0)
    }

    /// Every coefficient multiplied by `s` (one more rounding).
    pub fn scale(&self, s: f64) -> Piecewise {
        let mut f = self.clone();
        for c in &mut f.coefs {
            *c *= s;
        }
        let d = self.dim;
        for (j, e) in f.err.iter_mut().enumerate() {
            let m = self.coordinate_magnitude(j / d, j % d);
            *e = s.abs() * *e + numeric::rounding::gamma(1) * s.abs() * m;
        }
        f
    }

    /// Every coefficient multiplied by a constant `s` that is itself in error by up to `s_err`
    /// against the exact constant it stands for (computed from exact parameters).
    pub fn scale_inexact(&self, s: f64, s_err: f64) -> Piecewise {
        let mut f = self.scale(s);
        let d = self.dim;
        for (j, e) in f.err.iter_mut().enumerate() {
            let m = self.coordinate_magnitude(j / d, j % d) + self.err[j];
            *e += s_err * m;
        }
        f
    }

    /// The coordinates `which` (in that order) as a function of dimension `which.len()`:
    /// no arithmetic, the errors unchanged.
    pub fn components(&self, which: &[usize]) -> Result<Piecewise> {
        if let Some(&k) = which.iter().find(|&&k| k >= self.dim) {
            return Err(Error::DimensionMismatch {
                expected: self.dim,
                got: k + 1,
            });
        }
        if which.is_empty() {
            return Err(Error::ZeroDimension);
        }
        let pick = |v: &[f64]| -> Vec<f64> {
            v.chunks_exact(self.dim)
                .flat_map(|pt| which.iter().map(move |&k| pt[k]))
                .collect()
        };
        Ok(Piecewise {
            coefs: pick(&self.coefs),
            err: pick(&self.err),
            dim: which.len(),
            ..self.clone()
        })
    }

    /// Functions on the same breaks stacked into one (their degrees raised to the highest).
    pub fn stack(parts: &[&Piecewise]) -> Result<Piecewise> {
        let Some(first) = parts.first() else {
            return Err(Error::ZeroDimension);
        };
        for g in parts {
            first.same_breaks(g)?;
        }
        let deg = parts.iter().map(|g| g.degree).max().unwrap_or(0);
        let raised: Vec<Piecewise> = parts.iter().map(|g| g.elevate(deg - g.degree)).collect();
        let dim: usize = raised.iter().map(|g| g.dim).sum();
        let n = first.pieces();
        let mut coefs = Vec::with_capacity(n * (deg + 1) * dim);
        for i in 0..n {
            for j in 0..=deg {
                for g in &raised {
                    coefs.extend_from_slice(&g.piece(i)[j * g.dim..(j + 1) * g.dim]);
                }
            }
        }
        let err = (0..n)
            .flat_map(|i| raised.iter().flat_map(move |g| g.errors(i).to_vec()))
            .collect();
        let smooth = (0..first.smooth.len())
            .map(|k| raised.iter().map(|g| g.smooth[k]).min().unwrap_or(i32::MAX))
            .collect();
        Ok(Piecewise {
            breaks: first.breaks.clone(),
            degree: deg,
            dim,
            coefs,
            err,
            smooth,
            binoms: binomials(deg),
        })
    }
}
