//! Snapshots of canonical results, rounded to 10 significant digits so that harmless
//! floating-point noise does not break them.
#![allow(clippy::unwrap_used)]

use bspline::roots::{find_roots_periodic, RootOptions};
use bspline::{symbolic, BSpline, Rational};
use serde_json::{json, Value};

fn round(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let digits = 10 - x.abs().log10().ceil() as i32;
    let m = 10f64.powi(digits);
    let r = (x * m).round() / m;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

fn describe(f: &BSpline) -> Value {
    json!({
        "degree": f.degree(),
        "dim": f.dim(),
        "knots": f.knots().iter().map(|&k| round(k)).collect::<Vec<_>>(),
        "coefs": f.coefs().iter().map(|&c| round(c)).collect::<Vec<_>>(),
    })
}

#[test]
fn product_of_two_small_bsplines() {
    let a = BSpline::new(
        2,
        vec![0., 0., 0., 0.5, 1., 1., 1.],
        1,
        vec![1., 3., -1., 2.],
    )
    .unwrap();
    let b = BSpline::new(1, vec![0., 0., 0.25, 1., 1.], 1, vec![2., -1., 1.]).unwrap();
    insta::assert_json_snapshot!(describe(&a.mul(&b).unwrap()));
}

#[test]
fn curvature_numerator_of_a_closed_cubic() {
    // The periodic fixture curve of the interfaces file.
    let pts = vec![0., 0., 2., -1., 4., 0., 4., 2., 2., 1.2, 0., 2.];
    let c = Rational::polynomial(&BSpline::periodic(3, 2, pts).unwrap().clamped());
    let k = symbolic::curvature_numerator(&c).unwrap();
    let infl: Vec<Value> = find_roots_periodic(&k, &RootOptions::default())
        .unwrap()
        .iter()
        .map(|r| json!({"u": round(r.u), "certified": r.certified}))
        .collect();
    insta::assert_json_snapshot!(json!({"numerator": describe(&k), "inflections": infl}));
}

#[test]
fn rational_quarter_circle_curvature_numerator() {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let pts = BSpline::bezier(2, vec![1., 0., 1., 1., 0., 1.]).unwrap();
    let c = Rational::new(pts, Some(&[1.0, w, 1.0])).unwrap();
    insta::assert_json_snapshot!(describe(&symbolic::curvature_numerator(&c).unwrap()));
}
