//! The boundary of the set where several bivariate functions are all non-negative: each
//! function's zero set, traced by the subdivision of [`crate::zero_set`] only where no other
//! function is proven negative, then cut where another function changes sign.
//!
//! The set `{F₁ ≥ 0, …, Fₙ ≥ 0}` is bounded by pieces of the zero sets `Fₖ = 0` on which every
//! other function is non-negative; consecutive pieces meet where two zero sets cross. Tracing
//! each `Fₖ = 0` on the whole domain would spend most of the work where some other function is
//! negative, so a patch is passed over when another function's Bernstein coefficients there
//! are all negative beyond their rounding (or the caller proves the set empty there).
//!
//! On a domain of pairs (`t < r` of one parameter, as for two contacts on one curve) every
//! function vanishes on the diagonal: the factor `(t − r)` is divided out of the diagonal
//! cells, as for a self-bisector, and only the half `t < r` is traced.
//!
//! Where every function vanishes at a corner of the domain (two contacts meeting at a joint
//! of a curve), zero sets leave the corner in several directions and no subdivision parts
//! them. A small box at that corner is cut out of every function's cells and traced apart,
//! blown up ([`crate::blowup`]: divided by the distance to the corner, the functions no
//! longer vanish there); its pieces are joined to the rest where they cross its border, and
//! where a set of pinch grasps reaches the corner, its boundary runs into it.

use crate::assemble::MATCH_TOL;
use crate::blowup::Corner;
use crate::boundary::{drop_retraced, end_at, join_loose, BoundaryPiece, PieceEnd};
use crate::error::{Error, Result};
use crate::extract::Settle;
use crate::patch::{common_sign, Patch};
use crate::system::unique;
use crate::zeroset::{finish, run_cells, Filters, ZeroSetOptions};
use affine::affine_set;
use bspline::tensor::TensorBSpline;
use cells::Cells;
use numeric::newton2::{polish, Matrix2, Newton2, StepVerdict, Vector2};
use numeric::rounding::UNIT_ROUNDOFF;
use numeric::solve::{bracketed_free, Accuracy};
use numeric::tolerance::Size;
use numeric::Rect;
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
use std::collections::HashMap;

mod affine;
mod cells;

/// A function within this much (relative to its largest coefficient) of zero at a point of
/// another's zero set is taken as vanishing there: two zero sets that coincide along a
/// stretch (a circle's two cone conditions, one at each contact) then give that stretch
/// once, to the function of lower index, rather than cut at every vertex by rounding.
const ZERO_BAND: f64 = 1e-10;

/// Two functions vanishing at a point vanish along one curve there when their gradients are
/// parallel to this (the sine of the angle between them): well above the rounding of
/// gradients of coinciding zero sets, far below any transversal crossing's.
const ALONG: f64 = 1e-6;

/// Newton steps for a crossing of two zero sets (quadratic convergence from a start within a
/// chord of the crossing needs a handful).
const CROSSING_STEPS: usize = 12;

/// Newton steps moving a point of a chord onto its zero set (it starts within the chord
/// tolerance: quadratic convergence needs a few).
const PROJECTION_STEPS: usize = 3;

/// How far (relative to the chord) the two-dimensional Newton may move a crossing found by
/// bisection before it is distrusted: it only polishes the last bits.
const POLISH_REACH: f64 = 1e-3;

/// Boxes whose restricted patches a set's tracing keeps at most: a few tens of megabytes at
/// the highest degrees, however many patches the limit lets the subdivision visit (beyond
/// it they are restricted again).
const RESTRICTED_BOXES: usize = 1 << 14;

/// Bisection steps along a chord for where another function changes sign (to the last bit of
/// a unit chord).
const CHORD_BISECTIONS: usize = 60;

/// Options for [`nonnegative_set`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct NonNegativeOptions {
    /// The tolerances and the patch limit of each function's zero set.
    pub zero: ZeroSetOptions,
    /// A domain of pairs: only `t < r` is traced, and every function vanishes on the diagonal
    /// `t = r` (where its factor `t − r` is divided out).
    pub pairs: bool,
    /// Points where every function vanishes besides the diagonal (where two contacts on a
    /// curve meet: the corner `(start, end)` of a closed curve's seam, the joint of two
    /// segments). At a corner of the domain, a small box round the point is traced blown up
    /// (the zero sets leaving the point are told apart there); elsewhere, an arc through one
    /// is that point's, not a boundary's, and its patch is split on until `excluded` passes
    /// over it.
    pub meets: Vec<[f64; 2]>,
}

/// The boundary of `{F₁ ≥ 0, …, Fₙ ≥ 0}` ([`nonnegative_set`]).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct NonNegativeSet {
    /// The pieces of the boundary.
    pub pieces: Vec<BoundaryPiece>,
    /// Isolated points of the set (a zero of one function where the others are positive and
    /// which its zero set does not leave).
    pub points: Vec<[f64; 2]>,
    /// Points of the boundary the subdivision did not resolve (a zero set's singular points).
    pub unresolved: Vec<[f64; 2]>,
    /// False when a patch limit was hit or a function vanishes on a whole cell.
    pub complete: bool,
    /// Patches examined.
    pub patches: usize,
}

/// The boundary of the set where every function of `fs` is non-negative, on their common
/// domain. `excluded(rect)` is the caller's own proof that the set has no point in `rect`
/// (return `false` when there is none); such patches are passed over.
///
/// ```
/// use bspline::{tensor::TensorBSpline, BSpline};
/// use zeroset::{nonnegative_set, NonNegativeOptions, PieceEnd};
/// // t ≥ 0 and r ≥ 0 on [−1, 1]²: the quarter [0, 1]², bounded by two pieces that cross at
/// // the origin and end on the border.
/// let t = BSpline::bezier(1, vec![-1.0, 1.0]).unwrap().reparam(-1.0, 1.0).unwrap();
/// let one = BSpline::constant(&[1.0], 0, -1.0, 1.0).unwrap();
/// let ft = TensorBSpline::outer(&t, &one).unwrap();
/// let fr = TensorBSpline::outer(&one, &t).unwrap();
/// let s = nonnegative_set(&[ft, fr], &NonNegativeOptions::default(), &|_| false).unwrap();
/// assert!(s.complete);
/// assert_eq!(s.pieces.len(), 2);
/// for p in &s.pieces {
///     let ends = p.ends.unwrap();
///     assert!(ends.contains(&PieceEnd::Border));
///     assert!(ends.contains(&PieceEnd::Crossing(1 - p.function)));
/// }
/// ```
pub fn nonnegative_set(
    fs: &[TensorBSpline],
    opts: &NonNegativeOptions,
    excluded: &dyn Fn(Rect) -> bool,
) -> Result<NonNegativeSet> {
    nonnegative_set_mapped(fs, opts, excluded, &|t, r| Some([t, r]))
}

/// [`nonnegative_set`] with the chord tolerance kept where `map` sends the pairs `(t, r)`:
/// a caller that reports the boundary in other coordinates (a curve's own parameter, not
/// linear in its exact form's) gets polylines whose images stay within the tolerance of the
/// image of the boundary. The tolerance is relative to `opts.zero.settings.size` there (by
/// default the domain's diagonal, as measured in `(t, r)`); the vertices stay in `(t, r)`.
pub fn nonnegative_set_mapped(
    fs: &[TensorBSpline],
    opts: &NonNegativeOptions,
    excluded: &dyn Fn(Rect) -> bool,
    map: &dyn Fn(f64, f64) -> Option<[f64; 2]>,
) -> Result<NonNegativeSet> {
    let Some(first) = fs.first() else {
        return Ok(NonNegativeSet {
            complete: true,
            ..NonNegativeSet::default()
        });
    };
    let (dt, dr) = (first.domain_t(), first.domain_r());
    if let Some(f) = fs.iter().find(|f| (f.domain_t(), f.domain_r()) != (dt, dr)) {
        let (left, right) = if f.domain_t() != dt {
            (dt, f.domain_t())
        } else {
            (dr, f.domain_r())
        };
        return Err(Error::Spline(bspline::Error::DomainMismatch {
            left,
            right,
        }));
    }
    let dom = Rect::of(dt, dr);
    let diag = (dt.1 - dt.0).hypot(dr.1 - dr.0);
    let chord_abs =
        opts.zero.settings.chord_tol.get() * opts.zero.settings.size.map_or(diag, Size::get);
    // (Affine functions, as the cone conditions of two straight segments, in closed form.)
    if !opts.pairs {
        if let Some(set) = affine_set(fs, dom, &opts.meets, map, chord_abs) {
            return Ok(set);
        }
    }
    let (stores, values): (Vec<Cells>, Vec<Cells>) =
        fs.iter().map(|f| Cells::of(f, opts.pairs)).unzip();
    let stores = cut_corners(stores, dom, &opts.meets, opts.pairs);
    // A meeting point at a corner of the domain is blown up (its small cell is traced apart,
    // in the coordinates where the zero sets leaving it part); any other is split on.
    let corners: Vec<Corner> = opts
        .meets
        .iter()
        .filter_map(|&m| corner(&stores, dom, m, opts.pairs))
        .collect();
    let meets: Vec<[f64; 2]> = opts
        .meets
        .iter()
        .filter(|m| !corners.iter().any(|c| c.meet == **m))
        .copied()
        .collect();
    let skip: Vec<Rect> = corners.iter().map(|c| c.bx).collect();
    let mut out = trace_set(
        fs,
        &stores,
        &values,
        &Tracing {
            dom,
            zero: &opts.zero,
            pairs: opts.pairs,
            meets: &meets,
            skip: &skip,
            excluded,
            map,
            chord_abs,
        },
    );
    if corners.is_empty() {
        out.pieces = drop_retraced(out.pieces, chord_abs, map);
        return Ok(out);
    }
    let mut pieces = std::mem::take(&mut out.pieces);
    let unit = Rect::of((0.0, 1.0), (0.0, 1.0));
    for c in &corners {
        for (chart, hs) in &c.halves {
            let (sub_stores, sub_values): (Vec<Cells>, Vec<Cells>) =
                hs.iter().map(|h| Cells::of(h, false)).unzip();
            let sub = trace_set(
                hs,
                &sub_stores,
                &sub_values,
                &Tracing {
                    dom: unit,
                    zero: &opts.zero,
                    pairs: false,
                    meets: &[],
                    skip: &[],
                    excluded: &|bx| excluded(chart.image(bx)),
                    map: &|w, l| {
                        let [t, r] = chart.point([w, l]);
                        map(t, r)
                    },
                    chord_abs,
                },
            );
            out.complete &= sub.complete;
            out.patches += sub.patches;
            out.points
                .extend(sub.points.iter().map(|&p| chart.point(p)));
            out.unresolved
                .extend(sub.unresolved.iter().map(|&p| chart.point(p)));
            for mut p in sub.pieces {
                p.pts.iter_mut().for_each(|x| *x = chart.point(*x));
                if chart.reverses() {
                    p.pts.reverse();
                    if let Some(e) = p.ends.as_mut() {
                        e.swap(0, 1);
                    }
                }
                // An end on the half's border is on the domain's (the corner, the sides
                // through it) or inside it, where a piece of the other half or of the rest
                // of the domain goes on.
                let (first, last) = (p.pts[0], p.pts[p.pts.len() - 1]);
                if let Some(e) = p.ends.as_mut() {
                    for (end, at) in e.iter_mut().zip([first, last]) {
                        if *end == PieceEnd::Border {
                            *end = end_at(dom, at);
                        }
                    }
                }
                pieces.push(p);
            }
        }
    }
    let joined = join_loose(
        pieces,
        [MATCH_TOL * dom.t.width(), MATCH_TOL * dom.r.width()],
    );
    out.pieces = drop_retraced(joined, chord_abs, map);
    Ok(out)
}

/// What one tracing of a set looks at.
struct Tracing<'a> {
    dom: Rect,
    zero: &'a ZeroSetOptions,
    pairs: bool,
    /// Points where every function vanishes, split on until `excluded` passes over them.
    meets: &'a [[f64; 2]],
    /// Boxes traced apart (a whole cell of every function each).
    skip: &'a [Rect],
    excluded: &'a dyn Fn(Rect) -> bool,
    /// Where chords are measured.
    map: &'a dyn Fn(f64, f64) -> Option<[f64; 2]>,
    chord_abs: f64,
}

/// The boundary pieces of the set of `fs` (with their cells to trace `stores` and of values
/// `values`, [`Cells::of`]) on `how.dom`.
fn trace_set(
    fs: &[TensorBSpline],
    stores: &[Cells],
    values: &[Cells],
    how: &Tracing<'_>,
) -> NonNegativeSet {
    let dom = how.dom;
    let band: Vec<f64> = fs.iter().map(|f| ZERO_BAND * f.max_abs_coef()).collect();
    let mut out = NonNegativeSet {
        complete: true,
        ..NonNegativeSet::default()
    };
    let live: RefCell<HashMap<[u64; 4], bool>> = RefCell::new(HashMap::new());
    // Every function restricted to a patch's box, as far as asked: the keeping of the box and
    // the settling of each trace's arc there read the same patches.
    let restricted: RefCell<HashMap<[u64; 4], Vec<Option<Patch>>>> = RefCell::new(HashMap::new());
    let restrict_upto = |key: [u64; 4], bx: Rect, upto: usize| {
        let mut memo = restricted.borrow_mut();
        if memo.len() >= RESTRICTED_BOXES && !memo.contains_key(&key) {
            memo.clear();
        }
        let row = memo.entry(key).or_default();
        while row.len() < upto {
            row.push(stores[row.len()].restricted(bx));
        }
    };
    // Whether function `j` is proven negative on the box `key` (its part of the memo computed).
    let negative = |j: usize, key: [u64; 4], bx: Rect| {
        let memo = restricted.borrow();
        match memo.get(&key).and_then(|row| row.get(j)) {
            // (A box across cells is asked of every cell it meets.)
            Some(Some(q)) if q.rect() == bx => stores[j].negative_restricted(q),
            _ => stores[j].negative_on(bx),
        }
    };
    for (k, store) in stores.iter().enumerate() {
        // Whether the set may meet a patch is the same question for every function's trace
        // (a function negative there has no zero there either), and the traces split their
        // cells alike: each answer is kept for the traces after.
        let keep = |p: &Patch| {
            if how.pairs && p.t0 >= p.r1 {
                return false;
            }
            let key = box_key(p);
            if let Some(&known) = live.borrow().get(&key) {
                return known;
            }
            let bx = p.rect();
            let may = !how.skip.iter().any(|s| inside(bx, *s))
                && !(0..stores.len()).any(|j| {
                    restrict_upto(key, bx, j + 1);
                    negative(j, key, bx)
                })
                && !(how.excluded)(bx);
            live.borrow_mut().insert(key, may);
            may
        };
        // An arc stands where every other function keeps one sign on its patch, or meets
        // this one at most once there (a regular interval Jacobian), or vanishes along it
        // (coinciding zero sets): then the signs at the arc's vertices tell where it leaves
        // the set, and no excursion between two vertices goes unseen. The functions that
        // must vanish along it, by the first two tests failing:
        let undecided = |p: &Patch| -> Option<Vec<usize>> {
            // Where the contacts meet every function vanishes: an arc through such a point is
            // that point's, not a boundary's. Split on, until the caller's proof excludes it.
            let meets = (how.pairs && p.t1 >= p.r0)
                || how
                    .meets
                    .iter()
                    .any(|m| p.t0 <= m[0] && m[0] <= p.t1 && p.r0 <= m[1] && m[1] <= p.r1);
            if meets {
                return None;
            }
            let key = box_key(p);
            restrict_upto(key, p.rect(), stores.len());
            let memo = restricted.borrow();
            let row = memo.get(&key)?;
            Some(
                row.iter()
                    .enumerate()
                    .filter(|&(j, q)| {
                        j != k
                            && q.as_ref().is_some_and(|q| {
                                let err =
                                    16.0 * (q.pt + q.pr + 2) as f64 * UNIT_ROUNDOFF * q.max_abs();
                                common_sign(q.c.iter().copied(), err) == 0 && !unique(p, q)
                            })
                    })
                    .map(|(j, _)| j)
                    .collect(),
            )
        };
        let settle = |p: &Patch| match undecided(p) {
            None => Settle::Splits,
            Some(js) if js.is_empty() => Settle::Stands,
            Some(_) => Settle::ByVertices,
        };
        let settle_vertices = |p: &Patch, pts: &[[f64; 2]]| {
            undecided(p).is_some_and(|js| {
                js.iter()
                    .all(|&j| pts.iter().all(|&v| values[j].eval(v).abs() <= band[j]))
            })
        };
        let filters = Filters {
            keep: &keep,
            lax: &|_| false,
            settle: &settle,
            settle_vertices: &settle_vertices,
        };
        let pieces = run_cells(
            &store.cells,
            dom,
            how.zero,
            how.map,
            how.chord_abs,
            &filters,
        );
        let z = finish(&pieces, dom, &store.cells);
        out.complete &= z.complete;
        out.patches += z.patches;
        let cut = Cutter {
            fs: values,
            k,
            dom,
            band: &band,
            degenerate: std::cell::Cell::new(None),
        };
        for b in z.branches {
            cut.pieces(b.pts, b.closed, &mut out.pieces);
        }
        out.points
            .extend(z.isolated.into_iter().filter(|&p| cut.others_hold(p)));
        out.unresolved
            .extend(z.singular.into_iter().filter(|&p| cut.others_hold(p)));
        // (A set that is a curve there is not a region's boundary: said, not traced.)
        out.unresolved.extend(cut.degenerate.get());
    }
    out
}

/// A patch's box, as the key of what is kept per box.
fn box_key(p: &Patch) -> [u64; 4] {
    [p.t0, p.t1, p.r0, p.r1].map(f64::to_bits)
}

/// Whether the box `a` lies inside the box `b`.
fn inside(a: Rect, b: Rect) -> bool {
    b.t.lo <= a.t.lo && a.t.hi <= b.t.hi && b.r.lo <= a.r.lo && a.r.hi <= b.r.hi
}

/// The share of its cell's width (in `t`) that a box blown up at a corner of the domain takes:
/// small, so that little more than the zero sets leaving the corner runs through it.
const CORNER_SHARE: f64 = 0.125;

/// The ratio of the corner box's share in `r` to its share in `t`: not 1, so that the
/// diagonal dividing its two halves is not the line of mirror pairs `(u, −u)` of a symmetric
/// curve, where zero sets cross (a crossing on a half's border would not be joined).
const CORNER_ASPECT: f64 = 0.618_034;

/// The cells of every function with a small box cut out at each meeting point at a corner of
/// the domain (split off along a row and a column of cells, both ways on a domain of pairs so
/// its diagonal cells stay square).
fn cut_corners(mut stores: Vec<Cells>, dom: Rect, meets: &[[f64; 2]], pairs: bool) -> Vec<Cells> {
    for m in meets {
        let Some(first) = stores.first() else {
            break;
        };
        let Some(cell) = first.cells.iter().find(|c| at_corner_of(c, *m)) else {
            continue;
        };
        if !at_corner_of_rect(dom, *m) {
            continue;
        }
        let toward = |from: f64, lo: f64, hi: f64, share: f64| {
            if from == lo {
                lo + share * (hi - lo)
            } else {
                hi - share * (hi - lo)
            }
        };
        let at_t = toward(m[0], cell.t0, cell.t1, CORNER_SHARE);
        let at_r = toward(m[1], cell.r0, cell.r1, CORNER_SHARE * CORNER_ASPECT);
        stores = stores
            .into_iter()
            .map(|s| {
                if pairs {
                    s.split(&[(0, at_t), (1, at_r), (0, at_r), (1, at_t)])
                } else {
                    s.split(&[(0, at_t), (1, at_r)])
                }
            })
            .collect();
    }
    stores
}

/// Whether `m` is a corner of the patch `c`.
fn at_corner_of(c: &Patch, m: [f64; 2]) -> bool {
    (c.t0 == m[0] || c.t1 == m[0]) && (c.r0 == m[1] || c.r1 == m[1])
}

/// Whether `m` is a corner of the box `b`.
fn at_corner_of_rect(b: Rect, m: [f64; 2]) -> bool {
    (m[0] == b.t.lo || m[0] == b.t.hi) && (m[1] == b.r.lo || m[1] == b.r.hi)
}

/// The corner of the domain `meet` blown up, when every function's cell there is one box
/// (not a diagonal cell of a domain of pairs, whose factor `t − r` is divided out).
fn corner(stores: &[Cells], dom: Rect, meet: [f64; 2], pairs: bool) -> Option<Corner> {
    if !at_corner_of_rect(dom, meet) {
        return None;
    }
    let mut patches = Vec::with_capacity(stores.len());
    for s in stores {
        let at = s.cells.iter().position(|c| at_corner_of(c, meet))?;
        let c = &s.cells[at];
        let diagonal = pairs && c.t0 == c.r0 && c.t1 == c.r1;
        if s.sign[at] < 0.0 || diagonal {
            return None;
        }
        patches.push(c);
    }
    Corner::new(meet, &patches)
}

/// Cuts one function's zero set where another function changes sign.
struct Cutter<'a> {
    /// The functions, as their cells.
    fs: &'a [Cells],
    k: usize,
    dom: Rect,
    /// Per function, the values taken as zero ([`ZERO_BAND`]).
    band: &'a [f64],
    /// A point where another function vanishes along this zero set but is positive on its
    /// other side: the set there is that curve alone, with no inside to bound.
    degenerate: std::cell::Cell<Option<[f64; 2]>>,
}

impl Cutter<'_> {
    /// Whether every other function is non-negative at `p`.
    fn others_hold(&self, p: [f64; 2]) -> bool {
        self.first_negative(p).is_none()
    }

    /// The first other function negative at `p`.
    fn first_negative(&self, p: [f64; 2]) -> Option<usize> {
        (0..self.fs.len()).find(|&j| j != self.k && !self.holds(j, p))
    }

    /// Whether function `j` is non-negative at `p`; within its band of zero, only for a
    /// function after this one (a stretch on both zero sets belongs to the first), and only
    /// where it grows to the same side as this one (where it grows to the other, the set is
    /// the curve alone).
    fn holds(&self, j: usize, p: [f64; 2]) -> bool {
        let v = self.fs[j].eval(p);
        if v.abs() <= self.band[j] && j > self.k {
            // Entries: [F, F_t, F_r].
            let a = self.fs[self.k].eval_grad(p);
            let b = self.fs[j].eval_grad(p);
            let (dot, cross) = (a[1] * b[1] + a[2] * b[2], a[1] * b[2] - a[2] * b[1]);
            let norms = a[1].hypot(a[2]) * b[1].hypot(b[2]);
            // (Where they cross, or touch growing the same way, the band rule below holds.)
            if dot < 0.0 && cross.abs() <= ALONG * norms {
                self.degenerate.set(Some(p));
                return false;
            }
        }
        if j > self.k {
            v >= -self.band[j]
        } else {
            v > self.band[j]
        }
    }

    /// Which functions hold (are non-negative) at `p`; this one always.
    fn signs(&self, p: [f64; 2]) -> Vec<bool> {
        (0..self.fs.len())
            .map(|j| j == self.k || self.holds(j, p))
            .collect()
    }

    /// The kept pieces of one branch of the zero set of function `k`.
    ///
    /// Along a segment between two vertices each other function changes sign at most once
    /// (the tracer's `settle` split every patch until that holds), so a function whose signs
    /// at the two ends differ crosses exactly once between them, and one whose signs agree
    /// does not cross: the crossings, sorted along the segment, cut it into stretches inside
    /// and outside the set.
    fn pieces(&self, mut pts: Vec<[f64; 2]>, closed: bool, out: &mut Vec<BoundaryPiece>) {
        if pts.len() < 2 {
            return;
        }
        let mut signs: Vec<Vec<bool>> = pts.iter().map(|&p| self.signs(p)).collect();
        let all = |v: &[bool]| v.iter().all(|&x| x);
        if closed {
            // Start the walk at a vertex outside the set, so no piece wraps round the start
            // (a loop inside throughout, with no crossing, is one closed piece).
            pts.pop();
            signs.pop();
            match signs.iter().position(|v| !all(v)) {
                Some(at) => {
                    pts.rotate_left(at);
                    signs.rotate_left(at);
                }
                None if !self.any_crossing(&pts, &signs) => {
                    pts.push(pts[0]);
                    out.push(self.oriented(pts, None));
                    return;
                }
                None => {}
            }
            pts.push(pts[0]);
            signs.push(signs[0].clone());
        }
        let mut state = signs[0].clone();
        let mut run: Option<(Vec<[f64; 2]>, PieceEnd)> =
            all(&state).then(|| (vec![pts[0]], end_at(self.dom, pts[0])));
        for i in 0..pts.len() - 1 {
            let (a, b) = (pts[i], pts[i + 1]);
            let mut cuts: Vec<(f64, usize)> = (0..self.fs.len())
                .filter(|&j| signs[i][j] != signs[i + 1][j])
                .map(|j| (self.along(a, b, j), j))
                .collect();
            cuts.sort_by(|x, y| x.0.total_cmp(&y.0));
            for (l, j) in cuts {
                let was = all(&state);
                state[j] = !state[j];
                let now = all(&state);
                if was == now {
                    continue;
                }
                let x = self.crossing_at(a, b, l, j);
                if now {
                    run = Some((vec![x], PieceEnd::Crossing(j)));
                } else if let Some((mut v, start)) = run.take() {
                    v.push(x);
                    out.push(self.oriented(v, Some([start, PieceEnd::Crossing(j)])));
                }
            }
            // The vertex's own signs (the same as the flips, but for rounding).
            state.clone_from(&signs[i + 1]);
            match (run.as_mut(), all(&state)) {
                (Some((v, _)), true) => v.push(b),
                (None, true) => run = Some((vec![b], PieceEnd::Loose)),
                // The flips and the vertex's signs disagree (within rounding): the piece
                // ends here, unresolved.
                (Some(_), false) => {
                    if let Some((mut v, start)) = run.take() {
                        v.push(b);
                        out.push(self.oriented(v, Some([start, PieceEnd::Loose])));
                    }
                }
                (None, false) => {}
            }
        }
        if let Some((v, start)) = run {
            let end = end_at(self.dom, v[v.len() - 1]);
            if v.len() >= 2 {
                out.push(self.oriented(v, Some([start, end])));
            }
        }
    }

    /// Whether some function changes sign along a closed polyline inside the set at every
    /// vertex.
    fn any_crossing(&self, pts: &[[f64; 2]], signs: &[Vec<bool>]) -> bool {
        let n = pts.len();
        (0..n).any(|i| signs[i] != signs[(i + 1) % n])
    }

    /// Where along the chord from `a` to `b` function `j` changes sign (a share in `[0, 1]`),
    /// on the chord's points moved onto this zero set.
    fn along(&self, a: [f64; 2], b: [f64; 2], j: usize) -> f64 {
        let at = |l: f64| self.onto_zero_set([a[0] + l * (b[0] - a[0]), a[1] + l * (b[1] - a[1])]);
        // The value whose sign is `holds`: shifted by the band to the side the band counts.
        let shift = if j > self.k {
            self.band[j]
        } else {
            -self.band[j]
        };
        let value = |l: f64| {
            let p = at(l);
            self.fs[j].eval(p) + shift
        };
        let ends = (value(0.0), value(1.0));
        if ends.0 * ends.1 < 0.0 {
            return bracketed_free(value, (0.0, 1.0), ends, Accuracy::param(f64::EPSILON));
        }
        // (Where the signs come from more than the value, as beside coinciding zero sets:
        // bisection on them.)
        let start = self.holds(j, a);
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..CHORD_BISECTIONS {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if self.holds(j, at(mid)) == start {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// The crossing of this zero set with function `j`'s at the share `l` of the chord from
    /// `a` to `b` (found by bisection on the chord's points moved onto this zero set, so two
    /// crossings close together, as where two zero sets nearly touch, are told apart), polished
    /// onto both zero sets where Newton stays beside it.
    fn crossing_at(&self, a: [f64; 2], b: [f64; 2], l: f64, j: usize) -> [f64; 2] {
        let start = self.onto_zero_set([a[0] + l * (b[0] - a[0]), a[1] + l * (b[1] - a[1])]);
        let reach = POLISH_REACH * (b[0] - a[0]).hypot(b[1] - a[1]);
        self.polish(start, j, reach).unwrap_or(start)
    }

    /// `p` moved onto this function's zero set along its gradient (a few Newton steps; where
    /// the gradient vanishes, `p` as it is).
    fn onto_zero_set(&self, p: [f64; 2]) -> [f64; 2] {
        let f = &self.fs[self.k];
        let mut x = p;
        for _ in 0..PROJECTION_STEPS {
            // Entries: [F, F_t, F_r].
            let d = f.eval_grad(x);
            let g2 = d[1] * d[1] + d[2] * d[2];
            if g2.is_nan() || g2 <= 0.0 || d[0] == 0.0 {
                break;
            }
            let step = d[0] / g2;
            let next = [x[0] - step * d[1], x[1] - step * d[2]];
            let moved = (next[0] - x[0]).hypot(next[1] - x[1]);
            x = next;
            if moved <= f64::EPSILON * (x[0].abs() + x[1].abs() + 1.0) {
                break;
            }
        }
        x
    }

    /// Newton on `F_k = F_j = 0` from `start`, kept if it stays within `reach` of it.
    fn polish(&self, start: [f64; 2], j: usize, reach: f64) -> Option<[f64; 2]> {
        let (fk, fj) = (&self.fs[self.k], &self.fs[j]);
        let lin = |x: &Vector2<f64>| {
            // Entries: [F, F_t, F_r].
            let a = fk.eval_grad([x.x, x.y]);
            let b = fj.eval_grad([x.x, x.y]);
            let value = Vector2::new(a[0], b[0]);
            let jac = Matrix2::new(a[1], a[2], b[1], b[2]);
            let res = (a[0] / (a[1].hypot(a[2]) + f64::MIN_POSITIVE)).abs()
                + (b[0] / (b[1].hypot(b[2]) + f64::MIN_POSITIVE)).abs();
            (value, jac, res)
        };
        let x = polish(
            Vector2::new(start[0], start[1]),
            Newton2::steps(CROSSING_STEPS),
            lin,
            |x, d| x - d,
            |_| StepVerdict::Continue,
        )
        .best()?;
        let inside = self.dom.t.lo <= x.x
            && x.x <= self.dom.t.hi
            && self.dom.r.lo <= x.y
            && x.y <= self.dom.r.hi;
        ((x.x - start[0]).hypot(x.y - start[1]) <= reach && inside).then_some([x.x, x.y])
    }

    /// The piece turned so the set lies on its left (where `F_k` grows).
    fn oriented(&self, mut pts: Vec<[f64; 2]>, ends: Option<[PieceEnd; 2]>) -> BoundaryPiece {
        let m = (pts.len() - 1) / 2;
        let (a, b) = (pts[m], pts[m + 1]);
        let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        let g = self.fs[self.k].eval_grad(mid);
        let (gt, gr) = (g[1], g[2]);
        let v = [b[0] - a[0], b[1] - a[1]];
        let mut ends = ends;
        if v[0] * gr - v[1] * gt < 0.0 {
            pts.reverse();
            if let Some(e) = ends.as_mut() {
                e.swap(0, 1);
            }
        }
        BoundaryPiece {
            function: self.k,
            pts,
            ends,
        }
    }
}
