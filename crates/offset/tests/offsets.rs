//! Offsets against closed forms (rectangles, disks, annuli) and against an independent
//! distance (the boundary sampled densely): every offset point lies at the distance, the loops
//! close, run the right way round, and their number follows the region's shape.
#![allow(clippy::unwrap_used)]

mod common;
use common::{arcs_sweep, ends, samples};
use curve::{ParamCurve, Profile, Region, Segment};
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use offset::{offsets, OffsetOptions, OffsetSegment, Offsets};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

use testkit::cases;
use testkit::outlines::polygon;

fn circle(center: [f64; 2], r: f64) -> Profile {
    Profile::new(vec![Segment::arc(center, r, 0.0, TAU).unwrap()], None).unwrap()
}

/// The 10 × 6 pocket with corner radius 1 and a round island of radius 1 (the issue's).
fn pocket() -> Region {
    let q = FRAC_PI_2;
    let outer = Profile::new(
        vec![
            Segment::line([1.0, 0.0], [9.0, 0.0]).unwrap(),
            Segment::arc([9.0, 1.0], 1.0, -q, 0.0).unwrap(),
            Segment::line([10.0, 1.0], [10.0, 5.0]).unwrap(),
            Segment::arc([9.0, 5.0], 1.0, 0.0, q).unwrap(),
            Segment::line([9.0, 6.0], [1.0, 6.0]).unwrap(),
            Segment::arc([1.0, 5.0], 1.0, q, PI).unwrap(),
            Segment::line([0.0, 5.0], [0.0, 1.0]).unwrap(),
            Segment::arc([1.0, 1.0], 1.0, PI, PI + q).unwrap(),
        ],
        None,
    )
    .unwrap();
    Region::new(outer, vec![circle([6.5, 3.0], 1.0)]).unwrap()
}

fn offsets_of(region: &Region, distances: &[f64]) -> Offsets {
    let axis = medial_axis(region, &MedialOptions::default()).unwrap();
    assert!(axis.certified(), "{:?}", axis.reason());
    offsets(region, &axis, distances, &OffsetOptions::default()).unwrap()
}

/// The offsets of `region` by `distances`, found right by [`check`] to `tol`; with the
/// areas it measured.
fn checked_offsets(region: &Region, distances: &[f64], tol: f64) -> (Offsets, Vec<Vec<f64>>) {
    let found = offsets_of(region, distances);
    let areas = check(region, &found, tol);
    (found, areas)
}

/// The region inside the polygon through `corners` (no holes).
fn polygon_region(corners: &[[f64; 2]]) -> Region {
    Region::new(polygon(corners), vec![]).unwrap()
}

/// The region inside a closed chain of Béziers ([`testkit::profiles::bezier_chain`]) with a
/// round hole of radius 0.15 at the origin: the random chains' regression cases.
fn chain_round_a_hole(radii: &[f64], wobble: &[(f64, f64)], smooth: &[bool]) -> Region {
    let outer = testkit::profiles::bezier_chain_profile(radii, wobble, smooth, 0, false).unwrap();
    Region::new(outer, vec![circle([0.0, 0.0], 0.15)]).unwrap()
}

/// The offset of `region` by `distance`, which must be certified.
fn certified_offsets(region: &Region, distance: f64) -> Offsets {
    let found = offsets_of(region, &[distance]);
    assert!(found.certified(), "{:?}", found.reason());
    found
}

/// Chords a query looks at together: one box stands for them all.
const RUN: usize = 32;

/// A region's boundary as chords (lines as they are, every other segment by `per_curve`
/// chords), for the distance and the inside by dense sampling, independent of the code under
/// test. The chords are kept in runs of [`RUN`] with their boxes, and the queries skip the
/// runs whose box is too far to matter: brute force with the same answers, several times
/// quicker.
struct Chords {
    chords: Vec<([f64; 2], [f64; 2])>,
    /// Each run's box (low and high corners).
    boxes: Vec<([f64; 2], [f64; 2])>,
}

impl Chords {
    fn of(region: &Region, per_curve: usize) -> Self {
        let mut chords = Vec::new();
        for b in std::iter::once(region.outer()).chain(region.holes()) {
            for (i, s) in b.segments().iter().enumerate() {
                let n = if s.kind() == curve::SegmentKind::Line {
                    1
                } else {
                    per_curve
                };
                let at = |k: usize| b.jet_to(i as f64 + k as f64 / n as f64, 0).p.arr();
                chords.extend((0..n).map(|k| (at(k), at(k + 1))));
            }
        }
        let boxes = chords
            .chunks(RUN)
            .map(|run| {
                run.iter().fold(
                    ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
                    |(lo, hi), (a, b)| {
                        (
                            [lo[0].min(a[0]).min(b[0]), lo[1].min(a[1]).min(b[1])],
                            [hi[0].max(a[0]).max(b[0]), hi[1].max(a[1]).max(b[1])],
                        )
                    },
                )
            })
            .collect();
        Self { chords, boxes }
    }

    /// The distance from `p` to the boundary: at most that to the nearest run's first point,
    /// so runs whose box is farther cannot hold a nearer chord.
    fn distance(&self, p: [f64; 2]) -> f64 {
        let gap = |q: [f64; 2]| (q[0] - p[0]).hypot(q[1] - p[1]);
        let mut best = self
            .chords
            .iter()
            .step_by(RUN)
            .map(|(a, _)| gap(*a))
            .fold(f64::INFINITY, f64::min);
        for (run, (lo, hi)) in self.chords.chunks(RUN).zip(&self.boxes) {
            let dx = (lo[0] - p[0]).max(p[0] - hi[0]).max(0.0);
            let dy = (lo[1] - p[1]).max(p[1] - hi[1]).max(0.0);
            if dx.hypot(dy) >= best {
                continue;
            }
            for (a, b) in run {
                best = best.min(curve::distance_to_segment(p, *a, *b));
            }
        }
        best
    }

    /// Whether `p` is in the region (even-odd over all its boundaries' chords, counting
    /// crossings of the ray to its right; a run wholly above, below or left of `p` has none).
    fn inside(&self, p: [f64; 2]) -> bool {
        let mut crossings = 0;
        for (run, (lo, hi)) in self.chords.chunks(RUN).zip(&self.boxes) {
            if p[1] < lo[1] || p[1] >= hi[1] || p[0] >= hi[0] {
                continue;
            }
            crossings += run
                .iter()
                .filter(|(a, b)| {
                    (a[1] > p[1]) != (b[1] > p[1])
                        && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
                })
                .count();
        }
        crossings % 2 == 1
    }

    /// The boundary's box (low and high corners).
    fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        self.boxes.iter().fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), (a, b)| {
                (
                    [lo[0].min(a[0]), lo[1].min(a[1])],
                    [hi[0].max(b[0]), hi[1].max(b[1])],
                )
            },
        )
    }
}

/// Every loop closes, every sampled point is at the distance (within `tol`), and the signed
/// area of each loop says which way it runs.
fn check(region: &Region, found: &Offsets, tol: f64) -> Vec<Vec<f64>> {
    check_against(&fine_chords(region), found, tol, 2000)
}

/// The boundary within the sagitta of 4,000 chords a curve: far below any tolerance asked.
fn fine_chords(region: &Region) -> Chords {
    Chords::of(region, 4000)
}

/// [`check`] against `chords`, each loop's area summed over `area_samples` points a piece.
fn check_against(chords: &Chords, found: &Offsets, tol: f64, area_samples: usize) -> Vec<Vec<f64>> {
    let mut areas = Vec::new();
    for o in &found.offsets {
        let mut per = Vec::new();
        for l in &o.loops {
            assert!(!l.segments.is_empty());
            let mut area = 0.0;
            for (k, s) in l.segments.iter().enumerate() {
                let (_, end) = ends(s);
                let (next, _) = ends(&l.segments[(k + 1) % l.segments.len()]);
                let gap = ((end[0] - next[0]).powi(2) + (end[1] - next[1]).powi(2)).sqrt();
                // (Rounding of the coordinates: relative to their size, far from the origin.)
                assert!(
                    gap < 1e-9 * end[0].abs().max(end[1].abs()).max(1.0),
                    "d = {}: piece {k} ends {gap} from the next",
                    o.distance
                );
                let fine = samples(s, area_samples);
                for w in fine.windows(2) {
                    area += 0.5 * (w[0][0] * w[1][1] - w[1][0] * w[0][1]);
                }
                for p in samples(s, 24) {
                    let dist = chords.distance(p);
                    testkit::assert_near!(
                        dist,
                        o.distance,
                        tol,
                        "d = {}: {p:?} is {dist} from the boundary",
                        o.distance
                    );
                }
            }
            per.push(area);
        }
        areas.push(per);
    }
    areas
}

#[test]
fn a_rectangle_shrinks_to_a_rectangle_until_it_vanishes() {
    let region = polygon_region(&[[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]);
    let (found, areas) = checked_offsets(&region, &[0.25, 0.5, 0.9, 1.1], 1e-9);
    for (k, d) in [0.25, 0.5, 0.9].iter().enumerate() {
        assert_eq!(found.offsets[k].loops.len(), 1);
        assert_eq!(found.offsets[k].loops[0].segments.len(), 4);
        let expected = (4.0 - 2.0 * d) * (2.0 - 2.0 * d);
        testkit::assert_near!(areas[k][0], expected, 1e-9, "{} vs {expected}", areas[k][0]);
    }
    assert!(
        found.offsets[3].loops.is_empty(),
        "beyond half the width nothing is left"
    );
    assert!(found.certified() && found.complete);
    let drawn = found.offsets[0].loops[0].polyline(8);
    assert_eq!(drawn.len(), 9, "four lines, closed");
    assert_eq!(drawn.first(), drawn.last());
}

#[test]
fn an_annulus_gives_two_circles_each_way_round() {
    let region = Region::new(circle([1.0, 2.0], 3.0), vec![circle([1.0, 2.0], 1.0)]).unwrap();
    let (found, areas) = checked_offsets(&region, &[0.5, 0.99, 1.01], 1e-6);
    for (k, d) in [0.5_f64, 0.99].iter().enumerate() {
        let mut got = areas[k].clone();
        got.sort_by(f64::total_cmp);
        // (Clockwise round the hole: negative area.)
        let (hole, outer) = (-PI * (1.0 + d).powi(2), PI * (3.0 - d).powi(2));
        testkit::assert_near!(got[0], hole, 1e-3 * hole.abs(), "{got:?}");
        testkit::assert_near!(got[1], outer, 1e-3 * outer, "{got:?}");
    }
    assert!(found.offsets[2].loops.is_empty());
}

#[test]
fn the_pocket_keeps_its_island_then_splits_then_vanishes() {
    let region = pocket();
    let distances: Vec<f64> = (1..=12).map(|k| 0.25 * k as f64).collect();
    let (found, _) = checked_offsets(&region, &distances, 1e-6);
    let counts: Vec<usize> = found.offsets.iter().map(|o| o.loops.len()).collect();
    // Two loops (round the pocket, round the island) while the island's gap to the right
    // wall (2.5 wide) is open; then one loop left of the island; then none.
    assert_eq!(counts[0], 2, "{counts:?}");
    assert_eq!(counts.last(), Some(&0), "{counts:?}");
    assert!(found.certified() && found.complete, "{:?}", found.reason());
}

#[test]
fn reflex_corners_become_arcs_of_the_distance() {
    // An L-shaped room: its one reflex corner at (2, 2).
    let region = polygon_region(&[
        [0.0, 0.0],
        [6.0, 0.0],
        [6.0, 2.0],
        [2.0, 2.0],
        [2.0, 6.0],
        [0.0, 6.0],
    ]);
    let (found, _) = checked_offsets(&region, &[0.5], 1e-9);
    let arcs: Vec<&OffsetSegment> = found.offsets[0].loops[0]
        .segments
        .iter()
        .filter(|s| matches!(s, OffsetSegment::Arc { .. }))
        .collect();
    assert_eq!(arcs.len(), 1);
    let OffsetSegment::Arc {
        center,
        r,
        start,
        end,
    } = arcs[0]
    else {
        unreachable!()
    };
    assert_eq!((*center, *r), ([2.0, 2.0], 0.5));
    assert!(
        (start - end - FRAC_PI_2).abs() < 1e-9,
        "a quarter turn clockwise"
    );
}

#[test]
fn a_stretch_across_a_round_islands_seam_is_one_arc() {
    // The island's parameter starts at angle 0, where the offset at 1 crosses it (the
    // fixture region-pocket.json).
    let mut region = pocket();
    region = Region::new(region.outer().clone(), vec![circle([6.5, 3.0], 1.2)]).unwrap();
    let (found, _) = checked_offsets(&region, &[1.0, 1.1], 1e-6);
    for o in &found.offsets {
        let arcs = o.loops.iter().flat_map(|l| &l.segments).filter(
            |s| matches!(s, OffsetSegment::Arc { r, .. } if (r - (1.2 + o.distance)).abs() < 1e-9),
        );
        assert!(
            arcs.count() <= 3,
            "d = {}: the island's offset in a few arcs",
            o.distance
        );
    }
}

mod random_regions {
    use super::*;
    use proptest::prelude::*;

    /// A star-shaped polygon (simple by construction, with reflex corners where its radii
    /// dip), and maybe a round hole about its centre.
    pub(super) fn region(radii: &[f64], turns: &[f64], hole: bool) -> Region {
        let n = radii.len();
        let corners: Vec<[f64; 2]> = (0..n)
            .map(|i| {
                let a = TAU * (i as f64 + 0.4 * turns[i]) / n as f64;
                [radii[i] * a.cos(), radii[i] * a.sin()]
            })
            .collect();
        Region::new(polygon(&corners), round_hole(hole)).unwrap()
    }

    fn round_hole(hole: bool) -> Vec<Profile> {
        if hole {
            vec![circle([0.0, 0.0], 0.15)]
        } else {
            vec![]
        }
    }

    /// Chords a curve of the oracle's boundary: within 1e-5 of the exact distance on these
    /// shapes.
    const PER_CURVE: usize = 720;

    /// The box of the chords, grown by a tenth and by `reach` each way.
    fn grid_box(chords: &Chords, reach: f64) -> ([f64; 2], f64) {
        let (lo, hi) = chords.bounds();
        let side = (hi[0] - lo[0]).max(hi[1] - lo[1]) * 1.2 + 2.0 * reach;
        let centre = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
        ([centre[0] - 0.5 * side, centre[1] - 0.5 * side], side)
    }

    /// The number of boundary curves of the set at distance ≥ `d` inside the region (or
    /// `outward`, of the region grown by `d`), on an `n` × `n` grid: its components plus those
    /// of the rest of the plane (the grid's border all outside) less one, as the components of
    /// a planar set and of its complement form a tree joined by the curves. `None` where the
    /// count depends on which of the two sets is taken 8-connected (a part of either a cell
    /// thin, which the grid does not resolve).
    fn loops_on_grid(chords: &Chords, d: f64, n: usize, outward: bool) -> Option<usize> {
        let (lo, side) = grid_box(chords, d);
        let h = side / (n - 1) as f64;
        let kept: Vec<bool> = (0..n * n)
            .map(|k| {
                let p = [lo[0] + (k % n) as f64 * h, lo[1] + (k / n) as f64 * h];
                if outward {
                    chords.inside(p) || chords.distance(p) <= d
                } else {
                    chords.inside(p) && chords.distance(p) >= d
                }
            })
            .collect();
        let components = |want: bool, diagonal: bool| {
            let mut seen = vec![false; n * n];
            let mut count = 0usize;
            for start in 0..n * n {
                if seen[start] || kept[start] != want {
                    continue;
                }
                count += 1;
                seen[start] = true;
                let mut stack = vec![start];
                while let Some(k) = stack.pop() {
                    let (x, y) = ((k % n) as i64, (k / n) as i64);
                    for (dx, dy) in [
                        (1, 0),
                        (-1, 0),
                        (0, 1),
                        (0, -1),
                        (1, 1),
                        (1, -1),
                        (-1, 1),
                        (-1, -1),
                    ]
                    .into_iter()
                    .take(if diagonal { 8 } else { 4 })
                    {
                        let (u, v) = (x + dx, y + dy);
                        if u < 0 || v < 0 || u >= n as i64 || v >= n as i64 {
                            continue;
                        }
                        let j = v as usize * n + u as usize;
                        if !seen[j] && kept[j] == want {
                            seen[j] = true;
                            stack.push(j);
                        }
                    }
                }
            }
            count
        };
        let one_way = components(true, false) + components(false, true);
        let other_way = components(true, true) + components(false, false);
        (one_way == other_way).then(|| one_way.saturating_sub(1))
    }

    /// Whether loops sampled as `loops` are all wider than `w` (their area over their length,
    /// a quarter of the width of a disk and half of a strip's, at least `w / 2`), and apart
    /// by more than `w` from each other and from themselves across any passage (points more
    /// than `3 w` apart along a loop), with no sharp tip (turning by more than 135° within
    /// `w` along: near a tip sharper than the grid's 45° between neighbours, a grid point may
    /// have none of its eight neighbours in the set and count as a part of its own): then a
    /// grid of cells a quarter of `w` resolves the set they bound.
    fn resolved(loops: &[Vec<[f64; 2]>], w: f64) -> bool {
        let gap = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]);
        let wide = |a: &[[f64; 2]]| {
            let length: f64 = a.windows(2).map(|s| gap(s[0], s[1])).sum();
            let area = a
                .windows(2)
                .map(|s| 0.5 * (s[0][0] * s[1][1] - s[1][0] * s[0][1]))
                .sum::<f64>()
                .abs();
            area >= 0.5 * w * length
        };
        // (The passages and gaps on samples thinned to a sixteenth of `w` apart: fewer pairs,
        // and none of either wider than that missed.)
        let thinned: Vec<Vec<[f64; 2]>> = loops
            .iter()
            .map(|l| {
                let mut kept = vec![l[0]];
                for &p in &l[1..] {
                    if gap(p, kept[kept.len() - 1]) >= w / 16.0 {
                        kept.push(p);
                    }
                }
                kept
            })
            .collect();
        loops.iter().all(|a| wide(a))
            && thinned.iter().enumerate().all(|(i, a)| {
                let mut along = vec![0.0];
                for pair in a.windows(2) {
                    along.push(along[along.len() - 1] + gap(pair[0], pair[1]));
                }
                let length = along[along.len() - 1];
                let heading: Vec<f64> = a
                    .windows(2)
                    .map(|s| (s[1][1] - s[0][1]).atan2(s[1][0] - s[0][0]))
                    .collect();
                let turn = |j: usize| {
                    let t = heading[(j + 1) % heading.len()] - heading[j];
                    (t + PI).rem_euclid(TAU) - PI
                };
                let no_tip = (0..heading.len()).all(|j| {
                    let (mut turned, mut run, mut k) = (0.0f64, 0.0, j);
                    while run <= w && k < j + heading.len() {
                        turned += turn(k % heading.len());
                        run += gap(a[(k + 1) % a.len()], a[(k + 2) % a.len()]);
                        k += 1;
                        if turned.abs() > 0.75 * PI {
                            return false;
                        }
                    }
                    true
                });
                let no_passage = (0..a.len()).all(|j| {
                    (j + 1..a.len()).all(|k| {
                        let apart = (along[k] - along[j]).min(length - along[k] + along[j]);
                        apart <= 3.0 * w || gap(a[j], a[k]) > w
                    })
                });
                let apart = thinned[i + 1..]
                    .iter()
                    .all(|b| a.iter().all(|&p| b.iter().all(|&q| gap(p, q) > w)));
                no_tip && no_passage && apart
            })
    }

    /// The independent checks of one region's offsets: every point of each loop at the
    /// distance (dense distance), loops closed, not crossing; nothing at the distance missing
    /// (each crossing of the distance on a grid lies on a loop); and as many loops as a grid
    /// counts boundary curves of the set kept, where the loops are wide and apart enough for
    /// it to resolve them (counted per thread). Inward offsets are looked for inside the
    /// region, `outward` ones outside.
    fn check_all(
        region: &Region,
        found: &Offsets,
        point_tol: f64,
        outward: bool,
    ) -> Result<(), TestCaseError> {
        check(region, found, point_tol);
        let chords = Chords::of(region, PER_CURVE);
        for o in &found.offsets {
            let loops: Vec<Vec<[f64; 2]>> = o
                .loops
                .iter()
                .map(|l| l.segments.iter().flat_map(|s| samples(s, 64)).collect())
                .collect();
            for (i, a) in loops.iter().enumerate() {
                for b in &loops[i + 1..] {
                    prop_assert!(!cross(a, b), "d = {}: two loops cross", o.distance);
                }
            }
            // Each loop is a profile the tool reads back (which it is not if it crosses itself).
            for l in &o.loops {
                let read = l.profile();
                prop_assert!(read.is_ok(), "d = {}: {:?}", o.distance, read.err());
            }
            let to_loops = |p: [f64; 2]| {
                o.loops
                    .iter()
                    .flat_map(|l| &l.segments)
                    .map(|s| distance_to_piece(p, s))
                    .fold(f64::INFINITY, f64::min)
            };
            // Nothing missing: where the distance crosses d along a grid line on the offset's
            // side of the boundary, the crossing (by bisection) lies on a loop.
            let (lo, side) = grid_box(&chords, o.distance);
            let on_side = |p: [f64; 2]| chords.inside(p) != outward;
            let n = 48;
            let h = side / (n - 1) as f64;
            let f = |p: [f64; 2]| chords.distance(p) - o.distance;
            for k in 0..n * n {
                let p = [lo[0] + (k % n) as f64 * h, lo[1] + (k / n) as f64 * h];
                for q in [[p[0] + h, p[1]], [p[0], p[1] + h]] {
                    if !(on_side(p) && on_side(q)) || (f(p) >= 0.0) == (f(q) >= 0.0) {
                        continue;
                    }
                    let (mut a, mut b) = (p, q);
                    for _ in 0..50 {
                        let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                        if (f(m) >= 0.0) == (f(a) >= 0.0) {
                            a = m;
                        } else {
                            b = m;
                        }
                    }
                    if on_side(a) {
                        let off = to_loops(a);
                        prop_assert!(
                            off <= point_tol + 1e-5,
                            "d = {}: {a:?} is at the distance but {off} from every loop",
                            o.distance
                        );
                    }
                }
            }
            // As many loops as boundary curves of the set kept, counted on a grid whose cells
            // are a quarter of the loops' least width and gaps.
            let n = 100;
            let h = grid_box(&chords, o.distance).1 / (n - 1) as f64;
            if resolved(&loops, 4.0 * h) {
                if let Some(count) = loops_on_grid(&chords, o.distance, n, outward) {
                    prop_assert_eq!(
                        o.loops.len(),
                        count,
                        "d = {}: loops against the grid's count (outward: {})",
                        o.distance,
                        outward
                    );
                    COUNTED.with(|c| c.set(c.get() + 1));
                }
            }
            CHECKED.with(|c| c.set(c.get() + 1));
        }
        Ok(())
    }

    thread_local! {
        /// Offsets checked, per test thread.
        static CHECKED: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
        /// Offsets whose loops were counted against the grid, per test thread.
        static COUNTED: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
    }

    /// Checks that at least `share` of the offsets checked on this thread had their loops
    /// counted.
    fn assert_counted(share: f64) {
        let (checked, counted) = (CHECKED.with(|c| c.get()), COUNTED.with(|c| c.get()));
        assert!(
            checked >= 24 && counted as f64 >= share * checked as f64,
            "loops counted for {counted} offsets of {checked}"
        );
    }

    /// Runs the random polygons' property and checks it was not vacuous.
    #[test]
    fn offsets_of_random_polygons_match_the_oracle() {
        offsets_of_random_polygons_are_at_the_distance();
        // (Most of the polygons' offsets are wide: 80 % counted with the seed of CI.)
        assert_counted(0.7);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(cases(120)))]

        /// Random polygons, maybe with a hole, inward and outward: see [`check_all`].
        fn offsets_of_random_polygons_are_at_the_distance(
            radii in proptest::collection::vec(0.6..1.4f64, 5..11),
            turns in proptest::collection::vec(-1.0..1.0f64, 11),
            hole in any::<bool>(),
            distances in proptest::collection::vec(0.02..0.45f64, 1..4),
        ) {
            let region = region(&radii, &turns, hole);
            let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
            prop_assume!(axis.certified());
            let found = offsets(&region, &axis, &distances, &OffsetOptions::default()).unwrap();
            prop_assert!(found.complete);
            check_all(&region, &found, 1e-6, false)?;
            // Outward, from the exterior axis: the same checks.
            let outside = medial_axis(
                &region,
                &MedialOptions { exterior: true, ..MedialOptions::default() },
            )
            .unwrap();
            if outside.certified() {
                let grown =
                    offset::outward_offsets(&region, &outside, &distances, &OffsetOptions::default())
                        .unwrap();
                prop_assert!(grown.complete);
                check_all(&region, &grown, 1e-6, true)?;
            }
        }
    }

    thread_local! {
        static SPLINE_CASES: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
        static SPLINE_CERTIFIED: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
    }

    /// Runs the spline regions' property and checks that most of its offsets were certified
    /// and had their loops counted.
    #[test]
    fn offsets_of_spline_regions_are_mostly_certified() {
        offsets_of_random_spline_regions_are_at_the_distance();
        let (cases, certified) = (
            SPLINE_CASES.with(|c| c.get()),
            SPLINE_CERTIFIED.with(|c| c.get()),
        );
        assert!(
            cases >= 12 && 2 * certified >= cases,
            "{certified} of {cases} certified"
        );
        // (The Béziers' offsets at larger distances are often narrow: 62 % counted with the
        // seed of CI.)
        assert_counted(0.5);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(cases(60)))]

        /// Random closed chains of cubic Béziers with corners and smooth joints, maybe with a
        /// hole: the spline pieces within the chord tolerance (and the error reported within
        /// it), and the checks of [`check_all`].
        fn offsets_of_random_spline_regions_are_at_the_distance(
            radii in proptest::collection::vec(1.0f64..2.0, 3..6),
            wobble in proptest::collection::vec(
                (prop_oneof![-0.4f64..-0.05, 0.05f64..0.4], prop_oneof![-0.4f64..-0.05, 0.05f64..0.4]),
                6,
            ),
            smooth in proptest::collection::vec(any::<bool>(), 6),
            hole in any::<bool>(),
            distances in proptest::collection::vec(0.02..0.6f64, 1..4),
        ) {
            let n = radii.len();
            let Some(segs) = testkit::profiles::bezier_chain(&radii, &wobble[..n], &smooth[..n]) else { return Ok(()) };
            let Some(outer) = testkit::profiles::assemble(segs, 0, false) else { return Ok(()) };
            let Ok(region) = Region::new(outer, round_hole(hole)) else { return Ok(()) };
            let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
            prop_assume!(axis.certified());
            let opts = OffsetOptions::default();
            let found = offsets(&region, &axis, &distances, &opts).unwrap();
            prop_assert!(found.complete);
            let chord = opts.settings.chord_tol.get() * size_of(&region);
            for o in &found.offsets {
                prop_assert!(o.error <= chord, "d = {}: error {} past {chord}", o.distance, o.error);
            }
            // (Certified but where the radius may dip between two of the axis's vertices, a
            // neck the bound from its slope cannot rule out.)
            if found.certified() {
                SPLINE_CERTIFIED.with(|c| c.set(c.get() + 1));
            } else {
                prop_assert!(found.reason().as_deref().is_some_and(|r| r.contains("neck")), "{:?}", found.reason());
            }
            SPLINE_CASES.with(|c| c.set(c.get() + 1));
            check_all(&region, &found, chord + 1e-5, false)?;
        }
    }

    /// The region's size as the offsets take it: the larger side of its outer box.
    fn size_of(region: &Region) -> f64 {
        let outer = Region::new(region.outer().clone(), vec![]).unwrap();
        let (lo, hi) = Chords::of(&outer, PER_CURVE).bounds();
        (hi[0] - lo[0]).max(hi[1] - lo[1])
    }

    /// Whether two polylines cross (a proper crossing of two of their chords).
    fn cross(a: &[[f64; 2]], b: &[[f64; 2]]) -> bool {
        let orient = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
            (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
        };
        a.windows(2).any(|s| {
            b.windows(2).any(|t| {
                orient(s[0], s[1], t[0]) * orient(s[0], s[1], t[1]) < 0.0
                    && orient(t[0], t[1], s[0]) * orient(t[0], t[1], s[1]) < 0.0
            })
        })
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

/// Offsetting by D1, then the result by D2, gives the offset by D1 + D2 (the loops as point
/// sets, within 1e-7): on the pocket, whose offsets are lines and arcs. Both are taken with
/// the pocket's size: at 1 its passes touch the island, and each horn there is cut where it
/// is 1e-8 of the size wide (6e-4 from its tip; of the smaller size of the region offset by
/// 0.5, 3e-5 nearer).
#[test]
fn offsets_compose() {
    let region = pocket();
    let first = offsets_of(&region, &[0.5]);
    let profiles: Vec<Profile> = first.offsets[0]
        .loops
        .iter()
        .map(|l| l.profile().unwrap())
        .collect();
    let inner = Region::nested(profiles).unwrap();
    assert_eq!(
        inner.len(),
        1,
        "the pocket at 0.5 is one region with its island"
    );
    let opts = OffsetOptions {
        settings: numeric::tolerance::Settings::new(
            numeric::tolerance::DEFAULT_PARAM_TOL,
            numeric::tolerance::DEFAULT_CHORD_TOL,
            Some(region.size()),
        )
        .expect("settings in range"),
    };
    for d2 in [0.25, 0.5, 0.6] {
        let axis = medial_axis(&inner[0], &MedialOptions::default()).unwrap();
        assert!(axis.certified(), "{:?}", axis.reason());
        let again = offsets(&inner[0], &axis, &[d2], &opts).unwrap();
        let direct = offsets_of(&region, &[0.5 + d2]);
        assert_eq!(
            again.offsets[0].loops.len(),
            direct.offsets[0].loops.len(),
            "d2 = {d2}"
        );
        // (Each one's sampled points lie on the other's exact pieces.)
        for (from, onto) in [(&again, &direct), (&direct, &again)] {
            let pieces: Vec<&OffsetSegment> = onto.offsets[0]
                .loops
                .iter()
                .flat_map(|l| &l.segments)
                .collect();
            for l in &from.offsets[0].loops {
                for p in l.segments.iter().flat_map(|s| samples(s, 40)) {
                    let off = pieces
                        .iter()
                        .map(|s| distance_to_piece(p, s))
                        .fold(f64::INFINITY, f64::min);
                    assert!(off < 1e-7, "d2 = {d2}: {p:?} is {off} off");
                }
            }
        }
    }
}

/// The distance from `p` to an offset piece (exact for lines and arcs).
fn distance_to_piece(p: [f64; 2], s: &OffsetSegment) -> f64 {
    match s {
        OffsetSegment::Line { from, to } => curve::distance_to_segment(p, *from, *to),
        OffsetSegment::Arc {
            center,
            r,
            start,
            end,
        } => {
            let a = (p[1] - center[1]).atan2(p[0] - center[0]);
            let (lo, hi) = if start <= end {
                (*start, *end)
            } else {
                (*end, *start)
            };
            let within = (a - lo).rem_euclid(TAU) <= hi - lo + 1e-12;
            let ends = samples(s, 1);
            let to_end = |q: [f64; 2]| ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
            let by_ends = to_end(ends[0]).min(to_end(ends[1]));
            if within {
                ((p[0] - center[0]).hypot(p[1] - center[1]) - r)
                    .abs()
                    .min(by_ends)
            } else {
                by_ends
            }
        }
        OffsetSegment::BSpline { .. } => samples(s, 256)
            .windows(2)
            .map(|w| curve::distance_to_segment(p, w[0], w[1]))
            .fold(f64::INFINITY, f64::min),
    }
}

fn outward_of(region: &Region, distances: &[f64]) -> Offsets {
    let opts = MedialOptions {
        exterior: true,
        ..MedialOptions::default()
    };
    let axis = medial_axis(region, &opts).unwrap();
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
    let axis = medial_axis(
        &region,
        &MedialOptions {
            exterior: true,
            ..MedialOptions::default()
        },
    )
    .unwrap();
    let far = offset::outward_offsets(&region, &axis, &[6.0], &OffsetOptions::default());
    assert!(
        far.is_err(),
        "beyond half the size the exterior axis is clipped"
    );
    let found = outward_of(&region, &[0.3, 0.9, 2.0]);
    check(&region, &found, 1e-6);
}

/// The options are checked against what the algorithms deliver, by the tolerances' one
/// range, where the settings are made: a chord tolerance in [1e-9, 0.5] for the offsets, as
/// for the axis (whose size must also be a finite number above zero); out of it, an error
/// naming the field. Settings in range are taken.
#[test]
fn options_out_of_range_are_refused_by_name() {
    use numeric::tolerance::{Settings, DEFAULT_CHORD_TOL, DEFAULT_PARAM_TOL};
    let region = pocket();
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    for (chord_tol, ok) in [
        (1e-9, true),
        (0.5, true),
        (1e-10, false),
        (0.6, false),
        (f64::NAN, false),
    ] {
        match Settings::new(DEFAULT_PARAM_TOL, chord_tol, None) {
            Ok(settings) => {
                assert!(ok, "chord_tol {chord_tol} taken");
                let found = offsets(&region, &axis, &[0.5], &OffsetOptions { settings });
                assert!(found.is_ok(), "chord_tol {chord_tol}: {found:?}");
            }
            Err(e) => {
                assert!(!ok, "chord_tol {chord_tol} refused: {e}");
                assert!(e.to_string().contains("chord_tol"), "{e}");
            }
        }
    }
    for size in [0.0, -1.0, f64::INFINITY, f64::NAN] {
        let e = Settings::new(DEFAULT_PARAM_TOL, DEFAULT_CHORD_TOL, Some(size)).unwrap_err();
        assert!(e.to_string().contains("size"), "{e}");
    }
    let tiny = Settings::new(1e-16, DEFAULT_CHORD_TOL, None).unwrap_err();
    assert_eq!(tiny.field, "tol", "{tiny}");
    assert!(tiny.to_string().starts_with("tol: "), "{tiny}");
}

#[test]
fn a_square_hole_grows_rounded_corners_inward() {
    let outer = polygon(&[[-4.0, -4.0], [4.0, -4.0], [4.0, 4.0], [-4.0, 4.0]]);
    let hole = polygon(&[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]);
    let region = Region::new(outer, vec![hole]).unwrap();
    let (found, areas) = checked_offsets(&region, &[0.5], 1e-6);
    let round_hole = found.offsets[0]
        .loops
        .iter()
        .find(|l| l.segments.len() == 8)
        .expect("the hole's offset: four lines and four quarter circles");
    let arcs = round_hole
        .segments
        .iter()
        .filter(|s| matches!(s, OffsetSegment::Arc { .. }))
        .count();
    assert_eq!(arcs, 4);
    let hole_area = -(4.0 + 4.0 * 2.0 * 0.5 + PI * 0.25);
    assert!(
        areas[0].iter().any(|a| (a - hole_area).abs() < 1e-4),
        "{areas:?}"
    );
}

/// A hole whose last segment is an arc ending at a corner at the parameter 0: the corner's
/// arc is turned from that arc's end normal, not its start's (a review found it).
#[test]
fn a_d_shaped_hole_closes_round_its_corners() {
    let outer = polygon(&[[-4.0, -4.0], [4.0, -4.0], [4.0, 4.0], [-4.0, 4.0]]);
    let hole = Profile::new(
        vec![
            Segment::line([0.0, 1.0], [0.0, -1.0]).unwrap(),
            Segment::arc([0.0, 0.0], 1.0, -FRAC_PI_2, FRAC_PI_2).unwrap(),
        ],
        None,
    )
    .unwrap();
    let region = Region::new(outer, vec![hole]).unwrap();
    for d in [0.3, 0.5, 1.0] {
        let (found, _) = checked_offsets(&region, &[d], 1e-6);
        assert_eq!(found.offsets[0].loops.len(), 2, "d = {d}");
    }
}

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

/// An axis that is not the region's is an error, not a panic: arrays of unequal lengths, a
/// number that is not finite, a boundary or a foot out of range.
#[test]
fn a_malformed_axis_is_an_error() {
    let region = pocket();
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    let opts = OffsetOptions::default();
    let breakages: [&dyn Fn(&mut medial::MedialAxis); 6] = [
        &|a| {
            a.edges[0].radius.pop();
        },
        &|a| a.edges[0].xy[0][0] = f64::NAN,
        &|a| a.edges[0].radius[0] = -1.0,
        &|a| a.edges[0].boundary[0][1] = 7,
        &|a| a.edges[0].feet[0][0] = 1e9,
        &|a| a.edges[0].to = 1000,
    ];
    for (k, breaks) in breakages.iter().enumerate() {
        let mut broken = axis.clone();
        breaks(&mut broken);
        let got = offsets(&region, &broken, &[0.5], &opts);
        assert!(
            matches!(got, Err(offset::Error::BadAxis(_))),
            "breakage {k}: {got:?}"
        );
    }
    assert!(offsets(&region, &axis, &[0.5], &opts).is_ok());
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

/// Metamorphic: the pocket (lines and arcs) and a chain of Béziers moved far from the origin,
/// scaled by 1e±6 or rotated have, at the moved distances, as many loops, every point at the
/// distance (within the tolerance scaled), the spline pieces' errors within it; certified
/// where the moved axis is (always, but far from the origin).
#[test]
fn offsets_moved_scaled_or_rotated_are_the_moved_offsets() {
    let segs = testkit::profiles::bezier_chain(
        &[1.5, 1.2, 1.8, 1.4],
        &[(0.2, -0.1), (-0.1, 0.3), (0.15, 0.1), (-0.2, -0.2)],
        &[true, false, true, false],
    )
    .unwrap();
    let chain = Region::new(testkit::profiles::assemble(segs, 0, false).unwrap(), vec![]).unwrap();
    let (c, s) = (0.6f64, 0.8f64); // a rotation with exact sine and cosine
    let maps = [
        curve::Affine([1.0, 0.0, 0.0, 1.0, 1e6, -1e6]),
        curve::Affine([1e-6, 0.0, 0.0, 1e-6, 3e-6, 0.0]),
        curve::Affine([1e6, 0.0, 0.0, 1e6, 0.0, -7e6]),
        curve::Affine([c, s, -s, c, 0.25, 0.5]),
    ];
    for (region, distances) in [
        (pocket(), vec![0.5, 1.0, 2.0]),
        (chain, vec![0.2, 0.5, 0.9]),
    ] {
        let base = offsets_of(&region, &distances);
        assert!(base.certified(), "{:?}", base.reason());
        for map in &maps {
            let scale = map.determinant().abs().sqrt();
            let moved_region = region.transformed(map).unwrap();
            let moved_distances: Vec<f64> = distances.iter().map(|d| d * scale).collect();
            let axis = medial_axis(&moved_region, &MedialOptions::default()).unwrap();
            // (Far from the origin the axis's digits may run out: uncertified, then said so.)
            let translated = map.0[..4] == [1.0, 0.0, 0.0, 1.0];
            assert!(
                axis.certified() || translated,
                "{map:?}: {:?}",
                axis.reason()
            );
            let moved = offsets(
                &moved_region,
                &axis,
                &moved_distances,
                &OffsetOptions::default(),
            )
            .unwrap();
            if !axis.certified() {
                assert!(!moved.certified());
                continue;
            }
            assert!(moved.certified(), "{map:?}: {:?}", moved.reason());
            for (b, m) in base.offsets.iter().zip(&moved.offsets) {
                assert_eq!(b.loops.len(), m.loops.len(), "{map:?}, d = {}", b.distance);
                assert!(m.error <= 1e-3 * 4.0 * scale, "{map:?}: error {}", m.error);
            }
            check(&moved_region, &moved, 4e-3 * scale);
        }
    }
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

/// Offsets run under a cancelled watch stop with `Cancelled`, never a partial list; the same
/// call unwatched, or under a watch not cancelled, gives every offset.
#[test]
fn cancelled_offsets_say_so() {
    use curve::watch::Watch;
    use std::sync::Arc;
    let region = pocket();
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    let opts = OffsetOptions::default();
    let distances = [0.25, 0.5, 0.75];
    let watch = Arc::new(Watch::default());
    let found = watch.run(|| offsets(&region, &axis, &distances, &opts));
    assert_eq!(found.unwrap().offsets.len(), 3);
    assert_eq!(watch.progress().stage, "offsets: one distance each");
    watch.cancel();
    let found = watch.run(|| offsets(&region, &axis, &distances, &opts));
    assert!(matches!(found, Err(offset::Error::Cancelled)), "{found:?}");
    assert_eq!(
        offsets(&region, &axis, &distances, &opts)
            .unwrap()
            .offsets
            .len(),
        3
    );
}
