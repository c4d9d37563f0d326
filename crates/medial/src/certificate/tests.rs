use super::*;
use crate::{medial_axis, MedialOptions, Verdict};
use curve::{Profile, Region, Segment, V2};

const TOL: f64 = numeric::tolerance::DEFAULT_PARAM_TOL;

/// A 10 × 6 pocket with rounded corners of radius 1: four ends at the arcs' centres, two
/// junctions.
fn pocket() -> Region {
    let (w, h, r) = (10.0, 6.0, 1.0);
    let q = std::f64::consts::FRAC_PI_2;
    let segs = vec![
        Segment::line([r, 0.0], [w - r, 0.0]),
        Segment::arc([w - r, r], r, -q, 0.0),
        Segment::line([w, r], [w, h - r]),
        Segment::arc([w - r, h - r], r, 0.0, q),
        Segment::line([w - r, h], [r, h]),
        Segment::arc([r, h - r], r, q, 2.0 * q),
        Segment::line([0.0, h - r], [0.0, r]),
        Segment::arc([r, r], r, 2.0 * q, 3.0 * q),
    ];
    let segs = segs
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .expect("segments");
    Region::new(Profile::new(segs, None).expect("profile"), vec![]).expect("region")
}

#[test]
fn a_pocket_of_lines_and_arcs_is_certified() {
    let region = pocket();
    let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
    assert!(axis.certified(), "{:?}", axis.reason());
    assert_eq!(
        doubt(&Sites::new(&region, false), &axis, TOL, &HashSet::new()),
        None
    );
}

#[test]
fn a_junction_moved_off_its_place_is_not_proven() {
    let region = pocket();
    let sites = Sites::new(&region, false);
    let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
    let j = axis
        .nodes
        .iter()
        .position(|n| n.kind == NodeKind::Junction)
        .expect("a junction");
    // 2e-9 of the size off: the exact point lies outside both disks searched about it.
    let mut moved = axis.clone();
    moved.nodes[j].xy[1] += 2e-9 * sites.size;
    assert_eq!(
        doubt(&sites, &moved, TOL, &HashSet::new()),
        Some(Doubt::Junction)
    );
    // Within the first disk's room it stays proven.
    let mut nudged = axis.clone();
    nudged.nodes[j].xy[1] += 0.2 * JUNCTION_ROOM[0] * sites.size;
    assert_eq!(doubt(&sites, &nudged, TOL, &HashSet::new()), None);
}

/// A 10 × 6 box whose bottom side bends outwards at its middle by `turn` (rad): a convex
/// corner whose leaf meets the two bottom sides' bisectors with the top's at a junction
/// whose two equations of the bottom sides are nearly one.
fn bent_box(turn: f64) -> Region {
    let dip = 5.0 * (0.5 * turn).tan();
    let c = [
        [0.0, 0.0],
        [5.0, -dip],
        [10.0, 0.0],
        [10.0, 6.0],
        [0.0, 6.0],
    ];
    let sides = (0..5)
        .map(|i| Segment::line(c[i], c[(i + 1) % 5]))
        .collect::<Result<Vec<_>, _>>()
        .expect("sides");
    Region::new(Profile::new(sides, None).expect("profile"), vec![]).expect("box")
}

/// Beside a convex corner that turns by 1e-3 to 1e-5 rad, the junction on its leaf is
/// proven in closed form (Krawczyk's test) where the winding test cannot part its
/// equations (from 1e-4 rad on), and lies where the closed form puts it: on the leaf
/// `x = 5`, as far from the top as from the bottom sides' lines.
#[test]
fn a_junction_beside_a_nearly_flat_corner_is_proven_in_closed_form() {
    for turn in [1e-3, 1e-4, 1e-5] {
        let region = bent_box(turn);
        let sites = Sites::new(&region, false);
        let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
        assert!(axis.certified(), "{turn}: {:?}", axis.reason());
        let node = axis
            .nodes
            .iter()
            .find(|n| n.kind == NodeKind::Junction && (n.xy[0] - 5.0).abs() < 0.5)
            .expect("the leaf's junction");
        // (The bottom-left side's unit normal, and the distance from it equal to 6 − y.)
        let dip = 5.0 * (0.5 * turn).tan();
        let normal = V2::new(dip, 5.0) * (1.0 / dip.hypot(5.0));
        let y = (6.0 - 5.0 * normal.x) / (normal.y + 1.0);
        let off = (V2::from_arr(node.xy) - V2::new(5.0, y)).norm();
        assert!(off < JUNCTION_ROOM[1] * sites.size, "{turn}: {off:e}");
        if turn <= 1e-4 {
            let mut edges: Vec<usize> = Vec::new();
            for (k, e) in axis.edges.iter().enumerate() {
                if e.from == node.id || e.to == node.id {
                    edges.push(k);
                }
            }
            let same = SAME_FOOT * sites.size;
            let merged = feet_of(&sites, &axis, &edges, node.id, same);
            assert!(!junction_proven(&sites, node, &merged), "{turn}");
            let all = feet_of(&sites, &axis, &edges, node.id, 0.0);
            assert!(closed_form_junction_proven(&sites, node, &all), "{turn}");
        }
    }
}

#[test]
fn a_graph_missing_an_edge_or_with_a_cycle_too_many_is_no_region_axis() {
    let axis = medial_axis(&pocket(), &MedialOptions::default()).expect("axis");
    assert!(shaped_like_the_region(&axis, 0));
    let mut cut = axis.clone();
    cut.edges.pop();
    assert!(!shaped_like_the_region(&cut, 0));
    let mut looped = axis.clone();
    let twin = looped.edges[0].clone();
    looped.edges.push(twin);
    assert!(!shaped_like_the_region(&looped, 0));
    assert!(shaped_like_the_region(&looped, 1));
}

#[test]
fn a_corner_leaf_at_a_reflex_corner_is_not_proven() {
    let c = [[0., 0.], [4., 0.], [4., 2.], [2., 2.], [2., 4.], [0., 4.]];
    let sides = (0..6)
        .map(|i| Segment::line(c[i], c[(i + 1) % 6]))
        .collect::<Result<Vec<_>, _>>()
        .expect("sides");
    let room = Region::new(Profile::new(sides, None).expect("profile"), vec![]).expect("room");
    let sites = Sites::new(&room, false);
    let mut axis = medial_axis(&room, &MedialOptions::default()).expect("axis");
    assert!(axis.certified(), "{:?}", axis.reason());
    let k = axis
        .nodes
        .iter()
        .position(|n| n.kind == NodeKind::Corner)
        .expect("a corner");
    axis.nodes[k].xy = [2.0, 2.0]; // the reflex corner
    assert_eq!(
        doubt(&sites, &axis, TOL, &HashSet::new()),
        Some(Doubt::CornerLeaf)
    );
}

#[test]
fn an_end_off_its_arcs_centre_is_not_proven() {
    let region = pocket();
    let sites = Sites::new(&region, false);
    let mut axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
    let e = axis
        .nodes
        .iter()
        .position(|n| n.kind == NodeKind::End)
        .expect("an end");
    axis.nodes[e].xy[0] += 2e-9 * sites.size;
    assert_eq!(
        doubt(&sites, &axis, TOL, &HashSet::new()),
        Some(Doubt::AxisEnd)
    );
}

/// The periodic cubic: two ends at centres of curvature of its sharpest points.
fn periodic_cubic() -> Region {
    let pts = testkit::outlines::PERIODIC_CUBIC_POINTS;
    let periodic = curve::SplineCurve::periodic(3, &pts, None).expect("spline");
    let (a, b) = periodic.domain();
    let one_turn = periodic.curve().restrict(a, b).expect("restricted");
    let c = curve::SplineCurve::new(one_turn).expect("spline");
    let seg = Segment::spline(curve::SegmentKind::BSpline, c).expect("segment");
    let outline = Profile::new(vec![seg], Some(true)).expect("profile");
    Region::new(outline, vec![]).expect("region")
}

#[test]
fn ends_at_proven_peaks_of_a_splines_curvature_are_certified() {
    let region = periodic_cubic();
    let sites = Sites::new(&region, false);
    let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
    assert!(axis.certified(), "{:?}", axis.reason());
    assert_eq!(axis.nodes.len(), 2);
    // The same end moved to the centre of curvature 1e-6 along the boundary from its
    // foot: a centre of curvature, but no peak within the tolerance of its foot.
    let mut moved = axis.clone();
    let (e, edge) = (0, &mut moved.edges[0]);
    let (k, u) = if edge.from == e {
        (0, edge.feet[0][0])
    } else {
        (edge.feet.len() - 1, edge.feet[edge.feet.len() - 1][0])
    };
    let b = sites.boundaries[0];
    let v = u + 1e-6;
    let j = b.jet_on(b.locate(v).0, v, 2);
    let centre = j.p + j.d1.perp().unit() * (1.0 / j.curvature());
    edge.feet[k] = [v, v];
    moved.nodes[e].xy = centre.arr();
    moved.nodes[e].radius = 1.0 / j.curvature().abs();
    assert_eq!(
        doubt(&sites, &moved, TOL, &HashSet::new()),
        Some(Doubt::AxisEnd)
    );
    // Its disk is still empty: the rates decided.
    assert_eq!(
        sites.disk(moved.nodes[e].xy, moved.nodes[e].radius),
        Disk::Empty
    );
}
