//! The conditions of force closure as bivariate B-splines.
//!
//! With `d = C(t) − C(s)`, tangent `T = C'` and inward normal `N = ±T⊥` (`+` on a
//! counterclockwise curve), the contact at `s` holds `d` inside its friction cone of
//! half-angle `α = atan μ` when `angle(N, d) ≤ α`. Since `|N| = |T|`, that is
//! `|⟨T, d⟩| ≤ μ ⟨N, d⟩`: two functions linear in `d`,
//! `⟨μN − T, d⟩ ≥ 0` and `⟨μN + T, d⟩ ≥ 0`, whose vectors are the normals of the cone's two
//! edges. (Their product is `cos⁻²α` times the issue's `⟨N, d⟩² − cos²α |N|² |d|²`; each
//! factor has half its degree and is positive exactly on its own side of the cone, so no
//! side condition `⟨N, d⟩ > 0` is needed.) At `t` the same with `−d`.
//!
//! A rational curve `C = P / w` has `C' = q / w²` with `q = P'w − Pw'`, and
//! `w(s) w(t) d = e = P(t) w(s) − P(s) w(t)`; both factors are positive, so the functions
//! `⟨μ q⊥ ∓ q, e⟩` have the signs of the Euclidean ones. Each is a sum of three outer
//! products of univariate splines (`TensorBSpline::sum_of_outer`), of degree `(3p − 2, p)`
//! for a rational curve of degree `p` and `(2p − 1, p)` for a polynomial one.

use crate::error::Result;
use bspline::tensor::TensorBSpline;
use bspline::Bezier;
use bspline::{BSpline, Rational};

/// One exact curve form's univariate parts.
pub(crate) struct Form {
    /// Homogeneous coordinates (Euclidean for a polynomial curve).
    x: BSpline,
    y: BSpline,
    /// The weight (the constant 1 for a polynomial curve).
    w: BSpline,
    /// The hodograph's numerator `q = P'w − Pw'` (`C'` itself for a polynomial curve).
    qx: BSpline,
    qy: BSpline,
    /// `q` as Bézier pieces (dimension 2), for the cone test near the diagonal.
    q_pieces: Vec<Bezier>,
    /// The curve itself, for evaluation.
    curve: Rational,
    /// `+1` counterclockwise, `−1` clockwise: `N = orientation · T⊥`.
    orientation: f64,
}

impl Form {
    /// The parts of the planar rational curve `curve`, running round its region the way
    /// `orientation` says.
    pub(crate) fn new(curve: &Rational, orientation: f64) -> Result<Self> {
        let h = curve.homogeneous();
        let (hx, hy, hw) = (h.component(0)?, h.component(1)?, h.component(2)?);
        let (x, y, w, qx, qy) = if curve.is_rational() {
            let qx = hx.deriv().mul(&hw)?.sub(&hx.mul(&hw.deriv())?)?;
            let qy = hy.deriv().mul(&hw)?.sub(&hy.mul(&hw.deriv())?)?;
            (hx, hy, hw, qx, qy)
        } else {
            // Equal weights: the Euclidean curve is the homogeneous one scaled.
            let s = 1.0 / h.ctrl(0)[2];
            let (x, y) = (hx.scale(s), hy.scale(s));
            let (a, b) = curve.domain();
            let one = BSpline::constant(&[1.0], 0, a, b)?;
            let (qx, qy) = (x.deriv(), y.deriv());
            (x, y, one, qx, qy)
        };
        let q_pieces = BSpline::stack(&[&qx, &qy])?.bezier_pieces();
        Ok(Self {
            x,
            y,
            w,
            qx,
            qy,
            q_pieces,
            curve: curve.clone(),
            orientation,
        })
    }

    /// The same form on `[lo, hi]` (inside the domain): the functions of a box of pairs
    /// are built from their contacts' stretches, not cut out of the whole cell's.
    pub(crate) fn restrict(&self, lo: f64, hi: f64) -> Result<Self> {
        let (qx, qy) = (self.qx.restrict(lo, hi)?, self.qy.restrict(lo, hi)?);
        let q_pieces = BSpline::stack(&[&qx, &qy])?.bezier_pieces();
        Ok(Self {
            x: self.x.restrict(lo, hi)?,
            y: self.y.restrict(lo, hi)?,
            w: self.w.restrict(lo, hi)?,
            qx,
            qy,
            q_pieces,
            curve: self.curve.restrict(lo, hi)?,
            orientation: self.orientation,
        })
    }

    /// The parameter domain.
    pub(crate) fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    /// The point and the tangent at `v` (clamped to the domain).
    pub(crate) fn point_tangent(&self, v: f64) -> ([f64; 2], [f64; 2]) {
        let (a, b) = self.domain();
        let mut out = [0.0; 4];
        self.curve.eval_derivs(v.clamp(a, b), 1, &mut out);
        ([out[0], out[1]], [out[2], out[3]])
    }

    /// The normal of the cone's edge toward `+T` (`ahead`: `μN − T`) or toward `−T`
    /// (`μN + T`), as the two univariate splines `μ o q⊥ ∓ q`.
    fn edge_normal(&self, mu: f64, ahead: bool) -> Result<(BSpline, BSpline)> {
        let (o, sign) = (self.orientation, if ahead { -1.0 } else { 1.0 });
        // q⊥ = (−qy, qx).
        Ok((
            self.qy.lincomb(-mu * o, &self.qx, sign)?,
            self.qx.lincomb(mu * o, &self.qy, sign)?,
        ))
    }

    /// The edge normal of [`Form::edge_normal`] at one hodograph point `q`.
    pub(crate) fn edge_normal_at(&self, q: [f64; 2], mu: f64, ahead: bool) -> [f64; 2] {
        let (o, sign) = (self.orientation, if ahead { -1.0 } else { 1.0 });
        [-mu * o * q[1] + sign * q[0], mu * o * q[0] + sign * q[1]]
    }

    /// The control points of `q` over `[lo, hi]` (inside the domain): the directions every
    /// chord of that arc is a positive combination of.
    pub(crate) fn hodograph_points(&self, lo: f64, hi: f64, out: &mut Vec<[f64; 2]>) {
        for piece in &self.q_pieces {
            if piece.b <= lo || piece.a >= hi {
                continue;
            }
            let mut p = piece.clone();
            if lo > p.a {
                p = p.split(lo).1;
            }
            if hi < p.b {
                p = p.split(hi).0;
            }
            out.extend(p.coefs.chunks_exact(2).map(|c| [c[0], c[1]]));
        }
    }
}

/// The functions of one variable for a contact at the fixed point `corner` and `t` on `b`
/// (each times `w(t) > 0`): the cone conditions at `t` (`⟨μN ∓ T, corner − C(t)⟩`), then the
/// width conditions, then `×(edge, C(t) − corner)` for each edge normal of the corner's
/// widened cone (which the caller combines by its width).
pub(crate) fn corner_functions(
    b: &Form,
    corner: [f64; 2],
    edges: [[f64; 2]; 2],
    mu: f64,
    widths: [Option<f64>; 2],
) -> Result<(Vec<BSpline>, [BSpline; 2])> {
    // e = corner w(t) − P(t), that is w (corner − C).
    let ex = b.w.lincomb(corner[0], &b.x, -1.0)?;
    let ey = b.w.lincomb(corner[1], &b.y, -1.0)?;
    let mut holds = Vec::with_capacity(4);
    for ahead in [false, true] {
        let (wx, wy) = b.edge_normal(mu, ahead)?;
        holds.push(wx.mul(&ex)?.add(&wy.mul(&ey)?)?);
    }
    let sq = ex.mul(&ex)?.add(&ey.mul(&ey)?)?;
    let w2 = b.w.mul(&b.w)?;
    if let Some(least) = widths[0] {
        holds.push(sq.lincomb(1.0, &w2, -least * least)?);
    }
    if let Some(most) = widths[1] {
        holds.push(w2.lincomb(most * most, &sq, -1.0)?);
    }
    // ×(edge, C − corner) w = −×(edge, e) = ey·edge_x... : edge × (−e).
    let side = |edge: [f64; 2]| ey.lincomb(-edge[0], &ex, edge[1]);
    Ok((holds, [side(edges[0])?, side(edges[1])?]))
}

/// The functions of force closure for contacts at `s` on `a` and `t` on `b`, in this order:
/// `d` not beyond the edge of the cone at `s` toward `−T(s)` (`⟨μN + T, d⟩ ≥ 0`), nor toward
/// `+T(s)` (`⟨μN − T, d⟩ ≥ 0`); the same for `−d` at `t`; then `|d|` at least the least width
/// and at most the greatest, where given.
pub(crate) fn functions(
    a: &Form,
    b: &Form,
    mu: f64,
    widths: [Option<f64>; 2],
) -> Result<Vec<TensorBSpline>> {
    let mut out = Vec::with_capacity(6);
    for ahead in [false, true] {
        // ⟨V(s), e⟩ = (Vx wA)(s) PBx(t) + (Vy wA)(s) PBy(t) − ⟨V, PA⟩(s) wB(t).
        let (vx, vy) = a.edge_normal(mu, ahead)?;
        let dot = vx.mul(&a.x)?.add(&vy.mul(&a.y)?)?;
        let f = TensorBSpline::sum_of_outer(&[
            (vx.mul(&a.w)?, b.x.clone()),
            (vy.mul(&a.w)?, b.y.clone()),
            (dot.scale(-1.0), b.w.clone()),
        ])?;
        out.push(f);
    }
    for ahead in [false, true] {
        // ⟨W(t), −e⟩ = PAx(s) (Wx wB)(t) + PAy(s) (Wy wB)(t) − wA(s) ⟨W, PB⟩(t).
        let (wx, wy) = b.edge_normal(mu, ahead)?;
        let dot = wx.mul(&b.x)?.add(&wy.mul(&b.y)?)?;
        let f = TensorBSpline::sum_of_outer(&[
            (a.x.clone(), wx.mul(&b.w)?),
            (a.y.clone(), wy.mul(&b.w)?),
            (a.w.scale(-1.0), dot),
        ])?;
        out.push(f);
    }
    if widths.iter().any(Option::is_some) {
        // |e|² = Σ_c (PBc wA − PAc wB)²; the width w bounds it by w² wA² wB².
        let (wa2, wb2) = (a.w.mul(&a.w)?, b.w.mul(&b.w)?);
        let mut sq = Vec::with_capacity(7);
        for (pa, pb) in [(&a.x, &b.x), (&a.y, &b.y)] {
            sq.push((wa2.clone(), pb.mul(pb)?));
            sq.push((pa.mul(&a.w)?.scale(-2.0), pb.mul(&b.w)?));
            sq.push((pa.mul(pa)?, wb2.clone()));
        }
        let [least, most] = widths;
        if let Some(wmin) = least {
            let mut terms = sq.clone();
            terms.push((wa2.scale(-wmin * wmin), wb2.clone()));
            out.push(TensorBSpline::sum_of_outer(&terms)?);
        }
        if let Some(wmax) = most {
            let mut terms: Vec<(BSpline, BSpline)> =
                sq.iter().map(|(f, g)| (f.scale(-1.0), g.clone())).collect();
            terms.push((wa2.scale(wmax * wmax), wb2));
            out.push(TensorBSpline::sum_of_outer(&terms)?);
        }
    }
    Ok(out)
}
