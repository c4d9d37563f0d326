//! Antipodal pairs of profiles against an independent oracle, on random profiles: polygons
//! with some corners rounded by arcs, and closed chains of cubic Béziers with corners, both
//! ways round, the seam at a corner or at a smooth joint.
//!
//! The oracle shares no code with the crate: smooth pairs by a grid over every pair of
//! segments (sign changes of both equations in a cell, then Newton); corner pairs by dense
//! sampling of the foot-point function of each corner on each segment, then bisection; pairs
//! of corners by the definition. Nothing the oracle finds may be missing; everything reported
//! must satisfy the definition. Directions within 1e-6 of a cone's edge, and pairs with an end
//! within 1e-6 of a corner (the contract's limit cases), are left out of the comparison.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

mod common;

use antipodal::{antipodal, AntipodalPair, Options, Profile, Segment};
use curve::{JointKind, ParamCurve, SegmentKind, SplineCurve, V2};
use numeric::certificate::Verdict;
use proptest::prelude::*;
use std::f64::consts::{PI, TAU};
use std::sync::atomic::{AtomicUsize, Ordering};

use testkit::profiles::{
    bezier_chains, filleted_polygon, filleted_polygons, one_spline, step_angles,
};

// ---- the oracle -------------------------------------------------------------------------

/// A point of the profile: segment and share of its domain.
#[derive(Clone, Copy, Debug)]
struct At {
    seg: usize,
    x: f64,
}

fn jet(p: &Profile, at: At, order: usize) -> curve::Jet {
    let c = p.segments()[at.seg].curve();
    let (a, b) = c.domain();
    let mut j = c.jet_to(a + (b - a) * at.x, order);
    // Derivatives in the share x.
    j.d1 = j.d1 * (b - a);
    j.d2 = j.d2 * ((b - a) * (b - a));
    j
}

fn corner_at(p: &Profile, at: At) -> bool {
    let n = p.segments().len();
    let joint = if at.x <= 1e-6 {
        at.seg
    } else if at.x >= 1.0 - 1e-6 {
        (at.seg + 1) % n
    } else {
        return false;
    };
    p.joints()
        .iter()
        .any(|j| j.u as usize == joint && j.kind != JointKind::Smooth)
}

/// What the oracle expects: pairs of points, and points of pairs it leaves undecided (limit
/// cases), each as `(p, q)`.
#[derive(Default, Debug)]
struct Expected {
    pairs: Vec<(V2, V2)>,
    limits: Vec<(V2, V2)>,
}

const GRID: usize = 48;

/// Smooth pairs by a grid over each pair of segments, then Newton on
/// `F = (Q − P)·P′ = 0`, `G = (Q − P)·Q′ = 0`.
fn smooth_pairs(p: &Profile, size: f64, out: &mut Expected) {
    let n = p.segments().len();
    let orient = p.orientation();
    let fg = |a: At, b: At| {
        let (ja, jb) = (jet(p, a, 1), jet(p, b, 1));
        let r = jb.p - ja.p;
        (r.dot(ja.d1.unit()), r.dot(jb.d1.unit()))
    };
    for i in 0..n {
        for j in i..n {
            let f = |x: f64, y: f64| fg(At { seg: i, x }, At { seg: j, x: y });
            // (On one segment, the cells above the diagonal: each pair once.)
            let look = |a: usize, b: usize| i != j || b > a;
            for (s0, t0) in common::straddling_cells(GRID, f, look) {
                let Some((s, t)) = newton(p, i, j, s0, t0) else {
                    continue;
                };
                let h = 2.0 / GRID as f64;
                if (s - s0).abs() > h || (t - t0).abs() > h {
                    continue;
                }
                let (sa, tb) = (At { seg: i, x: s }, At { seg: j, x: t });
                let (js, jt) = (jet(p, sa, 1), jet(p, tb, 1));
                let r = jt.p - js.p;
                if r.norm() < 1e-3 * size {
                    continue;
                }
                let inward = js.d1.perp() * orient;
                if js.d1.dot(jt.d1) >= 0.0 || inward.dot(r) <= 0.0 {
                    continue;
                }
                let pair = (js.p, jt.p);
                if corner_at(p, sa) || corner_at(p, tb) {
                    out.limits.push(pair);
                } else {
                    push_unique(&mut out.pairs, pair, size);
                }
            }
        }
    }
}

fn newton(p: &Profile, i: usize, j: usize, s: f64, t: f64) -> Option<(f64, f64)> {
    let system = |s: f64, t: f64| {
        let (js, jt) = (
            jet(p, At { seg: i, x: s }, 2),
            jet(p, At { seg: j, x: t }, 2),
        );
        let r = jt.p - js.p;
        (
            [r.dot(js.d1), r.dot(jt.d1)],
            [
                [-js.d1.dot(js.d1) + r.dot(js.d2), jt.d1.dot(js.d1)],
                [-js.d1.dot(jt.d1), jt.d1.dot(jt.d1) + r.dot(jt.d2)],
            ],
        )
    };
    common::newton_in_unit_square(system, s, t)
}

/// Where `d` lies against the corner's cone: positive inside (the sine of the angle to the
/// nearer edge), negative outside.
fn cone_margin(cone: [V2; 2], d: V2) -> f64 {
    let d = d.unit();
    let [a, b] = cone;
    let turn = a.cross(b).signum();
    (turn * a.cross(d)).min(turn * d.cross(b))
}

struct Site {
    at: V2,
    seg: usize,
    cone: [V2; 2],
}

fn sites(p: &Profile) -> Vec<Site> {
    let n = p.segments().len();
    p.joints()
        .iter()
        .filter(|j| j.kind == JointKind::Convex)
        .map(|j| {
            let i = j.u as usize;
            let tin = jet(
                p,
                At {
                    seg: (i + n - 1) % n,
                    x: 1.0,
                },
                1,
            )
            .d1
            .unit();
            let tout = jet(p, At { seg: i, x: 0.0 }, 1).d1.unit();
            let o = p.orientation();
            Site {
                at: jet(p, At { seg: i, x: 0.0 }, 0).p,
                seg: i,
                cone: [tin.perp() * o, tout.perp() * o],
            }
        })
        .collect()
}

/// Corner–corner and corner–smooth pairs.
fn corner_pairs(p: &Profile, size: f64, out: &mut Expected) {
    const SAMPLES: usize = 4000;
    const EDGE: f64 = 1e-6;
    let ss = sites(p);
    let o = p.orientation();
    for (k, a) in ss.iter().enumerate() {
        for b in &ss[k + 1..] {
            let d = b.at - a.at;
            let m = cone_margin(a.cone, d).min(cone_margin(b.cone, -d));
            if m > EDGE {
                out.pairs.push((a.at, b.at));
            } else if m > -EDGE {
                out.limits.push((a.at, b.at));
            }
        }
    }
    for c in &ss {
        for i in 0..p.segments().len() {
            let g = |x: f64| {
                let j = jet(p, At { seg: i, x }, 1);
                (j.p - c.at).dot(j.d1.unit())
            };
            let mut prev = g(0.0);
            for k in 1..=SAMPLES {
                let x1 = k as f64 / SAMPLES as f64;
                let cur = g(x1);
                if (prev < 0.0) != (cur < 0.0) || cur == 0.0 {
                    let x = common::bisect(g, (k - 1) as f64 / SAMPLES as f64, x1);
                    let at = At { seg: i, x };
                    let j = jet(p, at, 1);
                    let d = j.p - c.at;
                    let inward = j.d1.perp() * o;
                    if d.norm() > 1e-3 * size && inward.dot(-d) > 0.0 {
                        let m = cone_margin(c.cone, d);
                        if corner_at(p, at) || m.abs() <= EDGE {
                            out.limits.push((c.at, j.p));
                        } else if m > 0.0 {
                            push_unique(&mut out.pairs, (c.at, j.p), size);
                        }
                    }
                }
                prev = cur;
            }
        }
        let _ = c.seg;
    }
}

fn push_unique(v: &mut Vec<(V2, V2)>, pair: (V2, V2), size: f64) {
    if !v.iter().any(|&q| same(q, pair, size)) {
        v.push(pair);
    }
}

fn same(a: (V2, V2), b: (V2, V2), size: f64) -> bool {
    let room = 1e-6 * size;
    let near = |x: V2, y: V2| (x - y).norm() <= room;
    (near(a.0, b.0) && near(a.1, b.1)) || (near(a.0, b.1) && near(a.1, b.0))
}

/// Whether a reported pair satisfies the definition (to rounding): collinear normals facing
/// each other at smooth ends, the segment inside the cone at corners.
fn satisfies(p: &Profile, pair: &AntipodalPair) -> Result<(), String> {
    let (a, b) = (V2::from_arr(pair.p), V2::from_arr(pair.q));
    let d = b - a;
    let ss = sites(p);
    let o = p.orientation();
    for (end, from, dir, u) in [
        (corners(pair)[0], a, d, pair.s),
        (corners(pair)[1], b, -d, pair.t),
    ] {
        if end {
            let site = ss
                .iter()
                .find(|c| (c.at - from).norm() < 1e-9)
                .ok_or(format!("no convex corner at {from:?}"))?;
            if cone_margin(site.cone, dir) < -1e-9 {
                return Err(format!("{dir:?} outside the cone at {from:?}"));
            }
        } else {
            let j = p.jet(u);
            if (j.p - from).norm() > 1e-9 {
                return Err(format!("point {from:?} is not P({u})"));
            }
            let n = j.d1.unit().perp() * o;
            if n.cross(dir.unit()).abs() > 1e-7 || n.dot(dir) <= 0.0 {
                return Err(format!("the normal at {u} is not along {dir:?} inward"));
            }
        }
    }
    Ok(())
}

fn check(p: &Profile, size: f64) -> Result<(usize, usize, usize), TestCaseError> {
    let r = antipodal(p, &Options::default()).unwrap();
    // (Uncertified results are compared all the same; they must stay rare.)
    RUNS.fetch_add(1, Ordering::Relaxed);
    if !r.certified() {
        UNCERTIFIED.fetch_add(1, Ordering::Relaxed);
    }
    prop_assert!(r.families.is_empty(), "families {:?}", r.families);
    let mut want = Expected::default();
    smooth_pairs(p, size, &mut want);
    corner_pairs(p, size, &mut want);
    for w in &want.pairs {
        let found = r
            .pairs
            .iter()
            .any(|g| same((V2::from_arr(g.p), V2::from_arr(g.q)), *w, size));
        prop_assert!(found, "missed {:?}; found {:?}", w, r.pairs);
    }
    for g in &r.pairs {
        let got = (V2::from_arr(g.p), V2::from_arr(g.q));
        if want.limits.iter().any(|&l| same(l, got, size)) {
            continue;
        }
        if let Err(e) = satisfies(p, g) {
            return Err(TestCaseError::fail(format!("{g:?}: {e}")));
        }
        prop_assert!((got.1 - got.0).norm() >= 1e-3 * size || want.pairs.is_empty());
    }
    let count = |f: &dyn Fn(&AntipodalPair) -> bool| r.pairs.iter().filter(|g| f(g)).count();
    Ok((
        count(&|g| corners(g) == [true, true]),
        count(&|g| corners(g)[0] != corners(g)[1]),
        count(&|g| corners(g) == [false, false] && g.kind.is_some()),
    ))
}

static RUNS: AtomicUsize = AtomicUsize::new(0);
static UNCERTIFIED: AtomicUsize = AtomicUsize::new(0);
static CORNER_CORNER: AtomicUsize = AtomicUsize::new(0);
static CORNER_SMOOTH: AtomicUsize = AtomicUsize::new(0);
static CURVED: AtomicUsize = AtomicUsize::new(0);

fn tally((cc, cs, sm): (usize, usize, usize)) {
    CORNER_CORNER.fetch_add(cc.min(1), Ordering::Relaxed);
    CORNER_SMOOTH.fetch_add(cs.min(1), Ordering::Relaxed);
    CURVED.fetch_add(sm.min(1), Ordering::Relaxed);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: common::cases(150), ..ProptestConfig::default() })]

    fn filleted_polygons_match_the_oracle(p in filleted_polygons(3..8, 16)) {
        let Some(p) = p else { return Ok(()) };
        tally(check(&p, 4.0)?);
    }

    fn bezier_chains_match_the_oracle(p in bezier_chains(3..7, 8, 0.4)) {
        let Some(p) = p else { return Ok(()) };
        tally(check(&p, 4.0)?);
    }
}

/// Runs both properties and checks that they are not vacuous (pairs of corners, corner and
/// smooth point, and two curved smooth points all occur) and that uncertified results (near
/// degenerate configurations) stay below one in twenty.
#[test]
fn profile_pairs_match_the_oracle() {
    filleted_polygons_match_the_oracle();
    bezier_chains_match_the_oracle();
    let (cc, cs, sm) = (
        CORNER_CORNER.load(Ordering::Relaxed),
        CORNER_SMOOTH.load(Ordering::Relaxed),
        CURVED.load(Ordering::Relaxed),
    );
    let (runs, doubtful) = (
        RUNS.load(Ordering::Relaxed),
        UNCERTIFIED.load(Ordering::Relaxed),
    );
    assert!(
        cc >= 20 && cs >= 50 && sm >= 20,
        "corner-corner {cc}, corner-smooth {cs}, curved {sm}"
    );
    assert!(
        runs >= 200 && doubtful * 20 <= runs,
        "{doubtful} of {runs} uncertified"
    );
}

/// The papers' square-ish cases by hand: a rectangle's opposite sides are families and its
/// diagonals pairs of corners; a half disc pairs its flat side's middle with the arc's top.
#[test]
fn rectangles_and_half_discs() {
    let c = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
    let rect = Profile::new(
        (0..4)
            .map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap())
            .collect(),
        None,
    )
    .unwrap();
    let r = antipodal(&rect, &Options::default()).unwrap();
    assert!(r.certified());
    assert_eq!(r.families.len(), 2);
    assert_eq!(r.pairs.len(), 2);
    assert!(r
        .pairs
        .iter()
        .all(|p| p.corner == Some([true, true]) && p.kind.is_none()));
    let d = Profile::new(
        vec![
            Segment::line([-1.0, 0.0], [1.0, 0.0]).unwrap(),
            Segment::arc([0.0, 0.0], 1.0, 0.0, PI).unwrap(),
        ],
        None,
    )
    .unwrap();
    let r = antipodal(&d, &Options::default()).unwrap();
    assert!(r.certified() && r.families.is_empty());
    assert_eq!(r.pairs.len(), 1);
    let p = &r.pairs[0];
    assert_eq!(
        (p.s, p.t, p.corner, p.segment),
        (0.5, 1.5, Some([false, false]), Some([0, 1]))
    );
    assert!((p.q[1] - 1.0).abs() < 1e-15 && p.distance == p.q[1]);
}

/// The pairs as sorted point pairs, for comparing two runs.
fn point_pairs(pairs: &[AntipodalPair]) -> Vec<[f64; 4]> {
    let mut v: Vec<[f64; 4]> = pairs
        .iter()
        .map(|p| {
            let (a, b) = if (p.p[0], p.p[1]) <= (p.q[0], p.q[1]) {
                (p.p, p.q)
            } else {
                (p.q, p.p)
            };
            [a[0], a[1], b[0], b[1]]
        })
        .collect();
    v.sort_by(|x, y| x.partial_cmp(y).unwrap());
    v
}

fn assert_same_points(a: &[[f64; 4]], b: &[[f64; 4]], room: f64) {
    assert_eq!(a.len(), b.len(), "{a:?} against {b:?}");
    for (x, y) in a.iter().zip(b) {
        assert!(
            x.iter().zip(y).all(|(u, v)| (u - v).abs() <= room),
            "{x:?} against {y:?}"
        );
    }
}

/// A curve's pairs as those of a profile of that one smooth segment (no corners; both points
/// on segment 0).
fn as_profile_pairs(pairs: &[AntipodalPair]) -> Vec<AntipodalPair> {
    pairs.iter().map(|&p| p.on_one_segment()).collect()
}

/// Whether a profile's pair has a corner at `s`, and at `t`.
fn corners(pair: &AntipodalPair) -> [bool; 2] {
    pair.corner
        .expect("a profile's pair says where its corners are")
}

/// A smooth closed curve given as a one-segment profile has the curve's pairs, and a periodic
/// B-spline split into its Bézier pieces (joined G2) has the same pairs as the spline.
#[test]
fn round_trips_through_profiles() {
    // Closed clamped, its end tangents along one line (no corner at the seam).
    let pts = [
        [0.0, 0.0],
        [2.0, 0.0],
        [4.0, 1.0],
        [4.0, 4.0],
        [0.0, 4.0],
        [-2.0, 0.0],
        [0.0, 0.0],
    ];
    let c = SplineCurve::clamped(3, &pts, None, None).unwrap();
    let alone = antipodal::antipodal(&c, &Options::default()).unwrap();
    let one = one_spline(c);
    let r = antipodal(&one, &Options::default()).unwrap();
    assert!(alone.certified() && r.certified());
    let curve_pairs = as_profile_pairs(&alone.pairs);
    assert!(!curve_pairs.is_empty());
    assert_same_points(&point_pairs(&r.pairs), &point_pairs(&curve_pairs), 1e-10);
    for (a, b) in r.pairs.iter().zip(&alone.pairs) {
        assert_eq!(a.kind, b.kind);
    }

    // A periodic cubic: its Bézier pieces as segments.
    let ring: Vec<[f64; 2]> = (0..7)
        .map(|i| {
            let a = TAU * i as f64 / 7.0;
            let r = if i % 2 == 0 { 2.0 } else { 1.3 };
            [r * a.cos(), 0.7 * r * a.sin()]
        })
        .collect();
    let periodic = SplineCurve::periodic(3, &ring, None).unwrap();
    let whole = antipodal::antipodal(&periodic, &Options::default()).unwrap();
    let hom = periodic.exact_pieces().hom;
    let segs: Vec<Segment> = (0..hom.pieces())
        .map(|i| {
            let pts: Vec<[f64; 2]> = hom
                .piece(i)
                .chunks_exact(3)
                .map(|h| [h[0] / h[2], h[1] / h[2]])
                .collect();
            Segment::spline(
                SegmentKind::Bezier,
                SplineCurve::clamped(3, &pts, None, None).unwrap(),
            )
            .unwrap()
        })
        .collect();
    let split = Profile::new(segs, None).unwrap();
    assert!(split.corners().next().is_none());
    let r = antipodal(&split, &Options::default()).unwrap();
    assert!(whole.certified() && r.certified(), "{:?}", r.reason());
    let whole_pairs = as_profile_pairs(&whole.pairs);
    assert!(whole_pairs.len() >= 2);
    assert_same_points(&point_pairs(&r.pairs), &point_pairs(&whole_pairs), 1e-9);
}

/// A profile moved far away, scaled by a power of two and turned by a right angle has the same
/// pairs, moved likewise (the moves of lines are exact; arcs' points round). At 1e8 a small
/// fillet's tangents round 1e-7 apart: its joints stay smooth, and the pairs at them are found.
#[test]
fn pairs_move_with_the_profile() {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig {
        cases: common::cases(40),
        ..ProptestConfig::default()
    });
    let strategy = (
        proptest::collection::vec(0.5f64..1.5, 3..7),
        proptest::collection::vec(1.0f64..2.0, 7),
        proptest::collection::vec(prop_oneof![Just(0.0), 0.2f64..1.0], 7),
        -8i32..20,
        prop_oneof![Just([3.0e6, -1.25e6]), Just([1.0e8, -7.0e7])],
    );
    runner
        .run(&strategy, |(steps, radii, round, k, offset)| {
            let n = steps.len();
            let angles = step_angles(&steps);
            let scale = 2f64.powi(k);
            let moved = |v: V2| V2::new(-v.y * scale + offset[0], v.x * scale + offset[1]);
            let here = filleted_polygon(&angles, &radii[..n], &round[..n]);
            let there = filleted_polygon_mapped(&angles, &radii[..n], &round[..n], &moved);
            let (Some(here), Some(there)) = (here, there) else {
                return Ok(());
            };
            let (Ok(a), Ok(b)) = (Profile::new(here, None), Profile::new(there, None)) else {
                return Ok(());
            };
            let ra = antipodal(&a, &Options::default()).unwrap();
            let rb = antipodal(&b, &Options::default()).unwrap();
            prop_assert_eq!(ra.pairs.len(), rb.pairs.len());
            prop_assert_eq!(ra.certified(), rb.certified());
            let expect: Vec<AntipodalPair> = ra
                .pairs
                .iter()
                .map(|p| {
                    let (mp, mq) = (moved(V2::from_arr(p.p)), moved(V2::from_arr(p.q)));
                    AntipodalPair {
                        p: mp.arr(),
                        q: mq.arr(),
                        ..*p
                    }
                })
                .collect();
            // The arcs' points round at the offset (a few ulps of it), and a pair moves by
            // that times its conditioning.
            let far = offset[0].abs().max(offset[1].abs());
            let room = 1e-9 * 4.0 * scale + 1e3 * far * f64::EPSILON;
            let (x, y) = (point_pairs(&expect), point_pairs(&rb.pairs));
            for (u, v) in x.iter().zip(&y) {
                prop_assert!(
                    u.iter().zip(v).all(|(a, b)| (a - b).abs() <= room),
                    "{:?} against {:?}",
                    u,
                    v
                );
            }
            for (u, v) in ra.pairs.iter().zip(&rb.pairs) {
                prop_assert_eq!(u.corner, v.corner);
            }
            Ok(())
        })
        .unwrap();
}

/// [`filleted_polygon`] with its vertices and arc centres moved by `map` (a rotation by a
/// right angle, a scaling and a translation), the arcs' angles turned with it.
fn filleted_polygon_mapped(
    angles: &[f64],
    radii: &[f64],
    round: &[f64],
    map: &dyn Fn(V2) -> V2,
) -> Option<Vec<Segment>> {
    let segs = filleted_polygon(angles, radii, round)?;
    let o = map(V2::new(0.0, 0.0));
    let scale = (map(V2::new(1.0, 0.0)) - o).norm();
    segs.iter()
        .map(|s| match s.kind() {
            SegmentKind::Line => {
                let pts = s.curve().control_points();
                Segment::line(
                    map(V2::from_arr(pts[0])).arr(),
                    map(V2::from_arr(pts[1])).arr(),
                )
                .ok()
            }
            _ => {
                // An arc: from its end points and its middle, its centre and angles.
                let (a, b) = s.curve().domain();
                let p0 = s.curve().jet(a).p;
                let p1 = s.curve().jet(b).p;
                let pm = s.curve().jet(0.5 * (a + b)).p;
                let (c, r) = circle_through(p0, pm, p1);
                let a0 = (p0 - c).angle();
                let turn = wrap_signed((pm - c).angle() - a0) * 2.0;
                let sweep = sweep_of(a0, (p1 - c).angle(), turn);
                Segment::arc(
                    map(c).arr(),
                    r * scale,
                    a0 + PI / 2.0,
                    a0 + PI / 2.0 + sweep,
                )
                .ok()
            }
        })
        .collect()
}

fn circle_through(a: V2, b: V2, c: V2) -> (V2, f64) {
    let d = 2.0 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
    let sq = |p: V2| p.dot(p);
    let ux = (sq(a) * (b.y - c.y) + sq(b) * (c.y - a.y) + sq(c) * (a.y - b.y)) / d;
    let uy = (sq(a) * (c.x - b.x) + sq(b) * (a.x - c.x) + sq(c) * (b.x - a.x)) / d;
    let center = V2::new(ux, uy);
    (center, (a - center).norm())
}

fn wrap_signed(a: f64) -> f64 {
    (a + PI).rem_euclid(TAU) - PI
}

/// The signed sweep from `a0` to `a1` whose sign and rough size is `approx`.
fn sweep_of(a0: f64, a1: f64, approx: f64) -> f64 {
    let d = wrap_signed(a1 - a0);
    if (d > 0.0) == (approx > 0.0) {
        d
    } else {
        d + TAU * approx.signum()
    }
}
