//! A certified finish for the marches of §4.2, whose convergence is only linear.
//!
//! Newton's method on the antipodal system proposes the pair ahead of the march. It is taken
//! only when the stretch `J` from the march's point to just past the proposal provably holds
//! exactly one pair: θ changes sign across `J`, and θ is strictly monotone on `J`. Along a
//! section (normals opposite, so `t` follows `s` with `dt/ds = κ(s)/κ(t)` in arc length),
//!
//! ```text
//! θ′(s) = |C′(s)| · ((1 + κ(s)/κ(t)) cos θ / |r| − κ(s))
//! ```
//!
//! (Jia eq. 10 in an arbitrary parametrisation), and the bracket is bounded over `J` by
//! interval arithmetic on certified ranges of κ on both arcs, of `|r|` between their bounding
//! boxes, and of θ. When that range excludes zero, θ is monotone on `J`. The same test with
//! `J` reaching the section's end and no sign change proves that no pair lies ahead.
//!
//! Only curves with symbolic forms have certified ranges; the others keep the march (or its
//! sampled finish).

use crate::bisect::bisect;
use crate::monotone::{monotone_reach, theta_monotone};
use crate::pairs::{polish, Pair};
use numeric::certificate::Doubts;

/// What a finishing attempt proved.
pub(crate) enum Finish {
    /// The pair ahead, the only one between the march and it.
    Found(f64, f64),
    /// No pair between the march and the section's end.
    Nothing,
    /// No pair between the march and this point (θ proven monotone up to it, with the
    /// march's sign there): the march goes on from it.
    Leap(f64, f64),
    /// Nothing proven: the march goes on.
    Unproven,
}

/// Tries to finish a march standing at `(s, t)` and heading up in `s` when `up`; `limit`: how
/// far ahead the march's linear convergence puts its limit (NaN when not converging).
pub(crate) fn certified_finish(
    p: &Pair,
    s: f64,
    t: f64,
    up: bool,
    limit: f64,
    doubts: &mut Doubts,
) -> Finish {
    let (end_s, end_t) = if up { (p.sb, p.tb) } else { (p.sa, p.ta) };
    let dir = if up { 1.0 } else { -1.0 };
    let th_s = p.sin_theta(s, t);
    let remaining = (end_s - s) * dir;
    if p.is_noise(s, t, th_s) || remaining.is_nan() || remaining <= 0.0 {
        return Finish::Unproven;
    }
    let reach = remaining.max((end_t - t).abs());
    let ahead_ok = |&(ps, pt): &(f64, f64)| {
        let ahead = (ps - s) * dir;
        ahead > 0.0 && ahead < remaining && p.sin_theta(ps, pt).abs() <= NEWTON_ROOT
    };
    // Newton from the march's point, or else (near a nearly double pair Newton overshoots) a
    // sign change of θ found around the limit the march's linear convergence predicts.
    let proposal = polish(p.vs, p.vt, s, t, reach)
        .filter(ahead_ok)
        .or_else(|| bracketed_ahead(p, (s, t), (end_s, end_t), th_s, limit, doubts));
    // J runs from s to a little past the proposal, or to the end when there is none.
    let (e, te) = match proposal {
        Some((ps, pt)) => {
            let ahead = (ps - s) * dir;
            let past = (PAST_PROPOSAL * ahead).max(64.0 * p.vs.tol);
            if ahead + past < remaining {
                let e = ps + dir * past;
                (e, p.opposite_following(e, (ps, pt), (end_s, end_t), doubts))
            } else {
                (end_s, end_t)
            }
        }
        None => (end_s, end_t),
    };
    let th_e = p.sin_theta(e, te);
    if p.is_noise(e, te, th_e) || theta_monotone(p, (s, t), (e, te)).is_none() {
        return leap(p, (s, t), (e, te), th_s, doubts);
    }
    match ((th_e < 0.0) != (th_s < 0.0), proposal) {
        (true, Some((ps, pt))) => Finish::Found(ps, pt),
        (false, _) if e == end_s => Finish::Nothing,
        // Monotone with one sign at both ends: no zero up to e (the proposal was noise).
        (false, _) => Finish::Leap(e, te),
        _ => Finish::Unproven,
    }
}

/// A march at `(s, t)` heading up in `s` when `up` that escapes from a pair behind it: no pair
/// lies ahead when θ has its sign at the section's end and is proven monotone up to there.
pub(crate) fn clear_ahead(p: &Pair, s: f64, t: f64, up: bool) -> bool {
    let end = if up { (p.sb, p.tb) } else { (p.sa, p.ta) };
    let ends = (p.sin_theta(s, t), p.sin_theta(end.0, end.1));
    clear_between(p, (s, t), end, ends)
}

/// No pair lies on `p` between the opposite points `a` and `b`, where θ is `th.0` and `th.1`:
/// their signs agree beyond the noise, and θ is proven monotone in between. (The cheap tests
/// first: the monotonicity proof fails fast where θ′ changes sign between the ends.)
pub(crate) fn clear_between(p: &Pair, a: (f64, f64), b: (f64, f64), th: (f64, f64)) -> bool {
    (th.0 < 0.0) == (th.1 < 0.0)
        && th.0 != 0.0
        && th.1 != 0.0
        && theta_monotone(p, a, b).is_some()
        && p.is_clear(a.0, a.1, th.0)
        && p.is_clear(b.0, b.1, th.1)
}

/// Where θ is not proven monotone from the march's point `from` to `to`: over the first half
/// of the way it may be (the ranges tighten as the stretch shrinks), and with the march's
/// sign at its end that half holds no pair.
fn leap(p: &Pair, from: (f64, f64), to: (f64, f64), th: f64, doubts: &mut Doubts) -> Finish {
    let m = 0.5 * (from.0 + to.0);
    let tm = p.opposite_between(m, from, to, doubts);
    let th_m = p.sin_theta(m, tm);
    if p.is_noise(m, tm, th_m) || (th_m < 0.0) != (th < 0.0) {
        return Finish::Unproven;
    }
    match theta_monotone(p, from, (m, tm)) {
        Some(_) => Finish::Leap(m, tm),
        None => Finish::Unproven,
    }
}

/// A pair ahead of the march at `from` (θ = `th` there, heading to `end`): θ sampled at the
/// limit the march predicts and at twice, four and eight times that distance; the first
/// sign change brackets a pair, found by bisection. (Which pair of the bracket does not
/// matter: the stretch up to it must still be proven monotone.)
fn bracketed_ahead(
    p: &Pair,
    from: (f64, f64),
    end: (f64, f64),
    th: f64,
    limit: f64,
    doubts: &mut Doubts,
) -> Option<(f64, f64)> {
    let dir = if end.0 >= from.0 { 1.0 } else { -1.0 };
    let remaining = (end.0 - from.0) * dir;
    if limit.is_nan() || limit <= 0.0 {
        return None;
    }
    let mut prev = from;
    for k in 0..4 {
        let reach = limit * f64::from(1u32 << k);
        if reach >= remaining {
            return None;
        }
        let x = from.0 + dir * reach;
        let y = p.opposite_within(x, prev.1, end.1, doubts);
        let th_x = p.sin_theta(x, y);
        if p.is_clear(x, y, th_x) && (th_x < 0.0) != (th < 0.0) {
            let sub = if dir > 0.0 {
                p.sub(prev.0, prev.1, x, y)
            } else {
                p.sub(x, y, prev.0, prev.1)
            };
            let f = bisect(&sub, sub.sin_theta(sub.sa, sub.ta), doubts)?;
            return Some((f.s, f.t));
        }
        prev = (x, y);
    }
    None
}

/// What is left of `p` beside a found pair `(s, t)` on the side `dir` (+1: above `s`), cut
/// where θ is proven monotone from the pair on: `Some(None)` when that reaches the section's
/// end (nothing left), `Some(Some(rest))` for the rest beyond the cut, `None` when nothing
/// could be proven (the caller then cuts by the signs of θ, Table 1's ε).
///
/// The cut is tried at the section's end first and then ever closer to the pair: the ranges
/// tighten as the stretch shrinks.
pub(crate) fn certified_rest<'a>(
    p: &Pair<'a>,
    s: f64,
    t: f64,
    dir: f64,
    doubts: &mut Doubts,
) -> Option<Option<Pair<'a>>> {
    rest_beyond(p, (s, t), dir, 1.0, doubts)
}

/// [`certified_rest`] with the first cut tried at the fraction `first` of the way to the end.
fn rest_beyond<'a>(
    p: &Pair<'a>,
    (s, t): (f64, f64),
    dir: f64,
    first: f64,
    doubts: &mut Doubts,
) -> Option<Option<Pair<'a>>> {
    let end = if dir > 0.0 {
        (p.sb, p.tb)
    } else {
        (p.sa, p.ta)
    };
    let room = (end.0 - s) * dir;
    if room.is_nan() || room <= 0.0 {
        return Some(None);
    }
    // From the pair itself: the exact pair lies within the tolerance of it, either on the
    // proven stretch (its only zero there) or behind it, closer than anything resolved.
    let (e, te) = monotone_reach(p, (s, t), end, first, doubts)?;
    if e == end.0 {
        return Some(None);
    }
    cut_at(p, s, (e, te), dir)
}

/// The rest of `p` beyond a cut at `e` on the side `dir` of a found pair at `s`: `None` when
/// the cut is within the tolerance of the pair or θ there is within its noise.
fn cut_at<'a>(p: &Pair<'a>, s: f64, (e, te): (f64, f64), dir: f64) -> Option<Option<Pair<'a>>> {
    if (e - s) * dir <= 64.0 * p.vs.tol || p.is_noise(e, te, p.sin_theta(e, te)) {
        return None;
    }
    Some(Some(if dir > 0.0 {
        p.sub(e, te, p.sb, p.tb)
    } else {
        p.sub(p.sa, p.ta, e, te)
    }))
}

/// Both sides of a found pair `(s, t)` inside `p` at once, as [`certified_rest`] gives each
/// (below, then above): a side is settled by θ proven monotone from the pair to its end.
/// Where the side below is not, both share one proof over a quarter of each, across the pair
/// (θ monotone there has no zero but the pair's), before the side above is tried to its end
/// (the two sides mostly fare alike: on the elliptic lemniscate neither proof to an end
/// holds, and the second one cost 4 % of its run). A side still open goes on alone
/// from a quarter on.
pub(crate) fn certified_rests<'a>(
    p: &Pair<'a>,
    s: f64,
    t: f64,
    doubts: &mut Doubts,
) -> [Option<Option<Pair<'a>>>; 2] {
    let ends = [(p.sa, p.ta), (p.sb, p.tb)];
    let room = |i: usize| (ends[i].0 - s).abs();
    let whole = |i: usize| {
        let r = room(i);
        if r.is_nan() || r <= 0.0 || theta_monotone(p, (s, t), ends[i]).is_some() {
            Some(None)
        } else {
            None
        }
    };
    let mut out = [whole(0), None];
    if out[0].is_none() && room(1) > 0.0 {
        let lo = s - 0.25 * room(0);
        let hi = s + 0.25 * room(1);
        let (tl, th) = (
            p.opposite_following(lo, (s, t), ends[0], doubts),
            p.opposite_following(hi, (s, t), ends[1], doubts),
        );
        if theta_monotone(p, (lo, tl), (hi, th)).is_some() {
            out = [cut_at(p, s, (lo, tl), -1.0), cut_at(p, s, (hi, th), 1.0)];
        }
    }
    if out[1].is_none() {
        out[1] = whole(1);
    }
    for (i, dir) in [(0, -1.0), (1, 1.0)] {
        if out[i].is_none() {
            out[i] = rest_beyond(p, (s, t), dir, 0.25, doubts);
        }
    }
    out
}

/// `|sin θ|` at the point Newton's method proposes for it to be a pair: a few thousand units
/// of rounding of θ (the proof that follows decides; this only rules out a stalled Newton).
pub(crate) const NEWTON_ROOT: f64 = 1e-12;

/// How far past the proposed pair (relative to the way to it) the stretch proven to hold one
/// pair reaches: enough to bracket it with room for its solve, short enough to stay clear of
/// the next.
const PAST_PROPOSAL: f64 = 1e-3;
