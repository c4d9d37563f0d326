//! The zero-set extractor on functions whose zero sets are known exactly.
#![allow(clippy::unwrap_used)]
mod common;
use bspline::tensor::TensorBSpline;
use common::*;
use proptest::prelude::*;
use zeroset::{zero_set, ZeroSet, ZeroSetOptions};

const UNIT: [f64; 4] = [0.0, 1.0, 0.0, 1.0];

fn run(f: &TensorBSpline) -> ZeroSet {
    let z = zero_set(f, &ZeroSetOptions::default()).unwrap();
    assert!(z.complete);
    // Every vertex is on F = 0 to rounding.
    let scale = f.max_abs_coef();
    for b in &z.branches {
        for p in &b.pts {
            assert!(
                f.eval(p[0], p[1]).abs() <= 1e-7 * scale,
                "{p:?} F = {}",
                f.eval(p[0], p[1])
            );
        }
    }
    z
}

/// Points of a circle all lie within `tol` of some branch.
fn covers_circle(z: &ZeroSet, c: [f64; 2], rho: f64, tol: f64) -> bool {
    (0..400).all(|k| {
        let a = k as f64 * std::f64::consts::TAU / 400.0;
        let q = [c[0] + rho * a.cos(), c[1] + rho * a.sin()];
        if q[0] < 0.0 || q[0] > 1.0 || q[1] < 0.0 || q[1] > 1.0 {
            return true;
        }
        z.branches
            .iter()
            .any(|b| dist_to_polyline(q, &b.pts) <= tol)
    })
}

#[test]
fn circle_is_one_closed_loop() {
    let z = run(&circle(0.5, 0.5, 0.3, UNIT));
    assert_eq!(z.branches.len(), 1);
    assert!(z.branches[0].closed);
    assert!(z.singular.is_empty() && z.isolated.is_empty());
    assert!(covers_circle(&z, [0.5, 0.5], 0.3, 2e-3));
}

/// Two lines crossing: one singular point, and each line is one polyline through it (the
/// arms leaving the crossing in opposite directions are joined).
#[test]
fn crossing_lines_give_two_branches_through_a_singular_point() {
    let f = plane(1.0, -1.0, 0.0, UNIT)
        .mul(&plane(1.0, 1.0, -1.0, UNIT))
        .unwrap();
    let z = run(&f);
    assert_eq!(z.singular.len(), 1);
    let s = z.singular[0];
    assert!(
        (s[0] - 0.5).abs() < 1e-6 && (s[1] - 0.5).abs() < 1e-6,
        "{s:?}"
    );
    assert_eq!(z.branches.len(), 2);
    let mut lines = [0, 0];
    for b in &z.branches {
        assert!(!b.closed);
        assert!(b.pts.contains(&s), "the crossing is a vertex of both lines");
        // All on t = r or all on t + r = 1, from border to border.
        let k = usize::from((b.pts[0][0] - b.pts[0][1]).abs() > 1e-9);
        lines[k] += 1;
        for p in &b.pts {
            let off = if k == 0 {
                p[0] - p[1]
            } else {
                p[0] + p[1] - 1.0
            };
            assert!(off.abs() < 1e-6, "{p:?} off line {k}");
        }
        let border = |p: [f64; 2]| p.iter().any(|&x| x == 0.0 || x == 1.0);
        assert!(border(b.pts[0]) && border(b.pts[b.pts.len() - 1]));
    }
    assert_eq!(lines, [1, 1]);
}

/// Three lines through one point (six arms): each line is one polyline through it.
#[test]
fn three_concurrent_lines_give_three_branches() {
    let f = plane(1.0, -1.0, 0.0, UNIT)
        .mul(&plane(1.0, 1.0, -1.0, UNIT))
        .unwrap()
        .mul(&plane(1.0, 0.0, -0.5, UNIT))
        .unwrap();
    let z = run(&f);
    assert_eq!(z.singular.len(), 1, "{:?}", z.singular);
    assert_eq!(z.branches.len(), 3);
    assert!(z
        .branches
        .iter()
        .all(|b| !b.closed && b.pts.contains(&z.singular[0])));
}

/// A figure eight (lemniscate-like quartic `(t² + r²)² = t² − r²` scaled into the square):
/// one closed curve through its own crossing.
#[test]
fn figure_eight_is_one_closed_branch() {
    // u = 2.2 (t − ½), v = 2.2 (r − ½): (u² + v²)² − (u² − v²) = 0.
    let u = lin(-1.1, 2.2, 0.0, 1.0);
    let one = cst(1.0, 0.0, 1.0);
    let u2 = u.mul(&u).unwrap();
    let sum = TensorBSpline::sum_of_outer(&[(u2.clone(), one.clone()), (one.clone(), u2.clone())])
        .unwrap();
    let diff =
        TensorBSpline::sum_of_outer(&[(u2.clone(), one.clone()), (one.clone(), u2.scale(-1.0))])
            .unwrap();
    let f = sum.mul(&sum).unwrap().sub(&diff).unwrap();
    let z = run(&f);
    assert_eq!(z.singular.len(), 1);
    assert!((z.singular[0][0] - 0.5).abs() < 1e-6 && (z.singular[0][1] - 0.5).abs() < 1e-6);
    assert_eq!(
        z.branches.len(),
        1,
        "{:?}",
        z.branches.iter().map(|b| b.pts.len()).collect::<Vec<_>>()
    );
    assert!(z.branches[0].closed);
    // Both lobes are there: points at u = ±1 (t = ½ ± 1/2.2) on r = ½.
    for t in [0.5 - 1.0 / 2.2, 0.5 + 1.0 / 2.2] {
        assert!(z
            .branches
            .iter()
            .any(|b| dist_to_polyline([t, 0.5], &b.pts) < 2e-3));
    }
}

#[test]
fn nested_small_loops_are_all_found() {
    // Three concentric circles, the inner one tiny, and a separate tiny circle.
    let radii = [0.3, 0.1, 0.004];
    let mut f = circle(0.45, 0.5, radii[0], UNIT);
    for r in &radii[1..] {
        f = f.mul(&circle(0.45, 0.5, *r, UNIT)).unwrap();
    }
    f = f.mul(&circle(0.85, 0.15, 0.002, UNIT)).unwrap();
    let z = run(&f);
    assert_eq!(
        z.branches.len(),
        4,
        "{:?}",
        z.branches.iter().map(|b| b.pts.len()).collect::<Vec<_>>()
    );
    assert!(z.branches.iter().all(|b| b.closed));
    for r in radii {
        assert!(
            covers_circle(&z, [0.45, 0.5], r, 2e-3 + 1e-3 * r),
            "radius {r}"
        );
    }
    assert!(covers_circle(&z, [0.85, 0.15], 0.002, 1e-3));
}

#[test]
fn circle_touching_and_crossing_the_border() {
    // Tangent to r = 0 at t = 0.5, and a circle cut by the border t = 1.
    let f = circle(0.5, 0.3, 0.3, UNIT)
        .mul(&circle(1.0, 0.8, 0.15, UNIT))
        .unwrap();
    let z = run(&f);
    assert!(covers_circle(&z, [0.5, 0.3], 0.3, 2e-3));
    assert!(covers_circle(&z, [1.0, 0.8], 0.15, 2e-3));
    // The cut circle is one open branch from border to border.
    let open: Vec<_> = z.branches.iter().filter(|b| !b.closed).collect();
    assert!(!open.is_empty());
    for b in open {
        let (a, e) = (b.pts[0], b.pts[b.pts.len() - 1]);
        let on_border = |p: [f64; 2]| p[0] == 0.0 || p[0] == 1.0 || p[1] == 0.0 || p[1] == 1.0;
        assert!(
            on_border(a) || on_border(e) || !z.singular.is_empty(),
            "{a:?} {e:?}"
        );
    }
}

#[test]
fn isolated_point_is_reported() {
    // (t − 0.3)² + (r − 0.6)²: a single zero.
    let f = circle(0.3, 0.6, 0.0, UNIT);
    let z = zero_set(&f, &ZeroSetOptions::default()).unwrap();
    assert!(z.branches.is_empty());
    assert_eq!(z.isolated.len(), 1);
    assert!((z.isolated[0][0] - 0.3).abs() < 1e-12 && (z.isolated[0][1] - 0.6).abs() < 1e-12);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    /// Two random circles inside the square: two loops, or one curve with crossings where they
    /// meet; either way every point of both circles is covered.
    #[test]
    fn random_circle_pairs(cx in 0.2..0.8f64, cy in 0.2..0.8f64, r in 0.01..0.19f64,
                           dx in 0.2..0.8f64, dy in 0.2..0.8f64, s in 0.01..0.19f64) {
        let f = circle(cx, cy, r, UNIT).mul(&circle(dx, dy, s, UNIT)).unwrap();
        let z = run(&f);
        prop_assert!(covers_circle(&z, [cx, cy], r, 3e-3));
        prop_assert!(covers_circle(&z, [dx, dy], s, 3e-3));
        let d = (cx - dx).hypot(cy - dy);
        if d > r + s + 1e-3 || d < (r - s).abs() - 1e-3 {
            prop_assert_eq!(z.branches.len(), 2);
            prop_assert!(z.branches.iter().all(|b| b.closed));
        }
    }
}

/// Where lines `i` and `j` (`a t + b r + c = 0`) cross.
fn crossing(l: [f64; 3], m: [f64; 3]) -> Option<[f64; 2]> {
    let det = l[0] * m[1] - l[1] * m[0];
    (det.abs() > 1e-12).then(|| {
        [
            (l[1] * m[2] - l[2] * m[1]) / det,
            (l[2] * m[0] - l[0] * m[2]) / det,
        ]
    })
}

/// Three lines through the square (at least 15° apart, crossings inside and apart
/// from each other and from the border, or outside): every crossing is a singular point,
/// every point of every line is covered, every vertex lies on a line, and every branch
/// end is on the border or at a crossing.
///
/// (Each line is one branch through its crossings, with exactly one singular point per
/// crossing, in all but about two cases in ten thousand: within ~1e-5 of a crossing the flat
/// region, where |F| is below its rounding bound, can come out of the subdivision in
/// pieces along an arm; a piece beyond the reach of the crossing's own becomes a second
/// singular point and the arm is cut there, or (rarer) the arms are paired wrongly and a
/// polyline turns from one line into another at the crossing. What is asserted allows
/// that — extra singular points only within 1e-5 of a crossing, at most two extra
/// branches per crossing, branches may change line only at a crossing — and nothing
/// more.)
fn line_arrangement(p: &[f64], a: &[f64]) -> Result<(), TestCaseError> {
    let lines: Vec<[f64; 3]> = (0..3)
        .map(|i| {
            let (s, c) = a[i].sin_cos();
            // Through (p[2i], p[2i+1]) with direction (c, s): normal (−s, c).
            [-s, c, s * p[2 * i] - c * p[2 * i + 1]]
        })
        .collect();
    let mut inside = Vec::new();
    for i in 0..3 {
        for j in i + 1..3 {
            let mut da = (a[i] - a[j]).abs();
            da = da.min(std::f64::consts::PI - da);
            prop_assume!(da > 15f64.to_radians());
            if let Some(q) = crossing(lines[i], lines[j]) {
                let margin = q
                    .iter()
                    .map(|&x| x.min(1.0 - x))
                    .fold(f64::INFINITY, f64::min);
                prop_assume!(!(-0.05..=0.05).contains(&margin));
                if margin > 0.0 {
                    inside.push(q);
                }
            }
        }
    }
    for i in 0..inside.len() {
        for j in i + 1..inside.len() {
            prop_assume!((inside[i][0] - inside[j][0]).hypot(inside[i][1] - inside[j][1]) > 0.05);
        }
    }
    let mut f = plane(lines[0][0], lines[0][1], lines[0][2], UNIT);
    for l in &lines[1..] {
        f = f.mul(&plane(l[0], l[1], l[2], UNIT)).unwrap();
    }
    let z = run(&f);
    for q in &inside {
        prop_assert!(
            z.singular
                .iter()
                .any(|s| (s[0] - q[0]).hypot(s[1] - q[1]) < 1e-6),
            "crossing {q:?} lost"
        );
    }
    for s in &z.singular {
        prop_assert!(
            inside
                .iter()
                .any(|q| (s[0] - q[0]).hypot(s[1] - q[1]) < 1e-5),
            "singular point {s:?} at no crossing"
        );
    }
    prop_assert!(z.isolated.is_empty(), "isolated points {:?}", z.isolated);
    prop_assert!(
        z.branches.len() >= 3 && z.branches.len() <= 3 + 2 * inside.len(),
        "{} branches",
        z.branches.len()
    );
    let border = |p: [f64; 2]| p.iter().any(|&x| x == 0.0 || x == 1.0);
    let near_crossing = |p: [f64; 2]| {
        inside
            .iter()
            .any(|q| (q[0] - p[0]).hypot(q[1] - p[1]) < 1e-5)
    };
    for b in &z.branches {
        for p in [b.pts[0], b.pts[b.pts.len() - 1]] {
            prop_assert!(border(p) || near_crossing(p), "branch end {p:?} nowhere");
        }
    }
    for b in &z.branches {
        for p in &b.pts {
            let off = lines
                .iter()
                .map(|l| (l[0] * p[0] + l[1] * p[1] + l[2]).abs())
                .fold(f64::INFINITY, f64::min);
            prop_assert!(off < 1e-6, "vertex {p:?} off the lines by {off:e}");
        }
    }
    for l in &lines {
        // Points of the line inside the square are covered.
        for k in 0..=50 {
            let t = k as f64 / 50.0;
            // Parametrise by t when the line is not vertical, else by r.
            let q = if l[1].abs() > 0.3 {
                [t, -(l[0] * t + l[2]) / l[1]]
            } else {
                [-(l[1] * t + l[2]) / l[0], t]
            };
            if q.iter().all(|&x| (0.0..=1.0).contains(&x)) {
                prop_assert!(
                    z.branches
                        .iter()
                        .any(|b| dist_to_polyline(q, &b.pts) < 2e-3),
                    "{q:?} not covered"
                );
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn random_line_arrangements(p in prop::collection::vec(0.2..0.8f64, 6), a in prop::collection::vec(0.0..std::f64::consts::PI, 3)) {
        line_arrangement(&p, &a)?;
    }
}

/// Arrangements that failed: at each, two arms of a crossing meet at a small angle to a grid
/// line, and within ~1e-5 of the crossing F is below its rounding bound over a band along
/// each arm.
///
/// - A column of flat leaves inside the band of one arm, 1.2e-9 beside it, had no arc
///   attached and came out as an isolated point 6.4e-6 from the crossing, though ∂F/∂t is
///   −1.1e-6 all over it (F has no critical point there, so no isolated zero and no loop).
/// - A patch beside a crossing held one arm at its corner (F within rounding there) and the
///   other entering through the same edge; the edge root was sought from the chord between
///   the end values, which starts at that corner, and the corner zero was taken for the root
///   of the sign change. The arc bridged the two arms and the arm's end below had no partner.
/// - An arm passing within rounding of a patch corner was seen on the two lines through it
///   by the patches on either side, 8e-8 apart; the border of the crossing's grown hull ran
///   between the two ends, so one went to the crossing and the other ended a branch 1.2e-5
///   from it.
/// - An arm passing through a patch corner (within rounding) was traced by the patches on
///   either side, and the patch diagonally across cut the corner with a duplicate 2e-7 long,
///   within the uncertainty of its two ends (1.8e-7 and 2.6e-8), which found nothing to meet:
///   a piece of debris ending nowhere, 1.5e-5 from the crossing.
#[test]
fn line_arrangements_that_failed() {
    let cases: [([f64; 6], [f64; 3]); 4] = [
        (
            [
                0.37692335199058014,
                0.3315670999995136,
                0.4112656074539773,
                0.2,
                0.21931415093892334,
                0.6338232010618492,
            ],
            [1.5487684403891682, 2.0723246717697346, 0.8236772969354804],
        ),
        (
            [
                0.7536440403572238,
                0.2946764027360524,
                0.319045177330317,
                0.6159995382815101,
                0.40552446284559696,
                0.7334768137755336,
            ],
            [2.2567206084812304, 0.018648290853216603, 1.681587447701493],
        ),
        (
            [
                0.4198709609397856,
                0.6981371367242156,
                0.2948165412804193,
                0.30977828023924264,
                0.5396750568991904,
                0.2785145871861411,
            ],
            [1.0935689123606356, 3.049613557622173, 2.682199747312916],
        ),
        (
            [
                0.507693128792043,
                0.6425276382172478,
                0.5797369409387482,
                0.7487752691199887,
                0.24905335299221262,
                0.6940160831899791,
            ],
            [0.5138878375110767, 0.9625656626829238, 0.14038493412677638],
        ),
    ];
    for (p, a) in cases {
        line_arrangement(&p, &a).unwrap();
    }
}
