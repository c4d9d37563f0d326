//! Subdivision of `F(t, r)` into patches whose zero set is proven simple (§4 of Elber–Kim).
//!
//! A patch is dropped when all its coefficients share a trusted sign (no zero, convex hull). It
//! is *simple* when the coefficients of one partial derivative share a trusted sign — then the
//! zero set is a graph over the other variable, so it has no loop and every component is an
//! arc from border to border — and the edge coefficients show exactly two sign changes in all
//! (each edge at most one, so each change is exactly one simple edge root). Such a patch holds
//! exactly one arc, traced by one-dimensional Newton in the graph variable. A monotone patch
//! with no edge sign change holds no zero. Everything else is split; what is still unresolved at
//! the size tolerance (crossings, isolated points, loops below the tolerance) becomes a leaf.

use crate::deviation::measured_deviation;
use crate::patch::{common_sign, tsign, variations, vsign, Patch};
use crate::solve1::{bracketed_from, bracketed_or_end};
use curve::distance_to_segment;
use numeric::rounding::UNIT_ROUNDOFF;
use numeric::subdivide::{depth_first, Decision};
use numeric::Rect;

/// Where an arc ends: on a patch edge.
#[derive(Debug, Clone, Copy)]
pub(crate) struct End {
    /// The end point `(t, r)`.
    pub(crate) p: [f64; 2],
    /// Edge of the patch it lies on (0 bottom, 1 right, 2 top, 3 left).
    pub(crate) edge: usize,
    /// The fixed coordinate of that edge's line.
    pub(crate) line: f64,
    /// Uncertainty of the position along the line: the patch's rounding bound of F (below
    /// which a corner value counts as positive, moving a root that passes near a corner onto
    /// the corner) over the slope of F along the line there. Large beside a crossing, where
    /// the slope vanishes, and where the zero set meets the line at a grazing angle.
    pub(crate) unc: f64,
}

/// An arc inside one simple patch, from `a` to `b`, with its vertices (ends included).
#[derive(Debug, Clone)]
pub(crate) struct Arc {
    pub(crate) pts: Vec<[f64; 2]>,
    pub(crate) ends: [End; 2],
}

/// A patch left unresolved at the size tolerance.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Leaf {
    pub(crate) bx: Rect,
    /// Centre and `|F|` there.
    pub(crate) center: [f64; 2],
    pub(crate) fabs: f64,
    /// Index of the Bézier cell it lies in.
    pub(crate) cell: usize,
}

/// What the tracer needs besides the function.
pub(crate) struct Tracer<'a> {
    /// Leaf size in `t` and `r` (absolute).
    pub(crate) min_size: [f64; 2],
    /// Domain extents, to compare patch sizes in both directions.
    pub(crate) extent: [f64; 2],
    /// The domain `[t0, t1, r0, r1]`.
    pub(crate) dom: Rect,
    pub(crate) max_depth: usize,
    pub(crate) max_patches: usize,
    /// Maps `(t, r)` to the space where chords are measured (`None`: far away, do not refine).
    pub(crate) map: &'a dyn Fn(f64, f64) -> Option<[f64; 2]>,
    pub(crate) chord_tol: f64,
    /// Region filter: patches for which this is false are dropped unseen.
    pub(crate) keep: &'a dyn Fn(&Patch) -> bool,
    /// Cells where F has a known zero of high order at a corner (a self-bisector's cells
    /// touching the diagonal there), in which the check of inner edge coefficients is off.
    pub(crate) lax: &'a dyn Fn(&Patch) -> bool,
    /// Whether the arc of a simple patch may stand as it is, as far as the patch tells
    /// before the arc is traced; [`Settle::Splits`] splits the patch further (down to the
    /// size limit), as a caller that must know more about each arc than that it is simple
    /// asks (see [`crate::nonnegative_set`]).
    pub(crate) settle: &'a dyn Fn(&Patch) -> Settle,
    /// Where `settle` says [`Settle::ByVertices`]: whether the arc with these vertices (its
    /// ends first, then all of them) stands.
    pub(crate) settle_vertices: &'a dyn Fn(&Patch, &[[f64; 2]]) -> bool,
}

/// What a caller tells of a simple patch's arc before it is traced ([`Tracer::settle`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Settle {
    /// The arc stands as traced.
    Stands,
    /// The patch is split further, whatever its arc.
    Splits,
    /// The arc's vertices decide ([`Tracer::settle_vertices`]).
    ByVertices,
}

/// Result of the subdivision of all cells.
#[derive(Debug, Default)]
pub(crate) struct Pieces {
    pub(crate) arcs: Vec<Arc>,
    pub(crate) leaves: Vec<Leaf>,
    /// Patches examined.
    pub(crate) patches: usize,
    /// True when a limit (patch count) cut the search short.
    pub(crate) truncated: bool,
}

/// Split ratios slightly off the middle and different in `t` and `r`, so zeros at "round"
/// parameters (and on the diagonal of a square domain) rarely land on corners.
const SPLIT_T: f64 = 0.498_763_4;
const SPLIT_R: f64 = 0.501_349_7;
/// Samples on both sides of a chord farther than this fraction of the tolerance make an S
/// (halved); below it, the smaller bump's peak stays within the tolerance: it is the image of
/// at most half the parameter (one sample lies on it), where the `UNEVEN` bound makes its peak
/// at most a few times its sample.
const TWO_BUMPS_FLOOR: f64 = 0.1;

/// Longest segment in `(t, r)`, relative to the domain.
const MAX_SEG: f64 = 1.0 / 16.0;
/// Vertex refinement depth per arc for the chord test.
const MAX_TRACE_CHORD_DEPTH: usize = 20;
/// Largest ratio of the images of the two halves of a segment before it is halved anyway.
const UNEVEN: f64 = 4.0;
/// Step (relative to the domain) along the zero set for the direction of its image.
const TANGENT_STEP: f64 = 1e-7;
/// Bisection depth toward the edge of the valid set (one new vertex pair per level).
const MAX_CELL_EDGE_DEPTH: usize = 48;
/// Bisection toward the edge of the valid set stops at segments this short (relative to the
/// domain in each parameter): the edge is then located as finely as arc ends are matched
/// (`MATCH_TOL` of the assembly), far above the parameters' rounding.
const EDGE_RESOLUTION: f64 = 1e-7;

impl Tracer<'_> {
    /// Runs the subdivision on every cell (`cells` are the function's Bézier patches).
    pub(crate) fn run(&self, cells: &[Patch], out: &mut Pieces) {
        for (ci, cell) in cells.iter().enumerate() {
            if !(self.keep)(cell) {
                continue;
            }
            let scale = cell.max_abs();
            if scale == 0.0 {
                // F vanishes on the whole cell: nothing a zero-set extractor can report.
                out.truncated = true;
                continue;
            }
            let strict = !(self.lax)(cell);
            let over = depth_first(cell.clone(), self.max_depth, |p, visit| {
                // (A half the region filter drops is passed over unseen and uncounted; the
                // cell itself passed it above.)
                if visit.depth > 0 && !(self.keep)(&p) {
                    return Decision::Decided;
                }
                out.patches += 1;
                if out.patches > self.max_patches {
                    out.truncated = true;
                    return Decision::Stop(());
                }
                let err =
                    (p.pt + p.pr + 2) as f64 * (visit.depth + 4) as f64 * UNIT_ROUNDOFF * scale;
                match self.classify(&p, err, strict) {
                    Class::Empty => {}
                    Class::Simple(graph_r) => {
                        let small =
                            p.t1 - p.t0 <= self.min_size[0] && p.r1 - p.r0 <= self.min_size[1];
                        let may_split = !small && visit.can_halve;
                        // (What is split is not traced: its halves are.)
                        let verdict = (self.settle)(&p);
                        if verdict == Settle::Splits && may_split {
                            return self.halve(&p);
                        }
                        let Some(ends) = self.ends(cell, &p, err) else {
                            return Decision::Decided;
                        };
                        let by_vertices = verdict == Settle::ByVertices && may_split;
                        if by_vertices && !(self.settle_vertices)(&p, &[ends[0].p, ends[1].p]) {
                            return self.halve(&p);
                        }
                        let arc = self.arc(cell, &p, graph_r, ends);
                        if by_vertices && !(self.settle_vertices)(&p, &arc.pts) {
                            return self.halve(&p);
                        }
                        out.arcs.push(arc);
                    }
                    Class::Split => {
                        let small =
                            p.t1 - p.t0 <= self.min_size[0] && p.r1 - p.r0 <= self.min_size[1];
                        // F within rounding of zero on the whole patch: no sign can be trusted
                        // here, so splitting further cannot resolve anything.
                        let flat = p.max_abs() <= 4.0 * err;
                        if small || flat || !visit.can_halve {
                            let c = [0.5 * (p.t0 + p.t1), 0.5 * (p.r0 + p.r1)];
                            out.leaves.push(Leaf {
                                bx: p.rect(),
                                center: c,
                                fabs: cell.eval(c[0], c[1]).abs(),
                                cell: ci,
                            });
                            return Decision::Decided;
                        }
                        return self.halve(&p);
                    }
                }
                Decision::Decided
            });
            if over.is_some() {
                return;
            }
        }
    }

    /// The patch split across its longer side (relative to the domain).
    fn halve<R>(&self, p: &Patch) -> Decision<Patch, R> {
        let wt = (p.t1 - p.t0) / self.extent[0];
        let wr = (p.r1 - p.r0) / self.extent[1];
        let (a, b) = if wt >= wr {
            p.split_t(SPLIT_T)
        } else {
            p.split_r(SPLIT_R)
        };
        Decision::Halve(a, b)
    }

    fn classify(&self, p: &Patch, err: f64, strict: bool) -> Class {
        if common_sign(p.c.iter().copied(), err) != 0 {
            return Class::Empty;
        }
        let mono_t = common_sign(p.dt_coefs(), 2.0 * err) != 0;
        let mono_r = common_sign(p.dr_coefs(), 2.0 * err) != 0;
        if !(mono_t || mono_r) {
            return Class::Split;
        }
        // The count of edge roots below is only a proof when the inner coefficients of each
        // edge have trusted signs. One within rounding of zero (beside the flat region around
        // a crossing) can hide a pair of roots: a V of two arms just beside a crossing then
        // looked like one arc from side to side, and the crossing was lost. Such a patch is
        // split (and ends as a leaf if it stays so). Corner values within rounding are fine
        // (adjacent patches agree on the sign convention, so a zero at a corner is seen once,
        // beside it), and so are edges on the border of the domain, where nothing is joined
        // (a curve tangent to the border would be split down to the size limit all along
        // its contact). Off in `lax` cells: around a self-bisector's knot corner on the
        // diagonal F is flat to fourth order, and the check would swallow the short genuine
        // branches that start there into leaves.
        if strict {
            let unsure = |e: usize| {
                let on_border = match e {
                    0 => p.r0 == self.dom.r.lo,
                    1 => p.t1 == self.dom.t.hi,
                    2 => p.r1 == self.dom.r.hi,
                    _ => p.t0 == self.dom.t.lo,
                };
                let c = p.edge(e);
                // (An edge of degree 0 or 1 has no inner coefficient.)
                let inner = c.get(1..c.len().saturating_sub(1)).unwrap_or(&[]);
                !on_border && inner.iter().any(|&x| tsign(x, err) == 0)
            };
            if (0..4).any(unsure) {
                return Class::Split;
            }
        }
        let mut total = 0;
        for e in 0..4 {
            match variations(p.edge(e).into_iter(), err) {
                v @ 0..=1 => total += v,
                _ => return Class::Split,
            }
        }
        match total {
            0 => Class::Empty,
            2 => {
                // Prefer the graph variable along which the arc is long (better conditioned).
                let graph_r = if mono_t && mono_r {
                    (p.r1 - p.r0) / self.extent[1] >= (p.t1 - p.t0) / self.extent[0]
                } else {
                    mono_t
                };
                Class::Simple(graph_r)
            }
            _ => Class::Split,
        }
    }

    /// The two ends of the arc of a simple patch, on its edges (`None` when the edge solves
    /// do not give two).
    fn ends(&self, cell: &Patch, p: &Patch, err: f64) -> Option<[End; 2]> {
        let noise = cell_noise(cell);
        let mut ends: Vec<End> = Vec::with_capacity(2);
        for e in 0..4 {
            let coefs = p.edge(e);
            if variations(coefs.iter().copied(), err) != 1 {
                continue;
            }
            let s0 = vsign(coefs[0], err);
            // Edges 0 and 2 run along t at a fixed r, edges 1 and 3 along r at a fixed t; the
            // crossing is found by a bracketed solve in the running variable.
            let along_t = e == 0 || e == 2;
            let (fixed, lo, hi) = match e {
                0 => (p.r0, p.t0, p.t1),
                2 => (p.r1, p.t0, p.t1),
                3 => (p.t0, p.r0, p.r1),
                _ => (p.t1, p.r0, p.r1),
            };
            let at = |x: f64| if along_t { [x, fixed] } else { [fixed, x] };
            // Index of the partial derivative in the running variable in `eval_grad`.
            let k = if along_t { 1 } else { 2 };
            let x0 = polygon_crossing(lo, hi, &coefs, err);
            let x = bracketed_from(|x| cell.value_and_partial(at(x), k), lo, hi, s0, x0, noise);
            let [t, r] = at(x);
            let end = End {
                p: [t, r],
                edge: e,
                line: fixed,
                unc: err / cell.eval_grad(t, r)[k].abs(),
            };
            ends.push(end);
        }
        (ends.len() == 2).then(|| [ends[0], ends[1]])
    }

    /// The arc of a simple patch between its `ends`. `graph_r`: the arc is `t = φ(r)` (else
    /// `r = ψ(t)`).
    fn arc(&self, cell: &Patch, p: &Patch, graph_r: bool, [a, b]: [End; 2]) -> Arc {
        let noise = cell_noise(cell);
        // The arc as a function of the graph variable s; the other coordinate is solved for.
        let k = if graph_r { 1 } else { 0 };
        // Start each solve on the chord between the ends (the arc is close to it).
        let (sa, sb) = (a.p[k], b.p[k]);
        let (oa, ob) = (a.p[1 - k], b.p[1 - k]);
        // The solved variable is t (∂/∂t is `eval_grad`'s entry 1) on a graph over r, else r.
        let (lo, hi, dk) = if graph_r {
            (p.t0, p.t1, 1)
        } else {
            (p.r0, p.r1, 2)
        };
        let at = |x: f64, s: f64| if graph_r { [x, s] } else { [s, x] };
        let point = |s: f64| -> [f64; 2] {
            let w = if sb != sa { (s - sa) / (sb - sa) } else { 0.5 };
            let x0 = oa + w * (ob - oa);
            let x = bracketed_or_end(|x| cell.value_and_partial(at(x, s), dk), lo, hi, x0, noise);
            at(x, s)
        };
        // The direction of the mapped curve at a vertex, oriented from `a` toward `b`: the
        // image of a short step along the zero set's tangent (F_r, −F_t).
        let forward = if sb >= sa { 1.0 } else { -1.0 };
        let tangent = |q: [f64; 2], m: Option<[f64; 2]>| -> Option<[f64; 2]> {
            let m = m?;
            let g = cell.eval_grad(q[0], q[1]);
            let mut d = [g[2] * self.extent[0], -g[1] * self.extent[1]];
            if d[k] * forward < 0.0 {
                d = [-d[0], -d[1]];
            }
            let len = d[0].hypot(d[1]);
            if len == 0.0 || !len.is_finite() {
                return None;
            }
            let h = TANGENT_STEP / len;
            let z = (self.map)(
                q[0] + h * d[0] * self.extent[0],
                q[1] + h * d[1] * self.extent[1],
            )?;
            Some([z[0] - m[0], z[1] - m[1]])
        };
        let mut pts = vec![a.p];
        let ma = (self.map)(a.p[0], a.p[1]);
        let mb = (self.map)(b.p[0], b.p[1]);
        let va = Vtx {
            s: a.p[k],
            p: a.p,
            m: ma,
            tan: tangent(a.p, ma),
        };
        let vb = Vtx {
            s: b.p[k],
            p: b.p,
            m: mb,
            tan: tangent(b.p, mb),
        };
        self.refine(&point, &tangent, va, vb, None, 0, &mut pts);
        pts.push(b.p);
        Arc { pts, ends: [a, b] }
    }

    /// Adds the interior vertices between two arc points until every chord is within tolerance
    /// in the mapped space (checked at the middle and at the quarter points of the parameter)
    /// and the mapped curve runs forward along each chord at both its ends.
    ///
    /// The second test catches folds of the image (a bisector turns back at a cusp): a fold
    /// narrower than the sample spacing passes the sampled chord test, since all samples may
    /// lie on the returning part, but the tangent at the vertex before it points away from
    /// the next vertex.
    #[allow(clippy::too_many_arguments)]
    fn refine(
        &self,
        point: &dyn Fn(f64) -> [f64; 2],
        tangent: &dyn Fn([f64; 2], Option<[f64; 2]>) -> Option<[f64; 2]>,
        a: Vtx,
        b: Vtx,
        mid: Option<Sample>,
        depth: usize,
        out: &mut Vec<[f64; 2]>,
    ) {
        let sm = 0.5 * (a.s + b.s);
        let (pm, mm) = mid.unwrap_or_else(|| {
            let pm = point(sm);
            (pm, (self.map)(pm[0], pm[1]))
        });
        // A sampled chord test can miss an excursion between its samples: also keep the
        // segments short in (t, r), where the zero set itself is smooth and slow.
        let long = (b.p[0] - a.p[0]).abs() > MAX_SEG * self.extent[0]
            || (b.p[1] - a.p[1]).abs() > MAX_SEG * self.extent[1];
        // Where the mapped curve runs off to infinity (a pole of P) or leaves the valid set,
        // bisect toward the boundary so the branch gets as close as the mapping allows.
        let toward_edge =
            (a.m.is_some() != b.m.is_some()) || (a.m.is_some() && b.m.is_some() && mm.is_none());
        let tiny = (b.p[0] - a.p[0]).abs() <= EDGE_RESOLUTION * self.extent[0]
            && (b.p[1] - a.p[1]).abs() <= EDGE_RESOLUTION * self.extent[1];
        // The quarter points, when the chord test computed them: the children's midpoints.
        let mut quarters: (Option<Sample>, Option<Sample>) = (None, None);
        let need = if toward_edge {
            depth < MAX_CELL_EDGE_DEPTH && !tiny
        } else {
            depth < MAX_TRACE_CHORD_DEPTH
                && (long
                    || match (a.m, b.m, mm) {
                        (Some(x), Some(y), Some(m)) => {
                            let c = [y[0] - x[0], y[1] - x[1]];
                            let back = |t: Option<[f64; 2]>| {
                                t.is_some_and(|t| t[0] * c[0] + t[1] * c[1] <= 0.0)
                            };
                            let (h1, h2) = (
                                (m[0] - x[0]).hypot(m[1] - x[1]),
                                (m[0] - y[0]).hypot(m[1] - y[1]),
                            );
                            // A fold is located to within the chord tolerance: once the
                            // image of the segment is that small, stop.
                            let big = h1.max(h2) > self.chord_tol;
                            // Samples at fixed fractions of the parameter say little where
                            // the image speed varies strongly (toward a pole of the bisector
                            // point): halve until the two halves' images are comparable.
                            let uneven = big && h1.max(h2) > UNEVEN * h1.min(h2);
                            uneven || (big && (back(a.tan) || back(b.tan))) || {
                                let sample = |w: f64| {
                                    let q = point((1.0 - w) * a.s + w * b.s);
                                    (q, (self.map)(q[0], q[1]))
                                };
                                let (q1, q3) = (sample(0.25), sample(0.75));
                                quarters = (Some(q1), Some(q3));
                                // The quarters' images as uneven as the halves' may be:
                                // a bump between samples then escapes the parabolic climb.
                                let quarter_uneven = match (q1.1, q3.1) {
                                    (Some(z1), Some(z3)) => {
                                        let len = |p: [f64; 2], q: [f64; 2]| {
                                            (p[0] - q[0]).hypot(p[1] - q[1])
                                        };
                                        let steps =
                                            [len(x, z1), len(z1, m), len(m, z3), len(z3, y)];
                                        let most = steps.iter().fold(0.0f64, |a, &b| a.max(b));
                                        let least =
                                            steps.iter().fold(f64::INFINITY, |a, &b| a.min(b));
                                        big && most > UNEVEN * least
                                    }
                                    _ => false,
                                };
                                // (From the chord as a segment: the parameter need not be
                                // proportional to arc length, so the nearest chord point is
                                // not at the sample's fraction.)
                                let off =
                                    |q: Sample| q.1.map_or(0.0, |z| distance_to_segment(z, x, y));
                                let sampled = [off(q1), distance_to_segment(m, x, y), off(q3)];
                                let deviation = |w: f64| off(sample(w));
                                // An arc seen on both sides of its chord is an S, two bumps:
                                // a peak may hide beside either, where neither the unseen-peak
                                // bound nor the climb (both for one bump) looks.
                                let side = |z: [f64; 2]| {
                                    (y[0] - x[0]) * (z[1] - x[1]) - (y[1] - x[1]) * (z[0] - x[0])
                                };
                                let lobes = [q1.1, Some(m), q3.1];
                                let seen = |positive: bool| {
                                    (0..3).any(|i| {
                                        lobes[i].is_some_and(|z| (side(z) > 0.0) == positive)
                                            && sampled[i] > TWO_BUMPS_FLOOR * self.chord_tol
                                    })
                                };
                                quarter_uneven
                                    || (seen(true) && seen(false))
                                    || measured_deviation(&deviation, sampled, self.chord_tol)
                                        > self.chord_tol
                            }
                        }
                        _ => false,
                    })
        };
        // Always keep one interior vertex (a patch-sized chord can hide a bulge in tr), and
        // test the two chords it makes: the arc within the tolerance of the whole chord may
        // stray from a half's (an S about the whole chord, the middle on one side).
        if need || depth == 0 {
            let vm = Vtx {
                s: sm,
                p: pm,
                m: mm,
                tan: tangent(pm, mm),
            };
            self.refine(point, tangent, a, vm, quarters.0, depth + 1, out);
            out.push(pm);
            self.refine(point, tangent, vm, b, quarters.1, depth + 1, out);
        }
    }
}

/// The rounding level of the values of the cell `cell` (where the edge and arc solves stop).
fn cell_noise(cell: &Patch) -> f64 {
    2.0 * (cell.pt + cell.pr + 2) as f64 * UNIT_ROUNDOFF * cell.max_abs()
}

/// A point of an arc and its image.
type Sample = ([f64; 2], Option<[f64; 2]>);

/// A vertex of an arc under refinement: graph parameter, point, its image (`None`: not a
/// valid point of the mapping) and the image's direction there.
#[derive(Clone, Copy)]
struct Vtx {
    s: f64,
    p: [f64; 2],
    m: Option<[f64; 2]>,
    tan: Option<[f64; 2]>,
}

/// Where the control polygon of the Bernstein coefficients `c` of an edge from `a` to `b`
/// crosses zero at the one sign variation of [`variations`] (the start for its edge root).
///
/// Not the chord between the end values: with a corner value within rounding of zero (a
/// curve passing through the corner, seen by the patch across) and the variation at the other
/// end, the chord crosses zero at that corner, where `|F|` is at rounding level, so the solve
/// stopped there at once and took the corner's curve for the one the variation counts — an arc
/// bridging two arms beside a crossing, and a branch end left with no partner.
fn polygon_crossing(a: f64, b: f64, c: &[f64], err: f64) -> f64 {
    let n = c.len() - 1;
    let Some(i) = (0..n).find(|&i| vsign(c[i], err) != vsign(c[i + 1], err)) else {
        return 0.5 * (a + b);
    };
    let w = if c[i] == c[i + 1] {
        0.5
    } else {
        (c[i] / (c[i] - c[i + 1])).clamp(0.0, 1.0)
    };
    a + (b - a) * (i as f64 + w) / n as f64
}

enum Class {
    Empty,
    /// One arc; `true` when it is a graph over `r`.
    Simple(bool),
    Split,
}
