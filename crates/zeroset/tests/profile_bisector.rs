//! Bisectors of profiles against an independent oracle, on random profiles (polygons with
//! some corners rounded by arcs, closed chains of cubic Béziers with corners, both ways round,
//! the seam anywhere).
//!
//! The oracle shares no code with the crate: distances to a profile by dense sampling refined
//! by golden-section search on the profile's own evaluation. Between two profiles, every
//! point where the distances to both are equal (found on a grid, then by bisection) must lie
//! within the chord tolerance of the reported bisector, and every vertex of the trimmed
//! bisector must be at equal distance from both. Inside one profile, every point where the
//! nearest boundary point jumps (the medial axis) must lie within the chord tolerance of the
//! self-bisector, and every vertex of the trimmed self-bisector must have its foot points at
//! the distance of the boundary.

#![allow(clippy::unwrap_used, missing_docs)]

use curve::{ParamCurve, Profile};
use proptest::prelude::*;
use std::cell::Cell;
use testkit::boundary_oracle::{off_segment, winding, Oracle};
use testkit::cases;
use testkit::outlines::polygon;
use testkit::profiles::{bezier_chains, filleted_polygons};
use zeroset::{bisector, self_bisector, Bisector, BisectorOptions};

/// Grid nodes per side.
const GRID: usize = 40;

/// The distance from `x` to the reported branches (as polylines).
fn to_branches(b: &Bisector, x: [f64; 2]) -> f64 {
    let mut best = f64::INFINITY;
    for br in &b.branches {
        for w in br.xy.windows(2) {
            best = best.min(off_segment(x, w[0], w[1]));
        }
        if let [one] = br.xy[..] {
            best = best.min((one[0] - x[0]).hypot(one[1] - x[1]));
        }
    }
    for p in &b.isolated {
        best = best.min((p.xy[0] - x[0]).hypot(p.xy[1] - x[1]));
    }
    best
}

fn bbox(ps: &[&Profile]) -> ([f64; 2], [f64; 2], f64) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in ps {
        for q in p.segments().iter().flat_map(|s| s.curve().control_points()) {
            for k in 0..2 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
    }
    (lo, hi, (hi[0] - lo[0]).hypot(hi[1] - lo[1]))
}

fn grid(lo: [f64; 2], hi: [f64; 2]) -> Vec<Vec<[f64; 2]>> {
    (0..=GRID)
        .map(|i| {
            (0..=GRID)
                .map(|j| {
                    let s = |k: usize, t: usize| lo[k] + (hi[k] - lo[k]) * t as f64 / GRID as f64;
                    [s(0, i), s(1, j)]
                })
                .collect()
        })
        .collect()
}

/// The grid's edges (pairs of neighbouring nodes).
fn edges(g: &[Vec<[f64; 2]>]) -> Vec<([f64; 2], [f64; 2])> {
    let mut out = Vec::new();
    for i in 0..=GRID {
        for j in 0..=GRID {
            if i < GRID {
                out.push((g[i][j], g[i + 1][j]));
            }
            if j < GRID {
                out.push((g[i][j], g[i][j + 1]));
            }
        }
    }
    out
}

fn lerp(a: [f64; 2], b: [f64; 2], s: f64) -> [f64; 2] {
    [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])]
}

// Counts per test thread (proptest runs a property's cases on its caller's thread), so that
// each property runs as a test of its own, in parallel, and is checked for being vacuous.
thread_local! {
    static FOUND: Cell<usize> = const { Cell::new(0) };
    static CORNER_BRANCHES: Cell<usize> = const { Cell::new(0) };
}

fn bump(counter: &'static std::thread::LocalKey<Cell<usize>>, by: usize) {
    counter.with(|c| c.set(c.get() + by));
}

const CHORD: f64 = 1e-3;

fn options(trimmed: bool) -> BisectorOptions {
    BisectorOptions {
        settings: testkit::settings(CHORD, None),
        trimmed,
        ..Default::default()
    }
}

/// Two profiles: the oracle's equidistant points against the untrimmed bisector, the
/// trimmed bisector's vertices against the oracle's distances.
fn check_pair(a: &Profile, b: &Profile) -> Result<(), TestCaseError> {
    let (lo, hi, size) = bbox(&[a, b]);
    let full = bisector(a, b, &options(false)).unwrap();
    let trimmed = bisector(a, b, &options(true)).unwrap();
    prop_assert!(full.complete && trimmed.complete);
    let (oa, ob) = (Oracle::new(a), Oracle::new(b));
    let f = |x: [f64; 2]| oa.nearest(x).0 - ob.nearest(x).0;
    let g = grid(lo, hi);
    let room = CHORD * size + 1e-6 * size;
    let mut found = 0;
    for (p, q) in edges(&g) {
        let (fp, fq) = (f(p), f(q));
        if fp.signum() == fq.signum() {
            continue;
        }
        let (mut s0, mut s1) = (0.0, 1.0);
        for _ in 0..40 {
            let m = 0.5 * (s0 + s1);
            if f(lerp(p, q, m)).signum() == fp.signum() {
                s0 = m;
            } else {
                s1 = m;
            }
        }
        let y = lerp(p, q, 0.5 * (s0 + s1));
        found += 1;
        let off = to_branches(&full, y);
        prop_assert!(
            off <= room,
            "equidistant point {y:?} is {off} off the bisector"
        );
    }
    bump(&FOUND, found.min(1));
    prop_assert!(found == 0 || !trimmed.branches.is_empty());
    for br in &trimmed.branches {
        if br.corners().contains(&true) {
            bump(&CORNER_BRANCHES, 1);
        }
        for x in &br.xy {
            let (da, db) = (oa.nearest(*x).0, ob.nearest(*x).0);
            testkit::prop_assert_near!(
                da,
                db,
                1e-7 * size,
                "trimmed vertex {x:?}: distances {da} and {db} (sites {:?} corner {:?})",
                br.segment,
                br.corner
            );
        }
    }
    Ok(())
}

/// Inside one closed profile: where the nearest boundary point jumps between two grid nodes,
/// the medial axis crosses; it must lie on the self-bisector. Every vertex of the trimmed
/// self-bisector is at the boundary's distance from its foot points.
fn check_self(p: &Profile) -> Result<(), TestCaseError> {
    let (lo, hi, size) = bbox(&[p]);
    let full = self_bisector(p, &options(false)).unwrap();
    let trimmed = self_bisector(p, &options(true)).unwrap();
    prop_assert!(full.complete && trimmed.complete);
    let o = Oracle::new(p);
    let polygon: Vec<[f64; 2]> = o.pts.clone();
    let inside = |x: [f64; 2]| winding(&polygon, x) != 0;
    let foot = |x: [f64; 2]| p.jet(o.nearest(x).1).p.arr();
    let apart = |x: [f64; 2], y: [f64; 2]| {
        let (a, b) = (foot(x), foot(y));
        (a[0] - b[0]).hypot(a[1] - b[1]) > 0.1 * size
    };
    let room = CHORD * size + 1e-6 * size;
    let mut found = 0;
    for (a, b) in edges(&grid(lo, hi)) {
        if !(inside(a) && inside(b) && apart(a, b)) {
            continue;
        }
        let (mut x, mut y) = (a, b);
        for _ in 0..40 {
            let m = lerp(x, y, 0.5);
            if apart(x, m) {
                y = m;
            } else {
                x = m;
            }
        }
        if !apart(x, y) {
            continue; // the feet slid round a bend without jumping
        }
        let z = lerp(x, y, 0.5);
        // The jump is the axis only where both feet are at one distance (not where the
        // nearest point slides fast round a tight bend without jumping).
        let (d, _) = o.nearest(z);
        let (dx, dy) = (o.nearest(x).0, o.nearest(y).0);
        if (dx - dy).abs() > 1e-6 * size || (d - dx).abs() > 1e-6 * size {
            continue;
        }
        found += 1;
        let off = to_branches(&full, z);
        prop_assert!(
            off <= room,
            "medial point {z:?} is {off} off the self-bisector; feet at {} and {}; corners {:?}",
            o.nearest(x).1,
            o.nearest(y).1,
            p.corners().map(|j| (j.u, j.kind)).collect::<Vec<_>>()
        );
    }
    bump(&FOUND, found.min(1));
    for br in &trimmed.branches {
        if br.corners().contains(&true) {
            bump(&CORNER_BRANCHES, 1);
        }
        for (tr, x) in br.tr.iter().zip(&br.xy) {
            let (d, _) = o.nearest(*x);
            for u in tr {
                let f = p.jet(*u).p.arr();
                let rho = (x[0] - f[0]).hypot(x[1] - f[1]);
                testkit::prop_assert_near!(
                    rho,
                    d,
                    1e-7 * size,
                    "trimmed vertex {x:?}: foot at {rho}, boundary at {d}"
                );
            }
        }
    }
    Ok(())
}

fn moved(p: &Profile, by: [f64; 2]) -> Profile {
    let segs = p
        .segments()
        .iter()
        .map(|s| {
            s.transformed(&curve::Affine([1.0, 0.0, 0.0, 1.0, by[0], by[1]]))
                .unwrap()
        })
        .collect();
    Profile::new(segs, None).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(24), ..ProptestConfig::default() })]

    fn filleted_polygon_pairs(a in filleted_polygons(3..6, 12), dy in -2.0f64..2.0) {
        let Some(a) = a else { return Ok(()) };
        let b = moved(&a, [5.0, dy]);
        check_pair(&a, &b)?;
    }

    fn filleted_polygons_inside(p in filleted_polygons(3..7, 12)) {
        let Some(p) = p else { return Ok(()) };
        check_self(&p)?;
    }

    fn bezier_chains_inside(p in bezier_chains(3..6, 6, 0.4)) {
        let Some(p) = p else { return Ok(()) };
        check_self(&p)?;
    }
}

/// Checks that the property just run on this thread was not vacuous: equidistant or medial
/// points were found in at least `share` of its cases, and (where the profiles have reflex
/// corners, as the polygons do) corners took part as point sites.
fn assert_not_vacuous(share: f64, with_corners: bool) {
    let found = FOUND.with(Cell::get);
    let corners = CORNER_BRANCHES.with(Cell::get);
    assert!(
        found as f64 >= share * cases(24) as f64,
        "only {found} cases with oracle points"
    );
    assert!(
        !with_corners || corners > 0,
        "no trimmed branch with a corner"
    );
}

#[test]
fn filleted_polygon_pairs_match_the_oracle() {
    filleted_polygon_pairs();
    assert_not_vacuous(0.5, true);
}

#[test]
fn filleted_polygons_inside_match_the_oracle() {
    filleted_polygons_inside();
    assert_not_vacuous(0.5, true);
}

#[test]
fn bezier_chains_inside_match_the_oracle() {
    bezier_chains_inside();
    assert_not_vacuous(0.5, false);
}

/// The self-bisector moves with the profile: an L-shaped room (a reflex corner) and
/// a chain of Béziers with corners, rotated, scaled by 2^10 and moved 1e6 of their sizes
/// from the origin, or run the other way round, have the moved bisector (each vertex of one
/// within the chord tolerance of the other's polylines, both ways), as many corner branches.
#[test]
fn profile_bisectors_move_with_the_profile() {
    let room = polygon(&[[0., 0.], [4., 0.], [4., 2.], [2., 2.], [2., 4.], [0., 4.]]);
    let chain = testkit::profiles::five_cubics([true, false, true, false, false]);
    for shape in [&room, &chain] {
        moves_with_the_profile(shape);
    }
}

fn moves_with_the_profile(shape: &Profile) {
    // Untrimmed: the trimmed bisector drops whole polyline edges where its vertices stop
    // being nearest, so its branch ends depend on where the vertices fall.
    let opts = options(false);
    let base = self_bisector(shape, &opts).unwrap();
    assert!(base.complete && !base.branches.is_empty());
    let (s, (sin, cos)) = (1024.0, 0.6f64.sin_cos());
    let (lo, hi, size) = bbox(&[shape]);
    let far = 1e6 * size * s;
    let map = curve::Affine([s * cos, s * sin, -s * sin, s * cos, far, -0.5 * far]);
    for reverse in [false, true] {
        let mut segs: Vec<curve::Segment> = shape
            .segments()
            .iter()
            .map(|seg| seg.transformed(&map).unwrap())
            .collect();
        if reverse {
            segs = segs
                .iter()
                .rev()
                .map(|seg| seg.reversed().unwrap())
                .collect();
        }
        let moved_shape = Profile::new(segs, None).unwrap();
        let moved = self_bisector(&moved_shape, &opts).unwrap();
        assert!(moved.complete);
        let expected = Bisector {
            branches: base
                .branches
                .iter()
                .map(|b| zeroset::Branch {
                    xy: b.xy.iter().map(|p| map.apply(*p)).collect(),
                    ..b.clone()
                })
                .collect(),
            ..base.clone()
        };
        // Each vertex on the bisector, within the chord tolerance of the other polyline (the
        // larger of the two: it is relative to the box, and a rotated shape's box is wider),
        // and the moved data rounded at 1e6 sizes from the origin (~1e-10 of the size).
        let chord = CHORD * bbox(&[&moved_shape]).2.max(size * s);
        let rounding = 1e-6 * size * s;
        // Twice that on the bisector of two segments meeting smoothly: it vanishes to high
        // order where both feet reach the joint (as a self-bisector does on its diagonal),
        // and where its branch stops short of that corner of the domain moves by about the
        // chord tolerance with the data.
        let n = shape.segments().len();
        let smooth_pair = |b: &zeroset::Branch| {
            let [i, j] = b.segments();
            b.corners() == [false, false] && (j == i + 1 || (i == 0 && j + 1 == n))
        };
        // Rays are cut at 1e3 box diagonals from the box's centre, and the box of a rotated
        // shape is another: compare within 10 sizes of the shape.
        let centre = map.apply([0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])]);
        let near = |x: &[f64; 2]| (x[0] - centre[0]).hypot(x[1] - centre[1]) <= 10.0 * size * s;
        for (a, b) in [(&moved, &expected), (&expected, &moved)] {
            for br in &a.branches {
                let room = if smooth_pair(br) { 2.0 } else { 1.0 } * chord + rounding;
                for x in br.xy.iter().filter(|x| near(x)) {
                    let off = to_branches(b, *x);
                    assert!(off <= room, "reverse {reverse}: {x:?} is {off} off");
                }
            }
        }
        // The corners' branches alone also match (a corner site on one side is a corner
        // site on the other).
        let corners_only = |b: &Bisector| Bisector {
            branches: b
                .branches
                .iter()
                .filter(|br| br.corners().contains(&true))
                .cloned()
                .collect(),
            isolated: Vec::new(),
            ..b.clone()
        };
        let (cm, ce) = (corners_only(&moved), corners_only(&expected));
        assert_eq!(cm.branches.is_empty(), ce.branches.is_empty());
        for (a, b) in [(&cm, &ce), (&ce, &cm)] {
            for br in &a.branches {
                for x in br.xy.iter().filter(|x| near(x)) {
                    let off = to_branches(b, *x);
                    let room = chord + rounding;
                    assert!(off <= room, "reverse {reverse}: corner {x:?} is {off} off");
                }
            }
        }
    }
}

/// One entry for curves and profiles: a spline beside a profile is taken as the profile of its
/// one segment, in its own parameter; a curve known by evaluation only is refused by name.
#[test]
fn a_curve_beside_a_profile_is_its_one_segment() {
    use curve::{Boundary, Segment, SegmentKind, SplineCurve};
    let arch = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]];
    let spline = SplineCurve::clamped(3, &arch, None, None).unwrap();
    let segment = Segment::spline(SegmentKind::BSpline, spline.clone()).unwrap();
    let as_segment = Profile::of_curve(segment, spline.domain()).unwrap();
    let c = [[0.0, -3.0], [4.0, -3.0], [4.0, -1.0], [0.0, -1.0]];
    let box_below = polygon(&c);
    let opts = BisectorOptions::default();
    let mixed = bisector(&spline, &box_below, &opts).unwrap();
    assert_eq!(mixed, bisector(&as_segment, &box_below, &opts).unwrap());
    assert!(mixed.complete && !mixed.branches.is_empty());
    // (A profile's branches say which segments their feet are on.)
    assert!(mixed.branches.iter().all(|b| b.segment.is_some()));

    let sampled = testkit::evaluation_only::EvaluationOnly(spline);
    let refused = bisector(&box_below, Boundary::Curve(&sampled), &opts);
    assert_eq!(refused, Err(zeroset::Error::NotExact { which: 2 }));
}
