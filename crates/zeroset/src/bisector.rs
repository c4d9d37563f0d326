//! Bisectors of two planar curves and self-bisectors (Elber & Kim): the zero set of `F(t, r)`
//! mapped to bisector points and cleaned.
//!
//! Cleaning: a vertex is kept only when its point `P(t, r)` is a genuine, finite bisector point
//! (equidistant from both foot points, on both normal lines, to a relative residual of
//! [`RESIDUAL`]). This drops the parallel-normal component of `F1`/`F2` (Eq. 4) and the points
//! at infinity; a branch is split where it leaves the valid set. A vertex that fails only
//! because `F` is ill-conditioned there (beside a point where the curves cross, a crossing of
//! the zero set) is first polished by Newton on the bisector condition itself. For the
//! self-bisector the trivial diagonal `t = r` is divided out of the diagonal Bézier cells
//! symbolically (`(t − r)⁴` for F3, `(t − r)⁵` for F1 and F2), only the half `t ≤ r` is
//! searched, and mirrored parts are clipped at the diagonal.

use crate::error::{Error, Result};
use crate::extract::Pieces;
use crate::patch::Patch;
use crate::symbolic::{bisector_function_scaled, Method};
use crate::zeroset::{finish, run_cells, ZeroSetOptions};
use bspline::Rational;
use curve::Frame;
use serde::{Deserialize, Serialize};

/// Largest relative residual of the three bisector conditions for a reported point: the
/// largest of `| |P − C1| − |P − C2| |` and the two foot-point orthogonalities
/// `|⟨P − Ci, Ci'⟩| / |Ci'|`, divided by the larger distance `|P − Ci|` — but by no less than
/// 1e-6 of the coordinate size (bounding-box diagonal plus distance of its centre from the
/// origin), so that where the curves cross the requirement stays above what doubles hold.
pub const RESIDUAL: f64 = 1e-9;
/// Points farther than this many bounding-box diagonals count as points at infinity.
const FAR: f64 = 1e3;
/// Residuals are relative to the distance from the foot points, but never to less than this
/// fraction of the size of the coordinates (bounding-box diagonal plus distance of its
/// centre from the origin): the coordinates themselves carry rounding errors of ~1e-16 of
/// that size, so where the curves cross (distances → 0) a purely relative test would ask for
/// more than doubles hold. 1e-6 keeps the absolute requirement there at 1e-15 of the size.
const FLOOR: f64 = 1e-6;
/// Newton steps when polishing a vertex on the bisector condition.
const MAX_POLISH: usize = 8;
/// Largest move of a polished vertex, relative to the domain.
const MOVE: f64 = 1e-6;
/// Self-bisector vertices closer than this (relative to the domain) to the diagonal are
/// dropped: their foot points (nearly) coincide.
const DIAGONAL_MARGIN: f64 = 1e-9;
/// A self-bisector branch ending this close (relative to the domain) to a knot corner of the
/// diagonal, on the cell across it, is extended to the corner.
const CORNER_REACH: f64 = 1e-3;
/// Halvings toward a knot corner at most (from ~1e-5 of the domain down to ~1e-11).
const MAX_CORNER_STEPS: usize = 20;
/// Relative residual below which a diagonal cell counts as divisible by `t − r`.
const DIVISIBLE: f64 = 1e-8;

/// Options for [`bisector`] and [`self_bisector`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BisectorOptions {
    /// Which function of §3 to use (default `F3`).
    pub method: Method,
    /// Parameter tolerance relative to the domains (default 1e-12).
    pub tol: f64,
    /// Chord tolerance relative to the curves' bounding-box diagonal (default 1e-3): the
    /// bisector polylines stay this close to the bisector in the plane.
    pub chord_tol: f64,
    /// Keep only points whose foot points are the nearest points of the curves.
    pub trimmed: bool,
    /// Patch limit of the zero-set search.
    pub max_patches: usize,
}

impl Default for BisectorOptions {
    fn default() -> Self {
        Self {
            method: Method::F3,
            tol: 1e-12,
            chord_tol: 1e-3,
            trimmed: false,
            max_patches: 200_000,
        }
    }
}

/// One branch: matched foot-point parameters and the bisector points they give.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Branch {
    /// `[t, r]` per vertex.
    pub tr: Vec<[f64; 2]>,
    /// `P(t, r)` per vertex.
    pub xy: Vec<[f64; 2]>,
}

/// A special point of the bisector.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BisectorPoint {
    /// Foot-point parameters.
    pub tr: [f64; 2],
    /// The bisector point.
    pub xy: [f64; 2],
}

/// The bisector of two curves, or the self-bisector of one.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Bisector {
    /// The branches.
    pub branches: Vec<Branch>,
    /// Where branches cross (singular points of the zero set).
    pub singular: Vec<BisectorPoint>,
    /// Isolated bisector points.
    pub isolated: Vec<BisectorPoint>,
    /// False when a search limit was hit.
    pub complete: bool,
}

/// Point, first derivative of a planar rational curve at `u`.
fn pd(c: &Rational, u: f64) -> ([f64; 2], [f64; 2]) {
    let mut o = [0.0; 4];
    c.eval_derivs(u, 1, &mut o);
    ([o[0], o[1]], [o[2], o[3]])
}

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
/// Three candidates: the intersection of the normal lines (Eq. 16, Cramer's rule) and the
/// equidistant point along each normal line (accurate where the normals nearly coincide); the
/// one with the smallest residual wins.
fn point_and_residual(
    c1: &Rational,
    c2: &Rational,
    t: f64,
    r: f64,
    floor: f64,
) -> Option<([f64; 2], f64)> {
    let (p1, d1) = pd(c1, t);
    let (p2, d2) = pd(c2, r);
    let d = [p1[0] - p2[0], p1[1] - p2[1]];
    let dd = d[0] * d[0] + d[1] * d[1];
    let mut cands: [Option<[f64; 2]>; 3] = [None; 3];
    let den = d1[0] * d2[1] - d1[1] * d2[0];
    if den != 0.0 {
        let a1 = p1[0] * d1[0] + p1[1] * d1[1];
        let a2 = p2[0] * d2[0] + p2[1] * d2[1];
        cands[0] = Some([
            (a1 * d2[1] - a2 * d1[1]) / den,
            (d1[0] * a2 - d2[0] * a1) / den,
        ]);
    }
    if dd == 0.0 {
        cands[1] = Some(p1);
    } else {
        // P = C1 + α N1 with |α N1|² = |P − C2|²  ⇒  α = −|d|² / (2 ⟨N1, d⟩).
        let n1 = [-d1[1], d1[0]];
        let s1 = n1[0] * d[0] + n1[1] * d[1];
        if s1 != 0.0 {
            let al = -dd / (2.0 * s1);
            cands[1] = Some([p1[0] + al * n1[0], p1[1] + al * n1[1]]);
        }
        let n2 = [-d2[1], d2[0]];
        let s2 = n2[0] * d[0] + n2[1] * d[1];
        if s2 != 0.0 {
            let be = dd / (2.0 * s2);
            cands[2] = Some([p2[0] + be * n2[0], p2[1] + be * n2[1]]);
        }
    }
    cands
        .iter()
        .flatten()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .map(|&p| (p, residual(p, p1, d1, p2, d2, floor)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

/// The bisector condition `ψ = 2 ⟨N1, d⟩ ⟨d, C2'⟩ − |d|² ⟨N1, C2'⟩` (with `d = C1 − C2`,
/// `N1` the normal of `C1`: the equidistant point on the normal line of `C1(t)` lies on the
/// normal line of `C2(r)`) and its partial derivatives. Cubic in `d`, so its rounding error
/// shrinks with `d` where the curves cross, unlike that of F3.
fn psi(c1: &Rational, c2: &Rational, t: f64, r: f64) -> (f64, f64, f64) {
    let (mut a, mut b) = ([0.0; 6], [0.0; 6]);
    c1.eval_derivs(t, 2, &mut a);
    c2.eval_derivs(r, 2, &mut b);
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
pub fn bisector_point(c1: &Rational, c2: &Rational, t: f64, r: f64) -> Option<[f64; 2]> {
    let (center, diag) = bbox(&[c1, c2]);
    let floor = FLOOR * (diag + center[0].hypot(center[1]));
    point_and_residual(c1, c2, t, r, floor).and_then(|(p, res)| (res <= RESIDUAL).then_some(p))
}

/// Bounding box of the control points: (centre, diagonal).
fn bbox(curves: &[&Rational]) -> ([f64; 2], f64) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for c in curves {
        for p in c.control_points() {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    let diag = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
    (
        [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])],
        if diag > 0.0 { diag } else { 1.0 },
    )
}

fn check(opts: &BisectorOptions) -> Result<ZeroSetOptions> {
    opts.validate()?;
    Ok(zero_set_options(opts))
}

fn zero_set_options(opts: &BisectorOptions) -> ZeroSetOptions {
    ZeroSetOptions {
        tol: opts.tol,
        chord_tol: opts.chord_tol,
        max_patches: opts.max_patches,
    }
}

impl BisectorOptions {
    /// Checks the options against what the computation can deliver (the bisector functions
    /// check them too): the parameter tolerance in `[1e-15, 1e-3)`, the chord tolerance in
    /// `[1e-9, 0.5]`.
    ///
    /// ```
    /// let opts = zeroset::BisectorOptions { chord_tol: 1e-12, ..Default::default() };
    /// assert!(opts.validate().is_err());
    /// ```
    pub fn validate(&self) -> Result<()> {
        zero_set_options(self).check()
    }
}

/// Context shared by the two entry points.
struct Ctx<'a> {
    c1: &'a Rational,
    c2: &'a Rational,
    center: [f64; 2],
    diag: f64,
    selfb: bool,
    trimmed: bool,
}

impl Ctx<'_> {
    /// Whether the (self-bisector) curve closes: start and end points and tangents agree.
    fn is_closed(&self) -> bool {
        let (a, b) = self.c1.domain();
        let ((p, d), (q, e)) = (pd(self.c1, a), pd(self.c1, b));
        let tol = 1e-12 * self.diag;
        let dn = d[0].hypot(d[1]).max(f64::MIN_POSITIVE);
        (p[0] - q[0]).hypot(p[1] - q[1]) <= tol && (d[0] - e[0]).hypot(d[1] - e[1]) <= 1e-9 * dn
    }

    fn map(&self, t: f64, r: f64) -> Option<[f64; 2]> {
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
        if let Some((p, res)) = point_and_residual(self.c1, self.c2, t, r, floor) {
            if res <= RESIDUAL {
                return (!far(p)).then_some(([t, r], p));
            }
        }
        let (e1, e2) = (d1.1 - d1.0, d2.1 - d2.0);
        let mut q = [t, r];
        for _ in 0..MAX_POLISH {
            let (v, gt, gr) = psi(self.c1, self.c2, q[0], q[1]);
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
            if let Some((p, res)) = point_and_residual(self.c1, self.c2, q[0], q[1], floor) {
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
    fn accept(&self, t: f64, r: f64) -> Option<([f64; 2], [f64; 2])> {
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
            let (q1, _) = pd(self.c1, q[0]);
            let rho = (p[0] - q1[0]).hypot(p[1] - q1[1]);
            let slack = 1e-9 * self.diag;
            if min_dist(self.c1, p) < rho - slack || min_dist(self.c2, p) < rho - slack {
                return None;
            }
        }
        Some((q, p))
    }

    fn build(&self, pieces: &Pieces, dom: [f64; 4], cells: &[Patch]) -> Bisector {
        let z = finish(pieces, dom, cells);
        let mut branches = Vec::new();
        for pl in &z.branches {
            let pts = if self.selfb {
                clip_diagonal(&pl.pts, DIAGONAL_MARGIN * (dom[1] - dom[0]), &|a, b| {
                    diagonal_end(cells, a, b, dom)
                })
            } else {
                pl.pts.iter().map(|&q| Some(q)).collect()
            };
            let mut cur = Branch {
                tr: Vec::new(),
                xy: Vec::new(),
            };
            for q in pts {
                match q.and_then(|q| self.accept(q[0], q[1])) {
                    Some((q, p)) => {
                        cur.tr.push(q);
                        cur.xy.push(p);
                    }
                    None => flush(&mut cur, &mut branches),
                }
            }
            flush(&mut cur, &mut branches);
        }
        if self.selfb {
            self.reach_knot_corners(&mut branches, cells, dom);
        }
        let closed = self.selfb && self.is_closed();
        if closed {
            branches = join_seam(branches, dom);
        }
        // Leaf clusters at the diagonal corners of the Bézier cells (where the undivided F has
        // its trivial double zero) are artefacts of the diagonal, not bisector points.
        let ext = dom[1] - dom[0];
        let special = |v: &[[f64; 2]]| -> Vec<BisectorPoint> {
            v.iter()
                .filter(|q| !self.selfb || q[1] - q[0] > 1e-3 * ext)
                // For a closed curve the corner (start, end) is the diagonal across the seam.
                .filter(|q| !closed || q[1] - q[0] < (1.0 - 1e-3) * ext)
                .filter_map(|q| {
                    self.accept(q[0], q[1])
                        .map(|(tr, xy)| BisectorPoint { tr, xy })
                })
                .collect()
        };
        Bisector {
            branches,
            singular: special(&z.singular),
            isolated: special(&z.isolated),
            complete: z.complete,
        }
    }
}

impl Ctx<'_> {
    /// Extends self-bisector branches that end beside a knot corner `(k, k)` of the diagonal
    /// up to it.
    ///
    /// Where the curvature has an extremum exactly at a knot (its derivative changes sign
    /// there, common for B-splines), a branch ends at the corner `(k, k)`, reached through the
    /// cell `t < k < r`. That cell is not divided by `(t − r)⁴` (its two foot points lie on
    /// different polynomial pieces), so `F` is flat to fourth order around the corner and the
    /// zero set stops where the flat region begins, ~1e-5 of the domain short (in the plane,
    /// ~1e-5 of the size short of the branch's end). Near the corner the branch is a ray;
    /// points along it, halving the distance each time, are polished onto the bisector
    /// condition ψ (whose rounding error shrinks with the distances) while they stay valid
    /// and in step. On the demo's periodic NURBS this takes the branches to ~1e-8 of the
    /// corner (their images to 2e-8–6e-8 of the limit point, the centre of curvature there).
    fn reach_knot_corners(&self, branches: &mut [Branch], cells: &[Patch], dom: [f64; 4]) {
        let ext = dom[1] - dom[0];
        let mut knots: Vec<f64> = cells
            .iter()
            .filter(|p| p.t0 == p.r0 && p.t0 > dom[0])
            .map(|p| p.t0)
            .collect();
        knots.sort_by(f64::total_cmp);
        knots.dedup();
        for b in branches.iter_mut() {
            for front in [false, true] {
                let Some(&q) = (if front { b.tr.first() } else { b.tr.last() }) else {
                    continue;
                };
                let Some(&k) = knots.iter().find(|&&k| {
                    q[0] <= k
                        && k < q[1]
                        && k - q[0] <= CORNER_REACH * ext
                        && q[1] - k <= CORNER_REACH * ext
                }) else {
                    continue;
                };
                let n = b.xy.len();
                let (p0, p1) = if front {
                    (b.xy[0], b.xy[1.min(n - 1)])
                } else {
                    (b.xy[n - 1], b.xy[n.saturating_sub(2)])
                };
                // The image converges along the ray; each new point must stay in step (its
                // move at most twice the previous one), and the polish may not leave the ray
                // by more than a quarter of the distance to the corner — else it found another
                // zero of ψ (ψ has three near the corner) and the extension stops.
                let (mut last, mut step) = (p0, (p0[0] - p1[0]).hypot(p0[1] - p1[1]));
                let mut extra: Vec<([f64; 2], [f64; 2])> = Vec::new();
                let mut f = 1.0;
                for _ in 0..MAX_CORNER_STEPS {
                    f *= 0.5;
                    let g = [k + f * (q[0] - k), k + f * (q[1] - k)];
                    let Some((tr, xy)) = self.accept(g[0], g[1]) else {
                        break;
                    };
                    let off = (tr[0] - g[0]).hypot(tr[1] - g[1]);
                    let moved = (xy[0] - last[0]).hypot(xy[1] - last[1]);
                    if off > 0.25 * f * (q[0] - k).hypot(q[1] - k)
                        || moved > 2.0 * step + 1e-12 * self.diag
                    {
                        break;
                    }
                    extra.push((tr, xy));
                    (last, step) = (xy, moved);
                }
                if front {
                    for (tr, xy) in extra {
                        b.tr.insert(0, tr);
                        b.xy.insert(0, xy);
                    }
                } else {
                    for (tr, xy) in extra {
                        b.tr.push(tr);
                        b.xy.push(xy);
                    }
                }
            }
        }
    }
}

fn flush(cur: &mut Branch, out: &mut Vec<Branch>) {
    if cur.tr.len() >= 2 {
        out.push(std::mem::replace(
            cur,
            Branch {
                tr: Vec::new(),
                xy: Vec::new(),
            },
        ));
    } else {
        cur.tr.clear();
        cur.xy.clear();
    }
}

/// Joins branches across the seam of a closed curve: `(start, ρ)` on the border `t = start`
/// is the same foot-point pair as `(ρ, end)` on the border `r = end` (parameters modulo the
/// period, mirrored into `t ≤ r`).
fn join_seam(mut v: Vec<Branch>, dom: [f64; 4]) -> Vec<Branch> {
    let tol = 1e-9 * (dom[1] - dom[0]);
    let on_top = |q: [f64; 2]| q[1] == dom[3];
    let on_left = |q: [f64; 2]| q[0] == dom[0];
    let ends = |b: &Branch| [b.tr[0], b.tr[b.tr.len() - 1]];
    // Bounded: each join removes one branch.
    for _ in 0..v.len() {
        let mut found = None;
        'search: for i in 0..v.len() {
            for (ei, qi) in ends(&v[i]).into_iter().enumerate() {
                if !on_top(qi) {
                    continue;
                }
                for j in (0..v.len()).filter(|&j| j != i) {
                    for (ej, qj) in ends(&v[j]).into_iter().enumerate() {
                        if on_left(qj) && (qj[1] - qi[0]).abs() <= tol {
                            found = Some((i, ei, j, ej));
                            break 'search;
                        }
                    }
                }
            }
        }
        let Some((i, ei, j, ej)) = found else { break };
        // Orient: the matching end of i last, the matching end of j first.
        if ei == 0 {
            v[i].tr.reverse();
            v[i].xy.reverse();
        }
        let mut tail = v.remove(j);
        if ej == 1 {
            tail.tr.reverse();
            tail.xy.reverse();
        }
        let i = if j < i { i - 1 } else { i };
        v[i].tr.extend(tail.tr.into_iter().skip(1));
        v[i].xy.extend(tail.xy.into_iter().skip(1));
    }
    v
}

/// The part of a polyline with `t ≤ r`; `None` marks a cut where it crosses the diagonal, and
/// `end` supplies a vertex on the zero set just beside the crossing (so the branch reaches the
/// diagonal whatever the vertex spacing).
///
/// A vertex within `margin` of the diagonal counts as outside: the symmetric zero set can put
/// a vertex exactly on the diagonal where it crosses, and such a vertex is no bisector point
/// (the foot points coincide), so the crossing must be cut there, not one vertex later.
fn clip_diagonal(
    pts: &[[f64; 2]],
    margin: f64,
    end: &dyn Fn([f64; 2], [f64; 2]) -> Option<[f64; 2]>,
) -> Vec<Option<[f64; 2]>> {
    let mut out = Vec::with_capacity(pts.len() + 2);
    for (k, q) in pts.iter().enumerate() {
        let inside = q[1] - q[0] > margin;
        if k > 0 {
            let p = pts[k - 1];
            let was = p[1] - p[0] > margin;
            if was && !inside {
                out.push(end(p, *q));
                out.push(None);
            } else if !was && inside {
                out.push(end(*q, p));
            }
        }
        if inside {
            out.push(Some(*q));
        }
    }
    out
}

/// Where the segment from `a` (`t ≤ r`) to `b` (`t > r`) meets the diagonal, the zero set of
/// the divided function crosses it at right angles (it is symmetric). Find that crossing
/// `(s, s)` by Newton along the diagonal, then the zero-set point at a small offset from it
/// on the `t < r` side (Newton along the diagonal direction).
fn diagonal_end(cells: &[Patch], a: [f64; 2], b: [f64; 2], dom: [f64; 4]) -> Option<[f64; 2]> {
    let (da, db) = (a[1] - a[0], b[1] - b[0]);
    let w = da / (da - db);
    let c = a[0] + w * (b[0] - a[0]);
    let cell = cells
        .iter()
        .find(|p| p.t0 <= c && c <= p.t1 && p.r0 <= c && c <= p.r1)?;
    let (lo, hi) = (cell.t0.max(cell.r0), cell.t1.min(cell.r1));
    // Newton along a line q(μ) = base + μ (1, 1), kept inside the cell.
    let solve = |base: [f64; 2], mut mu: f64| -> Option<f64> {
        for _ in 0..30 {
            let g = cell.eval_grad(base[0] + mu, base[1] + mu);
            let slope = g[1] + g[2];
            if slope == 0.0 || !slope.is_finite() {
                return None;
            }
            let step = g[0] / slope;
            mu -= step;
            // Newton converges quadratically: after a step this small the error is far below
            // rounding, while the steps themselves need not fall below the rounding noise of
            // G (1e-15 of the cell is about one ulp: asking for it can fail to converge).
            if step.abs() <= 1e-12 * (hi - lo) {
                return Some(mu);
            }
        }
        None
    };
    let s = solve([0.0, 0.0], c)?;
    let delta = 1e-6 * (dom[1] - dom[0]);
    let base = [s - delta, s + delta];
    let mu = solve(base, 0.0)?;
    let e = [base[0] + mu, base[1] + mu];
    let inside = e[0] >= cell.t0 && e[0] <= cell.t1 && e[1] >= cell.r0 && e[1] <= cell.r1;
    (inside && s > lo && s < hi && mu.abs() < 1e3 * delta).then_some(e)
}

/// The bisector of `c1(t)` and `c2(r)`.
pub fn bisector(c1: &Rational, c2: &Rational, opts: &BisectorOptions) -> Result<Bisector> {
    let z = check(opts)?;
    for (which, c) in [(1, c1), (2, c2)] {
        if c.dim() != 2 {
            return Err(Error::NotPlanar {
                which,
                dim: c.dim(),
            });
        }
    }
    let (frame, local) = local_curves(&[c1, c2])?;
    let (c1, c2) = (&local[0], &local[1]);
    let (f, terms) = bisector_function_scaled(c1, c2, opts.method)?;
    let (center, diag) = bbox(&[c1, c2]);
    let ctx = Ctx {
        c1,
        c2,
        center,
        diag,
        selfb: false,
        trimmed: opts.trimmed,
    };
    let cells: Vec<Patch> = f
        .bezier_patches()
        .iter()
        .map(|b| within_rounding_as_zero(Patch::from_bezier(b), terms))
        .collect();
    let (dt, dr) = (f.domain_t(), f.domain_r());
    let dom = [dt.0, dt.1, dr.0, dr.1];
    let map = |t: f64, r: f64| ctx.map(t, r);
    let keep = |_: &Patch| true;
    let pieces = run_cells(&cells, dom, &z, &map, opts.chord_tol * diag, &keep, &|_| {
        false
    });
    Ok(to_global(ctx.build(&pieces, dom, &cells), &frame))
}

/// A cell whose coefficients are all within the rounding of the terms that formed them
/// (`terms`, see [`bisector_function_scaled`]) as zero: the function vanishes there as far
/// as double precision tells (two straight pieces; rationally parametrised they left noise
/// that the extractor ground through for seconds), and the extractor reports it so.
fn within_rounding_as_zero(mut p: Patch, terms: f64) -> Patch {
    if p.max_abs() <= VANISHING * terms {
        p.c.iter_mut().for_each(|x| *x = 0.0);
    }
    p
}

/// The size of a cell's coefficients, relative to the terms that formed them, below which
/// they are rounding: a few hundred roundings of the products (degree-12 products of
/// degree-3 pieces, six outer products summed).
const VANISHING: f64 = 1e-12;

/// The curves moved into one frame (a local origin and a power-of-two scale, see
/// [`Frame`]): the bisector is the same in parameters and moves with the plane, and its
/// functions, products of coordinate differences, keep the precision of unit-size data
/// (a curve of size 100 at 2e14 from the origin lost all of it, and the extraction ground
/// through noise without end).
fn local_curves(curves: &[&Rational]) -> Result<(Frame, Vec<Rational>)> {
    let points: Vec<Vec<[f64; 2]>> = curves
        .iter()
        .map(|c| c.control_points().iter().map(|p| [p[0], p[1]]).collect())
        .collect();
    let sets: Vec<&[[f64; 2]]> = points.iter().map(Vec::as_slice).collect();
    let frame = Frame::for_all(&sets);
    let local = curves
        .iter()
        .zip(&points)
        .map(|(c, pts)| {
            let mut at = pts.iter();
            let moved = c.homogeneous().map_points(2, |_, dst| {
                if let Some(&p) = at.next() {
                    dst.copy_from_slice(&frame.to_local(p));
                }
            });
            let weights = c.weights();
            Rational::new(moved, c.is_rational().then_some(&weights[..]))
        })
        .collect::<std::result::Result<Vec<_>, _>>()?;
    Ok((frame, local))
}

/// A bisector found in a frame, in global coordinates (the parameters are the same).
fn to_global(mut b: Bisector, frame: &Frame) -> Bisector {
    let points = b
        .branches
        .iter_mut()
        .flat_map(|br| br.xy.iter_mut())
        .chain(b.singular.iter_mut().map(|p| &mut p.xy))
        .chain(b.isolated.iter_mut().map(|p| &mut p.xy));
    for xy in points {
        *xy = frame.to_global(*xy);
    }
    b
}

/// The self-bisector of `c`: pairs `t < r` of distinct foot points on the same curve.
pub fn self_bisector(c: &Rational, opts: &BisectorOptions) -> Result<Bisector> {
    let z = check(opts)?;
    if c.dim() != 2 {
        return Err(Error::NotPlanar {
            which: 1,
            dim: c.dim(),
        });
    }
    let (frame, local) = local_curves(&[c])?;
    let c = &local[0];
    let (f, terms) = bisector_function_scaled(c, c, opts.method)?;
    let (center, diag) = bbox(&[c]);
    let ctx = Ctx {
        c1: c,
        c2: c,
        center,
        diag,
        selfb: true,
        trimmed: opts.trimmed,
    };
    let mut cells: Vec<Patch> = Vec::new();
    for b in f.bezier_patches() {
        let mut p = within_rounding_as_zero(Patch::from_bezier(&b), terms);
        if p.t0 >= p.r1 {
            continue; // entirely below the diagonal: the mirror of a cell above it
        }
        // Diagonal cells: divide (t − r) out as often as it divides. For F3 that is four
        // times: F3 = den · F̂3 with den = C'(t) × C'(r) = O(t − r) and F̂3 = O((t − r)³)
        // (|P − C(u)|² has critical points at both foot points, so its difference between
        // them is a cubic in t − r). The quotient vanishes on the diagonal only at curvature
        // extrema, where self-bisector branches end. A divisible cell has a relative
        // residual near 1e-13, an indivisible one near 1; a cell left with a factor (t − r)
        // would keep the extractor grinding along the whole diagonal.
        for _ in 0..8 {
            match p.divide_diagonal(DIVISIBLE) {
                Some(q) => p = q,
                None => break,
            }
        }
        cells.push(p);
    }
    let (dt, dr) = (f.domain_t(), f.domain_r());
    let dom = [dt.0, dt.1, dr.0, dr.1];
    let map = |t: f64, r: f64| ctx.map(t, r);
    let keep = |p: &Patch| p.t0 < p.r1;
    // Cells touching the diagonal at a corner (t1 = r0), and for a closed curve the cell at
    // the corner (start, end) — the diagonal across the seam: F vanishes to fourth order at
    // that corner (see `lax` in the tracer).
    let lax = |p: &Patch| p.t1 == p.r0 || (p.t0 == dom[0] && p.r1 == dom[3]);
    let pieces = run_cells(&cells, dom, &z, &map, opts.chord_tol * diag, &keep, &lax);
    Ok(to_global(ctx.build(&pieces, dom, &cells), &frame))
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

#[cfg(test)]
mod tests {
    use super::*;
    use bspline::BSpline;

    /// How often `(t − r)` divides each diagonal cell of the self-bisector function.
    fn divisions(c: &Rational, method: Method) -> Vec<usize> {
        let f = crate::bisector_function(c, c, method).unwrap();
        f.bezier_patches()
            .iter()
            .map(Patch::from_bezier)
            .filter(|p| p.t0 == p.r0 && p.t1 == p.r1)
            .map(|mut p| {
                let mut k = 0;
                while let Some(q) = p.divide_diagonal(DIVISIBLE) {
                    p = q;
                    k += 1;
                    assert!(k <= 8);
                }
                k
            })
            .collect()
    }

    fn pts(v: &[[f64; 2]]) -> Vec<f64> {
        v.iter().flat_map(|p| [p[0], p[1]]).collect()
    }

    /// F3 of a curve with itself vanishes to fourth order on the diagonal (den = O(t − r),
    /// F̂3 = O((t − r)³)), F1 and F2 to fifth (they carry den once more, and are
    /// antisymmetric). The division finds exactly that in every diagonal cell, for a cubic
    /// B-spline, a cubic NURBS (degree 11 cells) and a periodic NURBS.
    #[test]
    fn self_bisector_functions_divide_by_the_expected_power() {
        let seven = pts(&[
            [0.0, 0.0],
            [1.0, 2.0],
            [3.0, 2.5],
            [4.0, 0.5],
            [3.0, -1.5],
            [1.5, -1.0],
            [2.0, 0.5],
        ]);
        let cubic = Rational::polynomial(&BSpline::clamped_uniform(3, 2, seven.clone()).unwrap());
        let w = [1.0, 3.0, 1.0, 1.0, 0.5, 2.0, 1.0];
        let nurbs =
            Rational::new(BSpline::clamped_uniform(3, 2, seven).unwrap(), Some(&w)).unwrap();
        let ring = pts(&[
            [3.0, 0.0],
            [2.5, 2.0],
            [0.5, 1.0],
            [-1.0, 2.5],
            [-3.0, 0.5],
            [-2.5, -2.0],
            [0.0, -0.8],
            [2.0, -2.5],
        ]);
        let mut wr = vec![1.0, 2.0, 0.5, 1.0, 1.5, 1.0, 0.6, 1.0];
        wr.extend_from_slice(&[1.0, 2.0, 0.5]);
        let periodic = Rational::new(BSpline::periodic(3, 2, ring).unwrap(), Some(&wr)).unwrap();
        for c in [&cubic, &nurbs, &periodic] {
            let d3 = divisions(c, Method::F3);
            assert!(!d3.is_empty() && d3.iter().all(|&k| k == 4), "F3: {d3:?}");
        }
        for m in [Method::F1, Method::F2] {
            let d = divisions(&cubic, m);
            assert!(!d.is_empty() && d.iter().all(|&k| k == 5), "{m:?}: {d:?}");
        }
    }
}
