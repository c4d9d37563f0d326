//! March (Jia §4.2.1, §4.2.2): from a section's end where θ has one sign, steps towards the
//! pair ahead with provable (linear) convergence; on curves with symbolic forms it ends by
//! Newton's method as soon as the stretch to the proposed pair is proven to hold no other
//! ([`crate::finish`]). Also the section's width, which settles what a march leaves.

use crate::bisect::bisect;
use crate::finish::{certified_finish, clear_ahead, Finish, NEWTON_ROOT};
use crate::ledger::Ledger;
use crate::pairs::{negligible, polish, Pair, THETA_NOISE};
use crate::prims::Prefer;
use numeric::certificate::{Doubt, Doubts};

/// §4.2.1, two convex segments with θ of one sign at both ends: march from `s_b` down when
/// θ < 0 (from `s_a` up when θ > 0), each step moving `s` to the point whose normal is parallel
/// to `r(s_i)` and `t` to its opposite point.
pub(crate) fn march_convex(p: &Pair, theta_a: f64, ledger: &mut Ledger) -> March {
    let up = theta_a > 0.0;
    let end = if up { p.sb } else { p.sa };
    let far = (end, p.vs.jet_to(end, 1).d1);
    let step = |_, s, t, hint, ledger: &mut Ledger| {
        let dir = p.r(s, t).unit();
        let here = (s, p.vs.jet_to(s, 1).d1);
        p.vs.point_with_normal_from(here, far, dir, hint, ledger.of(p.vs))
    };
    march(p, up, step, ledger)
}

/// §4.2.2, `S` convex and `T` concave: march from the end whose normal ray at `t` meets `S`,
/// each step moving `s` to where the ray of `N(t_i)` meets `S`.
pub(crate) fn march_mixed(p: &Pair, ledger: &mut Ledger) -> March {
    let (psa, psb) = (p.vs.point(p.sa), p.vs.point(p.sb));
    let ray_hits = |t: f64| {
        let jt = p.vt.jet_to(t, 1);
        let (pt, n) = (jt.p, jt.normal());
        let c0 = (psa - pt).cross(n);
        let c1 = (psb - pt).cross(n);
        (c0 < 0.0) != (c1 < 0.0)
    };
    // Lemma 9: no ray meets S, no pair.
    let up = if ray_hits(p.ta) {
        true
    } else if ray_hits(p.tb) {
        false
    } else {
        return March::Nothing;
    };
    let step = |i, s, t, hint, ledger: &mut Ledger| {
        let (lo, hi) = if up { (s, p.sb) } else { (p.sa, s) };
        let prefer = if up { Prefer::Low } else { Prefer::High };
        let jt = p.vt.jet_to(t, 1);
        let hint = if i == 0 { f64::NAN } else { hint };
        p.vs.point_on_ray(lo, hi, jt.p, jt.normal(), prefer, hint, ledger.of(p.vs))
    };
    march(p, up, step, ledger)
}

/// The march loop shared by §4.2.1 and §4.2.2, from the `s_a` end when `up` (else from `s_b`):
/// `next(i, s, t, hint)` gives step `i`'s new `s` (`hint`: the last move extrapolated by the
/// step ratio, where Newton should start), or `None` when no pair lies ahead; `t` follows to
/// the opposite point. (`next` is handed the ledger: its solves on `S` meet `S`'s doubts.)
fn march(
    p: &Pair,
    up: bool,
    mut next: impl FnMut(usize, f64, f64, f64, &mut Ledger) -> Option<f64>,
    ledger: &mut Ledger,
) -> March {
    let (mut s, mut t) = if up { (p.sa, p.ta) } else { (p.sb, p.tb) };
    // The sign of θ the march keeps until it reaches a pair.
    let start_negative = p.sin_theta(s, t) < 0.0;
    // T's far end, kept with its tangent: every step's solve for t is bracketed by it.
    let t_end = if up { p.tb } else { p.ta };
    let t_far = (t_end, p.vt.jet_to(t_end, 1).d1);
    let mut last_step = f64::INFINITY;
    let (mut ds, mut dt, mut ratio) = (0.0, 0.0, 1.0);
    let certified = p.vs.cert.is_some() && p.vt.cert.is_some();
    // Steps to the next finishing attempt, and the gap after a failed one (doubling).
    let (mut wait, mut gap) = (FIRST_WAIT, FIRST_GAP);
    // The step from which an escaping march next tries to prove nothing lies ahead, and |θ|
    // at the last point (the march escapes while it grows).
    let (mut escape_at, mut last_theta) = (ESCAPE_CHECK, f64::INFINITY);
    // The greatest |θ| so far, and whether the march has come down from it.
    let (mut peak, mut past_peak) = (0.0f64, false);
    for i in 0..MARCH_STEPS {
        let Some(ns) = next(i, s, t, s + ds * ratio, ledger) else {
            // No step ahead: nothing lies ahead, unless the last step went past a pair (by
            // the tolerance its solves are made to) and the next one would lie behind.
            return match i {
                0 => March::Nothing,
                _ => overshot(
                    p,
                    (s - ds, t - dt),
                    (s, t),
                    (start_negative, up),
                    ledger.of(p.vt),
                ),
            };
        };
        let nt = p.opposite_near_from(ns, t, t_far, t + dt * ratio, ledger.of(p.vt));
        let mut step = (ns - s).abs();
        ratio = (step / last_step).clamp(0.0, 3.0);
        (ds, dt) = (ns - s, nt - t);
        s = ns;
        t = nt;
        if let Some((s, t)) = converged(p, step, last_step, s, t) {
            return March::Found(s, t, up);
        }
        if i >= CRAWL_CHECK && ratio >= 1.0 && crawls(p, s, up, step, ratio, MARCH_STEPS - i) {
            // The step bound would be used up before the section's end: hand over now.
            return March::Crawled(s, t, up);
        }
        if certified {
            let theta = p.sin_theta(s, t).abs();
            // First come down from the peak: the finish is tried at once.
            let fallen = !past_peak && theta < PAST_PEAK * peak;
            // A finish is tried while the march converges, at steps ever farther apart
            // after failures. While it escapes from a pair behind (steps and |θ| growing)
            // with several steps to go, a proof that none lies ahead may end it early.
            if step > last_step {
                (wait, gap) = (0, FIRST_GAP);
                let escaping = theta > last_theta && i + 1 >= escape_at;
                if escaping && steps_left(p, s, up, step, ratio) >= ESCAPE_STEPS {
                    if clear_ahead(p, s, t, up) {
                        return March::Nothing;
                    }
                    escape_at = 2 * (i + 1);
                }
            } else if wait == 0 || fallen {
                past_peak |= fallen;
                let q = step / last_step;
                let limit = if q < 1.0 {
                    step * q / (1.0 - q)
                } else {
                    f64::NAN
                };
                let mut finish = certified_finish(p, s, t, up, limit, ledger.of(p.vt));
                // Proven leaps over stretches without pairs, each followed by a new attempt
                // from where it lands (bounded: each halves what is left at most).
                for _ in 0..MAX_LEAPS {
                    let Finish::Leap(ls, lt) = finish else {
                        break;
                    };
                    (s, t) = (ls, lt);
                    (ds, dt, ratio, step) = (0.0, 0.0, 1.0, f64::INFINITY);
                    finish = certified_finish(p, s, t, up, f64::NAN, ledger.of(p.vt));
                }
                match finish {
                    Finish::Found(s, t) => return March::Found(s, t, up),
                    Finish::Nothing => return March::Nothing,
                    Finish::Unproven | Finish::Leap(..) => {
                        wait = gap;
                        gap *= 2;
                    }
                }
            } else {
                wait -= 1;
            }
            peak = peak.max(theta);
            // (After leaps the march stands elsewhere, its θ unknown.)
            last_theta = if step.is_finite() {
                theta
            } else {
                f64::INFINITY
            };
        } else {
            match finish_early(p, s, t, step, last_step, up, ledger.of(p.vt)) {
                Early::Found((s, t, up)) => return March::Found(s, t, up),
                Early::Nothing => return March::Nothing,
                Early::Continue => {}
            }
        }
        last_step = step;
    }
    March::Crawled(s, t, up)
}

/// A march whose step from `prev` to `here` found no next step ahead: where θ at `here` still
/// has the march's sign (`start_negative`) nothing lies ahead; where it has the other sign,
/// the last step crossed a pair, which lies between the two points and is bisected for. Where
/// θ is within its noise at `here`, Newton's method there must resolve a pair; else θ is
/// merely small (the curves nearly arcs of one circle) and the march crawls: the section's
/// width settles the rest from `prev` on. (Every such point was taken for a pair: a slender
/// elliptic lemniscate at a tolerance of 1e-6 had a "pair" every 1e-4 along its lobes.)
fn overshot(
    p: &Pair,
    prev: (f64, f64),
    here: (f64, f64),
    (start_negative, up): (bool, bool),
    doubts: &mut Doubts,
) -> March {
    let (s, t) = here;
    let th = p.sin_theta(s, t);
    if p.is_noise(s, t, th) {
        return match polish(p.vs, p.vt, s, t, 64.0 * p.vs.tol) {
            Some((s, t)) if p.is_resolved(s, t) => March::Found(s, t, up),
            _ => March::Crawled(prev.0, prev.1, up),
        };
    }
    if (th < 0.0) == start_negative {
        return March::Nothing;
    }
    let sub = if prev.0 <= s {
        p.sub(prev.0, prev.1, s, t)
    } else {
        p.sub(s, t, prev.0, prev.1)
    };
    match bisect(&sub, sub.sin_theta(sub.sa, sub.ta), doubts) {
        Some(f) => March::Found(f.s, f.t, up),
        None => March::Nothing,
    }
}

/// Steps after which a march that does not converge is checked for crawling.
const CRAWL_CHECK: usize = 64;

/// A march at `s` heading up (`up`) or down, whose steps (the last one `step`) do not shrink
/// but grow by `ratio` each, would need more than `left` steps to reach the section's end:
/// it crawls (θ stays so small along the section that each step turns the normal by little),
/// and [`by_width`] would settle the rest anyway once the step bound is used up.
fn crawls(p: &Pair, s: f64, up: bool, step: f64, ratio: f64, left: usize) -> bool {
    steps_left(p, s, up, step, ratio) > left as f64
}

/// How many more steps a march at `s` heading up (`up`) or down, whose steps (the last one
/// `step`) grow by `ratio` each, takes to the section's end (0 when it cannot tell).
fn steps_left(p: &Pair, s: f64, up: bool, step: f64, ratio: f64) -> f64 {
    let remaining = if up { p.sb - s } else { s - p.sa };
    if step.is_nan() || step <= 0.0 || remaining <= 0.0 {
        return 0.0;
    }
    if ratio > 1.0 + RATIO_ROUNDING {
        // Steps growing geometrically: Σ step·ratioᵏ reaches `remaining` after this many.
        (1.0 + remaining * (ratio - 1.0) / step).ln() / ratio.ln()
    } else {
        remaining / step
    }
}

/// Outcome of a march: the pair it reached (`moved_up` in `s`), no pair ahead, or its step
/// bound used up at `(s, t)` with the stretch behind free of pairs.
pub(crate) enum March {
    Found(f64, f64, bool),
    Nothing,
    Crawled(f64, f64, bool),
}

/// Samples of `w''` per section in [`by_width`].
const WIDTH_SAMPLES: usize = 256;

/// Settles a section the march could not cross (the antipodal angle stays so small that its
/// steps, which turn the normal by θ, crawl: the segments are close to arcs of one circle).
/// With both segments parametrised by the normal angle ψ, the distance between the parallel
/// tangent lines `w(ψ) = d` has `w′ = ±|r| sin θ` and `w″ = ρ(s) + ρ(t) − w` (signed radii of
/// curvature). Between the zeros of `w″` the derivative `w′` is monotone: each stretch holds a
/// pair exactly when θ changes sign across it, found by bisection. The zeros of `w″` are
/// located by sampling (the result is no longer certified). Returns `false` when `w″` cannot
/// be evaluated.
pub(crate) fn by_width(p: &Pair, out: &mut Vec<(f64, f64)>, ledger: &mut Ledger) -> bool {
    ledger.of(p.vs).add(Doubt::ConstantWidth);
    let doubts = ledger.of(p.vt);
    let w2 = |s: f64, t: f64| {
        let (js, jt) = (p.vs.jet_to(s, 2), p.vt.jet_to(t, 2));
        1.0 / js.curvature() + 1.0 / jt.curvature() - p.d(s, t)
    };
    let mut cuts = vec![(p.sa, p.ta)];
    let (mut prev_s, mut prev_t) = (p.sa, p.ta);
    let mut prev_w = w2(p.sa, p.ta);
    if prev_w.is_nan() {
        return false;
    }
    for k in 1..=WIDTH_SAMPLES {
        let (s, t) = if k == WIDTH_SAMPLES {
            (p.sb, p.tb)
        } else {
            let s = p.sa + (p.sb - p.sa) * k as f64 / WIDTH_SAMPLES as f64;
            (s, p.opposite_near(s, prev_t, p.tb, prev_t, doubts))
        };
        let w = w2(s, t);
        if w.is_nan() {
            return false;
        }
        if (w < 0.0) != (prev_w < 0.0) {
            // A zero of w″ in (prev_s, s): bisection on its sign.
            let (mut lo, mut hi, mut tl, mut th) = (prev_s, s, prev_t, t);
            while !negligible(p.vs, lo, hi) {
                let m = 0.5 * (lo + hi);
                if !(m > lo && m < hi) {
                    break;
                }
                let tm = p.opposite_between(m, (lo, tl), (hi, th), doubts);
                if (w2(m, tm) < 0.0) == (prev_w < 0.0) {
                    (lo, tl) = (m, tm);
                } else {
                    (hi, th) = (m, tm);
                }
            }
            cuts.push((lo, tl));
        }
        (prev_s, prev_t, prev_w) = (s, t, w);
    }
    cuts.push((p.sb, p.tb));
    for w in cuts.windows(2) {
        let ((s0, t0), (s1, t1)) = (w[0], w[1]);
        if negligible(p.vs, s0, s1) {
            continue;
        }
        let sub = p.sub(s0, t0, s1, t1);
        let (a, b) = (sub.sin_theta(s0, t0), sub.sin_theta(s1, t1));
        if a == 0.0 {
            out.push((s0, t0));
        } else if (a < 0.0) != (b < 0.0) && b != 0.0 {
            if let Some(f) = bisect(&sub, a, doubts) {
                out.push((f.s, f.t));
            }
        }
    }
    true
}

enum Early {
    Found((f64, f64, bool)),
    Nothing,
    Continue,
}

/// The finish of a march on a curve without symbolic forms (where [`certified_finish`] has no
/// ranges to prove anything with; such results are reported uncertified anyway): once the
/// march is converging (steps shrinking, below 1e-4 of the period), Newton on the antipodal
/// system finishes it. (Tried earlier — at a ratio of 0.9 and steps up to 1e-2 of the period —
/// it skipped pairs close to others on random curves.) The pair it reaches must lie ahead in the marching direction
/// with the antipodal angle keeping its sign in between (no pair skipped): inside the section
/// it is the pair the march converges to; beyond the section's far end (a pair just cut off
/// there) the march would only crawl up to that end, finding nothing. Otherwise the march goes
/// on.
fn finish_early(
    p: &Pair,
    s: f64,
    t: f64,
    step: f64,
    last: f64,
    up: bool,
    doubts: &mut Doubts,
) -> Early {
    let (end_s, end_t) = if up { (p.sb, p.tb) } else { (p.sa, p.ta) };
    // Linear convergence with ratio q puts the limit about step·q/(1−q) ahead. (Newton is
    // not tried before the march shows its convergence: from a first iterate it may jump to
    // the pair just cut off beyond the far end and over one in between.)
    let q = step / last;
    if !(q < FINISH_RATIO && step <= FINISH_STEP * p.vs.period) {
        return Early::Continue;
    }
    let ahead_by = step * q / (1.0 - q);
    let Some((ps, pt)) = polish(p.vs, p.vt, s, t, 4.0 * ahead_by + 1e3 * p.vs.tol) else {
        return Early::Continue;
    };
    let ahead = if up {
        ps >= s - p.vs.tol
    } else {
        ps <= s + p.vs.tol
    };
    if !ahead || p.sin_theta(ps, pt).abs() > NEWTON_ROOT || !p.is_resolved(ps, pt) {
        return Early::Continue;
    }
    let sign = p.sin_theta(s, t) < 0.0;
    let beyond = if up { ps >= end_s } else { ps <= end_s };
    if beyond {
        // The far end itself, and the middle of what is left, must still show the marching
        // sign.
        let sm = 0.5 * (s + end_s);
        let tm = p.opposite_within(sm, t, end_t, doubts);
        let same = |s: f64, t: f64| (p.sin_theta(s, t) < 0.0) == sign;
        return if same(end_s, end_t) && same(sm, tm) {
            Early::Nothing
        } else {
            Early::Continue
        };
    }
    let sm = 0.5 * (s + ps);
    let tm = p.opposite_within(sm, t, pt, doubts);
    if (p.sin_theta(sm, tm) < 0.0) == sign || (ps - s).abs() <= 4.0 * p.vs.tol {
        Early::Found((ps, pt, up))
    } else {
        Early::Continue
    }
}

/// Steps a march takes before its first finishing attempt: the attempt's proof must cover
/// the stretch to the pair the march converges on (or to the section's end), and from a
/// section's end that is rarely short enough. Measured on the papers' shapes and a wavy
/// cubic: 2 saves 2–13 % of a run against 0.
const FIRST_WAIT: usize = 2;

/// Steps of a march before it first tries to prove that nothing lies ahead as it escapes
/// from a pair behind (then at steps twice as far in after each failure).
const ESCAPE_CHECK: usize = 2;

/// Steps an escaping march must still have ahead (predicted from the growth of its steps)
/// for the proof that ends it early to be worth its cost (a few steps' worth of jets): with
/// fewer it ends by itself sooner (the ellipse's and limaçon's marches; those of the
/// elliptic lemniscate run ten steps to an inflection).
const ESCAPE_STEPS: f64 = 3.0;

/// Proven leaps in a row at one finishing attempt of a march.
const MAX_LEAPS: usize = 8;

/// Steps a march waits after its first failed finishing attempt (then twice as many, …): 8
/// did best with [`FIRST_WAIT`] (fewer wasted attempts, few extra steps).
const FIRST_GAP: usize = 8;

/// Fraction of the greatest |θ| of a march below which it has passed the peak: θ falls
/// monotonically from there on as a rule, and a finish is tried at once.
const PAST_PEAK: f64 = 0.8;

/// Bound on march steps: linear convergence needs O(ω) of them, a few hundred at worst. A march
/// whose steps stay tiny (θ small all along: nearly circular segments) stops here and
/// [`by_width`] settles the rest of its section.
const MARCH_STEPS: usize = 4000;

/// Converged: the steps shrink (linear convergence, not an escape from a nearby pair) and what
/// is left to the limit, `step·q/(1 − q)` at the ratio `q` of the last two steps, is below the
/// tolerance, or the antipodal angle is zero to rounding — and Newton's method from there
/// confirms a pair within a few tolerances (returned). (Neither the step nor the predicted
/// distance alone is enough: where θ hardly changes, as between the nearly double pairs of
/// the curve with convexities `p = 3, ε = 0.5, m = 11`, the steps are tiny and erratic far
/// from any pair, and at a tolerance of 1e-8 hundreds of march points were taken for pairs.)
fn converged(p: &Pair, step: f64, last: f64, s: f64, t: f64) -> Option<(f64, f64)> {
    let q = step / last;
    if q.is_nan() || q > 1.0 {
        return None;
    }
    let left = if q < 0.5 { step } else { step * q / (1.0 - q) };
    let close =
        left <= p.vs.tol || (p.sin_theta(s, t).abs() <= THETA_ROUNDING && step <= 1e3 * p.vs.tol);
    if !close {
        return None;
    }
    let (ps, pt) = polish(p.vs, p.vt, s, t, 64.0 * p.vs.tol.max(left))?;
    let th = p.sin_theta(ps, pt);
    (th.abs() <= THETA_NOISE.min(1e3 * p.theta_noise(ps, pt)) && p.is_resolved(ps, pt))
        .then_some((ps, pt))
}

/// A ratio of steps above 1 by more than this grows geometrically (not rounding of 1).
const RATIO_ROUNDING: f64 = 1e-9;

/// The uncertified finish starts once the march converges with steps shrinking by this
/// ratio at least (0.9 skipped pairs close to others on random curves) …
const FINISH_RATIO: f64 = 0.98;

/// … and below this part of the period.
const FINISH_STEP: f64 = 1e-4;

/// `|sin θ|` that is zero to the rounding of θ's evaluation (a few units).
const THETA_ROUNDING: f64 = 1e-15;
