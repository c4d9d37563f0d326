//! Exact symbolic algebra: sums, products (scalar, dot, cross) and degree elevation.
//!
//! A product of B-splines of degrees `p` and `q` is a spline of degree `p + q` whose knots are
//! the union of the factors' breakpoints, each with the smallest multiplicity that the factors'
//! continuity allows. We compute it in two exact steps: multiply the Bézier pieces on the common
//! breakpoints (a binomial convolution), then read each B-spline coefficient of the minimal knot
//! vector off the blossom of one piece in its support. The blossom identity makes the result
//! exact; picking the widest piece in the support keeps the extrapolation, and so rounding, small.

use crate::bilinear::Bilinear;
use crate::error::{Error, Result};
use crate::knots::multiplicity;
use crate::refine::Bezier;
use crate::spline::BSpline;

/// Relative tolerance for two domains to count as the same.
const DOMAIN_RTOL: f64 = 1e-12;

fn check_same_domain(a: &BSpline, b: &BSpline) -> Result<(f64, f64)> {
    let (da, db) = (a.domain(), b.domain());
    let scale = (da.1 - da.0).abs().max(da.0.abs()).max(da.1.abs()).max(1.0);
    if (da.0 - db.0).abs() > DOMAIN_RTOL * scale || (da.1 - db.1).abs() > DOMAIN_RTOL * scale {
        return Err(Error::DomainMismatch {
            left: da,
            right: db,
        });
    }
    Ok(da)
}

/// Union of the breakpoints of two splines on the same domain, with the first spline's ends.
fn union_breaks(a: &BSpline, b: &BSpline) -> Vec<f64> {
    let (lo, hi) = a.domain();
    let mut v: Vec<f64> = a
        .breakpoints()
        .into_iter()
        .chain(b.breakpoints())
        .filter(|&x| x > lo && x < hi)
        .collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    let mut out = Vec::with_capacity(v.len() + 2);
    out.push(lo);
    out.extend(v);
    out.push(hi);
    out
}

/// Continuity order of `f` at the interior value `x`: `p − multiplicity`, −1 where `f` jumps
/// (a derivative of a C⁰ spline), and "infinite" where `x` is no knot.
fn continuity(f: &BSpline, x: f64) -> isize {
    match multiplicity(f.knots(), x) {
        0 => isize::MAX,
        m => f.degree() as isize - m as isize,
    }
}

/// Binomial coefficients C(n, 0..=n) as f64.
fn binomials(n: usize) -> smallvec::SmallVec<[f64; 32]> {
    let mut row = smallvec::smallvec![1.0; n + 1];
    for k in 1..n {
        row[k] = row[k - 1] * (n + 1 - k) as f64 / k as f64;
    }
    row
}

fn product(a: &BSpline, b: &BSpline, form: &Bilinear) -> Result<BSpline> {
    let (lo, hi) = check_same_domain(a, b)?;
    // Work on b's parameters mapped exactly onto a's domain so breakpoints coincide.
    let b_owned;
    let b = if b.domain() != (lo, hi) {
        b_owned = b.reparam(lo, hi)?;
        &b_owned
    } else {
        b
    };
    let deg = a.degree() + b.degree();
    let dout = form.out_dim;
    // One piece: its Bernstein coefficients are the B-spline coefficients on the clamped
    // knots, as the blossoms below would give them (less their rounding).
    let one_piece = |coefs: Vec<f64>| {
        let mut knots = vec![lo; deg + 1];
        knots.extend(std::iter::repeat_n(hi, deg + 1));
        BSpline::from_raw(deg, dout, knots, coefs)
    };
    if a.is_clamped_bezier() && b.is_clamped_bezier() {
        // (Their coefficients are their Bernstein coefficients already.)
        let whole = |f: &BSpline| Bezier {
            a: lo,
            b: hi,
            degree: f.degree(),
            dim: f.dim(),
            coefs: f.coefs().to_vec(),
        };
        return Ok(one_piece(bezier_product(&whole(a), &whole(b), form).coefs));
    }
    let breaks = union_breaks(a, b);
    let pa = a.bezier_pieces_at(&breaks);
    let pb = b.bezier_pieces_at(&breaks);
    let mut pieces: Vec<Bezier> = pa
        .iter()
        .zip(&pb)
        .map(|(fa, fb)| bezier_product(fa, fb, form))
        .collect();
    if pieces.len() == 1 {
        return Ok(one_piece(pieces.swap_remove(0).coefs));
    }
    // Minimal knot vector: continuity of the product is the smaller of the factors'.
    let mut knots = vec![lo; deg + 1];
    for &x in &breaks[1..breaks.len() - 1] {
        let cont = continuity(a, x).min(continuity(b, x));
        let mult = (deg as isize - cont).clamp(0, deg as isize + 1) as usize;
        knots.extend(std::iter::repeat_n(x, mult));
    }
    knots.extend(std::iter::repeat_n(hi, deg + 1));
    Ok(from_pieces(deg, dout, knots, &breaks, &pieces))
}

/// The product of two Bézier pieces on one interval, combined by `form`:
/// `h_k = Σ_{i+j=k} C(p,i) C(q,j) / C(p+q,k) f_i g_j`.
fn bezier_product(fa: &Bezier, fb: &Bezier, form: &Bilinear) -> Bezier {
    let (p, q, da, db, dout) = (fa.degree, fb.degree, fa.dim, fb.dim, form.out_dim);
    let deg = p + q;
    let (cp, cq, cd) = (binomials(p), binomials(q), binomials(deg));
    let mut h = vec![0.0; (deg + 1) * dout];
    for i in 0..=p {
        let ai = &fa.coefs[i * da..(i + 1) * da];
        for j in 0..=q {
            let bj = &fb.coefs[j * db..(j + 1) * db];
            let w = cp[i] * cq[j] / cd[i + j];
            let hk = &mut h[(i + j) * dout..(i + j + 1) * dout];
            for &(ia, ib, k, c) in form.terms.iter() {
                hk[k] += w * c * ai[ia] * bj[ib];
            }
        }
    }
    Bezier {
        a: fa.a,
        b: fa.b,
        degree: deg,
        dim: dout,
        coefs: h,
    }
}

/// B-spline coefficients on `knots` of the piecewise polynomial given by `pieces` (one per
/// interval of `breaks`), by blossoming; `knots` must be a space that contains the function.
pub(crate) fn from_pieces(
    deg: usize,
    dim: usize,
    knots: Vec<f64>,
    breaks: &[f64],
    pieces: &[Bezier],
) -> BSpline {
    let n = knots.len() - deg - 1;
    let mut coefs = vec![0.0; n * dim];
    // piece_of[j]: which piece covers knot span j (None for empty spans).
    for i in 0..n {
        // Support of the i-th basis function is [knots[i], knots[i+deg+1]]; choose the widest
        // non-empty span inside it.
        let mut best: Option<(f64, usize)> = None;
        for j in i..=i + deg {
            let w = knots[j + 1] - knots[j];
            if w > 0.0 && best.is_none_or(|(bw, _)| w > bw) {
                best = Some((w, j));
            }
        }
        let Some((_, j)) = best else { continue };
        let mid = 0.5 * (knots[j] + knots[j + 1]);
        let k = breaks
            .partition_point(|&b| b <= mid)
            .saturating_sub(1)
            .min(pieces.len() - 1);
        pieces[k].blossom(
            &knots[i + 1..i + deg + 1],
            &mut coefs[i * dim..(i + 1) * dim],
        );
    }
    BSpline::from_raw(deg, dim, knots, coefs)
}

impl BSpline {
    /// Product of a scalar function (`self`, dim 1) and a function of any dimension.
    ///
    /// The result has degree `p + q` and the minimal knot vector: its continuity at each knot is
    /// exactly what the factors allow.
    ///
    /// ```
    /// use bspline::BSpline;
    /// let f = BSpline::bezier(1, vec![1., 2., 0.]).unwrap();
    /// let g = BSpline::bezier(1, vec![3., -1.]).unwrap();
    /// let h = f.mul(&g).unwrap();
    /// assert_eq!(h.degree(), 3);
    /// let u = 0.3;
    /// assert!((h.eval_scalar(u) - f.eval_scalar(u) * g.eval_scalar(u)).abs() < 1e-14);
    /// ```
    pub fn mul(&self, other: &BSpline) -> Result<BSpline> {
        if self.dim() != 1 {
            if other.dim() == 1 {
                return other.mul(self);
            }
            return Err(Error::DimensionMismatch {
                expected: 1,
                got: self.dim(),
            });
        }
        product(self, other, &Bilinear::scalar_times(other.dim()))
    }

    /// Dot product of two functions of the same dimension, a scalar function.
    pub fn dot(&self, other: &BSpline) -> Result<BSpline> {
        product(self, other, &Bilinear::dot([self.dim(), other.dim()])?)
    }

    /// The planar cross product `x_a y_b − y_a x_b` of two 2D functions, a scalar function.
    ///
    /// ```
    /// use bspline::BSpline;
    /// // C × C′ for the parabola C(u) = (u, u²): u·2u − u² = u².
    /// let c = BSpline::bezier(2, vec![0., 0., 0.5, 0., 1., 1.]).unwrap();
    /// let k = c.cross(&c.deriv()).unwrap();
    /// assert!((k.eval_scalar(0.6) - 0.36).abs() < 1e-15);
    /// ```
    pub fn cross(&self, other: &BSpline) -> Result<BSpline> {
        product(self, other, &Bilinear::cross([self.dim(), other.dim()])?)
    }

    /// The 3D cross product of two 3D functions (used for homogeneous planar curves).
    pub fn cross3(&self, other: &BSpline) -> Result<BSpline> {
        product(self, other, &Bilinear::cross3([self.dim(), other.dim()])?)
    }

    /// Raises the degree by `times`; the function is unchanged and every knot's multiplicity
    /// grows by `times`, so the continuity is kept exactly.
    ///
    /// ```
    /// use bspline::BSpline;
    /// let f = BSpline::new(2, vec![0., 0., 0., 0.5, 1., 1., 1.], 1, vec![0., 2., -1., 1.]).unwrap();
    /// let g = f.elevate(1);
    /// assert_eq!(g.degree(), 3);
    /// assert_eq!(g.knots(), &[0., 0., 0., 0., 0.5, 0.5, 1., 1., 1., 1.]);
    /// assert!((g.eval_scalar(0.7) - f.eval_scalar(0.7)).abs() < 1e-15);
    /// ```
    pub fn elevate(&self, times: usize) -> BSpline {
        if times == 0 {
            return self.clone();
        }
        let (a, b) = self.domain();
        // The product with the constant 1 of degree `times` is exactly the degree elevation.
        match BSpline::constant(&[1.0], times, a, b).and_then(|one| one.mul(self)) {
            Ok(f) => f,
            Err(_) => self.clone(), // unreachable: same domain, scalar factor
        }
    }

    /// Whether the spline is one polynomial piece on clamped knots: its coefficients are
    /// then its Bernstein coefficients on its domain.
    fn is_clamped_bezier(&self) -> bool {
        let (p, k) = (self.degree(), self.knots());
        self.n_ctrl() == p + 1 && k[0] == k[p] && k[p + 1] == k[2 * p + 1]
    }

    /// Whether `other` lies in this function's spline space, clamped: harmonising them
    /// changes neither.
    pub(crate) fn same_space(&self, other: &BSpline) -> bool {
        self.degree() == other.degree() && self.knots() == other.knots() && self.is_clamped()
    }

    /// Brings two functions into one spline space (common degree, merged knot vector).
    pub fn harmonize(&self, other: &BSpline) -> Result<(BSpline, BSpline)> {
        if self.same_space(other) {
            return Ok((self.clone(), other.clone()));
        }
        let (lo, hi) = check_same_domain(self, other)?;
        if self.is_clamped_bezier() && other.is_clamped_bezier() && other.domain() == (lo, hi) {
            // One span each, on the same interval: the common space is the higher degree's.
            let deg = self.degree().max(other.degree());
            return Ok((
                self.elevate(deg - self.degree()),
                other.elevate(deg - other.degree()),
            ));
        }
        let other = if other.domain() != (lo, hi) {
            other.reparam(lo, hi)?
        } else {
            other.clone()
        };
        let deg = self.degree().max(other.degree());
        let a = self.elevate(deg - self.degree());
        let b = other.elevate(deg - other.degree());
        let missing = |f: &BSpline, g: &BSpline| -> Vec<f64> {
            let mut x = Vec::new();
            for v in g.breakpoints() {
                if v > lo && v < hi {
                    let (mf, mg) = (multiplicity(f.knots(), v), multiplicity(g.knots(), v));
                    x.extend(std::iter::repeat_n(v, mg.saturating_sub(mf)));
                }
            }
            x
        };
        let (xa, xb) = (missing(&a, &b), missing(&b, &a));
        let (a, b) = (a.clamped(), b.clamped());
        Ok((a.refine_sorted(&xa), b.refine_sorted(&xb)))
    }

    /// Sum of two functions of the same dimension on the same domain.
    pub fn add(&self, other: &BSpline) -> Result<BSpline> {
        self.lincomb(1.0, other, 1.0)
    }

    /// Difference of two functions of the same dimension on the same domain.
    pub fn sub(&self, other: &BSpline) -> Result<BSpline> {
        self.lincomb(1.0, other, -1.0)
    }

    /// `s·self + t·other`, exactly, in the common spline space.
    pub fn lincomb(&self, s: f64, other: &BSpline, t: f64) -> Result<BSpline> {
        if self.dim() != other.dim() {
            return Err(Error::DimensionMismatch {
                expected: self.dim(),
                got: other.dim(),
            });
        }
        let same_space = self.degree() == other.degree() && self.knots() == other.knots();
        let (a, b) = if same_space {
            (self.clone(), other.clone())
        } else {
            self.harmonize(other)?
        };
        let (deg, dim, knots, mut coefs) = a.into_parts();
        for (c, d) in coefs.iter_mut().zip(b.coefs()) {
            *c = s * *c + t * d;
        }
        Ok(BSpline::from_raw(deg, dim, knots, coefs))
    }

    /// Stacks scalar functions (or lower-dimensional ones) into one vector-valued function.
    pub fn stack(parts: &[&BSpline]) -> Result<BSpline> {
        let Some((first, rest)) = parts.split_first() else {
            return Err(Error::ZeroDimension);
        };
        // Bring every part into one common space (where they do not share one already).
        let harmonized: Vec<BSpline>;
        let spaced: Vec<&BSpline> = if rest.iter().all(|g| first.same_space(g)) {
            parts.to_vec()
        } else {
            let mut acc: BSpline = (*first).clone();
            for g in rest {
                acc = acc.harmonize(g)?.0;
            }
            harmonized = parts
                .iter()
                .map(|g| g.harmonize(&acc).map(|(g, _)| g))
                .collect::<Result<_>>()?;
            harmonized.iter().collect()
        };
        let space = spaced[0];
        let dim: usize = spaced.iter().map(|g| g.dim()).sum();
        let n = space.n_ctrl();
        let mut coefs = Vec::with_capacity(n * dim);
        for i in 0..n {
            for g in &spaced {
                coefs.extend_from_slice(g.ctrl(i));
            }
        }
        Ok(BSpline::from_raw(
            space.degree(),
            dim,
            space.knots().to_vec(),
            coefs,
        ))
    }
}
