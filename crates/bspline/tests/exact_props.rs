//! The certified numerics layer against exact rational arithmetic: every error bound the
//! piecewise forms carry holds for the exact coefficients (extraction from B-splines,
//! products, derivatives, restrictions, the symbolic forms of curves far from the origin and
//! with extreme weights), and every decision of the root counter and of root isolation agrees
//! with the exact roots of polynomials built from them (near-double roots, huge dynamic
//! ranges, degree 64).
#![allow(clippy::unwrap_used)]

mod common;
use bspline::knots::find_span;
use bspline::roots::{count_roots, find_roots_in, Count, RootKind, RootOptions};
use bspline::{symbolic, BSpline, Piecewise, Rational, JUMP};
use common::exact::{self, q, Q};
use common::{cases, spline};
use num_traits::Zero;
use proptest::prelude::*;

/// Every coefficient of every piece of `got` within its bound of the exact `want(piece)`
/// (coordinate-major per point, as the pieces store them).
fn bounds_hold(got: &Piecewise, want: impl Fn(usize) -> Vec<Vec<Q>>) -> Result<(), String> {
    let d = got.dim();
    for i in 0..got.pieces() {
        let exact = want(i);
        for (j, pt) in got.piece(i).chunks_exact(d).enumerate() {
            for (c, &x) in pt.iter().enumerate() {
                let e = got.errors(i)[c];
                if exact::exceeds(&exact[c][j], x, e) {
                    return Err(format!(
                        "piece {i}, point {j}, coordinate {c}: {x} vs exact {} (bound {e:e}, off by {:e})",
                        exact::f(&exact[c][j]),
                        exact::f(&(q(x) - &exact[c][j]))
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The exact Bézier pieces of a B-spline (per piece, per coordinate).
fn exact_pieces(f: &BSpline) -> Vec<Vec<Vec<Q>>> {
    let (p, d, n) = (f.degree(), f.dim(), f.n_ctrl());
    f.breakpoints()
        .windows(2)
        .map(|w| {
            let s = find_span(p, n, f.knots(), 0.5 * (w[0] + w[1]));
            (0..d)
                .map(|c| {
                    let coefs: Vec<Q> =
                        f.coefs().iter().skip(c).step_by(d).map(|&x| q(x)).collect();
                    exact::bezier_of_span(p, f.knots(), &coefs, s)
                })
                .collect()
        })
        .collect()
}

/// A magnitude far from the origin or near it.
fn offset() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), Just(1e3), Just(-7.5e7), Just(1e9), Just(3e15)]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(250), ..ProptestConfig::default() })]

    /// Knot insertion to Bézier pieces: random knots (with multiplicities), degrees 1–9,
    /// coefficients near the origin or far from it.
    #[test]
    fn extraction_bounds_hold(f in spline(9, 16, 2), off in offset()) {
        let f = f.map_points(2, |c, o| { o[0] = c[0] + off; o[1] = c[1] - 0.5 * off; });
        let pw = Piecewise::from_bspline(&f);
        let want = exact_pieces(&f);
        prop_assert!(bounds_hold(&pw, |i| want[i].clone()).is_ok(), "{}", bounds_hold(&pw, |i| want[i].clone()).unwrap_err());
    }
}

/// A single Bézier piece of `degree` and dimension `dim` on `[lo, hi]`, coefficients offset.
fn bezier() -> impl Strategy<Value = (usize, f64, f64, Vec<f64>, f64)> {
    (
        0usize..=40,
        -2.0f64..2.0,
        0.01f64..3.0,
        prop::collection::vec(-5.0f64..5.0, 41 * 3),
        offset(),
    )
}

fn piece(
    dim: usize,
    (deg, lo, len, c, off): &(usize, f64, f64, Vec<f64>, f64),
) -> (Piecewise, Vec<Vec<Q>>) {
    let coefs: Vec<f64> = c[..(deg + 1) * dim].iter().map(|x| x + off).collect();
    let pw = Piecewise::from_parts(
        *deg,
        dim,
        vec![*lo, lo + len],
        coefs.clone(),
        vec![0.0; dim],
        vec![JUMP, JUMP],
    )
    .unwrap();
    let exact = (0..dim)
        .map(|k| coefs.iter().skip(k).step_by(dim).map(|&x| q(x)).collect())
        .collect();
    (pw, exact)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(200), ..ProptestConfig::default() })]

    /// Products, derivatives, degree elevation, linear combinations and scaling of pieces of
    /// degrees 0–40, offsets up to 3e15.
    #[test]
    fn algebra_bounds_hold(a in bezier(), b in bezier(), s in -4.0f64..4.0, t in -4.0f64..4.0) {
        let (lo, len) = (a.1, a.2);
        let b = (b.0, lo, len, b.3, b.4);
        let (a1, ea1) = piece(1, &a);
        let (b2, eb2) = piece(2, &b);
        let (a2, ea2) = piece(2, &a);
        let (a3, ea3) = piece(3, &a);
        let (b3, eb3) = piece(3, &b);
        let (b1, eb1) = piece(1, &b);
        let check = |got: Piecewise, want: Vec<Vec<Q>>| bounds_hold(&got, |_| want.clone());
        let results = [
            ("mul", check(a1.mul(&b2).unwrap(), eb2.iter().map(|bc| exact::product(&ea1[0], bc)).collect())),
            ("dot", check(a2.dot(&b2).unwrap(), vec![{
                let x = exact::product(&ea2[0], &eb2[0]);
                let y = exact::product(&ea2[1], &eb2[1]);
                exact::lincomb(&Q::from_integer(1.into()), &x, &Q::from_integer(1.into()), &y)
            }])),
            ("cross", check(a2.cross(&b2).unwrap(), vec![{
                let x = exact::product(&ea2[0], &eb2[1]);
                let y = exact::product(&ea2[1], &eb2[0]);
                exact::lincomb(&Q::from_integer(1.into()), &x, &Q::from_integer((-1).into()), &y)
            }])),
            ("cross3", check(a3.cross3(&b3).unwrap(), (0..3).map(|k| {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                let x = exact::product(&ea3[i], &eb3[j]);
                let y = exact::product(&ea3[j], &eb3[i]);
                exact::lincomb(&Q::from_integer(1.into()), &x, &Q::from_integer((-1).into()), &y)
            }).collect())),
            ("derivative", check(a2.derivative(), ea2.iter().map(|c| exact::derivative(c, lo, lo + len)).collect())),
            ("elevate", check(a2.elevate(1), ea2.iter().map(|c| exact::elevate(c)).collect())),
            ("lincomb", check(a1.lincomb(s, &b1, t).unwrap(), vec![{
                let deg = a.0.max(b.0);
                let mut x = ea1[0].clone();
                while x.len() <= deg { x = exact::elevate(&x); }
                let mut y = eb1[0].clone();
                while y.len() <= deg { y = exact::elevate(&y); }
                exact::lincomb(&q(s), &x, &q(t), &y)
            }])),
            ("scale", check(a2.scale(s), ea2.iter().map(|c| c.iter().map(|x| x * q(s)).collect()).collect())),
        ];
        for (what, r) in results {
            prop_assert!(r.is_ok(), "{what}: {}", r.unwrap_err());
        }
    }

    /// The restriction of `Σ wₖ fₖ` to a stretch of a piece (the counter's input): within its
    /// bound of the exact restriction at the same cut parameters.
    #[test]
    fn restriction_bounds_hold(a in bezier(), w in prop::array::uniform3(-3.0f64..3.0), x0 in 0.0f64..1.0, x1 in 0.0f64..1.0) {
        let (p3, e3) = piece(3, &a);
        let (lo, len) = (a.1, a.2);
        let (r0, r1) = (x0.min(x1), x0.max(x1));
        prop_assume!(r1 > r0);
        let (u0, u1) = (lo + len * r0, lo + len * r1);
        let combo: Vec<Q> = (0..=a.0).map(|j| (0..3).fold(Q::zero(), |acc, k| acc + q(w[k]) * &e3[k][j])).collect();
        let mut seen = 0;
        p3.for_each_restricted(&w, u0, u1, |_, y0, y1, c, err| {
            seen += 1;
            // The cuts as the restriction makes them.
            let h = (lo + len) - lo;
            let (s0, s1) = ((y0 - lo) / h, (y1 - lo) / h);
            let mut want = combo.clone();
            if s1 < 1.0 { want = exact::split_left(&want, &q(s1)); }
            if s0 > 0.0 {
                let r = if s1 < 1.0 { s0 / s1 } else { s0 };
                want = exact::split_right(&want, &q(r));
            }
            for (x, y) in c.iter().zip(&want) {
                assert!(!exact::exceeds(y, *x, err), "{x} vs {} (bound {err:e})", exact::f(y));
            }
            true
        });
        prop_assert_eq!(seen, 1);
    }
}

/// A random rational planar curve of degree 2–6 far from the origin or near it, with weights
/// moderate or extreme: the curve, and its points and weights as given.
fn curve() -> impl Strategy<Value = (Rational, BSpline, Option<Vec<f64>>)> {
    (
        spline(6, 12, 2),
        prop_oneof![
            Just(None),
            prop::collection::vec(0.5f64..2.0, 12).prop_map(Some),
            prop::collection::vec(-6.0f64..6.0, 12)
                .prop_map(|e| Some(e.iter().map(|x| 10f64.powf(*x)).collect()))
        ],
        offset(),
    )
        .prop_filter_map("degree ≥ 2", |(pts, w, off)| {
            if pts.degree() < 2 {
                return None;
            }
            let pts = pts.map_points(2, |c, o| {
                o[0] = c[0] + off;
                o[1] = c[1] + 0.25 * off;
            });
            let w = w.map(|w| w[..pts.n_ctrl()].to_vec());
            let c = Rational::new(pts.clone(), w.as_deref()).unwrap();
            Some((c, pts, w))
        })
}

/// The exact homogeneous pieces `(wx, wy, w)` of the curve given by `pts` and `weights`,
/// multiplied exactly (the rounding of `w·x` in the curve's own form is part of what the
/// bounds cover).
fn exact_homogeneous(pts: &BSpline, weights: Option<&[f64]>) -> Vec<Vec<Vec<Q>>> {
    let (p, n) = (pts.degree(), pts.n_ctrl());
    let w = |i: usize| weights.map_or(q(1.0), |w| q(w[i]));
    let hom: Vec<Vec<Q>> = vec![
        (0..n).map(|i| q(pts.ctrl(i)[0]) * w(i)).collect(),
        (0..n).map(|i| q(pts.ctrl(i)[1]) * w(i)).collect(),
        (0..n).map(w).collect(),
    ];
    pts.breakpoints()
        .windows(2)
        .map(|win| {
            let s = find_span(p, n, pts.knots(), 0.5 * (win[0] + win[1]));
            hom.iter()
                .map(|h| exact::bezier_of_span(p, pts.knots(), h, s))
                .collect()
        })
        .collect()
}

/// Per piece: the exact tangent numerator `D = wX′ − w′X` and curvature numerator
/// `det[H, H′, H″]` (`w₀ X′ × X″` for a constant weight).
fn exact_forms(
    c: &Rational,
    pts: &BSpline,
    weights: Option<&[f64]>,
    hom: &Piecewise,
) -> Vec<(Vec<Vec<Q>>, Vec<Q>)> {
    let one = Q::from_integer(1.into());
    let minus = Q::from_integer((-1).into());
    exact_homogeneous(pts, weights)
        .into_iter()
        .enumerate()
        .map(|(i, h)| {
            let (lo, hi) = hom.piece_span(i);
            let d1: Vec<Vec<Q>> = h.iter().map(|x| exact::derivative(x, lo, hi)).collect();
            let d2: Vec<Vec<Q>> = d1.iter().map(|x| exact::derivative(x, lo, hi)).collect();
            if !c.is_rational() {
                let tangent = vec![d1[0].clone(), d1[1].clone()];
                let k = exact::lincomb(
                    &one,
                    &exact::product(&d1[0], &d2[1]),
                    &minus,
                    &exact::product(&d1[1], &d2[0]),
                );
                return (tangent, k);
            }
            let tangent = (0..2)
                .map(|k| {
                    exact::lincomb(
                        &one,
                        &exact::product(&h[2], &d1[k]),
                        &minus,
                        &exact::product(&d1[2], &h[k]),
                    )
                })
                .collect();
            // det[H, H′, H″] = H · (H′ × H″).
            let cross: Vec<Vec<Q>> = (0..3)
                .map(|k| {
                    let (a, b) = ((k + 1) % 3, (k + 2) % 3);
                    exact::lincomb(
                        &one,
                        &exact::product(&d1[a], &d2[b]),
                        &minus,
                        &exact::product(&d1[b], &d2[a]),
                    )
                })
                .collect();
            let mut k = exact::product(&h[0], &cross[0]);
            for c in 1..3 {
                k = exact::lincomb(&one, &k, &one, &exact::product(&h[c], &cross[c]));
            }
            (tangent, k)
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(200), ..ProptestConfig::default() })]

    /// The symbolic forms of curves far from the origin (up to 3e15) and with weights over
    /// twelve orders of magnitude hold the exact forms within their bounds.
    #[test]
    fn curve_forms_bounds_hold((c, pts, w) in curve()) {
        let curve = symbolic::homogeneous_pieces(&c);
        let tangent = curve.tangent().unwrap();
        let curvature = curve.curvature().unwrap();
        let want = exact_forms(&c, &pts, w.as_deref(), &curve.hom);
        let r = bounds_hold(&tangent, |i| want[i].0.clone());
        prop_assert!(r.is_ok(), "tangent: {}", r.unwrap_err());
        let r = bounds_hold(&curvature, |i| vec![want[i].1.clone()]);
        prop_assert!(r.is_ok(), "curvature: {}", r.unwrap_err());
    }
}

/// Exact roots in `[−0.2, 1.2]`: separated ones, near-double pairs (gaps down to 1e-15) and
/// exact doubles; with the leading coefficient, a polynomial of degree up to 64.
fn roots() -> impl Strategy<Value = (Vec<f64>, f64)> {
    (
        prop::collection::vec(
            (
                -0.2f64..1.2,
                prop_oneof![
                    Just(None),
                    (-15.0f64..-2.0).prop_map(Some),
                    Just(Some(f64::NEG_INFINITY))
                ],
            ),
            1..20,
        ),
        prop_oneof![-100.0f64..-0.01, 0.01f64..100.0],
        0usize..=44,
    )
        .prop_map(|(rs, c, extra)| {
            let mut out = Vec::new();
            for (r, gap) in rs {
                out.push(r);
                if let Some(g) = gap {
                    out.push(r + 10f64.powf(g));
                }
            }
            // Far roots raise the degree (to 64) and the dynamic range of the coefficients.
            for k in 0..extra {
                out.push(if k % 2 == 0 {
                    3.0 + k as f64
                } else {
                    -2.0 - k as f64
                });
            }
            out.truncate(64);
            (out, c)
        })
}

fn exact_polynomial(rs: &[f64], c: f64) -> (Piecewise, Vec<Q>) {
    let qs: Vec<Q> = rs.iter().map(|&r| q(r)).collect();
    let coefs = exact::from_roots(rs, c);
    let (v, err) = exact::rounded(&coefs);
    let pw = Piecewise::from_parts(
        v.len() - 1,
        1,
        vec![0.0, 1.0],
        v,
        vec![err],
        vec![JUMP, JUMP],
    )
    .unwrap();
    (pw, qs)
}

/// The exact roots in `[lo, hi]`, with multiplicity.
fn inside(qs: &[Q], lo: f64, hi: f64) -> usize {
    qs.iter().filter(|r| **r >= q(lo) && **r <= q(hi)).count()
}

/// No exact root within `slack` of `x` (the counter's cuts are made to within a few units of
/// rounding of the interval's ends).
fn clear_of(qs: &[Q], x: f64, slack: f64) -> bool {
    qs.iter().all(|r| exact::exceeds(r, x, slack))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(1500), ..ProptestConfig::default() })]

    /// Every decision of the counter on random stretches agrees with the exact roots.
    #[test]
    fn counts_match_exact_roots((rs, c) in roots(), x0 in 0.0f64..1.0, x1 in 0.0f64..1.0) {
        let (f, qs) = exact_polynomial(&rs, c);
        let (lo, hi) = (x0.min(x1), x0.max(x1));
        prop_assume!(hi > lo && clear_of(&qs, lo, 1e-13) && clear_of(&qs, hi, 1e-13));
        let n = inside(&qs, lo, hi);
        match count_roots(&f, &[1.0], lo, hi) {
            Count::Zero => prop_assert_eq!(n, 0, "Zero on [{}, {}] with roots {:?}", lo, hi, rs),
            Count::One(a, b) => {
                prop_assert_eq!(n, 1, "One on [{}, {}] with roots {:?}", lo, hi, rs);
                prop_assert_eq!(inside(&qs, a, b), 1);
            }
            Count::AtEnd(_) => prop_assert!(n <= 1),
            Count::Open => {}
        }
    }

    /// Isolation misses no exact root, and every certified simple root's bracket holds exactly
    /// one exact root (counted with multiplicity).
    #[test]
    fn isolation_matches_exact_roots((rs, c) in roots()) {
        let (f, qs) = exact_polynomial(&rs, c);
        let found = find_roots_in(&f, 0.0, 1.0, &RootOptions::default()).unwrap();
        for (r, x) in qs.iter().zip(&rs) {
            if *r < q(0.0) || *r > q(1.0) {
                continue;
            }
            prop_assert!(found.iter().any(|f| !exact::exceeds(r, f.bracket.0.max(f.bracket.1.min(*x)), 1e-12)),
                "root {} lost in {:?}", x, found);
        }
        for root in found.iter().filter(|r| r.certified) {
            prop_assert_eq!(root.kind, RootKind::Simple);
            prop_assert_eq!(inside(&qs, root.bracket.0, root.bracket.1), 1, "{:?}", root);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(256)))]

    /// `numeric::rounding::Bounded` through sums and products (with cancellations: the second product
    /// near the first) holds its bound on the exact value of the same expression of exact
    /// inputs anywhere within the inputs' errors.
    #[test]
    fn bounded_arithmetic_holds_its_bound(
        x in prop::collection::vec(-1.0..1.0f64, 6),
        scale in prop::collection::vec(-60i32..60, 6),
        near in any::<bool>(),
        rel_err in prop::collection::vec(prop_oneof![Just(0.0), 0.0..1e-10f64], 6),
        at in prop::collection::vec(-1.0..1.0f64, 6),
    ) {
        use numeric::rounding::Bounded;
        let mut v: Vec<f64> = x.iter().zip(&scale).map(|(a, k)| a * 2f64.powi(*k)).collect();
        if near {
            // x2 x3 within rounding of x0 x1.
            v[2] = v[0];
            v[3] = v[1] * (1.0 + 1e-15);
        }
        let errs: Vec<f64> = v.iter().zip(&rel_err).map(|(a, e)| a.abs() * e).collect();
        let b: Vec<Bounded> = v.iter().zip(&errs).map(|(&a, &e)| Bounded::new(a, e)).collect();
        let got = b[0]
            .mul(b[1])
            .sub(b[2].mul(b[3]))
            .mul(b[4].add(b[5]))
            .sub(b[0].mul(b[0]).mul(b[5]));
        // The exact inputs: each value moved by a share `at` of its error.
        let e: Vec<Q> = v
            .iter()
            .zip(&errs)
            .zip(&at)
            .map(|((&a, &err), &t)| q(a) + q(err) * q(t))
            .collect();
        let want = (&e[0] * &e[1] - &e[2] * &e[3]) * (&e[4] + &e[5]) - &e[0] * &e[0] * &e[5];
        prop_assert!(
            !exact::exceeds(&want, got.value, got.error),
            "{} vs exact {} (bound {:e})",
            got.value,
            exact::f(&want),
            got.error
        );
    }
}
