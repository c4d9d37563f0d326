//! Which vertices of the zero set are bisector points: the context of one computation, the
//! residual test with its Newton polish on ψ, the half `t < r` and the trimming. One vertex at
//! a time; the branches built from them are in `output`.

use super::jets::Jets;
use super::point::{point_and_residual, psi, FLOOR, RESIDUAL};
use bspline::Rational;

/// Points farther than this many bounding-box diagonals count as points at infinity.
pub(crate) const FAR: f64 = 1e3;

/// Newton steps when polishing a vertex on the bisector condition.
const MAX_POLISH: usize = 8;

/// Largest move of a polished vertex, relative to the domain.
const MOVE: f64 = 1e-6;

/// Self-bisector vertices closer than this (relative to the domain) to the diagonal are
/// dropped: their foot points (nearly) coincide.
pub(super) const DIAGONAL_MARGIN: f64 = 1e-9;

/// The (self-bisector) curve closes when its end points agree to this fraction of the
/// bounding-box diagonal: a closed curve's ends are one control point, evaluated to rounding
/// (~1e-16 of the size) from either end.
const CLOSED_POINT: f64 = 1e-12;

/// The curve closes only if its end tangents also agree to this fraction of their length:
/// they come from different control points at either end and carry more rounding than the
/// points.
const CLOSED_TANGENT: f64 = 1e-9;

/// A trimmed bisector drops a point when a curve comes nearer to it than its foot point by
/// more than this (relative to the bounding-box diagonal): the point holds the bisector
/// conditions only to [`RESIDUAL`] of the distances, so the nearest foot point may seem
/// farther by about that.
pub(crate) const TRIM_SLACK: f64 = 1e-9;

/// Context shared by the two entry points.
pub(super) struct Ctx<'a> {
    pub(super) c1: &'a Rational,
    pub(super) c2: &'a Rational,
    /// The two curves prepared for evaluation (the same curve twice for a self-bisector).
    pub(super) jets1: Jets,
    pub(super) jets2: Jets,
    pub(super) center: [f64; 2],
    pub(super) diag: f64,
    pub(super) selfb: bool,
    pub(super) trimmed: bool,
    /// The chord tolerance (absolute).
    pub(super) chord: f64,
}

impl Ctx<'_> {
    /// Whether the (self-bisector) curve closes: start and end points and tangents agree.
    pub(super) fn is_closed(&self) -> bool {
        let (a, b) = self.c1.domain();
        let ((p, d), (q, e)) = (self.jets1.point_tangent(a), self.jets1.point_tangent(b));
        let tol = CLOSED_POINT * self.diag;
        let dn = d[0].hypot(d[1]).max(f64::MIN_POSITIVE);
        (p[0] - q[0]).hypot(p[1] - q[1]) <= tol
            && (d[0] - e[0]).hypot(d[1] - e[1]) <= CLOSED_TANGENT * dn
    }

    pub(super) fn map(&self, t: f64, r: f64) -> Option<[f64; 2]> {
        self.valid(t, r).map(|(_, p)| p)
    }

    /// The vertex `(t, r)`, polished if needed, and its bisector point, when they are a
    /// genuine finite bisector point (residual ≤ [`RESIDUAL`], not at infinity).
    ///
    /// A vertex refined on `F = 0` is as accurate as `F` is well conditioned: near a point
    /// where the two curves cross, F3 vanishes to second order (its zero set has a crossing
    /// there: the two angle bisectors), so the vertex is off by ~rounding / distance and the
    /// residual, relative to the tiny distances, fails within ~1e-3 of the crossing. Such a
    /// vertex is polished by Newton on the bisector condition itself ([`psi`]), whose
    /// rounding error shrinks with the distances; it may move by at most [`MOVE`] of the
    /// domain (a vertex of the redundant parallel-normal component of F1/F2 or beside a
    /// point at infinity does not converge nearby and stays rejected).
    fn valid(&self, t: f64, r: f64) -> Option<([f64; 2], [f64; 2])> {
        let (d1, d2) = (self.c1.domain(), self.c2.domain());
        // (A point the assembly located at a domain's edge may stand outside it by rounding.)
        let (t, r) = (t.clamp(d1.0, d1.1), r.clamp(d2.0, d2.1));
        let floor = self.floor();
        let far =
            |p: [f64; 2]| (p[0] - self.center[0]).hypot(p[1] - self.center[1]) > FAR * self.diag;
        if let Some((p, res)) = point_and_residual(&self.jets1, &self.jets2, t, r, floor) {
            if res <= RESIDUAL {
                return (!far(p)).then_some(([t, r], p));
            }
        }
        let (e1, e2) = (d1.1 - d1.0, d2.1 - d2.0);
        let mut q = [t, r];
        for _ in 0..MAX_POLISH {
            let (v, gt, gr) = psi(&self.jets1, &self.jets2, q[0], q[1]);
            // Newton toward ψ = 0 along its gradient, in coordinates scaled by the domains.
            let (st, sr) = (gt * e1, gr * e2);
            let g2 = st * st + sr * sr;
            if g2 == 0.0 || !g2.is_finite() {
                return None;
            }
            q = [q[0] - v * st / g2 * e1, q[1] - v * sr / g2 * e2];
            if !(q[0] >= d1.0 && q[0] <= d1.1 && q[1] >= d2.0 && q[1] <= d2.1) {
                return None;
            }
            if ((q[0] - t) / e1).hypot((q[1] - r) / e2) > MOVE {
                return None;
            }
            if let Some((p, res)) = point_and_residual(&self.jets1, &self.jets2, q[0], q[1], floor)
            {
                if res <= RESIDUAL {
                    return (!far(p)).then_some((q, p));
                }
            }
        }
        None
    }

    /// The distance below which residuals are measured absolutely (see [`FLOOR`]).
    fn floor(&self) -> f64 {
        FLOOR * (self.diag + self.center[0].hypot(self.center[1]))
    }

    /// Whether a vertex belongs in the output (valid point, right half, trimmed if asked).
    /// Returns the (possibly polished) vertex and its bisector point.
    pub(super) fn accept(&self, t: f64, r: f64) -> Option<([f64; 2], [f64; 2])> {
        let half = |q: [f64; 2]| {
            let ext = self.c1.domain().1 - self.c1.domain().0;
            !self.selfb || q[1] - q[0] > DIAGONAL_MARGIN * ext
        };
        if !half([t, r]) {
            return None;
        }
        let (q, p) = self.valid(t, r)?;
        if !half(q) {
            return None;
        }
        if self.trimmed {
            let (q1, _) = self.jets1.point_tangent(q[0]);
            let rho = (p[0] - q1[0]).hypot(p[1] - q1[1]);
            let slack = TRIM_SLACK * self.diag;
            if min_dist(self.c1, p) < rho - slack || min_dist(self.c2, p) < rho - slack {
                return None;
            }
        }
        Some((q, p))
    }
}

/// Distance from `p` to the curve: dense samples, then Newton on `⟨C − p, C'⟩ = 0` from every
/// sampled local minimum (not certified: a feature narrower than the sampling can be missed).
fn min_dist(c: &Rational, p: [f64; 2]) -> f64 {
    let (a, b) = c.domain();
    let n = 64 * c.homogeneous().breakpoints().len().max(2);
    let dist = |u: f64| {
        let q = c.point(u);
        (q[0] - p[0]).hypot(q[1] - p[1])
    };
    let us: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    let ds: Vec<f64> = us.iter().map(|&u| dist(u)).collect();
    let mut best = ds.iter().fold(f64::INFINITY, |m, &d| m.min(d));
    for i in 1..n {
        if ds[i] <= ds[i - 1] && ds[i] <= ds[i + 1] {
            let mut u = us[i];
            for _ in 0..20 {
                let mut o = [0.0; 6];
                c.eval_derivs(u, 2, &mut o);
                let v = [o[0] - p[0], o[1] - p[1]];
                let g = v[0] * o[2] + v[1] * o[3];
                let h = o[2] * o[2] + o[3] * o[3] + v[0] * o[4] + v[1] * o[5];
                if h <= 0.0 {
                    break;
                }
                u = (u - g / h).clamp(us[i - 1], us[i + 1]);
            }
            best = best.min(dist(u));
        }
    }
    best
}
