//! Cases the random regions found on splines and smooth joints: leaves, junctions and
//! branches beside curvature maxima, knots and joints where the curvature jumps.

use crate::helpers::{checked_region, closed_spline, kinds};
use crate::traced::axis;
use curve::Profile;
use medial::NodeKind;
use testkit::profiles::bezier_chain_profile;

/// A random chain with a smooth joint where the curvature jumps from 2.5 to 0.75: the leaf
/// whose feet close in on the joint ends at the centre of curvature of the sharper side,
/// 0.4 from it (it had taken the joint's curvature from the flatter side, 1.33 away, a disk
/// the boundary enters).
#[test]
fn a_leaf_at_a_smooth_joint_ends_at_the_sharper_sides_centre() {
    let radii = [1.5570411342319914, 1.0, 1.0, 1.0, 1.8492921489460934];
    let wobble = [
        (-0.05, -0.05),
        (-0.05, -0.05),
        (0.05, -0.05),
        (-0.05, -0.05),
        (-0.05, -0.05),
    ];
    let outline = bezier_chain_profile(
        &radii,
        &wobble,
        &[false, false, false, true, false],
        0,
        false,
    )
    .unwrap();
    let sharper = 1.0 / outline.jet_on(2, 3.0, 3).curvature().abs();
    assert!(sharper < 0.41 && 1.0 / outline.jet_on(3, 3.0, 3).curvature().abs() > 1.3);
    let a = axis(&checked_region(outline, &[]));
    let ends: Vec<_> = a.nodes.iter().filter(|n| n.kind == NodeKind::End).collect();
    assert_eq!(ends.len(), 1, "{:?}", a.nodes);
    testkit::assert_near!(ends[0].radius, sharper, 1e-9, "{:?} {sharper}", ends[0]);
}

/// CI's random case: a hole's bisector with a cubic runs past the cubic's curvature maximum,
/// where the cubic itself enters the disks by up to 2e-5; the junction's third contact is on
/// the foot's own segment, and its solve must not fall back into that foot.
#[test]
fn a_junction_whose_third_contact_is_on_a_feet_segment() {
    let radii = [
        1.6727626012002006,
        1.0,
        1.7651561410569272,
        1.0343275269823962,
    ];
    let wobble = [
        (-0.05, -0.05),
        (-0.05, -0.05),
        (-0.05, -0.17367561327226244),
        (-0.2006562983337941, 0.17490760724839632),
    ];
    let outer = bezier_chain_profile(&radii, &wobble, &[false; 4], 0, false).unwrap();
    let hole = (
        [-0.8707659644847356, 0.8174766831175151],
        0.20672370399983253,
    );
    checked_region(outer, &[hole]);
}

/// CI's random case: a leaf from a cubic's curvature maximum to a junction, short (1.7e-2)
/// because the disk at the centre of curvature nearly touches the next segment; the foot
/// solve beside the feet's meeting fell into the trivial solution (both feet at one point)
/// and the leaf became a loop at the centre, apart from the rest.
#[test]
fn a_short_leaf_from_a_curvature_maximum_reaches_its_junction() {
    let region = checked_region(sharply_bent_cubics(0), &[]);
    assert_eq!(kinds(&axis(&region), NodeKind::End), 1);
}

/// The same region with a hole beside that leaf: the leaf meets the hole's bisector with
/// the cubic at a junction whose disk touches the cubic on both sides of its curvature
/// maximum. Between them the hole's bisector crosses the evolute and back, off the axis for
/// a stretch narrower than its polyline's step; it must break there too. (From each
/// segment: from the third, the disk test's point entering beside the junction is no longer
/// taken to be the nearest point found, which was the foot itself.)
#[test]
fn a_branch_past_the_evolute_between_two_vertices_breaks_at_its_junction() {
    let hole = (
        [-0.6954968030837503, -0.32210892744741626],
        0.11131415240713867,
    );
    for start in 0..4 {
        checked_region(sharply_bent_cubics(start), &[hole]);
    }
}

/// CI's random chain of four cubics, the last bent sharply (a curvature maximum whose
/// osculating disk nearly touches the segment before), started at segment `start`.
fn sharply_bent_cubics(start: usize) -> Profile {
    let radii = [
        1.8035314906715636,
        1.5098684308198518,
        1.811428679165584,
        1.3965996105786107,
    ];
    let wobble = [
        (-0.05, -0.05),
        (-0.05, -0.05),
        (-0.05, -0.1681011491931554),
        (-0.268686652326142, 0.27506893294054613),
    ];
    bezier_chain_profile(&radii, &wobble, &[false; 4], start, false).unwrap()
}

/// A random closed cubic B-spline of 9 control points (one segment, no hole): the short
/// edge joining its two junctions lies between two polyline vertices of its candidates, off
/// the axis and entered by the same segment; the search for such hidden stretches compared
/// the entering sites by segment, never different on a one-segment boundary. They are now
/// compared by piece (knot span).
#[test]
fn a_short_edge_hidden_between_vertices_of_one_spline_is_found() {
    let radii = [
        1.0511224093873475,
        1.463754729345834,
        1.1463382143957017,
        1.321236160285634,
        1.460932873881018,
        1.1117222968797171,
        1.492016295106644,
        1.079719207003536,
        1.3076141591901762,
    ];
    let region = checked_region(closed_spline(&radii, None).unwrap(), &[]);
    assert_eq!(kinds(&axis(&region), NodeKind::Junction), 2);
}

/// The same fault on a wiggly one (21 control points at radii 1 to 2) with a hole: the
/// hole's cycle was broken.
#[test]
fn a_hole_in_a_wiggly_spline_keeps_its_cycle() {
    let radii = [
        1.334036682899554,
        1.5532322141124781,
        1.3077706286700195,
        1.0727873833733816,
        1.8171124553644258,
        1.2430148004209336,
        1.9938213721982099,
        1.0235893733004309,
        1.4460635228037888,
        1.7743089183678753,
        1.7397035472896019,
        1.3297734094239446,
        1.0484726029267986,
        1.9687424541153078,
        1.8509699072228802,
        1.5731909743782515,
        1.8382137487092314,
        1.0974106481374195,
        1.6387158143762734,
        1.5202080736959023,
        1.9952582250289026,
    ];
    let outer = closed_spline(&radii, None).unwrap();
    let hole = (
        [0.17990307859668112, 0.548683511017336],
        0.13434422286911718,
    );
    checked_region(outer, &[hole]);
}

/// A random chain with two smooth joints and a hole (a wider random run's case): the hole's
/// bisector with the segment after a joint turns between two of its polyline vertices (the
/// hole's foot goes past both of theirs and back) on its way to the junction with the
/// segment before the joint; the exact vertices there were refused as too far from the
/// vertices' feet, and the branch stopped 6e-4 short of its junction, breaking the hole's
/// cycle.
#[test]
fn a_branch_turning_between_its_vertices_reaches_its_junction() {
    let radii = [1.4458403445253272, 1.9907059228053479, 1.1323003324290553];
    let outer =
        bezier_chain_profile(&radii, &[(-0.05, -0.05); 3], &[true, false, true], 0, false).unwrap();
    let hole = (
        [-0.15635263822222772, -0.08988750577444202],
        0.09570641978321387,
    );
    let region = checked_region(outer, &[hole]);
    assert_eq!(kinds(&axis(&region), NodeKind::Junction), 3);
}

/// A random closed NURBS whose curvature peaks just before a knot: the leaf to that peak's
/// centre is cut at the knot, and the two stretches there end 2e-6 apart (the feet are
/// ill-conditioned beside a centre of curvature), so the leaf's tip, 4e-6 long, had both its
/// ends in one node and became a loop (a cycle without a hole). It is a stub: the leaf
/// ends at the tip.
#[test]
fn a_leaf_tip_cut_at_a_knot_is_no_loop() {
    let radii = [
        1.479133819623651,
        1.0570018362329054,
        1.8108436538105146,
        1.8814003504955212,
        1.8088165370835616,
        1.616860332363555,
        1.517638183258671,
        1.198090876029087,
        1.0897072408724409,
        1.1763633862742156,
        1.4899631445465806,
    ];
    let weights = [
        1.5046744967382513,
        0.6694067193137289,
        0.8832749632857433,
        1.0888617116539767,
        1.6362735628711187,
        1.550846791899508,
        0.9253587655197315,
        1.8469327049001967,
        0.7440691955233469,
        1.0389430425540485,
        0.7086053176434862,
    ];
    let region = checked_region(closed_spline(&radii, Some(&weights)).unwrap(), &[]);
    let a = axis(&region);
    let tip = a
        .nodes
        .iter()
        .find(|n| (n.xy[0] - 0.1547016).abs() < 1e-6)
        .unwrap();
    assert_eq!(tip.kind, NodeKind::End);
}

/// A random chain whose curvature peaks just before a smooth joint: the leaf to that peak's
/// centre is made of the bisector of the two segments at the joint and the self-bisector of
/// the first, whose ends beside the centre (the feet ill-conditioned there) lay 2.3e-5 of
/// the size apart, every vertex on the axis; the leaf's tip was a piece of its own, apart
/// from the rest of the axis.
#[test]
fn a_leaf_to_a_peak_beside_a_smooth_joint_is_one_edge() {
    let radii = [
        1.0,
        1.9663460010865133,
        1.084056684050446,
        1.7325378671521632,
    ];
    let wobble = [
        (-0.05, -0.05),
        (0.25552091945791006, -0.05),
        (-0.05, -0.05),
        (-0.05, -0.05),
    ];
    let outer = bezier_chain_profile(&radii, &wobble, &[false, false, true, false], 0, false);
    let region = checked_region(outer.unwrap(), &[]);
    assert_eq!(kinds(&axis(&region), NodeKind::End), 1);
}

/// A random chain with a smooth joint where the curvature jumps, and a peak of the
/// curvature 0.018 past it: two leaves end 1.9e-3 apart, at the joint's sharper side's centre
/// and at the peak's. The peak's tip lay 1.2e-4 from where two stretches of the other leaf
/// meet (feet apart, beside the joint): merged as ends beside one centre of curvature, it
/// closed a cycle in a region without holes. Tip ends are one node only where their feet
/// close in on one foot.
#[test]
fn two_leaf_tips_beside_a_smooth_joint_are_two_nodes() {
    let radii = [1.1734166947687361, 1.358203108478783, 1.5105291489044317];
    let wobble = [
        (-0.05, -0.17253932115048498),
        (-0.05, -0.05),
        (-0.05, -0.05),
    ];
    let outer = bezier_chain_profile(&radii, &wobble, &[true, false, true], 1, false);
    let region = checked_region(outer.unwrap(), &[]);
    let a = axis(&region);
    assert_eq!(
        (kinds(&a, NodeKind::End), kinds(&a, NodeKind::Junction)),
        (3, 2)
    );
}
