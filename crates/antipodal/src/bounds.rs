//! The curve's proof layer for arcs: the enclosures of its curvature numerator, tangent
//! numerator and weight ([`crate::enclosure`]), and per fine piece the curvature, greatest
//! speed and rate of the radius of curvature over its cells ([`crate::cells`]), built on first
//! use and combined in interval arithmetic ([`crate::interval`]). [`crate::arcs`] reads them
//! for an arc of a view.

use crate::cells::{
    cell_of, cell_span, Blocks, Cells, RunUnions, Union, COARSE_CELLS, FINE_CELLS, SPLIT,
};
use crate::enclosure::Enclosure;
use crate::taylor::Taylor;
use bspline::Piecewise;
use numeric::rounding::ulps;
use numeric::Interval;
use std::sync::OnceLock;

/// The curvature cells of a fine piece, and what they and the hulls prove over all of it.
#[derive(Debug, Clone)]
struct PieceKappa {
    cells: Blocks<KappaCell>,
    covered: KappaCell,
}

/// The enclosures behind [`crate::view::View::arc_bounds`]: the curvature numerator `K`, the tangent
/// numerator `D` and the weight `w`, built on first use.
#[derive(Debug, Clone)]
pub(crate) struct BoundForms {
    curvature: Enclosure,
    pub(crate) tangent: Enclosure,
    weight: Option<Enclosure>,
    /// The three enclosures share their fine pieces (always, for forms of one curve): the
    /// curvature is then bounded by Taylor models, piece by piece.
    aligned: bool,
    /// Per fine piece (when aligned), built on first use: the curvature and greatest speed
    /// over its cells (`None` where they do not prove `|D|` and `w` positive), which a
    /// stretch covering several cells of the piece in part reads instead of evaluating its
    /// own models; and those its hulls prove, narrowed to the union of its cells', for a
    /// stretch covering it whole.
    kappa: Vec<OnceLock<PieceKappa>>,
    /// Per fine piece, the rates of its radius of curvature (see `BoundForms::rho_rates`)
    /// over its cells, with κ clipped to negative and to positive values; built on first use.
    rates: Vec<OnceLock<Cells<[Option<Interval>; 2]>>>,
}

impl BoundForms {
    /// `None` when the forms are not those of a plane curve.
    pub(crate) fn new(hom: &Piecewise, tangent: &Piecewise, curvature: &Piecewise) -> Option<Self> {
        let w = hom.components(&[2]).ok()?;
        // (A polynomial curve's weight is exactly 1: see `bspline::symbolic::CurvePieces`.)
        let polynomial = (0..w.pieces()).all(|i| w.piece(i).iter().all(|&c| c == 1.0));
        let curvature = Enclosure::new(curvature)?;
        let tangent = Enclosure::new(tangent)?;
        let weight = match polynomial {
            true => None,
            false => Some(Enclosure::new(&w)?),
        };
        let aligned = curvature.breaks() == tangent.breaks()
            && weight
                .as_ref()
                .is_none_or(|e| e.breaks() == curvature.breaks());
        let pieces = curvature.hull.len();
        let n = if aligned { pieces } else { 0 };
        Some(Self {
            curvature,
            tangent,
            weight,
            aligned,
            kappa: (0..n).map(|_| OnceLock::new()).collect(),
            rates: (0..n).map(|_| OnceLock::new()).collect(),
        })
    }

    /// The curvature cells of fine piece `i` (built on first use).
    fn piece_kappa(&self, i: usize) -> &PieceKappa {
        self.kappa[i].get_or_init(|| {
            let cells =
                Blocks::new(&self.over_cells(i, COARSE_CELLS, |x0, x1| self.partial(i, x0, x1)));
            let covered = self.whole_piece(i, &cells);
            PieceKappa { cells, covered }
        })
    }

    /// The curvature and greatest speed over the fine cells of coarse cell `k` of fine piece
    /// `i`.
    fn fine_kappa(&self, i: usize, k: usize) -> [KappaCell; SPLIT] {
        let span = self.curvature.pw.piece_span(i);
        std::array::from_fn(|c| {
            let (x0, x1) = cell_span(span, FINE_CELLS, k * SPLIT + c);
            self.partial(i, x0, x1)
        })
    }

    /// The curvature and greatest speed over fine piece `i`: what its hulls prove and its
    /// coarse cells prove, in common.
    fn whole_piece(&self, i: usize, cells: &Blocks<KappaCell>) -> KappaCell {
        let weight = self
            .weight
            .as_ref()
            .map_or(Interval::new(1.0, 1.0), |e| e.hull[i]);
        let d = self.tangent.hull[i];
        let hulls = quotient(self.curvature.hull[i], d, weight)?;
        let speed = d.hi / (weight.lo * weight.lo);
        Some(match cells.whole() {
            Some((k, v)) => (
                Interval::new(hulls.lo.max(k.lo), hulls.hi.min(k.hi)),
                speed.min(v),
            ),
            None => (hulls, speed),
        })
    }

    /// The union of fine cells `c0 ..= c1` of fine piece `i` (`None` unless all prove `|D|`
    /// and `w` positive).
    fn cells_range(&self, i: usize, c0: usize, c1: usize) -> KappaCell {
        self.piece_kappa(i)
            .cells
            .union(c0, c1, |k| self.fine_kappa(i, k))
    }

    /// The curvature and greatest speed over `[x0, x1]` inside fine piece `i`: the common
    /// part of the Taylor model's range and of the quotient of the factors' ranges.
    fn partial(&self, i: usize, x0: f64, x1: f64) -> KappaCell {
        let delta = 0.5 * (x1 - x0);
        let clip = |(t, hull): (Taylor, Interval)| {
            let r = t.range(delta);
            (t, Interval::new(r.lo.max(hull.lo), r.hi.min(hull.hi)))
        };
        let (tk, k) = clip(self.curvature.taylor(i, x0, x1)?);
        let (td, d) = clip(self.tangent.taylor(i, x0, x1)?);
        let (tw, w) = match &self.weight {
            Some(e) => clip(e.taylor(i, x0, x1)?),
            None => (Taylor::constant(1.0), Interval::new(1.0, 1.0)),
        };
        let kappa = kappa_from([tk, td, tw], [k, d, w], delta)?;
        Some((kappa, d.hi / (w.lo * w.lo)))
    }

    /// The ranges of `dρ/dψ` over `[x0, x1]` inside fine piece `i`, with κ clipped to
    /// negative and to positive values (indexed by `convex`): the rate at which the radius of
    /// curvature `ρ = 1/κ` changes with the tangent angle ψ, `−κ′ / (κ³ |C′|)`, with
    /// `κ′ = w² (K′w + 3Kw′) / |D|³ − 3κ |D|′ / |D|` from the Taylor models of the factors and
    /// their derivatives. Where κ may reach zero on its side (an inflection ending a piece) the
    /// rate is unbounded on the side the signs of κ and κ′ give. `None` where nothing is
    /// proven (or κ has no values of that sign).
    fn rho_rates(&self, i: usize, x0: f64, x1: f64) -> [Option<Interval>; 2] {
        let none = [None, None];
        let delta = 0.5 * (x1 - x0);
        let value = |(t, hull, slope): (Taylor, Interval, Interval)| {
            let r = t.range(delta);
            (Interval::new(r.lo.max(hull.lo), r.hi.min(hull.hi)), slope)
        };
        let models = (
            self.curvature.taylor_slope(i, x0, x1),
            self.tangent.taylor_slope(i, x0, x1),
        );
        let (Some(km), Some(dm)) = models else {
            return none;
        };
        let ((k, k1), (d, d1)) = (value(km), value(dm));
        let (w, w1, tw) = match &self.weight {
            Some(e) => match e.taylor_slope(i, x0, x1) {
                Some(m) => {
                    let (w, w1) = value(m);
                    (w, w1, m.0)
                }
                None => return none,
            },
            None => (
                Interval::new(1.0, 1.0),
                Interval::new(0.0, 0.0),
                Taylor::constant(1.0),
            ),
        };
        // (From the same models as the rates; `None` unless |D| and w are proven positive.)
        let Some(kappa) = kappa_from([km.0, dm.0, tw], [k, d, w], delta) else {
            return none;
        };
        let Some(inv_d) = d.recip() else {
            return none;
        };
        let speed = Interval::new(d.lo / (w.hi * w.hi), d.hi / (w.lo * w.lo));
        let three = Interval::new(3.0, 3.0);
        let scaled = w.mul(w).mul(k1.mul(w).add(three.mul(k).mul(w1)));
        let cubed = inv_d.mul(inv_d).mul(inv_d);
        [false, true].map(|convex| {
            let kappa = match convex {
                true => Interval::new(kappa.lo.max(0.0), kappa.hi),
                false => Interval::new(kappa.lo, kappa.hi.min(0.0)),
            };
            // (Empty where κ has no values of that sign.)
            let some = kappa.lo <= kappa.hi;
            if !some {
                return None;
            }
            let rate = scaled
                .mul(cubed)
                .sub(three.mul(kappa).mul(d1).mul(inv_d))
                .widened(MARGIN);
            if kappa.excludes_zero() {
                let out = rate.mul(kappa.mul(kappa).mul(kappa).mul(speed).recip()?);
                return Some(Interval::new(-out.hi, -out.lo).widened(MARGIN));
            }
            // κ reaches zero on its side: |ρ′| ≥ |κ′|min / (|κ|max³ |C′|max), of the sign of
            // −κ′κ.
            if !rate.excludes_zero() || kappa.mag() == 0.0 {
                return None;
            }
            let least = rate.lo.abs().min(rate.hi.abs()) / (kappa.mag().powi(3) * speed.hi);
            let least = least * (1.0 - MARGIN);
            Some(match (rate.lo > 0.0) != convex {
                true => Interval::new(least, f64::INFINITY),
                false => Interval::new(f64::NEG_INFINITY, -least),
            })
        })
    }

    /// The rates of the radius of curvature over `n` equal cells of fine piece `i`.
    fn rate_cells(&self, i: usize, n: usize) -> RunUnions<[Option<Interval>; 2]> {
        RunUnions::new(&self.over_cells(i, n, |x0, x1| self.rho_rates(i, x0, x1)))
    }

    /// `cell(x0, x1)` over each of `n` equal cells `[x0, x1]` of fine piece `i`.
    fn over_cells<T>(&self, i: usize, n: usize, cell: impl Fn(f64, f64) -> T) -> Vec<T> {
        let span = self.curvature.pw.piece_span(i);
        (0..n)
            .map(|c| {
                let (x0, x1) = cell_span(span, n, c);
                cell(x0, x1)
            })
            .collect()
    }

    /// The range of `dρ/dψ` over fine piece `i`, or over its fine cells `c0 ..= c1` (κ of
    /// the sign `convex` gives), from the coarse cells holding them unless `fine`.
    fn cells_rho_rate(
        &self,
        i: usize,
        cells: Option<(usize, usize)>,
        convex: bool,
        fine: bool,
    ) -> Option<Interval> {
        let rates = self.rates.get(i)?;
        let rates = rates.get_or_init(|| Cells::new(self.rate_cells(i, COARSE_CELLS)));
        let r = match cells {
            None => rates.whole(),
            Some((c0, c1)) if fine => rates.fine(c0, c1, || self.rate_cells(i, FINE_CELLS)),
            Some((c0, c1)) => rates.coarse_over(c0, c1),
        };
        r[usize::from(convex)]
    }

    /// The range of `dρ/dψ` `acc` over an arc, with the break between fine pieces `j` and
    /// `i` (`i` after `j` along the arc) inside it: unchanged where the curvature is
    /// continuous there; where it jumps (a curve only C¹ there, as every quadratic spline at
    /// its knots), `ρ` jumps too and its rate holds a Dirac impulse, unbounded on the side of
    /// the jump's sign as ψ grows. `None` where that sign is not proven.
    fn with_rho_jump(&self, acc: Interval, j: usize, i: usize, convex: bool) -> Option<Interval> {
        let pw = &self.curvature.pw;
        let k = if i == 0 { 0 } else { i };
        if pw.continuity(k) >= 0 {
            return Some(acc);
        }
        // κ on either side, each from its own piece's polynomial (clipped to the arc's sign).
        let side = |piece: usize, at: f64| -> Option<Interval> {
            let (kappa, _) = self.partial(piece, at, at)?;
            match convex {
                true => Interval::new(kappa.lo.max(0.0), kappa.hi),
                false => Interval::new(kappa.lo, kappa.hi.min(0.0)),
            }
            .recip()
        };
        let (rho_before, rho_after) = (side(j, pw.piece_span(j).1)?, side(i, pw.piece_span(i).0)?);
        // As ψ grows: along the parameter on a convex arc, against it on a concave one.
        let jump = rho_after.sub(rho_before).widened(ulps(4.0));
        let jump = if convex {
            jump
        } else {
            Interval::new(-jump.hi, -jump.lo)
        };
        if jump.lo >= 0.0 {
            Some(Interval::new(acc.lo, f64::INFINITY))
        } else if jump.hi <= 0.0 {
            Some(Interval::new(f64::NEG_INFINITY, acc.hi))
        } else {
            None
        }
    }

    /// The breaks of the fine pieces where the curvature may jump, and whether it may jump
    /// across the seam (between the last piece and the first): where the curvature numerator
    /// is discontinuous by its structure (a curve only `C¹` there, as every quadratic spline
    /// at its knots) and its two sides' values are not proven equal to rounding (their
    /// ranges, each from its own piece's models, meet). A jump within that rounding is taken
    /// for none: it moves θ′ by no more, so a pair it could hide would be double to rounding.
    /// Every structural break counts when the enclosures do not share their pieces.
    pub(crate) fn curvature_jumps(&self) -> (Vec<f64>, bool) {
        let pw = &self.curvature.pw;
        let (breaks, n) = (pw.breaks(), pw.pieces());
        let may_jump = |k: usize| {
            if pw.continuity(k) >= 0 {
                return false;
            }
            if !self.aligned {
                return true;
            }
            let (before, after) = if k == 0 { (n - 1, 0) } else { (k - 1, k) };
            let side = |i: usize, at: f64| self.partial(i, at, at).map(|(kappa, _)| kappa);
            match (
                side(before, pw.piece_span(before).1),
                side(after, pw.piece_span(after).0),
            ) {
                (Some(a), Some(b)) => a.hi < b.lo || b.hi < a.lo,
                _ => true,
            }
        };
        let inner = (1..n).filter(|&k| may_jump(k)).map(|k| breaks[k]).collect();
        (inner, may_jump(0))
    }

    /// Joins the curvature over `[x0, x1]` (within the domain) into `acc`; returns the
    /// greatest speed there. `None` where nothing is proven.
    pub(crate) fn join_arc_kappa(&self, x0: f64, x1: f64, acc: &mut Interval) -> Option<f64> {
        if self.aligned {
            self.join_kappa(x0, x1, acc)
        } else {
            self.join_kappa_ranges(x0, x1, acc)
        }
    }

    /// Joins the rate of the radius of curvature over `[x0, x1]` (within the domain; κ of the
    /// sign `convex` gives) into `acc`, from the cells it touches, with the impulses at the
    /// breaks it crosses (`before`: the fine piece the arc was in last). `None` where nothing
    /// is proven.
    pub(crate) fn join_rho_rate(
        &self,
        x0: f64,
        x1: f64,
        before: &mut Option<usize>,
        mut acc: Interval,
        convex: bool,
        fine: bool,
    ) -> Option<Interval> {
        if !self.aligned {
            return None;
        }
        let pw = &self.curvature.pw;
        for (i, y0, y1) in pw.overlaps(x0, x1) {
            if y1 <= y0 {
                continue;
            }
            if let Some(j) = before.replace(i) {
                acc = self.with_rho_jump(acc, j, i, convex)?;
            }
            let span = pw.piece_span(i);
            let whole = y0 <= span.0 && y1 >= span.1;
            let cells = (!whole).then(|| (cell_of(y0, span), cell_of(y1, span)));
            acc = acc.hull(self.cells_rho_rate(i, cells, convex, fine)?);
        }
        Some(acc)
    }

    /// The curvature `κ = K w³ / |D|³` over `[lo, hi]` (inside the domain), joined into `acc`:
    /// per fine piece it covers, the piece's precomputed range; for a stretch within two cells
    /// of one piece, its own Taylor models ([`BoundForms::partial`]); per piece any other
    /// stretch overlaps in part, the union of the cells it touches. Returns the greatest speed
    /// `|C′| = |D| / w²` there; `None` where `|D|` or `w` is not proven positive.
    ///
    /// (Measured on the papers' shapes against models for every partly covered piece: with
    /// 16 cells per piece the limaçon and the lemniscate take a fifth fewer instructions per
    /// run, the others 2–4 % fewer; 8 and 32 cells do about as well, 4 and 64 worse.)
    fn join_kappa(&self, lo: f64, hi: f64, acc: &mut Interval) -> Option<f64> {
        let mut speed = 0.0f64;
        // A stretch within one fine piece may be short enough for its own models to matter;
        // one across several reads cells at its ends.
        let pw = &self.curvature.pw;
        // (A stretch ending on a break lies within the piece before it: the next one's
        // empty overlap is no part of it.)
        let overlaps = || {
            pw.overlaps(lo, hi)
                .filter(move |&(_, x0, x1)| x1 > x0 || lo == hi)
        };
        let within_one = overlaps().nth(1).is_none();
        for (i, x0, x1) in overlaps() {
            let (a, b) = pw.piece_span(i);
            let (kappa, v) = if x0 <= a && x1 >= b {
                self.piece_kappa(i).covered?
            } else {
                // The cells the overlap touches (one more at an end on a cell boundary).
                let (c0, c1) = (cell_of(x0, (a, b)), cell_of(x1, (a, b)));
                if c1 - c0 <= 1 && within_one {
                    // Within two cells: the stretch's own models are tighter.
                    self.partial(i, x0, x1)?
                } else {
                    // Where a cell proves nothing (the speed varying by orders of magnitude
                    // across it, as at a slender ellipse's vertex), the overlap's own models
                    // may.
                    match self.cells_range(i, c0, c1) {
                        Some(r) => r,
                        None => self.partial(i, x0, x1)?,
                    }
                }
            };
            speed = speed.max(v);
            *acc = acc.hull(kappa);
        }
        Some(speed)
    }

    /// [`BoundForms::join_kappa`] from the factors' ranges over the whole of `[lo, hi]`.
    fn join_kappa_ranges(&self, lo: f64, hi: f64, acc: &mut Interval) -> Option<f64> {
        let empty = Interval::new(f64::INFINITY, f64::NEG_INFINITY);
        let (mut k, mut d, mut w) = (empty, empty, Interval::new(1.0, 1.0));
        self.curvature.join_range(lo, hi, &mut k);
        self.tangent.join_range(lo, hi, &mut d);
        if let Some(e) = &self.weight {
            w = empty;
            e.join_range(lo, hi, &mut w);
        }
        let q = quotient(k, d, w)?;
        *acc = acc.hull(q);
        Some(d.hi / (w.lo * w.lo))
    }
}

/// What a stretch's Taylor models prove about the curvature: its range and the greatest
/// speed (`None` where they do not prove `|D|` and `w` positive).
pub(crate) type KappaCell = Option<(Interval, f64)>;

/// A cell's curvature and greatest speed (`None` where `|D|` or `w` is not proven positive).
impl Union for KappaCell {
    fn union(self, other: Self) -> Self {
        let ((ka, va), (kb, vb)) = (self?, other?);
        Some((ka.hull(kb), va.max(vb)))
    }
}

/// A cell's rates of the radius of curvature, with κ negative and positive.
impl Union for [Option<Interval>; 2] {
    fn union(self, other: Self) -> Self {
        [0, 1].map(|k| Some(self[k]?.hull(other[k]?)))
    }
}

/// Relative room for the rounding of the coefficients the ranges were read from and of the
/// operations that combine them.
pub(crate) const MARGIN: f64 = 1e-12;

/// The curvature `κ = K w³ / |D|³` over a stretch of half-width `delta`: the range of its
/// Taylor model, from the models `[K, |D|, w]`, within the quotient of the factors' ranges
/// `[k, d, w]`. `None` unless `|D|` and `w` are proven positive.
fn kappa_from([tk, td, tw]: [Taylor; 3], [k, d, w]: [Interval; 3], delta: f64) -> Option<Interval> {
    let ranges = quotient(k, d, w)?;
    let model = td
        .recip(delta)
        .map(|inv| tk.mul(tw.cube(delta), delta).mul(inv.cube(delta), delta));
    Some(match model {
        Some(t) => {
            let r = t.range(delta).widened(MARGIN);
            Interval::new(r.lo.max(ranges.lo), r.hi.min(ranges.hi))
        }
        None => ranges,
    })
}

/// `K w³ / |D|³` from the ranges of its factors; `None` unless `|D|` and `w` are positive.
fn quotient(k: Interval, d: Interval, w: Interval) -> Option<Interval> {
    if !(d.lo > 0.0 && w.lo > 0.0 && k.lo.is_finite() && k.hi.is_finite()) {
        return None;
    }
    let w3 = Interval::new(w.lo.powi(3), w.hi.powi(3));
    let d3 = Interval::new(d.lo.powi(3), d.hi.powi(3))
        .widened(MARGIN)
        .recip()?;
    Some(k.widened(MARGIN).mul(w3).mul(d3))
}
