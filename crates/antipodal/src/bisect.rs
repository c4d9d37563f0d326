//! Bisect (Jia §4.1): on a pair whose antipodal angle θ changes sign between its ends, a pair
//! of antipodal points inside, by regula falsi on the sign of θ with Newton's method on the
//! antipodal system tried along the way.

use crate::pairs::{negligible, polish_within, Pair};

/// An antipodal pair found inside a section: its parameters on the two pieces.
pub(crate) struct Found {
    pub(crate) s: f64,
    pub(crate) t: f64,
}

/// §4.1: bisection on the sign of θ (regula falsi, Illinois variant, inside the bracket),
/// with Newton's method on the antipodal system tried along the way: any pair inside the
/// bracket will do (what lies beside it is searched on).
pub(crate) fn bisect(p: &Pair, theta_a: f64) -> Option<Found> {
    let (mut s0, mut t0, mut f0) = (p.sa, p.ta, theta_a);
    let (mut s1, mut t1) = (p.sb, p.tb);
    let mut f1 = p.sin_theta(s1, t1);
    let mut side = 0i8;
    // Newton on the antipodal system first, from the secant of θ with `t` following `s`
    // linearly (no opposite point solved): taken when it lands on a pair inside the bracket.
    // (Per run, 3–4 % fewer instructions on the curves with convexities m = 3, 4 and a wavy
    // cubic, 9 % on a random cubic with 20 points; +3 % on one with 8.)
    let w = f0 / (f0 - f1);
    let guess = (s0 + w * (s1 - s0), t0 + w * (t1 - t0));
    if let Some(found) = pair_within(p, guess, (s0, t0), (s1, t1)) {
        return Some(found);
    }
    for i in 0..300 {
        // Down to the parameter tolerance, and on until the normal no longer turns across
        // the bracket (a stretch narrower than the tolerance may still turn it by a finite
        // angle).
        if negligible(p.vs, s0.min(s1), s0.max(s1)) {
            break;
        }
        // Illinois step, with a plain halving every few steps to bound the worst case.
        let mut sm = if i % 5 == 4 {
            0.5 * (s0 + s1)
        } else {
            (s0 * f1 - s1 * f0) / (f1 - f0)
        };
        if !(sm > s0.min(s1) && sm < s0.max(s1)) {
            sm = 0.5 * (s0 + s1);
            if !(sm > s0.min(s1) && sm < s0.max(s1)) {
                // Neighbouring floats: the bracket cannot shrink further.
                break;
            }
        }
        let tm = if (sm - s0).abs() <= (sm - s1).abs() {
            p.opposite_from(sm, (s0, t0), (s1, t1))
        } else {
            p.opposite_from(sm, (s1, t1), (s0, t0))
        };
        let fm = p.sin_theta(sm, tm);
        if fm == 0.0 {
            return Some(Found { s: sm, t: tm });
        }
        if (fm < 0.0) == (f0 < 0.0) {
            s0 = sm;
            t0 = tm;
            f0 = fm;
            if side == -1 {
                f1 *= 0.5;
            }
            side = -1;
        } else {
            s1 = sm;
            t1 = tm;
            f1 = fm;
            if side == 1 {
                f0 *= 0.5;
            }
            side = 1;
        }
        // Newton on the antipodal system from the better end, accepted only when it lands
        // on a pair inside the current bracket (which then holds a pair for sure).
        if i % 2 == 0 {
            let better = if f0.abs() < f1.abs() {
                (s0, t0)
            } else {
                (s1, t1)
            };
            if let Some(found) = pair_within(p, better, (s0, t0), (s1, t1)) {
                return Some(found);
            }
        }
    }
    let (s, t) = if f0.abs() < f1.abs() {
        (s0, t0)
    } else {
        (s1, t1)
    };
    Some(Found { s, t })
}

/// Newton's method on the antipodal system from `start`, accepted only when it lands on a
/// pair inside the bracket of the opposite points `a` and `b` without leaving it.
fn pair_within(p: &Pair, start: (f64, f64), a: (f64, f64), b: (f64, f64)) -> Option<Found> {
    let area = ((a.0.min(b.0), a.0.max(b.0)), (a.1.min(b.1), a.1.max(b.1)));
    let (s, t) = polish_within(p.vs, p.vt, start.0, start.1, area)?;
    (p.sin_theta(s, t).abs() <= BRACKETED_ROOT).then_some(Found { s, t })
}

/// `|sin θ|` at Newton's point inside a bracket for it to be the bracket's pair: a few hundred
/// units of rounding of θ (the bracket itself proves a pair inside; this only checks that
/// Newton reached it rather than stalling).
const BRACKETED_ROOT: f64 = 1e-13;
