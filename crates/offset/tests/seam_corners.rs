//! Offsets of a region bounded by one closed clamped spline whose ends meet at a corner (issue
//! 38: "outward offsets have spikes at corners where a spline's ends meet"). Its only joint is
//! at the parameter 0, which is both ends of its one segment: the corner's normals were both
//! taken at the segment's start, so the arc about a corner swept nothing and the loop did not
//! close across it. Judged by an oracle of its own: the boundary sampled densely (its distance
//! and winding number), the loops sampled by their own evaluation (lines, arcs, Cox–de Boor).
#![allow(clippy::unwrap_used)]

mod common;
use common::{arcs_sweep, ends, exterior_axis, samples};
use curve::{ParamCurve, Profile, Region, Segment, SegmentKind, SplineCurve};
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use offset::{offsets, outward_offsets, OffsetOptions, Offsets};
use testkit::boundary_oracle::winding;

/// The region bounded by the closed clamped cubic through (by) `points`, its first and last
/// equal.
fn spline_region(points: &[[f64; 2]]) -> Region {
    let curve = SplineCurve::clamped(3, points, None, None).unwrap();
    let segment = Segment::spline(SegmentKind::BSpline, curve).unwrap();
    Region::new(Profile::new(vec![segment], None).unwrap(), vec![]).unwrap()
}

/// The boundary as a closed polygon of 20,000 points (its chords within 1e-6 of it here).
fn boundary(region: &Region) -> Vec<[f64; 2]> {
    let outer = region.outer();
    let (a, b) = outer.domain();
    let n = 20_000;
    (0..n)
        .map(|k| outer.jet_to(a + (b - a) * k as f64 / n as f64, 0).p.arr())
        .collect()
}

fn gap(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// The distance from `p` to the closed polygon `poly`.
fn distance(poly: &[[f64; 2]], p: [f64; 2]) -> f64 {
    (0..poly.len())
        .map(|k| {
            let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
            let ab = [b[0] - a[0], b[1] - a[1]];
            let t = (((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1])
                / (ab[0] * ab[0] + ab[1] * ab[1]))
                .clamp(0.0, 1.0);
            gap(p, [a[0] + t * ab[0], a[1] + t * ab[1]])
        })
        .fold(f64::INFINITY, f64::min)
}

/// Checks one offset of `region` at `d` (grown, `outward`): one loop, certified, each piece
/// starting where the one before ends (to rounding), every point at `d` from the boundary
/// (within the chord tolerance), and its winding number on a grid 1 on the side kept
/// (within `d` of the region, or in it farther than `d`) and 0 off it, beyond a margin.
fn check(region: &Region, found: &Offsets, d: f64, outward: bool) {
    assert!(found.certified(), "d = {d}: {:?}", found.reason());
    let loops = &found.offsets[0].loops;
    assert_eq!(loops.len(), 1, "d = {d}: {loops:?}");
    let poly = boundary(region);
    let size = region.size();
    let pieces = &loops[0].segments;
    let mut points = Vec::new();
    for (k, s) in pieces.iter().enumerate() {
        let (end, next) = (ends(s).1, ends(&pieces[(k + 1) % pieces.len()]).0);
        let apart = gap(end, next);
        assert!(
            apart <= 1e-12 * size,
            "d = {d}: piece {k} ends {apart} from the next"
        );
        let along = samples(s, 200);
        for &p in &along {
            let off = distance(&poly, p) - d;
            assert!(off.abs() <= 1e-3 * size, "d = {d}: {p:?} is {off} off");
        }
        points.extend_from_slice(&along[..along.len() - 1]);
    }
    let (lo, hi) = poly.iter().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    );
    let n = 60;
    let reach = 1.5 * d;
    for k in 0..n * n {
        let p = [
            lo[0] - reach + (hi[0] - lo[0] + 2.0 * reach) * (k % n) as f64 / (n - 1) as f64,
            lo[1] - reach + (hi[1] - lo[1] + 2.0 * reach) * (k / n) as f64 / (n - 1) as f64,
        ];
        let (inside, dist) = (winding(&poly, p) != 0, distance(&poly, p));
        if (dist - d).abs() < 0.02 * size {
            continue;
        }
        let kept = if outward {
            inside || dist < d
        } else {
            inside && dist > d
        };
        let w = winding(&points, p);
        assert_eq!(
            w,
            i32::from(kept),
            "d = {d}: the loop winds {w} times round {p:?}"
        );
    }
}

/// The spline, outward: its ends meet at a convex corner at the origin, which grows
/// an arc of the distance there, from the end's normal to the start's.
#[test]
fn outward_a_corner_where_a_splines_ends_meet_grows_its_arc() {
    let region = spline_region(&[
        [0.0, 0.0],
        [4.0, -1.0],
        [6.0, 2.0],
        [3.0, 5.0],
        [-1.0, 3.0],
        [0.0, 0.0],
    ]);
    let axis = exterior_axis(&region);
    assert!(axis.certified(), "{:?}", axis.reason());
    for d in [0.3, 1.0] {
        let found = outward_offsets(&region, &axis, &[d], &OffsetOptions::default()).unwrap();
        check(&region, &found, d, true);
        // (The corner's arc turns by the corner's turn, about 57.5 degrees.)
        let swept = arcs_sweep(&found.offsets[0].loops[0].segments);
        testkit::assert_near!(swept, 1.004, 1e-2, "d = {d}: arcs sweep {swept}");
    }
}

/// A heart whose notch (a reflex corner) is where the spline's ends meet: inward, an arc of
/// the distance about the notch.
#[test]
fn inward_a_notch_where_a_splines_ends_meet_is_an_arc() {
    let region = spline_region(&[
        [0.0, 0.0],
        [-2.0, 2.0],
        [-4.0, 0.0],
        [0.0, -5.0],
        [4.0, 0.0],
        [2.0, 2.0],
        [0.0, 0.0],
    ]);
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    assert!(axis.certified(), "{:?}", axis.reason());
    for d in [0.2, 0.5] {
        let found = offsets(&region, &axis, &[d], &OffsetOptions::default()).unwrap();
        check(&region, &found, d, false);
    }
}
