//! An oriented, periodic view of a curve: the parametrisation the algorithms work in.
//!
//! Parameters are unwrapped reals: a closed curve is evaluated modulo its period, so segments may
//! run across the seam and no pair is ever split or found twice there. A clockwise curve is
//! viewed reversed (`u ↦ a + b − u`), so inside the algorithms every closed curve runs
//! counterclockwise and the left normal is the inward normal, as the papers assume.

use crate::forms::SymbolicForms;
use bspline::roots::{find_roots_in, Count, Root, RootOptions, SignCount};
use bspline::Piecewise;
use curve::circle::Angle;
use curve::{Jet, ParamCurve, StraightSpan, V2};
use numeric::certificate::{Certified, Doubt};
use numeric::rounding::ulps;
use numeric::tolerance::ParamTol;
use smallvec::SmallVec;
use std::cell::{Cell, RefCell};
use std::f64::consts::TAU;

/// Symbolic forms of a spline curve in the view's parametrisation.
pub(crate) struct Cert<'a> {
    pub(crate) forms: &'a SymbolicForms,
    pub(crate) opts: RootOptions,
}

impl std::ops::Deref for Cert<'_> {
    type Target = SymbolicForms;
    fn deref(&self) -> &SymbolicForms {
        self.forms
    }
}

/// How far (relative to the period) the ends of a stretch whose curvature vanishes within
/// rounding may lie from those of a proven straight stretch and still be that stretch: the
/// isolation of the curvature's roots brackets the ends to its tolerance, far below this.
const STRAIGHT_END: f64 = 1e-9;

/// The loosest tolerance (relative to the domain) points are solved to, whatever the
/// parameter tolerance asked for: the default one. Solved only to a loose tolerance, an
/// opposite point carries an error into θ far above θ itself where the curves are nearly arcs
/// of one circle (θ of 1e-9 along the lobes of a slender elliptic lemniscate, against 1e-6 of
/// noise at a tolerance of 1e-6), and the searches read its sign: hundreds of pairs were
/// found along such lobes. Newton's method converges quadratically: the extra precision costs
/// a step or two per solve.
pub(crate) const POINT_TOL: f64 = 1e-12;

/// What a view looks at: the curve evaluated in the parameter the algorithms run in, its
/// symbolic forms when decisions are certified, whether it is simple and regular by
/// construction (an analytic shape), and how its parameter maps to the one reported.
#[derive(Clone, Copy)]
pub(crate) struct Source<'a> {
    pub(crate) curve: &'a dyn ParamCurve,
    pub(crate) forms: Option<&'a SymbolicForms>,
    pub(crate) simple: bool,
    pub(crate) report: Option<Angle>,
    /// The least number of samples of a sampled track (Jia's sampling must resolve the
    /// curve's oscillations).
    pub(crate) samples: usize,
    /// The stretches proven exactly straight (in the curve's parameters).
    pub(crate) straight: &'a [StraightSpan],
    /// The curve is exactly a circle by its definition (its pairs are one family).
    pub(crate) exact_circle: bool,
}

pub(crate) struct View<'a> {
    curve: &'a dyn ParamCurve,
    /// Simple and regular by construction (the analytic shapes): the simplicity test is
    /// skipped.
    simple: bool,
    /// The least number of samples of a sampled track.
    pub(crate) samples: usize,
    /// The stretches proven exactly straight (in the curve's parameters).
    pub(crate) straight: &'a [StraightSpan],
    /// The curve is exactly a circle by its definition.
    pub(crate) exact_circle: bool,
    pub(crate) a: f64,
    pub(crate) b: f64,
    pub(crate) period: f64,
    pub(crate) closed: bool,
    pub(crate) rev: bool,
    pub(crate) cert: Option<Cert<'a>>,
    /// Size of the curve (bounding-box diagonal): the scale for geometric tolerances.
    pub(crate) scale: f64,
    /// Parameter tolerance: how closely the searches locate what they report.
    pub(crate) tol: f64,
    /// The tolerance points are solved to (an opposite point, a point with a given normal, a
    /// tangent's point): never looser than [`POINT_TOL`] of the domain, whatever the
    /// searches' tolerance, since the signs of θ and of the primitives that steer the searches
    /// are read at those points.
    pub(crate) point_tol: f64,
    /// Which book of a run's [`crate::ledger::Ledger`] keeps the doubts met on this view
    /// (0 unless the run searches several views).
    pub(crate) book: usize,
    /// Maps the evaluated curve's parameter to the reported one (the analytic `φ` of a shape
    /// run on its rational-circle form).
    report: Option<Angle>,
    /// The last few jets evaluated (see [`JetCache`]).
    cache: JetCache,
    /// Points of given tangent angle found on pieces, per piece (see
    /// [`View::piece_point_memo`]).
    piece_points: RefCell<Vec<SmallVec<[PiecePoint; 4]>>>,
}

/// A point of a piece whose tangent angle is `rel` beyond the piece's first one: its
/// parameter, or `None` where there is none.
#[derive(Clone, Copy)]
struct PiecePoint {
    rel: f64,
    u: Option<f64>,
}

/// Tangent angles closer than this on one piece are one: far below the snapping of
/// angles to a piece's ends (1e-10) and above the rounding of the angles of piece ends
/// that two neighbouring pieces share.
const SAME_ANGLE: f64 = 1e-13;

/// How close below a closed curve's end (relative to the period) a reported parameter is
/// the seam: a few units of rounding.
const SEAM_ROUNDING: f64 = ulps(8.0);

/// The least order a jet is evaluated to: the second derivative costs little beside the first
/// (analytic formulas; de Casteljau's levels for splines), and the many requests for a point's
/// first and then second derivatives (θ, then its noise; a Newton step's end, then the next
/// solve) then find it cached (splines: 4 % fewer instructions per run than with order 0).
const LEAST_ORDER: usize = 2;

/// Slots of [`JetCache`] (a power of two; 20 kB). Against eight entries searched in turn,
/// 64 slots take 3–11 % fewer instructions per run on the papers' shapes and random cubics,
/// 256 slots 7–17 % fewer; 512 gain little more.
const CACHED_JETS: usize = 256;

/// The jets evaluated so far, by parameter, in a direct-mapped table: each parameter has one
/// slot (by a hash of its bits), and a later jet whose parameter maps to the same slot
/// replaces it. The algorithms ask for the same points again and again — a march step's
/// ends, the segment ends of every primitive call, the pair a Newton solve has just reached,
/// the ends of a stretch whose bounds are taken — and a jet is most of the cost of a step.
/// (Eight entries searched in turn, replaced oldest first, kept 40–60 % of the requests but
/// lost the older points a proof or the final classification comes back to.)
struct JetCache {
    /// On the heap: the view holding it is moved a few times while it is set up.
    slots: Box<[Slot]>,
}

/// One parameter's jet, evaluated to `order`.
#[derive(Clone)]
struct Slot {
    u: Cell<f64>,
    order: Cell<usize>,
    jet: Cell<Jet>,
}

impl JetCache {
    fn new() -> Self {
        // No parameter compares equal to NaN: every slot starts empty.
        let empty = Slot {
            u: Cell::new(f64::NAN),
            order: Cell::new(0),
            jet: Cell::new(Jet::default()),
        };
        Self {
            slots: vec![empty; CACHED_JETS].into_boxed_slice(),
        }
    }

    /// The slot of parameter `u` (a multiplicative hash of its bits; always present).
    #[inline]
    fn slot(&self, u: f64) -> Option<&Slot> {
        let h = u.to_bits().wrapping_mul(0x9E37_79B9_7F4A_7C15);
        self.slots
            .get((h >> (64 - CACHED_JETS.trailing_zeros())) as usize)
    }

    #[inline]
    fn get(&self, u: f64, order: usize) -> Option<Jet> {
        let s = self.slot(u)?;
        (s.u.get() == u && s.order.get() >= order).then(|| s.jet.get())
    }

    fn put(&self, u: f64, order: usize, jet: Jet) {
        if let Some(s) = self.slot(u) {
            s.u.set(u);
            s.order.set(order);
            s.jet.set(jet);
        }
    }
}

impl<'a> View<'a> {
    /// The view of `src`, run backwards when `rev`, with the parameter tolerance `tol`
    /// (relative to the domain's length); doubted when it has no exact form to prove signs
    /// on.
    pub(crate) fn new(src: Source<'a>, rev: bool, tol: f64) -> Certified<Self> {
        let curve = src.curve;
        let (a, b) = curve.domain();
        let closed = curve.is_closed();
        // The forms oriented as the view; none: nothing is certified.
        let forms = match rev {
            false => src.forms,
            true => src.forms.and_then(SymbolicForms::reversed),
        };
        let cert = forms.map(|forms| Cert {
            forms,
            opts: RootOptions::default().tolerance(tol.max(ParamTol::FINEST)),
        });
        let mut v = Self {
            curve,
            simple: src.simple,
            samples: src.samples,
            straight: src.straight,
            exact_circle: src.exact_circle,
            a,
            b,
            period: b - a,
            closed,
            rev,
            cert,
            scale: 1.0,
            tol: tol * (b - a).max(1.0),
            point_tol: tol.min(POINT_TOL) * (b - a).max(1.0),
            book: 0,
            report: src.report,
            cache: JetCache::new(),
            piece_points: RefCell::new(Vec::new()),
        };
        let sampled = || {
            let samples = (0..64).map(|i| v.point(a + (b - a) * i as f64 / 63.0).arr());
            curve::points_scale(samples).max(f64::MIN_POSITIVE)
        };
        // The sample grid maps to itself reversed: the scale does not depend on the
        // orientation, and forms kept by the curve keep it too.
        let scale = match &v.cert {
            Some(c) => c.forms.size(sampled),
            None => sampled(),
        };
        v.scale = scale;
        match v.cert {
            Some(_) => Certified::proven(v),
            None => Certified::with(v, Doubt::NoExactForm),
        }
    }

    /// The parameter wrapped into `[a, b)` for closed curves (clamped for open ones).
    pub(crate) fn wrap(&self, u: f64) -> f64 {
        if u >= self.a && u < self.b {
            return u;
        }
        if self.closed {
            // Unwrapped parameters are mostly within a period of the domain (pieces across
            // the seam): a subtraction, not a floating-point remainder.
            let w = if u >= self.b && u < self.b + self.period {
                u - self.period
            } else if u < self.a && u >= self.a - self.period {
                u + self.period
            } else {
                self.a + (u - self.a).rem_euclid(self.period)
            };
            if w >= self.b {
                self.a
            } else {
                w
            }
        } else {
            u.clamp(self.a, self.b)
        }
    }

    /// The parameter reported to the caller. On a closed curve, a parameter within a few
    /// units of rounding below the domain's end is the seam itself, and reads as the start.
    pub(crate) fn to_curve(&self, u: f64) -> f64 {
        let x = self.eval_param(u);
        let (x, (a, b)) = match self.report {
            Some(angle) => (angle.phi(x), (0.0, TAU)),
            None => (x, (self.a, self.b)),
        };
        if self.closed && b - x <= SEAM_ROUNDING * (b - a) {
            a
        } else {
            x
        }
    }

    /// A bracket `[lo, hi]` of the view's parameters as one of the reported parameters: from
    /// the reported image of its (view-)first end, as long as the bracket is, so that one
    /// crossing the seam runs past the reported domain's end.
    pub(crate) fn bracket_to_curve(&self, lo: f64, hi: f64) -> [f64; 2] {
        let (a, b) = self.reported_domain();
        let (first, second) = if self.rev { (hi, lo) } else { (lo, hi) };
        let start = self.to_curve(first);
        if !self.closed {
            // (No seam to run past: a bracket over the whole domain is that.)
            return [start, self.to_curve(second)];
        }
        let span = (self.to_curve(second) - start).rem_euclid(b - a);
        [start, start + span]
    }

    /// The domain of the parameters reported ([`View::to_curve`]).
    pub(crate) fn reported_domain(&self) -> (f64, f64) {
        match self.report {
            Some(_) => (0.0, TAU),
            None => (self.a, self.b),
        }
    }

    /// The parameter of the evaluated curve.
    fn eval_param(&self, u: f64) -> f64 {
        let w = self.wrap(u);
        if self.rev {
            let r = self.a + self.b - w;
            if self.closed && r >= self.b {
                self.a
            } else {
                r
            }
        } else {
            w
        }
    }

    pub(crate) fn jet(&self, u: f64) -> Jet {
        self.jet_to(u, 3)
    }

    /// Point and derivatives up to `order` only (cheaper for splines).
    #[inline]
    pub(crate) fn jet_to(&self, u: f64, order: usize) -> Jet {
        match self.cache.get(u, order) {
            Some(j) => j,
            None => self.evaluate(u, order),
        }
    }

    /// A jet that is not cached: evaluated and kept (out of line, so that the lookup above
    /// inlines into its many callers).
    #[inline(never)]
    fn evaluate(&self, u: f64, order: usize) -> Jet {
        let order = order.max(LEAST_ORDER);
        let j = self.oriented_jet(u, order);
        self.cache.put(u, order, j);
        j
    }

    fn oriented_jet(&self, u: f64, order: usize) -> Jet {
        let j = self.curve.jet_to(self.eval_param(u), order);
        if self.rev {
            Jet {
                p: j.p,
                d1: -j.d1,
                d2: j.d2,
                d3: -j.d3,
            }
        } else {
            j
        }
    }

    /// The point of the piece numbered `piece` whose tangent angle lies `rel` beyond the
    /// piece's first one, from `solve` once and kept: the cone overlaps of §5.2 end at piece
    /// ends, and every piece end angle shared by two neighbouring pieces is solved for on
    /// each piece opposite them twice.
    pub(crate) fn piece_point_memo(
        &self,
        piece: usize,
        rel: f64,
        solve: impl FnOnce() -> Option<f64>,
    ) -> Option<f64> {
        let known = self.piece_points.borrow().get(piece).and_then(|points| {
            points
                .iter()
                .find(|e| (e.rel - rel).abs() <= SAME_ANGLE)
                .map(|e| e.u)
        });
        if let Some(u) = known {
            return u;
        }
        let u = solve();
        let mut all = self.piece_points.borrow_mut();
        if all.len() <= piece {
            all.resize(piece + 1, SmallVec::new());
        }
        if let Some(points) = all.get_mut(piece) {
            points.push(PiecePoint { rel, u });
        }
        u
    }

    #[inline]
    pub(crate) fn point(&self, u: f64) -> V2 {
        self.jet_to(u, 0).p
    }
    #[inline]
    pub(crate) fn normal(&self, u: f64) -> V2 {
        self.jet_to(u, 1).normal()
    }

    /// True when the curve is simple by construction.
    pub(crate) fn curve_known_simple(&self) -> bool {
        self.simple
    }

    /// The stretch proven exactly straight that the view's stretch `[lo, hi]` is (its ends
    /// within [`STRAIGHT_END`] of the period of a proven one's), if any.
    pub(crate) fn straight_span(&self, lo: f64, hi: f64) -> Option<StraightSpan> {
        match self.straight_chain(lo, hi)? {
            (first, 1) => Some(first),
            _ => None,
        }
    }

    /// The proven straight stretches, one after the other (on lines of their own: a polyline
    /// and its corners), that the view's stretch `[lo, hi]` is made of: the first and how many.
    pub(crate) fn straight_chain(&self, lo: f64, hi: f64) -> Option<(StraightSpan, usize)> {
        if self.straight.is_empty() {
            return None;
        }
        let [x, y] = self.bracket_to_curve(lo, hi);
        let (a, b) = self.reported_domain();
        let period = b - a;
        let near = |u: f64, v: f64| {
            let d = (u - v).rem_euclid(period);
            d.min(period - d) <= STRAIGHT_END * period
        };
        let starting = |at: f64| self.straight.iter().find(|s| near(s.lo, at)).copied();
        let first = starting(x)?;
        let (mut reached, mut count, mut last) = (x + (first.hi - first.lo), 1, first);
        // (Each stretch once at most: the walk ends.)
        while count <= self.straight.len() {
            if near(last.hi, y) && (reached - y).abs() <= 2.0 * STRAIGHT_END * period {
                return Some((first, count));
            }
            let next = starting(last.hi)?;
            reached += next.hi - next.lo;
            (last, count) = (next, count + 1);
        }
        None
    }

    /// The unwrapped interval `[lo, hi]` as pieces `(x0, x1, shift)` inside the domain (split
    /// at the seam): `x + shift` is the unwrapped parameter.
    pub(crate) fn domain_pieces(&self, lo: f64, hi: f64) -> SmallVec<[(f64, f64, f64); 2]> {
        let mut out = SmallVec::new();
        let mut push = |x0: f64, x1: f64, shift: f64| {
            let (x0, x1) = (x0.max(self.a), x1.min(self.b));
            if x1 > x0 {
                out.push((x0, x1, shift));
            }
        };
        if !self.closed {
            push(lo, hi, 0.0);
        } else {
            let k = ((lo - self.a) / self.period).floor();
            let shift = k * self.period;
            let (l, h) = (lo - shift, hi - shift);
            if h <= self.b {
                push(l, h, shift);
            } else {
                push(l, self.b, shift);
                push(self.a, h - self.period, shift + self.period);
            }
        }
        out
    }

    /// The unwrapped parameters strictly inside `(lo, hi)` where the curvature may jump, in
    /// increasing order ([`SymbolicForms::curvature_jumps`]: as at every knot of a quadratic).
    /// Jia's primitives assume the curvature continuous; across such a break θ has a kink,
    /// and may touch zero there without changing sign. None without forms (nothing is
    /// certified then) and on the analytic shapes, whose curvature is continuous whatever
    /// their rational-circle form's breaks.
    pub(crate) fn curvature_jumps(&self, lo: f64, hi: f64) -> SmallVec<[f64; 4]> {
        let mut out = SmallVec::new();
        let Some(cert) = self.cert.as_ref().filter(|_| !self.simple) else {
            return out;
        };
        let (inner, seam) = cert.curvature_jumps();
        for (x0, x1, shift) in self.domain_pieces(lo, hi) {
            // (The seam is a piece's end here: it is taken below, once per turn.)
            let from = inner.partition_point(|&x| x <= x0);
            let to = inner.partition_point(|&x| x < x1);
            out.extend(inner[from..to.max(from)].iter().map(|&x| x + shift));
        }
        if self.closed && *seam {
            let first = ((lo - self.a) / self.period).floor() as i64 + 1;
            for k in first.. {
                let at = self.a + k as f64 * self.period;
                if at >= hi {
                    break;
                }
                if at > lo {
                    out.push(at);
                }
            }
        }
        out.sort_by(f64::total_cmp);
        out
    }

    /// Certified roots of the scalar function `Σ weights[c] f_c` of a symbolic form (in the
    /// view's parameter) on the unwrapped interval `[lo, hi]`, split at the seam.
    pub(crate) fn cert_roots(
        &self,
        f: &Piecewise,
        weights: &[f64],
        lo: f64,
        hi: f64,
    ) -> Option<Vec<Root>> {
        let cert = self.cert.as_ref()?;
        let g = f.weighted(weights);
        let mut out = Vec::new();
        for (x0, x1, shift) in self.domain_pieces(lo, hi) {
            for mut r in find_roots_in(&g, x0, x1, &cert.opts).ok()? {
                r.u += shift;
                r.bracket = (r.bracket.0 + shift, r.bracket.1 + shift);
                out.push(r);
            }
        }
        Some(out)
    }

    /// What the control polygon of the scalar function `Σ weights[c] f_c` of a symbolic form
    /// proves about its roots on the unwrapped interval `[lo, hi]` (see
    /// [`bspline::roots::Count`]): the pieces across breaks and the seam read as one polygon,
    /// joined as the form continues there. `None` when it does not decide (then full root
    /// isolation does).
    ///
    /// A sliver of a piece at an end (the interval ends just past a break) holds nothing but
    /// the break's value again, and is left out.
    pub(crate) fn cert_count(
        &self,
        f: &Piecewise,
        weights: &[f64],
        lo: f64,
        hi: f64,
    ) -> Option<Count> {
        let mut count = SignCount::new(lo, hi);
        let mut first = true;
        for (x0, x1, shift) in self.domain_pieces(lo, hi) {
            let mut fed = true;
            f.for_each_restricted(weights, x0, x1, |i, a, b, c, err| {
                let (a, b) = (a + shift, b + shift);
                let sliver = b - a <= 4.0 * self.tol;
                let leading = first && b < hi - 4.0 * self.tol;
                let trailing = !first && b >= hi - 4.0 * self.tol;
                if sliver && (leading || trailing) {
                    return true;
                }
                // At a domain piece's start (the seam) the form continues as across its seam.
                let joint = if a - shift == f.domain().0 {
                    f.continuity(0)
                } else {
                    f.continuity(i)
                };
                first = false;
                fed = count.piece(a, b, c, err, joint);
                fed
            });
            if !fed {
                return None;
            }
        }
        match count.finish() {
            Count::Open => None,
            decided => Some(decided),
        }
    }
}

#[cfg(test)]
mod tests;
