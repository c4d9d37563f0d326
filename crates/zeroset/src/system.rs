//! Isolated common zeros of two bivariate B-spline functions `F = G = 0` in their domain box.
//!
//! Subdivision as for zero sets: a box is dropped when either function has coefficients of one
//! trusted sign. A box holds at most one solution when the interval Jacobian built from the
//! coefficient ranges of the four partial derivatives has a determinant interval that excludes
//! zero (every matrix in it is regular, so the map is injective on the convex box). Newton from
//! the box centre then either converges inside the box (a solution, `certified`) or the box is
//! split further. Boxes unresolved at the tolerance give uncertified candidates.

use crate::error::Result;
use crate::patch::{common_sign, Patch};
use crate::zeroset::TOL_FLOOR;
use bspline::tensor::TensorBSpline;
use nalgebra::{Matrix2, Vector2};
use numeric::newton2::{newton2, Iterate, Newton2, StepVerdict};
use numeric::rounding::{ulps, UNIT_ROUNDOFF};
use numeric::subdivide::{depth_first, Decision};
use numeric::Rect;
use serde::{Deserialize, Serialize};

/// Options for [`solve_system`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SystemOptions {
    /// Parameter tolerance relative to the domain.
    pub tol: f64,
    /// Limit on the boxes examined.
    pub max_boxes: usize,
}

impl Default for SystemOptions {
    fn default() -> Self {
        Self {
            tol: numeric::tolerance::DEFAULT_PARAM_TOL,
            max_boxes: 1_000_000,
        }
    }
}

/// One solution of the system.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Solution {
    /// Parameter `t`.
    pub t: f64,
    /// Parameter `r`.
    pub r: f64,
    /// True when uniqueness in a box (interval Jacobian) and Newton convergence inside it
    /// were both established.
    pub certified: bool,
}

/// All isolated solutions of `f = g = 0` on the common domain, sorted by `(t, r)`.
///
/// ```
/// use bspline::tensor::TensorBSpline;
/// use zeroset::{solve_system, SystemOptions};
/// // f = t − r and g = t + r − 1 on the unit square (bilinear, by their corner values):
/// // one common zero, at (1/2, 1/2).
/// let unit = || vec![0.0, 0.0, 1.0, 1.0];
/// let f = TensorBSpline::new(1, unit(), 1, unit(), vec![0.0, -1.0, 1.0, 0.0]).unwrap();
/// let g = TensorBSpline::new(1, unit(), 1, unit(), vec![-1.0, 0.0, 0.0, 1.0]).unwrap();
/// let found = solve_system(&f, &g, &SystemOptions::default()).unwrap();
/// assert_eq!(found.len(), 1);
/// assert!(found[0].certified);
/// assert!((found[0].t - 0.5).abs() < 1e-12 && (found[0].r - 0.5).abs() < 1e-12);
/// ```
pub fn solve_system(
    f: &TensorBSpline,
    g: &TensorBSpline,
    opts: &SystemOptions,
) -> Result<Vec<Solution>> {
    // Bring both onto one grid of Bézier cells: insert each other's breakpoints.
    let f2 = f.refine_t(&missing(g.knots_t(), f.knots_t(), f.domain_t()))?;
    let f2 = f2.refine_r(&missing(g.knots_r(), f.knots_r(), f.domain_r()))?;
    let g2 = g.refine_t(&missing(f.knots_t(), g.knots_t(), g.domain_t()))?;
    let g2 = g2.refine_r(&missing(f.knots_r(), g.knots_r(), g.domain_r()))?;
    let fc: Vec<Patch> = f2.bezier_patches().iter().map(Patch::from_bezier).collect();
    let gc: Vec<Patch> = g2.bezier_patches().iter().map(Patch::from_bezier).collect();
    let (dt, dr) = (f.domain_t(), f.domain_r());
    let ext = [dt.1 - dt.0, dr.1 - dr.0];
    let min = [opts.tol * ext[0], opts.tol * ext[1]];
    let max_depth = 2
        * ((1.0 / opts.tol.max(TOL_FLOOR))
            .log2()
            .ceil()
            .clamp(1.0, 1100.0) as usize
            + 4);
    let mut sols: Vec<Solution> = Vec::new();
    let mut boxes = 0usize;
    for (cf, cg) in fc.iter().zip(&gc) {
        let (sf, sg) = (cf.max_abs(), cg.max_abs());
        // Rounding level of a value of the cell polynomials (their coefficients' own error
        // and the evaluation's), for Newton's stopping test.
        let noise = [
            4.0 * (cf.pt + cf.pr + 2) as f64 * UNIT_ROUNDOFF * sf,
            4.0 * (cg.pt + cg.pr + 2) as f64 * UNIT_ROUNDOFF * sg,
        ];
        depth_first((cf.clone(), cg.clone()), max_depth, |(pf, pg), visit| {
            let depth = visit.depth;
            boxes += 1;
            if boxes > opts.max_boxes {
                return Decision::Stop(());
            }
            let ef = (pf.pt + pf.pr + 2) as f64 * (depth + 4) as f64 * UNIT_ROUNDOFF * sf;
            let eg = (pg.pt + pg.pr + 2) as f64 * (depth + 4) as f64 * UNIT_ROUNDOFF * sg;
            if common_sign(pf.c.iter().copied(), ef) != 0
                || common_sign(pg.c.iter().copied(), eg) != 0
            {
                return Decision::Decided;
            }
            let bx = pf.rect();
            if unique(&pf, &pg) {
                if let Some((t, r)) = newton(cf, cg, bx, noise) {
                    sols.push(Solution {
                        t,
                        r,
                        certified: true,
                    });
                    return Decision::Decided;
                }
            }
            let [wt, wr] = bx.widths();
            let small = wt <= min[0] && wr <= min[1];
            if small || !visit.can_halve {
                let [mt, mr] = bx.mid();
                let (t, r) = newton(cf, cg, bx.grown(min), noise).unwrap_or((mt, mr));
                sols.push(Solution {
                    t,
                    r,
                    certified: false,
                });
                return Decision::Decided;
            }
            let split_t = wt / ext[0] >= wr / ext[1];
            let s = 0.498_763_4;
            let ((fa, fb), (ga, gb)) = if split_t {
                (pf.split_t(s), pg.split_t(s))
            } else {
                (pf.split_r(s), pg.split_r(s))
            };
            Decision::Halve((fa, ga), (fb, gb))
        });
    }
    Ok(dedup(
        sols,
        [1e3 * min[0].max(ulps(1.0)), 1e3 * min[1].max(ulps(1.0))],
    ))
}

/// Breakpoints of `from` not already knots of `into`, inside the domain.
fn missing(from: &[f64], into: &[f64], dom: (f64, f64)) -> Vec<f64> {
    let mut v: Vec<f64> = from
        .iter()
        .copied()
        .filter(|&x| x > dom.0 && x < dom.1 && !into.contains(&x))
        .collect();
    v.dedup();
    v
}

/// Interval range of a coefficient iterator; `[0, 0]` for none (the partial derivative in a
/// direction of degree 0 vanishes).
fn range(it: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = it.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    });
    if lo > hi {
        (0.0, 0.0)
    } else {
        (lo, hi)
    }
}

fn imul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let p = [a.0 * b.0, a.0 * b.1, a.1 * b.0, a.1 * b.1];
    (
        p.iter().fold(f64::INFINITY, |m, &x| m.min(x)),
        p.iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x)),
    )
}

/// The margin by which the determinant interval must exclude 0, relative to the magnitudes of
/// its two products: each end is a few roundings of products of scaled coefficient ranges
/// (units of 1e-16), and a determinant within this of 0 is not trusted as regular.
const DET_SLACK: f64 = 1e-12;

/// Whether the interval Jacobian over the box is regular (its determinant excludes 0). The
/// coefficient differences are positive multiples of the partials' coefficients; the common
/// factors do not change the sign of the determinant.
pub(crate) fn unique(f: &Patch, g: &Patch) -> bool {
    let (ft, fr) = (range(f.dt_coefs()), range(f.dr_coefs()));
    let (gt, gr) = (range(g.dt_coefs()), range(g.dr_coefs()));
    // Scale differences into derivative units so the two products are comparable.
    let sc = |x: (f64, f64), k: f64| (x.0 * k, x.1 * k);
    let (kt_f, kr_f) = (f.pt as f64 / (f.t1 - f.t0), f.pr as f64 / (f.r1 - f.r0));
    let (kt_g, kr_g) = (g.pt as f64 / (g.t1 - g.t0), g.pr as f64 / (g.r1 - g.r0));
    let a = imul(sc(ft, kt_f), sc(gr, kr_g));
    let b = imul(sc(fr, kr_f), sc(gt, kt_g));
    let lo = a.0 - b.1;
    let hi = a.1 - b.0;
    let slack = DET_SLACK * (a.0.abs().max(a.1.abs()) + b.0.abs().max(b.1.abs()));
    lo > slack || hi < -slack
}

/// Newton steps on a box before it is split instead: from the centre of a box with a regular
/// interval Jacobian Newton converges quadratically or leaves the box within a few.
const SYSTEM_NEWTON_STEPS: usize = 60;

/// Newton on the cell polynomials from the box centre ([`numeric::newton2`]); `Some` when it
/// converges inside the box.
///
/// Converged means the step has come down to the rounding level: a few ulps of the iterate,
/// or what the rounding `noise` of the values of `f` and `g` moves the Newton step by (the
/// iterates then wander among a few neighbouring doubles and cannot get closer). The ulp
/// test alone cannot be met near `t = 0` or `r = 0`, where an ulp is far below the error the
/// values carry, nor at a shallow crossing, where `J⁻¹` magnifies that error. The converged
/// iterate may lie that far outside the box (a root on its border, met from both sides).
fn newton(f: &Patch, g: &Patch, bx: Rect, noise: [f64; 2]) -> Option<(f64, f64)> {
    let start = Vector2::new(bx.t.mid(), bx.r.mid());
    let inside = |x: &Vector2<f64>, st: f64, sr: f64| {
        x[0] >= bx.t.lo - st && x[0] <= bx.t.hi + st && x[1] >= bx.r.lo - sr && x[1] <= bx.r.hi + sr
    };
    let linearize = |x: &Vector2<f64>| {
        let (a, b) = (f.eval_grad(x[0], x[1]), g.eval_grad(x[0], x[1]));
        (
            Vector2::new(a[0], b[0]),
            Matrix2::new(a[1], a[2], b[1], b[2]),
        )
    };
    let judge = |step: &Iterate<Vector2<f64>>| {
        let (j, d, x) = (step.jacobian, step.step, step.to);
        let det = (j[(0, 0)] * j[(1, 1)] - j[(0, 1)] * j[(1, 0)]).abs();
        // What errors of `noise` in the values move the step by.
        let nt = (noise[0] * j[(1, 1)].abs() + noise[1] * j[(0, 1)].abs()) / det;
        let nr = (noise[0] * j[(1, 0)].abs() + noise[1] * j[(0, 0)].abs()) / det;
        let small = d[0].abs() <= ulps(4.0) * x[0].abs().max(bx.t.width()) + nt
            && d[1].abs() <= ulps(4.0) * x[1].abs().max(bx.r.width()) + nr;
        if small && inside(&x, nt, nr) {
            StepVerdict::Converged
        } else if !inside(&x, 0.0, 0.0) {
            StepVerdict::Abandon
        } else {
            StepVerdict::Continue
        }
    };
    let limits = Newton2::steps(SYSTEM_NEWTON_STEPS);
    newton2(start, limits, linearize, |x, d| x - d, judge)
        .converged()
        .map(|x| (x[0], x[1]))
}

/// One report per solution: close duplicates (found from two boxes sharing a border) merge.
fn dedup(mut v: Vec<Solution>, tol: [f64; 2]) -> Vec<Solution> {
    v.sort_by(|a, b| a.t.total_cmp(&b.t).then(a.r.total_cmp(&b.r)));
    let mut out: Vec<Solution> = Vec::new();
    for s in v {
        if let Some(o) = out
            .iter_mut()
            .find(|o| (o.t - s.t).abs() <= tol[0] && (o.r - s.r).abs() <= tol[1])
        {
            o.certified |= s.certified;
            continue;
        }
        out.push(s);
    }
    out
}
