//! curvekit against the line/arc tools a CAM user would pick instead (issue 39), one core,
//! each figure beside its peer's on the same input in the same run:
//! - the medial axis of star polygons of 100, 400 and 1,600 lines against boostvoronoi's
//!   Voronoi diagram of the same segments (integer coordinates, as it takes them), and so the
//!   CAD outline of 1,500 and 5,000 lines (a plate's arcs as chords, its sides as collinear
//!   runs);
//! - the medial axis of gears of 25 and 100 teeth (lines and arcs) against boostvoronoi's
//!   diagram of their arcs as chords within the axis's chord tolerance;
//! - the pocket's offsets at step 0.25 (the axis included) and the star of 400 lines' offsets
//!   at step 0.05 (its axis included too) against CavalierContours' parallel offsets at the
//!   same distances.
//!
//! `CURVEKIT_PEERS_MAX` caps the star sizes curvekit is run on (the axis of the exhaustive
//! path grows as n^1.7: 1,600 lines take seconds an iteration).
#![allow(missing_docs, clippy::unwrap_used)]

use boostvoronoi::prelude::{Builder, Line};
use cavalier_contours::polyline::{PlineSource, PlineSourceMut, Polyline};
use cavalier_contours::shape_algorithms::{Shape as CavShape, ShapeOffsetOptions};
use criterion::measurement::WallTime;
use criterion::{
    black_box, criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion,
};
use curve::Region;
use curvekit::medial::{medial_axis, MedialOptions};
use curvekit::offset::{offsets, OffsetOptions};
use numeric::certificate::Verdict;
use std::f64::consts::FRAC_PI_2;
use std::time::Duration;

#[path = "common/read.rs"]
mod read;
use read::region_of;
use testkit::outlines::{dense_outline, gear, gear_chords, polygon, star_polygon, POCKET};

/// The grid boostvoronoi's integer input is snapped to: the star spans [-1.1, 1.1].
const GRID: f64 = 1e6;

fn boost_diagram(vertices: &[[f64; 2]]) -> usize {
    boost_diagram_of_loops(&[vertices], 1.0)
}

/// boostvoronoi's diagram of the closed polylines `loops`, scaled by `scale` onto the grid's
/// span; the number of its edges.
fn boost_diagram_of_loops(loops: &[&[[f64; 2]]], scale: f64) -> usize {
    let snap = |p: [f64; 2]| {
        [
            (p[0] * scale * GRID).round() as i64,
            (p[1] * scale * GRID).round() as i64,
        ]
    };
    let lines: Vec<Line<i64>> = loops
        .iter()
        .flat_map(|vertices| {
            let n = vertices.len();
            (0..n).map(move |i| {
                let (a, b) = (snap(vertices[i]), snap(vertices[(i + 1) % n]));
                Line::from([a[0], a[1], b[0], b[1]])
            })
        })
        .collect();
    let diagram = Builder::<i64>::default()
        .with_segments(lines.iter())
        .unwrap()
        .build()
        .unwrap();
    diagram.edges().len()
}

/// A closed polyline through `vertices` (bulge 0: lines).
fn cavalier_polygon(vertices: &[[f64; 2]]) -> Polyline<f64> {
    let mut p = Polyline::new_closed();
    for v in vertices {
        p.add(v[0], v[1], 0.0);
    }
    p
}

/// The pocket as CavalierContours takes it: the outer boundary counter-clockwise with its
/// quarter arcs as bulges (tan(θ/4) = tan(π/8)), the island clockwise as two half circles.
fn cavalier_pocket() -> CavShape<f64> {
    let quarter = (FRAC_PI_2 / 4.0).tan();
    let mut outer = Polyline::new_closed();
    for (x, y, bulge) in [
        (1.0, 0.0, 0.0),
        (9.0, 0.0, quarter),
        (10.0, 1.0, 0.0),
        (10.0, 5.0, quarter),
        (9.0, 6.0, 0.0),
        (1.0, 6.0, quarter),
        (0.0, 5.0, 0.0),
        (0.0, 1.0, quarter),
    ] {
        outer.add(x, y, bulge);
    }
    let mut island = Polyline::new_closed();
    island.add(7.5, 3.0, -1.0);
    island.add(5.5, 3.0, -1.0);
    CavShape::from_plines([outer, island])
}

/// CavalierContours' offsets of `shape` inward at `distances`; the number of loops.
fn cavalier_offsets(shape: &CavShape<f64>, distances: &[f64]) -> usize {
    let opts = ShapeOffsetOptions::default();
    distances
        .iter()
        .map(|&d| {
            let s = shape.parallel_offset(d, &opts);
            s.ccw_plines.len() + s.cw_plines.len()
        })
        .sum()
}

/// Benchmarks curvekit's medial axis of the polygon through `vertices` as `n` in `group`
/// ([`bench_region_axis`]).
fn bench_axis(
    group: &mut BenchmarkGroup<'_, WallTime>,
    label: &str,
    n: usize,
    vertices: &[[f64; 2]],
) {
    let region = Region::new(polygon(vertices), Vec::new()).unwrap();
    bench_region_axis(group, label, n, &region);
}

/// Benchmarks curvekit's medial axis of `region` as `n` in `group`, having said on stderr
/// what it is (nodes, edges, certified or why not).
fn bench_region_axis(
    group: &mut BenchmarkGroup<'_, WallTime>,
    label: &str,
    n: usize,
    region: &Region,
) {
    let opts = MedialOptions::default();
    let axis = medial_axis(region, &opts).unwrap();
    eprintln!(
        "{label}: {} nodes, {} edges, certified {} {}",
        axis.nodes.len(),
        axis.edges.len(),
        axis.certified(),
        axis.reason().as_deref().unwrap_or("")
    );
    group.bench_with_input(BenchmarkId::new("curvekit", n), region, |b, r| {
        b.iter(|| medial_axis(black_box(r), &opts).unwrap())
    });
}

fn peers(c: &mut Criterion) {
    let _ = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global();
    let max: usize = std::env::var("CURVEKIT_PEERS_MAX")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(usize::MAX);
    let opts = MedialOptions::default();
    let mut group = c.benchmark_group("star_axis");
    for n in [100, 400, 1600] {
        let vertices = star_polygon(n);
        group.bench_with_input(BenchmarkId::new("boostvoronoi", n), &vertices, |b, v| {
            b.iter(|| boost_diagram(black_box(v)))
        });
        if n <= max {
            bench_axis(&mut group, &format!("star {n}"), n, &vertices);
        }
    }
    group.finish();

    // A CAD export: a plate of arcs as chords and sides as collinear runs (as many lines).
    let mut group = c.benchmark_group("dense_outline_axis");
    for n in [1500, 5000] {
        let vertices = dense_outline(n);
        // (boostvoronoi's grid: the plate spans [0, 100].)
        let scaled: Vec<[f64; 2]> = vertices
            .iter()
            .map(|p| [p[0] / 50.0 - 1.0, p[1] / 50.0 - 1.0])
            .collect();
        group.bench_with_input(BenchmarkId::new("boostvoronoi", n), &scaled, |b, v| {
            b.iter(|| boost_diagram(black_box(v)))
        });
        // (The traced path takes these in a fraction of a second: never capped.)
        bench_axis(&mut group, &format!("dense outline {n}"), n, &vertices);
    }
    group.finish();

    // A part of lines and arcs: gears of 25 and 100 teeth, against boostvoronoi's diagram of
    // their arcs as chords within the axis's chord tolerance (1e-3 of the size, 20).
    let mut group = c.benchmark_group("gear_axis");
    for n in [25, 100] {
        let [outline, hole] = gear_chords(n, 1e-3 * 20.0);
        let loops = [&outline[..], &hole[..]];
        // (boostvoronoi's grid: the gear spans [-10, 10].)
        group.bench_with_input(BenchmarkId::new("boostvoronoi", n), &loops, |b, l| {
            b.iter(|| boost_diagram_of_loops(black_box(l), 0.1))
        });
        let label = format!(
            "gear {n} ({} chords for boostvoronoi)",
            outline.len() + hole.len()
        );
        bench_region_axis(&mut group, &label, n, &gear(n));
    }
    group.finish();

    let mut group = c.benchmark_group("offsets");
    let pocket = region_of(POCKET);
    let steps: Vec<f64> = (1..=12).map(|k| 0.25 * k as f64).collect();
    let cav_pocket = cavalier_pocket();
    // (The pocket is 6 wide: 12 steps of 0.25 reach its middle; so do CavalierContours'.)
    assert!(cavalier_offsets(&cav_pocket, &steps[..1]) == 2);
    group.bench_function("pocket_step_quarter/cavalier_contours", |b| {
        b.iter(|| cavalier_offsets(black_box(&cav_pocket), &steps))
    });
    group.bench_function("pocket_step_quarter/curvekit", |b| {
        b.iter(|| {
            let axis = medial_axis(black_box(&pocket), &opts).unwrap();
            offsets(&pocket, &axis, &steps, &OffsetOptions::default()).unwrap()
        })
    });
    let star = star_polygon(400);
    let star_steps: Vec<f64> = (1..=10).map(|k| 0.05 * k as f64).collect();
    let cav_star = CavShape::from_plines([cavalier_polygon(&star)]);
    assert!(cav_star.ccw_plines[0].polyline.area() > 0.0);
    group.bench_function("star_400_step_0.05/cavalier_contours", |b| {
        b.iter(|| cavalier_offsets(black_box(&cav_star), &star_steps))
    });
    if 400 <= max {
        let region = Region::new(polygon(&star), Vec::new()).unwrap();
        group.bench_function("star_400_step_0.05/curvekit", |b| {
            b.iter(|| {
                let axis = medial_axis(black_box(&region), &opts).unwrap();
                offsets(&region, &axis, &star_steps, &OffsetOptions::default()).unwrap()
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = peers
}
criterion_main!(benches);
