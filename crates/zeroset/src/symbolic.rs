//! The bisector functions `F1`, `F2`, `F3` of §3, built exactly as tensor-product B-splines.
//!
//! Each is a polynomial in the coordinates of `C1(t)`, `C1'(t)`, `C2(r)`, `C2'(r)`, so it is a
//! sum of outer products `f_k(t) g_k(r)` of univariate B-splines, which
//! [`TensorBSpline::sum_of_outer`] turns into one coefficient grid. Rational curves are taken
//! in homogeneous form `C = p / W`, `C' = q / W²` with `q = p'W − pW'`; each function is
//! multiplied by the power of `W1 W2` that clears every denominator (positive, so the zero set
//! and the sign are unchanged).
//!
//! With `e = p1 W2 − p2 W1` (that is `W1 W2 (C1 − C2)`):
//! - `F1 = |q1|² ⟨e, q2⟩² − |q2|² ⟨e, q1⟩²` (Eq. 3),
//! - `F2 = |q2|² (e × q1)² − |q1|² (e × q2)²` (the normal form of §3.2),
//! - `F3 = W2 ⟨p1, q1⟩ (e × q2) − W1 ⟨p2, q2⟩ (e × q1) − ½ (q1 × q2)(|p1|² W2² − |p2|² W1²)`,
//!   Eq. 13 times its denominator `C1' × C2'`, which expands into six outer products.
//!
//! For polynomial curves of degree `m` the total degrees are those of §3.4 (`6m − 4` for `F1`
//! and `F2`, `4m − 2` for `F3`); the tensor degrees are lower: `(4m − 2, 4m − 2)` and
//! `(3m − 1, 3m − 1)`, because no variable carries the full total degree.

use crate::error::{Error, Result};
use bspline::tensor::TensorBSpline;
use bspline::{BSpline, Rational};
use serde::{Deserialize, Serialize};

/// Which bivariate function of §3 carries the bisector.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Eq. 3: equal distance along the two normals (contains the parallel-normal factor).
    F1,
    /// §3.2: equal angles with the two normals (contains the parallel-normal factor).
    F2,
    /// Eq. 13 times `C1' × C2'`: the lowest degree, no redundant factor.
    #[default]
    F3,
}

/// The per-curve univariate pieces: `p = (x, y)`, `q = (qx, qy)`, weight `w` (`None`: ≡ 1).
struct Parts {
    x: BSpline,
    y: BSpline,
    qx: BSpline,
    qy: BSpline,
    w: Option<BSpline>,
}

fn parts(c: &Rational, which: usize) -> Result<Parts> {
    if c.dim() != 2 {
        return Err(Error::NotPlanar {
            which,
            dim: c.dim(),
        });
    }
    let h = c.homogeneous();
    let (hx, hy, hw) = (h.component(0)?, h.component(1)?, h.component(2)?);
    if !c.is_rational() {
        // Equal weights: the Euclidean curve is the homogeneous one scaled.
        let s = 1.0 / h.ctrl(0)[2];
        let (x, y) = (hx.scale(s), hy.scale(s));
        let (qx, qy) = (x.deriv(), y.deriv());
        return Ok(Parts {
            x,
            y,
            qx,
            qy,
            w: None,
        });
    }
    let qx = hx.deriv().mul(&hw)?.sub(&hx.mul(&hw.deriv())?)?;
    let qy = hy.deriv().mul(&hw)?.sub(&hy.mul(&hw.deriv())?)?;
    Ok(Parts {
        x: hx,
        y: hy,
        qx,
        qy,
        w: Some(hw),
    })
}

impl Parts {
    /// `f · W^k` (no-op for a polynomial curve).
    fn times_w(&self, f: &BSpline, k: usize) -> Result<BSpline> {
        let mut out = f.clone();
        if let Some(w) = &self.w {
            for _ in 0..k {
                out = out.mul(w)?;
            }
        }
        Ok(out)
    }
    fn one(&self) -> Result<BSpline> {
        let (a, b) = self.x.domain();
        Ok(BSpline::constant(&[1.0], 0, a, b)?)
    }
    fn w_or_one(&self) -> Result<BSpline> {
        match &self.w {
            Some(w) => Ok(w.clone()),
            None => self.one(),
        }
    }
}

/// A sum of outer products `Σ f_k(t) g_k(r)` under construction.
#[derive(Clone, Default)]
struct Sep(Vec<(BSpline, BSpline)>);

impl Sep {
    fn term(f: BSpline, g: BSpline) -> Self {
        Sep(vec![(f, g)])
    }
    fn add(mut self, other: Sep) -> Sep {
        self.0.extend(other.0);
        self
    }
    fn neg(self) -> Sep {
        Sep(self
            .0
            .into_iter()
            .map(|(f, g)| (f.scale(-1.0), g))
            .collect())
    }
    fn mul(&self, other: &Sep) -> Result<Sep> {
        let mut out = Vec::with_capacity(self.0.len() * other.0.len());
        for (f, g) in &self.0 {
            for (a, b) in &other.0 {
                out.push((f.mul(a)?, g.mul(b)?));
            }
        }
        Ok(Sep(out))
    }
}

/// The bivariate function of `method` for the curves `c1(t)`, `c2(r)` (both planar).
///
/// ```
/// use bspline::{BSpline, Rational};
/// use zeroset::{bisector_function, Method};
/// // Segments on the axes, c1(t) = (1 + 2t, 0) and c2(r) = (0, 1 + 2r): matched feet (t = r)
/// // are zeros of F3, unmatched ones are not.
/// let c1 = Rational::polynomial(&BSpline::bezier(2, vec![1.0, 0.0, 3.0, 0.0]).unwrap());
/// let c2 = Rational::polynomial(&BSpline::bezier(2, vec![0.0, 1.0, 0.0, 3.0]).unwrap());
/// let f = bisector_function(&c1, &c2, Method::F3).unwrap();
/// assert!(f.eval(0.3, 0.3).abs() < 1e-12);
/// assert!(f.eval(0.3, 0.7).abs() > 1e-3);
/// ```
pub fn bisector_function(c1: &Rational, c2: &Rational, method: Method) -> Result<TensorBSpline> {
    Ok(bisector_function_scaled(c1, c2, method)?.0)
}

/// [`bisector_function`] and the size of the terms that sum to it, `Σ ‖f_k‖ ‖g_k‖` over its
/// outer products: the scale of its coefficients' rounding. (Where the curves are straight
/// the terms cancel exactly; a rational parametrisation leaves their rounding, which the
/// function's own size cannot tell from a signal.)
pub(crate) fn bisector_function_scaled(
    c1: &Rational,
    c2: &Rational,
    method: Method,
) -> Result<(TensorBSpline, f64)> {
    let a = parts(c1, 1)?;
    let b = parts(c2, 2)?;
    let terms = match method {
        Method::F3 => f3_terms(&a, &b)?,
        Method::F1 | Method::F2 => {
            let (one_t, one_r) = (a.one()?, b.one()?);
            // e paired with a vector (u, v) of r-functions or t-functions, as Seps.
            let w2 = b.w_or_one()?;
            let w1 = a.w_or_one()?;
            let ex =
                Sep::term(a.x.clone(), w2.clone()).add(Sep::term(w1.clone(), b.x.clone()).neg());
            let ey = Sep::term(a.y.clone(), w2).add(Sep::term(w1, b.y.clone()).neg());
            let t_ = |f: &BSpline| Sep::term(f.clone(), one_r.clone());
            let r_ = |g: &BSpline| Sep::term(one_t.clone(), g.clone());
            let nq1 = a.qx.mul(&a.qx)?.add(&a.qy.mul(&a.qy)?)?;
            let nq2 = b.qx.mul(&b.qx)?.add(&b.qy.mul(&b.qy)?)?;
            let (k1, k2) = if method == Method::F1 {
                // ⟨e, q2⟩ and ⟨e, q1⟩.
                (
                    ex.mul(&r_(&b.qx))?.add(ey.mul(&r_(&b.qy))?),
                    ex.mul(&t_(&a.qx))?.add(ey.mul(&t_(&a.qy))?),
                )
            } else {
                // e × q1 and e × q2, paired so that F2 = |q2|² (e×q1)² − |q1|² (e×q2)².
                (
                    ex.mul(&t_(&a.qy))?.add(ey.mul(&t_(&a.qx))?.neg()),
                    ex.mul(&r_(&b.qy))?.add(ey.mul(&r_(&b.qx))?.neg()),
                )
            };
            let (k1, k2) = (k1.mul(&k1)?, k2.mul(&k2)?);
            let first = if method == Method::F1 {
                t_(&nq1).mul(&k1)?
            } else {
                r_(&nq2).mul(&k1)?
            };
            let second = if method == Method::F1 {
                r_(&nq2).mul(&k2)?
            } else {
                t_(&nq1).mul(&k2)?
            };
            first.add(second.neg()).0
        }
    };
    let largest = |f: &BSpline| f.coefs().iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let scale = terms.iter().map(|(f, g)| largest(f) * largest(g)).sum();
    Ok((TensorBSpline::sum_of_outer(&terms)?, scale))
}

/// The six outer products of `F3` (module docs):
/// `U1⊗W2²qy2 − V1⊗W2²qx2 − A1W1⊗W2S2 − W1S1⊗A2W2 + W1²qy1⊗U2 − W1²qx1⊗V2` with
/// `A = ⟨p, q⟩`, `N = |p|²`, `S = p × q`, `U = A x − ½ N qx`, `V = A y − ½ N qy`.
fn f3_terms(a: &Parts, b: &Parts) -> Result<Vec<(BSpline, BSpline)>> {
    struct Q {
        u: BSpline,
        v: BSpline,
        aw: BSpline,
        ws: BSpline,
        wqx: BSpline,
        wqy: BSpline,
    }
    let q = |c: &Parts| -> Result<Q> {
        let aa = c.x.mul(&c.qx)?.add(&c.y.mul(&c.qy)?)?;
        let n = c.x.mul(&c.x)?.add(&c.y.mul(&c.y)?)?;
        let s = c.x.mul(&c.qy)?.sub(&c.y.mul(&c.qx)?)?;
        Ok(Q {
            u: aa.mul(&c.x)?.lincomb(1.0, &n.mul(&c.qx)?, -0.5)?,
            v: aa.mul(&c.y)?.lincomb(1.0, &n.mul(&c.qy)?, -0.5)?,
            aw: c.times_w(&aa, 1)?,
            ws: c.times_w(&s, 1)?,
            wqx: c.times_w(&c.qx, 2)?,
            wqy: c.times_w(&c.qy, 2)?,
        })
    };
    let (a, b) = (q(a)?, q(b)?);
    Ok(vec![
        (a.u, b.wqy.clone()),
        (a.v.scale(-1.0), b.wqx.clone()),
        (a.aw.scale(-1.0), b.ws),
        (a.ws.scale(-1.0), b.aw),
        (a.wqy, b.u),
        (a.wqx.scale(-1.0), b.v),
    ])
}
