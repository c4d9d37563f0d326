//! No pair on a stretch of a section where θ has one sign at both ends and the rates of the
//! two radii of curvature have the right sign all along (the maximum principle): this settles
//! stretches where θ has an extremum, which no proof of monotonicity reaches.

use crate::pairs::Pair;
use numeric::Interval;

/// No pair lies on `p` between the opposite points `a` and `b`, where θ is `th.0` and `th.1`,
/// of one sign beyond the noise: so it stays, by the maximum principle.
///
/// In the tangent angle ψ of `S` the tangential offset `G = r · T = −|r| sin θ` satisfies
/// `G″ + G = −(ρ′(s) + ρ′(t))`, the rates at which the two radii of curvature change with ψ
/// (`r′ = −(ρ(s) + ρ(t)) T`, `T′ = N`, `N′ = −T`). On a stretch turning by less than π, with
/// `G` of one sign at both ends and `G″ + G` of the other sign (or zero) all along, `G` keeps
/// its sign throughout: the maximum principle of `d²/dψ² + 1`, for which `cos(ψ − ψ_mid)` is
/// positive there. The rates are bounded over the two arcs apart
/// ([`crate::view::View::arc_rho_rate`]). This settles stretches where θ has an extremum,
/// which no proof of monotonicity reaches (a march used to cross them).
pub(crate) fn clear_by_rates(p: &Pair, a: (f64, f64), b: (f64, f64), th: (f64, f64)) -> bool {
    let positive = th.0 > 0.0;
    if (th.1 > 0.0) != positive || th.0 == 0.0 || th.1 == 0.0 {
        return false;
    }
    // Needed: ρ′(s) + ρ′(t) of the sign opposite to θ's. In terms of σ = ±1 with that sign:
    // σ (ρ′(s) + ρ′(t)) > 0. First at the ends (cheap, from the jets), then over the arcs,
    // S's first: what T's rates are at least at the ends may already rule it out.
    let sigma = if positive { -1.0 } else { 1.0 };
    let rates_s = [a.0, b.0].map(|u| rho_rate_at(p.vs, u, p.s_convex));
    let rates_t = [a.1, b.1].map(|u| rho_rate_at(p.vt, u, p.t_convex));
    // Both radii unbounded at one end (two inflections facing each other): their rates'
    // sum is 0/0 there, and its bounds cannot have a sign.
    let wild = |x: f64| x.abs() >= 1e8 * p.vs.scale.max(p.vt.scale) || x.is_nan();
    if (0..2).any(|i| wild(rates_s[i]) && wild(rates_t[i])) {
        return false;
    }
    let at_ends = [rates_s[0] + rates_t[0], rates_s[1] + rates_t[1]];
    // (NaN, as at two inflections facing each other, fails too.)
    if !at_ends.into_iter().all(|f| sigma * f > 0.0) {
        return false;
    }
    // The least of σρ′ over an arc: its range's end on the side of −σ.
    let least = |r: Interval| if sigma > 0.0 { r.lo } else { -r.hi };
    // (T's least is at most its value at either end.)
    let cap_t = (sigma * rates_t[0]).min(sigma * rates_t[1]);
    // (NaN fails too.)
    let above_zero = |x: f64| x > 0.0;
    // From coarse cells first; where they fail, from fine ones (built on first use: most
    // stretches need none).
    let proven = [false, true].into_iter().any(|fine| {
        let Some(fs) = p.vs.arc_rho_rate(a.0, b.0, p.s_convex, fine) else {
            return false;
        };
        if !above_zero(least(fs) + cap_t) {
            return false;
        }
        let Some(ft) = p.vt.arc_rho_rate(a.1, b.1, p.t_convex, fine) else {
            return false;
        };
        // (NaN, from unbounded rates of both signs, fails too.)
        least(fs) + least(ft) > 0.0
    });
    proven && p.is_clear(a.0, a.1, th.0) && p.is_clear(b.0, b.1, th.1)
}

/// `dρ/dψ = −κ′ / (κ³ |C′|)` at `u` on an arc of positive curvature when `convex` (else
/// negative). At an inflection ending the arc it is infinite, of the sign of its limit from
/// inside the arc: κ is taken of the arc's sign there (rounding may give it the other one),
/// and a zero of that sign gives the quotient its sign. NaN where κ′ is zero too.
fn rho_rate_at(v: &crate::view::View, u: f64, convex: bool) -> f64 {
    let j = v.jet_to(u, 3);
    let k = match j.curvature() {
        k if convex && k <= 0.0 => 0.0,
        k if !convex && k >= 0.0 => -0.0,
        k => k,
    };
    -j.curvature_rate() / (k * k * k * j.d1.norm())
}

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
    /// Stretches proven free of pairs by the rates of the radii of curvature, and stretches
    /// whose enclosure of those rates was checked.
    static CLEARED: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    static ENCLOSED: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

    /// `dρ/dψ` by central differences of ρ against the tangent angle ψ (jets of order two
    /// only: independent of the formula in κ′).
    fn rho_rate_by_differences(v: &crate::view::View, u: f64, h: f64) -> f64 {
        let at = |x: f64| {
            let j = v.jet_to(x, 2);
            (1.0 / j.curvature(), j.d1.angle())
        };
        let ((r0, a0), (r1, a1)) = (at(u - h), at(u + h));
        let da = curve::wrap_pi(a1 - a0);
        (r1 - r0) / da
    }

    /// A random closed B-spline or NURBS (a star of degree `deg` from `seed`, rational with
    /// the weights `w` when `rational`), or, given `bumps = (ε, m)`, a curve with convexities
    /// on its circle form.
    #[derive(Debug, Clone)]
    struct RandomCurve {
        deg: usize,
        seed: Vec<f64>,
        w: Vec<f64>,
        rational: bool,
        bumps: Option<(f64, u32)>,
    }

    prop_compose! {
        /// The curves the rate properties run on.
        fn random_curve()(
            deg in 3usize..=5,
            seed in proptest::collection::vec(0.0f64..1.0, 12..=30),
            w in proptest::collection::vec(0.5f64..2.0, 15),
            rational in any::<bool>(),
            bumps in proptest::option::of((0.1f64..0.6, 3u32..=6)),
        ) -> RandomCurve {
            RandomCurve { deg, seed, w, rational, bumps }
        }
    }

    /// Runs `check` on the dissection of `curve`; nothing when the curve is rejected.
    fn on_random_curve(
        curve: &RandomCurve,
        check: impl FnOnce(&crate::driver::Dissected) -> Result<(), TestCaseError>,
    ) -> Result<(), TestCaseError> {
        let RandomCurve {
            deg,
            seed,
            w,
            rational,
            bumps,
        } = curve;
        let star = star_curve(*deg, seed, rational.then_some(&w[..]));
        let bumpy = bumps.map(|(eps, m)| curve::shapes::Convexities::new(4.0, eps, m).unwrap());
        let c: &dyn curve::PlaneCurve = match &bumpy {
            Some(b) => b,
            None => &star,
        };
        // (The curve with convexities runs on its circle form.)
        let given = as_given(c);
        match dissect(given.source(true), &Options::default(), None, 0) {
            Ok(prep) => check(&prep.value),
            Err(_) => Ok(()),
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 120, ..ProptestConfig::default() })]

        /// The enclosure of dρ/dψ over random stretches of the monotone pieces of random
        /// closed B-splines and NURBS, and of curves with convexities on their circle form,
        /// holds the rate found by differences at points inside.
        fn rho_rate_enclosure_holds_differences(
            curve in random_curve(),
            picks in proptest::collection::vec((0.0f64..1.0, 0.01f64..1.0, any::<bool>()), 3),
        ) {
            on_random_curve(&curve, |prep| {
                let v = &prep.view;
                for piece in &prep.pieces {
                    for &(f, len, fine) in &picks {
                        let x0 = piece.lo + f * (piece.hi - piece.lo);
                        let x1 = (x0 + len * (piece.hi - piece.lo)).min(piece.hi);
                        let Some(r) = v.arc_rho_rate(x0, x1, piece.convex, fine) else {
                            continue;
                        };
                        ENCLOSED.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let h = 1e-6 * (piece.hi - piece.lo);
                        for k in 1..20 {
                            let u = x0 + (x1 - x0) * k as f64 / 20.0;
                            if u - h <= x0 || u + h >= x1 {
                                continue;
                            }
                            let fd = rho_rate_by_differences(v, u, h);
                            let slack = 1e-4 * (fd.abs() + 1.0);
                            prop_assert!(
                                fd >= r.lo - slack && fd <= r.hi + slack,
                                "dρ/dψ = {fd} at {u} outside {r:?} over [{x0}, {x1}]"
                            );
                        }
                    }
                }
                Ok(())
            })?;
        }

        /// Wherever θ is proven of one sign by the rates on random stretches of random pairs,
        /// dense sampling (opposite points by bisection) finds it of that sign.
        fn cleared_by_rates_stretches_hold_no_pair(
            curve in random_curve(),
            picks in proptest::collection::vec((0.0f64..1.0, 0.02f64..1.0), 4),
        ) {
            on_random_curve(&curve, |prep| {
                let (v, pieces) = (&prep.view, &prep.pieces);
                // (The doubts met are not what is tested here.)
                let mut ledger = Ledger::new();
                for i in 0..pieces.len() {
                    for j in i + 1..pieces.len() {
                        let Some(pair) = opposite_pair(v, &pieces[i], v, &pieces[j], &mut ledger) else {
                            continue;
                        };
                        let opp = |s: f64| match s {
                            s if s == pair.sa => pair.ta,
                            s if s == pair.sb => pair.tb,
                            s => opposite_by_bisection(&pair, s),
                        };
                        for &(f, len) in [(0.0, 1.0)].iter().chain(&picks) {
                            let s0 = pair.sa + f * (pair.sb - pair.sa);
                            let s1 = (s0 + len * (pair.sb - pair.sa)).min(pair.sb);
                            if s1 <= s0 {
                                continue;
                            }
                            let (a, b) = ((s0, opp(s0)), (s1, opp(s1)));
                            let th = (pair.sin_theta(a.0, a.1), pair.sin_theta(b.0, b.1));
                            if !clear_by_rates(&pair, a, b, th) {
                                continue;
                            }
                            CLEARED.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                            for k in 0..=60 {
                                let s = s0 + (s1 - s0) * k as f64 / 60.0;
                                let st = pair.sin_theta(s, opp(s));
                                prop_assert!(
                                    st != 0.0 && (st > 0.0) == (th.0 > 0.0),
                                    "sin θ = {st} at {s}, proven of the sign of {} on [{s0}, {s1}]",
                                    th.0
                                );
                            }
                        }
                    }
                }
                Ok(())
            })?;
        }
    }

    /// Ends of monotone pieces on inflections checked by the property below.
    static INFLECTION_ENDS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

    proptest! {
        #![proptest_config(ProptestConfig { cases: 120, ..ProptestConfig::default() })]

        /// At the end of a monotone piece on an inflection, dρ/dψ has the sign of its limit
        /// from inside the piece, whatever sign rounding leaves κ there.
        fn rate_at_inflection_ends_has_its_limit_sign(
            curve in random_curve(),
        ) {
            on_random_curve(&curve, |prep| {
                let v = &prep.view;
                for piece in &prep.pieces {
                    let len = piece.hi - piece.lo;
                    let typical = v.jet_to(piece.lo + 0.5 * len, 2).curvature().abs();
                    for (end, inward) in [(piece.lo, 1.0), (piece.hi, -1.0)] {
                        if v.jet_to(end, 2).curvature().abs() > 1e-9 * typical {
                            continue;
                        }
                        let inside = rho_rate_at(v, end + inward * 1e-4 * len, piece.convex);
                        if !inside.is_finite() || inside.abs() < 1e-6 {
                            continue;
                        }
                        INFLECTION_ENDS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let at = rho_rate_at(v, end, piece.convex);
                        prop_assert!(
                            at.signum() == inside.signum() && at.abs() >= inside.abs(),
                            "{at} at the inflection {end}, {inside} inside (convex {})",
                            piece.convex
                        );
                    }
                }
                Ok(())
            })?;
        }
    }

    /// Runs the property and checks that it is not vacuous.
    #[test]
    fn rates_at_inflection_ends_have_their_limit_signs() {
        rate_at_inflection_ends_has_its_limit_sign();
        let n = INFLECTION_ENDS.load(std::sync::atomic::Ordering::Relaxed);
        // (Measured: about 1,700.)
        assert!(n >= 500, "{n} inflection ends");
    }

    /// Runs both properties and checks that neither is vacuous.
    #[test]
    fn rates_are_enclosed_and_clear_stretches_hold_no_pair() {
        rho_rate_enclosure_holds_differences();
        cleared_by_rates_stretches_hold_no_pair();
        let (e, c) = (
            ENCLOSED.load(std::sync::atomic::Ordering::Relaxed),
            CLEARED.load(std::sync::atomic::Ordering::Relaxed),
        );
        // (Measured: about 3,300 and 2,600.)
        assert!(e >= 1000 && c >= 500, "enclosed {e}, cleared {c}");
    }
}
