//! Inflections and corners of profiles against an independent oracle (dense sampling of the
//! curvature of each segment, corners from the control points), on random closed chains of
//! cubic Bézier segments joined smoothly or at corners, both ways round.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use antipodal::{inflections, CornerKind, Options, Profile, Segment};
use curve::{ParamCurve, SegmentKind, SplineCurve};
use numeric::certificate::Verdict;
use proptest::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// A closed chain of cubic Béziers round a star ([`testkit::profiles::bezier_chain`]), run
/// backwards when `reverse`; `None` where a wobble makes it cross itself.
fn chain(radii: &[f64], wobble: &[(f64, f64)], smooth: &[bool], reverse: bool) -> Option<Profile> {
    testkit::profiles::bezier_chain_profile(radii, wobble, smooth, 0, reverse)
}

/// Sign changes of the curvature by dense sampling: inside each segment, and across smooth
/// joints; with the smallest |κ| (times the size) beside any of them, to tell whether the
/// sampling resolves them.
fn sampled_inflections(p: &Profile, size: f64) -> (Vec<f64>, f64) {
    const N: usize = 2000;
    let mut out = Vec::new();
    let mut least = f64::INFINITY;
    let n = p.segments().len();
    for (i, seg) in p.segments().iter().enumerate() {
        let (a, b) = seg.curve().domain();
        let k = |x: f64| seg.jet(a + (b - a) * x).curvature();
        let mut prev = k(0.0);
        for j in 1..=N {
            let x = j as f64 / N as f64;
            let cur = k(x);
            // (Also in the last step: a root there is inside the segment, before the joint,
            // whose own comparison takes the sign at the very end.)
            if (cur > 0.0) != (prev > 0.0) {
                out.push(i as f64 + x);
                least = least.min(cur.abs().min(prev.abs()) * size);
            }
            prev = cur;
        }
        // Across the joint at the start of the next segment, where it is smooth.
        let next = &p.segments()[(i + 1) % n];
        let smooth = p
            .joints()
            .iter()
            .any(|jt| jt.u as usize == (i + 1) % n && jt.kind == curve::JointKind::Smooth);
        if smooth {
            let (na, _) = next.curve().domain();
            let kn = next.jet(na).curvature();
            let kb = k(1.0);
            if (kn > 0.0) != (kb > 0.0) {
                out.push(((i + 1) % n) as f64);
            }
            least = least.min(kn.abs().min(kb.abs()) * size);
        }
    }
    out.sort_by(f64::total_cmp);
    (out, least)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Every inflection the sampling resolves is found, nothing else; the corners are the
    /// joints where the control points turn, convex where they turn the profile's way.
    fn profile_inflections_match_dense_sampling(
        radii in proptest::collection::vec(1.0f64..2.0, 3..8),
        wobble in proptest::collection::vec((-0.4f64..0.4, -0.4f64..0.4), 8),
        smooth in proptest::collection::vec(any::<bool>(), 8),
        reverse in any::<bool>(),
    ) {
        let n = radii.len();
        let Some(p) = chain(&radii, &wobble[..n], &smooth[..n], reverse) else {
            return Ok(());
        };
        let r = inflections(&p, &Options::default()).unwrap();
        let size = 4.0;
        let (want, least) = sampled_inflections(&p, size);
        // Resolved: every sign change clear of the sampling's own noise.
        prop_assume!(least > 1e-6);
        prop_assert_eq!(r.inflections.len(), want.len(), "found {:?}, sampled {:?}", r.inflections, want);
        if !want.is_empty() {
            WITH_INFLECTIONS.fetch_add(1, Ordering::Relaxed);
        }
        if want.iter().any(|&u| u.fract() == 0.0) {
            AT_JOINTS.fetch_add(1, Ordering::Relaxed);
        }
        for (f, w) in r.inflections.iter().zip(&want) {
            testkit::prop_assert_near!(f.u, w, 2e-3, "{} against {}", f.u, w);
            let on = p.jet(f.u).p;
            prop_assert!((on.x - f.p[0]).abs() < 1e-12 && (on.y - f.p[1]).abs() < 1e-12);
        }
        // Corners: the joints built sharp (their control points turn by more than 1e-9).
        let sharp: Vec<f64> = (0..n)
            .filter(|&i| {
                let k = if reverse { (n - i) % n } else { i };
                !smooth[k]
            })
            .map(|i| i as f64)
            .collect();
        let mut got: Vec<f64> = r.corner_list().iter().map(|c| c.u).collect();
        got.sort_by(f64::total_cmp);
        let mut sharp = sharp;
        sharp.sort_by(f64::total_cmp);
        prop_assert_eq!(&got, &sharp);
        for c in r.corner_list() {
            let convex = c.turn * p.orientation() > 0.0;
            prop_assert_eq!(c.kind == CornerKind::Convex, convex);
        }
    }
}

static WITH_INFLECTIONS: AtomicUsize = AtomicUsize::new(0);
static AT_JOINTS: AtomicUsize = AtomicUsize::new(0);

/// Runs the property and checks that it is not vacuous: profiles with inflections, some of
/// them at smooth joints.
#[test]
fn profile_inflections_match_dense_sampling_and_many() {
    profile_inflections_match_dense_sampling();
    let (w, j) = (
        WITH_INFLECTIONS.load(Ordering::Relaxed),
        AT_JOINTS.load(Ordering::Relaxed),
    );
    assert!(w >= 100 && j >= 10, "with inflections {w}, at joints {j}");
}

/// A smooth closed curve given as a one-segment profile has the curve's inflections exactly.
#[test]
fn one_segment_profiles_have_the_curves_inflections() {
    let pts = [
        [0.0, 0.0],
        [2.0, -1.0],
        [4.0, 0.0],
        [4.5, 2.0],
        [2.0, 0.5],
        [-0.5, 2.0],
        [0.0, 0.0],
    ];
    let c = SplineCurve::clamped(3, &pts, None, None).unwrap();
    let alone = antipodal::inflections(&c, &Options::default()).unwrap();
    let p = testkit::profiles::one_spline(c);
    let r = inflections(&p, &Options::default()).unwrap();
    let inside: Vec<f64> = alone
        .inflections
        .iter()
        .map(|i| i.u)
        .filter(|&u| u > 0.0 && u < 1.0)
        .collect();
    let got: Vec<f64> = r.inflections.iter().map(|i| i.u).collect();
    assert_eq!(got, inside);
    assert!(!inside.is_empty());
}

/// Corners are listed, not taken for inflections; lines carry none; a bad segment is named.
#[test]
fn corners_lines_and_bad_segments() {
    use std::f64::consts::PI;
    // A D shape: a line and a half circle, two convex corners.
    let d = Profile::new(
        vec![
            Segment::line([0.0, 1.0], [0.0, -1.0]).unwrap(),
            Segment::arc([0.0, 0.0], 1.0, -PI / 2.0, PI / 2.0).unwrap(),
        ],
        None,
    )
    .unwrap();
    let r = inflections(&d, &Options::default()).unwrap();
    assert!(r.inflections.is_empty() && r.certified());
    assert_eq!(r.corner_list().len(), 2);
    assert!(r.corner_list().iter().all(|c| c.kind == CornerKind::Convex));
    testkit::assert_near!(r.corner_list()[0].turn, PI / 2.0, 1e-12);
    // A cusp inside a Bézier segment is refused, naming the segment.
    let cusp = SplineCurve::clamped(
        3,
        &[[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]],
        None,
        None,
    )
    .unwrap();
    let p = Profile::new(
        vec![
            Segment::line([1.0, 0.0], [0.0, 0.0]).unwrap(),
            Segment::spline(SegmentKind::Bezier, cusp).unwrap(),
        ],
        None,
    )
    .unwrap();
    let e = inflections(&p, &Options::default()).unwrap_err();
    assert!(e.to_string().starts_with("segment 1:"), "{e}");
}

/// A Bézier whose first three control points lie on one line (as written in decimals) has no
/// curvature at its start; rounding may put a sign change a few 1e-14 of its domain inside.
/// There, at a corner, the joint decides: no inflection is listed, and the result says the
/// curvature vanishes at the joint (octicons' flag-24 writes such a corner).
#[test]
fn a_curvature_vanishing_at_a_corner_is_not_an_inflection() {
    let cubic = |p: [[f64; 2]; 4]| {
        let c = SplineCurve::clamped(3, &p, None, None).unwrap();
        Segment::spline(SegmentKind::Bezier, c).unwrap()
    };
    let flag = Profile::new(
        vec![
            cubic([[19.77, 4.4], [19.76, 4.39], [19.73, 4.38], [19.72, 4.37]]),
            cubic([[19.72, 4.37], [19.66, 4.32], [19.6, 4.27], [19.53, 4.24]]),
            Segment::line([19.53, 4.24], [19.53, 3.0]).unwrap(),
            Segment::line([19.53, 3.0], [21.0, 3.0]).unwrap(),
            Segment::line([21.0, 3.0], [19.77, 4.4]).unwrap(),
        ],
        None,
    )
    .unwrap();
    let r = inflections(&flag, &Options::default()).unwrap();
    let near_corner = |u: f64| (u - 1.0).abs() < 1e-6;
    assert!(
        r.inflections.iter().all(|i| !near_corner(i.u)),
        "{:?}",
        r.inflections
    );
    assert!(
        r.corner_list().iter().any(|c| near_corner(c.u)),
        "{:?}",
        r.corners
    );
    assert!(!r.certified());
    assert!(
        r.reason().as_deref().is_some_and(|m| m.contains("corner")),
        "{:?}",
        r.reason()
    );
}
