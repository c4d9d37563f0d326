//! Offsets against closed forms: a rectangle, an annulus, the pocket, reflex corners, a round
//! island's seam, and holes (a square one, a D-shaped one) grown inward.

use crate::helpers::{checked_offsets, circle, pocket, polygon_region};
use curve::{Profile, Region, Segment};
use numeric::certificate::Verdict;
use offset::OffsetSegment;
use std::f64::consts::{FRAC_PI_2, PI};
use testkit::outlines::polygon;

#[test]
fn a_rectangle_shrinks_to_a_rectangle_until_it_vanishes() {
    let region = polygon_region(&[[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]);
    let (found, areas) = checked_offsets(&region, &[0.25, 0.5, 0.9, 1.1], 1e-9);
    for (k, d) in [0.25, 0.5, 0.9].iter().enumerate() {
        assert_eq!(found.offsets[k].loops.len(), 1);
        assert_eq!(found.offsets[k].loops[0].segments.len(), 4);
        let expected = (4.0 - 2.0 * d) * (2.0 - 2.0 * d);
        testkit::assert_near!(areas[k][0], expected, 1e-9, "{} vs {expected}", areas[k][0]);
    }
    assert!(
        found.offsets[3].loops.is_empty(),
        "beyond half the width nothing is left"
    );
    assert!(found.certified() && found.complete);
    let drawn = found.offsets[0].loops[0].polyline(8);
    assert_eq!(drawn.len(), 9, "four lines, closed");
    assert_eq!(drawn.first(), drawn.last());
}

#[test]
fn an_annulus_gives_two_circles_each_way_round() {
    let region = Region::new(circle([1.0, 2.0], 3.0), vec![circle([1.0, 2.0], 1.0)]).unwrap();
    let (found, areas) = checked_offsets(&region, &[0.5, 0.99, 1.01], 1e-6);
    for (k, d) in [0.5_f64, 0.99].iter().enumerate() {
        let mut got = areas[k].clone();
        got.sort_by(f64::total_cmp);
        // (Clockwise round the hole: negative area.)
        let (hole, outer) = (-PI * (1.0 + d).powi(2), PI * (3.0 - d).powi(2));
        testkit::assert_near!(got[0], hole, 1e-3 * hole.abs(), "{got:?}");
        testkit::assert_near!(got[1], outer, 1e-3 * outer, "{got:?}");
    }
    assert!(found.offsets[2].loops.is_empty());
}

#[test]
fn the_pocket_keeps_its_island_then_splits_then_vanishes() {
    let region = pocket();
    let distances: Vec<f64> = (1..=12).map(|k| 0.25 * k as f64).collect();
    let (found, _) = checked_offsets(&region, &distances, 1e-6);
    let counts: Vec<usize> = found.offsets.iter().map(|o| o.loops.len()).collect();
    // Two loops (round the pocket, round the island) while the island's gap to the right
    // wall (2.5 wide) is open; then one loop left of the island; then none.
    assert_eq!(counts[0], 2, "{counts:?}");
    assert_eq!(counts.last(), Some(&0), "{counts:?}");
    assert!(found.certified() && found.complete, "{:?}", found.reason());
}

#[test]
fn reflex_corners_become_arcs_of_the_distance() {
    // An L-shaped room: its one reflex corner at (2, 2).
    let region = polygon_region(&[
        [0.0, 0.0],
        [6.0, 0.0],
        [6.0, 2.0],
        [2.0, 2.0],
        [2.0, 6.0],
        [0.0, 6.0],
    ]);
    let (found, _) = checked_offsets(&region, &[0.5], 1e-9);
    let arcs: Vec<&OffsetSegment> = found.offsets[0].loops[0]
        .segments
        .iter()
        .filter(|s| matches!(s, OffsetSegment::Arc { .. }))
        .collect();
    assert_eq!(arcs.len(), 1);
    let OffsetSegment::Arc {
        center,
        r,
        start,
        end,
    } = arcs[0]
    else {
        unreachable!()
    };
    assert_eq!((*center, *r), ([2.0, 2.0], 0.5));
    assert!(
        (start - end - FRAC_PI_2).abs() < 1e-9,
        "a quarter turn clockwise"
    );
}

#[test]
fn a_stretch_across_a_round_islands_seam_is_one_arc() {
    // The island's parameter starts at angle 0, where the offset at 1 crosses it (the
    // fixture region-pocket.json).
    let mut region = pocket();
    region = Region::new(region.outer().clone(), vec![circle([6.5, 3.0], 1.2)]).unwrap();
    let (found, _) = checked_offsets(&region, &[1.0, 1.1], 1e-6);
    for o in &found.offsets {
        let arcs = o.loops.iter().flat_map(|l| &l.segments).filter(
            |s| matches!(s, OffsetSegment::Arc { r, .. } if (r - (1.2 + o.distance)).abs() < 1e-9),
        );
        assert!(
            arcs.count() <= 3,
            "d = {}: the island's offset in a few arcs",
            o.distance
        );
    }
}

#[test]
fn a_square_hole_grows_rounded_corners_inward() {
    let outer = polygon(&[[-4.0, -4.0], [4.0, -4.0], [4.0, 4.0], [-4.0, 4.0]]);
    let hole = polygon(&[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]);
    let region = Region::new(outer, vec![hole]).unwrap();
    let (found, areas) = checked_offsets(&region, &[0.5], 1e-6);
    let round_hole = found.offsets[0]
        .loops
        .iter()
        .find(|l| l.segments.len() == 8)
        .expect("the hole's offset: four lines and four quarter circles");
    let arcs = round_hole
        .segments
        .iter()
        .filter(|s| matches!(s, OffsetSegment::Arc { .. }))
        .count();
    assert_eq!(arcs, 4);
    let hole_area = -(4.0 + 4.0 * 2.0 * 0.5 + PI * 0.25);
    assert!(
        areas[0].iter().any(|a| (a - hole_area).abs() < 1e-4),
        "{areas:?}"
    );
}

/// A hole whose last segment is an arc ending at a corner at the parameter 0: the corner's
/// arc is turned from that arc's end normal, not its start's (a review found it).
#[test]
fn a_d_shaped_hole_closes_round_its_corners() {
    let outer = polygon(&[[-4.0, -4.0], [4.0, -4.0], [4.0, 4.0], [-4.0, 4.0]]);
    let hole = Profile::new(
        vec![
            Segment::line([0.0, 1.0], [0.0, -1.0]).unwrap(),
            Segment::arc([0.0, 0.0], 1.0, -FRAC_PI_2, FRAC_PI_2).unwrap(),
        ],
        None,
    )
    .unwrap();
    let region = Region::new(outer, vec![hole]).unwrap();
    for d in [0.3, 0.5, 1.0] {
        let (found, _) = checked_offsets(&region, &[d], 1e-6);
        assert_eq!(found.offsets[0].loops.len(), 2, "d = {d}");
    }
}
