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
use numeric::rounding::gamma;

/// One exact curve form's univariate parts.
///
/// With the cone edge's normal `V = μ o q⊥ ± q` at a contact on this form and `P`, `w` the
/// other contact's, the cone function `⟨V w, P_other⟩ − ⟨V, P⟩ w_other` is `Σ_k a_k ⊗ b_k`
/// over the factors `a = [V_x w, V_y w, −⟨V, P⟩]` and `b = [x, y, w]` of the other: `μ` times
/// its normal part (`V = o q⊥`) plus or minus its tangent part (`V = q`). Those parts do not
/// depend on the friction and are kept here, each set of factors in one spline space (so the
/// sums of outer products need no harmonising per pair of forms).
pub(crate) struct Form {
    /// Homogeneous coordinates and the weight (the constant 1 for a polynomial curve):
    /// `[x, y, w]`.
    point: [BSpline; 3],
    /// The factors of the normal part, `[o q⊥_x w, o q⊥_y w, −⟨o q⊥, P⟩]`, with the hodograph's
    /// numerator `q = P'w − Pw'` (`C'` itself for a polynomial curve).
    normal: [BSpline; 3],
    /// The factors of the tangent part, `[q_x w, q_y w, −⟨q, P⟩]`.
    tangent: [BSpline; 3],
    /// `q` as Bézier pieces (dimension 2), for the cone test near the diagonal.
    q_pieces: Vec<Bezier>,
    /// The curve itself, for evaluation.
    curve: Rational,
    /// For a straight segment of degree one, its start and its constant derivative: the
    /// point and tangent without the general evaluation (the searches for best grasps ask
    /// for thousands).
    line: Option<[[f64; 2]; 2]>,
    /// `+1` counterclockwise, `−1` clockwise: `N = orientation · T⊥`.
    orientation: f64,
}

/// A straight segment's start and its constant derivative.
fn straight(curve: &Rational) -> Option<[[f64; 2]; 2]> {
    let [p, q] = curve.straight_ends()?;
    let (a, b) = curve.domain();
    let h = b - a;
    // (The derivative from the ends, so the line runs exactly through both.)
    Some([[p[0], p[1]], [(q[0] - p[0]) / h, (q[1] - p[1]) / h]])
}

/// `parts` in one spline space (common degree, merged knots).
fn in_one_space(parts: [BSpline; 3]) -> Result<[BSpline; 3]> {
    // (Stacking harmonises its parts; the components are the parts in the common space.)
    let stacked = BSpline::stack(&[&parts[0], &parts[1], &parts[2]])?;
    Ok([
        stacked.component(0)?,
        stacked.component(1)?,
        stacked.component(2)?,
    ])
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
        let o = orientation;
        // o q⊥ = o (−q_y, q_x).
        let (nx, ny) = (qy.scale(-o), qx.scale(o));
        let factors = |vx: &BSpline, vy: &BSpline| -> Result<[BSpline; 3]> {
            let dot = vx.mul(&x)?.add(&vy.mul(&y)?)?;
            in_one_space([vx.mul(&w)?, vy.mul(&w)?, dot.scale(-1.0)])
        };
        let normal = factors(&nx, &ny)?;
        let tangent = factors(&qx, &qy)?;
        Ok(Self {
            point: in_one_space([x, y, w])?,
            normal,
            tangent,
            q_pieces,
            line: straight(curve),
            curve: curve.clone(),
            orientation,
        })
    }

    /// The same form on `[lo, hi]` (inside the domain): the functions of a box of pairs
    /// are built from their contacts' stretches, not cut out of the whole cell's.
    pub(crate) fn restrict(&self, lo: f64, hi: f64) -> Result<Self> {
        // (Splines of one space restricted alike stay in one space.)
        let cut = |fs: &[BSpline; 3]| -> Result<[BSpline; 3]> {
            Ok([
                fs[0].restrict(lo, hi)?,
                fs[1].restrict(lo, hi)?,
                fs[2].restrict(lo, hi)?,
            ])
        };
        let q_pieces = self
            .q_pieces
            .iter()
            .filter(|p| p.b > lo && p.a < hi)
            .map(|p| {
                let mut p = p.clone();
                if lo > p.a {
                    p = p.split(lo).1;
                }
                if hi < p.b {
                    p = p.split(hi).0;
                }
                p
            })
            .collect();
        Ok(Self {
            point: cut(&self.point)?,
            normal: cut(&self.normal)?,
            tangent: cut(&self.tangent)?,
            q_pieces,
            line: self.line.map(|[start, d]| {
                let a = self.domain().0;
                [[start[0] + (lo - a) * d[0], start[1] + (lo - a) * d[1]], d]
            }),
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
        if let Some([start, d]) = self.line {
            let h = v.clamp(a, b) - a;
            return ([start[0] + h * d[0], start[1] + h * d[1]], d);
        }
        let mut out = [0.0; 4];
        self.curve.eval_derivs(v.clamp(a, b), 1, &mut out);
        ([out[0], out[1]], [out[2], out[3]])
    }

    /// The normal of the cone's edge toward `+T` (`ahead`: `μN − T`) or toward `−T`
    /// (`μN + T`) at one hodograph point `q`.
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

/// `Σ_k c_k f_k` for factors in one spline space.
fn combine(c: [f64; 3], fs: &[BSpline; 3]) -> Result<BSpline> {
    Ok(fs[0]
        .lincomb(c[0], &fs[1], c[1])?
        .lincomb(1.0, &fs[2], c[2])?)
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
    // With e = corner w(t) − P(t), that is w (corner − C): ⟨V, e⟩ = Σ_k [corner, 1]_k a_k.
    let at = [corner[0], corner[1], 1.0];
    let (normal, tangent) = (combine(at, &b.normal)?, combine(at, &b.tangent)?);
    let mut holds = Vec::with_capacity(4);
    for ahead in [false, true] {
        holds.push(normal.lincomb(mu, &tangent, if ahead { -1.0 } else { 1.0 })?);
    }
    let [x, y, w] = &b.point;
    let ex = w.lincomb(corner[0], x, -1.0)?;
    let ey = w.lincomb(corner[1], y, -1.0)?;
    if widths.iter().any(Option::is_some) {
        let sq = ex.mul(&ex)?.add(&ey.mul(&ey)?)?;
        let w2 = w.mul(w)?;
        if let Some(least) = widths[0] {
            holds.push(sq.lincomb(1.0, &w2, -least * least)?);
        }
        if let Some(most) = widths[1] {
            holds.push(w2.lincomb(most * most, &sq, -1.0)?);
        }
    }
    // ×(edge, C − corner) w = −×(edge, e) = ey·edge_x... : edge × (−e).
    let side = |edge: [f64; 2]| ey.lincomb(-edge[0], &ex, edge[1]);
    Ok((holds, [side(edges[0])?, side(edges[1])?]))
}

/// [`corner_functions`] on a straight segment `b` (without width limits), where every one is
/// affine: each function's values at the segment's two ends, with a bound on their rounding
/// (from the magnitudes of the terms, which cancel where a value is small).
pub(crate) fn straight_corner_ends(
    b: &Form,
    corner: [f64; 2],
    edges: [[f64; 2]; 2],
    mu: f64,
) -> Option<[[(f64, f64); 2]; 4]> {
    let [start, q] = b.line?;
    let (lo, hi) = b.domain();
    let o = b.orientation;
    let normal = [-o * q[1], o * q[0]];
    let dot = |a: [f64; 2], e: [f64; 2]| a[0] * e[0] + a[1] * e[1];
    let at = |v: f64| {
        let h = v - lo;
        let e = [
            corner[0] - (start[0] + h * q[0]),
            corner[1] - (start[1] + h * q[1]),
        ];
        let size = e[0].abs() + e[1].abs();
        let (n, t) = (dot(normal, e), dot(q, e));
        // (e itself is rounded: a few units of the points' magnitudes.)
        let reach = size + corner[0].abs() + corner[1].abs() + start[0].abs() + start[1].abs();
        let q_size = q[0].abs() + q[1].abs();
        let cone_err = gamma(8) * (1.0 + mu) * q_size * reach;
        let side = |edge: [f64; 2]| {
            let err = gamma(6) * (edge[0].abs() + edge[1].abs()) * reach;
            (e[0] * edge[1] - e[1] * edge[0], err)
        };
        [
            (mu * n + t, cone_err),
            (mu * n - t, cone_err),
            side(edges[0]),
            side(edges[1]),
        ]
    };
    let (a, z) = (at(lo), at(hi));
    Some([[a[0], z[0]], [a[1], z[1]], [a[2], z[2]], [a[3], z[3]]])
}

/// `Σ_k f_k ⊗ g_k`.
fn outer_sum(fs: &[BSpline; 3], gs: &[BSpline; 3]) -> Result<TensorBSpline> {
    Ok(TensorBSpline::sum_of_outer(&[
        (&fs[0], &gs[0]),
        (&fs[1], &gs[1]),
        (&fs[2], &gs[2]),
    ])?)
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
    // At s: ⟨V(s), e⟩ with e = P_b(t) w_a(s) − P_a(s) w_b(t). At t: ⟨W(t), −e⟩, the same
    // sum with the forms' roles exchanged.
    let at_s = [
        outer_sum(&a.normal, &b.point)?,
        outer_sum(&a.tangent, &b.point)?,
    ];
    let at_t = [
        outer_sum(&a.point, &b.normal)?,
        outer_sum(&a.point, &b.tangent)?,
    ];
    for [normal, tangent] in [&at_s, &at_t] {
        for ahead in [false, true] {
            out.push(normal.lincomb(mu, tangent, if ahead { -1.0 } else { 1.0 })?);
        }
    }
    if widths.iter().any(Option::is_some) {
        // |e|² = Σ_c (PBc wA − PAc wB)²; the width w bounds it by w² wA² wB².
        let ([ax, ay, aw], [bx, by, bw]) = (&a.point, &b.point);
        let (wa2, wb2) = (aw.mul(aw)?, bw.mul(bw)?);
        let mut sq = Vec::with_capacity(7);
        for (pa, pb) in [(ax, bx), (ay, by)] {
            sq.push((wa2.clone(), pb.mul(pb)?));
            sq.push((pa.mul(aw)?.scale(-2.0), pb.mul(bw)?));
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
