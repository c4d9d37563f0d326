//! The bisector as returned (branches, singular and isolated points) and how it is built from
//! the zero set's polylines: cut at the diagonal, extended to knot corners, joined at the seam.
//! Whole branches; the test of each vertex is in `vertices`.

use super::vertices::{Ctx, DIAGONAL_MARGIN};
use crate::extract::Pieces;
use crate::patch::Patch;
use crate::zeroset::finish;
use serde::{Deserialize, Serialize};

/// A self-bisector branch ending this close (relative to the domain) to a knot corner of the
/// diagonal, on the cell across it, is extended to the corner.
const CORNER_REACH: f64 = 1e-3;

/// Halvings toward a knot corner at most (from ~1e-5 of the domain down to ~1e-11).
const MAX_CORNER_STEPS: usize = 20;

/// Slack on "in step" toward a knot corner, relative to the bounding-box diagonal: the
/// bisector points carry rounding of ~1e-16 of the size, so steps that have shrunk to that
/// noise still count as in step.
const STEP_SLACK: f64 = 1e-12;

/// Singular and isolated points of a self-bisector within this fraction of the domain of the
/// diagonal are taken for leaf clusters at the cells' diagonal corners, where the undivided
/// function has its trivial double zero: artefacts, not bisector points (a wide margin: the
/// flat region at a corner reaches ~1e-5 of the domain, see `reach_knot_corners`).
const DIAGONAL_ARTEFACT: f64 = 1e-3;

/// Two branch ends on the two borders of the seam are one foot-point pair when their
/// parameters agree to this fraction of the domain: both are zero-set vertices refined to
/// rounding, which agree far closer than this.
const SEAM_MATCH: f64 = 1e-9;

/// Newton along a line through the diagonal has converged when its step is this small
/// relative to the cell: it converges quadratically, so the error after such a step is far
/// below rounding, while the steps themselves need not fall below the rounding noise of `G`
/// (1e-15 of the cell is about one ulp: asking for it can fail to converge).
const DIAGONAL_NEWTON_STEP: f64 = 1e-12;

/// A branch cut at the diagonal ends this far off it (relative to the domain), on the
/// zero set: far outside [`DIAGONAL_MARGIN`], so the end is kept as a vertex, and close
/// enough that the branch reaches the diagonal as drawn.
const DIAGONAL_OFFSET: f64 = 1e-6;

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

impl Ctx<'_> {
    pub(super) fn build(&self, pieces: &Pieces, dom: [f64; 4], cells: &[Patch]) -> Bisector {
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
                .filter(|q| !self.selfb || q[1] - q[0] > DIAGONAL_ARTEFACT * ext)
                // For a closed curve the corner (start, end) is the diagonal across the seam.
                .filter(|q| !closed || q[1] - q[0] < (1.0 - DIAGONAL_ARTEFACT) * ext)
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
                        || moved > 2.0 * step + STEP_SLACK * self.diag
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
    let tol = SEAM_MATCH * (dom[1] - dom[0]);
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
            if step.abs() <= DIAGONAL_NEWTON_STEP * (hi - lo) {
                return Some(mu);
            }
        }
        None
    };
    let s = solve([0.0, 0.0], c)?;
    let delta = DIAGONAL_OFFSET * (dom[1] - dom[0]);
    let base = [s - delta, s + delta];
    let mu = solve(base, 0.0)?;
    let e = [base[0] + mu, base[1] + mu];
    let inside = e[0] >= cell.t0 && e[0] <= cell.t1 && e[1] >= cell.r0 && e[1] <= cell.r1;
    (inside && s > lo && s < hi && mu.abs() < 1e3 * delta).then_some(e)
}
