//! Tests of profiles: joints and their kinds, chains refused (gaps, cusps, crossings), jets.
#![allow(clippy::unwrap_used)]
use super::*;
use crate::segment::SegmentKind;
use crate::spline::SplineCurve;
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

/// A rectangle `w × h` with its corners rounded by arcs of radius `r` (`r = 0`: sharp),
/// counterclockwise unless `reverse`.
pub(crate) fn rounded_rectangle(w: f64, h: f64, r: f64, reverse: bool) -> Profile {
    let mut segs = Vec::new();
    let corners = [[w, 0.0], [w, h], [0.0, h], [0.0, 0.0]];
    for (k, c) in corners.iter().enumerate() {
        let dir = V2::polar(FRAC_PI_2 * k as f64);
        let prev = V2::from_arr(corners[(k + 3) % 4]);
        let c = V2::from_arr(*c);
        segs.push(Segment::line((prev + dir * r).arr(), (c - dir * r).arr()).unwrap());
        if r > 0.0 {
            let centre = c - dir * r + dir.perp() * r;
            let a = FRAC_PI_2 * k as f64 - FRAC_PI_2;
            segs.push(Segment::arc(centre.arr(), r, a, a + FRAC_PI_2).unwrap());
        }
    }
    if reverse {
        segs = segs.iter().rev().map(|s| s.reversed().unwrap()).collect();
    }
    Profile::new(segs, None).unwrap()
}

#[test]
fn rounded_rectangles_have_smooth_joints_and_sharp_ones_convex_corners() {
    for reverse in [false, true] {
        let p = rounded_rectangle(4.0, 2.0, 0.5, reverse);
        assert_eq!(p.segments().len(), 8);
        assert!(p.is_closed());
        assert_eq!(p.orientation(), if reverse { -1.0 } else { 1.0 });
        assert!(
            p.joints().iter().all(|j| j.kind == JointKind::Smooth),
            "{:?}",
            p.joints()
        );
        let q = rounded_rectangle(4.0, 2.0, 0.0, reverse);
        assert_eq!(q.corners().count(), 4);
        for j in q.joints() {
            assert_eq!(j.kind, JointKind::Convex);
            let want = if reverse { -FRAC_PI_2 } else { FRAC_PI_2 };
            testkit::assert_near!(j.turn, want, 1e-15, "{j:?}");
        }
    }
}

#[test]
fn an_l_shape_has_one_reflex_corner() {
    let pts = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ];
    let segs = (0..6)
        .map(|i| Segment::line(pts[i], pts[(i + 1) % 6]).unwrap())
        .collect();
    let p = Profile::new(segs, None).unwrap();
    let reflex: Vec<f64> = p
        .joints()
        .iter()
        .filter(|j| j.kind == JointKind::Reflex)
        .map(|j| j.u)
        .collect();
    assert_eq!(reflex, vec![3.0]);
    assert_eq!(p.corners().count(), 6);
}

#[test]
fn bad_chains_are_refused_naming_the_segment() {
    let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
    let gap = Profile::new(
        vec![l([0.0, 0.0], [1.0, 0.0]), l([1.0, 1e-6], [1.0, 1.0])],
        None,
    );
    assert!(matches!(gap, Err(Error::Gap { segment: 1, .. })), "{gap:?}");
    // Within the contract's tolerance: joined.
    let near = Profile::new(
        vec![l([0.0, 0.0], [1.0, 0.0]), l([1.0, 1e-10], [1.0, 1.0])],
        None,
    );
    assert!(near.is_ok());
    let back = Profile::new(
        vec![l([0.0, 0.0], [1.0, 0.0]), l([1.0, 0.0], [0.5, 0.0])],
        None,
    );
    assert!(
        matches!(back, Err(Error::Cusp { segment: 1, .. })),
        "{back:?}"
    );
    let open = Profile::new(
        vec![l([0.0, 0.0], [1.0, 0.0]), l([1.0, 0.0], [1.0, 1.0])],
        Some(true),
    );
    assert!(
        matches!(open, Err(Error::Gap { segment: 0, .. })),
        "{open:?}"
    );
    let flat = Profile::new(
        vec![l([0.0, 0.0], [1.0, 0.0]), l([1.0, 0.0], [0.0, 0.0])],
        None,
    );
    assert!(flat.is_err());
    assert!(matches!(
        Profile::new(Vec::new(), None),
        Err(Error::EmptyProfile)
    ));
}

#[test]
fn crossing_chains_are_refused_naming_both_segments() {
    let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
    // A bow tie: its second and fourth sides cross at (1, 1).
    let tie = Profile::new(
        vec![
            l([0.0, 0.0], [2.0, 0.0]),
            l([2.0, 0.0], [0.0, 2.0]),
            l([0.0, 2.0], [2.0, 2.0]),
            l([2.0, 2.0], [0.0, 0.0]),
        ],
        None,
    );
    match tie {
        Err(Error::SelfCrossing {
            first: 1,
            second: 3,
            at,
        }) => {
            assert!(
                (at[0] - 1.0).abs() < 1e-12 && (at[1] - 1.0).abs() < 1e-12,
                "{at:?}"
            );
        }
        other => panic!("{other:?}"),
    }
    // An arc cutting through two lines of the same profile (x = 4 at y = 0.4, y = 0 at
    // x = 2 ± 1.79).
    let a0 = 0.8f64.atan2(2.0);
    let cut = Profile::new(
        vec![
            l([0.0, 0.0], [4.0, 0.0]),
            l([4.0, 0.0], [4.0, 2.0]),
            Segment::arc([2.0, 1.2], 4.64f64.sqrt(), a0, -PI - a0).unwrap(),
        ],
        None,
    );
    assert!(matches!(cut, Err(Error::SelfCrossing { .. })), "{cut:?}");
    // Rounded and sharp rectangles, both ways round, do not cross.
    for r in [0.0, 0.3, 0.9] {
        for reverse in [false, true] {
            let _ = rounded_rectangle(4.0, 2.0, r, reverse);
        }
    }
}

proptest! {
    /// On random polygons (exact as polylines) the crossing test agrees with testing every
    /// pair of sides that are not neighbours by the signs of four cross products.
    #[test]
    fn polygon_crossings_match_brute_force(
        pts in proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 4..10),
    ) {
        let v: Vec<V2> = pts.iter().map(|&(x, y)| V2::new(x, y)).collect();
        let n = v.len();
        let side = |p: V2, q: V2, r: V2| (q - p).cross(r - p);
        let proper = |a: V2, b: V2, c: V2, d: V2| {
            side(c, d, a) * side(c, d, b) < 0.0 && side(a, b, c) * side(a, b, d) < 0.0
        };
        let crossing = (0..n).any(|i| {
            (i + 2..n).any(|j| {
                !(i == 0 && j == n - 1) && proper(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])
            })
        });
        let segs: Vec<Segment> = (0..n)
            .map(|k| Segment::line(v[k].arr(), v[(k + 1) % n].arr()).unwrap())
            .collect();
        match Profile::new(segs, None) {
            Ok(_) => prop_assert!(!crossing),
            Err(Error::SelfCrossing { first, second, .. }) => {
                prop_assert!(crossing);
                prop_assert!(first < second);
            }
            // (Turning back exactly, or no area: not from random points.)
            Err(e) => prop_assert!(false, "{e}"),
        }
    }
}

#[test]
fn an_arc_joined_tangentially_to_an_arc_bent_the_other_way_is_smooth() {
    // An S: two half circles.
    let a = Segment::arc([1.0, 0.0], 1.0, PI, 0.0).unwrap();
    let b = Segment::arc([3.0, 0.0], 1.0, PI, TAU_PLUS).unwrap();
    let s = Profile::new(vec![a, b], None).unwrap();
    assert!(!s.is_closed());
    assert_eq!(s.joints().len(), 1);
    assert_eq!(s.joints()[0].kind, JointKind::Smooth);
}
const TAU_PLUS: f64 = 2.0 * PI;

proptest! {
    /// The profile's jets are its segments' jets, scaled by the linear map of parameters,
    /// and agree with finite differences of its points inside each segment.
    #[test]
    fn jets_are_the_segments_scaled(
        w in 0.5f64..10.0, h in 0.5f64..10.0, frac in 0.05f64..0.45,
        u in 0.0f64..8.0, reverse in any::<bool>(),
    ) {
        let p = rounded_rectangle(w, h, frac * w.min(h), reverse);
        let (i, x) = p.locate(u);
        prop_assume!(x > 1e-3 && x < 1.0 - 1e-3);
        let j = p.jet(u);
        let e = 1e-6;
        let (a, b) = (p.jet_to(u - e, 0).p, p.jet_to(u + e, 0).p);
        let d1 = (b - a) * (0.5 / e);
        prop_assert!((d1 - j.d1).norm() <= 1e-6 * (1.0 + j.d1.norm()), "{d1:?} {:?}", j.d1);
        let seg = &p.segments()[i];
        let (s0, s1) = seg.curve().domain();
        let own = seg.curve().jet(s0 + x * (s1 - s0));
        prop_assert!((own.p - j.p).norm() <= 1e-12 * (w + h));
        prop_assert!((own.d1 * (s1 - s0) - j.d1).norm() <= 1e-12 * (1.0 + j.d1.norm()));
        prop_assert_eq!(p.profile_param(i, s0 + x * (s1 - s0)), u);
    }
}

#[test]
fn open_bezier_chains_take_the_side_of_their_turn() {
    let b1 = SplineCurve::clamped(
        3,
        &[[0.0, 0.0], [1.0, 0.0], [2.0, 0.5], [3.0, 0.0]],
        None,
        None,
    )
    .unwrap();
    let b2 = SplineCurve::clamped(2, &[[3.0, 0.0], [3.5, -1.0], [4.0, -1.0]], None, None).unwrap();
    let p = Profile::new(
        vec![
            Segment::spline(SegmentKind::Bezier, b1).unwrap(),
            Segment::spline(SegmentKind::Bezier, b2).unwrap(),
        ],
        None,
    )
    .unwrap();
    // Arriving heading down-right at 45°, leaving at atan(−2): a right turn.
    assert_eq!(p.joints().len(), 1);
    assert_eq!(p.joints()[0].kind, JointKind::Reflex);
    assert!(p.joints()[0].turn < 0.0);
}
