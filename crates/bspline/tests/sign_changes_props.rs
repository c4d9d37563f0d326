//! Sign changes against an independent oracle: the signs of the function sampled densely (and
//! more densely where the two disagree), on random splines built from known parts: simple roots,
//! double roots (no sign change), flat stretches, jumps at knots of full multiplicity, on open,
//! clamped closed and periodic domains.
#![allow(clippy::unwrap_used)]

use bspline::roots::{sign_changes, RootOptions, SignChangeKind, SignChanges};
use bspline::BSpline;
use proptest::prelude::*;

/// Samples over the domain (one period on a closed one).
const SAMPLES: usize = 4000;

/// The function `u − r` on `[a, b]`.
fn linear(r: f64, a: f64, b: f64) -> BSpline {
    BSpline::new(1, vec![a, a, b, b], 1, vec![a - r, b - r]).unwrap()
}

/// The sign of a value, 0 within `noise` of zero.
fn sign(v: f64, noise: f64) -> i32 {
    if v > noise {
        1
    } else if v < -noise {
        -1
    } else {
        0
    }
}

/// What the search reports as sign changes: its changes and the flats across which the sign
/// changes, as sorted parameters, shifted into `(first, first + period]` on a closed domain.
fn reported(s: &SignChanges, closed: bool, first: f64, period: f64) -> Vec<f64> {
    let mut v: Vec<f64> = s
        .changes
        .iter()
        .map(|c| c.u)
        .chain(s.flats.iter().filter(|f| f.sign_change).map(|f| f.u))
        .map(|u| if closed && u <= first { u + period } else { u })
        .collect();
    v.sort_by(f64::total_cmp);
    v
}

/// Between two parameters with trusted signs `s_lo` and `s_hi`, the number of reported sign
/// changes in `(lo, hi]` is 1 where the signs differ and 0 where they agree. Where it is not,
/// the stretch is sampled more densely (two close roots that the sampling stepped over) and
/// each piece checked again; a stretch where no denser sample rises above the noise (beside a
/// flat, say) is only held to the parity of the count: sampling cannot see into it.
fn check_stretch(
    value: &dyn Fn(f64) -> f64,
    found: &[f64],
    (lo, s_lo): (f64, i32),
    (hi, s_hi): (f64, i32),
    noise: f64,
    depth: usize,
) -> Result<(), String> {
    let count = found.iter().filter(|&&u| u > lo && u <= hi).count();
    let expected = usize::from(s_lo != s_hi);
    if count == expected {
        return Ok(());
    }
    let fail = || {
        Err(format!(
            "({lo}, {hi}]: signs {s_lo} → {s_hi}, {count} sign changes reported: {found:?}"
        ))
    };
    if depth >= 4 {
        return fail();
    }
    let m = 256;
    let mut pts = vec![(lo, s_lo)];
    for i in 1..m {
        let x = lo + (hi - lo) * i as f64 / m as f64;
        let s = sign(value(x), noise);
        if s != 0 {
            pts.push((x, s));
        }
    }
    pts.push((hi, s_hi));
    if pts.len() == 2 {
        return if count % 2 == expected {
            Ok(())
        } else {
            fail()
        };
    }
    for w in pts.windows(2) {
        check_stretch(value, found, w[0], w[1], noise, depth + 1)?;
    }
    Ok(())
}

/// The reported sign changes of `f` agree with its sampled signs, and every flat is flat.
fn check_against_sampling(f: &BSpline, closed: bool, s: &SignChanges) -> Result<(), String> {
    let (a, b) = f.domain();
    let period = b - a;
    // Some 30 times the rounding error of an evaluation: beside a flat the function is tiny
    // but its sign still matters.
    let noise = 64.0 * (f.degree() + 2) as f64 * f64::EPSILON * f.max_abs_coef();
    let value = |u: f64| {
        let u = if closed && u >= b { u - period } else { u };
        f.eval_scalar(u)
    };
    // Inside, off the knots (a position reported within rounding of a jump may lie on either
    // side of it); the first sample at the domain start, the last at an open domain's end.
    let n = if closed { SAMPLES - 1 } else { SAMPLES };
    let at = |i: usize| {
        let shift = if i == 0 || i == n { 0.0 } else { 0.381966 };
        a + period * (i as f64 + shift) / SAMPLES as f64
    };
    let trusted: Vec<(f64, i32)> = (0..=n)
        .map(at)
        .map(|x| (x, sign(value(x), noise)))
        .filter(|&(_, s)| s != 0)
        .collect();
    let (Some(&first), Some(&last)) = (trusted.first(), trusted.last()) else {
        return Err("no sample beyond the noise".into());
    };
    let found = reported(s, closed, first.0, period);
    for w in trusted.windows(2) {
        check_stretch(&value, &found, w[0], w[1], noise, 0)?;
    }
    if closed {
        check_stretch(&value, &found, last, (first.0 + period, first.1), noise, 0)?;
    } else if found.iter().any(|&u| u <= first.0 || u > last.0) {
        return Err(format!(
            "a sign change beyond the trusted samples: {found:?}"
        ));
    }
    // A flat is within rounding of zero all along.
    for fl in &s.flats {
        let (lo, hi) = fl.bracket;
        for i in 1..64 {
            let v = value(lo + (hi - lo) * i as f64 / 64.0);
            if v.abs() > 1e-9 * f.max_abs_coef() {
                return Err(format!("flat {fl:?} is not flat: {v}"));
            }
        }
    }
    Ok(())
}

/// What a built function is made of (on a domain of length `len`).
#[derive(Debug, Clone)]
struct Parts {
    len: f64,
    simple: Vec<f64>,
    double: Vec<f64>,
    /// Knots where the function may jump (outside the flat).
    jumps: Vec<f64>,
    /// All knots of the step factor, sorted, and its values: `slopes[i]` before `steps[i]`.
    steps: Vec<f64>,
    slopes: Vec<f64>,
    /// The flat span `[lo, hi]`, if any.
    flat: Option<(f64, f64)>,
    /// Simple roots inside the flat.
    hidden_roots: Vec<f64>,
}

impl Parts {
    /// The sign of the step factor flips at `steps[i]`.
    fn flips(&self, i: usize) -> bool {
        (self.slopes[i] > 0.0) != (self.slopes[i + 1] > 0.0)
    }
}

/// `c · Π(u − rᵢ) · Π(u − dⱼ)² · J(u) · Z(u)`: `J` is piecewise constant (the derivative of a
/// piecewise linear function) with jumps at the `jumps`, `Z ≥ 0` a cubic that vanishes exactly
/// on the flat span and nowhere else.
fn build(
    a: f64,
    len: f64,
    features: &[(f64, u8)],
    slopes: &[f64],
    flat: Option<(usize, usize)>,
    c: f64,
) -> (BSpline, Parts) {
    let b = a + len;
    let at = |x: f64| a + len * x;
    let flat_span = flat.map(|(m, k)| (at(k as f64 / m as f64), at((k + 1) as f64 / m as f64)));
    let mut parts = Parts {
        len,
        simple: vec![],
        double: vec![],
        jumps: vec![],
        steps: vec![],
        slopes: vec![],
        flat: flat_span,
        hidden_roots: vec![],
    };
    // Parts inside the flat are hidden (they only decide whether the sign changes across it);
    // parts just beside it are left out.
    let mut hidden = (vec![], vec![]);
    for &(x, kind) in features {
        let u = at(x);
        let inside = flat_span.is_some_and(|(lo, hi)| u > lo && u < hi);
        if !inside && flat_span.is_some_and(|(lo, hi)| u > lo - 0.03 * len && u < hi + 0.03 * len) {
            continue;
        }
        match (kind % 3, inside) {
            (0, false) => parts.simple.push(u),
            (1, false) => parts.double.push(u),
            (_, false) => parts.jumps.push(u),
            (0, true) => hidden.0.push(u),
            (1, true) => {}
            (_, true) => hidden.1.push(u),
        }
    }
    parts.hidden_roots = hidden.0;
    let mut steps: Vec<f64> = parts.jumps.iter().chain(&hidden.1).copied().collect();
    steps.sort_by(f64::total_cmp);
    let mut f = BSpline::constant(&[c], 0, a, b).unwrap();
    for &r in parts.simple.iter().chain(&parts.hidden_roots) {
        f = f.mul(&linear(r, a, b)).unwrap();
    }
    for &d in &parts.double {
        let l = linear(d, a, b);
        f = f.mul(&l).unwrap().mul(&l).unwrap();
    }
    if !steps.is_empty() {
        parts.slopes = slopes[..=steps.len()].to_vec();
        let mut bp = vec![a];
        bp.extend(&steps);
        bp.push(b);
        let mut knots = vec![a];
        knots.extend(&bp);
        knots.push(b);
        let mut coefs = vec![0.0];
        for (i, w) in bp.windows(2).enumerate() {
            let last = coefs[coefs.len() - 1];
            coefs.push(last + parts.slopes[i] * (w[1] - w[0]));
        }
        let g = BSpline::new(1, knots, 1, coefs).unwrap();
        f = f.mul(&g.deriv()).unwrap();
        parts.steps = steps;
    }
    if let Some((m, k)) = flat {
        let coefs: Vec<f64> = (0..m + 3)
            .map(|i| if (k..k + 4).contains(&i) { 0.0 } else { 1.0 })
            .collect();
        let z = BSpline::clamped_uniform(3, 1, coefs)
            .unwrap()
            .reparam(a, b)
            .unwrap();
        f = f.mul(&z).unwrap();
    }
    (f, parts)
}

/// Feature positions in `(0.05, 0.95)` at least 0.03 apart, each with a kind.
fn features() -> impl Strategy<Value = Vec<(f64, u8)>> {
    prop::collection::vec((0.05f64..0.95, any::<u8>()), 0..8).prop_map(|mut v| {
        v.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut out: Vec<(f64, u8)> = Vec::new();
        for (x, k) in v {
            if out.last().is_none_or(|l| x - l.0 >= 0.03) {
                out.push((x, k));
            }
        }
        out
    })
}

/// The known parts are where they should be: simple roots and sign-changing jumps reported
/// there, double roots seen and not reported, the flat reported, the seam decided.
fn check_parts(f: &BSpline, closed: bool, p: &Parts, s: &SignChanges) -> Result<(), String> {
    let len = p.len;
    let at = |u: f64, slack: f64| s.changes.iter().find(|c| (c.u - u).abs() <= slack);
    for &r in &p.simple {
        match at(r, 1e-9 * len.max(1.0)) {
            Some(c) if c.kind == SignChangeKind::Simple && c.certified => {}
            other => return Err(format!("simple root {r}: {other:?}")),
        }
    }
    for &k in &p.jumps {
        let flips = p
            .steps
            .iter()
            .position(|&x| x == k)
            .is_some_and(|i| p.flips(i));
        match (flips, at(k, 1e-9 * len.max(1.0))) {
            (true, Some(c)) if c.certified => {}
            (false, None) => {}
            (_, other) => return Err(format!("jump at {k} (flips: {flips}): {other:?}")),
        }
    }
    for &d in &p.double {
        if let Some(c) = at(d, 0.01 * len) {
            return Err(format!("double root {d} reported as {c:?}"));
        }
        let seen = s
            .unresolved
            .iter()
            .map(|r| r.bracket)
            .chain(s.flats.iter().map(|f| f.bracket))
            .any(|(lo, hi)| lo - 1e-6 * len <= d && d <= hi + 1e-6 * len);
        if !seen {
            return Err(format!("double root {d} not seen: {s:?}"));
        }
    }
    if let Some((lo, hi)) = p.flat {
        let w = hi - lo;
        let covered = s
            .flats
            .iter()
            .any(|f| f.bracket.0 <= lo + 1e-3 * w && f.bracket.1 >= hi - 1e-3 * w);
        if !covered {
            return Err(format!("flat [{lo}, {hi}] not reported: {:?}", s.flats));
        }
        // Across it the sign changes by the hidden roots and steps.
        let hidden_steps = (0..p.steps.len())
            .filter(|&i| p.steps[i] > lo && p.steps[i] < hi && p.flips(i))
            .count();
        let change = (p.hidden_roots.len() + hidden_steps) % 2 == 1;
        let fl = s.flats.iter().find(|f| f.u > lo && f.u < hi);
        if fl.is_none_or(|f| f.sign_change != change) {
            return Err(format!("flat [{lo}, {hi}] (sign change {change}): {fl:?}"));
        }
    }
    for fl in &s.flats {
        let known = p.flat.is_some_and(|(lo, hi)| fl.u > lo && fl.u < hi);
        let double = p.double.iter().any(|d| (fl.u - d).abs() <= 1e-3 * len);
        if !known && !double {
            return Err(format!("unexpected flat {fl:?}"));
        }
    }
    if closed {
        let (a, b) = f.domain();
        let (fa, fb) = (f.eval_scalar(a), f.eval_scalar(b));
        let seam = s.changes.iter().find(|c| c.u == a);
        match ((fa > 0.0) != (fb > 0.0), seam) {
            (true, Some(c)) if c.kind == SignChangeKind::Jump && c.certified => {}
            (false, None) => {}
            (flips, other) => return Err(format!("seam ({fb} → {fa}, {flips}): {other:?}")),
        }
    }
    if p.double.is_empty() && s.changes.iter().any(|c| !c.certified) {
        return Err(format!("uncertified change without double roots: {s:?}"));
    }
    Ok(())
}

/// A periodic function with jumps at its interior integer knots but none at the seam: the
/// derivative of a periodic piecewise linear function whose first and last slopes agree.
fn periodic_steps(n: usize, slope0: f64, inner: &[f64]) -> BSpline {
    let mut c = vec![0.0; n];
    c[1] = slope0;
    c[n - 1] = -slope0;
    for (i, &v) in inner.iter().enumerate().take(n - 3) {
        c[2 + i] = v;
    }
    BSpline::periodic(1, 1, c).unwrap().deriv()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    /// Functions built from known parts, on an open or a clamped closed domain: the parts are
    /// reported as they should be, and nothing is missed or added against dense sampling.
    #[test]
    fn built_functions_open_and_clamped_closed(
        a in -3.0f64..3.0,
        len in 0.5f64..4.0,
        feats in features(),
        slopes in prop::collection::vec(
            (0.5f64..2.0, any::<bool>()).prop_map(|(m, neg)| if neg { -m } else { m }), 9),
        flat in prop_oneof![
            Just(None),
            (3usize..8).prop_flat_map(|m| (Just(m), 1..m - 1)).prop_map(Some),
        ],
        c in prop_oneof![-50.0f64..-0.1, 0.1f64..50.0],
        closed in any::<bool>(),
    ) {
        let (f, parts) = build(a, len, &feats, &slopes, flat, c);
        let s = sign_changes(&f, closed, &RootOptions::default()).unwrap();
        let sampled = check_against_sampling(&f, closed, &s);
        prop_assert!(sampled.is_ok(), "{}\n{:?}\n{:?}", sampled.unwrap_err(), parts, s);
        let known = check_parts(&f, closed, &parts, &s);
        prop_assert!(known.is_ok(), "{}\n{:?}\n{:?}", known.unwrap_err(), parts, s);
        // Sorted, in the domain (one period on a closed one).
        let (a, b) = f.domain();
        prop_assert!(s.changes.windows(2).all(|w| w[0].u <= w[1].u));
        let in_domain = |u: f64| u >= a && (u < b || (!closed && u == b));
        prop_assert!(s.changes.iter().all(|c| in_domain(c.u)), "{:?}", s.changes);
    }

    /// Periodic functions `g · h² · Z · J`: random periodic `g` (its roots the sign changes),
    /// `h` (its roots double roots), `Z ≥ 0` with an optional flat span, `J` with optional jumps
    /// at interior knots, continuous at the seam: against dense sampling around the circle.
    #[test]
    fn periodic_functions_against_sampling(
        n in 5usize..12,
        pg in 1usize..5,
        ph in 1usize..4,
        g in prop::collection::vec(-10.0f64..10.0, 12),
        h in prop::collection::vec(-10.0f64..10.0, 12),
        use_h in any::<bool>(),
        zero_at in prop::option::of(0usize..12),
        steps in prop::option::of((0.5f64..2.0, prop::collection::vec(-5.0f64..5.0, 9))),
    ) {
        let mut f = BSpline::periodic(pg, 1, g[..n].to_vec()).unwrap();
        if use_h {
            let h = BSpline::periodic(ph, 1, h[..n].to_vec()).unwrap();
            f = f.mul(&h).unwrap().mul(&h).unwrap();
        }
        if let Some(z) = zero_at {
            let coefs: Vec<f64> = (0..n)
                .map(|i| if (i + n - z % n) % n < 4 { 0.0 } else { 1.0 })
                .collect();
            f = f.mul(&BSpline::periodic(3, 1, coefs).unwrap()).unwrap();
        }
        if let Some((s0, inner)) = &steps {
            f = f.mul(&periodic_steps(n, *s0, inner)).unwrap();
        }
        let s = sign_changes(&f, true, &RootOptions::default()).unwrap();
        let sampled = check_against_sampling(&f, true, &s);
        prop_assert!(sampled.is_ok(), "{}\n{:?}", sampled.unwrap_err(), s);
        if let Some(z) = zero_at {
            // Z vanishes on the span [z, z + 1] (mod n), shaped by its points z..z + 3: a flat.
            let lo = (z % n) as f64;
            prop_assert!(s.flats.iter().any(|fl| {
                let (l, h) = fl.bracket;
                let k = ((lo - l) / n as f64).floor() * n as f64;
                l + k <= lo + 0.01 && h + k >= lo + 0.99
            }), "flat at [{}, {}] not reported: {:?}", lo, lo + 1.0, s.flats);
        }
    }
}

#[test]
fn step_function_changes_sign_at_its_jump() {
    // The slope of a function with a kink at 0.3 jumps from 1 to −0.5 there.
    let g = BSpline::new(1, vec![0., 0., 0.3, 1., 1.], 1, vec![0., 0.3, -0.05]).unwrap();
    let s = sign_changes(&g.deriv(), false, &RootOptions::default()).unwrap();
    assert_eq!(s.changes.len(), 1, "{s:?}");
    let c = s.changes[0];
    // Root isolation may see it as a simple root; else it is a jump.
    assert!((c.u - 0.3).abs() < 1e-12 && c.certified, "{c:?}");
    assert!(s.certified() && s.flats.is_empty() && s.unresolved.is_empty());
}

#[test]
fn zero_function_is_one_flat_without_sign_change() {
    for closed in [false, true] {
        let f = BSpline::clamped_uniform(3, 1, vec![0.0; 6]).unwrap();
        let s = sign_changes(&f, closed, &RootOptions::default()).unwrap();
        assert!(s.changes.is_empty(), "{s:?}");
        assert_eq!(s.flats.len(), 1);
        assert!(!s.flats[0].sign_change);
    }
}

#[test]
fn flat_between_opposite_signs_is_a_sign_change() {
    // −1 on [0, 0.3], a straight stretch on [0.4, 0.6] (within rounding), +1 from 0.7 on.
    let f = BSpline::new(1, vec![0., 0., 0.4, 0.6, 1., 1.], 1, vec![-1., 0., 0., 1.]).unwrap();
    let s = sign_changes(&f, false, &RootOptions::default()).unwrap();
    assert!(s.changes.is_empty(), "{s:?}");
    assert_eq!(s.flats.len(), 1, "{s:?}");
    assert!(s.flats[0].sign_change);
    assert!((s.flats[0].bracket.0 - 0.4).abs() < 1e-9 && (s.flats[0].bracket.1 - 0.6).abs() < 1e-9);
}

#[test]
fn bad_input_is_an_error() {
    let f = BSpline::clamped_uniform(2, 2, vec![0.0; 8]).unwrap();
    assert!(sign_changes(&f, false, &RootOptions::default()).is_err());
    let g = BSpline::clamped_uniform(2, 1, vec![1.0, -1.0, 1.0]).unwrap();
    let nan = RootOptions::default().tolerance(f64::NAN);
    assert!(sign_changes(&g, false, &nan).is_err());
    assert!(sign_changes(&g, true, &nan).is_err());
}
