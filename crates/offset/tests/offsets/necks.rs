//! Necks, dips and bumps of the axis's radius (most found by the random regions): where loops
//! close, split, pinch or stand, their seams and joints, and offsets at the vertices' radii.

use crate::common::{arcs_sweep, ends, samples};
use crate::helpers::{
    certified_offsets, chain_round_a_hole, checked_offsets, circle, distance_to_piece, offsets_of,
    pocket, polygon_region,
};
use crate::oracle::{check, check_against, fine_chords, Chords};
use crate::random_regions;
use curve::Region;
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use offset::{offsets, OffsetOptions};
use std::f64::consts::TAU;
use testkit::outlines::polygon;

/// Between two equal round holes the axis is straight, and its radius is least at the neck
/// between them, where it need have no vertex: a distance just above the neck's radius must
/// not keep a passage that is not there (or must not be certified), and one just below it
/// keeps the passage, certified where points along the step show the radius above it.
#[test]
fn a_neck_between_two_round_holes_closes() {
    let outer = polygon(&[[-4.0, -4.0], [4.0, -4.0], [4.0, 4.0], [-4.0, 4.0]]);
    let region = Region::new(
        outer,
        vec![circle([-1.5, 0.0], 1.0), circle([1.5, 0.0], 1.0)],
    )
    .unwrap();
    for d in [0.45, 0.499, 0.4999999, 0.5005, 0.55, 0.8] {
        let (found, _) = checked_offsets(&region, &[d], 1e-6);
        // (Round the pocket and each hole while the neck is open, then round both holes.)
        assert_eq!(
            found.offsets[0].loops.len(),
            if d < 0.5 { 3 } else { 2 },
            "d = {d}"
        );
        // (At 0.4999999 the neck's least radius, found on the axis between its vertices, is
        // 1e-7 above the distance: open.)
        assert!(found.certified(), "d = {d}: {:?}", found.reason());
    }
}

/// A smooth oval of four cubic Béziers about the origin, 2, 1.1, 1.9 and 1 out along the
/// axes: its medial axis has its widest disk inside an edge, and leaves at centres of
/// curvature.
fn oval() -> Region {
    let segs = testkit::profiles::bezier_chain(
        &[2.0, 1.1, 1.9, 1.0],
        &[(0.05, 0.05), (0.05, -0.05), (-0.05, 0.05), (0.05, 0.05)],
        &[true, true, true, true],
    )
    .unwrap();
    Region::new(testkit::profiles::assemble(segs, 0, false).unwrap(), vec![]).unwrap()
}

/// An L of arms exactly twice the distance wide: the arms are closed (they are the distance
/// from both sides), the elbow is wider, and its loop touches the arms' middles, turning back
/// there. The horns' tips are cut where they are 1e-8 of the size wide, so that the loop is a
/// profile (which cannot turn back).
#[test]
fn arms_exactly_twice_the_distance_wide_leave_the_elbow() {
    let region = polygon_region(&[
        [0.0, 0.0],
        [6.0, 0.0],
        [6.0, 1.0],
        [1.0, 1.0],
        [1.0, 6.0],
        [0.0, 6.0],
    ]);
    let (found, _) = checked_offsets(&region, &[0.5], 1e-6);
    assert_eq!(found.offsets[0].loops.len(), 1);
    let elbow = &found.offsets[0].loops[0];
    let profile = elbow.profile();
    assert!(profile.is_ok(), "{profile:?}: {elbow:?}");
    // (Two lines and the arc about the reflex corner, two cuts.)
    assert_eq!(elbow.segments.len(), 5, "{elbow:?}");
}

/// A loop of a few millionths of the size, about to vanish (a random polygon with a hole,
/// found with 120 cases): its two arcs, each ended at its own foot of the seam, ended 8e-15
/// apart, more than the reader allows a joint on so small a loop. Joints are now where the
/// circles cross, to the rounding of the coordinates.
#[test]
fn a_vanishing_loops_joints_are_exact() {
    let radii = [
        0.6,
        0.6,
        0.6,
        0.6,
        0.6,
        0.6,
        1.0411656753651706,
        0.730616930899417,
        1.09808795557149,
        0.8055810147776206,
    ];
    let mut turns = [0.0; 11];
    turns[7..10].copy_from_slice(&[0.7242960815328968, -0.5902672261327535, -0.4429535495315861]);
    let region = random_regions::region(&radii, &turns, true);
    let found = offsets_of(&region, &[0.36592819494784207]);
    let tiny = found.offsets[0]
        .loops
        .iter()
        .find(|l| {
            let (lo, hi) = l.segments.iter().flat_map(|s| samples(s, 8)).fold(
                ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
                |(lo, hi), p| {
                    (
                        [lo[0].min(p[0]), lo[1].min(p[1])],
                        [hi[0].max(p[0]), hi[1].max(p[1])],
                    )
                },
            );
            (hi[0] - lo[0]).max(hi[1] - lo[1]) < 1e-5
        })
        .expect("the vanishing loop");
    assert!(tiny.profile().is_ok(), "{:?}", tiny.profile().err());
    for (k, s) in tiny.segments.iter().enumerate() {
        let (_, end) = ends(s);
        let (next, _) = ends(&tiny.segments[(k + 1) % tiny.segments.len()]);
        let gap = (end[0] - next[0]).hypot(end[1] - next[1]);
        assert!(gap <= 4.0 * f64::EPSILON, "joint {k}: {gap}");
    }
}

/// Between a round hole and a chain of Béziers the radius dips just below the distance at one
/// vertex of the axis (found with 240 random chains): the seams on either side of the dip
/// were both solved for at the far one, since there the two offsets run nearly parallel and
/// Newton's first step leapt across, so the loop touched itself and went round all of the
/// hole's offset. Each seam is now solved for within its step of the axis.
#[test]
fn the_seams_either_side_of_a_dip_are_apart() {
    let radii = [
        1.0,
        1.779630083359844,
        1.1923283520648418,
        1.3734189100855305,
    ];
    let mut wobble = [(-0.05, -0.05); 4];
    wobble[2].0 = 0.27650936262867126;
    let region = chain_round_a_hole(&radii, &wobble, &[false, false, false, true]);
    let found = certified_offsets(&region, 0.31863438899044777);
    let loops = &found.offsets[0].loops;
    assert_eq!(loops.len(), 1);
    assert!(loops[0].profile().is_ok(), "{:?}", loops[0].profile().err());
    // (The hole's offset is left where it passes the dip: its arcs span less than a turn.)
    let turned = arcs_sweep(&loops[0].segments);
    assert!(turned < TAU - 0.2, "the hole's offset turns {turned}");
    check(&region, &found, 2e-3);
}

/// A round hole beside a chain of three Béziers, where the radius dips to 0.3376 between two
/// vertices of the axis at 0.3416 and 0.3411 (found with 240 random chains): at 0.3386 the
/// hole's offset and the outer one merge through that neck, which no vertex shows. Points of
/// the step moved onto the axis show the dip, and bisection on them finds the two seams
/// either side, where the loops join (they were two loops crossing, uncertified).
#[test]
fn a_neck_between_two_vertices_is_pinched_through() {
    let radii = [1.3575459749564318, 1.7484363407870969, 1.891938139778087];
    let wobble = [(0.09469513577707032, -0.05), (-0.05, -0.05), (-0.05, -0.05)];
    let region = chain_round_a_hole(&radii, &wobble, &[false, true, false]);
    let found = certified_offsets(&region, 0.3386013494889568);
    let loops = &found.offsets[0].loops;
    assert_eq!(loops.len(), 1, "{loops:?}");
    assert!(loops[0].profile().is_ok(), "{:?}", loops[0].profile().err());
    check(&region, &found, 4e-3);
}

/// A neck between a round hole and a chain of Béziers, between two vertices of the axis
/// where it curves round the hole (found with 480 random chains): whether the radius falls at
/// one vertex and rises at the other was judged along the step's chord from one foot, which
/// on a curved axis is not the radius's slope, and the neck went unseen (the loops crossed,
/// uncertified). The slope is taken along the axis, across the chord between the feet; at
/// 0.5530 the region splits in two there.
#[test]
fn a_neck_where_the_axis_curves_round_a_hole_is_seen() {
    let radii = [1.367748594300923, 1.451288655030718, 1.5787204787821496];
    let region = chain_round_a_hole(&radii, &[(-0.05, -0.05); 3], &[false, true, true]);
    let found = certified_offsets(&region, 0.5530143102806266);
    let loops = &found.offsets[0].loops;
    assert_eq!(loops.len(), 2);
    for l in loops {
        assert!(l.profile().is_ok(), "{:?}", l.profile().err());
    }
    check(&region, &found, 4e-3);
}

/// A bump of the radius between two vertices both below the distance (the axis of an oval,
/// the vertex at its widest removed): a small loop of the offset stands there, between two
/// seams found as a neck's are; without them it was missed, and the offsets certified.
#[test]
fn a_bump_between_two_vertices_has_its_loop() {
    let region = oval();
    let mut axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    assert!(axis.certified(), "{:?}", axis.reason());
    // The widest vertex inside an edge, and the edge without it.
    let (e, k) = axis
        .edges
        .iter()
        .enumerate()
        .flat_map(|(e, edge)| (1..edge.xy.len() - 1).map(move |k| (e, k)))
        .max_by(|a, b| axis.edges[a.0].radius[a.1].total_cmp(&axis.edges[b.0].radius[b.1]))
        .expect("an edge with an inner vertex");
    let edge = &mut axis.edges[e];
    let widest = edge.radius[k];
    let below = edge.radius[k - 1].max(edge.radius[k + 1]);
    let top = edge.xy[k];
    edge.xy.remove(k);
    edge.radius.remove(k);
    edge.feet.remove(k);
    edge.boundary.remove(k);
    let d = below + 0.5 * (widest - below);
    let found = offsets(&region, &axis, &[d], &OffsetOptions::default()).unwrap();
    assert!(found.certified(), "{:?}", found.reason());
    let loops = &found.offsets[0].loops;
    assert_eq!(loops.len(), 1, "d = {d} between {below} and {widest}");
    let near = loops[0]
        .segments
        .iter()
        .map(|s| distance_to_piece(top, s))
        .fold(f64::INFINITY, f64::min);
    assert!(
        near <= widest - below,
        "the loop is {near} from the widest point"
    );
    check(&region, &found, 4e-3);
}

/// Offsets at exactly the radius of each vertex of the axis (the seam at a vertex, the
/// swallowtail shrunk to a point at a leaf, a pass touching the island, the widest disk) are
/// certified and at the distance, with as many loops as just below or just above it.
#[test]
fn offsets_at_the_axis_vertices_radii_are_certified() {
    for region in [oval(), pocket()] {
        let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
        let (lo, hi) = Chords::of(&region, 100).bounds();
        let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let mut radii: Vec<f64> = axis
            .edges
            .iter()
            .flat_map(|e| e.radius.iter().copied())
            .filter(|&r| r > 1e-6 * size)
            .collect();
        radii.sort_by(f64::total_cmp);
        radii.dedup();
        assert!(radii.len() > 50);
        let opts = OffsetOptions::default();
        let chords = fine_chords(&region);
        for &r in &radii {
            let aside = 1e-6 * size;
            let found = offsets(&region, &axis, &[r - aside, r, r + aside], &opts).unwrap();
            assert!(found.certified(), "d = {r}: {:?}", found.reason());
            check_against(&chords, &found, 1e-3 * size, 100);
            let count: Vec<usize> = found.offsets.iter().map(|o| o.loops.len()).collect();
            assert!(
                count[1] == count[0] || count[1] == count[2],
                "d = {r}: {count:?} loops"
            );
        }
    }
}

/// A case the random test found: an axis edge whose vertices list their two feet in the other
/// order after a reflex corner takes over one side (seams must pair feet by side).
#[test]
fn feet_listed_in_either_order_are_paired_by_side() {
    let radii = [
        0.8934658253940653,
        0.6,
        0.6,
        0.6,
        0.6,
        0.6,
        1.2262237539045797,
        0.7837112724784945,
        1.341901869548578,
    ];
    let mut turns = [0.0; 11];
    turns[7] = 0.7892853767185828;
    turns[8] = -0.47010607440650237;
    let region = random_regions::region(&radii, &turns, false);
    let found = offsets_of(&region, &[0.43051319204881144]);
    assert!(found.certified() && found.complete, "{:?}", found.reason());
    check(&region, &found, 1e-6);
}
