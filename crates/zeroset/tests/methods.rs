//! F1, F2 and F3 give the same bisector once cleaned; the trimmed bisector is a subset whose
//! points have their foot points as nearest points.
#![allow(clippy::unwrap_used)]
mod common;
use bspline::Rational;
use common::*;
use zeroset::{bisector, Bisector, BisectorOptions, Method};

fn covered(a: &Bisector, b: &Bisector, tol: f64) -> bool {
    let mut ok = true;
    for br in &a.branches {
        for (tr, p) in br.tr.iter().zip(&br.xy) {
            // Near a pole (parallel normals) the branches run off to infinity; compare the
            // finite part, where the chord tolerance means something.
            if p[0].hypot(p[1]) > 10.0 * tol / 3e-3 {
                continue;
            }
            let d = b
                .branches
                .iter()
                .map(|q| dist_to_polyline(*p, &q.xy))
                .fold(f64::INFINITY, f64::min);
            if d > tol {
                eprintln!("uncovered {tr:?} {p:?} d {d}");
                ok = false;
            }
        }
    }
    ok
}

fn pairs() -> Vec<(Rational, Rational, f64)> {
    vec![
        (
            bez(&[[-1.0, 0.0], [0.0, 1.5], [1.0, 0.0]]),
            bez(&[[-1.0, 2.0], [0.2, 0.6], [1.2, 2.2]]),
            3.2,
        ),
        (
            bez(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]),
            bez(&[[0.5, 1.8], [1.0, -0.5], [1.8, 1.6]]),
            2.9,
        ),
        (
            bez(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]),
            bez(&[[0.0, 2.0], [0.7, 1.2], [1.4, 2.8], [2.0, 2.0]]),
            3.4,
        ),
    ]
}

#[test]
fn f1_f2_f3_agree() {
    for (c1, c2, diag) in pairs() {
        let run = |m| {
            bisector(
                &as_curve(&c1),
                &as_curve(&c2),
                &BisectorOptions {
                    method: m,
                    ..Default::default()
                },
            )
            .unwrap()
        };
        let (f1, f2, f3) = (run(Method::F1), run(Method::F2), run(Method::F3));
        let tol = 3e-3 * diag;
        for (name, f) in [("F1", &f1), ("F2", &f2)] {
            assert!(f.complete);
            assert!(
                covered(f, &f3, tol),
                "{name} has points off the F3 bisector"
            );
            assert!(
                covered(&f3, f, tol),
                "{name} misses points of the F3 bisector"
            );
        }
    }
}

#[test]
fn trimmed_is_a_nearest_point_subset() {
    for (c1, c2, diag) in pairs() {
        let all = bisector(&as_curve(&c1), &as_curve(&c2), &BisectorOptions::default()).unwrap();
        let trimmed = bisector(
            &as_curve(&c1),
            &as_curve(&c2),
            &BisectorOptions {
                trimmed: true,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(covered(&trimmed, &all, 3e-3 * diag));
        // Dense check of the nearest-point property.
        for br in &trimmed.branches {
            for (tr, p) in br.tr.iter().zip(&br.xy) {
                let rho = {
                    let (q, _) = pd(&c1, tr[0]);
                    (p[0] - q[0]).hypot(p[1] - q[1])
                };
                for c in [&c1, &c2] {
                    let m = (0..=2000)
                        .map(|i| {
                            let q = c.point(i as f64 / 2000.0);
                            (p[0] - q[0]).hypot(p[1] - q[1])
                        })
                        .fold(f64::INFINITY, f64::min);
                    assert!(m >= rho - 1e-6 * diag, "{tr:?}: {m} < {rho}");
                }
            }
        }
    }
}
