//! Offsets where two sides of a region touch exactly at the distance (issue 38): a 100 × 100
//! plate with corners rounded by 10 and a round hole of radius 35 in its middle is exactly 15
//! wide at four points, so at 7.5 its offset is four corner pieces touching there (the
//! touching points taken as closed, as everywhere). Judged by an oracle of its own: the
//! distance to this plate in closed form (a rounded square's and a circle's), and the winding
//! number of the loops at every point of a grid, which must be 1 where the point is farther
//! than the distance from the boundary and 0 where it is nearer (an arc run the long way round,
//! or a stretch left out, shows there), apart from a margin about the distance itself.
#![allow(clippy::unwrap_used)]

mod common;
use common::ends;
use curve::{Affine, Profile, Region, Segment};
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use offset::{offsets, OffsetOptions, OffsetSegment, Offsets};
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use testkit::boundary_oracle::winding;

/// The plate's side, corner radius, and the hole's centre and radius.
const SIDE: f64 = 100.0;
const CORNER: f64 = 10.0;
const HOLE: ([f64; 2], f64) = ([50.0, 50.0], 35.0);

/// The plate with its hole, moved by `map` (a similarity).
fn plate(map: &Affine) -> Region {
    let q = FRAC_PI_2;
    let (a, b) = (CORNER, SIDE - CORNER);
    let outer = Profile::new(
        vec![
            Segment::line([a, 0.0], [b, 0.0]).unwrap(),
            Segment::arc([b, a], CORNER, -q, 0.0).unwrap(),
            Segment::line([SIDE, a], [SIDE, b]).unwrap(),
            Segment::arc([b, b], CORNER, 0.0, q).unwrap(),
            Segment::line([b, SIDE], [a, SIDE]).unwrap(),
            Segment::arc([a, b], CORNER, q, PI).unwrap(),
            Segment::line([0.0, b], [0.0, a]).unwrap(),
            Segment::arc([a, a], CORNER, PI, PI + q).unwrap(),
        ],
        None,
    )
    .unwrap();
    let hole = Profile::new(vec![Segment::arc(HOLE.0, HOLE.1, 0.0, TAU).unwrap()], None).unwrap();
    Region::new(outer, vec![hole])
        .unwrap()
        .transformed(map)
        .unwrap()
}

/// The signed distance from `p` (in the plate's own frame) to its boundary: positive inside.
fn signed_distance(p: [f64; 2]) -> f64 {
    // (A rounded square: the distance to its inner square, less the corner radius.)
    let half = 0.5 * SIDE - CORNER;
    let (qx, qy) = (
        (p[0] - 0.5 * SIDE).abs() - half,
        (p[1] - 0.5 * SIDE).abs() - half,
    );
    let outside = qx.max(0.0).hypot(qy.max(0.0)) + qx.max(qy).min(0.0);
    let to_plate = CORNER - outside;
    let to_hole = (p[0] - HOLE.0[0]).hypot(p[1] - HOLE.0[1]) - HOLE.1;
    to_plate.min(to_hole)
}

/// The inverse of the similarity `map`.
fn inverse(map: &Affine) -> Affine {
    let [a, b, c, d, e, f] = map.0;
    let det = a * d - b * c;
    let (ia, ib, ic, id) = (d / det, -b / det, -c / det, a / det);
    Affine([ia, ib, ic, id, -(ia * e + ic * f), -(ib * e + id * f)])
}

/// A loop as a closed polygon: lines as they are, arcs by chords of at most 1e-2 rad; the
/// gap at each joint must be rounding (relative to the coordinates).
fn polygon_of(segments: &[OffsetSegment]) -> Vec<[f64; 2]> {
    let mut points = Vec::new();
    for (k, s) in segments.iter().enumerate() {
        let (from, to) = ends(s);
        let next = ends(&segments[(k + 1) % segments.len()]).0;
        let gap = (to[0] - next[0]).hypot(to[1] - next[1]);
        let scale = to[0].abs().max(to[1].abs()).max(SIDE);
        assert!(gap <= 1e-12 * scale, "piece {k} ends {gap} from the next");
        match s {
            OffsetSegment::Arc {
                center,
                r,
                start,
                end,
            } => {
                let n = (((end - start).abs() / 1e-2).ceil() as usize).max(1);
                points.extend((0..n).map(|j| {
                    let a = start + (end - start) * j as f64 / n as f64;
                    [center[0] + r * a.cos(), center[1] + r * a.sin()]
                }));
            }
            _ => points.push(from),
        }
    }
    points
}

/// The offsets of the plate moved by `map` at `distances` (in the plate's frame), each
/// checked against the oracle: every point of each loop at the distance, and the loops'
/// winding number on a 120 × 120 grid 1 farther than the distance from the boundary and 0
/// nearer, beyond a margin of 0.05 (the chords' sagitta is below 1e-3). Certified, under every
/// map (all keep the axis certified).
fn plate_offsets(map: &Affine, distances: &[f64]) -> Offsets {
    let region = plate(map);
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    assert!(axis.certified(), "{map:?}: {:?}", axis.reason());
    let scale = map.determinant().abs().sqrt();
    let moved: Vec<f64> = distances.iter().map(|d| d * scale).collect();
    let found = offsets(&region, &axis, &moved, &OffsetOptions::default()).unwrap();
    assert!(found.certified(), "{map:?}: {:?}", found.reason());
    let back = inverse(map);
    for (o, &d) in found.offsets.iter().zip(distances) {
        let loops: Vec<Vec<[f64; 2]>> = o
            .loops
            .iter()
            .map(|l| {
                assert!(l.profile().is_ok(), "{map:?}, d = {d}: {l:?}");
                polygon_of(&l.segments)
                    .into_iter()
                    .map(|p| back.apply(p))
                    .collect()
            })
            .collect();
        for (i, l) in loops.iter().enumerate() {
            for p in l {
                let off = signed_distance(*p) - d;
                assert!(
                    off.abs() < 1e-6,
                    "{map:?}, d = {d}: loop {i} has {p:?}, {off} off"
                );
            }
        }
        let n = 120;
        for k in 0..n * n {
            let p = [
                (k % n) as f64 * SIDE / (n - 1) as f64,
                (k / n) as f64 * SIDE / (n - 1) as f64,
            ];
            let s = signed_distance(p);
            if (s - d).abs() < 0.05 {
                continue;
            }
            let w: i32 = loops.iter().map(|l| winding(l, p)).sum();
            assert_eq!(
                w,
                i32::from(s > d),
                "{map:?}, d = {d}: the loops wind {w} times round {p:?}, {s} from the boundary"
            );
        }
    }
    found
}

/// The number of loops of each offset.
fn counts(found: &Offsets) -> Vec<usize> {
    found.offsets.iter().map(|o| o.loops.len()).collect()
}

/// The maps the plate is tried under: as drawn, rotated (exact sine and cosine), and moved
/// ten sizes and more from the origin (at a hundred, the medial axis is not certified: a
/// junction's disk is not proven within 1e-9 of the size).
fn maps() -> [Affine; 4] {
    let (c, s) = (0.6f64, 0.8f64);
    [
        Affine::IDENTITY,
        Affine([c, s, -s, c, 3.0, -7.0]),
        Affine([1.0, 0.0, 0.0, 1.0, 1e3, -3e3]),
        Affine([s, -c, c, s, -2e3, 1e3]),
    ]
}

/// At exactly half the passages' width the four corners are apart, touching at the four
/// points (closed there), each corner one loop turning back at both touching points (its
/// horns cut); the same within the 1e-9 of the size a touch is taken within, either side.
/// Certified and as the oracle says, under every map.
#[test]
fn a_plate_touching_its_hole_at_the_distance_is_four_corners() {
    let touch = 1e-9 * SIDE;
    for map in maps() {
        let found = plate_offsets(&map, &[7.5, 7.5 - 0.3 * touch, 7.5 + 0.3 * touch]);
        assert_eq!(counts(&found), [4, 4, 4], "{map:?}: {:?}", found.offsets);
    }
}

/// Metamorphic: 1e-6 of the size below the touch, the passages are open (a ring: two loops);
/// 1e-6 of the size above it, they are closed (four corners).
#[test]
fn a_plate_beside_the_touch_is_a_ring_or_four_corners() {
    let aside = 1e-6 * SIDE;
    for map in maps() {
        let found = plate_offsets(&map, &[7.5 - aside, 7.5 + aside]);
        assert_eq!(counts(&found), [2, 4], "{map:?}");
    }
}
