//! The differential tests of the fast paths to the axis of lines and arcs: the traced path
//! (the seed's diagram walked, [`crate::traced_axis`]) and the pairwise path (every pair of
//! true sites, [`crate::pairwise_axis`]), each against the axis built from every pair the
//! bounds keep, on the same 1,000 random regions (the bounds' axis, the costly one, built
//! once per region for both).

use crate::candidates::PairSource;
use crate::test_shapes::{
    merged, random_polygon, random_rounded, same_graph, stands_as_the_bounds, Judge,
};
use crate::{MedialAxis, MedialOptions, Verdict};
use curve::Region;
use testkit::rng;

/// Vertices of the same edge within twice the chord tolerance.
fn near(region: &Region) -> f64 {
    2.0 * MedialOptions::default().settings.chord_tol.get() * region.size()
}

/// The traced axis on polygons: the same graph as the bounds' axis.
fn traced_on_polygons(
    traced: &MedialAxis,
    bounds: &MedialAxis,
    region: &Region,
) -> Result<(), String> {
    same_graph(traced, bounds, near(region))
}

/// The same, where the bounds' axis is certified (else it is no judge: beside a convex
/// corner of an arc and a line it may end a leaf a little off the corner, unproven, where
/// the traced one ends it at the corner).
fn traced(traced: &MedialAxis, bounds: &MedialAxis, region: &Region) -> Result<(), String> {
    if !bounds.certified() {
        return Ok(());
    }
    same_graph(traced, bounds, near(region))
}

/// The same, junctions within a millionth of the size taken as one node, as the bounds'
/// path merges them.
fn pairwise(pairwise: &MedialAxis, bounds: &MedialAxis, region: &Region) -> Result<(), String> {
    if !bounds.certified() {
        return Ok(());
    }
    let one_node = 1e-6 * region.size();
    same_graph(
        &merged(pairwise, one_node),
        &merged(bounds, one_node),
        near(region),
    )
}

/// On 1,000 random polygons with reflex and convex corners and polygonal holes (10 to 30
/// sides), the traced and the pairwise axes, wherever they stand, are the bounds' axis; and
/// each stands wherever that one is certified but for a few.
#[test]
fn the_fast_axes_of_polygons_are_the_bounds_axis() {
    let paths: [(PairSource, Judge); 2] = [
        (PairSource::SeedEdges, traced_on_polygons),
        (PairSource::Pairwise, pairwise),
    ];
    stands_as_the_bounds(&mut rng(3901), &paths, |rnd, _| random_polygon(rnd));
}

/// The same on 1,000 random stars with rounded corners, sides bulging either way and round
/// holes.
#[test]
fn the_fast_axes_of_lines_and_arcs_are_the_bounds_axis() {
    let paths: [(PairSource, Judge); 2] = [
        (PairSource::SeedEdges, traced),
        (PairSource::Pairwise, pairwise),
    ];
    stands_as_the_bounds(&mut rng(3902), &paths, |rnd, _| random_rounded(rnd));
}
