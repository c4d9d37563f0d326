//! The tests of the parent module.

/// The bisection on the marks agrees with a scan of them all, round the seam and with
/// starts a shade below zero (which round to the length).
#[test]
fn marks_within_is_a_scan() {
    use proptest::prelude::*;
    let mut runner = proptest::test_runner::TestRunner::default();
    let strategy = (
        prop::collection::vec(0.0f64..10.0, 0..8),
        -20.0f64..20.0,
        0.0f64..5.0,
        0.0f64..5.0,
        prop::bool::ANY,
    );
    runner
        .run(&strategy, |(mut marks, start, lo, width, tiny)| {
            marks.sort_by(f64::total_cmp);
            marks.push(0.0);
            marks.sort_by(f64::total_cmp);
            let length = 10.0;
            let start = if tiny { -1e-17 } else { start };
            let hi = lo + width.min(length - lo - 1e-9);
            let scan = marks.iter().any(|&c| {
                let from_start = (c - start).rem_euclid(length) % length;
                from_start > lo && from_start < hi
            });
            prop_assert_eq!(super::marks_within(&marks, length, start, lo, hi), scan);
            Ok(())
        })
        .unwrap();
}

use super::*;
use crate::candidates::PairSource;
use crate::test_shapes::polygon_star;
use crate::{axis_of, MedialOptions, Verdict};
use curve::Region;
use proptest::prelude::*;

fn bounds_axis(region: &Region) -> MedialAxis {
    axis_of(region, &MedialOptions::default(), PairSource::Bounds)
        .unwrap()
        .0
}

fn covered(region: &Region, axis: &MedialAxis) -> Result<(), &'static str> {
    feet_cover(&crate::sites::Sites::new(region, false), axis)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// The check refuses no true axis of lines: every certified axis built from the pairs
    /// the bounds keep (complete by them) has its feet cover its boundaries, on stars of
    /// lines (reflex corners and their fans) with round holes. (On curves a disk may touch
    /// a stretch of boundary within the slack, its feet then claimed by two edges: the
    /// check refuses such an axis, and the axis is built again from the bounds' pairs;
    /// the seed's differential test counts how rarely.)
    #[test]
    fn certified_axes_are_covered(
        radii in proptest::collection::vec(1.0f64..1.6, 5..14),
        wobble in proptest::collection::vec(-0.2f64..0.2, 14),
        holes in proptest::collection::vec(([-0.4f64..0.4, -0.4f64..0.4], 0.05f64..0.2), 0..3),
    ) {
        let w = &wobble[..radii.len()];
        let Some(region) = polygon_star(&radii, w, &holes) else { return Ok(()) };
        let axis = bounds_axis(&region);
        if axis.certified() {
            prop_assert_eq!(covered(&region, &axis), Ok(()));
        }
    }
}

/// Positions on a boundary's line and profile parameters map back and forth: off the
/// corners exactly, and every position in a reflex corner's fan to that corner.
#[test]
fn the_line_maps_back_to_parameters() {
    let radii = [1.0, 1.4, 1.1, 1.5, 1.2, 1.3];
    let wobble = [0.1, -0.15, 0.12, -0.1, 0.05, -0.2];
    let star = polygon_star(&radii, &wobble, &[]).unwrap();
    let sites = crate::sites::Sites::new(&star, false);
    let line = Line::new(&sites, 0);
    assert!(!line.fans.is_empty() && !line.convex.is_empty());
    let far = V2::new(1e3, 1e3); // (off the corners, where the axis point is is not read)
    for j in 0..=1200 {
        let u = 12.0 * j as f64 / 1200.0 + 1e-3;
        if u >= 12.0 {
            continue;
        }
        let foot = V2::from_arr(sites.foot(0, u));
        let back = line.param_at(line.place(u, || foot, far));
        testkit::assert_near!(back, u, 1e-12, "{u} -> {back}");
    }
    for fan in &line.fans {
        for t in [0.0, 0.3, 0.9] {
            let u = line.param_at(fan.start + t * fan.angle);
            testkit::assert_near!(u, u.round(), 1e-12, "{u}");
        }
    }
}

/// A star of six points with a hole (fans at its reflex corners, a cycle round the
/// hole).
fn star_with_hole() -> Region {
    let radii = [1.0, 1.4, 1.1, 1.5, 1.2, 1.3];
    let wobble = [0.1, -0.15, 0.12, -0.1, 0.05, -0.2];
    polygon_star(&radii, &wobble, &[([0.1, 0.0], 0.15)]).unwrap()
}

/// Any one edge left out of a true axis leaves its feet uncovered: on a star of lines
/// with a hole (fans at its reflex corners, a cycle round the hole) and on a rounded
/// pocket with an island (arcs whose centres are nodes).
#[test]
fn an_axis_missing_an_edge_is_not_covered() {
    let star = star_with_hole();
    let axis = bounds_axis(&star);
    assert!(axis.certified() && axis.edges.len() > 10);
    assert_eq!(covered(&star, &axis), Ok(()));
    for k in 0..axis.edges.len() {
        let mut cut = axis.clone();
        cut.edges.remove(k);
        assert!(
            covered(&star, &cut).is_err(),
            "edge {k} left out, still covered"
        );
    }
    // A side of an edge whose feet turn back is refused too.
    let mut back = axis.clone();
    let e = back.edges.iter_mut().max_by_key(|e| e.xy.len()).unwrap();
    let m = e.feet.len() / 2;
    e.feet.swap(m, m + 1);
    assert!(covered(&star, &back).is_err());
}

/// On a true axis every convex corner ends a leaf; with a leaf's corner node taken
/// away, that corner (and no other) is named, with its turn.
#[test]
fn a_convex_corner_without_its_leaf_is_named() {
    let star = star_with_hole();
    let axis = bounds_axis(&star);
    let sites = Sites::new(&star, false);
    assert_eq!(unreached_convex_corners(&sites, &axis), vec![]);
    let leaves: Vec<usize> = (0..axis.nodes.len())
        .filter(|&k| axis.nodes[k].kind == NodeKind::Corner)
        .collect();
    // (At least the star's six tips.)
    assert!(leaves.len() >= 6, "{leaves:?}");
    for k in leaves {
        let mut cut = axis.clone();
        cut.nodes[k].kind = NodeKind::Junction;
        let named = unreached_convex_corners(&sites, &cut);
        assert_eq!(named.len(), 1);
        assert_eq!(named[0].xy, axis.nodes[k].xy);
        assert!(named[0].turn > 0.0 && named[0].turn < std::f64::consts::PI);
    }
}
