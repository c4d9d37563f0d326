//! The bisector point of two matched foot points and the residual of the three bisector
//! conditions there: plain geometry of the curves, apart from the zero-set search and cleaning.

use super::jets::Jets;
use bspline::Rational;
use numeric::rounding::ulps;

/// Largest relative residual of the three bisector conditions for a reported point: the
/// largest of `| |P − C1| − |P − C2| |` and the two foot-point orthogonalities
/// `|⟨P − Ci, Ci'⟩| / |Ci'|`, divided by the larger distance `|P − Ci|` — but by no less than
/// 1e-6 of the coordinate size (bounding-box diagonal plus distance of its centre from the
/// origin), so that where the curves cross the requirement stays above what doubles hold.
pub const RESIDUAL: f64 = 1e-9;

/// Residuals are relative to the distance from the foot points, but never to less than this
/// fraction of the size of the coordinates (bounding-box diagonal plus distance of its
/// centre from the origin): the coordinates themselves carry rounding errors of ~1e-16 of
/// that size, so where the curves cross (distances → 0) a purely relative test would ask for
/// more than doubles hold. 1e-6 keeps the absolute requirement there at 1e-15 of the size.
pub(super) const FLOOR: f64 = 1e-6;

/// The largest relative residual of the three bisector conditions at `P` for the foot points
/// `c1` (tangent `d1`) and `c2` (tangent `d2`); `floor` keeps it finite where the foot points
/// meet (where the curves intersect, the intersection point is on the bisector).
fn residual(
    p: [f64; 2],
    c1: [f64; 2],
    d1: [f64; 2],
    c2: [f64; 2],
    d2: [f64; 2],
    floor: f64,
) -> f64 {
    let v1 = [p[0] - c1[0], p[1] - c1[1]];
    let v2 = [p[0] - c2[0], p[1] - c2[1]];
    // Plain square roots: hypot's care about overflow is not needed (a huge or infinite
    // candidate fails the test either way) and it was a visible cost.
    let norm = |x: [f64; 2]| (x[0] * x[0] + x[1] * x[1]).sqrt();
    let (r1, r2) = (norm(v1), norm(v2));
    let rho = r1.max(r2).max(floor);
    let o1 = (v1[0] * d1[0] + v1[1] * d1[1]).abs() / norm(d1).max(f64::MIN_POSITIVE);
    let o2 = (v2[0] * d2[0] + v2[1] * d2[1]).abs() / norm(d2).max(f64::MIN_POSITIVE);
    (r1 - r2).abs().max(o1).max(o2) / rho
}

/// The bisector point `P(t, r)` for matched foot points, with its relative residual.
///
/// Three candidates, each `P = C + λ N` on a normal line: the intersection of the two normal
/// lines (Eq. 16, solved on the first normal line so far coordinates do not enter), and the
/// equidistant point along each normal line (accurate where the normals nearly coincide).
///
/// Each formula divides by a quantity that can vanish: the intersection by the sine of the
/// angle between the normals, the equidistant points by the component of the chord
/// `C1 − C2` along the normal, which is second order in the gap where the two foot points
/// close in on one point of a curve. The residual cannot tell the candidates apart there:
/// moving `P` along the normal changes `|P − C1| − |P − C2|` only by the angle squared, so
/// a point 1e-2 of the size off passed the residual test beside a self-bisector's end. So
/// among the candidates that meet [`RESIDUAL`], the one with the least estimated rounding
/// error wins; failing that, the least residual (which the caller then rejects).
pub(super) fn point_and_residual(
    c1: &Jets,
    c2: &Jets,
    t: f64,
    r: f64,
    floor: f64,
) -> Option<([f64; 2], f64)> {
    let (p1, d1) = c1.point_tangent(t);
    let (p2, d2) = c2.point_tangent(r);
    let dot = |x: [f64; 2], y: [f64; 2]| x[0] * y[0] + x[1] * y[1];
    let norm = |x: [f64; 2]| dot(x, x).sqrt();
    let d = [p1[0] - p2[0], p1[1] - p2[1]];
    let dd = dot(d, d);
    let (n1, n2) = ([-d1[1], d1[0]], [-d2[1], d2[0]]);
    // Rounding of the evaluated points (their coordinates' size) and of the chord.
    let point_err =
        EVAL_ROUNDING * (p1[0].abs().max(p1[1].abs()) + p2[0].abs().max(p2[1].abs()) + norm(d));
    let at = |c: [f64; 2], n: [f64; 2], lambda: f64| [c[0] + lambda * n[0], c[1] + lambda * n[1]];
    // (point, estimated error of the point)
    let mut cands: [Option<([f64; 2], f64)>; 3] = [None; 3];
    let den = dot(n1, d2);
    if den != 0.0 {
        // (C1 − C2 + λ N1) · C2' = 0.
        let lambda = -dot(d, d2) / den;
        let (nn1, nd2) = (norm(n1), norm(d2));
        let err = nn1 * (point_err * nd2 + EVAL_ROUNDING * lambda.abs() * nn1 * nd2) / den.abs();
        cands[0] = Some((at(p1, n1, lambda), err));
    }
    if dd == 0.0 {
        cands[1] = Some((p1, point_err));
    } else {
        // P = C1 + α N1 with |α N1|² = |P − C2|²  ⇒  α = −|d|² / (2 ⟨N1, d⟩); likewise on N2.
        for (k, c, n, sign) in [(1, p1, n1, -1.0), (2, p2, n2, 1.0)] {
            let s = dot(n, d);
            if s != 0.0 {
                let alpha = sign * dd / (2.0 * s);
                let nn = norm(n);
                let rel = 2.0 * point_err / norm(d) + nn * point_err / s.abs();
                cands[k] = Some((at(c, n, alpha), alpha.abs() * nn * rel));
            }
        }
    }
    // In order of estimated error, the first to meet the residual test.
    let rank = |c: &Option<([f64; 2], f64)>| c.map_or(f64::INFINITY, |c| c.1);
    cands.sort_by(|a, b| rank(a).total_cmp(&rank(b)));
    let finite = |p: &[f64; 2]| p[0].is_finite() && p[1].is_finite();
    let mut least: Option<([f64; 2], f64)> = None;
    for (p, _) in cands.into_iter().flatten().filter(|(p, _)| finite(p)) {
        let res = residual(p, p1, d1, p2, d2, floor);
        if res <= RESIDUAL {
            return Some((p, res));
        }
        if least.is_none_or(|l| res < l.1) {
            least = Some((p, res));
        }
    }
    least
}

/// Relative rounding of an evaluated point or derivative, for comparing the candidates of
/// [`point_and_residual`]: a few units of rounding (de Boor's recurrence is a chain of convex
/// combinations, as is de Casteljau's); only the candidates' ratios matter, not the constant.
const EVAL_ROUNDING: f64 = ulps(4.0);

/// The bisector condition `ψ = 2 ⟨N1, d⟩ ⟨d, C2'⟩ − |d|² ⟨N1, C2'⟩` (with `d = C1 − C2`,
/// `N1` the normal of `C1`: the equidistant point on the normal line of `C1(t)` lies on the
/// normal line of `C2(r)`) and its partial derivatives. Cubic in `d`, so its rounding error
/// shrinks with `d` where the curves cross, unlike that of F3.
pub(super) fn psi(c1: &Jets, c2: &Jets, t: f64, r: f64) -> (f64, f64, f64) {
    let (a, b) = (c1.derivs(t, 2), c2.derivs(r, 2));
    let dot = |x: [f64; 2], y: [f64; 2]| x[0] * y[0] + x[1] * y[1];
    let d = [a[0] - b[0], a[1] - b[1]];
    let (d1, e1) = ([a[2], a[3]], [a[4], a[5]]);
    let (d2, e2) = ([b[2], b[3]], [b[4], b[5]]);
    let n1 = [-d1[1], d1[0]];
    let m1 = [-e1[1], e1[0]];
    let (s, g, dd, k) = (dot(n1, d), dot(d, d2), dot(d, d), dot(n1, d2));
    let v = 2.0 * s * g - dd * k;
    let (s_t, g_t, dd_t, k_t) = (dot(m1, d), dot(d1, d2), 2.0 * dot(d, d1), dot(m1, d2));
    let (s_r, g_r, dd_r, k_r) = (
        -dot(n1, d2),
        dot(d, e2) - dot(d2, d2),
        -2.0 * dot(d, d2),
        dot(n1, e2),
    );
    (
        v,
        2.0 * (s_t * g + s * g_t) - (dd_t * k + dd * k_t),
        2.0 * (s_r * g + s * g_r) - (dd_r * k + dd * k_r),
    )
}

/// The bisector point of the foot points `c1(t)`, `c2(r)` if they are matched (residual of the
/// bisector conditions ≤ [`RESIDUAL`]), else `None`.
///
/// ```
/// use bspline::{BSpline, Rational};
/// use zeroset::bisector_point;
/// // Segments on the axes, c1(t) = (1 + 2t, 0) and c2(r) = (0, 1 + 2r): the feet (2, 0) and
/// // (0, 2) are matched at the point (2, 2); the feet (2, 0) and (0, 1) are not.
/// let c1 = Rational::polynomial(&BSpline::bezier(2, vec![1.0, 0.0, 3.0, 0.0]).unwrap());
/// let c2 = Rational::polynomial(&BSpline::bezier(2, vec![0.0, 1.0, 0.0, 3.0]).unwrap());
/// let p = bisector_point(&c1, &c2, 0.5, 0.5).unwrap();
/// assert!((p[0] - 2.0).abs() < 1e-12 && (p[1] - 2.0).abs() < 1e-12);
/// assert_eq!(bisector_point(&c1, &c2, 0.5, 0.0), None);
/// ```
pub fn bisector_point(c1: &Rational, c2: &Rational, t: f64, r: f64) -> Option<[f64; 2]> {
    let (center, diag) = bbox(&[c1, c2]);
    let floor = FLOOR * (diag + center[0].hypot(center[1]));
    point_and_residual(&Jets::of(c1), &Jets::of(c2), t, r, floor)
        .and_then(|(p, res)| (res <= RESIDUAL).then_some(p))
}

/// Bounding box of the control points: (centre, diagonal).
pub(super) fn bbox(curves: &[&Rational]) -> ([f64; 2], f64) {
    let pts: Vec<[f64; 2]> = curves
        .iter()
        .flat_map(|c| c.control_points())
        .map(|p| [p[0], p[1]])
        .collect();
    bbox_of_points(&pts)
}

/// The size the chord tolerance of the bisector of `curves` is relative to: the contract's
/// max(width, height) of the box of their points (the diagonal of their control points' box
/// where that cannot be found, or for a single point).
pub(crate) fn chord_size(curves: &[&Rational]) -> f64 {
    match curve::curves_box(curves).map(curve::box_size) {
        Ok(size) if size > 0.0 && size.is_finite() => size,
        _ => bbox(curves).1,
    }
}

/// The centre and diagonal of the box of `points` (a diagonal of 1 for a single point).
pub(crate) fn bbox_of_points(points: &[[f64; 2]]) -> ([f64; 2], f64) {
    let (lo, hi) = bounds(points);
    let diag = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
    (
        [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])],
        if diag > 0.0 { diag } else { 1.0 },
    )
}

/// The lower and upper corners of the box of `points`.
fn bounds(points: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}
