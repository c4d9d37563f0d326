//! Adversarial inputs for the topology seed (issue 39): nearly cocircular sites, parallel
//! lines 1e-9 apart, arcs the seed takes in very few chords, tiny features beside huge ones;
//! a seeded shape moved far, scaled, rotated and reversed; and dense CAD outlines (arcs as
//! chords, sides as runs of collinear pieces), exact and with rounded coordinates.
//!
//! Each is right and certified, or honestly uncertified (with a reason): judged by the
//! independent oracle of `drawn_shapes.rs` (dense boundary distances, the sampled Voronoi
//! diagram) wherever it is certified.

#![allow(clippy::unwrap_used, missing_docs)]

#[path = "common/graph.rs"]
mod graph;
#[path = "common/judge.rs"]
mod judge;
#[path = "common/sampled_voronoi.rs"]
mod sampled_voronoi;
#[path = "common/traced.rs"]
mod traced;

use curve::{Affine, Profile, Region, Segment, V2};
use judge::judge;
use medial::{MedialAxis, NodeKind};
use numeric::certificate::Verdict;
use testkit::outlines::polygon;
use traced::axis;

/// The axis of `region`: right by the oracle where certified, with a reason where not.
fn right_or_honest(name: &str, region: &Region) -> MedialAxis {
    let a = axis(region);
    if a.certified() {
        if let Err(e) = judge(region, &a) {
            panic!("{name}: certified and wrong: {e}");
        }
    } else {
        assert!(a.reason().is_some(), "{name}: uncertified without a reason");
    }
    a
}

/// A regular polygon of `n` sides about the origin (its sides tangent to one circle), each
/// corner moved by up to `jitter` (a fixed pseudo-random pattern).
fn regular(n: usize, jitter: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let p = V2::polar(std::f64::consts::TAU * i as f64 / n as f64);
            let wiggle = |k: f64| ((i as f64 + 1.0) * k).sin();
            [
                p.x + jitter * wiggle(12.9898),
                p.y + jitter * wiggle(78.233),
            ]
        })
        .collect()
}

fn count(a: &MedialAxis, kind: NodeKind) -> usize {
    a.nodes.iter().filter(|n| n.kind == kind).count()
}

/// Nearly cocircular sites: the sides of a regular polygon of 64 are tangent to one circle
/// (its centre a junction of all of them: the axis is certified, 64 corner leaves); moved by
/// 1e-9 and 1e-7 of the size, the junction parts into many close together.
#[test]
fn nearly_cocircular_sites() {
    let exact = right_or_honest(
        "regular 64",
        &Region::new(polygon(&regular(64, 0.0)), vec![]).unwrap(),
    );
    assert!(exact.certified(), "{:?}", exact.reason());
    assert_eq!(count(&exact, NodeKind::Corner), 64);
    for jitter in [1e-9, 1e-7] {
        let region = Region::new(polygon(&regular(64, jitter)), vec![]).unwrap();
        let a = right_or_honest("jittered 64", &region);
        if a.certified() {
            assert_eq!(count(&a, NodeKind::Corner), 64, "jitter {jitter}");
        }
    }
}

/// Four lines tangent to almost one circle: a square's sides and one more cut across a
/// corner, tangent to the inscribed circle to within 1e-9, in a polygon of 64 sides.
#[test]
fn four_lines_nearly_tangent_to_one_circle() {
    // The square [-1, 1]² with its corner at (1, 1) cut by a line tangent to the unit
    // circle at 45° (moved out by 1e-9), and the other corners rounded by many short sides
    // well away from the circle.
    let t = std::f64::consts::FRAC_1_SQRT_2 * (1.0 + 1e-9);
    let cut = 2.0 * t - 1.0; // where the cut meets x = 1 and y = 1
    let mut points = vec![[1.0, cut], [cut, 1.0]];
    for (cx, cy, a0) in [(-1.0, 1.0, 0.5), (-1.0, -1.0, 1.0), (1.0, -1.0, 1.5)] {
        for k in 0..20 {
            let angle = std::f64::consts::PI * (a0 + 0.5 * k as f64 / 19.0);
            points.push([cx * 0.9 + 0.1 * angle.cos(), cy * 0.9 + 0.1 * angle.sin()]);
        }
    }
    let region = Region::new(polygon(&points), vec![]).unwrap();
    right_or_honest("four tangent lines", &region);
}

/// Parallel lines 1e-9 of the size apart: a slot that narrow cut into a polygon of 60 sides,
/// and the two long sides of a sliver.
#[test]
fn parallel_lines_1e9_apart() {
    let mut slotted = regular(60, 0.0);
    let first = slotted[0];
    slotted.splice(
        0..1,
        [
            [first[0], first[1] - 1e-9],
            [0.0, -1e-9],
            [0.0, 1e-9],
            [first[0], first[1] + 1e-9],
        ],
    );
    if let Ok(region) = Region::new(polygon(&slotted), vec![]) {
        right_or_honest("slot", &region);
    }
    let mut sliver = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1e-9]];
    sliver.extend((1..60).map(|i| [1.0 - i as f64 / 60.0, 1e-9 * (1.0 - i as f64 / 120.0)]));
    if let Ok(region) = Region::new(polygon(&sliver), vec![]) {
        right_or_honest("sliver", &region);
    }
}

/// Tiny features beside huge ones: a notch of 1e-6 of the size in a side of a polygon of
/// 64 (right and certified: the seed's grid is 2e-9), and a pentagonal hole that size.
#[test]
fn tiny_features_beside_huge_ones() {
    let mut points = regular(64, 0.0);
    let (a, b) = (V2::from_arr(points[0]), V2::from_arr(points[1]));
    let m = (a + b) * 0.5;
    let inward = (b - a).perp().unit() * 1e-6;
    let along = (b - a).unit() * 1e-6;
    points.splice(
        1..1,
        [(m - along).arr(), (m + inward).arr(), (m + along).arr()],
    );
    let notched = right_or_honest("notch", &Region::new(polygon(&points), vec![]).unwrap());
    assert!(notched.certified(), "{:?}", notched.reason());
    // (Clockwise, against the outer boundary.)
    let corner = |i: usize| {
        let angle = -std::f64::consts::TAU * (i % 5) as f64 / 5.0;
        (V2::new(0.3, 0.1) + V2::polar(angle) * 1e-6).arr()
    };
    let hole: Vec<Segment> = (0..5)
        .map(|i| Segment::line(corner(i), corner(i + 1)).unwrap())
        .collect();
    let region = Region::new(
        polygon(&regular(64, 0.0)),
        vec![Profile::new(hole, None).unwrap()],
    );
    let holed = right_or_honest("tiny hole", &region.unwrap());
    assert!(holed.certified(), "{:?}", holed.reason());
}

/// A 10 × 6 rectangle with its corners rounded by quarter circles of radius `r`, each side
/// cut into `pieces` collinear lines.
fn rounded_rectangle(r: f64, pieces: usize) -> Profile {
    use std::f64::consts::FRAC_PI_2;
    let (w, h) = (10.0, 6.0);
    let mut segments = Vec::new();
    let side = |from: [f64; 2], to: [f64; 2], segments: &mut Vec<Segment>| {
        for k in 0..pieces {
            let at = |s: f64| {
                [
                    from[0] + s * (to[0] - from[0]),
                    from[1] + s * (to[1] - from[1]),
                ]
            };
            let (s0, s1) = (k as f64 / pieces as f64, (k + 1) as f64 / pieces as f64);
            segments.push(Segment::line(at(s0), at(s1)).unwrap());
        }
    };
    side([r, 0.0], [w - r, 0.0], &mut segments);
    segments.push(Segment::arc([w - r, r], r, -FRAC_PI_2, 0.0).unwrap());
    side([w, r], [w, h - r], &mut segments);
    segments.push(Segment::arc([w - r, h - r], r, 0.0, FRAC_PI_2).unwrap());
    side([w - r, h], [r, h], &mut segments);
    segments.push(Segment::arc([r, h - r], r, FRAC_PI_2, 2.0 * FRAC_PI_2).unwrap());
    side([0.0, h - r], [0.0, r], &mut segments);
    segments.push(Segment::arc([r, r], r, 2.0 * FRAC_PI_2, 3.0 * FRAC_PI_2).unwrap());
    Profile::new(segments, None).unwrap()
}

/// Arcs the seed takes in very few chords: fillets of radius 1e-3 of the size (one chord
/// each at the seed's sag) and of 1, on a rectangle whose sides are 12 lines each, with a
/// round hole of either radius.
#[test]
fn arcs_in_very_few_chords() {
    for r in [1e-2, 1.0] {
        let outer = rounded_rectangle(r, 12);
        for hole_radius in [1e-2, 1.0] {
            let hole = Segment::arc([4.0, 3.0], hole_radius, 0.0, std::f64::consts::TAU).unwrap();
            let hole = Profile::new(vec![hole], None).unwrap();
            let region = Region::new(outer.clone(), vec![hole]).unwrap();
            let a = right_or_honest("fillets", &region);
            assert!(
                a.certified(),
                "fillet {r}, hole {hole_radius}: {:?}",
                a.reason()
            );
        }
    }
}

/// A seeded shape under maps: the star of 100 lines (right by the oracle) moved far, scaled
/// by 1e±3, rotated and reversed keeps its certified axis, mapped (the same nodes and radii,
/// to 1e-9 of the size).
#[test]
fn a_seeded_star_under_maps() {
    let points: Vec<[f64; 2]> = (0..100)
        .map(|i| {
            let r = if i % 2 == 0 { 1.0 } else { 0.5 } * (1.0 + 0.1 * ((i as f64) * 1.7).sin());
            (V2::polar(std::f64::consts::TAU * i as f64 / 100.0) * r).arr()
        })
        .collect();
    let region = Region::new(polygon(&points), vec![]).unwrap();
    let base = right_or_honest("star 100", &region);
    assert!(base.certified(), "{:?}", base.reason());
    let (c, s) = (0.6f64, 0.8f64);
    let maps = [
        (Affine([1.0, 0.0, 0.0, 1.0, 1e4, -3e4]), 1.0),
        (Affine([1e3, 0.0, 0.0, 1e3, 0.0, 0.0]), 1e3),
        (Affine([1e-3, 0.0, 0.0, 1e-3, 5e-3, 0.0]), 1e-3),
        (Affine([c, s, -s, c, 0.25, 0.5]), 1.0),
    ];
    let reversed: Vec<[f64; 2]> = points.iter().rev().copied().collect();
    let mut cases: Vec<(Region, Affine, f64)> = maps
        .into_iter()
        .map(|(m, scale)| (region.transformed(&m).unwrap(), m, scale))
        .collect();
    cases.push((
        Region::new(polygon(&reversed), vec![]).unwrap(),
        Affine::IDENTITY,
        1.0,
    ));
    for (k, (moved, map, scale)) in cases.into_iter().enumerate() {
        // (Judged by the base's axis, mapped: the oracle takes seconds on a star.)
        let a = axis(&moved);
        assert!(a.certified(), "map {k}: {:?}", a.reason());
        assert_eq!(a.nodes.len(), base.nodes.len(), "map {k}");
        assert_eq!(a.edges.len(), base.edges.len(), "map {k}");
        let near = 1e-9 * moved.size();
        for n in &base.nodes {
            let at = map.apply(n.xy);
            let found = a.nodes.iter().any(|m| {
                m.kind == n.kind
                    && (V2::from_arr(m.xy) - V2::from_arr(at)).norm() <= near
                    && (m.radius - n.radius * scale).abs() <= near
            });
            assert!(found, "map {k}: no node at {at:?} for {n:?}");
        }
    }
}

/// The benchmarks' CAD outline of `n` lines, turned by the rotation (c, s) about the origin
/// and its coordinates rounded to `grid` (none: as computed).
fn dense(n: usize, (c, s): (f64, f64), grid: Option<f64>) -> Region {
    let points: Vec<[f64; 2]> = testkit::outlines::dense_outline(n)
        .into_iter()
        .map(|p| {
            let q = [c * p[0] - s * p[1], s * p[0] + c * p[1]];
            grid.map_or(q, |g| q.map(|x| (x / g).round() * g))
        })
        .collect();
    Region::new(polygon(&points), vec![]).unwrap()
}

/// Dense CAD outlines: a plate with rounded corners and a notch with rounded reflex corners,
/// its arcs as chords and its sides as runs of collinear pieces. Right by the oracle and
/// certified at 400 lines; at 1,500 certified and the same axis turned and reversed; with
/// coordinates rounded to 1e-3 (every joint of a run a corner, each convex one a branch of
/// the axis) certified too.
#[test]
fn dense_cad_outlines() {
    let a = right_or_honest("dense 400", &dense(400, (1.0, 0.0), None));
    assert!(a.certified(), "{:?}", a.reason());
    let base = axis(&dense(1500, (1.0, 0.0), None));
    assert!(base.certified(), "{:?}", base.reason());
    let (c, s) = (0.6, 0.8);
    let turned = axis(&dense(1500, (c, s), None));
    let mut reversed_points = testkit::outlines::dense_outline(1500);
    reversed_points.reverse();
    let reversed = axis(&Region::new(polygon(&reversed_points), vec![]).unwrap());
    for (name, a, map) in [
        ("turned", turned, Affine([c, s, -s, c, 0.0, 0.0])),
        ("reversed", reversed, Affine::IDENTITY),
    ] {
        assert!(a.certified(), "{name}: {:?}", a.reason());
        assert_eq!(a.nodes.len(), base.nodes.len(), "{name}");
        assert_eq!(a.edges.len(), base.edges.len(), "{name}");
        for n in &base.nodes {
            let at = map.apply(n.xy);
            let found = a.nodes.iter().any(|m| {
                m.kind == n.kind
                    && (V2::from_arr(m.xy) - V2::from_arr(at)).norm() <= 1e-9 * 100.0
                    && (m.radius - n.radius).abs() <= 1e-9 * 100.0
            });
            assert!(found, "{name}: no node at {at:?} for {n:?}");
        }
    }
    let rounded = axis(&dense(1500, (c, s), Some(1e-3)));
    assert!(rounded.certified(), "{:?}", rounded.reason());
    // (A branch at most convex joints of the runs: far more edges than the exact plate's.)
    assert!(rounded.edges.len() > 3 * base.edges.len());
}
