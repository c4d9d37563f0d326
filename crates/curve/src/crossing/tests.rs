//! Tests of the crossing and winding tests against fine samples, and of the edge test.
#![allow(clippy::unwrap_used)]
use super::*;
use crate::param::ParamCurve;
use crate::segment::SegmentKind;
use crate::spline::SplineCurve;
use proptest::prelude::*;

/// A closed chain of cubic Béziers through `corners`, with `inner` control points.
fn bezier_loop(corners: &[[f64; 2]], inner: &[[f64; 2]]) -> Vec<Segment> {
    let n = corners.len();
    (0..n)
        .map(|k| {
            let pts = [
                corners[k],
                inner[2 * k],
                inner[2 * k + 1],
                corners[(k + 1) % n],
            ];
            let c = SplineCurve::clamped(3, &pts, None, None).unwrap();
            Segment::spline(SegmentKind::Bezier, c).unwrap()
        })
        .collect()
}

/// Each segment sampled at `per` equal steps of its parameter, in order round the chain
/// (the first point again at the end).
fn sampled(segments: &[Segment], per: usize) -> Vec<(usize, V2)> {
    let mut out = Vec::new();
    for (i, s) in segments.iter().enumerate() {
        let (a, b) = s.curve().domain();
        for k in 0..per {
            out.push((
                i,
                s.curve().jet_to(a + (b - a) * k as f64 / per as f64, 0).p,
            ));
        }
    }
    out.push((0, out[0].1));
    out
}

/// Brute force on a closed chain sampled finely: the least (first, second) segments of
/// chords that meet and are not neighbours; and whether the chain comes closer to itself
/// than samples can judge (two chords not neighbours, not meeting, nearly parallel and
/// closer than a thousandth of the way along the chain between them: where it turns back
/// on itself at a spike, or nearly touches).
fn brute_crossing(segments: &[Segment], per: usize) -> (Option<(usize, usize)>, bool) {
    brute_crossing_near(segments, per, None)
}

/// [`brute_crossing`] on the chords within `0.02` of `near` only, where given.
fn brute_crossing_near(
    segments: &[Segment],
    per: usize,
    near: Option<V2>,
) -> (Option<(usize, usize)>, bool) {
    let pts = sampled(segments, per);
    let n = pts.len() - 1;
    let mut along = vec![0.0];
    for w in pts.windows(2) {
        along.push(along[along.len() - 1] + (w[1].1 - w[0].1).norm());
    }
    let total = along[n];
    let mut best: Option<(usize, usize)> = None;
    let mut unclear = false;
    let gap_of = |a: V2, b: V2, c: V2, d: V2| {
        let dx = (a.x.min(b.x) - c.x.max(d.x)).max(c.x.min(d.x) - a.x.max(b.x));
        let dy = (a.y.min(b.y) - c.y.max(d.y)).max(c.y.min(d.y) - a.y.max(b.y));
        dx.max(dy)
    };
    let kept: Vec<usize> = (0..n)
        .filter(|&i| {
            near.is_none_or(|x| {
                crate::geom::distance_to_segment(x.arr(), pts[i].1.arr(), pts[i + 1].1.arr()) < 0.02
            })
        })
        .collect();
    for (k, &i) in kept.iter().enumerate() {
        for &j in &kept[k + 1..] {
            if j < i + 2 || (i == 0 && j == n - 1) {
                continue;
            }
            let (a, b, c, d) = (pts[i].1, pts[i + 1].1, pts[j].1, pts[j + 1].1);
            let way = (along[j] - along[i + 1]).min(total - along[j + 1] + along[i]);
            let room = 1e-9 + 1e-3 * way;
            if gap_of(a, b, c, d) > room {
                continue;
            }
            if meet(a, b, c, d).is_some() {
                let key = (pts[i].0.min(pts[j].0), pts[i].0.max(pts[j].0));
                best = Some(best.map_or(key, |b: (usize, usize)| b.min(key)));
                continue;
            }
            let to =
                |p: V2, q: V2, r: V2| crate::geom::distance_to_segment(p.arr(), q.arr(), r.arr());
            let apart = to(a, c, d)
                .min(to(b, c, d))
                .min(to(c, a, b))
                .min(to(d, a, b));
            // (Beside a crossing, chords near it are as close but at its angle.)
            let sine = (b - a).cross(d - c).abs() / ((b - a).norm() * (d - c).norm());
            // (A NaN sine, of a chord of no length, is unclear too.)
            unclear |=
                apart <= room && sine.partial_cmp(&0.05) != Some(std::cmp::Ordering::Greater);
        }
    }
    (best, unclear)
}

/// A closed chain round the origin: corners at radii `radii` (angles evenly spread),
/// each cubic's inner points a third of the way along its chord moved by `wild` times
/// `moves` (small: a simple loop; large: loops and crossings).
fn chain_of(radii: &[f64], moves: &[(f64, f64)], wild: f64) -> Vec<Segment> {
    let n = radii.len();
    let corners: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            [radii[k] * a.cos(), radii[k] * a.sin()]
        })
        .collect();
    let inner: Vec<[f64; 2]> = (0..2 * n)
        .map(|j| {
            let (k, t) = (j / 2, if j % 2 == 0 { 1.0 / 3.0 } else { 2.0 / 3.0 });
            let (a, b) = (corners[k], corners[(k + 1) % n]);
            [
                a[0] + (b[0] - a[0]) * t + wild * moves[j].0,
                a[1] + (b[1] - a[1]) * t + wild * moves[j].1,
            ]
        })
        .collect();
    bezier_loop(&corners, &inner)
}

/// Random chains for [`chain_of`].
fn chains() -> impl Strategy<Value = (Vec<f64>, Vec<(f64, f64)>, f64)> {
    (3usize..7).prop_flat_map(|n| {
        (
            proptest::collection::vec(0.4f64..1.0, n),
            proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 2 * n),
            prop_oneof![0.05f64..0.4, 0.4f64..2.0],
        )
    })
}

/// A quintic whose control points lie on its chord, going forward, back and forward
/// again, retraces itself: a crossing, though all of it is flat. A chain that turns
/// sharply but not back does not cross. (One turning back at a joint is refused as a
/// cusp there by the profile.)
#[test]
fn a_stretch_retracing_itself_crosses() {
    let cubic = |pts: [[f64; 2]; 4]| {
        Segment::spline(
            SegmentKind::Bezier,
            SplineCurve::clamped(3, &pts, None, None).unwrap(),
        )
        .unwrap()
    };
    let line = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
    // (Its points within its chord: x runs 0 to 0.67, back to 0.33, on to 1.)
    let quintic = SplineCurve::clamped(
        5,
        &[
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 0.0],
            [0.0, 0.0],
            [0.0, 0.0],
            [1.0, 0.0],
        ],
        None,
        None,
    )
    .unwrap();
    let retracing = [
        Segment::spline(SegmentKind::Bezier, quintic).unwrap(),
        line([1.0, 0.0], [1.0, 1.0]),
        line([1.0, 1.0], [0.0, 0.0]),
    ];
    assert!(first_crossing(&retracing, true, 2.0).unwrap().is_some());
    let sharp = [
        line([0.0, 0.0], [2.0, 0.0]),
        cubic([[2.0, 0.0], [1.0, 0.01], [1.0, 1.0], [0.5, 1.0]]),
        line([0.5, 1.0], [0.0, 0.0]),
    ];
    assert!(first_crossing(&sharp, true, 2.0).unwrap().is_none());
}

/// Where a chain turns back at a knot inside a segment, or where the test halves a
/// stretch, it retraces itself; a repeated control point of a polyline spline is no touch.
#[test]
fn retraces_at_knots_and_halvings_cross_and_repeated_points_do_not() {
    let spline = |degree: usize, pts: &[[f64; 2]]| {
        Segment::spline(
            SegmentKind::BSpline,
            SplineCurve::clamped(degree, pts, None, None).unwrap(),
        )
        .unwrap()
    };
    let at_knot = [spline(1, &[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]])];
    assert!(first_crossing(&at_knot, false, 2.0).unwrap().is_some());
    let at_halving = [spline(3, &[[0.0, 0.0], [5.0, 0.0], [3.0, 0.0], [2.0, 0.0]])];
    assert!(first_crossing(&at_halving, false, 5.0).unwrap().is_some());
    let repeated = [
        spline(1, &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 1.0]]),
        Segment::line([1.0, 1.0], [0.0, 0.0]).unwrap(),
    ];
    assert_eq!(first_crossing(&repeated, true, 1.5).unwrap(), None);
}

proptest! {
    /// On random closed chains of cubics (loops within segments, crossings between them,
    /// sharp corners) the test by bounds agrees with every pair of chords of the chain
    /// sampled finely, where two samplings agree with each other (else the chain comes
    /// too close to itself for samples to tell).
    #[test]
    fn crossings_match_fine_samples((radii, moves, wild) in chains()) {
        let segments = chain_of(&radii, &moves, wild);
        let (fine, unclear) = brute_crossing(&segments, 400);
        prop_assume!(!unclear);
        let got = first_crossing(&segments, true, 2.0).unwrap();
        // (A crossing too small for the samples: looked for finely about it.)
        let confirmed = |g: &Crossing| {
            let (there, unclear) =
                brute_crossing_near(&segments, 50_000, Some(V2::from_arr(g.at)));
            there.is_some() || unclear
        };
        match (got, fine) {
            (Some(g), Some(f)) if (g.first, g.second) == f => {}
            (Some(g), Some(f)) => {
                prop_assert!((g.first, g.second) < f, "{g:?} after {f:?}");
                prop_assert!(confirmed(&g), "no crossing near {g:?}");
            }
            (None, None) => {}
            (None, Some(f)) => prop_assert!(false, "the crossing of {f:?} is missed"),
            (Some(g), None) => prop_assert!(confirmed(&g), "no crossing near {g:?}"),
        }
    }

    /// Whether a closed chain winds round a point agrees with the winding number of a
    /// fine polygon of it, for points not near it.
    #[test]
    fn winding_matches_a_fine_polygon(
        (radii, moves, wild) in chains(),
        p in (-1.5f64..1.5, -1.5f64..1.5),
    ) {
        let segments = chain_of(&radii, &moves, wild);
        let pts: Vec<V2> = sampled(&segments, 2000).into_iter().map(|(_, q)| q).collect();
        let p = V2::new(p.0, p.1);
        let near = pts
            .windows(2)
            .map(|w| crate::geom::distance_to_segment(p.arr(), w[0].arr(), w[1].arr()))
            .fold(f64::INFINITY, f64::min);
        prop_assume!(near > 1e-4);
        let want = winding(&pts[..pts.len() - 1], p) != 0;
        prop_assert_eq!(Outline::new(&segments, 2.0).winds_round(p).unwrap(), want);
    }

    /// Moved far from the origin and scaled, a chain crosses itself where it did.
    #[test]
    fn crossings_survive_moving_and_scaling(
        (radii, moves, wild) in chains(),
        shift in (-1e6f64..1e6, -1e6f64..1e6),
        scale in prop_oneof![Just(1e-6), Just(1.0), Just(1e6)],
    ) {
        let segments = chain_of(&radii, &moves, wild);
        let (fine, unclear) = brute_crossing(&segments, 400);
        prop_assume!(!unclear);
        let far: Vec<Segment> = segments
            .iter()
            .map(|s| {
                let pts: Vec<[f64; 2]> = s
                    .curve()
                    .control_points()
                    .iter()
                    .map(|p| [(p[0] + shift.0) * scale, (p[1] + shift.1) * scale])
                    .collect();
                let c = SplineCurve::clamped(3, &pts, None, None).unwrap();
                Segment::spline(SegmentKind::Bezier, c).unwrap()
            })
            .collect();
        let here = first_crossing(&segments, true, 2.0).unwrap();
        let there = first_crossing(&far, true, 2.0 * scale).unwrap();
        // (As [`crossings_match_fine_samples`] checks it.)
        prop_assume!(here.is_some() == fine.is_some());
        prop_assert_eq!(there.map(|c| c.first), here.map(|c| c.first));
    }
}

proptest! {
    /// The edge test agrees with solving for the meet in exact-enough arithmetic away from
    /// touching configurations.
    #[test]
    fn edges_meet_where_their_lines_cross_inside_both(
        p in proptest::collection::vec(-10.0f64..10.0, 8),
    ) {
        let (a, b, c, d) = (V2::new(p[0], p[1]), V2::new(p[2], p[3]), V2::new(p[4], p[5]), V2::new(p[6], p[7]));
        let den = (b - a).cross(d - c);
        prop_assume!(den.abs() > 1e-6);
        let t = (c - a).cross(d - c) / den;
        let u = (c - a).cross(b - a) / den;
        prop_assume!((t - 0.5).abs() < 0.5 - 1e-6 || (t - 0.5).abs() > 0.5 + 1e-6);
        prop_assume!((u - 0.5).abs() < 0.5 - 1e-6 || (u - 0.5).abs() > 0.5 + 1e-6);
        let inside = (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u);
        let got = meet(a, b, c, d);
        prop_assert_eq!(got.is_some(), inside);
        if let Some(m) = got {
            let want = a + (b - a) * t;
            prop_assert!((m - want).norm() < 1e-9 * (1.0 + want.norm()));
        }
    }
}
