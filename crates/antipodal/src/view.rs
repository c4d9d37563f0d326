//! An oriented, periodic view of a curve: the parametrisation the algorithms work in.
//!
//! Parameters are unwrapped reals: a closed curve is evaluated modulo its period, so segments may
//! run across the seam and no pair is ever split or found twice there. A clockwise curve is
//! viewed reversed (`u ↦ a + b − u`), so inside the algorithms every closed curve runs
//! counterclockwise and the left normal is the inward normal, as the papers assume.

use crate::circle::Angle;
use crate::curve::PlaneCurve;
use crate::fast::Pw;
use crate::forms::{Forms, SymbolicForms};
use crate::geom::{Jet, V2};
use bspline::roots::{find_roots, Root, RootOptions};
use bspline::{BSpline, Rational};
use smallvec::SmallVec;
use std::cell::{Cell, RefCell};
use std::f64::consts::TAU;

/// Outcome of [`View::cert_count`].
pub(crate) enum Count {
    /// No root (certified).
    Zero,
    /// Exactly one simple root in this bracket (certified).
    One(f64, f64),
    /// No root but, within rounding, the end `lo` or `hi` given (the function's value there is
    /// within its rounding bound of zero).
    AtEnd(f64),
}

/// Symbolic forms of a spline curve in the view's parametrisation.
pub(crate) struct Cert<'a> {
    pub(crate) forms: Forms<'a>,
    pub(crate) opts: RootOptions,
}

impl std::ops::Deref for Cert<'_> {
    type Target = SymbolicForms;
    fn deref(&self) -> &SymbolicForms {
        &self.forms
    }
}

pub(crate) struct View<'a> {
    curve: &'a dyn PlaneCurve,
    pub(crate) a: f64,
    pub(crate) b: f64,
    pub(crate) period: f64,
    pub(crate) closed: bool,
    pub(crate) rev: bool,
    pub(crate) cert: Option<Cert<'a>>,
    /// Size of the curve (bounding-box diagonal): the scale for geometric tolerances.
    pub(crate) scale: f64,
    /// Parameter tolerance.
    pub(crate) tol: f64,
    /// Cleared when some decision fell back on sampling.
    pub(crate) certified: Cell<bool>,
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
const SEAM_ROUNDING: f64 = 8.0 * f64::EPSILON;

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
    pub(crate) fn new(
        curve: &'a dyn PlaneCurve,
        rev: bool,
        certify: bool,
        tol: f64,
    ) -> crate::Result<Self> {
        let (a, b) = curve.domain();
        let closed = curve.is_closed();
        let cert = match (certify, curve.rational()) {
            (true, Some(r)) => {
                let kept = curve.symbolic_forms();
                let forms = match (rev, kept, kept.and_then(|f| f.reversed())) {
                    (false, Some(f), _) => Forms::Kept(f),
                    (true, _, Some(f)) => Forms::Kept(f),
                    _ => {
                        let c = if rev { reverse(r)? } else { r.clone() };
                        Forms::Built(Box::new(SymbolicForms::new(c)?))
                    }
                };
                Some(Cert {
                    forms,
                    opts: RootOptions::default().tolerance(tol.max(1e-15)),
                })
            }
            _ => None,
        };
        let mut v = Self {
            curve,
            a,
            b,
            period: b - a,
            closed,
            rev,
            cert,
            scale: 1.0,
            tol: tol * (b - a).max(1.0),
            certified: Cell::new(certify && curve.rational().is_some()),
            report: None,
            cache: JetCache::new(),
            piece_points: RefCell::new(Vec::new()),
        };
        let sampled = || {
            let (mut lo, mut hi) = (V2::new(f64::MAX, f64::MAX), V2::new(f64::MIN, f64::MIN));
            for i in 0..64 {
                let p = v.point(a + (b - a) * i as f64 / 63.0);
                lo = V2::new(lo.x.min(p.x), lo.y.min(p.y));
                hi = V2::new(hi.x.max(p.x), hi.y.max(p.y));
            }
            (hi - lo).norm().max(f64::MIN_POSITIVE)
        };
        // The sample grid maps to itself reversed: the size does not depend on the
        // orientation, and forms kept by the curve keep it too.
        let scale = match &v.cert {
            Some(c) => c.forms.size(sampled),
            None => sampled(),
        };
        v.scale = scale;
        Ok(v)
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

    /// Reports parameters as the shape's angle: the view runs on a circle form, whose jets
    /// come from the shape's formula.
    pub(crate) fn set_report(&mut self, angle: Angle) {
        self.report = Some(angle);
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
        self.curve.known_simple()
    }

    pub(crate) fn uncertify(&self) {
        self.certified.set(false);
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

    /// Certified roots of a scalar B-spline `f` (in the view's parameter) on the unwrapped
    /// interval `[lo, hi]`, split at the seam.
    pub(crate) fn cert_roots(&self, f: &BSpline, lo: f64, hi: f64) -> Option<Vec<Root>> {
        let cert = self.cert.as_ref()?;
        let mut out = Vec::new();
        for (x0, x1, shift) in self.domain_pieces(lo, hi) {
            for mut r in find_roots(f, x0, x1, &cert.opts).ok()? {
                r.u += shift;
                r.bracket = (r.bracket.0 + shift, r.bracket.1 + shift);
                out.push(r);
            }
        }
        Some(out)
    }

    /// The fast certified decision: the control polygon of `f` restricted to `[lo, hi]`, with
    /// every coefficient's sign trusted (beyond its rounding bound), has no sign change (no
    /// root) or exactly one (exactly one simple root, by variation diminishing). `None` when
    /// that does not settle it (then full root isolation decides).
    pub(crate) fn cert_count(&self, f: &BSpline, lo: f64, hi: f64) -> Option<Count> {
        let mut one = None;
        for (x0, x1, shift) in self.domain_pieces(lo, hi) {
            let g = f.restrict(x0, x1).ok()?;
            let c = g.coefs();
            let err = 4.0 * (g.degree() + 2) as f64 * f64::EPSILON * g.max_abs_coef();
            if c.iter().any(|x| x.abs() <= err) {
                return None;
            }
            let changes = c
                .windows(2)
                .filter(|w| (w[0] < 0.0) != (w[1] < 0.0))
                .count();
            match (changes, one) {
                (0, _) => {}
                (1, None) => one = Some((x0 + shift, x1 + shift)),
                _ => return None,
            }
        }
        Some(match one {
            None => Count::Zero,
            Some((a, b)) => Count::One(a, b),
        })
    }
}

impl View<'_> {
    /// [`View::cert_count`] on the Bézier pieces of the scalar function
    /// `Σ_c weights[c] · f_c`: no allocation, no knot insertion, and brackets as tight as the
    /// pieces around the sign change.
    ///
    /// The pieces' control polygons (across breaks and the seam) are read as one sequence, the
    /// control polygon of the function on `[lo, hi]` with every break of full multiplicity, so
    /// variation diminishing bounds its roots by the sign changes. A coefficient within its
    /// rounding bound of zero has no trusted sign; it cannot change the count when it lies
    /// between trusted coefficients of opposite signs (a root exactly at a break, at the seam or
    /// on an axis of symmetry), and leaves the decision open otherwise. So do untrusted ends and
    /// a jump at a joint (a curve only C⁰ at its seam).
    pub(crate) fn cert_count_pw(&self, f: &Pw, weights: &[f64], lo: f64, hi: f64) -> Option<Count> {
        struct State {
            /// Sign of the last trusted coefficient and the start of its piece.
            last: Option<(bool, f64)>,
            /// Untrusted coefficients since the last trusted one.
            pending: bool,
            /// Last coefficient of the previous piece and its bound (joints).
            prev_end: Option<(f64, f64)>,
            changes: usize,
            bracket: (f64, f64),
            open: bool,
            /// Untrusted coefficients before the first trusted one.
            lead: usize,
            /// Untrusted coefficients after the last trusted one.
            trail: usize,
        }
        let mut st = State {
            last: None,
            pending: false,
            prev_end: None,
            changes: 0,
            bracket: (lo, hi),
            open: false,
            lead: 0,
            trail: 0,
        };
        let eps = 4.0 * (f.degree() + 2) as f64 * f64::EPSILON;
        for (x0, x1, shift) in self.domain_pieces(lo, hi) {
            f.for_each_restricted(weights, x0, x1, |a, b, c, scale| {
                let err = eps * scale;
                let (a, b) = (a + shift, b + shift);
                // A sliver of a piece at an end (the interval ends just past a break) holds
                // nothing but the break's value again.
                let sliver = b - a <= 4.0 * self.tol;
                let leading = st.prev_end.is_none() && b < hi - 4.0 * self.tol;
                let trailing = st.prev_end.is_some() && b >= hi - 4.0 * self.tol;
                if sliver && (leading || trailing) {
                    return true;
                }
                let mut skip_first = false;
                if let Some((prev, perr)) = st.prev_end {
                    // A joint: the same value twice for a continuous function.
                    if (prev - c[0]).abs() > err + perr {
                        st.open = true;
                        return false;
                    }
                    skip_first = true;
                }
                for (i, &x) in c.iter().enumerate() {
                    if i == 0 && skip_first {
                        continue;
                    }
                    if x.abs() <= err {
                        if st.last.is_none() {
                            // Untrusted first coefficient: f(lo) ≈ 0.
                            st.lead += 1;
                        } else {
                            st.pending = true;
                            st.trail += 1;
                        }
                        continue;
                    }
                    st.trail = 0;
                    let sign = x < 0.0;
                    match st.last {
                        Some((s0, start)) if s0 != sign => {
                            st.changes += 1;
                            if st.changes > 1 {
                                st.open = true;
                                return false;
                            }
                            st.bracket = (start, b);
                        }
                        Some(_) if st.pending => {
                            // Untrusted between equal signs: 0 or 2 roots, undecided.
                            st.open = true;
                            return false;
                        }
                        _ => {}
                    }
                    st.pending = false;
                    st.last = Some((sign, a));
                }
                st.prev_end = Some((c[c.len() - 1], err));
                true
            });
            if st.open {
                return None;
            }
        }
        // An end value within rounding of zero (its neighbour trusted, no other sign change):
        // the one root there is the end itself, up to rounding.
        match (st.changes, st.lead, st.trail, st.last.is_some()) {
            (0, 0, 0, true) => Some(Count::Zero),
            (0, 1, 0, true) => Some(Count::AtEnd(lo)),
            (0, 0, 1, true) => Some(Count::AtEnd(hi)),
            (1, 0, 0, true) => Some(Count::One(st.bracket.0, st.bracket.1)),
            _ => None,
        }
    }
}

/// The same rational curve run backwards over the same domain.
pub(crate) fn reverse(r: &Rational) -> crate::Result<Rational> {
    let h = r.homogeneous();
    let (a, b) = h.domain();
    let knots: Vec<f64> = h.knots().iter().rev().map(|k| a + b - k).collect();
    let d = h.dim();
    let n = h.n_ctrl();
    let coefs: Vec<f64> = (0..n).rev().flat_map(|i| h.ctrl(i).to_vec()).collect();
    let _ = n;
    let rev = BSpline::new(h.degree(), knots, d, coefs)?;
    Ok(Rational::from_homogeneous(rev)?)
}

/// Newton's method safeguarded by a bracket `[lo, hi]` on which `f` changes sign: never fails.
///
/// `f` returns the value and derivative; `flo`, `fhi` are the values at `lo`, `hi`; `hint`
/// (NaN for none) is a starting point. A bisection step replaces Newton whenever Newton would
/// leave the bracket or is not at least halving the step (the classic `rtsafe` safeguard), so
/// the loop (≤ 200 steps) converges for any continuous `f`. Once a Newton step falls below
/// the tolerance, the point it starts from (evaluated already) is returned.
pub(crate) fn newton_bracketed(
    f: impl Fn(f64) -> (f64, f64),
    bracket: (f64, f64),
    ends: (f64, f64),
    tol: f64,
    hint: f64,
) -> f64 {
    safeguarded(
        |x| {
            let (v, d) = f(x);
            (v, d, f64::NAN)
        },
        bracket,
        ends,
        tol,
        hint,
    )
}

/// [`newton_bracketed`] with Halley's step: `f` also returns the second derivative, and the
/// convergence is cubic (fewer evaluations where a jet of one more order costs little).
pub(crate) fn halley_bracketed(
    f: impl Fn(f64) -> (f64, f64, f64),
    bracket: (f64, f64),
    ends: (f64, f64),
    tol: f64,
    hint: f64,
) -> f64 {
    safeguarded(f, bracket, ends, tol, hint)
}

/// The loop of [`newton_bracketed`] and [`halley_bracketed`] (`f″` NaN: Newton's step).
fn safeguarded(
    f: impl Fn(f64) -> (f64, f64, f64),
    (mut lo, mut hi): (f64, f64),
    (flo, fhi): (f64, f64),
    tol: f64,
    hint: f64,
) -> f64 {
    // Start from the hint when it is inside (a nearby previous solution converges in a few
    // steps), else where the chord of the end values crosses zero (from the middle, the
    // first Newton steps tend to overshoot and halve instead).
    let inside = |x: f64| x > lo.min(hi) && x < lo.max(hi);
    let secant = lo - flo * (hi - lo) / (fhi - flo);
    let mut x = if inside(hint) {
        hint
    } else if inside(secant) {
        secant
    } else {
        0.5 * (lo + hi)
    };
    // Orient so that f(lo) < 0.
    if flo > 0.0 {
        std::mem::swap(&mut lo, &mut hi);
    }
    let mut dx_old = (hi - lo).abs();
    let mut dx = dx_old;
    let (mut fx, mut dfx, mut ddfx) = f(x);
    for _ in 0..200 {
        let out = ((x - hi) * dfx - fx) * ((x - lo) * dfx - fx) > 0.0;
        if out || (2.0 * fx).abs() > (dx_old * dfx).abs() {
            dx_old = dx;
            dx = 0.5 * (hi - lo);
            x = lo + dx;
            if dx.abs() <= 0.5 * tol {
                return x;
            }
        } else {
            dx_old = dx;
            dx = fx / dfx;
            // Halley's correction of the Newton step (which stays inside the bracket), unless
            // it is large (far from the root, where the local quadratic model is no better
            // than the line) or leaves the bracket.
            let shrink = 1.0 - 0.5 * dx * ddfx / dfx;
            if (0.5..=2.0).contains(&shrink) {
                let to = x - dx / shrink;
                if to > lo.min(hi) && to < lo.max(hi) {
                    dx /= shrink;
                }
            }
            // A step below the tolerance: the point it starts from, already evaluated (its
            // error is about the step), is returned, and the caller finds its jet cached.
            // (Sparing that evaluation instead, by a model of the error the step leaves, was
            // tried: estimates from the steps or from difference quotients of derivatives
            // missed by 100× where f″ changes between the points.)
            if dx.abs() <= 0.5 * tol || fx == 0.0 {
                return x;
            }
            x -= dx;
        }
        (fx, dfx, ddfx) = f(x);
        if fx < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// `f(x) = Σ cₖ xᵏ` (degree 3) with its first two derivatives.
    fn cubic(c: [f64; 4]) -> impl Fn(f64) -> (f64, f64, f64) {
        move |x| {
            let f = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
            let d = (3.0 * c[3] * x + 2.0 * c[2]) * x + c[1];
            (f, d, 6.0 * c[3] * x + 2.0 * c[2])
        }
    }

    /// A piece point is solved once per piece and angle (angles within rounding are one), and
    /// a point on another piece or at another angle is solved anew.
    #[test]
    fn piece_points_are_solved_once_per_piece_and_angle() {
        let seed = [
            0.3, 0.9, 0.5, 0.7, 0.2, 0.8, 0.4, 0.6, 0.1, 0.95, 0.35, 0.75,
        ];
        let curve = crate::curve::tests::star_curve(3, &seed, None);
        let v = View::new(&curve, false, false, 1e-12).unwrap();
        let solves = Cell::new(0);
        let ask = |piece: usize, rel: f64, answer: Option<f64>| {
            v.piece_point_memo(piece, rel, || {
                solves.set(solves.get() + 1);
                answer
            })
        };
        assert_eq!(ask(2, 0.25, Some(0.7)), Some(0.7));
        assert_eq!(ask(2, 0.25 + 1e-15, Some(9.0)), Some(0.7));
        assert_eq!(ask(2, 0.3, None), None);
        assert_eq!(ask(2, 0.3, Some(9.0)), None);
        assert_eq!(ask(0, 0.25, Some(0.8)), Some(0.8));
        assert_eq!(ask(2, 0.25 + 1e-9, Some(0.71)), Some(0.71));
        assert_eq!(solves.get(), 4);
    }

    proptest! {
        /// Jets asked for through the view (a few parameters again and again, in any order
        /// and to any order of derivatives, with many sharing a slot) are the curve's own.
        #[test]
        fn cached_jets_are_the_curves(
            picks in proptest::collection::vec((0usize..600, 0usize..=3), 1..400),
        ) {
            // (A spline's jet holds the derivatives up to the order asked for only.)
            let seed = [0.3, 0.9, 0.5, 0.7, 0.2, 0.8, 0.4, 0.6, 0.1, 0.95, 0.35, 0.75];
            let curve = crate::curve::tests::star_curve(3, &seed, None);
            let v = View::new(&curve, false, false, 1e-12).unwrap();
            let (a, b) = curve.domain();
            for (k, order) in picks {
                let u = a + (b - a) * k as f64 / 600.0;
                let (got, want) = (v.jet_to(u, order), curve.jet_to(v.eval_param(u), order));
                prop_assert_eq!(got.p, want.p);
                if order >= 1 {
                    prop_assert_eq!(got.d1, want.d1);
                }
                if order >= 2 {
                    prop_assert_eq!(got.d2, want.d2);
                }
                if order >= 3 {
                    prop_assert_eq!(got.d3, want.d3);
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 50000, max_global_rejects: 100_000, ..ProptestConfig::default() })]

        /// On any bracket of a random cubic (one, two or three roots inside), both solvers
        /// return a point where the sign changes within the tolerance, inside the bracket,
        /// from any hint.
        #[test]
        fn safeguarded_solvers_land_on_a_sign_change(
            c in proptest::array::uniform3(-2.0f64..2.0),
            lo in -2.0f64..0.0,
            hi in 0.0f64..2.0,
            at in 0.0f64..1.0,
            hint in -3.0f64..3.0,
        ) {
            // A root at `x0` inside the bracket (the sign may still not change: two more).
            let x0 = lo + at * (hi - lo);
            let c = [-((c[2] * x0 + c[1]) * x0 + c[0]) * x0, c[0], c[1], c[2]];
            let f = cubic(c);
            let (flo, fhi) = (f(lo).0, f(hi).0);
            prop_assume!((flo < 0.0) != (fhi < 0.0) && flo != 0.0 && fhi != 0.0);
            let tol = 1e-12;
            let by_halley = halley_bracketed(&f, (lo, hi), (flo, fhi), tol, hint);
            let by_newton = newton_bracketed(|x| { let (v, d, _) = f(x); (v, d) },
                (lo, hi), (flo, fhi), tol, hint);
            for (k, x) in [by_halley, by_newton].into_iter().enumerate() {
                prop_assert!(x >= lo && x <= hi, "{x} outside [{lo}, {hi}]");
                let (a, b) = (f((x - tol).max(lo)).0, f((x + tol).min(hi)).0);
                let scale = c.iter().map(|v| v.abs()).sum::<f64>();
                prop_assert!((a < 0.0) != (b < 0.0) || f(x).0.abs() <= 1e-14 * scale,
                    "solver {k}: no sign change at {x}: {a} {b}");
            }
        }

        /// The same on an oscillating function, where the steps overshoot most: the
        /// solvers never leave the bracket, and end on one of its sign changes.
        #[test]
        fn safeguarded_solvers_stay_in_the_bracket(
            k in 1.0f64..30.0,
            phase in 0.0f64..6.3,
            c in -3.0f64..3.0,
            lo in -2.0f64..0.0,
            hi in 0.0f64..2.0,
            hint in -2.0f64..2.0,
        ) {
            // An oscillation on a tilted exponential (the steps overshoot on its flat side).
            let f = |x: f64| {
                let (s, co) = (k * x + phase).sin_cos();
                let e = (c * x).exp();
                (s + e - 1.0, k * co + c * e, -k * k * s + c * c * e)
            };
            let (flo, fhi) = (f(lo).0, f(hi).0);
            prop_assume!((flo < 0.0) != (fhi < 0.0) && flo != 0.0 && fhi != 0.0);
            let tol = 1e-12;
            let by_halley = halley_bracketed(f, (lo, hi), (flo, fhi), tol, hint);
            let by_newton = newton_bracketed(|x| { let (v, d, _) = f(x); (v, d) },
                (lo, hi), (flo, fhi), tol, hint);
            for (k, x) in [by_halley, by_newton].into_iter().enumerate() {
                prop_assert!(x >= lo && x <= hi, "solver {k}: {x} outside [{lo}, {hi}]");
                let (a, b) = (f((x - tol).max(lo)).0, f((x + tol).min(hi)).0);
                prop_assert!((a < 0.0) != (b < 0.0) || f(x).0.abs() <= 1e-14,
                    "solver {k}: no sign change at {x}: {a} {b}");
            }
        }

        /// From a start within a tenth of the bracket of a simple root, Halley's iteration
        /// reaches the tolerance in at most four evaluations (the last one confirms) and
        /// Newton's in at most six.
        #[test]
        fn halley_converges_cubically(
            root in -1.0f64..1.0,
            slope in 0.5f64..2.0,
            curve in proptest::array::uniform2(-0.5f64..0.5),
            off in -0.1f64..0.1,
        ) {
            // (x − root)(slope + curve₀ (x − root) + curve₁ (x − root)²): monotone on the
            // bracket [root − 0.5, root + 0.5].
            let g = move |x: f64| {
                let y = x - root;
                let f = y * (slope + y * (curve[0] + y * curve[1]));
                let d = slope + y * (2.0 * curve[0] + 3.0 * y * curve[1]);
                (f, d, 2.0 * curve[0] + 6.0 * y * curve[1])
            };
            let (lo, hi) = (root - 0.5, root + 0.5);
            let ends = (g(lo).0, g(hi).0);
            let count = std::cell::Cell::new(0);
            let counted = |x: f64| { count.set(count.get() + 1); g(x) };
            let x = halley_bracketed(counted, (lo, hi), ends, 1e-12, root + off);
            prop_assert!((x - root).abs() <= 1e-12);
            prop_assert!(count.get() <= 4, "{} evaluations", count.get());
            count.set(0);
            let x = newton_bracketed(|x| { count.set(count.get() + 1); let (v, d, _) = g(x); (v, d) },
                (lo, hi), ends, 1e-12, root + off);
            prop_assert!((x - root).abs() <= 1e-12);
            prop_assert!(count.get() <= 6, "{} evaluations", count.get());
        }
    }
}
