//! Root isolation against independent oracles: polynomials built from known roots (including
//! clusters and double roots), and dense sampling of random B-splines.
#![allow(clippy::unwrap_used)]

mod common;
use bspline::roots::{find_roots, find_roots_in, find_roots_periodic, Root, RootKind, RootOptions};
use bspline::{BSpline, Piecewise};
use common::*;
use proptest::prelude::*;

/// c · Π (u − rᵢ) on [a, b], built exactly as a product of linear Bézier factors.
fn from_roots(roots: &[f64], c: f64, a: f64, b: f64) -> BSpline {
    let knots = vec![a, a, b, b];
    let mut f = BSpline::new(0, vec![a, b], 1, vec![c]).unwrap();
    for &r in roots {
        let lin = BSpline::new(1, knots.clone(), 1, vec![a - r, b - r]).unwrap();
        f = f.mul(&lin).unwrap();
    }
    f
}

fn covers(r: &Root, x: f64, slack: f64) -> bool {
    r.bracket.0 - slack <= x && x <= r.bracket.1 + slack
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// Well-separated simple roots: all found, all certified, none extra, accurate.
    #[test]
    fn separated_roots_are_all_certified(
        raw in prop::collection::vec(0.0f64..1.0, 1..13),
        c in prop_oneof![-100.0f64..-0.01, 0.01f64..100.0],
    ) {
        let mut rs = raw.clone();
        rs.sort_by(f64::total_cmp);
        rs.dedup_by(|x, y| (*x - *y).abs() < 0.02);
        let f = from_roots(&rs, c, -0.01, 1.01);
        let found = find_roots(&f, -0.01, 1.01, &RootOptions::default()).unwrap();
        prop_assert_eq!(found.len(), rs.len(), "{:?} vs {:?}", found, rs);
        for (r, x) in found.iter().zip(&rs) {
            prop_assert!(r.certified && r.kind == RootKind::Simple);
            testkit::prop_assert_near!(r.u, x, 1e-9, "{} vs {}", r.u, x);
            prop_assert!(covers(r, *x, 1e-10));
        }
    }

    /// Near-double and exact double roots are never lost: each true root lies in a reported
    /// bracket (a certified simple root or a cluster), and far roots stay certified.
    #[test]
    fn clustered_roots_are_never_dropped(
        r0 in 0.1f64..0.9,
        log_gap in -15.0f64..-2.0,
        double in any::<bool>(),
        others in prop::collection::vec(0.0f64..1.0, 0..5),
    ) {
        let gap = if double { 0.0 } else { 10f64.powf(log_gap) };
        let mut rs = vec![r0, r0 + gap];
        for o in others {
            if (o - r0).abs() > 0.05 { rs.push(o); }
        }
        rs.sort_by(f64::total_cmp);
        let f = from_roots(&rs, 1.0, -0.01, 1.01);
        let found = find_roots(&f, -0.01, 1.01, &RootOptions::default()).unwrap();
        for &x in &rs {
            // A double root's location is only determined to about sqrt(eps).
            prop_assert!(found.iter().any(|r| covers(r, x, 1e-7)), "root {} lost in {:?}", x, found);
        }
        for r in &found {
            prop_assert!(rs.iter().any(|&x| covers(r, x, 1e-7)), "invented {:?}", r);
        }
    }

    /// Random B-splines against dense sampling: every sign change of the samples lies in a
    /// reported bracket, and every certified root is a real sign change.
    #[test]
    fn random_splines_match_dense_sampling(f in spline(7, 25, 1)) {
        let (a, b) = f.domain();
        let found = find_roots(&f, a, b, &RootOptions::default()).unwrap();
        let scale = f.max_abs_coef();
        let n = 4000;
        let xs: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
        let vs: Vec<f64> = xs.iter().map(|&x| f.eval_scalar(x)).collect();
        let noise = 1e-12 * scale;
        for i in 0..n {
            if vs[i].abs() > noise && vs[i + 1].abs() > noise && (vs[i] > 0.0) != (vs[i + 1] > 0.0) {
                prop_assert!(found.iter().any(|r| r.bracket.1 >= xs[i] && r.bracket.0 <= xs[i + 1]),
                    "sign change in [{}, {}] missed: {:?}", xs[i], xs[i + 1], found);
            }
        }
        for r in found.iter().filter(|r| r.certified) {
            let h = 1e-6 * (b - a);
            let (lo, hi) = ((r.u - h).max(a), (r.u + h).min(b));
            let (fl, fh) = (f.eval_scalar(lo), f.eval_scalar(hi));
            if fl.abs() > noise && fh.abs() > noise {
                prop_assert!((fl > 0.0) != (fh > 0.0), "certified root {:?} without sign change", r);
            }
            // The residual is what the slope and the bracket width allow.
            let mut d = [0.0; 2];
            f.eval_derivs(r.u, 1, &mut d);
            let width = r.bracket.1 - r.bracket.0;
            prop_assert!(d[0].abs() <= d[1].abs() * (width + 1e-12) + 1e3 * f64::EPSILON * scale,
                "residual {} at {:?}", d[0], r);
        }
        for w in found.windows(2) {
            prop_assert!(w[0].bracket.1 <= w[1].bracket.0, "overlapping brackets {:?}", w);
        }
    }
}

/// `(u − r)(c + m (u − r)²)` on [0, 1] (`c` and `m` of one sign: one root): a simple root
/// whose function's coefficients are up to `m / c` times its slope there, so that it is within
/// their error bound on a bracket far wider than the tolerance.
fn steep_around(r: f64, c: f64, m: f64) -> BSpline {
    let line = from_roots(&[r], c, 0.0, 1.0).elevate(2);
    line.add(&from_roots(&[r, r, r], m, 0.0, 1.0)).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

    /// A simple root that rounding hides from the control polygon is still proven (by trusted
    /// values of opposite signs about it and a derivative of one sign between them) and
    /// brackets the exact root; one that hides two roots never is.
    #[test]
    fn roots_within_rounding_are_proven_when_simple(
        r in 0.2f64..0.8,
        c in 0.01f64..10.0,
        falling in any::<bool>(),
        log_m in 6.0f64..12.0,
        log_gap in -14.0f64..-10.0,
    ) {
        let sign = if falling { -1.0 } else { 1.0 };
        let (c, m) = (sign * c, sign * 10f64.powf(log_m));
        let f = steep_around(r, c, m);
        let found = find_roots(&f, 0.0, 1.0, &RootOptions::default()).unwrap();
        prop_assert_eq!(found.len(), 1, "{:?}", found);
        prop_assert!(found[0].certified && found[0].kind == RootKind::Simple, "{:?}", found);
        prop_assert!(covers(&found[0], r, 0.0), "{} not in {:?}", r, found);
        // Two roots `gap` apart, hidden by the same rounding: never one proven root.
        let gap = 10f64.powf(log_gap);
        let two = from_roots(&[r, r + gap], c, 0.0, 1.0)
            .elevate(1)
            .add(&from_roots(&[r, r + gap, r], m, 0.0, 1.0))
            .unwrap();
        let found = find_roots(&two, 0.0, 1.0, &RootOptions::default()).unwrap();
        for root in &found {
            let both = covers(root, r, 0.0) && covers(root, r + gap, 0.0);
            prop_assert!(!(both && root.certified && root.kind == RootKind::Simple), "{:?}", found);
        }
        for x in [r, r + gap] {
            prop_assert!(found.iter().any(|root| covers(root, x, 1e-9)), "{} lost in {:?}", x, found);
        }
    }
}

/// A function that jumps at a break (degree 1, a double knot) with a root within rounding of
/// the break: one proven root where its sign is declared continuous there, a cluster where it
/// is not (a sign change at a jump is no root).
#[test]
fn a_root_at_a_jump_is_proven_only_where_the_sign_is_continuous() {
    // The derivative of a quadratic with a double knot at 1/2 (C0 there): linear pieces
    // declared to jump at 1/2. Left from −1 to `left`, right from `right` to 1.
    let derivative = |left: f64, right: f64| {
        let knots = vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0];
        let (c1, c2) = (-0.25, -0.25 + 0.25 * left);
        let c3 = c2 + 0.25 * right;
        let g = BSpline::new(2, knots, 1, vec![0.0, c1, c2, c3, c3 + 0.25]).unwrap();
        Piecewise::from_bspline(&g).derivative()
    };
    // 2^-52 on both sides: its root a few 1e-17 short of the break, within rounding of it.
    let tiny = f64::EPSILON;
    let f = derivative(tiny, tiny);
    assert!(f.continuity(1) < 0);
    let plain = find_roots_in(&f, 0.0, 1.0, &RootOptions::default()).unwrap();
    assert_eq!(plain.len(), 1, "{plain:?}");
    assert_eq!(plain[0].kind, RootKind::Cluster, "{plain:?}");
    let opts = RootOptions::default().sign_continuous(true);
    let proven = find_roots_in(&f, 0.0, 1.0, &opts).unwrap();
    assert_eq!(proven.len(), 1, "{proven:?}");
    assert!(
        proven[0].certified && proven[0].kind == RootKind::Simple,
        "{proven:?}"
    );
    assert!(covers(&proven[0], 0.5, 0.0), "{proven:?}");
    // A sign change at the jump itself: no root, never a proven one.
    let g = derivative(-tiny, 2.0 * tiny);
    let found = find_roots_in(&g, 0.0, 1.0, &RootOptions::default()).unwrap();
    assert!(
        found
            .iter()
            .all(|r| !(r.certified && r.kind == RootKind::Simple)),
        "{found:?}"
    );
}

#[test]
fn degree_15_bezier_with_15_roots() {
    let rs: Vec<f64> = (0..15).map(|i| (i as f64 + 0.5) / 15.0).collect();
    let f = from_roots(&rs, 1.0, 0.0, 1.0);
    assert_eq!(f.degree(), 15);
    let found = find_roots(&f, 0.0, 1.0, &RootOptions::default()).unwrap();
    assert_eq!(found.len(), 15);
    let scale = f.max_abs_coef();
    for (r, x) in found.iter().zip(&rs) {
        assert!(r.certified);
        // Forward error = backward error (rounding of the coefficients) / |f'(root)|.
        let mut d = [0.0; 2];
        f.eval_derivs(*x, 1, &mut d);
        let limit = 1e-13 + 64.0 * 16.0 * f64::EPSILON * scale / d[1].abs();
        testkit::assert_near!(r.u, x, limit, "{} vs {} (limit {limit:e})", r.u, x);
    }
}

#[test]
fn roots_at_the_ends_and_the_seam() {
    // Root exactly at both ends of [0, 1].
    let f = from_roots(&[0.0, 0.5, 1.0], 1.0, 0.0, 1.0);
    let found = find_roots(&f, 0.0, 1.0, &RootOptions::default()).unwrap();
    for x in [0.0, 0.5, 1.0] {
        assert!(found.iter().any(|r| covers(r, x, 1e-12)), "{x}: {found:?}");
    }
    // A periodic function with a simple zero at the seam: reported once.
    let g = BSpline::periodic(3, 1, vec![0.0, 1.0, 2.0, 1.0, 0.0, -1.0, -2.0, -1.0]).unwrap();
    let v0 = g.eval_scalar(0.0);
    let g = g.map_points(1, |c, o| o[0] = c[0] - v0);
    let found = find_roots_periodic(&g, &RootOptions::default()).unwrap();
    let (a, b) = g.domain();
    let seam = found
        .iter()
        .filter(|r| r.u <= a + 1e-9 || r.u >= b - 1e-9)
        .count();
    assert_eq!(seam, 1, "{found:?}");
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found.iter().all(|r| r.certified));
}

#[test]
fn zero_function_is_one_cluster() {
    let f = BSpline::clamped_uniform(3, 1, vec![0.0; 8]).unwrap();
    let found = find_roots(&f, 0.0, 1.0, &RootOptions::default()).unwrap();
    assert_eq!(found.len(), 1);
    assert_eq!(found[0].kind, RootKind::Cluster);
    assert_eq!(found[0].bracket, (0.0, 1.0));
}

#[test]
fn bad_input_is_an_error() {
    let f = BSpline::clamped_uniform(2, 2, vec![0.0; 8]).unwrap();
    assert!(find_roots(&f, 0.0, 1.0, &RootOptions::default()).is_err());
    let g = BSpline::clamped_uniform(2, 1, vec![1.0, -1.0, 1.0]).unwrap();
    assert!(find_roots(&g, 0.5, 2.0, &RootOptions::default()).is_err());
    assert!(find_roots(&g, 0.0, 1.0, &RootOptions::default().tolerance(f64::NAN)).is_err());
}

/// The exact zeros of the piecewise-linear function with `values` at `knots`, on `[a, b]`: a
/// sorted list of closed intervals (points where the function crosses zero; stretches where two
/// consecutive values are zero).
fn polyline_zeros(knots: &[f64], values: &[f64], a: f64, b: f64) -> Vec<(f64, f64)> {
    use common::exact::{f, q};
    let mut out = Vec::new();
    for k in 0..knots.len() - 1 {
        let (x0, x1, v0, v1) = (knots[k], knots[k + 1], values[k], values[k + 1]);
        let zero = if v0 == 0.0 && v1 == 0.0 {
            Some((x0, x1))
        } else if (v0 <= 0.0) != (v1 <= 0.0) || v0 == 0.0 || v1 == 0.0 {
            // (Exactly, then rounded: x0 + (x1 − x0) v0 / (v0 − v1).)
            let x = q(x0) + (q(x1) - q(x0)) * q(v0) / (q(v0) - q(v1));
            Some((f(&x), f(&x)))
        } else {
            None
        };
        if let Some((lo, hi)) = zero {
            if hi >= a && lo <= b {
                out.push((lo.max(a), hi.min(b)));
            }
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    /// Piecewise-linear functions (the cone and foot-point functions of straight segments),
    /// with zeros exactly at knots and at the search's ends as often as inside: every exact
    /// zero lies in a reported bracket, every bracket holds one or lies within the tolerance of
    /// one, and a certified root is the exact one.
    #[test]
    fn straight_pieces_lose_no_zero_and_add_none(
        gaps in prop::collection::vec(0.05f64..1.0, 1..6),
        raw in prop::collection::vec((0usize..4, -1.0f64..1.0), 6),
        cut in (0.0f64..0.5, 0.5f64..1.0),
        whole in any::<bool>(),
    ) {
        let mut knots = vec![0.0];
        for g in &gaps {
            knots.push(knots[knots.len() - 1] + g);
        }
        let n = knots.len();
        // A zero a quarter of the time; small values a quarter.
        let values: Vec<f64> = raw[..n]
            .iter()
            .map(|&(kind, v)| match kind {
                0 => 0.0,
                1 => v * 1e-3,
                _ => v,
            })
            .collect();
        let mut full = vec![knots[0]];
        full.extend_from_slice(&knots);
        full.push(knots[n - 1]);
        let f = BSpline::new(1, full, 1, values.clone()).unwrap();
        let end = knots[n - 1];
        let (a, b) = if whole { (0.0, end) } else { (cut.0 * end, cut.1 * end) };
        let opts = RootOptions::default();
        let found = find_roots(&f, a, b, &opts).unwrap();
        let exact = polyline_zeros(&knots, &values, a, b);
        let slack = 1e-15 * end;
        for &(lo, hi) in &exact {
            for x in [lo, 0.5 * (lo + hi), hi] {
                prop_assert!(found.iter().any(|r| covers(r, x, slack)), "{x} lost: {found:?}");
            }
        }
        for r in &found {
            let near = exact.iter().any(|&(lo, hi)| {
                r.bracket.1 >= lo - opts.tol && r.bracket.0 <= hi + opts.tol
            });
            prop_assert!(near, "{r:?} holds no zero of {exact:?}");
            if r.certified {
                let at = exact.iter().any(|&(lo, hi)| lo - 1e-12 <= r.u && r.u <= hi + 1e-12);
                prop_assert!(at, "{r:?} is not at a zero of {exact:?}");
            }
        }
    }
}
