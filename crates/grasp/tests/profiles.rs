//! Profiles against the independent dense check: random star polygons with some corners
//! rounded by arcs (corners convex and reflex, lines and arcs) and closed chains of cubic
//! Béziers with corners. On a grid of pairs away from every reported boundary, force closure
//! decided from the profile's points and tangents alone agrees with membership in the
//! regions (the corner lines are measure zero: the grid never meets them).

use curve::Profile;
use grasp::{grasps, GraspOptions, GraspRegion, Grasps};
use numeric::certificate::Doubt;
use proptest::prelude::*;
use testkit::boundary_oracle::{off_polylines, winding};
use testkit::grasp_oracle::{in_stretches, least_friction, slip_angle, BEST_PROVEN_SHARE};
use testkit::profiles::{bezier_chain_profile, stepped_polygon};

/// Grid points per side of the square of pairs.
const GRID: usize = 80;

fn held(g: &Grasps, p: [f64; 2]) -> bool {
    g.regions.iter().any(|r| region_holds(r, p))
}

fn region_holds(r: &GraspRegion, p: [f64; 2]) -> bool {
    let parts: Vec<&Vec<[f64; 2]>> = if r.parts.is_empty() {
        vec![&r.boundary]
    } else {
        r.parts.iter().collect()
    };
    parts.iter().any(|part| winding(part, p) != 0) && !r.holes.iter().any(|h| winding(h, p) != 0)
}

/// The rounding of a grid pair's least friction (from points and tangents).
const FRICTION_ROUNDING: f64 = 1e-9;

fn check(p: &Profile, mu: f64) -> Result<(), TestCaseError> {
    let opts = GraspOptions::friction(mu);
    let g = grasps(p, &opts).map_err(|e| TestCaseError::fail(format!("{e}")))?;
    prop_assert!(g.complete);
    // Every boundary is resolved, corners sharper than twice the friction angle too (their
    // pinch grasps at the apex are traced in the blown-up corner).
    prop_assert!(
        !g.doubts
            .iter()
            .any(|d| *d == Doubt::GraspBoundaryUnresolved || *d == Doubt::GraspPairLost),
        "a boundary left unresolved: {:?}",
        g.doubts
    );
    let (a, b) = p.document_domain();
    let n = p.segments().len() as f64;
    // The chord tolerance is per cell (a pair of segments): a few of them, in the document's
    // parameter.
    let margin = 4.0 * opts.settings.chord_tol.get() * std::f64::consts::SQRT_2 * (b - a) / n;
    let lines: Vec<&[[f64; 2]]> = g
        .regions
        .iter()
        .flat_map(|r| {
            std::iter::once(r.boundary.as_slice())
                .chain(r.parts.iter().map(Vec::as_slice))
                .chain(r.holes.iter().map(Vec::as_slice))
        })
        .collect();
    // Per region, the least friction its grid pairs need outside the stretches spared.
    let mut least = vec![f64::INFINITY; g.regions.len()];
    for i in 0..GRID {
        for j in i + 1..GRID {
            let s = a + (b - a) * (i as f64 + 0.31) / GRID as f64;
            let t = a + (b - a) * (j as f64 + 0.37) / GRID as f64;
            if off_polylines([s, t], lines.iter().copied()) <= margin {
                continue;
            }
            let fc = slip_angle(p, s, t) <= mu.atan();
            prop_assert_eq!(
                fc,
                held(&g, [s, t]),
                "pair ({}, {}), slip {}",
                s,
                t,
                slip_angle(p, s, t)
            );
            for (k, r) in g.regions.iter().enumerate() {
                if region_holds(r, [s, t]) && !in_stretches(&r.best.toward, (a, b), [s, t]) {
                    least[k] = least[k].min(least_friction(p, s, t));
                }
            }
        }
    }
    let proven = !g.doubts.iter().any(|d| *d == Doubt::GraspBestUnproven);
    for (r, least) in g.regions.iter().zip(least) {
        prop_assert!(r.certified || !g.doubts.is_empty());
        prop_assert!(
            r.best.min_friction <= mu * (1.0 + 1e-9) + 1e-12,
            "best {:?}",
            r.best
        );
        if proven {
            prop_assert!(
                least >= r.best.min_friction * (1.0 - BEST_PROVEN_SHARE) - FRICTION_ROUNDING,
                "a grid pair of the region needs friction {}, its proven best {:?}",
                least,
                r.best
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(24)))]

    /// Star polygons of 3 to 7 vertices, some corners rounded.
    #[test]
    fn filleted_polygons_match_the_dense_check(
        steps in prop::collection::vec(0.5..1.5f64, 3..=7),
        radii in prop::collection::vec(0.5..1.0f64, 7),
        round in prop::collection::vec(-1.0..1.0f64, 7),
        mu in 0.05..1.0f64,
    ) {
        let Some(segments) = stepped_polygon(&steps, &radii, &round) else { return Ok(()) };
        let p = Profile::new(segments, Some(true)).map_err(|e| TestCaseError::reject(format!("{e}")))?;
        check(&p, mu)?;
    }

    /// Closed chains of 3 to 6 cubic Béziers, some joints corners.
    #[test]
    fn bezier_chains_match_the_dense_check(
        radii in prop::collection::vec(0.6..1.0f64, 3..=6),
        wobble in prop::collection::vec((-0.2..0.2f64, -0.2..0.2f64), 6),
        smooth in prop::collection::vec(any::<bool>(), 6),
        mu in 0.05..1.0f64,
    ) {
        let n = radii.len();
        let Some(p) = bezier_chain_profile(&radii, &wobble[..n], &smooth[..n], 0, false) else { return Ok(()) };
        check(&p, mu)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(24)))]

    /// Curved triangles (three cubic Béziers meeting at corners) at frictions up to 2: corners
    /// sharper than twice the friction angle, whose pinch grasps reach the apex, where every
    /// condition vanishes.
    #[test]
    fn pinch_grasps_of_sharp_corners_match_the_dense_check(
        radii in prop::collection::vec(0.6..1.0f64, 3),
        wobble in prop::collection::vec((-0.2..0.2f64, -0.2..0.2f64), 3),
        mu in 0.5..2.0f64,
    ) {
        let Some(p) = bezier_chain_profile(&radii, &wobble, &[false; 3], 0, false) else { return Ok(()) };
        check(&p, mu)?;
    }
}

/// Polygons at frictions above 1: every corner sharper than twice the friction angle, with
/// pinch grasps at its apex, resolved and matching the dense check.
#[test]
fn polygons_at_high_friction_match_the_dense_check() {
    let shapes: [&[[f64; 2]]; 3] = [
        &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
        &[[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [0.0, 1.0]],
        &[[0.0, 0.0], [3.0, 0.0], [1.0, 1.5]],
    ];
    for pts in shapes {
        for mu in [1.01, 1.5, 2.5] {
            let p = testkit::outlines::polygon(pts);
            if let Err(e) = check(&p, mu) {
                panic!("{pts:?}, μ = {mu}: {e}");
            }
        }
    }
}

/// A curved triangle whose corner at `s = 0` is sharper than twice the friction angle by
/// rounding only: its pinch grasps are a sliver within rounding of its traced edges, which
/// bows off the chord between them. Its best grasp is force closure (it was a pair on that
/// chord, needing friction 1e-4 above μ).
#[test]
fn a_sliver_s_best_grasp_is_force_closure() {
    let radii = [0.6610079091478593, 0.6709095683454489, 0.9761862535469958];
    let wobble = [
        (-0.1048536317505381, -0.024467017214925127),
        (0.0, 0.0),
        (-0.12276907646779311, 0.17303808593117304),
    ];
    let p = bezier_chain_profile(&radii, &wobble, &[false; 3], 0, false).unwrap();
    check(&p, 0.5323860168239313).unwrap();
}

/// A chain whose corners 0 and 1 have lines of pairs running, in the other finger, through
/// the reflex corner 3: the pair of a corner with a reflex corner is no grasp, so each line is
/// cut there, and the two regions it reaches on either side stay two (they were glued into
/// one, and certified, where the seam did not cut the line; started at corner 3 they were
/// two).
#[test]
fn a_corner_line_is_cut_where_the_other_finger_passes_a_reflex_corner() {
    let radii = [0.6, 0.6, 0.9623899084810694, 0.6, 0.9640104697933801, 0.6];
    let wobble = [
        (0.0, 0.0),
        (0.0, 0.0),
        (0.0, -0.11022444340699881),
        (0.0, 0.1374148912040726),
        (0.0, 0.0),
        (0.0, 0.0),
    ];
    let mu = 1.0350875222897833;
    for start in [0, 3] {
        let p = bezier_chain_profile(&radii, &wobble, &[false; 6], start, false).unwrap();
        check(&p, mu).unwrap();
        let g = grasps(&p, &GraspOptions::friction(mu)).unwrap();
        assert!(g.doubts.is_empty(), "start {start}: {:?}", g.doubts);
        assert_eq!(g.regions.len(), 2, "start {start}");
    }
}

/// A rectilinear outline turned 45° at μ = 0.5: cones' edges run exactly through other
/// corners (slopes 1/2 and 2 on a half-unit grid), whose conditions vanish at segments' ends
/// to rounding. Those roots are the other finger at a joint, decided apart: no doubt is said
/// (they once left every region uncertified).
#[test]
fn cone_edges_through_corners_leave_no_doubt() {
    let p = skyline(
        &[1.0, 1.5, 0.5],
        &[1.5, 2.0, 0.5],
        std::f64::consts::FRAC_PI_4,
    )
    .unwrap();
    check(&p, 0.5).unwrap();
    let g = grasps(&p, &GraspOptions::friction(0.5)).unwrap();
    assert!(g.doubts.is_empty(), "{:?}", g.doubts);
}

/// A right angle at μ = 1 exactly: its pinch grasps are the line of mirror pairs of its two
/// sides, a set with no inside. The result says its boundary is unresolved and certifies no
/// region (it once traced that line as a region with area, and certified it).
#[test]
fn a_right_angle_at_friction_one_certifies_nothing() {
    // (The kite's sides of slopes 2 and −2 at μ = 0.5: the cones' edges along the horizontal
    // chords between them, the same set without inside.)
    for (pts, mu) in [
        ([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]], 1.0),
        ([[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [0.0, 1.0]], 1.0),
        ([[2.0, 0.0], [0.0, 4.0], [-2.0, 0.0], [0.0, -2.0]], 0.5),
    ] {
        let p = testkit::outlines::polygon(&pts);
        let g = grasps(&p, &GraspOptions::friction(mu)).unwrap();
        assert!(
            g.doubts
                .iter()
                .any(|d| *d == Doubt::GraspBoundaryUnresolved),
            "{pts:?}"
        );
        assert!(g.regions.iter().all(|r| !r.certified), "{pts:?}");
    }
}

/// A circle as SVG and most drawing programs write it: four cubic Béziers of `k = 0.5523 r`.
fn drawn_circle(r: f64) -> Option<Profile> {
    let k = 0.552_284_749_831 * r;
    let quarters = [
        [[r, 0.0], [r, k], [k, r], [0.0, r]],
        [[0.0, r], [-k, r], [-r, k], [-r, 0.0]],
        [[-r, 0.0], [-r, -k], [-k, -r], [0.0, -r]],
        [[0.0, -r], [k, -r], [r, -k], [r, 0.0]],
    ];
    let segments = quarters
        .iter()
        .map(|q| {
            let c = curve::SplineCurve::clamped(3, q, None, None).ok()?;
            curve::Segment::spline(curve::SegmentKind::Bezier, c).ok()
        })
        .collect::<Option<Vec<_>>>()?;
    Profile::new(segments, None).ok()
}

/// The CAD shapes of the tests below: a slot (stadium) off the origin, a rectangle with
/// fillets and a drawn circle.
fn cad_shapes() -> Option<[Profile; 3]> {
    use testkit::far_joints::{filleted_rectangle, stadium};
    Some([
        stadium([1.0, -2.0], 2.0, 1.0),
        filleted_rectangle([0.0, 0.0], 4.0, 3.0, 0.5, 0.0),
        drawn_circle(2.0)?,
    ])
}

/// Shapes as CAD parts and drawings have them: a slot (stadium), a filleted rectangle and a
/// drawn circle. Parallel sides (turned any way: the pairs do not see the axes) make the cone
/// conditions at both contacts coincide along whole cells; they part at the joints into the
/// arcs, crossing on the cells' edges (to rounding: within 1e-10 of them, the piece of one
/// zero set from the edge to the crossing a few ulps long). Each is resolved and matches the
/// dense check (the slot was left unresolved at μ = 0.1, 1 and 2, the rectangle at 0.5 and
/// the circle at 1; earlier, all of them, the slot in 4 regions, the rectangle in 8).
#[test]
fn aligned_cad_shapes_match_the_dense_check() {
    let [slot, part, circle] = cad_shapes().unwrap();
    for mu in [0.1, 0.3, 0.5, 0.7, 1.0, 2.0] {
        check(&slot, mu).unwrap_or_else(|e| panic!("slot at μ = {mu}: {e}"));
    }
    for mu in [0.1, 0.3, 0.5, 0.7, 2.0] {
        check(&part, mu).unwrap_or_else(|e| panic!("filleted rectangle at μ = {mu}: {e}"));
    }
    for mu in [0.3, 1.0] {
        check(&circle, mu).unwrap_or_else(|e| panic!("drawn circle at μ = {mu}: {e}"));
    }
    // The slot: the family across its sides and the pair across its ends, apart (a chord
    // turning from one to the other leaves both cones).
    for mu in [0.1, 0.3] {
        let g = grasps(&slot, &GraspOptions::friction(mu)).unwrap();
        assert_eq!(g.regions.len(), 2, "μ = {mu}");
        assert!(g.regions.iter().all(|r| r.certified), "μ = {mu}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(16)))]

    /// Filleted rectangles and slots as drawn (sizes in halves, fillets in tenths, at the
    /// origin or off it, square to the axes or turned), at frictions as typed (0.1, 0.25, …)
    /// or any from 0.05 to 2: parallel sides whose cone conditions coincide, parting at the
    /// arcs on the cells' edges. Round numbers put those crossings exactly on the edges
    /// (random ones rarely do). (Not within 1e-3 of μ = 1, where each quarter fillet's two
    /// ends pair exactly at the cones' edges: a set touching itself at a point, said
    /// unresolved.)
    #[test]
    fn filleted_rectangles_and_slots_match_the_dense_check(
        w in (2u32..=10).prop_map(|k| 0.5 * f64::from(k)),
        h in (2u32..=10).prop_map(|k| 0.5 * f64::from(k)),
        share in (1u32..=4).prop_map(|k| 0.1 * f64::from(k)),
        turn in prop_oneof![
            Just(0.0),
            Just(std::f64::consts::FRAC_PI_2),
            Just(std::f64::consts::FRAC_PI_4),
            0.0..std::f64::consts::TAU,
        ],
        o in ((-3i32..=3), (-3i32..=3)).prop_map(|(x, y)| (f64::from(x), f64::from(y))),
        mu in prop_oneof![
            prop::sample::select(vec![0.1, 0.2, 0.25, 0.3, 0.5, 0.75, 1.5, 2.0]),
            0.05..2.0f64,
        ],
    ) {
        use testkit::far_joints::{filleted_rectangle, stadium};
        prop_assume!((mu - 1.0).abs() > 1e-3);
        let part = filleted_rectangle([o.0, o.1], w, h, share * w.min(h), turn);
        check(&part, mu)?;
        check(&stadium([o.0, o.1], 0.5 * w, 0.5 * h), mu)?;
    }
}

/// A skyline: columns of widths `widths` and heights `heights` on a common base, turned by
/// `turn` (a rectilinear outline as CAD parts have them: parallel sides in every cell, right
/// angles convex and reflex). `None` where two neighbouring columns are within 0.1 of one
/// height (their joint would be a straight angle).
fn skyline(widths: &[f64], heights: &[f64], turn: f64) -> Option<Profile> {
    if heights.windows(2).any(|h| (h[0] - h[1]).abs() < 0.1) {
        return None;
    }
    let mut xs = vec![0.0];
    for w in widths {
        xs.push(xs[xs.len() - 1] + w);
    }
    let mut pts = vec![[0.0, 0.0], [xs[xs.len() - 1], 0.0]];
    for k in (0..heights.len()).rev() {
        pts.push([xs[k + 1], heights[k]]);
        pts.push([xs[k], heights[k]]);
    }
    let (c, s) = (turn.cos(), turn.sin());
    let turned: Vec<[f64; 2]> = pts
        .iter()
        .map(|p| [c * p[0] - s * p[1], s * p[0] + c * p[1]])
        .collect();
    Some(testkit::outlines::polygon(&turned))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(16)))]

    /// Rectilinear outlines of 1 to 4 columns, sized in halves, square to the axes or turned,
    /// at frictions as typed or any from 0.05 to 2 (not within 1e-3 of 1, where a right
    /// angle's pinch grasps are a line without inside).
    #[test]
    fn rectilinear_outlines_match_the_dense_check(
        widths in prop::collection::vec((1u32..=4).prop_map(|k| 0.5 * f64::from(k)), 1..=4),
        heights in prop::collection::vec((1u32..=6).prop_map(|k| 0.5 * f64::from(k)), 4),
        turn in prop_oneof![Just(0.0), Just(std::f64::consts::FRAC_PI_4), 0.0..std::f64::consts::TAU],
        mu in prop_oneof![
            prop::sample::select(vec![0.1, 0.2, 0.25, 0.3, 0.5, 0.75, 1.5, 2.0]),
            0.05..2.0f64,
        ],
    ) {
        prop_assume!((mu - 1.0).abs() > 1e-3);
        let Some(p) = skyline(&widths, &heights[..widths.len()], turn) else { return Ok(()) };
        check(&p, mu)?;
    }
}

/// Whether two sides' friction cones share an edge direction, reversed: their normals are
/// exactly `2 atan μ` off opposite (a right angle at μ = 1; the kite's slopes ±2 at 0.5). The
/// pairs across them whose chord runs along that edge are then force closure with no margin
/// and no others near them are: a set without inside, said unresolved.
fn cones_share_an_edge(pts: &[[f64; 2]], mu: f64) -> bool {
    let n = pts.len();
    let dir = |k: usize| {
        let (a, b) = (pts[k], pts[(k + 1) % n]);
        (b[1] - a[1]).atan2(b[0] - a[0])
    };
    (0..n).any(|i| {
        (0..n).any(|j| {
            let apart = (dir(i) - dir(j) - std::f64::consts::PI).rem_euclid(std::f64::consts::TAU);
            let off = apart.min(std::f64::consts::TAU - apart);
            i != j && (off - 2.0 * mu.atan()).abs() < 1e-9
        })
    })
}

/// A polygon with its vertices on the integer grid: the points nearest `radii[k]` along
/// `k/n` of a turn (a star about the origin), `None` where two coincide or three in a row are
/// collinear, the profile is refused, or two sides' cones share an edge at friction `mu`
/// ([`cones_share_an_edge`]).
fn grid_polygon(radii: &[u32], mu: f64) -> Option<Profile> {
    let n = radii.len();
    let pts: Vec<[f64; 2]> = radii
        .iter()
        .enumerate()
        .map(|(k, &r)| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            let r = f64::from(r);
            [(r * a.cos()).round(), (r * a.sin()).round()]
        })
        .collect();
    let cross = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    if (0..n).any(|k| cross(pts[k], pts[(k + 1) % n], pts[(k + 2) % n]) == 0.0)
        || cones_share_an_edge(&pts, mu)
    {
        return None;
    }
    let sides = (0..n)
        .map(|k| curve::Segment::line(pts[k], pts[(k + 1) % n]).ok())
        .collect::<Option<Vec<_>>>()?;
    Profile::new(sides, None).ok()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(16)))]

    /// Polygons on the integer grid (sides of slopes 0, 1/2, 1, 2, …, often parallel) at
    /// frictions as typed, which put cone edges exactly along sides and chords (slope 1/2 at
    /// μ = 0.5), or any from 0.05 to 2 (not where two sides' cones share an edge).
    #[test]
    fn grid_polygons_match_the_dense_check(
        radii in prop::collection::vec(2u32..=5, 3..=8),
        mu in prop_oneof![
            prop::sample::select(vec![0.1, 0.2, 0.25, 0.3, 0.5, 0.75, 1.5, 2.0]),
            0.05..2.0f64,
        ],
    ) {
        let Some(p) = grid_polygon(&radii, mu) else { return Ok(()) };
        check(&p, mu)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(16)))]

    /// Closed chains of 3 to 6 cubic Béziers with their joints at round radii (symmetric
    /// shapes: a regular chain's pairs are exact mirror images), smooth or corners, at
    /// frictions as typed or any from 0.05 to 2. (A corner just sharper than twice the
    /// friction angle, as [1, 0.8, 0.8] at μ = 0.5, has pinch grasps in a wedge thinner than
    /// the chord tolerance.)
    #[test]
    fn round_bezier_chains_match_the_dense_check(
        radii in prop::collection::vec(prop::sample::select(vec![0.6, 0.8, 1.0]), 3..=6),
        smooth in prop::collection::vec(any::<bool>(), 6),
        mu in prop_oneof![
            prop::sample::select(vec![0.1, 0.2, 0.25, 0.3, 0.5, 0.75, 1.5, 2.0]),
            0.05..2.0f64,
        ],
    ) {
        let n = radii.len();
        let flat = [(0.0, 0.0); 6];
        let Some(p) = bezier_chain_profile(&radii, &flat[..n], &smooth[..n], 0, false) else { return Ok(()) };
        check(&p, mu)?;
    }
}
