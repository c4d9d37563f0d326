//! Independent brute-force oracles for the tests: a dense grid over the equations, sign
//! changes, then Newton. Deliberately shares no code with the crate's algorithms.
#![allow(dead_code, unreachable_pub, missing_docs)]

#[allow(unused_imports)] // (each test crate uses what it needs)
pub use testkit::cases;

use antipodal::{Jet, PlaneCurve, V2};

pub fn jets(c: &dyn PlaneCurve, n: usize) -> (Vec<f64>, Vec<Jet>) {
    let (a, b) = c.domain();
    let us: Vec<f64> = (0..n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    let js = us.iter().map(|&u| c.jet(u)).collect();
    (us, js)
}

fn wrap(c: &dyn PlaneCurve, u: f64) -> f64 {
    let (a, b) = c.domain();
    a + (u - a).rem_euclid(b - a)
}

/// Antipodal system: F1 = T(s) × T(t), F2 = r · T(s) / |r|.
fn f_anti(js: &Jet, jt: &Jet) -> (f64, f64) {
    let (ts, tt) = (js.d1.unit(), jt.d1.unit());
    let r = jt.p - js.p;
    (ts.cross(tt), r.dot(ts) / r.norm().max(1e-300))
}

/// The values and the Jacobian of a 2×2 system at a point: `([f, g], [[f_s, f_t], [g_s,
/// g_t]])`.
pub type System = ([f64; 2], [[f64; 2]; 2]);

/// The Newton step `(ds, dt)` of a 2×2 system (by Cramer's rule), `None` where its Jacobian
/// is singular or not finite.
pub fn newton_step((f, jac): System) -> Option<(f64, f64)> {
    let [[a11, a12], [a21, a22]] = jac;
    let det = a11 * a22 - a12 * a21;
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    Some((
        (f[0] * a22 - f[1] * a12) / det,
        (a11 * f[1] - a21 * f[0]) / det,
    ))
}

/// Newton on `system` from `(s, t)`, at most 60 steps: where it stopped, and whether because
/// the step fell below 1e-15 of the point; `None` where a Jacobian was singular.
fn newton_from(
    system: impl Fn(f64, f64) -> System,
    (mut s, mut t): (f64, f64),
) -> Option<((f64, f64), bool)> {
    for _ in 0..60 {
        let (ds, dt) = newton_step(system(s, t))?;
        s -= ds;
        t -= dt;
        if ds.abs() + dt.abs() < 1e-15 * (1.0 + s.abs() + t.abs()) {
            return Some(((s, t), true));
        }
    }
    Some(((s, t), false))
}

/// Newton on a 2×2 system in the unit square of two segments' parameters, from `(s, t)`: the
/// root, clamped into the square, where the steps fall below 1e-15 within 60 steps without
/// leaving the square by more than 1e-9; `None` otherwise.
pub fn newton_in_unit_square(
    system: impl Fn(f64, f64) -> System,
    mut s: f64,
    mut t: f64,
) -> Option<(f64, f64)> {
    for _ in 0..60 {
        let (ds, dt) = newton_step(system(s, t))?;
        s -= ds;
        t -= dt;
        if !(-1e-9..=1.0 + 1e-9).contains(&s) || !(-1e-9..=1.0 + 1e-9).contains(&t) {
            return None;
        }
        if ds.abs() < 1e-15 && dt.abs() < 1e-15 {
            return Some((s.clamp(0.0, 1.0), t.clamp(0.0, 1.0)));
        }
    }
    // (Not converged: no root here.)
    None
}

/// Where `g` changes sign in `[lo, hi]`, by 80 halvings: the last bracket's midpoint.
pub fn bisect(g: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if (g(lo) < 0.0) == (g(mid) < 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The cells of a `grid × grid` sampling of the unit square where both values of `f` change
/// sign (the least at the cell's corners at most 0, the greatest at least 0), as their centres;
/// only the cells `(a, b)` (by index) that `look(a, b)` are looked at.
pub fn straddling_cells(
    grid: usize,
    f: impl Fn(f64, f64) -> (f64, f64),
    look: impl Fn(usize, usize) -> bool,
) -> Vec<(f64, f64)> {
    let xs: Vec<f64> = (0..=grid).map(|k| k as f64 / grid as f64).collect();
    let vals: Vec<Vec<(f64, f64)>> = xs
        .iter()
        .map(|&s| xs.iter().map(|&t| f(s, t)).collect())
        .collect();
    let mut cells = Vec::new();
    for a in 0..grid {
        for b in (0..grid).filter(|&b| look(a, b)) {
            let c = [
                vals[a][b],
                vals[a + 1][b],
                vals[a][b + 1],
                vals[a + 1][b + 1],
            ];
            let spans = |f: &dyn Fn(&(f64, f64)) -> f64| {
                let lo = c.iter().map(f).fold(f64::INFINITY, f64::min);
                let hi = c.iter().map(f).fold(f64::NEG_INFINITY, f64::max);
                lo <= 0.0 && hi >= 0.0
            };
            if spans(&|v| v.0) && spans(&|v| v.1) {
                cells.push((0.5 * (xs[a] + xs[a + 1]), 0.5 * (xs[b] + xs[b + 1])));
            }
        }
    }
    cells
}

fn newton_anti(c: &dyn PlaneCurve, s: f64, t: f64) -> Option<(f64, f64)> {
    let system = |s: f64, t: f64| {
        let (js, jt) = (c.jet(wrap(c, s)), c.jet(wrap(c, t)));
        let r = jt.p - js.p;
        (
            [js.d1.cross(jt.d1), r.dot(js.d1)],
            [
                [js.d2.cross(jt.d1), js.d1.cross(jt.d2)],
                [-js.d1.dot(js.d1) + r.dot(js.d2), jt.d1.dot(js.d1)],
            ],
        )
    };
    // (Not converged within the steps: the residual test below judges the point reached.)
    let ((s, t), _) = newton_from(system, (s, t))?;
    let (s, t) = (wrap(c, s), wrap(c, t));
    let (js, jt) = (c.jet(s), c.jet(t));
    let (f1, f2) = f_anti(&js, &jt);
    let r = jt.p - js.p;
    // Inward normal: left normal for a counterclockwise curve; the caller passes orientation.
    (f1.abs() < 1e-10 && f2.abs() < 1e-10 && js.d1.dot(jt.d1) < 0.0 && r.norm() > 1e-9)
        .then_some((s, t))
}

/// Signed area (orientation) from a fine polygon.
pub fn orientation(c: &dyn PlaneCurve) -> f64 {
    let (_, js) = jets(c, 2000);
    let mut a = 0.0;
    for i in 0..js.len() {
        let (p, q) = (js[i].p, js[(i + 1) % js.len()].p);
        a += p.cross(q);
    }
    a.signum()
}

pub fn same_param(c: &dyn PlaneCurve, x: f64, y: f64, tol: f64) -> bool {
    let (a, b) = c.domain();
    let per = b - a;
    let d = (x - y).rem_euclid(per);
    d.min(per - d) <= tol
}

/// Sub-cells per side of a grid cell with sign changes (pairs closer than a cell apart).
const SUB: usize = 16;

/// All antipodal pairs (s < t after sorting each pair), by grid + Newton.
pub fn antipodal_oracle(c: &dyn PlaneCurve, n: usize) -> Vec<(f64, f64)> {
    let orient = orientation(c);
    let (us, js) = jets(c, n);
    let grid: Vec<(f64, f64)> = (0..n * n).map(|k| f_anti(&js[k / n], &js[k % n])).collect();
    let f = |i: usize, j: usize| grid[(i % n) * n + j % n];
    let mut found: Vec<(f64, f64)> = Vec::new();
    for i in 0..n {
        for j in 0..n {
            if i == j {
                continue;
            }
            let corners = [f(i, j), f(i + 1, j), f(i, j + 1), f(i + 1, j + 1)];
            let ch = |k: usize| {
                let sg = corners.map(|c| if k == 0 { c.0 > 0.0 } else { c.1 > 0.0 });
                sg.iter().any(|&x| x != sg[0])
            };
            if !(ch(0) && ch(1)) {
                continue;
            }
            // A cell with sign changes may hold several pairs close together: Newton from
            // the centre of every sub-cell that shows sign changes of both equations.
            let h = us[1] - us[0];
            let hs = h / SUB as f64;
            let at = |u: f64| c.jet(wrap(c, u));
            let sub: Vec<Jet> = (0..=SUB).map(|k| at(us[i] + k as f64 * hs)).collect();
            let tub: Vec<Jet> = (0..=SUB).map(|k| at(us[j] + k as f64 * hs)).collect();
            for a in 0..SUB {
                for b in 0..SUB {
                    let corners = [
                        f_anti(&sub[a], &tub[b]),
                        f_anti(&sub[a + 1], &tub[b]),
                        f_anti(&sub[a], &tub[b + 1]),
                        f_anti(&sub[a + 1], &tub[b + 1]),
                    ];
                    let ch = |k: usize| {
                        let sg = corners.map(|c| if k == 0 { c.0 > 0.0 } else { c.1 > 0.0 });
                        sg.iter().any(|&x| x != sg[0])
                    };
                    if !(ch(0) && ch(1)) {
                        continue;
                    }
                    let (s0, t0) = (us[i] + (a as f64 + 0.5) * hs, us[j] + (b as f64 + 0.5) * hs);
                    let Some((s, t)) = newton_anti(c, s0, t0) else {
                        continue;
                    };
                    let (js_, jt_) = (c.jet(s), c.jet(t));
                    let inward = js_.d1.unit().perp() * orient;
                    if inward.dot(jt_.p - js_.p) <= 0.0 {
                        continue;
                    }
                    let (s, t) = if s <= t { (s, t) } else { (t, s) };
                    if found.iter().any(|&(x, y)| {
                        (same_param(c, x, s, 1e-7) && same_param(c, y, t, 1e-7))
                            || (same_param(c, x, t, 1e-7) && same_param(c, y, s, 1e-7))
                    }) {
                        continue;
                    }
                    found.push((s, t));
                }
            }
        }
    }
    found.sort_by(|a, b| a.0.total_cmp(&b.0));
    found
}

/// Inflections by a fine sign scan of x'y'' − x''y' + bisection.
pub fn inflection_oracle(c: &dyn PlaneCurve, n: usize) -> Vec<f64> {
    let (us, js) = jets(c, n);
    let k = |j: &Jet| j.d1.cross(j.d2);
    let (a, b) = c.domain();
    let mut out = Vec::new();
    for i in 0..n {
        let (u0, u1) = (us[i], if i + 1 < n { us[i + 1] } else { b });
        let (k0, k1) = (k(&js[i]), k(&c.jet(u1)));
        if (k0 > 0.0) != (k1 > 0.0) {
            let (mut lo, mut hi, klo) = (u0, u1, k0);
            for _ in 0..200 {
                let m = 0.5 * (lo + hi);
                if (k(&c.jet(m)) > 0.0) == (klo > 0.0) {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            let z = 0.5 * (lo + hi);
            out.push(if z >= b { a } else { z });
        }
    }
    // A jump of the curvature's sign at the seam of a closed curve (a quadratic spline's
    // curvature jumps at every knot): the end's value is the limit from the left.
    let (k_end, k_start) = (k(&c.jet(b)), k(&js[0]));
    if c.is_closed() && (k_end > 0.0) != (k_start > 0.0) && !out.contains(&a) {
        out.push(a);
    }
    out
}

/// Residuals of a reported pair: |sin| of the angle between the normals' line and r, and
/// |T(s) × T(t)|.
pub fn residual(c: &dyn PlaneCurve, s: f64, t: f64) -> f64 {
    let (js, jt) = (c.jet(s), c.jet(t));
    let (a, b) = f_anti(&js, &jt);
    a.abs().max(b.abs())
}

pub fn v(x: f64, y: f64) -> V2 {
    V2::new(x, y)
}

/// Same unordered pair of parameters (modulo the period).
pub fn same_pair(c: &dyn PlaneCurve, p: (f64, f64), q: (f64, f64), tol: f64) -> bool {
    (same_param(c, p.0, q.0, tol) && same_param(c, p.1, q.1, tol))
        || (same_param(c, p.0, q.1, tol) && same_param(c, p.1, q.0, tol))
}

/// Same unordered pair of points.
pub fn same_points(c: &dyn PlaneCurve, s: f64, t: f64, p: [f64; 2], q: [f64; 2], tol: f64) -> bool {
    let (ps, pt) = (c.jet(s).p, c.jet(t).p);
    let (p, q) = (V2::from_arr(p), V2::from_arr(q));
    ((p - ps).norm() <= tol && (q - pt).norm() <= tol)
        || ((p - pt).norm() <= tol && (q - ps).norm() <= tol)
}

fn wrap2(c: &dyn PlaneCurve, u: f64) -> f64 {
    if c.is_closed() {
        wrap(c, u)
    } else {
        let (a, b) = c.domain();
        u.clamp(a, b)
    }
}

/// All common tangent lines of two curves, by grid + Newton on
/// `T₁(s) × T₂(t) = 0`, `(α₂(t) − α₁(s)) × T₁(s) = 0`.
pub fn tangent_oracle(c1: &dyn PlaneCurve, c2: &dyn PlaneCurve, n: usize) -> Vec<(f64, f64)> {
    let (u1, j1) = jets(c1, n);
    let (u2, j2) = jets(c2, n);
    let f = |a: &Jet, b: &Jet| {
        let (ta, tb) = (a.d1.unit(), b.d1.unit());
        let r = b.p - a.p;
        (ta.cross(tb), r.cross(ta) / r.norm().max(1e-300))
    };
    let system = |s: f64, t: f64| {
        let (a, b) = (c1.jet(wrap2(c1, s)), c2.jet(wrap2(c2, t)));
        let r = b.p - a.p;
        (
            [a.d1.cross(b.d1), r.cross(a.d1)],
            [
                [a.d2.cross(b.d1), a.d1.cross(b.d2)],
                [-a.d1.cross(a.d1) + r.cross(a.d2), b.d1.cross(a.d1)],
            ],
        )
    };
    let mut out: Vec<(f64, f64)> = Vec::new();
    let m = n - 1;
    let grid: Vec<(f64, f64)> = (0..n * n).map(|k| f(&j1[k / n], &j2[k % n])).collect();
    let g = |i: usize, j: usize| grid[i * n + j];
    for i in 0..m {
        for j in 0..m {
            let cs = [g(i, j), g(i + 1, j), g(i, j + 1), g(i + 1, j + 1)];
            let ch = |k: usize| {
                let sg = cs.map(|c| if k == 0 { c.0 > 0.0 } else { c.1 > 0.0 });
                sg.iter().any(|&x| x != sg[0])
            };
            if !(ch(0) && ch(1)) {
                continue;
            }
            let start = (0.5 * (u1[i] + u1[i + 1]), 0.5 * (u2[j] + u2[j + 1]));
            let Some(((s, t), true)) = newton_from(system, start) else {
                continue;
            };
            let (s, t) = (wrap2(c1, s), wrap2(c2, t));
            let (a, b) = (c1.jet(s), c2.jet(t));
            let (g1, g2) = f(&a, &b);
            if g1.abs() > 1e-10 || g2.abs() > 1e-10 {
                continue;
            }
            if out
                .iter()
                .any(|&(x, y)| same_param(c1, x, s, 1e-7) && same_param(c2, y, t, 1e-7))
            {
                continue;
            }
            out.push((s, t));
        }
    }
    out
}

/// Residual of a common tangent: |T₁ × T₂| and the sine of the angle between r and T₁.
pub fn tangent_residual(c1: &dyn PlaneCurve, c2: &dyn PlaneCurve, s: f64, t: f64) -> f64 {
    let (a, b) = (c1.jet(s), c2.jet(t));
    let r = b.p - a.p;
    let ta = a.d1.unit();
    ta.cross(b.d1.unit())
        .abs()
        .max((r.cross(ta) / r.norm()).abs())
}
