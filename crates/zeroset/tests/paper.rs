//! The examples of Elber & Kim's figures, as snapshots of rounded summaries, plus checks.
#![allow(clippy::unwrap_used)]
mod common;
use bspline::Rational;
use common::*;
use serde::Serialize;
use zeroset::{bisector, self_bisector, Bisector, BisectorOptions};

#[derive(Serialize)]
struct Summary {
    branches: Vec<BranchSummary>,
    singular: Vec<[f64; 4]>,
    isolated: Vec<[f64; 4]>,
    complete: bool,
}

#[derive(Serialize)]
struct BranchSummary {
    start_tr: [f64; 2],
    end_tr: [f64; 2],
    /// `None` for an end that runs off toward infinity (cut where the mapping stops being
    /// trustworthy; its exact place depends on the sampling).
    start_xy: Option<[f64; 2]>,
    end_xy: Option<[f64; 2]>,
}

fn near(p: [f64; 2]) -> Option<[f64; 2]> {
    (p[0].hypot(p[1]) < 50.0).then(|| r2(p))
}

fn round(x: f64) -> f64 {
    let v = (x * 1e4).round() / 1e4;
    if v == 0.0 {
        0.0
    } else {
        v
    }
}
fn r2(p: [f64; 2]) -> [f64; 2] {
    [round(p[0]), round(p[1])]
}

fn summary(b: &Bisector) -> Summary {
    let mut branches: Vec<BranchSummary> = b
        .branches
        .iter()
        .map(|br| {
            let n = br.tr.len() - 1;
            // Orient each branch by increasing t so the summary does not depend on tracing order.
            let (i, j) = if br.tr[0] <= br.tr[n] { (0, n) } else { (n, 0) };
            BranchSummary {
                start_tr: r2(br.tr[i]),
                end_tr: r2(br.tr[j]),
                start_xy: near(br.xy[i]),
                end_xy: near(br.xy[j]),
            }
        })
        .collect();
    branches.sort_by(|a, b| a.start_tr.partial_cmp(&b.start_tr).unwrap());
    let pts = |v: &[zeroset::BisectorPoint]| {
        v.iter()
            .map(|p| {
                [
                    round(p.tr[0]),
                    round(p.tr[1]),
                    round(p.xy[0]),
                    round(p.xy[1]),
                ]
            })
            .collect()
    };
    Summary {
        branches,
        singular: pts(&b.singular),
        isolated: pts(&b.isolated),
        complete: b.complete,
    }
}

fn two(c1: &Rational, c2: &Rational) -> Bisector {
    let b = bisector(&as_curve(c1), &as_curve(c2), &BisectorOptions::default()).unwrap();
    assert!(b.complete && !b.branches.is_empty());
    b
}

/// The self-bisector, complete, with every branch above the diagonal (the mirror dropped).
fn one(c: &Rational) -> Bisector {
    let b = self_bisector(&as_curve(c), &BisectorOptions::default()).unwrap();
    assert!(b.complete && !b.branches.is_empty());
    assert!(b
        .branches
        .iter()
        .all(|br| br.tr.iter().all(|q| q[0] < q[1])));
    b
}

#[test]
fn fig2_line_and_quadratic() {
    let c1 = bez(&[[-1.0, 0.0], [0.0, 2.0], [1.0, 0.0]]);
    let c2 = bez(&[[-1.0, -1.0], [1.0, -0.8]]);
    insta::assert_json_snapshot!(summary(&two(&c1, &c2)));
}

#[test]
fn fig3_two_quadratics() {
    let c1 = bez(&[[-1.0, 0.0], [0.0, 1.5], [1.0, 0.0]]);
    let c2 = bez(&[[-1.0, 2.0], [0.2, 0.6], [1.2, 2.2]]);
    insta::assert_json_snapshot!(summary(&two(&c1, &c2)));
}

#[test]
fn quadratic_and_cubic() {
    let c1 = bez(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]);
    let c2 = bez(&[[0.0, 2.0], [0.7, 1.2], [1.4, 2.8], [2.0, 2.0]]);
    insta::assert_json_snapshot!(summary(&two(&c1, &c2)));
}

#[test]
fn fig4_self_bisector_quadratic_bspline_seven_points() {
    let c = bsp(
        2,
        &[
            [0.0, 0.0],
            [1.0, 1.5],
            [2.5, 1.8],
            [3.5, 0.5],
            [2.5, -1.0],
            [1.0, -1.2],
            [0.5, 0.3],
        ],
    );
    insta::assert_json_snapshot!(summary(&one(&c)));
}

#[test]
fn fig5_self_bisector_cubic_bspline_seven_points() {
    let c = bsp(3, &testkit::outlines::FIG5_CUBIC_POINTS);
    insta::assert_json_snapshot!(summary(&one(&c)));
}

#[test]
fn fig6_cubic_bspline_eleven_points_and_line() {
    let c1 = bsp(
        3,
        &[
            [0.0, 0.0],
            [0.5, 1.0],
            [1.0, 0.2],
            [1.5, 1.2],
            [2.0, 0.3],
            [2.5, 1.4],
            [3.0, 0.1],
            [3.5, 1.0],
            [4.0, 0.4],
            [4.5, 1.3],
            [5.0, 0.5],
        ],
    );
    let c2 = bez(&[[0.0, -1.0], [5.0, -0.8]]);
    insta::assert_json_snapshot!(summary(&two(&c1, &c2)));
}

#[test]
fn fig7_two_quadratics() {
    let c1 = bez(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]);
    let c2 = bez(&[[0.5, 1.8], [1.0, -0.5], [1.8, 1.6]]);
    insta::assert_json_snapshot!(summary(&two(&c1, &c2)));
}

#[test]
fn rational_quarter_circles_have_the_diagonal_bisector() {
    // Two quarter circles of radius 1 around (0,0) and (3,0), facing: the bisector is x = 1.5.
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let mk = |pts: Vec<f64>| {
        Rational::new(
            bspline::BSpline::bezier(2, pts).unwrap(),
            Some(&[1.0, w, 1.0]),
        )
        .unwrap()
    };
    let c1 = mk(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0]);
    let c2 = mk(vec![2.0, 0.0, 2.0, 1.0, 3.0, 1.0]);
    let b = two(&c1, &c2);
    // Points matched on the two arcs at the same height: x = 1.5 exactly.
    let on_axis = b
        .branches
        .iter()
        .flat_map(|br| br.xy.iter())
        .filter(|p| (p[0] - 1.5).abs() < 1e-9)
        .count();
    assert!(on_axis > 3, "{on_axis}");
}

#[test]
fn closed_periodic_self_bisector_joins_across_the_seam() {
    let pts = vec![0., 0., 2., -1., 4., 0., 4., 2., 2., 1.2, 0., 2.];
    let c = Rational::polynomial(&bspline::BSpline::periodic(3, 2, pts).unwrap());
    let b = self_bisector(&as_curve(&c), &BisectorOptions::default()).unwrap();
    assert!(b.complete && !b.branches.is_empty());
    // No branch ends on the seam borders t = 0 or r = 6 any more (they were joined).
    for br in &b.branches {
        for q in [br.tr[0], br.tr[br.tr.len() - 1]] {
            assert!(q[0] != 0.0 && q[1] != 6.0, "{q:?}");
        }
        assert!(br.tr.iter().all(|q| q[0] < q[1]));
    }
    // The symmetric shape's axis x = 2 carries a branch.
    assert!(b
        .branches
        .iter()
        .flat_map(|br| br.xy.iter())
        .any(|p| (p[0] - 2.0).abs() < 1e-9));
}

/// The demo's open cubic NURBS (`fixtures/open_nurbs.json`): its self-bisector used to hit
/// the patch limit (95 fragments, incomplete) because the degree-11 diagonal cells were not
/// divided by (t − r)⁴. Four branches, ending on the diagonal at the four curvature extrema.
#[test]
fn open_nurbs_self_bisector() {
    let pts = [
        [0., 0.],
        [1., 2.],
        [2., 2.],
        [3., 0.],
        [4., -2.],
        [5., -2.],
        [6., 0.],
    ];
    let c: Vec<f64> = pts.iter().flat_map(|p| [p[0], p[1]]).collect();
    let knots = vec![0., 0., 0., 0., 1., 2., 3., 4., 4., 4., 4.];
    let s = bspline::BSpline::new(3, knots, 2, c).unwrap();
    let curve = Rational::new(s, Some(&[1., 3., 1., 1., 0.5, 2., 1.])).unwrap();
    let b = one(&curve);
    assert_eq!(b.branches.len(), 4);
    insta::assert_json_snapshot!(summary(&b));
}

/// The demo's periodic cubic NURBS (`fixtures/periodic_nurbs.json`): was 15 fragments,
/// incomplete. Eight branches: one zero-set curve passes through infinity twice and is cut
/// there (three pieces), the other branches end on the diagonal at curvature extrema.
#[test]
fn periodic_nurbs_self_bisector() {
    let pts = [
        [3., 0.],
        [2.5, 2.],
        [0.5, 1.],
        [-1., 2.5],
        [-3., 0.5],
        [-2.5, -2.],
        [0., -0.8],
        [2., -2.5],
    ];
    let c: Vec<f64> = pts.iter().flat_map(|p| [p[0], p[1]]).collect();
    let mut w = vec![1., 2., 0.5, 1., 1.5, 1., 0.6, 1.];
    w.extend_from_slice(&[1., 2., 0.5]);
    let curve = Rational::new(bspline::BSpline::periodic(3, 2, c).unwrap(), Some(&w)).unwrap();
    let b = one(&curve);
    assert_eq!(b.branches.len(), 8);
    insta::assert_json_snapshot!(summary(&b));
}
