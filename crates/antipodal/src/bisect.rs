//! Bisect (Jia §4.1): on a pair whose antipodal angle θ changes sign between its ends, a pair
//! of antipodal points inside, by regula falsi on the sign of θ with Newton's method on the
//! antipodal system tried along the way.

use crate::pairs::{negligible, polish_within, Pair};
use numeric::certificate::Doubts;
use numeric::solve::{End, Illinois};

/// An antipodal pair found inside a section: its parameters on the two pieces.
pub(crate) struct Found {
    pub(crate) s: f64,
    pub(crate) t: f64,
}

/// Steps of the search on θ at the most (the Illinois stepper's halvings close any bracket of
/// doubles well within this; [`negligible`] or Newton usually stops it within a dozen).
const BISECT_STEPS: usize = 300;

/// §4.1: regula falsi on the sign of θ (numeric's [`Illinois`] stepper, inside the bracket),
/// with the opposite point `t` carried along with each end and Newton's method on the
/// antipodal system tried along the way: any pair inside the bracket will do (what lies
/// beside it is searched on). `doubts`: those of `T`'s view, where its opposite points' solves
/// put theirs.
pub(crate) fn bisect(p: &Pair, theta_a: f64, doubts: &mut Doubts) -> Option<Found> {
    let (s0, t0, f0) = (p.sa, p.ta, theta_a);
    let (s1, t1) = (p.sb, p.tb);
    let f1 = p.sin_theta(s1, t1);
    // Newton on the antipodal system first, from the secant of θ with `t` following `s`
    // linearly (no opposite point solved): taken when it lands on a pair inside the bracket.
    // (Per run, 3–4 % fewer instructions on the curves with convexities m = 3, 4 and a wavy
    // cubic, 9 % on a random cubic with 20 points; +3 % on one with 8.)
    let w = f0 / (f0 - f1);
    let guess = (s0 + w * (s1 - s0), t0 + w * (t1 - t0));
    if let Some(found) = pair_within(p, guess, (s0, t0), (s1, t1)) {
        return Some(found);
    }
    let mut solve = Illinois::new((s0, f0), (s1, f1));
    // The opposite points of the two ends.
    let mut t = [t0, t1];
    for i in 0..BISECT_STEPS {
        let ((s0, _), (s1, _)) = solve.ends();
        // Down to the parameter tolerance, and on until the normal no longer turns across
        // the bracket (a stretch narrower than the tolerance may still turn it by a finite
        // angle).
        if negligible(p.vs, s0.min(s1), s0.max(s1)) {
            break;
        }
        let Some(sm) = solve.next() else {
            // Neighbouring floats: the bracket cannot shrink further.
            break;
        };
        let tm = if (sm - s0).abs() <= (sm - s1).abs() {
            p.opposite_following(sm, (s0, t[0]), (s1, t[1]), doubts)
        } else {
            p.opposite_following(sm, (s1, t[1]), (s0, t[0]), doubts)
        };
        let fm = p.sin_theta(sm, tm);
        if fm == 0.0 {
            return Some(Found { s: sm, t: tm });
        }
        match solve.update(sm, fm) {
            End::First => t[0] = tm,
            End::Second => t[1] = tm,
        }
        // Newton on the antipodal system from the better end, accepted only when it lands
        // on a pair inside the current bracket (which then holds a pair for sure).
        if i % 2 == 0 {
            let ((s0, f0), (s1, f1)) = solve.ends();
            let better = if f0.abs() < f1.abs() {
                (s0, t[0])
            } else {
                (s1, t[1])
            };
            if let Some(found) = pair_within(p, better, (s0, t[0]), (s1, t[1])) {
                return Some(found);
            }
        }
    }
    let ((s0, f0), (s1, f1)) = solve.ends();
    let (s, t) = if f0.abs() < f1.abs() {
        (s0, t[0])
    } else {
        (s1, t[1])
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
