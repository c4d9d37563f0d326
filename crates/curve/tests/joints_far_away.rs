//! A joint is a corner where its tangent turns by more than the contract's 1e-9 rad, beyond
//! what the rounding of its tangents can turn them by. Near the origin that rounding is far
//! below 1e-9; far from it, on short segments, it is not: a stadium with fillets of radius
//! 0.01 drawn at 1e8 has its tangents rounded 1.5e-6 apart, and with the bare 1e-9 its four
//! smooth joints were reflex corners. A drawing's joints mean the same wherever it lies.
#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use curve::{Affine, JointKind, Profile, Segment, SegmentKind, SplineCurve};
use proptest::prelude::*;
use std::f64::consts::PI;
use testkit::profiles::{bezier_chains, filleted_polygons};

/// A stadium centred at `at`: two lines of length `2 half` joined by half circles of radius
/// `r`, tangentially.
fn stadium(at: [f64; 2], r: f64, half: f64) -> Profile {
    let [x, y] = at;
    Profile::new(
        vec![
            Segment::line([x - half, y - r], [x + half, y - r]).unwrap(),
            Segment::arc([x + half, y], r, -PI / 2.0, PI / 2.0).unwrap(),
            Segment::line([x + half, y + r], [x - half, y + r]).unwrap(),
            Segment::arc([x - half, y], r, PI / 2.0, 3.0 * PI / 2.0).unwrap(),
        ],
        None,
    )
    .unwrap()
}

/// The closed polygon through `corners`.
fn polygon(corners: &[[f64; 2]]) -> Profile {
    let n = corners.len();
    let sides = (0..n)
        .map(|i| Segment::line(corners[i], corners[(i + 1) % n]).unwrap())
        .collect();
    Profile::new(sides, None).unwrap()
}

fn kinds(p: &Profile) -> Vec<JointKind> {
    p.joints().iter().map(|j| j.kind).collect()
}

#[test]
fn tangent_joints_far_from_the_origin_are_smooth() {
    // (Each of these had corners with the bare 1e-9: turns of 1.5e-6 and 1.2e-8.)
    for (at, r, half) in [(1e8, 0.01, 0.01), (1e9, 10.0, 3.0), (1e4, 1.0, 1.0)] {
        let p = stadium([at, -at], r, half);
        assert_eq!(kinds(&p), vec![JointKind::Smooth; 4], "{at:e} {r}");
        assert!(p.corners().next().is_none());
        assert!(p.smooth_turn() >= p.joints().iter().map(|j| j.turn.abs()).fold(0.0, f64::max));
    }
    // Near the origin the contract's turn is the rule (the rounding adds some 1e-15).
    let near = stadium([0.0, 0.0], 1.0, 1.0).smooth_turn();
    assert!(near < curve::CORNER_TURN * (1.0 + 1e-5), "{near:e}");
}

#[test]
fn a_small_true_corner_far_from_the_origin_stays_a_corner() {
    // A square at 1e8 whose sides are 1 long, the middle of its bottom side pushed in by 1e-5:
    // a reflex corner turning 4e-5, far beyond the tangents' rounding there (about 3e-8).
    let (x, y) = (1e8, 1e8);
    let c = [
        [x, y],
        [x + 0.5, y + 1e-5],
        [x + 1.0, y],
        [x + 1.0, y + 1.0],
        [x, y + 1.0],
    ];
    let p = polygon(&c);
    let k = kinds(&p);
    assert_eq!(k.len(), 5);
    assert!(
        k.iter().all(|&k| k != JointKind::Smooth),
        "{:?}",
        p.joints()
    );
    assert_eq!(k.iter().filter(|&&k| k == JointKind::Reflex).count(), 1);
}

#[test]
fn a_tiny_chamfer_far_from_the_origin_keeps_its_corners() {
    // A unit square at 1e8 with one corner cut by a chamfer 1e-6 long: its two joints turn by
    // 45°, where the legs' rounding (some 0.1 rad over 1e-6) would explain any turn; the
    // rounding taken is capped at 1e-3, and they stay corners.
    let (x, y) = (1e8, 1e8);
    let cut = 1e-6 / 2f64.sqrt();
    let c = [
        [x, y],
        [x + 1.0 - cut, y],
        [x + 1.0, y + cut],
        [x + 1.0, y + 1.0],
        [x, y + 1.0],
    ];
    let p = polygon(&c);
    assert!(
        kinds(&p).iter().all(|&k| k == JointKind::Convex),
        "{:?}",
        p.joints()
    );
    assert!(p.smooth_turn() <= curve::CORNER_TURN + 1e-3);
}

/// A quadratic B-spline far away whose interior knot of full multiplicity (the curve passes
/// through its middle control point, only C0 there) sits between legs of about 1e-3 along one
/// line (their directions rounded some 1e-5 apart), or turning by `turn`: the profile of the
/// curve is cut there only where it turns.
fn spline_with_a_double_knot(turn: f64) -> Profile {
    let (x, y) = (1e8 + 0.123, -7e7 + 0.456);
    let along = |d: f64, angle: f64| [x + d * angle.cos(), y + d * angle.sin()];
    let a = 0.3f64;
    let points = [
        along(-2.6e-3, a),
        along(-1.3e-3, a),
        along(0.0, a),
        along(0.7e-3, a + turn),
        along(1.4e-3, a + turn),
    ];
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0];
    let c = SplineCurve::clamped(2, &points, None, Some(knots)).unwrap();
    Profile::of_curve(
        Segment::spline(SegmentKind::BSpline, c).unwrap(),
        (0.0, 2.0),
    )
    .unwrap()
}

#[test]
fn a_double_knot_far_from_the_origin_is_a_corner_only_where_it_turns() {
    // (A turn of 0.01 is a corner.)
    let straight = spline_with_a_double_knot(0.0);
    assert_eq!(straight.segments().len(), 1, "{:?}", straight.joints());
    let bent = spline_with_a_double_knot(0.01);
    assert_eq!(bent.segments().len(), 2);
    assert_eq!(bent.corners().count(), 1);
}

/// The profile moved to `offset` and scaled by `scale` about the origin first.
fn moved(p: &Profile, scale: f64, offset: [f64; 2]) -> Profile {
    p.transformed(&Affine([scale, 0.0, 0.0, scale, offset[0], offset[1]]))
        .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(if std::env::var("CI").is_ok() { 64 } else { 256 }))]

    /// Metamorphic: filleted polygons (lines and tangent arcs, corners of at least 0.05 rad)
    /// and chains of cubics (smooth or cornered joints), scaled down to a hundredth (fillets
    /// down to some 1e-3, whose tangents round by up to 1e-4 at 1e8) and drawn up to 1e8 away,
    /// have the joints they have at the origin.
    #[test]
    fn joints_keep_their_kind_wherever_the_profile_lies(
        polygon in filleted_polygons(4..9, 8),
        chain in bezier_chains(3..7, 7, 0.4),
        scale in prop_oneof![Just(1.0), 1e-2f64..1.0],
        offset in (-1e8f64..1e8, -1e8f64..1e8),
    ) {
        for p in [polygon, chain].into_iter().flatten() {
            // (A chain folding back on itself, a joint within 0.01 rad of turning back, is
            // nearly a cusp, and whether its two segments cross far from the origin is the
            // crossing test's question, not this one.)
            if p.joints().iter().any(|j| j.turn.abs() > PI - 0.01) {
                continue;
            }
            let near = moved(&p, scale, [0.0, 0.0]);
            let far = moved(&p, scale, [offset.0, offset.1]);
            prop_assert_eq!(kinds(&near), kinds(&far));
            prop_assert_eq!(kinds(&near), kinds(&p));
        }
    }
}
