//! Property tests: every exact operation agrees with pointwise evaluation of its definition.
#![allow(clippy::needless_range_loop)]
#![allow(clippy::unwrap_used)]

mod common;
use bspline::BSpline;
use common::*;
use proptest::prelude::*;

const TOL: f64 = 1e-12;

fn scale_of(f: &BSpline, df: &BSpline) -> f64 {
    f.max_abs_coef().max(df.max_abs_coef())
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 2000,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn product_matches_pointwise((a, b) in pair(5, 12, 1, 2)) {
        let h = a.mul(&b).unwrap();
        prop_assert_eq!(h.degree(), a.degree() + b.degree());
        let scale = a.max_abs_coef() * b.max_abs_coef();
        for u in sample_params(&h, 40) {
            let (fa, fb, fh) = (a.eval(u), b.eval(u), h.eval(u));
            for k in 0..2 {
                prop_assert!(close(fh[k], fa[0] * fb[k], scale, TOL), "u={u} k={k}: {} vs {}", fh[k], fa[0] * fb[k]);
            }
        }
    }

    /// Derivatives of C⁰ splines jump at their knots: the product must keep the jumps.
    #[test]
    fn product_of_discontinuous_factors_matches((a, b) in pair(4, 10, 1, 1)) {
        let (da, db) = (a.deriv(), b.deriv());
        let h = da.mul(&db).unwrap();
        let scale = da.max_abs_coef() * db.max_abs_coef();
        let mut bp = a.breakpoints();
        bp.extend(b.breakpoints());
        bp.sort_by(f64::total_cmp);
        bp.dedup();
        for w in bp.windows(2) {
            for s in [0.1, 0.5, 0.9] {
                let u = w[0] + (w[1] - w[0]) * s;
                let want = da.eval_scalar(u) * db.eval_scalar(u);
                prop_assert!(close(h.eval_scalar(u), want, scale, TOL), "u={u}: {} vs {want}", h.eval_scalar(u));
            }
        }
    }

    #[test]
    fn product_has_minimal_knots((a, b) in pair(4, 10, 1, 1)) {
        let h = a.mul(&b).unwrap();
        let (p, q) = (a.degree(), b.degree());
        for x in h.breakpoints() {
            let (lo, hi) = h.domain();
            if x == lo || x == hi { continue; }
            let m = |f: &BSpline| bspline::knots::multiplicity(f.knots(), x);
            let cont = |f: &BSpline, deg: usize| if m(f) == 0 { usize::MAX } else { deg - m(f) };
            let want = (p + q) - cont(&a, p).min(cont(&b, q));
            prop_assert_eq!(m(&h), want);
        }
    }

    #[test]
    fn dot_and_cross_match_pointwise((a, b) in pair(4, 10, 2, 2)) {
        let d = a.dot(&b).unwrap();
        let c = a.cross(&b).unwrap();
        let scale = a.max_abs_coef() * b.max_abs_coef();
        for u in sample_params(&d, 30) {
            let (fa, fb) = (a.eval(u), b.eval(u));
            prop_assert!(close(d.eval_scalar(u), fa[0] * fb[0] + fa[1] * fb[1], scale, TOL));
            prop_assert!(close(c.eval_scalar(u), fa[0] * fb[1] - fa[1] * fb[0], scale, TOL));
        }
    }

    #[test]
    fn sum_and_difference_match_pointwise((a, b) in pair(5, 12, 2, 2)) {
        let s = a.add(&b).unwrap();
        let d = a.sub(&b).unwrap();
        let scale = a.max_abs_coef() + b.max_abs_coef();
        for u in sample_params(&s, 30) {
            let (fa, fb) = (a.eval(u), b.eval(u));
            for k in 0..2 {
                prop_assert!(close(s.eval(u)[k], fa[k] + fb[k], scale, TOL));
                prop_assert!(close(d.eval(u)[k], fa[k] - fb[k], scale, TOL));
            }
        }
    }

    /// One span each (the fast paths of product, elevation and a common space): the same
    /// functions pointwise, and one space for both.
    #[test]
    fn one_span_algebra_matches_pointwise((a, b) in pair(6, 0, 1, 2), t in 0usize..4) {
        let h = a.mul(&b).unwrap();
        let e = b.elevate(t);
        let (ha, hb) = a.harmonize(&b).unwrap();
        prop_assert_eq!(h.degree(), a.degree() + b.degree());
        prop_assert_eq!(e.degree(), b.degree() + t);
        prop_assert_eq!(ha.degree(), a.degree().max(b.degree()));
        prop_assert_eq!(ha.knots(), hb.knots());
        let scale = a.max_abs_coef() * b.max_abs_coef().max(1.0);
        for u in sample_params(&h, 30) {
            prop_assert!(close(ha.eval(u)[0], a.eval(u)[0], a.max_abs_coef(), TOL));
            for k in 0..2 {
                prop_assert!(close(h.eval(u)[k], a.eval(u)[0] * b.eval(u)[k], scale, TOL));
                prop_assert!(close(e.eval(u)[k], b.eval(u)[k], b.max_abs_coef(), TOL));
                prop_assert!(close(hb.eval(u)[k], b.eval(u)[k], b.max_abs_coef(), TOL));
            }
        }
    }

    #[test]
    fn elevation_keeps_function_and_continuity(f in spline(5, 12, 2), t in 1usize..4) {
        let g = f.elevate(t);
        prop_assert_eq!(g.degree(), f.degree() + t);
        for x in f.breakpoints() {
            let m = |h: &BSpline| bspline::knots::multiplicity(h.knots(), x);
            let (lo, hi) = f.domain();
            if x != lo && x != hi { prop_assert_eq!(m(&g), m(&f) + t); }
        }
        let scale = f.max_abs_coef();
        for u in sample_params(&f, 30) {
            for k in 0..2 { prop_assert!(close(g.eval(u)[k], f.eval(u)[k], scale, TOL)); }
        }
    }

    #[test]
    fn knot_insertion_and_refinement_keep_function(f in spline(5, 12, 2), xs in prop::collection::vec(0.001f64..0.999, 1..8)) {
        let (a, b) = f.domain();
        let xs: Vec<f64> = xs.iter().map(|s| a + (b - a) * s).collect();
        let g = f.refine(&xs).unwrap();
        prop_assert_eq!(g.n_ctrl(), f.n_ctrl() + xs.len());
        let h = f.insert_knot(xs[0], 2).unwrap();
        let scale = f.max_abs_coef();
        for u in sample_params(&g, 30) {
            for k in 0..2 {
                prop_assert!(close(g.eval(u)[k], f.eval(u)[k], scale, TOL));
                prop_assert!(close(h.eval(u)[k], f.eval(u)[k], scale, TOL));
            }
        }
    }

    #[test]
    fn split_and_restrict_keep_function(f in spline(5, 12, 2), s in 0.01f64..0.99, t in 0.0f64..1.0) {
        let (a, b) = f.domain();
        let u = a + (b - a) * s;
        let (l, r) = f.split_at(u).unwrap();
        prop_assert_eq!(l.domain(), (a, u));
        prop_assert_eq!(r.domain(), (u, b));
        let scale = f.max_abs_coef();
        for v in sample_params(&f, 30) {
            let piece = if v <= u { &l } else { &r };
            for k in 0..2 { prop_assert!(close(piece.eval(v)[k], f.eval(v)[k], scale, TOL)); }
        }
        let (c, d) = if u < a + (b - a) * t { (u, a + (b - a) * t) } else { (a + (b - a) * t, u) };
        if c < d {
            let g = f.restrict(c, d).unwrap();
            prop_assert!(g.is_clamped());
            for v in sample_params(&g, 20) {
                for k in 0..2 { prop_assert!(close(g.eval(v)[k], f.eval(v)[k], scale, TOL)); }
            }
        }
    }

    #[test]
    fn bezier_pieces_and_de_casteljau_match(f in spline(5, 12, 2), s in 0.05f64..0.95) {
        let scale = f.max_abs_coef();
        for piece in f.bezier_pieces() {
            let mut out = [0.0; 2];
            for i in 0..=10 {
                let u = piece.a + (piece.b - piece.a) * i as f64 / 10.0;
                piece.eval(u, &mut out);
                for k in 0..2 { prop_assert!(close(out[k], f.eval(u)[k], scale, TOL)); }
            }
            let m = piece.a + (piece.b - piece.a) * s;
            let (l, r) = piece.split(m);
            for i in 0..=10 {
                let u = piece.a + (piece.b - piece.a) * i as f64 / 10.0;
                let half = if u <= m { &l } else { &r };
                half.eval(u, &mut out);
                for k in 0..2 { prop_assert!(close(out[k], f.eval(u)[k], scale, TOL)); }
            }
        }
    }

    #[test]
    fn periodic_to_clamped_keeps_curve(p in 1usize..6, extra in 0usize..10, pts in prop::collection::vec(-10.0f64..10.0, 64)) {
        let n = p + 1 + extra;
        let f = BSpline::periodic(p, 2, pts[..2 * n].to_vec()).unwrap();
        let g = f.clamped();
        prop_assert!(g.is_clamped());
        prop_assert_eq!(g.domain(), (0.0, n as f64));
        // Closed and C^(p-1) at the seam.
        let (mut d0, mut d1) = (vec![0.0; 2 * p], vec![0.0; 2 * p]);
        f.eval_derivs(0.0, p - 1, &mut d0);
        f.eval_derivs(n as f64, p - 1, &mut d1);
        for (x, y) in d0.iter().zip(&d1) { prop_assert!(close(*x, *y, 10.0 * n.pow(p as u32) as f64, TOL)); }
        for u in sample_params(&f, 40) {
            for k in 0..2 { prop_assert!(close(g.eval(u)[k], f.eval(u)[k], 10.0, TOL)); }
        }
    }

    #[test]
    fn derivative_matches_finite_difference(f in spline(5, 12, 2)) {
        let df = f.deriv();
        let d2 = f.deriv_n(2);
        let (a, b) = f.domain();
        let h = (b - a) * 1e-3;
        let mut all = vec![0.0; 6];
        for br in f.breakpoints().windows(2) {
            // Inside each span the function is a polynomial: a 6th-order central difference.
            let (lo, hi) = (br[0], br[1]);
            if hi - lo < 8.0 * h { continue; }
            let u = 0.5 * (lo + hi);
            let fd = |k: usize| {
                let e = |s: f64| f.eval(u + s * h)[k];
                (-e(-3.0) + 9.0 * e(-2.0) - 45.0 * e(-1.0) + 45.0 * e(1.0) - 9.0 * e(2.0) + e(3.0)) / (60.0 * h)
            };
            f.eval_derivs(u, 2, &mut all);
            let mut d1 = [0.0; 4];
            f.eval_d1(u, &mut d1);
            for k in 0..4 {
                prop_assert!(close(d1[k], all[k], scale_of(&f, &df), TOL), "eval_d1 {} vs {}", d1[k], all[k]);
            }
            let scale = df.max_abs_coef();
            for k in 0..2 {
                prop_assert!(close(df.eval(u)[k], fd(k), scale, 1e-7), "fd {} vs {}", df.eval(u)[k], fd(k));
                prop_assert!(close(all[2 + k], df.eval(u)[k], scale, TOL));
                prop_assert!(close(all[4 + k], d2.eval(u)[k], d2.max_abs_coef(), TOL));
            }
        }
    }
}

/// The blossom the long way: de Casteljau with each argument in turn, over all points.
fn blossom_by_de_casteljau(p: &bspline::Bezier, args: &[f64]) -> Vec<f64> {
    let d = p.dim;
    let mut w = p.coefs.clone();
    for (level, &u) in args.iter().enumerate() {
        let s = (u - p.a) / (p.b - p.a);
        for k in 0..p.degree - level {
            for c in 0..d {
                w[k * d + c] = (1.0 - s) * w[k * d + c] + s * w[(k + 1) * d + c];
            }
        }
    }
    w[..d].to_vec()
}

proptest! {
    #![proptest_config(config())]

    /// The blossom, which applies arguments at the interval's ends by index, equals de
    /// Casteljau over every argument in turn exactly, whatever mix of ends and inner
    /// arguments (in any order) it is given.
    #[test]
    fn blossom_matches_de_casteljau(
        degree in 1usize..=12,
        dim in 1usize..=3,
        ends in (-3.0f64..3.0, 0.01f64..4.0),
        coefs in proptest::collection::vec(-5.0f64..5.0, 39),
        picks in proptest::collection::vec((0u8..3, 0.0f64..1.0), 12),
    ) {
        let (a, b) = (ends.0, ends.0 + ends.1);
        let p = bspline::Bezier { a, b, degree, dim, coefs: coefs[..(degree + 1) * dim].to_vec() };
        // Each argument: the start, the end, or a point inside or beyond the interval.
        let args: Vec<f64> = picks[..degree]
            .iter()
            .map(|&(kind, x)| match kind {
                0 => a,
                1 => b,
                _ => a + (b - a) * (2.0 * x - 0.5),
            })
            .collect();
        let mut out = vec![0.0; dim];
        p.blossom(&args, &mut out);
        let want = blossom_by_de_casteljau(&p, &args);
        for c in 0..dim {
            // (Exactly equal: the index steps are exact, and the other steps the same.)
            prop_assert!(out[c] == want[c], "{:?} vs {:?} at {:?}", out, want, args);
        }
    }
}

proptest! {
    #![proptest_config(config())]

    /// A Bézier patch restricted to a box inside its own is the same polynomial there: its
    /// corner and inner values match the patch's, evaluated from the Bernstein basis.
    #[test]
    fn bezier_patch_restriction_keeps_the_polynomial(
        (pt, pr) in (0usize..=6, 0usize..=6),
        coefs in proptest::collection::vec(-5.0f64..5.0, 49),
        (t0, tw) in (-2.0f64..2.0, 0.1f64..3.0),
        (r0, rw) in (-2.0f64..2.0, 0.1f64..3.0),
        cut in ((0.0f64..0.95, 0.0f64..0.95), (0.0f64..0.95, 0.0f64..0.95)),
    ) {
        let p = bspline::tensor::BezierPatch {
            t0, t1: t0 + tw, r0, r1: r0 + rw, deg_t: pt, deg_r: pr,
            coefs: coefs[..(pt + 1) * (pr + 1)].to_vec(),
        };
        let (a, b) = (cut.0 .0.min(cut.0 .1), cut.0 .0.max(cut.0 .1) + 0.05);
        let (c, d) = (cut.1 .0.min(cut.1 .1), cut.1 .0.max(cut.1 .1) + 0.05);
        let t = [t0 + a * tw, t0 + b * tw];
        let r = [r0 + c * rw, r0 + d * rw];
        let q = p.restrict(t, r);
        // Both as polynomials, evaluated from their Bernstein coefficients.
        let value = |bp: &bspline::tensor::BezierPatch, x: f64, y: f64| {
            let bern = |n: usize, u: f64, k: usize| {
                let binom = (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64);
                binom * u.powi(k as i32) * (1.0 - u).powi((n - k) as i32)
            };
            let (u, v) = ((x - bp.t0) / (bp.t1 - bp.t0), (y - bp.r0) / (bp.r1 - bp.r0));
            let mut s = 0.0;
            for i in 0..=bp.deg_t {
                for j in 0..=bp.deg_r {
                    s += bp.coefs[i * (bp.deg_r + 1) + j] * bern(bp.deg_t, u, i) * bern(bp.deg_r, v, j);
                }
            }
            s
        };
        let scale = coefs.iter().fold(1.0f64, |m, x| m.max(x.abs())) * 3f64.powi((pt + pr) as i32);
        for (x, y) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0), (0.3, 0.7), (0.61, 0.2)] {
            let (px, py) = (t[0] + x * (t[1] - t[0]), r[0] + y * (r[1] - r[0]));
            let (want, got) = (value(&p, px, py), value(&q, px, py));
            prop_assert!(close(got, want, scale, TOL), "at ({px}, {py}): {got} vs {want}");
        }
    }
}
