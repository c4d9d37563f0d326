//! Helpers the offset tests share: the regions (a circle, the pocket, polygons, chains of
//! Béziers round a hole), their offsets found (checked or certified), and the distance from a
//! point to an offset piece.

use crate::common::samples;
use crate::oracle::check;
use curve::{Profile, Region, Segment};
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use offset::{offsets, OffsetOptions, OffsetSegment, Offsets};
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use testkit::outlines::polygon;

pub(crate) fn circle(center: [f64; 2], r: f64) -> Profile {
    Profile::new(vec![Segment::arc(center, r, 0.0, TAU).unwrap()], None).unwrap()
}

/// The 10 × 6 pocket with corner radius 1 and a round island of radius 1 (the issue's).
pub(crate) fn pocket() -> Region {
    let q = FRAC_PI_2;
    let outer = Profile::new(
        vec![
            Segment::line([1.0, 0.0], [9.0, 0.0]).unwrap(),
            Segment::arc([9.0, 1.0], 1.0, -q, 0.0).unwrap(),
            Segment::line([10.0, 1.0], [10.0, 5.0]).unwrap(),
            Segment::arc([9.0, 5.0], 1.0, 0.0, q).unwrap(),
            Segment::line([9.0, 6.0], [1.0, 6.0]).unwrap(),
            Segment::arc([1.0, 5.0], 1.0, q, PI).unwrap(),
            Segment::line([0.0, 5.0], [0.0, 1.0]).unwrap(),
            Segment::arc([1.0, 1.0], 1.0, PI, PI + q).unwrap(),
        ],
        None,
    )
    .unwrap();
    Region::new(outer, vec![circle([6.5, 3.0], 1.0)]).unwrap()
}

pub(crate) fn offsets_of(region: &Region, distances: &[f64]) -> Offsets {
    let axis = medial_axis(region, &MedialOptions::default()).unwrap();
    assert!(axis.certified(), "{:?}", axis.reason());
    offsets(region, &axis, distances, &OffsetOptions::default()).unwrap()
}

/// The offsets of `region` by `distances`, found right by [`check`] to `tol`; with the
/// areas it measured.
pub(crate) fn checked_offsets(
    region: &Region,
    distances: &[f64],
    tol: f64,
) -> (Offsets, Vec<Vec<f64>>) {
    let found = offsets_of(region, distances);
    let areas = check(region, &found, tol);
    (found, areas)
}

/// The region inside the polygon through `corners` (no holes).
pub(crate) fn polygon_region(corners: &[[f64; 2]]) -> Region {
    Region::new(polygon(corners), vec![]).unwrap()
}

/// The region inside a closed chain of Béziers ([`testkit::profiles::bezier_chain`]) with a
/// round hole of radius 0.15 at the origin: the random chains' regression cases.
pub(crate) fn chain_round_a_hole(radii: &[f64], wobble: &[(f64, f64)], smooth: &[bool]) -> Region {
    let outer = testkit::profiles::bezier_chain_profile(radii, wobble, smooth, 0, false).unwrap();
    Region::new(outer, vec![circle([0.0, 0.0], 0.15)]).unwrap()
}

/// The offset of `region` by `distance`, which must be certified.
pub(crate) fn certified_offsets(region: &Region, distance: f64) -> Offsets {
    let found = offsets_of(region, &[distance]);
    assert!(found.certified(), "{:?}", found.reason());
    found
}

/// The distance from `p` to an offset piece (exact for lines and arcs).
pub(crate) fn distance_to_piece(p: [f64; 2], s: &OffsetSegment) -> f64 {
    match s {
        OffsetSegment::Line { from, to } => curve::distance_to_segment(p, *from, *to),
        OffsetSegment::Arc {
            center,
            r,
            start,
            end,
        } => {
            let a = (p[1] - center[1]).atan2(p[0] - center[0]);
            let (lo, hi) = if start <= end {
                (*start, *end)
            } else {
                (*end, *start)
            };
            let within = (a - lo).rem_euclid(TAU) <= hi - lo + 1e-12;
            let ends = samples(s, 1);
            let to_end = |q: [f64; 2]| ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
            let by_ends = to_end(ends[0]).min(to_end(ends[1]));
            if within {
                ((p[0] - center[0]).hypot(p[1] - center[1]) - r)
                    .abs()
                    .min(by_ends)
            } else {
                by_ends
            }
        }
        OffsetSegment::BSpline { .. } => samples(s, 256)
            .windows(2)
            .map(|w| curve::distance_to_segment(p, w[0], w[1]))
            .fold(f64::INFINITY, f64::min),
    }
}
