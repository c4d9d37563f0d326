//! Metamorphic relations: offsets compose, and moved, scaled or rotated regions have the moved
//! offsets.

use crate::common::samples;
use crate::helpers::{distance_to_piece, offsets_of, pocket};
use crate::oracle::check;
use curve::{Profile, Region};
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use offset::{offsets, OffsetOptions, OffsetSegment};

/// Offsetting by D1, then the result by D2, gives the offset by D1 + D2 (the loops as point
/// sets, within 1e-7): on the pocket, whose offsets are lines and arcs. Both are taken with
/// the pocket's size: at 1 its passes touch the island, and each horn there is cut where it
/// is 1e-8 of the size wide (6e-4 from its tip; of the smaller size of the region offset by
/// 0.5, 3e-5 nearer).
#[test]
fn offsets_compose() {
    let region = pocket();
    let first = offsets_of(&region, &[0.5]);
    let profiles: Vec<Profile> = first.offsets[0]
        .loops
        .iter()
        .map(|l| l.profile().unwrap())
        .collect();
    let inner = Region::nested(profiles).unwrap();
    assert_eq!(
        inner.len(),
        1,
        "the pocket at 0.5 is one region with its island"
    );
    let opts = OffsetOptions {
        settings: testkit::settings(numeric::tolerance::DEFAULT_CHORD_TOL, Some(region.size())),
    };
    for d2 in [0.25, 0.5, 0.6] {
        let axis = medial_axis(&inner[0], &MedialOptions::default()).unwrap();
        assert!(axis.certified(), "{:?}", axis.reason());
        let again = offsets(&inner[0], &axis, &[d2], &opts).unwrap();
        let direct = offsets_of(&region, &[0.5 + d2]);
        assert_eq!(
            again.offsets[0].loops.len(),
            direct.offsets[0].loops.len(),
            "d2 = {d2}"
        );
        // (Each one's sampled points lie on the other's exact pieces.)
        for (from, onto) in [(&again, &direct), (&direct, &again)] {
            let pieces: Vec<&OffsetSegment> = onto.offsets[0]
                .loops
                .iter()
                .flat_map(|l| &l.segments)
                .collect();
            for l in &from.offsets[0].loops {
                for p in l.segments.iter().flat_map(|s| samples(s, 40)) {
                    let off = pieces
                        .iter()
                        .map(|s| distance_to_piece(p, s))
                        .fold(f64::INFINITY, f64::min);
                    assert!(off < 1e-7, "d2 = {d2}: {p:?} is {off} off");
                }
            }
        }
    }
}

/// Metamorphic: the pocket (lines and arcs) and a chain of Béziers moved far from the origin,
/// scaled by 1e±6 or rotated have, at the moved distances, as many loops, every point at the
/// distance (within the tolerance scaled), the spline pieces' errors within it; certified
/// where the moved axis is (always, but far from the origin).
#[test]
fn offsets_moved_scaled_or_rotated_are_the_moved_offsets() {
    let segs = testkit::profiles::bezier_chain(
        &[1.5, 1.2, 1.8, 1.4],
        &[(0.2, -0.1), (-0.1, 0.3), (0.15, 0.1), (-0.2, -0.2)],
        &[true, false, true, false],
    )
    .unwrap();
    let chain = Region::new(testkit::profiles::assemble(segs, 0, false).unwrap(), vec![]).unwrap();
    let (c, s) = (0.6f64, 0.8f64); // a rotation with exact sine and cosine
    let maps = [
        curve::Affine([1.0, 0.0, 0.0, 1.0, 1e6, -1e6]),
        curve::Affine([1e-6, 0.0, 0.0, 1e-6, 3e-6, 0.0]),
        curve::Affine([1e6, 0.0, 0.0, 1e6, 0.0, -7e6]),
        curve::Affine([c, s, -s, c, 0.25, 0.5]),
    ];
    for (region, distances) in [
        (pocket(), vec![0.5, 1.0, 2.0]),
        (chain, vec![0.2, 0.5, 0.9]),
    ] {
        let base = offsets_of(&region, &distances);
        assert!(base.certified(), "{:?}", base.reason());
        for map in &maps {
            let scale = map.determinant().abs().sqrt();
            let moved_region = region.transformed(map).unwrap();
            let moved_distances: Vec<f64> = distances.iter().map(|d| d * scale).collect();
            let axis = medial_axis(&moved_region, &MedialOptions::default()).unwrap();
            // (Far from the origin the axis's digits may run out: uncertified, then said so.)
            let translated = map.0[..4] == [1.0, 0.0, 0.0, 1.0];
            assert!(
                axis.certified() || translated,
                "{map:?}: {:?}",
                axis.reason()
            );
            let moved = offsets(
                &moved_region,
                &axis,
                &moved_distances,
                &OffsetOptions::default(),
            )
            .unwrap();
            if !axis.certified() {
                assert!(!moved.certified());
                continue;
            }
            assert!(moved.certified(), "{map:?}: {:?}", moved.reason());
            for (b, m) in base.offsets.iter().zip(&moved.offsets) {
                assert_eq!(b.loops.len(), m.loops.len(), "{map:?}, d = {}", b.distance);
                assert!(m.error <= 1e-3 * 4.0 * scale, "{map:?}: error {}", m.error);
            }
            check(&moved_region, &moved, 4e-3 * scale);
        }
    }
}
