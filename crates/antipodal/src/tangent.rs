//! Common tangents of a segment pair (Jia §2.2–2.4, Appendix B).
//!
//! `d(s) = N(s) · (α(t) − α(s))` vanishes exactly at common tangents and has only simple zeros,
//! at most two (Theorem 2). Different end signs at `sₐ`, `s_b`: exactly one. Equal end signs:
//! none or two. Existence is decided by the Common-Tangent iteration of §2.3 itself, started
//! with the endpoint ordering of §2.4: it converges whenever a tangent exists (Lemma 4), and its
//! limit is verified (`d = 0` to rounding), so a run that fails to converge proves nothing
//! exists to find. For segments bending the same way the configuration test of §2.2 and
//! Appendix B (is an end point of one segment on two tangent lines of the other?) is evaluated
//! too; our copy of the paper is truncated there, so where it disagrees with the iteration the
//! result is marked uncertified rather than trusted.
//! Once one tangent is known, the second lies where `d` changes sign again: a bisection on `d`
//! backs the iteration up wherever a sign change brackets a tangent.

use crate::ledger::Ledger;
use crate::pairs::Pair;
use crate::prims::Prefer;
use crate::view::View;
use curve::V2;
use numeric::certificate::Doubt;
use smallvec::SmallVec;

/// Points of tangency `(s, t)` of the common tangents of `p`, sorted by `s`.
pub(crate) fn common_tangents(p: &Pair, ledger: &mut Ledger) -> SmallVec<[(f64, f64); 2]> {
    let da = p.d(p.sa, p.ta);
    let db = p.d(p.sb, p.tb);
    // An end on a common tangent: its lines one to rounding, and the chord along them to
    // rounding of its direction (two close points of one curve have tangent lines within
    // rounding of each other, `d ≈ κ |r|² / 2`, without sharing one).
    let room = LINE_ROUNDING * p.vs.scale.max(p.vt.scale);
    let on = |d: f64, s: f64, t: f64| d.abs() <= room && d.abs() <= CHORD_ALONG * p.r(s, t).norm();
    let on = (on(da, p.sa, p.ta), on(db, p.sb, p.tb));
    if on.0 || on.1 {
        if let Some(found) = tangents_at_ends(p, on, (da, db), ledger) {
            return found;
        }
    }
    let odd = (da > 0.0) != (db > 0.0);
    let mut out = SmallVec::new();
    if odd {
        let found = ct_from(p, true, ledger)
            .or_else(|| ct_from(p, false, ledger))
            .or_else(|| bisect_d(p, p.sa, p.ta, p.sb, p.tb, ledger));
        out.extend(found);
        return out;
    }
    // Equal end signs: none or two. None at all where the sign of d is proven throughout.
    if d_one_signed(p) {
        return out;
    }
    // Else the iteration converges whenever a tangent exists (Lemma 4) and its limit is
    // verified, so it decides existence. (In the §2.4 order, then in the other.)
    let ordered = t_first(p, true);
    let first = common_tangent(p, true, ordered, ledger)
        .or_else(|| common_tangent(p, true, !ordered, ledger));
    // Segments bending the same way: configuration (a) or none, by the region test. A
    // disagreement with the (verified) iteration is reported as uncertified.
    if p.s_convex != p.t_convex && two_tangents_same_bending(p) != first.is_some() {
        ledger.of(p.vs).add(Doubt::TangentTestsDisagree);
    }
    let Some(first) = first else {
        return out;
    };
    out.push(first);
    // The second one lies beyond the first: d changes sign once on (s_c, s_b].
    let second = ct_from(p, false, ledger)
        .filter(|q| q.0 > first.0 + 4.0 * p.vs.tol)
        .or_else(|| {
            let s1 = first.0 + 64.0 * p.vs.tol;
            let t1 = p.opposite(s1, ledger.of(p.vt))?;
            bisect_d(p, s1, t1, p.sb, p.tb, ledger)
        });
    out.extend(second);
    out.sort_by(|x, y| x.0.total_cmp(&y.0));
    out
}

/// The common tangents of `p` where one lies at an end (`d` within rounding there, as where
/// the arcs of two profiles end on the line of their collinear straight edges): that one, and
/// the one inside if `d` changes sign between the end's side and the other end. `d` has simple
/// zeros, at most two (Theorem 2): with both ends on tangents none lies between; with one, at
/// most one, where the sign of `d` just inside the tangent end differs from its sign at the
/// other. That sign is the slope's, `d′ = −κ |C′| (T · r)` (`N′ = −κ |C′| T`, and `N(s) · C′(t)`
/// vanishes on opposite points), of κ's sign on the piece. (The configuration test of §2.2,
/// which assumes `d` of one sign at the ends, would read such an end on the boundary of its
/// region.) `None` where the slope's sign is not clear (the curves touching at the end): the
/// general search decides.
fn tangents_at_ends(
    p: &Pair,
    (on_a, on_b): (bool, bool),
    (da, db): (f64, f64),
    ledger: &mut Ledger,
) -> Option<SmallVec<[(f64, f64); 2]>> {
    let mut out: SmallVec<[(f64, f64); 2]> = SmallVec::new();
    let ends = [((p.sa, p.ta), on_a, 1.0), ((p.sb, p.tb), on_b, -1.0)];
    out.extend(ends.iter().filter(|e| e.1).map(|e| e.0));
    if on_a && on_b {
        return Some(out);
    }
    let (((s, t), _, inward), ((so, to), _, _)) = if on_a {
        (ends[0], ends[1])
    } else {
        (ends[1], ends[0])
    };
    let far = if on_a { db } else { da };
    let js = p.vs.jet_to(s, 1);
    let along = js.d1.unit().dot(p.r(s, t));
    let kappa = if p.s_convex { 1.0 } else { -1.0 };
    let room = LINE_ROUNDING * p.vs.scale.max(p.vt.scale);
    if along.abs() <= room {
        // (The curves touch at the end: no slope to read.)
        return None;
    }
    let inside_positive = -kappa * along * inward > 0.0;
    if inside_positive == (far > 0.0) {
        return Some(out);
    }
    // A point just inside with the slope's sign, clear of rounding, brackets the one inside
    // with the other end.
    let doubts = ledger.of(p.vt);
    let mut step = 64.0 * p.vs.tol;
    for _ in 0..INSIDE_STEPS {
        let x = s + inward * step;
        if (so - x) * inward <= 0.0 {
            break;
        }
        let y = p.opposite_between(x, (s, t), (so, to), doubts);
        let d = p.d(x, y);
        if d.abs() > room {
            if (d > 0.0) == inside_positive {
                out.extend(bisect_d(p, x, y, so, to, ledger));
            } else {
                // (Past the one inside already: it lies within a few tolerances of the
                // end's, one line to rounding.)
                ledger.of(p.vs).add(Doubt::RootCluster);
            }
            out.sort_by(|x, y| x.0.total_cmp(&y.0));
            return Some(out);
        }
        step *= 2.0;
    }
    ledger.of(p.vs).add(Doubt::RootCluster);
    Some(out)
}

/// The sine of the angle between a chord and the tangent lines at its ends below which the
/// chord lies along them (to rounding of its direction, as [`LINE_ROUNDING`] for the lines).
const CHORD_ALONG: f64 = 1e-9;

/// Steps (doubling from a few tolerances) in from a tangent end to a point where `d` shows
/// its sign beyond rounding.
const INSIDE_STEPS: usize = 40;

/// `d = N(s) · r` keeps one sign over the whole of `p` (curves with symbolic forms): the
/// normals of `S` lie in the cone of its end normals (a monotone segment, turning by less than
/// π) and `r` in the difference of the two arcs' bounding boxes, and `N · r` has one sign,
/// beyond rounding, at the cone's two edges against the difference's four corners. That
/// holds over the whole box (linear in `r`), and for a corner over the whole cone (a cone
/// narrower than π with both edges in a half-plane lies in it). Segments far apart for their
/// size, the common case, are settled without iterating.
fn d_one_signed(p: &Pair) -> bool {
    if p.vs.cert.is_none() || p.vt.cert.is_none() {
        return false;
    }
    let (Some((s_lo, s_hi)), Some((t_lo, t_hi))) =
        (p.vs.arc_box(p.sa, p.sb), p.vt.arc_box(p.ta, p.tb))
    else {
        return false;
    };
    let (lo, hi) = (t_lo - s_hi, t_hi - s_lo);
    let corners = [lo, V2::new(lo.x, hi.y), V2::new(hi.x, lo.y), hi];
    let room = LINE_ROUNDING * p.vs.scale.max(p.vt.scale);
    let (mut pos, mut neg) = (true, true);
    for n in [p.vs.normal(p.sa), p.vs.normal(p.sb)] {
        for c in corners {
            let v = n.dot(c);
            pos &= v > room;
            neg &= v < -room;
        }
    }
    pos || neg
}

/// Common-Tangent started at the `a` ends (or the `b` ends) with the ordering rule of §2.4:
/// if the translation from `L_a` to `L'_a` is along the bending direction of `S`, update `t`
/// first.
fn ct_from(p: &Pair, at_a: bool, ledger: &mut Ledger) -> Option<(f64, f64)> {
    common_tangent(p, at_a, t_first(p, at_a), ledger)
}

/// The ordering rule of §2.4 at the `a` ends (or the `b` ends): `t` is updated first.
fn t_first(p: &Pair, at_a: bool) -> bool {
    let (s0, t0) = if at_a { (p.sa, p.ta) } else { (p.sb, p.tb) };
    let bend = if p.s_convex { 1.0 } else { -1.0 };
    p.d(s0, t0) * bend > 0.0
}

/// The iteration of §2.3: `x_{i+1}` = point of tangency on `X` of the tangent through
/// `α(y_i)`, `y_{i+1}` = its opposite point on `Y`. Returns `(s, t)` once it converges to a
/// verified common tangent.
fn common_tangent(p: &Pair, at_a: bool, t_first: bool, ledger: &mut Ledger) -> Option<(f64, f64)> {
    // X is the segment updated first.
    let q = if t_first { p.swapped() } else { *p };
    // In the swapped pair the a-ends are the ends of the smaller t; map `at_a` accordingly.
    let at_a_q = if t_first && p.ta > p.tb { !at_a } else { at_a };
    let (mut x, mut y) = if at_a_q { (q.sa, q.ta) } else { (q.sb, q.tb) };
    let x_end = if at_a_q { q.sb } else { q.sa };
    let prefer = if at_a_q { Prefer::Low } else { Prefer::High };
    let tol = q.vs.tol;
    for _ in 0..64 {
        let py = q.vt.point(y);
        let (lo, hi) = (x.min(x_end), x.max(x_end));
        // Skip the current point itself: its tangent line is parallel to the one at y.
        let nx =
            q.vs.point_of_tangency(lo, hi, py, prefer, ledger.of(q.vs))?;
        let ny = q.opposite(nx, ledger.of(q.vt))?;
        let done = (nx - x).abs() <= tol && (ny - y).abs() <= 4.0 * q.vt.tol;
        x = nx;
        y = ny;
        if done {
            break;
        }
    }
    let (s, t) = if t_first { (y, x) } else { (x, y) };
    verify(p, s, t).then_some((s, t))
}

/// `(sa, ta)` of a pair of no width ([`crate::pairs::touching_ends`]) where the tangent lines
/// there are one to rounding: a common tangent no section holds (as at two inflections of
/// mirrored curves, their normals' extremes).
pub(crate) fn tangent_start(p: &Pair) -> Option<(f64, f64)> {
    verify(p, p.sa, p.ta).then_some((p.sa, p.ta))
}

/// `(s, t)` lies on `p` (to the tolerances) and the tangent lines there are one to rounding.
fn verify(p: &Pair, s: f64, t: f64) -> bool {
    let inside_s = s > p.sa - p.vs.tol && s < p.sb + p.vs.tol;
    let (tl, th) = p.t_range();
    let inside_t = t > tl - p.vt.tol && t < th + p.vt.tol;
    let scale = p.vs.scale.max(p.vt.scale);
    inside_s && inside_t && p.d(s, t).abs() <= LINE_ROUNDING * scale
}

/// Bisection on `d` over a bracket with a sign change (never fails).
fn bisect_d(
    p: &Pair,
    s0: f64,
    t0: f64,
    s1: f64,
    t1: f64,
    ledger: &mut Ledger,
) -> Option<(f64, f64)> {
    let doubts = ledger.of(p.vt);
    let (mut s0, mut t0, mut s1, mut t1) = (s0, t0, s1, t1);
    let d0 = p.d(s0, t0);
    if (d0 > 0.0) == (p.d(s1, t1) > 0.0) {
        return None;
    }
    for _ in 0..200 {
        if (s1 - s0).abs() <= p.vs.tol {
            break;
        }
        let sm = 0.5 * (s0 + s1);
        let tm = p.opposite_between(sm, (s0, t0), (s1, t1), doubts);
        if (p.d(sm, tm) > 0.0) == (d0 > 0.0) {
            s0 = sm;
            t0 = tm;
        } else {
            s1 = sm;
            t1 = tm;
        }
    }
    let (s, t) = (0.5 * (s0 + s1), 0.5 * (t0 + t1));
    let t = p.opposite(s, doubts).unwrap_or(t);
    verify(p, s, t).then_some((s, t))
}

/// §2.2, configuration (a): segments bending the same way, `d` of one sign at both ends, have
/// two common tangents when the end of one lies on two tangent lines of the other: `α(tₐ)` in
/// the region `R₀` of `S`, or `α(sₐ)` in `R₀` of `T` (Appendix B).
fn two_tangents_same_bending(p: &Pair) -> bool {
    let (tl, th) = p.t_range();
    in_r0(p.vs, p.sa, p.sb, p.s_convex, p.vt.point(p.ta))
        || in_r0(p.vt, tl, th, p.t_convex, p.vs.point(p.sa))
}

/// Appendix B: `pt ∈ R₀` of the segment over `(a, b)` (on two of its tangent lines).
fn in_r0(v: &View, a: f64, b: f64, convex: bool, pt: V2) -> bool {
    let (ja, jb) = (v.jet_to(a, 2), v.jet_to(b, 2));
    let sign = if convex { 1.0 } else { -1.0 };
    let (va, vb) = (ja.normal() * sign, jb.normal() * sign);
    if (pt - ja.p).dot(va) <= 0.0 || (pt - jb.p).dot(vb) <= 0.0 {
        return false;
    }
    let den = ja.d1.cross(jb.d1);
    if den.abs() <= PARALLEL_SIN * ja.d1.norm() * jb.d1.norm() {
        return false;
    }
    let o = ja.p + ja.d1 * ((jb.p - ja.p).cross(jb.d1) / den);
    let tri = [ja.p, o, jb.p];
    let s1 = (tri[1] - tri[0]).cross(pt - tri[0]);
    let s2 = (tri[2] - tri[1]).cross(pt - tri[1]);
    let s3 = (tri[0] - tri[2]).cross(pt - tri[2]);
    let inside = (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || (s1 <= 0.0 && s2 <= 0.0 && s3 <= 0.0);
    if !inside {
        return false;
    }
    // Foot point: root of (p − α(u)) · α′(u), of opposite signs at the ends inside the triangle.
    let f = |u: f64| {
        let j = v.jet_to(u, 3);
        let r = pt - j.p;
        (
            r.dot(j.d1),
            r.dot(j.d2) - j.d1.dot(j.d1),
            r.dot(j.d3) - 3.0 * j.d1.dot(j.d2),
        )
    };
    let (fa, fb) = (f(a).0, f(b).0);
    if (fa > 0.0) == (fb > 0.0) {
        return false;
    }
    let u = crate::prims::solve_in(f, (a, b), (fa, fb), v.tol, f64::NAN);
    let j = v.jet_to(u, 2);
    (pt - j.p).dot(j.normal() * j.curvature()) < 0.0
}

/// A distance between tangent lines (relative to the curves' size) within the rounding of the
/// points and directions it is computed from: the lines are one.
const LINE_ROUNDING: f64 = 1e-9;

/// The sine of the angle between two tangents below which they are parallel to rounding (no
/// meet to compute).
const PARALLEL_SIN: f64 = 1e-14;

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::driver::dissect;
    use crate::ledger::Ledger;
    use crate::monotone::tests::opposite_by_bisection;
    use crate::pairs::opposite_pair;
    use crate::prepare::tests::{as_given, star_curve};
    use crate::Options;
    use proptest::prelude::*;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use testkit::stars::{star_curve_with, Star};

    /// Stretches where `d` was proven of one sign, and where sampling found it change sign
    /// (neither count may stay small: the property must not be vacuous either way).
    static PROVEN: AtomicUsize = AtomicUsize::new(0);
    static CHANGING: AtomicUsize = AtomicUsize::new(0);

    proptest! {
        #![proptest_config(ProptestConfig { cases: 100, ..ProptestConfig::default() })]

        /// On random stretches of random pairs of monotone pieces, of one random closed
        /// B-spline or NURBS and of two (whose inner common tangents have opposite normals),
        /// `d` sampled densely (opposite points by bisection) keeps the sign it is proven to
        /// keep; where it changes sign (a common tangent) nothing is proven.
        fn proven_one_signed_d_has_no_zero(
            deg in 3usize..=5,
            seed in proptest::collection::vec(0.0f64..1.0, 12..=30),
            seed2 in proptest::collection::vec(0.0f64..1.0, 12..=30),
            w in proptest::collection::vec(0.5f64..2.0, 15),
            rational in any::<bool>(),
            (dist, dir) in (1.2f64..3.0, 0.0f64..std::f64::consts::TAU),
            picks in proptest::collection::vec((0.0f64..1.0, 0.05f64..1.0), 3),
        ) {
            let weights = rational.then_some(&w[..]);
            let a = star_curve(deg, &seed, weights);
            let far = Star {
                center: [dist * dir.cos(), dist * dir.sin()],
                ..Star::default()
            };
            let b = star_curve_with(&far, deg, &seed2, weights);
            let opts = Options::default();
            let (ga, gb) = (as_given(&a), as_given(&b));
            let Ok(pa) = dissect(ga.source(true), &opts, Some(false), 0) else {
                return Ok(());
            };
            let pa = pa.value;
            let mut others = vec![];
            for rev in [false, true] {
                let Ok(pb) = dissect(gb.source(true), &opts, Some(rev), 1) else {
                    return Ok(());
                };
                others.push(pb.value);
            }
            let mut pairs = vec![];
            // (The doubts met are not what is tested here.)
            let mut ledger = Ledger::new();
            for (i, p) in pa.pieces.iter().enumerate() {
                pairs.extend(pa.pieces[i + 1..].iter().filter_map(|q| opposite_pair(&pa.view, p, &pa.view, q, &mut ledger)));
                for pb in &others {
                    pairs.extend(pb.pieces.iter().filter_map(|q| opposite_pair(&pa.view, p, &pb.view, q, &mut ledger)));
                }
            }
            for pair in &pairs {
                // Opposite points by bisection inside, the pair's own at its ends (where the
                // bisection cannot tell the root from the end it sits on).
                let opp = |s: f64| match s {
                    s if s == pair.sa => pair.ta,
                    s if s == pair.sb => pair.tb,
                    s => opposite_by_bisection(pair, s),
                };
                // The whole pair first (what a run asks about), then stretches of it.
                for &(f, len) in [(0.0, 1.0)].iter().chain(&picks) {
                    let s0 = pair.sa + f * (pair.sb - pair.sa);
                    let s1 = (s0 + len * (pair.sb - pair.sa)).min(pair.sb);
                    if s1 <= s0 {
                        continue;
                    }
                    let sub = pair.sub(s0, opp(s0), s1, opp(s1));
                    let ds: Vec<f64> = (0..=60)
                        .map(|k| {
                            let s = s0 + (s1 - s0) * k as f64 / 60.0;
                            sub.d(s, opp(s))
                        })
                        .collect();
                    let changes = ds.iter().any(|&d| (d > 0.0) != (ds[0] > 0.0));
                    if changes {
                        CHANGING.fetch_add(1, Ordering::Relaxed);
                    }
                    if !d_one_signed(&sub) {
                        continue;
                    }
                    PROVEN.fetch_add(1, Ordering::Relaxed);
                    prop_assert!(
                        !changes && ds.iter().all(|&d| d != 0.0),
                        "d proven of one sign on [{s0}, {s1}] but sampled {ds:?}"
                    );
                }
            }
        }
    }

    /// Runs the property and checks that both outcomes occur.
    #[test]
    fn proven_one_signed_d_has_no_zero_and_both_outcomes_occur() {
        proven_one_signed_d_has_no_zero();
        // (Measured: about 14,000 proven and 1,300 changing.)
        assert!(PROVEN.load(Ordering::Relaxed) >= 2000);
        assert!(CHANGING.load(Ordering::Relaxed) >= 200);
    }
}
