//! The numerical primitives of Jia's Appendix A.
//!
//! Each one finds the unique root of a scalar function of the curve parameter on a monotone
//! segment. For spline curves existence and the bracket come from certified root isolation of
//! the primitive's symbolic B-spline (control-polygon sign tests); otherwise from the signs at
//! the ends (Jia's criterion, exact on a monotone segment), refined by Newton's method inside
//! the bracket, which cannot fail.

use crate::view::View;
use bspline::roots::{Count, Root, RootKind};
use bspline::Piecewise;
use curve::V2;
use numeric::certificate::{Doubt, Doubts};
use numeric::rounding::ulps;
use numeric::solve::{bracketed, newton_within, Accuracy};
use smallvec::SmallVec;

/// Halley's step safeguarded by a bracket on which `f` changes sign (see
/// [`numeric::solve::bracketed`]), to the parameter tolerance `tol`, from `hint` (NaN: none).
pub(crate) fn solve_in(
    f: impl Fn(f64) -> (f64, f64, f64),
    bracket: (f64, f64),
    ends: (f64, f64),
    tol: f64,
    hint: f64,
) -> f64 {
    bracketed(f, bracket, ends, Accuracy::param(tol).hint(hint))
}

/// How close (relative to the size) a point of the curve is to a given point to be that point:
/// the gap a profile's joint may leave between its segments, and more.
const SAME_CURVE_POINT: f64 = 1e-8;

/// Which root to take when several qualify.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Prefer {
    Low,
    High,
}

impl View<'_> {
    /// Shared driver: `f` gives the value and its first two derivatives, `form` is the symbolic
    /// form with the weights whose combination is the numerator of `f` (same sign), `accept`
    /// filters roots by geometry.
    // The closures and the bracket are the primitive; bundling them would only rename them.
    #[allow(clippy::too_many_arguments)]
    fn solve(
        &self,
        lo: f64,
        hi: f64,
        f: impl Fn(f64) -> (f64, f64, f64),
        form: Option<(&Piecewise, [f64; 3])>,
        accept: impl Fn(f64) -> bool,
        prefer: Prefer,
        hint: f64,
        doubts: &mut Doubts,
    ) -> Option<f64> {
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        if let (Some(_), Some((pw, w))) = (&self.cert, form) {
            let weights = &w[..pw.dim()];
            // The sign test on the pieces settles almost every call.
            match self.cert_count(pw, weights, lo, hi) {
                Some(Count::Zero) => return None,
                Some(Count::AtEnd(x)) => return accept(x).then_some(x),
                Some(Count::One(a, b)) => {
                    let (fa, fb) = (f(a).0, f(b).0);
                    if (fa < 0.0) != (fb < 0.0) {
                        let u = solve_in(&f, (a, b), (fa, fb), self.point_tol, hint);
                        return accept(u).then_some(u);
                    }
                }
                Some(Count::Open) | None => {}
            }
            if let Some(roots) = self.cert_roots(pw, weights, lo, hi) {
                let (flo, fhi) = (f(lo).0, f(hi).0);
                return self.pick(roots, lo, hi, &f, &accept, prefer, (flo, fhi), doubts);
            }
        }
        if self.cert.is_some() {
            doubts.add(Doubt::RootsUnresolved);
        }
        let (flo, fhi) = (f(lo).0, f(hi).0);
        sampled(lo, hi, flo, fhi, &f, &accept, self.point_tol, hint)
    }

    #[allow(clippy::too_many_arguments)]
    fn pick(
        &self,
        roots: Vec<Root>,
        lo: f64,
        hi: f64,
        f: &impl Fn(f64) -> (f64, f64, f64),
        accept: &impl Fn(f64) -> bool,
        prefer: Prefer,
        (flo, fhi): (f64, f64),
        doubts: &mut Doubts,
    ) -> Option<f64> {
        let mut good = roots.iter().filter(|r| accept(r.u));
        let chosen = match prefer {
            Prefer::Low => good.next(),
            Prefer::High => good.last(),
        };
        match chosen {
            Some(r) => {
                if r.kind == RootKind::Cluster || !r.certified {
                    doubts.add(Doubt::RootCluster);
                }
                // A root within rounding of an interval end may be reported as a cluster:
                // polish it on the curve itself.
                let u = if r.kind == RootKind::Cluster {
                    polish(f, r.u, lo, hi)
                } else {
                    r.u
                };
                Some(u.clamp(lo, hi))
            }
            None => {
                // A root exactly at an end can escape isolation (its coefficient is within
                // rounding of zero and has no trusted sign): take the end itself then.
                let small = END_ROOT * (flo.abs() + fhi.abs());
                if flo.abs() <= small && accept(lo) {
                    doubts.add(Doubt::RootAtEnd);
                    Some(lo)
                } else if fhi.abs() <= small && accept(hi) {
                    doubts.add(Doubt::RootAtEnd);
                    Some(hi)
                } else {
                    None
                }
            }
        }
    }

    /// `point-with-normal(lo, hi, n)`: the point whose inward normal points along `n`.
    pub(crate) fn point_with_normal(
        &self,
        lo: f64,
        hi: f64,
        n: V2,
        doubts: &mut Doubts,
    ) -> Option<f64> {
        self.point_with_normal_near(lo, hi, n, f64::NAN, doubts)
    }

    /// `point-with-normal` started from a nearby parameter `hint`.
    pub(crate) fn point_with_normal_near(
        &self,
        lo: f64,
        hi: f64,
        n: V2,
        hint: f64,
        doubts: &mut Doubts,
    ) -> Option<f64> {
        let f = |u: f64| {
            let j = self.jet_to(u, 3);
            (j.d1.dot(n), j.d2.dot(n), j.d3.dot(n))
        };
        let accept = |u: f64| self.normal(u).dot(n) > 0.0;
        if self.cert.is_some() {
            let end = |u: f64| (u, self.jet_to(u, 1).d1);
            if let Some(found) = self.normal_by_end_signs(end(lo), end(hi), n, hint) {
                return found;
            }
        }
        let form = self.cert.as_ref().map(|c| (&c.tangent, [n.x, n.y, 0.0]));
        self.solve(lo, hi, f, form, accept, Prefer::Low, hint, doubts)
    }

    /// [`View::point_with_normal_near`] on a monotone segment where the signs of `C′ · n` at
    /// the ends are known without evaluating there (`ends`: values of those signs, as from
    /// the ends' tangent angles): the tangent meets the direction exactly once inside.
    pub(crate) fn point_with_normal_between(
        &self,
        lo: f64,
        hi: f64,
        n: V2,
        ends: (f64, f64),
        hint: f64,
    ) -> Option<f64> {
        let f = |u: f64| {
            let j = self.jet_to(u, 3);
            (j.d1.dot(n), j.d2.dot(n), j.d3.dot(n))
        };
        let u = solve_in(f, (lo, hi), ends, self.point_tol, hint);
        (self.normal(u).dot(n) > 0.0).then_some(u)
    }

    /// [`View::point_with_normal_near`] with the tangents at the two ends given (`(u, C′(u))`,
    /// either order): a march keeps its section's far end at hand, so the ends need no
    /// evaluation.
    pub(crate) fn point_with_normal_from(
        &self,
        a: (f64, V2),
        b: (f64, V2),
        n: V2,
        hint: f64,
        doubts: &mut Doubts,
    ) -> Option<f64> {
        if self.cert.is_some() {
            if let Some(found) = self.normal_by_end_signs(a, b, n, hint) {
                return found;
            }
        }
        self.point_with_normal_near(a.0, b.0, n, hint, doubts)
    }

    /// Every caller asks on a monotone segment (curvature of one sign, certified by the
    /// isolated inflections; total turning below π, certified by the hodograph): there the
    /// tangent meets each direction at most once, so the signs of `C′ · n` at the two ends
    /// (`(u, C′(u))`, either order) decide, when both are trusted beyond their rounding bound.
    /// `None` when they are not.
    fn normal_by_end_signs(
        &self,
        a: (f64, V2),
        b: (f64, V2),
        n: V2,
        hint: f64,
    ) -> Option<Option<f64>> {
        let ((lo, d_lo), (hi, d_hi)) = if a.0 <= b.0 { (a, b) } else { (b, a) };
        let (fl, fh) = (d_lo.dot(n), d_hi.dot(n));
        let bound = |d1: V2| ulps(64.0) * d1.norm();
        if fl.abs() <= bound(d_lo) || fh.abs() <= bound(d_hi) {
            return None;
        }
        if (fl < 0.0) == (fh < 0.0) {
            return Some(None);
        }
        Some(self.point_with_normal_between(lo, hi, n, (fl, fh), hint))
    }

    /// `point-of-tangency(lo, hi, p)`: the point whose tangent line passes through `p`.
    pub(crate) fn point_of_tangency(
        &self,
        lo: f64,
        hi: f64,
        p: V2,
        prefer: Prefer,
        doubts: &mut Doubts,
    ) -> Option<f64> {
        // `p` at an end of the segment (two segments of a profile meeting at a corner): the
        // tangency there is `p` itself, a double root, and no other tangent line of a
        // monotone segment (turning by less than π, curved) passes through its own end point.
        if [lo, hi]
            .iter()
            .any(|&u| (self.point(u) - p).norm() <= SAME_CURVE_POINT * self.scale)
        {
            return None;
        }
        let f = |u: f64| {
            let j = self.jet_to(u, 3);
            let r = j.p - p;
            (
                r.cross(j.d1),
                r.cross(j.d2),
                j.d1.cross(j.d2) + r.cross(j.d3),
            )
        };
        if self.cert.is_some() {
            if let Some(found) = self.tangency_on_monotone(lo.min(hi), lo.max(hi), p, &f) {
                return found;
            }
        }
        // A − p × D = A + p_y Dₓ − pₓ D_y.
        let form = self.cert.as_ref().map(|c| (&c.tangency, [1.0, p.y, -p.x]));
        self.solve(lo, hi, f, form, |_| true, prefer, f64::NAN, doubts)
    }

    /// `point-on-ray(lo, hi, c)`: where the segment meets the ray from `c` along the unit
    /// vector `dir` (the inward normal at `c`); Newton starts at `hint` (NaN for none).
    // (The segment, the ray, the preference, the start and the doubts: each its own.)
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn point_on_ray(
        &self,
        lo: f64,
        hi: f64,
        c: V2,
        dir: V2,
        prefer: Prefer,
        hint: f64,
        doubts: &mut Doubts,
    ) -> Option<f64> {
        let v = dir.perp();
        let f = |u: f64| {
            let j = self.jet_to(u, 2);
            ((j.p - c).dot(v), j.d1.dot(v), j.d2.dot(v))
        };
        let accept = |u: f64| (self.point(u) - c).dot(dir) > 0.0;
        if self.cert.is_some() {
            if let Some(r) =
                self.ray_on_monotone(lo.min(hi), lo.max(hi), c, v, &f, &accept, prefer, hint)
            {
                return r;
            }
        }
        // (X − c w) · v = vₓ X + v_y Y − (c · v) w.
        let form = self
            .cert
            .as_ref()
            .map(|cc| (&cc.hom, [v.x, v.y, -c.dot(v)]));
        self.solve(lo, hi, f, form, accept, prefer, hint, doubts)
    }
}

impl View<'_> {
    /// point-of-tangency decided by signs of the curve itself on a monotone segment with
    /// turning below π (every caller asks on one), where a point lies on at most two tangent
    /// lines (Jia, Appendix B): trusted end values of `f = (C − p) × C′` of different signs
    /// leave exactly one point of tangency (the case inside Common-Tangent, §2.3); equal signs
    /// leave none or two, and none is certain when `p` lies in the region `R₁` (behind both end
    /// tangents, on the side away from the bending) or in `R₂` outside the triangle of the
    /// chord and the end tangents. `None` when these tests do not decide (the caller then
    /// counts roots on the symbolic form).
    fn tangency_on_monotone(
        &self,
        lo: f64,
        hi: f64,
        p: V2,
        f: &impl Fn(f64) -> (f64, f64, f64),
    ) -> Option<Option<f64>> {
        let (jl, jh) = (self.jet_to(lo, 1), self.jet_to(hi, 1));
        let trusted =
            |x: f64, q: V2, d: V2| x.abs() > ulps(64.0) * (q.norm() + p.norm()) * d.norm();
        let (fl, fh) = ((jl.p - p).cross(jl.d1), (jh.p - p).cross(jh.d1));
        if !(trusted(fl, jl.p, jl.d1) && trusted(fh, jh.p, jh.d1)) {
            return None;
        }
        if (fl < 0.0) != (fh < 0.0) {
            return Some(Some(solve_in(
                f,
                (lo, hi),
                (fl, fh),
                self.point_tol,
                f64::NAN,
            )));
        }
        // The bending direction: the side the tangent turns to (|Φ| < π).
        let turn = jl.d1.cross(jh.d1);
        if !trusted(turn, jl.d1, jh.d1) {
            return None;
        }
        let (na, nb) = (jl.d1.unit().perp(), jh.d1.unit().perp());
        let (va, vb) = if turn > 0.0 { (na, nb) } else { (-na, -nb) };
        let (da, db) = ((p - jl.p).dot(va), (p - jh.p).dot(vb));
        if !(trusted(da, jl.p, va) && trusted(db, jh.p, vb)) {
            return None;
        }
        if da < 0.0 && db < 0.0 {
            // R₁: on no tangent line.
            return Some(None);
        }
        if da > 0.0 && db > 0.0 {
            // R₀ ∪ R₂: R₂ for certain outside the triangle of α(a), α(b) and the meet of the
            // end tangents.
            let chord = jh.p - jl.p;
            let apex = jl.p + jl.d1 * (chord.cross(jh.d1) / jl.d1.cross(jh.d1));
            // Each side's orientation of p, trusted beyond its rounding.
            let side = |a: V2, b: V2| {
                let x = (b - a).cross(p - a);
                let bound = ulps(64.0) * (b - a).norm() * (p.norm() + a.norm());
                (x.abs() > bound).then_some(x > 0.0)
            };
            let sides = [side(jl.p, apex), side(apex, jh.p), side(jh.p, jl.p)];
            if sides.iter().all(Option::is_some) {
                let inside = sides.iter().all(|&x| x == sides[0]);
                if !inside {
                    return Some(None);
                }
            }
        }
        None
    }

    /// point-on-ray decided by signs of the curve itself on a monotone segment (every caller
    /// asks on one): `f = (C − c) · v` has the derivative `C′ · v`, which vanishes at most
    /// once there (the tangent meets each direction once); that point (found by
    /// point-with-normal, itself decided by end signs) splits the segment into at most two
    /// stretches on which `f` is monotone, and the trusted signs of `f` at their ends decide
    /// each. `None` when some sign is within its rounding bound (the caller then decides).
    #[allow(clippy::too_many_arguments)]
    fn ray_on_monotone(
        &self,
        lo: f64,
        hi: f64,
        c: V2,
        v: V2,
        f: &impl Fn(f64) -> (f64, f64, f64),
        accept: &impl Fn(f64) -> bool,
        prefer: Prefer,
        hint: f64,
    ) -> Option<Option<f64>> {
        let eps = ulps(64.0);
        let (jl, jh) = (self.jet_to(lo, 1), self.jet_to(hi, 1));
        let (gl, gh) = (jl.d1.dot(v), jh.d1.dot(v));
        if gl.abs() <= eps * jl.d1.norm() || gh.abs() <= eps * jh.d1.norm() {
            return None;
        }
        let mut cuts: SmallVec<[(f64, V2); 3]> = SmallVec::new();
        cuts.push((lo, jl.p));
        if (gl < 0.0) != (gh < 0.0) {
            let g = |u: f64| {
                let j = self.jet_to(u, 3);
                (j.d1.dot(v), j.d2.dot(v), j.d3.dot(v))
            };
            let ue = solve_in(g, (lo, hi), (gl, gh), self.point_tol, f64::NAN);
            cuts.push((ue, self.point(ue)));
        }
        cuts.push((hi, jh.p));
        let val = |p: V2| (p - c).dot(v);
        let trusted = |p: V2| val(p).abs() > eps * (p.norm() + c.norm());
        if !cuts.iter().all(|&(_, p)| trusted(p)) {
            return None;
        }
        let n = cuts.len() - 1;
        for k in 0..n {
            let k = if prefer == Prefer::Low { k } else { n - 1 - k };
            let ((x0, p0), (x1, p1)) = (cuts[k], cuts[k + 1]);
            let (f0, f1) = (val(p0), val(p1));
            if (f0 < 0.0) != (f1 < 0.0) {
                let u = solve_in(f, (x0, x1), (f0, f1), self.point_tol, hint);
                if accept(u) {
                    return Some(Some(u));
                }
            }
        }
        Some(None)
    }
}

/// Jia's existence test (different signs at the ends) and a bracketed Newton solve.
#[allow(clippy::too_many_arguments)]
fn sampled(
    lo: f64,
    hi: f64,
    flo: f64,
    fhi: f64,
    f: &impl Fn(f64) -> (f64, f64, f64),
    accept: &impl Fn(f64) -> bool,
    tol: f64,
    hint: f64,
) -> Option<f64> {
    let u = if flo == 0.0 {
        lo
    } else if fhi == 0.0 {
        hi
    } else if (flo < 0.0) != (fhi < 0.0) {
        solve_in(f, (lo, hi), (flo, fhi), tol, hint)
    } else if flo.abs() <= END_ZERO * fhi.abs() {
        lo
    } else if fhi.abs() <= END_ZERO * flo.abs() {
        hi
    } else {
        return None;
    };
    accept(u).then_some(u)
}

/// Newton steps of a cluster's root polished on the curve, at most.
const CLUSTER_POLISH_STEPS: usize = 8;

/// A few Newton steps kept inside `[lo, hi]`.
fn polish(f: &impl Fn(f64) -> (f64, f64, f64), u: f64, lo: f64, hi: f64) -> f64 {
    let value_and_slope = |x| {
        let (value, slope, _) = f(x);
        (value, slope)
    };
    newton_within(value_and_slope, u, (lo, hi), CLUSTER_POLISH_STEPS)
}

/// A value at an end (relative to the two end values) within rounding of zero: a root there
/// that escaped isolation.
const END_ROOT: f64 = 1e-13;

/// Jia's sampled test: an end value this small beside the other is a root at that end (the
/// primitive touches zero there; its sign is rounding).
const END_ZERO: f64 = 1e-12;

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::driver::dissect;
    use crate::prepare::tests::{as_given, star_curve};
    use crate::Options;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

        /// Where the end-sign and region tests decide point-of-tangency on a monotone piece of
        /// a random closed B-spline, dense sampling of `(C − p) × C′` agrees: no sign change
        /// where none is claimed, exactly one (at the returned point) where one is.
        #[test]
        fn tangency_decisions_match_sampling(
            deg in 3usize..=5,
            seed in proptest::collection::vec(0.0f64..1.0, 12..=30),
            w in proptest::collection::vec(0.5f64..2.0, 15),
            rational in any::<bool>(),
            points in proptest::collection::vec((-1.5f64..1.5, -1.5f64..1.5), 6),
        ) {
            let c = star_curve(deg, &seed, rational.then_some(&w[..]));
            let given = as_given(&c);
            let Ok(prep) = dissect(given.source(true), &Options::default(), None, 0) else {
                return Ok(());
            };
            let v = &prep.value.view;
            for piece in prep.value.pieces.iter().filter(|q| !q.flat) {
                for &(x, y) in &points {
                    let p = V2::new(x, y);
                    let f = |u: f64| {
                        let j = v.jet_to(u, 3);
                        let r = j.p - p;
                        (r.cross(j.d1), r.cross(j.d2), j.d1.cross(j.d2) + r.cross(j.d3))
                    };
                    let Some(found) = v.tangency_on_monotone(piece.lo, piece.hi, p, &f) else {
                        continue;
                    };
                    let n = 2000;
                    let mut changes = Vec::new();
                    let mut last = f(piece.lo).0;
                    for k in 1..=n {
                        let u = piece.lo + (piece.hi - piece.lo) * k as f64 / n as f64;
                        let val = f(u).0;
                        if (val < 0.0) != (last < 0.0) {
                            changes.push(u);
                        }
                        last = val;
                    }
                    let h = 2.0 * (piece.hi - piece.lo) / n as f64;
                    match found {
                        None => prop_assert!(changes.is_empty(), "{p:?}: tangents at {changes:?}"),
                        Some(u) => {
                            prop_assert_eq!(changes.len(), 1, "{:?}: tangents at {:?}", p, changes);
                            testkit::prop_assert_near!(changes[0], u, h, "{u} vs {changes:?}");
                        }
                    }
                }
            }
        }
    }
}
