//! Segment pairs with opposite normals (Jia §5.2): intersecting normal cones.

use crate::dissect::Piece;
use crate::ledger::Ledger;
use crate::view::View;
use curve::V2;
use numeric::certificate::{Doubt, Doubts};
use numeric::newton2::{self, newton_step, Matrix2, Newton2, StepVerdict, Vector2};
use numeric::rounding::ulps;
use std::f64::consts::{PI, TAU};

/// Upper bound of the noise of |sin θ| (the antipodal angle of a found pair); the noise at a
/// given pair, from the parameter tolerance, is [`Pair::theta_noise`].
pub(crate) const THETA_NOISE: f64 = 1e-9;

/// Two monotone segments `S` over `(sa, sb)` (`sa < sb`) and `T` over `(ta, tb)` (either order)
/// with `N(sa) = −N(ta)`, `N(sb) = −N(tb)`: conditions (i)–(iii).
#[derive(Clone, Copy)]
pub(crate) struct Pair<'a> {
    pub(crate) vs: &'a View<'a>,
    pub(crate) vt: &'a View<'a>,
    pub(crate) sa: f64,
    pub(crate) sb: f64,
    pub(crate) ta: f64,
    pub(crate) tb: f64,
    pub(crate) s_convex: bool,
    pub(crate) t_convex: bool,
}

impl<'a> Pair<'a> {
    pub(crate) fn t_range(&self) -> (f64, f64) {
        (self.ta.min(self.tb), self.ta.max(self.tb))
    }

    /// The same pair with the roles of `S` and `T` exchanged.
    pub(crate) fn swapped(&self) -> Pair<'a> {
        let (sa, sb, ta, tb) = if self.ta <= self.tb {
            (self.ta, self.tb, self.sa, self.sb)
        } else {
            (self.tb, self.ta, self.sb, self.sa)
        };
        Pair {
            vs: self.vt,
            vt: self.vs,
            sa,
            sb,
            ta,
            tb,
            s_convex: self.t_convex,
            t_convex: self.s_convex,
        }
    }

    /// `(sa, ta)` where it is antipodal to rounding (`sin θ` within its noise): the test of
    /// a pair of no width ([`touching_ends`]).
    pub(crate) fn antipodal_start(&self) -> Option<(f64, f64)> {
        let (s, t) = (self.sa, self.ta);
        self.is_noise(s, t, self.sin_theta(s, t)).then_some((s, t))
    }

    /// The sub-pair over `(s0, s1)` whose opposite points are `t0`, `t1`.
    pub(crate) fn sub(&self, s0: f64, t0: f64, s1: f64, t1: f64) -> Pair<'a> {
        Pair {
            sa: s0,
            ta: t0,
            sb: s1,
            tb: t1,
            ..*self
        }
    }

    // The opposite points are solved on `T`: the doubts they meet are `T`'s view's, and each
    // takes that view's book (`doubts`).

    /// The opposite point of `s` on `T` (point-with-normal with `−N(s)`).
    pub(crate) fn opposite(&self, s: f64, doubts: &mut Doubts) -> Option<f64> {
        let (lo, hi) = self.t_range();
        self.vt
            .point_with_normal(lo, hi, -self.vs.normal(s), doubts)
    }

    /// The opposite point of `s`, searched between two known opposite points.
    pub(crate) fn opposite_within(&self, s: f64, t0: f64, t1: f64, doubts: &mut Doubts) -> f64 {
        self.opposite_near(s, t0, t1, t0, doubts)
    }

    /// The opposite point of `s`, which lies between the known opposite pairs `a` and `b`:
    /// Newton starts where `t` would be if it followed `s` linearly.
    pub(crate) fn opposite_between(
        &self,
        s: f64,
        a: (f64, f64),
        b: (f64, f64),
        doubts: &mut Doubts,
    ) -> f64 {
        let f = if b.0 != a.0 {
            (s - a.0) / (b.0 - a.0)
        } else {
            0.5
        };
        self.opposite_near(s, a.1, b.1, a.1 + f * (b.1 - a.1), doubts)
    }

    /// The opposite point of `s`, between those of `a` and `b`, with Newton started on the
    /// tangent of `t(s)` at `a` (`dt/ds = κ(s)|C′(s)| / (κ(t)|C′(t)|)`, the normals turning
    /// alike): closer than the chord where `s` is much nearer `a` than `b`, as beside a found
    /// pair.
    pub(crate) fn opposite_following(
        &self,
        s: f64,
        a: (f64, f64),
        b: (f64, f64),
        doubts: &mut Doubts,
    ) -> f64 {
        let (ja, jt) = (self.vs.jet_to(a.0, 2), self.vt.jet_to(a.1, 2));
        let slope = ja.curvature() * ja.d1.norm() / (jt.curvature() * jt.d1.norm());
        let h = a.1 + slope * (s - a.0);
        let hint = if h > a.1.min(b.1) && h < a.1.max(b.1) {
            h
        } else {
            f64::NAN
        };
        self.opposite_near(s, a.1, b.1, hint, doubts)
    }

    /// [`Pair::opposite_within`] with Newton started at `hint`.
    pub(crate) fn opposite_near(
        &self,
        s: f64,
        t0: f64,
        t1: f64,
        hint: f64,
        doubts: &mut Doubts,
    ) -> f64 {
        let d1 = self.vt.jet_to(t1, 1).d1;
        self.opposite_near_from(s, t0, (t1, d1), hint, doubts)
    }

    /// [`Pair::opposite_near`] with `T`'s tangent at `t1` given (a march's far end).
    pub(crate) fn opposite_near_from(
        &self,
        s: f64,
        t0: f64,
        t1: (f64, V2),
        hint: f64,
        doubts: &mut Doubts,
    ) -> f64 {
        let n = -self.vs.normal(s);
        let d0 = self.vt.jet_to(t0, 1).d1;
        match self
            .vt
            .point_with_normal_from((t0, d0), t1, n, hint, doubts)
        {
            Some(t) => t,
            None => self.opposite(s, doubts).unwrap_or(0.5 * (t0 + t1.0)),
        }
    }

    /// `r(s) = α(t) − α(s)`.
    pub(crate) fn r(&self, s: f64, t: f64) -> V2 {
        self.vt.point(t) - self.vs.point(s)
    }

    /// `sin θ = N(s) × r / |r|`: the sign of the antipodal angle (footnote 15).
    pub(crate) fn sin_theta(&self, s: f64, t: f64) -> f64 {
        let js = self.vs.jet_to(s, 1);
        let r = self.vt.point(t) - js.p;
        // N × r / |r| with N = C′⊥/|C′| is −C′ · r / (|C′| |r|): one root, of the product of
        // the squares (each length apart where that product would overflow or underflow).
        let sq = js.d1.dot(js.d1) * r.dot(r);
        let den = if sq.is_finite() && sq >= f64::MIN_POSITIVE {
            sq.sqrt()
        } else {
            js.d1.norm() * r.norm()
        };
        -js.d1.dot(r) / den.max(f64::MIN_POSITIVE)
    }

    /// Below this `|sin θ|` at `(s, t)` is numerically zero: what moving `s` and `t` by the
    /// parameter tolerance (to which opposite points are solved) changes it by — the points
    /// slide along the curve and the normal at `s` turns — or rounding, and never more than
    /// [`THETA_NOISE`]. (An absolute 1e-9 alone took the nearly circular lobes of a slender
    /// elliptic lemniscate, where θ stays of order 1e-10 but is resolved, for a family.)
    pub(crate) fn theta_noise(&self, s: f64, t: f64) -> f64 {
        let (js, jt) = (self.vs.jet_to(s, 2), self.vt.jet_to(t, 1));
        let r = (jt.p - js.p).norm().max(f64::MIN_POSITIVE);
        let (vs, vt) = (js.d1.norm(), jt.d1.norm());
        let slide = self.vs.tol * vs * (1.0 / r + js.curvature().abs()) + self.vt.tol * vt / r;
        (slide + ulps(64.0)).min(THETA_NOISE)
    }

    /// `sin θ = sin_theta` at `(s, t)` is within its noise there ([`Pair::theta_noise`], never
    /// more than [`THETA_NOISE`]: beyond that, no jets of second order are needed to tell).
    pub(crate) fn is_noise(&self, s: f64, t: f64, sin_theta: f64) -> bool {
        sin_theta.abs() <= THETA_NOISE && sin_theta.abs() <= self.theta_noise(s, t)
    }

    /// `sin θ = sin_theta` at `(s, t)` is beyond its noise there (false for NaN).
    pub(crate) fn is_clear(&self, s: f64, t: f64, sin_theta: f64) -> bool {
        sin_theta.abs() > THETA_NOISE || sin_theta.abs() > self.theta_noise(s, t)
    }

    /// `(s, t)` is a pair to the parameter tolerance (see [`is_resolved`]).
    pub(crate) fn is_resolved(&self, s: f64, t: f64) -> bool {
        is_resolved(
            self.vs,
            self.vt,
            s,
            t,
            RESOLVED_STEPS * self.vs.tol.max(self.vt.tol),
        )
    }

    /// `d(s) = N(s) · r(s)`: signed distance between the parallel tangent lines (§2.2).
    pub(crate) fn d(&self, s: f64, t: f64) -> f64 {
        let js = self.vs.jet_to(s, 1);
        js.normal().dot(self.vt.point(t) - js.p)
    }
}

/// A stretch `[s0, s1]` of a monotone segment holds nothing to search: it is empty, or both
/// narrower than the parameter tolerance and turning the normal by no more than the noise of
/// the antipodal angle. Narrowness alone does not do: where the parametrisation is very
/// uneven (a slender ellipse on its rational-circle form) the normal turns by a finite angle
/// within the parameter tolerance.
pub(crate) fn negligible(v: &View, s0: f64, s1: f64) -> bool {
    if s1 <= s0 {
        return true;
    }
    if s1 - s0 > v.tol {
        return false;
    }
    let (n0, n1) = (v.normal(s0), v.normal(s1));
    n0.cross(n1).atan2(n0.dot(n1)).abs() <= THETA_NOISE
}

/// The ranges of tangent angle `[lo, hi]` where `p`'s normals are opposite to `q`'s, with the
/// whole turns `shift` added to `q`'s angles: empty where `hi < lo`. (Normals are opposite
/// exactly when tangent angles differ by π; unwrapped angles of different pieces may be many
/// turns apart, so the turns tried are centred on them.)
fn overlaps(p: &Piece, q: &Piece) -> [(f64, f64, f64); 3] {
    let (p0, p1) = ordered(p.psi_lo, p.psi_lo + p.rot);
    let (q0, q1) = ordered(q.psi_lo + PI, q.psi_lo + PI + q.rot);
    let k0 = ((0.5 * (p0 + p1) - 0.5 * (q0 + q1)) / TAU).round();
    [-1.0, 0.0, 1.0].map(|k| {
        let shift = TAU * (k0 + k);
        (p0.max(q0 + shift), p1.min(q1 + shift), shift)
    })
}

/// The pair of no width at the ends of `p` (on `vs`) and `q` (on `vt`) whose normals are
/// opposite where the pieces' ranges of opposite normal angles only touch (within
/// [`ANGLE_OVERLAP`], where [`opposite_pair`] finds no section): there those ends are the only
/// points with opposite normals, as where both pieces end at inflections, or at knots where
/// the curvature jumps. What a section would hold is then a point test: an antipodal pair
/// ([`Pair::antipodal_start`]), a common tangent ([`crate::tangent::tangent_start`]). `None`
/// when the ranges do not touch at a pair of ends.
pub(crate) fn touching_ends<'a>(
    vs: &'a View<'a>,
    p: &Piece,
    vt: &'a View<'a>,
    q: &Piece,
) -> Option<Pair<'a>> {
    // The end of a piece (from `lo` at angle `start` to `hi`, turning by `rot`) at the angle.
    let end_at = |start: f64, rot: f64, lo: f64, hi: f64, angle: f64| {
        if (start - angle).abs() <= ANGLE_OVERLAP {
            Some(lo)
        } else if (start + rot - angle).abs() <= ANGLE_OVERLAP {
            Some(hi)
        } else {
            None
        }
    };
    overlaps(p, q).into_iter().find_map(|(lo, hi, shift)| {
        if (hi - lo).abs() > ANGLE_OVERLAP {
            return None;
        }
        let angle = 0.5 * (lo + hi);
        let s = end_at(p.psi_lo, p.rot, p.lo, p.hi, angle)?;
        let t = end_at(q.psi_lo + PI + shift, q.rot, q.lo, q.hi, angle)?;
        Some(Pair {
            vs,
            vt,
            sa: s,
            sb: s,
            ta: t,
            tb: t,
            s_convex: p.convex,
            t_convex: q.convex,
        })
    })
}

/// Intersects the normal cone of `p` with the outward-normal cone of `q` and returns the pair of
/// sub-segments with opposite normals, if the cones overlap.
pub(crate) fn opposite_pair<'a>(
    vs: &'a View<'a>,
    p: &Piece,
    vt: &'a View<'a>,
    q: &Piece,
    ledger: &mut Ledger,
) -> Option<Pair<'a>> {
    let mut best: Option<(f64, f64, f64)> = None;
    for (lo, hi, shift) in overlaps(p, q) {
        if hi > lo && best.is_none_or(|b| hi - lo > b.1 - b.0) {
            best = Some((lo, hi, shift));
        }
    }
    let (lo, hi, shift) = best?;
    if hi - lo <= ANGLE_OVERLAP {
        return None;
    }
    // Angles within rounding of a piece end snap to that end (its own normal there).
    const SNAP: f64 = 1e-10;
    // Newton starts where the piece's interpolant of u(ψ) puts the angle. On a certified
    // curve the angle lies inside the piece's range by more than the snapping, so the signs
    // of C′ · n at the piece's ends are those of sin(ψ − angle) there (no jets needed).
    let solve_on = |v: &View, piece: &Piece, ang: f64, doubts: &mut Doubts| {
        let n = V2::polar(ang).perp();
        let guess = piece.param_guess(ang);
        if v.cert.is_some() {
            let ends = (
                (piece.psi_lo - ang).sin(),
                (piece.psi_lo + piece.rot - ang).sin(),
            );
            if (ends.0 < 0.0) != (ends.1 < 0.0) {
                return v.point_with_normal_between(piece.lo, piece.hi, n, ends, guess);
            }
        }
        v.point_with_normal_near(piece.lo, piece.hi, n, guess, doubts)
    };
    // (A point kept by the memo met its doubts when it was solved.)
    let solve = |v: &View, piece: &Piece, ang: f64, ledger: &mut Ledger| {
        v.piece_point_memo(piece.id, ang - piece.psi_lo, || {
            solve_on(v, piece, ang, ledger.of(v))
        })
    };
    let s_at = |ang: f64, ledger: &mut Ledger| -> Option<f64> {
        if (ang - p.psi_lo).abs() <= SNAP {
            Some(p.lo)
        } else if (ang - (p.psi_lo + p.rot)).abs() <= SNAP {
            Some(p.hi)
        } else {
            solve(vs, p, ang, ledger)
        }
    };
    let t_at = |ang: f64, ledger: &mut Ledger| -> Option<f64> {
        let a = ang - shift - PI;
        if (ang - shift - (q.psi_lo + PI)).abs() <= SNAP {
            Some(q.lo)
        } else if (ang - shift - (q.psi_lo + PI + q.rot)).abs() <= SNAP {
            Some(q.hi)
        } else {
            solve(vt, q, a, ledger)
        }
    };
    let (s0, s1) = (s_at(lo, ledger)?, s_at(hi, ledger)?);
    let (t0, t1) = (t_at(lo, ledger)?, t_at(hi, ledger)?);
    let (sa, ta, sb, tb) = if s0 <= s1 {
        (s0, t0, s1, t1)
    } else {
        (s1, t1, s0, t0)
    };
    // The cones overlap by more than rounding (above), so the pair is dropped only when the
    // normals do not turn across it either: a stretch narrower than the parameter tolerance
    // may still turn the normal by a finite angle (an ellipse of aspect 1e12 turns it by π
    // within 1e-12 of its rational parameter) and hold a pair.
    if negligible(vs, sa, sb) {
        if sb <= sa && hi - lo > 2.0 * SNAP {
            // Cones overlapping by more than the snapping to one end, on a stretch rounding
            // collapsed to a point: the normal jumps within one unit of the parameter, beyond
            // what double precision resolves.
            ledger.of(vs).add(Doubt::NormalJump);
        }
        return None;
    }
    Some(Pair {
        vs,
        vt,
        sa,
        sb,
        ta,
        tb,
        s_convex: p.convex,
        t_convex: q.convex,
    })
}

fn ordered(a: f64, b: f64) -> (f64, f64) {
    if a <= b {
        (a, b)
    } else {
        (b, a)
    }
}

/// The residual of the antipodal system (sines of the angles between the tangents and between
/// `r` and the tangent at `s`, summed) below which a pair is at full precision: a few units of
/// rounding of the jets.
const RESIDUAL_FLOOR: f64 = 2e-15;

/// Newton's method on the antipodal system `α′(s) × α′(t) = 0`, `(α(t) − α(s)) · α′(s) = 0`
/// from a nearby pair: a few steps to full precision. `None` when it moves farther than
/// `max_move` or does not reduce the residual.
pub(crate) fn polish(vs: &View, vt: &View, s: f64, t: f64, max_move: f64) -> Option<(f64, f64)> {
    let area = ((s - max_move, s + max_move), (t - max_move, t + max_move));
    polish_within(vs, vt, s, t, area)
}

/// Linearisations of the antipodal system a polish makes, at most: from a nearby pair,
/// quadratic convergence reaches the rounding floor in four or five.
const PAIR_POLISH_STEPS: usize = 9;

/// [`polish`] inside the box `area = ((s_lo, s_hi), (t_lo, t_hi))`: `None` as soon as an
/// iterate leaves it (a bracket's Newton that heads out of the bracket is converging to
/// some other pair, and is given up before it spends more jets on it). The best point met is
/// kept: each linearisation (one pair of jets) measures the end of the step before it, and
/// the polish stops when that residual rises.
pub(crate) fn polish_within(
    vs: &View,
    vt: &View,
    s: f64,
    t: f64,
    area: ((f64, f64), (f64, f64)),
) -> Option<(f64, f64)> {
    let ((s_lo, s_hi), (t_lo, t_hi)) = area;
    // At the rounding floor another step only moves within the noise (it used to take three
    // or four more jet pairs to see the residual rise).
    let limits = Newton2 {
        residual: RESIDUAL_FLOOR,
        ..Newton2::steps(PAIR_POLISH_STEPS)
    };
    newton2::polish(
        Vector2::new(s, t),
        limits,
        |x| antipodal_system(vs, vt, x[0], x[1]),
        |x, step| x - step,
        |it| {
            let (s, t) = (it.from[0], it.from[1]);
            if it.step[0].abs() <= ulps(4.0) * s.abs().max(1.0)
                && it.step[1].abs() <= ulps(4.0) * t.abs().max(1.0)
            {
                return StepVerdict::Converged;
            }
            let (ns, nt) = (it.to[0], it.to[1]);
            // (NaN leaves too.)
            let inside = ns >= s_lo && ns <= s_hi && nt >= t_lo && nt <= t_hi;
            if inside {
                StepVerdict::Continue
            } else {
                StepVerdict::Abandon
            }
        },
    )
    .best()
    .map(|x| (x[0], x[1]))
}

/// Tolerances a Newton step from a found pair may still take for the pair to count as
/// resolved: the polish's own reach, within which a march's limit is placed.
const RESOLVED_STEPS: f64 = 64.0;

/// The antipodal system at `(s, t)`: its value `(α′(s) × α′(t), r · α′(s))`, its Jacobian,
/// and its residual, the sines of the angles between the tangents and between `r` and the
/// tangent at `s`, summed.
fn antipodal_system(vs: &View, vt: &View, s: f64, t: f64) -> (Vector2<f64>, Matrix2<f64>, f64) {
    let (js, jt) = (vs.jet_to(s, 2), vt.jet_to(t, 2));
    let r = jt.p - js.p;
    let f1 = js.d1.cross(jt.d1);
    let f2 = r.dot(js.d1);
    let residual =
        (f1 / (js.d1.norm() * jt.d1.norm())).abs() + (f2 / (r.norm() * js.d1.norm())).abs();
    let (a11, a12) = (js.d2.cross(jt.d1), js.d1.cross(jt.d2));
    let (a21, a22) = (-js.d1.dot(js.d1) + r.dot(js.d2), jt.d1.dot(js.d1));
    (
        Vector2::new(f1, f2),
        Matrix2::new(a11, a12, a21, a22),
        residual,
    )
}

/// `(s, t)` is a pair to the tolerance `tol`: a root of the antipodal system to rounding, or
/// one that Newton's method places within `tol` of it in both parameters. (The antipodal angle
/// alone does not say so: where the curves are nearly arcs of one circle, as the lobes of a
/// slender elliptic lemniscate, θ stays within 1e-9 of zero over stretches 1e5 tolerances
/// long, and Newton from any point of them found a "pair" whose θ was zero because its `t`
/// had left the opposite point, the tangents no longer parallel.)
pub(crate) fn is_resolved(vs: &View, vt: &View, s: f64, t: f64, tol: f64) -> bool {
    let (value, jacobian, residual) = antipodal_system(vs, vt, s, t);
    residual <= RESIDUAL_FLOOR
        || newton_step(value, jacobian, 0.0).is_some_and(|d| d[0].abs() <= tol && d[1].abs() <= tol)
}

/// Steps of a common tangent's polish, at most (each measured: one linearisation more).
const TANGENT_POLISH_STEPS: usize = 8;

/// Newton's method on the common-tangent system `α′(s) × β′(t) = 0`, `(β(t) − α(s)) × α′(s) = 0`
/// from a found tangent: polishes it to full precision (`None` if it moves away). The best
/// point met is kept: a step is taken while the residual at its end does not rise, and the
/// polish stops after a step below the parameters' rounding.
pub(crate) fn polish_tangent(
    vs: &View,
    vt: &View,
    s: f64,
    t: f64,
    max_move: f64,
) -> Option<(f64, f64)> {
    let tangent_system = |x: &Vector2<f64>| {
        let (js, jt) = (vs.jet_to(x[0], 2), vt.jet_to(x[1], 2));
        let r = jt.p - js.p;
        let f1 = js.d1.cross(jt.d1);
        let f2 = r.cross(js.d1);
        let residual =
            (f1 / (js.d1.norm() * jt.d1.norm())).abs() + (f2 / (r.norm() * js.d1.norm())).abs();
        let (a11, a12) = (js.d2.cross(jt.d1), js.d1.cross(jt.d2));
        let (a21, a22) = (r.cross(js.d2), jt.d1.cross(js.d1));
        (
            Vector2::new(f1, f2),
            Matrix2::new(a11, a12, a21, a22),
            residual,
        )
    };
    let (s0, t0) = (s, t);
    // The steps taken, and whether the last one was below the parameters' rounding: the
    // polish ends at its end (measured by the linearisation after it: not risen).
    let (mut steps, mut settled) = (0, false);
    // No residual test: only the rise of the residual, the step test and the bound end it.
    newton2::polish(
        Vector2::new(s, t),
        Newton2::steps(TANGENT_POLISH_STEPS + 1),
        tangent_system,
        |x, step| x - step,
        |it| {
            if settled || steps == TANGENT_POLISH_STEPS {
                return StepVerdict::Converged;
            }
            let (ns, nt) = (it.to[0], it.to[1]);
            if (ns - s0).abs() > max_move || (nt - t0).abs() > max_move {
                return StepVerdict::Abandon;
            }
            steps += 1;
            settled =
                it.step[0].abs() + it.step[1].abs() <= STEP_ROUNDING * (1.0 + ns.abs() + nt.abs());
            StepVerdict::Continue
        },
    )
    .best()
    .map(|x| (x[0], x[1]))
}

/// The overlap (in radians) of two pieces' ranges of opposite normal angles below which it is
/// rounding of the angles: no section.
const ANGLE_OVERLAP: f64 = 1e-12;

/// A Newton step on the common-tangent system below this part of the parameters is below
/// their rounding: converged.
const STEP_ROUNDING: f64 = 1e-17;
