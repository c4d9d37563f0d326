//! Outward offsets (by the exterior axis): a rectangle grows rounded corners, a hole shrinks,
//! and the distances stay within the axis.

use crate::common::exterior_axis;
use crate::helpers::{circle, pocket, polygon_region};
use crate::oracle::check;
use curve::Region;
use offset::{OffsetOptions, OffsetSegment, Offsets};
use std::f64::consts::PI;

fn outward_of(region: &Region, distances: &[f64]) -> Offsets {
    let axis = exterior_axis(region);
    offset::outward_offsets(region, &axis, distances, &OffsetOptions::default()).unwrap()
}

#[test]
fn outward_a_rectangle_grows_rounded_corners_and_a_hole_shrinks() {
    let region = polygon_region(&[[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]);
    let found = outward_of(&region, &[0.5]);
    let areas = check(&region, &found, 1e-6);
    assert_eq!(found.offsets[0].loops.len(), 1);
    let arcs = found.offsets[0].loops[0]
        .segments
        .iter()
        .filter(|s| matches!(s, OffsetSegment::Arc { r, .. } if *r == 0.5))
        .count();
    assert_eq!(arcs, 4, "a quarter circle round each corner");
    let expected = 8.0 + 2.0 * 6.0 * 0.5 + PI * 0.25;
    testkit::assert_near!(areas[0][0], expected, 1e-4, "{} vs {expected}", areas[0][0]);

    let washer = Region::new(circle([0.0, 0.0], 3.0), vec![circle([0.0, 0.0], 1.0)]).unwrap();
    let found = outward_of(&washer, &[0.5, 1.2]);
    let areas = check(&washer, &found, 1e-6);
    let mut first = areas[0].clone();
    first.sort_by(f64::total_cmp);
    assert!(
        (first[0] + PI * 0.25).abs() < 1e-3,
        "the hole shrinks to r = 0.5: {first:?}"
    );
    testkit::assert_near!(
        first[1],
        PI * 12.25,
        1e-2,
        "the outside grows to r = 3.5: {first:?}"
    );
    assert_eq!(
        areas[1].len(),
        1,
        "at 1.2 the hole is filled: {:?}",
        areas[1]
    );
}

#[test]
fn outward_distances_stay_within_the_exterior_axis() {
    let region = pocket();
    let axis = exterior_axis(&region);
    let far = offset::outward_offsets(&region, &axis, &[6.0], &OffsetOptions::default());
    assert!(
        far.is_err(),
        "beyond half the size the exterior axis is clipped"
    );
    let found = outward_of(&region, &[0.3, 0.9, 2.0]);
    check(&region, &found, 1e-6);
}
