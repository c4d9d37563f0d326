//! The medial axis (issue 19), one core. Targets: the periodic cubic of the issue at chord
//! 1e-3 in 1 ms; the 10×6 rounded-rectangle pocket (corner radius 1) with a round island of
//! radius 1 in 0.14 ms; a profile of 100 segments in 30 ms, growing about linearly with the
//! number of segments (chains of 12, 25 and 50 cubic Béziers with corners show the growth);
//! the smooth 250-point periodic cubic in 50 ms (too slow yet to sit in a benchmark: it is
//! timed with `curvekit medial --time`, see README). Each shape is measured warm (the region
//! built) and the first two cold (read from the file's bytes, then the axis).
#![allow(missing_docs, clippy::unwrap_used)]

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use curve::Region;
use curvekit::medial::{medial_axis, MedialOptions};
use std::time::Duration;

#[path = "common/read.rs"]
mod read;
use read::region_of;
use testkit::outlines::{bezier_chain, POCKET};

const PERIODIC_CUBIC: &str = r#"{"kind":"bspline","degree":3,"periodic":true,
    "points":[[0,0],[2,-1],[4,0],[4,2],[2,1.2],[0,2]]}"#;

fn medial(c: &mut Criterion) {
    // One core, as the targets are given (the crate's `parallel` feature would use them all;
    // the global pool is built once, here, before anything runs on it).
    let _ = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global();
    let opts = MedialOptions::default();
    for (name, text) in [
        ("medial_periodic_cubic", PERIODIC_CUBIC),
        ("medial_pocket_island", POCKET),
    ] {
        let region = region_of(text);
        let axis = medial_axis(&region, &opts).unwrap();
        eprintln!(
            "{name}: {} nodes, {} edges",
            axis.nodes.len(),
            axis.edges.len()
        );
        c.bench_function(name, |b| {
            b.iter(|| medial_axis(black_box(&region), &opts).unwrap())
        });
        c.bench_function(&format!("{name}_cold"), |b| {
            b.iter(|| medial_axis(&region_of(black_box(text)), &opts).unwrap())
        });
    }
    for n in [12, 25, 50] {
        let region = Region::new(bezier_chain(n), Vec::new()).unwrap();
        c.bench_function(&format!("medial_bezier_chain_{n}"), |b| {
            b.iter(|| medial_axis(black_box(&region), &opts).unwrap())
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = medial
}
criterion_main!(benches);
