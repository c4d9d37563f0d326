//! Antipodal-Points (Jia Table 1): Bisect (§4.1) and March (§4.2.1, §4.2.2) calling each other
//! on a pair satisfying conditions (i)–(v).
//!
//! On curves with symbolic forms two steps go beyond the paper, both resting on a proof that
//! θ is monotone over a stretch ([`crate::finish`]): a march ends by Newton's method as soon
//! as the stretch to the pair it proposes holds no other (Jia's march converges only
//! linearly), and the stretch beside a found pair that Table 1 cuts off by a small ε is as
//! long as θ is proven monotone from the pair (a guess of ε no longer decides what is skipped).

use crate::bisect::bisect;
use crate::finish::{certified_rest, certified_rests, clear_between};
use crate::ledger::Ledger;
use crate::march::{by_width, march_convex, march_mixed, March};
use crate::pairs::{negligible, Pair};
use crate::radius_rates::clear_by_rates;
use numeric::certificate::{Doubt, Doubts};
use smallvec::SmallVec;

/// Work limits shared by one run.
pub(crate) struct Budget {
    pub(crate) sections: usize,
    pub(crate) exhausted: bool,
}

/// Finds all antipodal pairs `(s, t)` of `pair`, appending them to `out`. `stack`: room for
/// the sub-pairs still to search (empty; kept by the caller from one pair to the next).
pub(crate) fn antipodal_points<'a>(
    pair: &Pair<'a>,
    out: &mut Vec<(f64, f64)>,
    budget: &mut Budget,
    stack: &mut Vec<Pair<'a>>,
    ledger: &mut Ledger,
) {
    stack.clear();
    stack.push(*pair);
    while let Some(p) = stack.pop() {
        if budget.sections == 0 {
            budget.exhausted = true;
            return;
        }
        budget.sections -= 1;
        if negligible(p.vs, p.sa, p.sb) {
            continue;
        }
        let ta = p.sin_theta(p.sa, p.ta);
        let tb = p.sin_theta(p.sb, p.tb);
        if (ta < 0.0) != (tb < 0.0) && ta != 0.0 && tb != 0.0 {
            // Bisect: one pair for sure; march on both remainders unless both are concave.
            let Some(found) = bisect(&p, ta, ledger.of(p.vt)) else {
                continue;
            };
            out.push((found.s, found.t));
            if p.s_convex || p.t_convex {
                stack.extend(rests(&p, found.s, found.t, true, true, ta < 0.0, ledger));
            }
        } else {
            let ends = ((p.sa, p.ta), (p.sb, p.tb));
            if long_march(&p, (ta, tb))
                && (clear_between(&p, ends.0, ends.1, (ta, tb))
                    || clear_by_rates(&p, ends.0, ends.1, (ta, tb)))
            {
                continue;
            }
            let march = match (p.s_convex, p.t_convex) {
                (true, true) => march_convex(&p, ta, ledger),
                (false, false) => March::Nothing,
                (true, false) => march_mixed(&p, ledger),
                (false, true) => match march_mixed(&p.swapped(), ledger) {
                    // Back to the original roles; "up" is in t, so flip it when t runs down.
                    March::Found(s, t, up) => {
                        March::Found(t, s, if p.ta <= p.tb { up } else { !up })
                    }
                    March::Crawled(s, t, up) => {
                        March::Crawled(t, s, if p.ta <= p.tb { up } else { !up })
                    }
                    March::Nothing => March::Nothing,
                },
            };
            let found = match march {
                March::Found(s, t, up) => Some((s, t, up)),
                March::Nothing => None,
                March::Crawled(s, t, up) => {
                    // The marched stretch is free of pairs; the rest is settled by the width.
                    let rest = if up {
                        p.sub(s, t, p.sb, p.tb)
                    } else {
                        p.sub(p.sa, p.ta, s, t)
                    };
                    if !by_width(&rest, out, ledger) {
                        // (The width's sampling hit its bound: pairs may be missing.)
                        budget.exhausted = true;
                    }
                    None
                }
            };
            if let Some((s, t, moved_up)) = found {
                out.push((s, t));
                // The marched side is free of pairs: continue on the other side only.
                stack.extend(rests(
                    &p,
                    s,
                    t,
                    moved_up,
                    !moved_up,
                    (ta < 0.0) == moved_up,
                    ledger,
                ));
            }
        }
    }
}

/// A march over the section `p` (θ = `th` at its ends, of one sign) would take several steps:
/// each turns the normal by about θ, so the normal's whole turn over `p` at the smaller |θ|
/// of the ends takes [`LONG_MARCH`] or more. Only on curves with symbolic forms (where the
/// section may be proven free of pairs instead), and not on two concave segments (which
/// hold no pair: no march).
fn long_march(p: &Pair, th: (f64, f64)) -> bool {
    if p.vs.cert.is_none() || p.vt.cert.is_none() || !(p.s_convex || p.t_convex) {
        return false;
    }
    let (na, nb) = (p.vs.normal(p.sa), p.vs.normal(p.sb));
    let turn = na.cross(nb).atan2(na.dot(nb)).abs();
    turn >= LONG_MARCH * th.0.abs().min(th.1.abs()).min(1.0).asin()
}

/// The sub-pairs left beside a found pair `(s, t)`: cut where θ is proven monotone from the
/// pair on (curves with symbolic forms), else by [`remainders`].
fn rests<'a>(
    p: &Pair<'a>,
    s: f64,
    t: f64,
    above: bool,
    below: bool,
    below_neg: bool,
    ledger: &mut Ledger,
) -> SmallVec<[Pair<'a>; 2]> {
    let certified = p.vs.cert.is_some() && p.vt.cert.is_some();
    let mut out = SmallVec::new();
    let both = match certified && above && below {
        true => certified_rests(p, s, t, ledger.of(p.vt)),
        false => [None, None],
    };
    for ((want, dir), joint) in [(below, -1.0), (above, 1.0)].into_iter().zip(both) {
        if !want {
            continue;
        }
        let proven = match (above && below, certified) {
            (true, _) => joint,
            (false, true) => certified_rest(p, s, t, dir, ledger.of(p.vt)),
            (false, false) => None,
        };
        match proven {
            Some(rest) => out.extend(rest),
            // Where no stretch is proven (θ′ changes sign right beside the pair, or the
            // ranges are too loose: a slender ellipse's type-B pair), Table 1's ε decided by
            // the signs of θ, without widening it by guess on a certified curve. Nothing
            // proves that the stretch skipped holds no other pair: not certified. (None of
            // the papers' shapes nor 2,400 random quadratics to quintics takes this path.)
            None => {
                if certified {
                    ledger.of(p.vs).add(Doubt::EpsilonCut);
                }
                out.extend(remainders(
                    p,
                    s,
                    dir > 0.0,
                    dir < 0.0,
                    below_neg,
                    !certified,
                    ledger,
                ))
            }
        }
    }
    out
}

/// Sub-pairs on either side of a found pair, cut at `s* ± ε` (Table 1). The side a pair was
/// approached from keeps its sign, the other side has the opposite one (`below_neg`: θ < 0
/// below `s*`). ε starts at 1e-6 of the section (the escape from `s*` then takes fewer march
/// steps) and comes closer whenever θ shows the wrong sign there (another pair within ε),
/// down to the parameter tolerance; it grows while θ is within rounding of zero.
///
/// The expected signs hold for a pair marched to, but not always for one bisected to: a
/// bracket with three pairs inside may end on the middle one (Newton lands there), whose θ
/// crosses zero the other way. A wrong sign that persists down to where θ is within rounding
/// (or down to the tolerance) is then the side's own sign: the cut is made at the closest ε
/// that shows it, and the search of the remainder — a sign change towards the section's end —
/// finds the pairs beyond. (Growing ε out of the rounding and shrinking it at the wrong sign
/// again used to cycle until the iterations ran out and drop both remainders.) A remainder
/// that still cannot be cut uncertifies the result. `widening`: the cut may then move away
/// from the pair by [`widen`] (a guess: only where nothing is certified anyway).
fn remainders<'a>(
    p: &Pair<'a>,
    s: f64,
    above: bool,
    below: bool,
    below_neg: bool,
    widening: bool,
    ledger: &mut Ledger,
) -> SmallVec<[Pair<'a>; 2]> {
    let mut out = SmallVec::new();
    let min_eps = 16.0 * p.vs.tol;
    for (want, dir, want_neg) in [(below, -1.0, below_neg), (above, 1.0, !below_neg)] {
        if !want {
            continue;
        }
        let cut_at = |se: f64, te: f64| {
            if dir < 0.0 {
                p.sub(p.sa, p.ta, se, te)
            } else {
                p.sub(se, te, p.sb, p.tb)
            }
        };
        let mut eps = (FIRST_EPS * (p.sb - p.sa)).max(min_eps);
        // The closest cut seen with the wrong sign: (ε, s, t).
        let mut wrong: Option<(f64, f64, f64)> = None;
        let mut decided = false;
        for _ in 0..64 {
            let se = s + dir * eps;
            if se <= p.sa || se >= p.sb {
                if eps > min_eps {
                    eps = (eps / 8.0).max(min_eps);
                    continue;
                }
                // Nothing left beyond the tolerance.
                decided = true;
                break;
            }
            let Some(te) = p.opposite(se, ledger.of(p.vt)) else {
                break;
            };
            let th = p.sin_theta(se, te);
            if p.is_noise(se, te, th) {
                eps *= 2.0;
                if let Some((w, sw, tw)) = wrong {
                    if eps >= w {
                        // Within rounding below the closest wrong sign: that sign is the
                        // side's own.
                        out.push(cut_at(sw, tw));
                        decided = true;
                        break;
                    }
                }
                continue;
            }
            if (th < 0.0) == want_neg {
                let (se, te) = if widening {
                    widen(p, s, dir, eps, th, (se, te), ledger.of(p.vt))
                } else {
                    (se, te)
                };
                out.push(cut_at(se, te));
                decided = true;
                break;
            }
            if eps <= min_eps {
                out.push(cut_at(se, te));
                decided = true;
                break;
            }
            wrong = Some((eps, se, te));
            eps = (eps / 8.0).max(min_eps);
        }
        if !decided {
            ledger.of(p.vs).add(Doubt::SectionUndecided);
        }
    }
    out
}

/// Moves a cut `s* ± ε` away from the found pair while θ grows at least half as fast as
/// linearly from it (so it does not turn back towards zero, which another pair close by
/// would need): the march that follows then starts farther from `s*` and escapes from it in
/// fewer steps. Returns the (possibly unchanged) cut.
fn widen(
    p: &Pair,
    s: f64,
    dir: f64,
    eps: f64,
    th: f64,
    cut: (f64, f64),
    doubts: &mut Doubts,
) -> (f64, f64) {
    let limit = WIDEN_LIMIT * (p.sb - p.sa);
    let (mut eps, mut th, mut cut) = (eps, th, cut);
    while eps * 64.0 <= limit {
        let e2 = eps * 64.0;
        let s2 = s + dir * e2;
        if s2 <= p.sa || s2 >= p.sb {
            break;
        }
        // The opposite point lies between the last cut's and the far end's.
        let t_far = if dir > 0.0 { p.tb } else { p.ta };
        let t2 = p.opposite_within(s2, cut.1, t_far, doubts);
        let th2 = p.sin_theta(s2, t2);
        if (th2 < 0.0) != (th < 0.0) || th2.abs() < 0.5 * 64.0 * th.abs() {
            break;
        }
        (eps, th, cut) = (e2, th2, (s2, t2));
    }
    cut
}

/// Steps (predicted from θ at a section's ends) from which a march is worth sparing by a
/// proof that the section holds no pair: shorter ones end by themselves for less.
const LONG_MARCH: f64 = 3.0;

/// Table 1's ε at first, relative to the section: the escape from the found pair then takes
/// few march steps, and ε comes closer wherever θ shows another pair within it.
const FIRST_EPS: f64 = 1e-6;

/// How far (relative to the section) [`widen`] may move a cut away from its pair.
const WIDEN_LIMIT: f64 = 1e-2;
