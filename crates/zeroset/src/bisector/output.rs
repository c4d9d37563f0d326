//! The bisector as returned (branches, singular and isolated points) and how it is built from
//! the zero set's polylines: cut at the diagonal, extended to knot corners, joined at the seam.
//! Whole branches; the test of each vertex is in `vertices`.

use super::vertices::{Ctx, DIAGONAL_MARGIN};
use crate::extract::Pieces;
use crate::patch::Patch;
use crate::zeroset::finish;
use numeric::Rect;
use serde::{Deserialize, Serialize};

/// Singular and isolated points of a self-bisector within this fraction of the domain of the
/// diagonal are taken for leaf clusters at the cells' diagonal corners, where the undivided
/// function has its trivial double zero: artefacts, not bisector points (a wide margin: the
/// flat region at a corner reaches ~1e-3 of the domain, see `knot_corners`).
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

/// One branch: matched foot-point parameters and the bisector points they give; of profiles,
/// also the sites its feet lie on (one site pair per branch).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Branch {
    /// `[t, r]` per vertex: the foot points' parameters (a profile's; a corner's is constant).
    pub tr: Vec<[f64; 2]>,
    /// `P(t, r)` per vertex.
    pub xy: Vec<[f64; 2]>,
    /// Of profiles: the segment of each foot point (for a corner, the segment starting
    /// there; `None` of curves, whose document does not write it: see [`Branch::segments`]).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub segment: Option<[usize; 2]>,
    /// Of profiles: whether each foot point is a corner.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub corner: Option<[bool; 2]>,
}

/// A special point of the bisector.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BisectorPoint {
    /// Foot-point parameters.
    pub tr: [f64; 2],
    /// The bisector point.
    pub xy: [f64; 2],
    /// Of profiles: the segment of each foot point (`None` of curves).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub segment: Option<[usize; 2]>,
    /// Of profiles: whether each foot point is a corner (always false: special points come
    /// from segments).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub corner: Option<[bool; 2]>,
}

/// The bisector of two curves or profiles, or the self-bisector of one.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Bisector {
    /// The branches (of profiles: site pair by site pair).
    pub branches: Vec<Branch>,
    /// Where branches cross (singular points of the zero set).
    pub singular: Vec<BisectorPoint>,
    /// Isolated bisector points (among them the centres of arcs of one circle).
    pub isolated: Vec<BisectorPoint>,
    /// False when a search limit was hit.
    pub complete: bool,
}

impl Branch {
    /// A branch of curves' bisector, its sites not stated.
    pub(crate) fn of_curves(tr: Vec<[f64; 2]>, xy: Vec<[f64; 2]>) -> Branch {
        Branch {
            tr,
            xy,
            segment: None,
            corner: None,
        }
    }

    /// The segment of each foot point: a profile's, segment 0 of a curve (a profile of that
    /// one segment).
    pub fn segments(&self) -> [usize; 2] {
        self.segment.unwrap_or([0; 2])
    }

    /// Whether each foot point is a corner (never on a curve).
    pub fn corners(&self) -> [bool; 2] {
        self.corner.unwrap_or([false; 2])
    }
}

impl BisectorPoint {
    /// The segment of each foot point: a profile's, segment 0 of a curve.
    pub fn segments(&self) -> [usize; 2] {
        self.segment.unwrap_or([0; 2])
    }

    /// Whether each foot point is a corner (never on a curve).
    pub fn corners(&self) -> [bool; 2] {
        self.corner.unwrap_or([false; 2])
    }
}

impl Bisector {
    /// The bisector as that of curves: the sites dropped, the parameters kept. For profiles
    /// of one segment without a corner, what the curves' bisector reports.
    pub fn without_sites(self) -> Bisector {
        let point = |p: BisectorPoint| BisectorPoint {
            segment: None,
            corner: None,
            ..p
        };
        Bisector {
            branches: self
                .branches
                .into_iter()
                .map(|b| Branch::of_curves(b.tr, b.xy))
                .collect(),
            singular: self.singular.into_iter().map(point).collect(),
            isolated: self.isolated.into_iter().map(point).collect(),
            complete: self.complete,
        }
    }
}

impl Ctx<'_> {
    pub(super) fn build(&self, pieces: &Pieces, dom: Rect, cells: &[Patch]) -> Bisector {
        let z = finish(pieces, dom, cells);
        let mut branches = Vec::new();
        for pl in &z.branches {
            let pts = if self.selfb {
                clip_diagonal(&pl.pts, DIAGONAL_MARGIN * (dom.t.width()), &|a, b| {
                    diagonal_end(cells, a, b, dom)
                })
            } else {
                pl.pts.iter().map(|&q| Some(q)).collect()
            };
            let mut cur = Branch::of_curves(Vec::new(), Vec::new());
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
        let ext = dom.t.width();
        let special = |v: &[[f64; 2]]| -> Vec<BisectorPoint> {
            v.iter()
                .filter(|q| !self.selfb || q[1] - q[0] > DIAGONAL_ARTEFACT * ext)
                // For a closed curve the corner (start, end) is the diagonal across the seam.
                .filter(|q| !closed || q[1] - q[0] < (1.0 - DIAGONAL_ARTEFACT) * ext)
                .filter_map(|q| {
                    self.accept(q[0], q[1]).map(|(tr, xy)| BisectorPoint {
                        tr,
                        xy,
                        segment: None,
                        corner: None,
                    })
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

fn flush(cur: &mut Branch, out: &mut Vec<Branch>) {
    if cur.tr.len() >= 2 {
        out.push(std::mem::replace(
            cur,
            Branch::of_curves(Vec::new(), Vec::new()),
        ));
    } else {
        cur.tr.clear();
        cur.xy.clear();
    }
}

/// Joins branches across the seam of a closed curve: `(start, ρ)` on the border `t = start`
/// is the same foot-point pair as `(ρ, end)` on the border `r = end` (parameters modulo the
/// period, mirrored into `t ≤ r`).
fn join_seam(mut v: Vec<Branch>, dom: Rect) -> Vec<Branch> {
    let tol = SEAM_MATCH * (dom.t.width());
    let on_top = |q: [f64; 2]| q[1] == dom.r.hi;
    let on_left = |q: [f64; 2]| q[0] == dom.t.lo;
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
/// on the `t < r` side (Newton along the diagonal direction). `None` where no crossing lies
/// beside the segment.
fn diagonal_end(cells: &[Patch], a: [f64; 2], b: [f64; 2], dom: Rect) -> Option<[f64; 2]> {
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
    // A crossing far from the segment is another zero of the divided function on the
    // diagonal (the segment may end at a knot corner, where the cell's piece has none).
    if (s - c).abs() > (b[0] - a[0]).abs() + (b[1] - a[1]).abs() {
        return None;
    }
    let delta = DIAGONAL_OFFSET * (dom.t.width());
    let base = [s - delta, s + delta];
    let mu = solve(base, 0.0)?;
    let e = [base[0] + mu, base[1] + mu];
    let inside = e[0] >= cell.t0 && e[0] <= cell.t1 && e[1] >= cell.r0 && e[1] <= cell.r1;
    (inside && s > lo && s < hi && mu.abs() < 1e3 * delta).then_some(e)
}
