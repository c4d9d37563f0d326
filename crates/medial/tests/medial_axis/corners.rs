//! Cases found beside corners: fillet centres, reflex corners' stretches, leaves and
//! junctions, and the benchmarks' chains of cubics.

use crate::helpers::{checked_region, end_foot};
use crate::oracle::shaped_like_the_region;
use crate::traced::axis;
use curve::Region;
use medial::NodeKind;
use numeric::certificate::Verdict;
use testkit::profiles::{assemble, bezier_chain_profile, stepped_polygon};

/// A filleted triangle whose two straight sides' bisector ends at a fillet's centre: the
/// end's feet are the sides' tangent points, at the joints with the arc, which the
/// certificate (and the oracle check) take as on the arc (found by a random sweep once the
/// two sides' bisector came in closed form, its end no longer met on the arc).
#[test]
fn an_end_at_a_fillet_centre_with_its_feet_at_the_joints() {
    let steps = [1.2848230929075242, 0.8138003385839884, 1.379317469934494];
    let radii = [
        1.8340827039167142,
        1.166597570924415,
        1.08728821403208,
        1.0,
        1.0,
        1.0,
        1.0,
    ];
    let round = [0.9157530236956428, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0];
    let segs = stepped_polygon(&steps, &radii, &round).unwrap();
    let region = checked_region(assemble(segs, 2, false).unwrap(), &[]);
    assert!(axis(&region).certified());
}

/// A chain of Béziers with a reflex corner where the bisector of the segment after the
/// corner and the corner itself has a stretch 9e-4 long, its feet closing in on the corner
/// at both ends: its two ends had been merged as one leaf's tip, which closed it into a loop
/// (the graph then said a region without holes had a cycle). The two ends of a stretch
/// longer than a stub stay apart now (found by a random sweep).
#[test]
fn a_short_stretch_beside_a_reflex_corner_is_no_loop() {
    let radii = [
        1.667916643291305,
        1.8662456717342735,
        1.5069512226395496,
        1.059050185545153,
        1.4543446782390808,
    ];
    let wobble = [
        (-0.05, -0.05),
        (-0.2864027286765499, -0.05),
        (-0.05, -0.11954445407404432),
        (-0.14240106738110647, -0.10247399197300341),
        (0.09959707074505725, -0.05),
        (-0.05, -0.05),
    ];
    let smooth = [true, false, false, false, false, false];
    let outer = bezier_chain_profile(&radii, &wobble[..5], &smooth[..5], 0, false);
    let region = checked_region(outer.unwrap(), &[]);
    assert!(axis(&region).edges.iter().all(|e| e.from != e.to));
}

/// A filleted polygon with a small hole, whose corner between two straight sides starts a
/// stretch of their closed-form bisector with no vertex before its junction: the points the
/// junction's bracket snapped onto the bisector came from a secant started at the corner,
/// on the kept side's own line, where the equidistant point is at infinity; half of them
/// failed, and the stretch ended as a leaf 0.3 short of its junction, the graph in two
/// pieces (found by a random sweep). The secant now tries again from the guessed foot.
#[test]
fn a_corners_stretch_reaches_its_junction_with_no_vertex_between() {
    let steps = [
        0.5513225361150629,
        1.01982154142017,
        1.1988542953645818,
        1.193994751493873,
        0.9016869774460274,
        1.2414604812853327,
    ];
    let radii = [
        1.568992751251152,
        1.196578677621842,
        1.8170164169116163,
        1.0,
        1.0,
        1.0,
        1.0,
    ];
    let round = [0.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let segs = stepped_polygon(&steps, &radii, &round).unwrap();
    let region = checked_region(assemble(segs, 0, false).unwrap(), &[([0.0, 0.0], 0.05)]);
    assert!(axis(&region).certified());
}

/// Beside a reflex corner a segment's curvature peaks at the corner: the leaf where its
/// foot closes in on the corner's point ends at the segment's centre of curvature there
/// (it had stopped 4e-5 of the parameter short, at the last foot traced, and was not
/// certified), proven by the curvature falling away from the corner on that side only.
#[test]
fn leaves_beside_reflex_corners_end_at_the_corners_centres_of_curvature() {
    let outline = testkit::outlines::bezier_chain(12);
    let region = checked_region(outline.clone(), &[]);
    let a = axis(&region);
    assert!(a.certified(), "{:?}", a.reason());
    let ends: Vec<_> = a.nodes.iter().filter(|n| n.kind == NodeKind::End).collect();
    assert_eq!(ends.len(), 4);
    for end in ends {
        let (u, _) = end_foot(&a, end.id).unwrap();
        assert_eq!(u, u.round(), "{end:?} has its foot off the corners");
        let k = u.round() as usize;
        // The centre of curvature at the corner on either side.
        let at_centre = [k, (k + 11) % 12].iter().any(|&s| {
            let j = outline.jet_on(s, u, 2);
            let c = j.p + j.d1.perp().unit() * (1.0 / j.curvature());
            (c.x - end.xy[0]).hypot(c.y - end.xy[1]) < 1e-12
                && (1.0 / j.curvature().abs() - end.radius).abs() < 1e-12
        });
        assert!(
            at_centre,
            "{end:?} is not at a centre of curvature at corner {k}"
        );
    }
}

/// The benchmarks' chain of 50 cubics: at the circumcentre of three reflex corners the
/// bisector of the outer two meets those of each with the middle one; the line of two
/// corners was tested at its two ends only, far apart and entered by one site, and its
/// stretch between them was missed (a leaf ended there, uncertified).
#[test]
fn three_reflex_corners_on_one_disk_make_a_junction() {
    let region = checked_region(testkit::outlines::bezier_chain(50), &[]);
    let a = axis(&region);
    assert!(a.certified(), "{:?}", a.reason());
}

/// The benchmarks' chain of 75 cubics: a junction's disk touches a reflex corner and, 9e-3
/// along the corner's own segment, a foot on it. The junction was solved for on the
/// distance to that segment near the corner, which is the foot's (the radius) all along:
/// found 1e-5 apart on two of its branches, it was two leaves, and the graph came apart.
/// The corner is now the third site.
#[test]
fn a_junction_touching_a_corner_beside_its_own_foot_is_one_node() {
    let region = checked_region(testkit::outlines::bezier_chain(75), &[]);
    let a = axis(&region);
    assert!(shaped_like_the_region(&a, 0), "the graph came apart");
    // The 100-segment chain: the branch of a corner and its own segment starts where its
    // disk shrinks to the corner's point; that start had been taken for the leaf's end at
    // the segment's centre of curvature (the foot 0.7 of the radius from the corner), and
    // the branch closed on itself, apart from the rest.
    let region = Region::new(testkit::outlines::bezier_chain(100), vec![]).unwrap();
    assert!(
        shaped_like_the_region(&axis(&region), 0),
        "the graph came apart"
    );
}

/// The benchmarks' chains of 25, 75 and 100 cubics are certified. On the first, the search
/// for where a stretch ends met a disk within rounding of touching the boundary (its node
/// then proven by itself); on the others, a junction touches a corner and, 0.03 of the
/// radius beside it as seen from the junction, a foot on the corner's segment: the
/// difference of those two distances barely changes about the junction, and its proof
/// needs narrow enclosures and a finely cut polygon.
#[test]
fn the_benchmark_chains_are_certified() {
    for n in [25, 75, 100] {
        let region = Region::new(testkit::outlines::bezier_chain(n), vec![]).unwrap();
        let a = axis(&region);
        assert!(a.certified(), "{n} segments: {:?}", a.reason());
        assert!(shaped_like_the_region(&a, 0), "{n} segments came apart");
    }
}
