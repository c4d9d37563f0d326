//! The medial axis of regions far from the origin, whose smooth joints turn by the rounding of
//! their tangents (a line and an arc meeting tangentially at 1e8 turn by some 1e-8; a fillet
//! of radius 0.01 there, by some 1e-6): the axis is certified only where the independent
//! oracle agrees (dense boundary distances, the sampled Voronoi diagram: every vertex inside
//! at its radius, to the rounding of the points; no medial point off the axis).

#![allow(clippy::unwrap_used, missing_docs)]

#[path = "common/sampled_voronoi.rs"]
mod sampled_voronoi;
#[path = "common/traced.rs"]
mod traced;

use curve::{Profile, Region};
use numeric::certificate::Verdict;
use sampled_voronoi::sampled_medial_points;
use testkit::boundary_oracle::{winding, Oracle};
use testkit::far_joints::shapes_at;
use traced::{axis, off_axis, CHORD};

/// Where the shapes are moved.
const FAR: [f64; 2] = [1e8, 1e8];

/// What the oracle finds wrong with the certified axis of `region` (bounded by `profile`).
fn faults(profile: &Profile, region: &Region) -> Option<String> {
    let a = axis(region);
    if !a.certified() {
        return None;
    }
    let oracle = Oracle::new(profile);
    let size = region.size();
    // (A vertex's radius is as exact as the points are far out.)
    let radius_room = 1e-9 * size + 8.0 * profile.point_rounding();
    let distance = |x: [f64; 2]| oracle.nearest(x).0;
    let inside = |x: [f64; 2]| winding(&oracle.pts, x) != 0;
    for e in &a.edges {
        for (&x, &r) in e.xy.iter().zip(&e.radius) {
            let d = distance(x);
            if (d - r).abs() > radius_room {
                return Some(format!("vertex {x:?}: radius {r}, distance {d}"));
            }
        }
    }
    let sampled = sampled_medial_points(&[profile], size, distance, inside);
    for z in &sampled.points {
        let off = off_axis(&a, z.xy);
        if off > CHORD * size + 1e-6 * size {
            return Some(format!(
                "medial point {:?} (radius {}) is {off:e} off the axis",
                z.xy, z.radius
            ));
        }
    }
    None
}

#[test]
fn a_certified_axis_round_far_smooth_joints_is_the_oracles() {
    let bad: Vec<String> = shapes_at(FAR)
        .into_iter()
        .filter_map(|(name, profile, _)| {
            let region = Region::new(profile.clone(), vec![]).unwrap();
            faults(&profile, &region).map(|why| format!("{name}: {why}"))
        })
        .collect();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
