//! The proof that θ is strictly monotone along a stretch of a section (Jia eq. 10 bounded by
//! interval arithmetic), on which the certified finish of the marches and the cuts beside a
//! found pair rest: one pair at most where θ changes sign, none where it does not.

use crate::pairs::{Pair, THETA_NOISE};
use numeric::certificate::Doubts;
use numeric::Interval;
use std::f64::consts::FRAC_PI_2;

/// How far from `from` towards `to` (pairs `(s, t)` of opposite points) θ is proven strictly
/// monotone: the fraction `first` of the way (1: the whole), or else a quarter of that, a
/// sixteenth, …, whichever is proven first; `None` when none is. (The ranges tighten as the
/// stretch shrinks. Extending a proven stretch piece by piece was tried: near where θ′
/// vanishes the pieces only crawl, and the march they spare is cheaper than their bounds.)
pub(crate) fn monotone_reach(
    p: &Pair,
    from: (f64, f64),
    to: (f64, f64),
    first: f64,
    doubts: &mut Doubts,
) -> Option<(f64, f64)> {
    let dir = if to.0 >= from.0 { 1.0 } else { -1.0 };
    let whole = (to.0 - from.0) * dir;
    let mut len = whole * first;
    for _ in 0..24 {
        if len <= 64.0 * p.vs.tol {
            break;
        }
        let next = if len >= whole {
            to
        } else {
            let e = from.0 + dir * len;
            (e, p.opposite_following(e, from, to, doubts))
        };
        if theta_monotone(p, from, next).is_some() {
            return Some(next);
        }
        len *= 0.25;
    }
    None
}

/// θ is strictly monotone for `s` between `a.0` and `b.0` (opposite points `a.1`, `b.1`):
/// `Some(true)` where it increases, `Some(false)` where it decreases.
///
/// The sign of θ′ is bounded by interval arithmetic on the ranges of κ on both arcs, of |r|
/// and of θ: as κ(s) times a bracket of radii, or free of radii where an arc reaches an
/// inflection.
pub(crate) fn theta_monotone(p: &Pair, a: (f64, f64), b: (f64, f64)) -> Option<bool> {
    let ((s0, t0), (s1, t1)) = (a, b);
    // θ′ must have one sign at the two ends, clear of rounding: a cheap necessary condition
    // that spares the bounds where they cannot succeed (as where both ends of a section are
    // inflections, and θ′ is 0/0 there).
    let (Some(h0), Some(h1)) = (turning_at(p, s0, t0), turning_at(p, s1, t1)) else {
        return None;
    };
    if (h0 < 0.0) != (h1 < 0.0) {
        return None;
    }
    // The arc of T is t(J) only if the ends are opposite points indeed, to the padding of
    // T's arc (a few tolerances, for the rounding of the solve): the normal of T, which turns
    // one way on its piece, passes the direction opposite to S's within the padding of the
    // solved point. (An angle below 1e-9 did not say so where T is nearly straight, and
    // refused the solved points at a slender ellipse's vertex, where it turns fast.)
    let (tl, th) = p.t_range();
    let pad = 64.0 * p.vt.tol;
    let opposite = |s: f64, t: f64| {
        let (ns, jt) = (p.vs.normal(s), p.vt.jet_to(t, 2));
        let nt = jt.normal();
        if ns.dot(nt) >= 0.0 {
            return false;
        }
        let c = ns.cross(nt);
        let side = |u: f64| ns.cross(p.vt.normal(u.clamp(tl, th)));
        // At an end of T's piece the arc stops there: the exact opposite point must lie
        // within the padding on the piece's side (at an inflection, where T's normal stands
        // still, the angle is mere rounding).
        if t == tl || t == th {
            let inward = if t == tl { t + pad } else { t - pad };
            return c.abs() <= PIECE_END_OPPOSITE || c * side(inward) <= 0.0;
        }
        // (Where the angle left is a small part of what the normal turns over the padding,
        // the solved point is well inside it; else the signs at the padding's ends decide.)
        let turn = (jt.curvature() * jt.d1.norm()).abs() * pad;
        c.abs() <= OPPOSITE_INSIDE * turn || side(t - pad) * side(t + pad) <= 0.0
    };
    if !opposite(s0, t0) || !opposite(s1, t1) {
        return None;
    }
    let bt = p.vt.arc_bounds_padded(t0, t1, pad, (tl, th));
    let (Some(bs), Some(bt)) = (p.vs.arc_bounds(s0, s1), bt) else {
        return None;
    };
    // |θ| anywhere on J, to begin with: its value at s0, plus the turn of the normal along S
    // over J, plus the turn of r, which moves by at most the two boxes' diameters. (θ at an
    // end is that of the solved opposite point: within its noise, at most `THETA_NOISE`, of
    // the exact one.)
    let end_angle = |s: f64, t: f64| (p.sin_theta(s, t).abs() + THETA_NOISE).min(1.0).asin();
    let th0 = end_angle(s0, t0);
    let r0 = p.r(s0, t0).norm();
    let turn_s = p.vs.normal(s0).dot(p.vs.normal(s1)).clamp(-1.0, 1.0).acos();
    let turn_r = ((bs.diameter() + bt.diameter()) / r0).min(1.0).asin();
    let mut theta_max = th0 + turn_s + turn_r;
    let mut dist = bs.distance(&bt);
    // κ keeps the sign of its piece (the isolated inflections prove it), reaching zero at
    // most at an inflection that ends the piece: the ranges are clipped to that sign, and
    // the signed radii ρ = 1/κ exist only where they keep clear of zero.
    let signed = |k: Interval, convex: bool| match convex {
        true => Interval::new(k.lo.max(0.0), k.hi),
        false => Interval::new(k.lo, k.hi.min(0.0)),
    };
    let (ks, kt) = (signed(bs.kappa, p.s_convex), signed(bt.kappa, p.t_convex));
    let (rho_s, rho_t) = (ks.recip(), kt.recip());
    let one = Interval::new(1.0, 1.0);
    // (t moves κ(s)/κ(t) times as far as s in arc length: the tangents at s and t are
    // opposite along a section.) The arc of T is padded: so is its length.
    let (len, len_t) = ((s1 - s0).abs(), (t1 - t0).abs() + 2.0 * pad);
    // The far end's angle and distance, and how far |r| can move over J at most (over sin θ),
    // once the first bound has failed.
    let mut far: Option<(f64, f64, f64)> = None;
    for _ in 0..4 {
        let inv_r = dist.recip()?;
        let cos = Interval::new(
            if theta_max < FRAC_PI_2 {
                theta_max.cos()
            } else {
                -1.0
            },
            1.0,
        );
        let c_r = cos.mul(inv_r);
        // θ′/|C′(s)| = (1 + κ(s)/κ(t)) cos θ/|r| − κ(s) (Jia eq. 10). First as κ(s) times the
        // bracket (ρ(s) + ρ(t)) cos θ/|r| − 1, each range entering once (the tightest).
        let g = match (rho_s, rho_t) {
            (Some(rs), Some(rt)) => Some(rs.add(rt).mul(c_r).sub(one).widened(BOUND_ROOM)),
            _ => None,
        };
        if let Some(g) = g.filter(|g| g.excludes_zero()) {
            return Some((ks.lo > 0.0) == (g.lo > 0.0));
        }
        // Then free of radii: κ(t) θ′/|C′(s)| = κ(s) (cos θ/|r| − κ(t)) + κ(t) cos θ/|r|,
        // which proves stretches that reach an inflection (κ(t) keeps its piece's sign).
        // Multilinear in κ(s), κ(t) and cos θ/|r|: its exact range is at the corners (each
        // curvature enters twice, and plain interval arithmetic lost a sign the ends share
        // where one arc runs into an inflection).
        let q = Interval::multilinear(
            [ks, kt, c_r],
            |a, b, c| a * (c - b) + b * c,
            BOUND_ROOM * (ks.mag() * (c_r.mag() + kt.mag()) + kt.mag() * c_r.mag()),
        );
        if q.excludes_zero() {
            return Some(p.t_convex == (q.lo > 0.0));
        }
        // Not proven: tighten the bound on |θ| by the rate θ can change at, a zero-free path
        // from both ends: |θ(x)| ≤ (|θ(s0)| + |θ(s1)| + max|θ′| |J|)/2. In s, |θ′|/|C′(s)| is
        // at most |κ(s)| |g| and |(1 + κ(s) ρ(t)) cos θ/|r| − κ(s)|; in t, by symmetry (θ is
        // also the angle of −r from N(t)), |dθ/dt|/|C′(t)| is at most |(1 + κ(t) ρ(s)) cos
        // θ/|r| − κ(t)|. (Towards an inflection of T, t outruns s and only the rate in t is
        // finite; towards one of S, the other way round.) Every bound so far holds on all of
        // J, so the new one does too; with it, the range of |r| by its own rate, |d|r|/ds| =
        // |C′(s)| |1 + κ(s) ρ(t)| |sin θ| (or in t), from both ends.
        let by_g = g.map_or(f64::INFINITY, |g| ks.mag() * g.mag());
        // (Multilinear again: exact at the corners.)
        let rate = |k: Interval, rho: Interval| {
            let size = (1.0 + k.mag() * rho.mag()) * c_r.mag() + k.mag();
            Interval::multilinear(
                [k, rho, c_r],
                |k, r, c| (1.0 + k * r) * c - k,
                BOUND_ROOM * size,
            )
            .mag()
        };
        let in_s = rho_t.map_or(f64::INFINITY, |rt| rate(ks, rt));
        let in_t = rho_s.map_or(f64::INFINITY, |rs| rate(kt, rs));
        let (th1, r1, r_swing) = *far.get_or_insert_with(|| {
            let by_s = rho_t.map_or(f64::INFINITY, |rt| {
                bs.speed * one.add(ks.mul(rt)).mag() * len
            });
            let by_t = rho_s.map_or(f64::INFINITY, |rs| {
                bt.speed * one.add(kt.mul(rs)).mag() * len_t
            });
            (end_angle(s1, t1), p.r(s1, t1).norm(), by_s.min(by_t))
        });
        let change = (bs.speed * by_g.min(in_s) * len).min(bt.speed * in_t * len_t);
        let next = 0.5 * (th0 + th1 + change) * (1.0 + BOUND_ROOM);
        // (NaN and infinity stop too.)
        if next.partial_cmp(&(0.9 * theta_max)) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        theta_max = next;
        let swing = r_swing * theta_max.min(FRAC_PI_2).sin();
        // (The ends' t are solved to the tolerance: |r| there is known to that times the
        // speed of T, and to its rounding.)
        let pad = 64.0 * p.vt.tol * bt.speed + DISTANCE_ROUNDING * (r0 + r1);
        let mid = 0.5 * (r0 + r1);
        dist = Interval::new(
            dist.lo.max(mid - 0.5 * swing - pad),
            dist.hi.min(mid + 0.5 * swing + pad),
        );
        if dist.lo > dist.hi {
            return None;
        }
    }
    None
}
/// `κ(t) θ′/|C′(s)| = κ(s) (cos θ/|r| − κ(t)) + κ(t) cos θ/|r|` at one point: its sign times
/// that of κ on `T` is the sign of θ′ (finite at an inflection ending either piece, where a
/// radius is not). `None` where it is within rounding of zero (curvatures of 1e-9 over the
/// distance, as at two inflections opposite each other).
fn turning_at(p: &Pair, s: f64, t: f64) -> Option<f64> {
    let (js, jt) = (p.vs.jet_to(s, 2), p.vt.jet_to(t, 2));
    let r = jt.p - js.p;
    let c_r = js.normal().dot(r) / r.dot(r);
    let (ks, kt) = (js.curvature(), jt.curvature());
    let h = ks * (c_r - kt) + kt * c_r;
    // Clear of the cancellation among its terms, and of the curvatures' own noise, which is
    // that of C′ × C″ against |C′||C″| (at inflections opposite each other h is all noise).
    // (An absolute floor of 1e-9 / |r|² hid the sign at a slender ellipse's minor axis,
    // where both curvatures are 1e-12 of 1 / |r| and exact to rounding.)
    let terms = (ks * c_r).abs() + (ks * kt).abs() + (kt * c_r).abs();
    let noise = |j: &curve::Jet| j.d2.norm() / j.d1.dot(j.d1);
    let h_noise = noise(&js) * (c_r - kt).abs() + noise(&jt) * (ks.abs() + c_r.abs());
    (h.abs() > TURNING_CLEAR * terms && h.abs() > TURNING_CLEAR * h_noise).then_some(h)
}

/// The part of the normal's turn over the padding of a solved opposite point that the angle
/// left between the normals may be for the exact opposite point to lie well inside the
/// padding without checking its ends (the turn rate varies little across it).
const OPPOSITE_INSIDE: f64 = 0.1;

/// The angle between the normals at the ends of a section that pair a piece's end of T
/// with its solved opposite point on S: rounding of the solve, far below any turn that
/// matters.
const PIECE_END_OPPOSITE: f64 = 1e-9;

/// How far the turning rate at an end must stand clear of the cancellation among its terms
/// and of the curvatures' noise for its sign to be taken (a cheap filter ahead of the
/// bounds, which prove the sign; about 10⁷ roundings).
const TURNING_CLEAR: f64 = 1e-9;

/// Relative room for the rounding of the interval operations that bound θ′ and θ (a few
/// dozen operations on ranges carrying their own rounding): far above it, far below what
/// decides a sign.
const BOUND_ROOM: f64 = 1e-9;

/// Relative rounding of `|r|` at the ends of a stretch, computed from two points.
const DISTANCE_ROUNDING: f64 = 1e-12;

#[cfg(test)]
pub(crate) mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::driver::dissect;
    use crate::ledger::Ledger;
    use crate::pairs::opposite_pair;
    use crate::prepare::tests::{as_given, star_curve};
    use crate::Options;
    use proptest::prelude::*;

    /// Stretches proven monotone over all cases (the property must not be vacuous).
    static PROVEN: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

    /// The opposite point of `s` by bisection on the side of `N(t)` against `−N(s)` over the
    /// whole of `T` (monotone: one crossing), independent of the solver and of conditioning.
    pub(crate) fn opposite_by_bisection(p: &Pair, s: f64) -> f64 {
        let n = -p.vs.normal(s);
        let side = |t: f64| p.vt.normal(t).cross(n) > 0.0;
        let (mut lo, mut hi) = (p.ta, p.tb);
        let s_lo = side(lo);
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if mid == lo || mid == hi {
                break;
            }
            if side(mid) == s_lo {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// The antipodal angle itself (not its sine): `atan2(N × r, N · r)`.
    fn theta(p: &Pair, s: f64, t: f64) -> f64 {
        let n = p.vs.normal(s);
        let r = p.r(s, t);
        n.cross(r).atan2(n.dot(r))
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

        /// Wherever θ is proven monotone on random pairs of monotone pieces of random closed
        /// B-splines and NURBS, dense sampling finds it monotone in the proven direction.
        fn proven_monotone_stretches_are_monotone(
            deg in 3usize..=5,
            seed in proptest::collection::vec(0.0f64..1.0, 12..=40),
            w in proptest::collection::vec(0.5f64..2.0, 20),
            rational in any::<bool>(),
            picks in proptest::collection::vec((0.0f64..1.0, prop_oneof![1e-4f64..1e-2, 1e-2f64..1.0]), 4),
        ) {
            let c = star_curve(deg, &seed, rational.then_some(&w[..]));
            let given = as_given(&c);
            let Ok(prep) = dissect(given.source(true), &Options::default(), None, 0) else {
                return Ok(());
            };
            let (v, pieces) = (&prep.value.view, &prep.value.pieces);
            let mut proven = 0;
            // (The doubts met are not what is tested here.)
            let mut ledger = Ledger::new();
            for i in 0..pieces.len() {
                for j in i + 1..pieces.len() {
                    let Some(pair) = opposite_pair(v, &pieces[i], v, &pieces[j], &mut ledger) else {
                        continue;
                    };
                    for &(f, len) in &picks {
                        let s0 = pair.sa + f * (pair.sb - pair.sa);
                        let s1 = (s0 + len * (pair.sb - pair.sa)).min(pair.sb);
                        let t0 = pair.opposite_within(s0, pair.ta, pair.tb, ledger.of(v));
                        let t1 = if s1 == pair.sb {
                            pair.tb
                        } else {
                            pair.opposite_within(s1, pair.ta, pair.tb, ledger.of(v))
                        };
                        let Some(up) = theta_monotone(&pair, (s0, t0), (s1, t1)) else {
                            continue;
                        };
                        proven += 1;
                        let mut last = theta(&pair, s0, opposite_by_bisection(&pair, s0));
                        for k in 1..=40 {
                            let s = s0 + (s1 - s0) * k as f64 / 40.0;
                            let t = opposite_by_bisection(&pair, s);
                            let th = theta(&pair, s, t);
                            let rise = if up { th - last } else { last - th };
                            prop_assert!(
                                rise > -1e-12,
                                "θ not {} on [{s0}, {s1}] near {s}: {last} then {th}",
                                if up { "increasing" } else { "decreasing" }
                            );
                            last = th;
                        }
                    }
                }
            }
            PROVEN.fetch_add(proven, std::sync::atomic::Ordering::Relaxed);
        }
    }

    /// Runs the property and checks that it is not vacuous.
    #[test]
    fn proven_monotone_stretches_are_monotone_and_many() {
        proven_monotone_stretches_are_monotone();
        assert!(PROVEN.load(std::sync::atomic::Ordering::Relaxed) >= 1000);
    }
}
