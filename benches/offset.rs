//! Offsets from the medial axis (issue 21), one core, the axis computed beforehand. Targets:
//! the 10×6 rounded-rectangle pocket with a round island of radius 1, every offset at step
//! 0.25, in 1 ms; a profile of 100 segments, 20 offsets, in 20 ms (a chain of 100 cubic
//! Béziers with corners). Writing the pocket's passes as DXF and as SVG paths (issue 40, whose
//! target is at most 10 % more than the command's work, axis and offsets; the README has the
//! figures).
#![allow(missing_docs, clippy::unwrap_used)]

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use curve::Region;
use curvekit::export::dxf_file::offsets_dxf;
use curvekit::export::svg_paths::offsets_svg;
use curvekit::medial::{medial_axis, MedialOptions};
use curvekit::offset::{offsets, OffsetOptions};
use std::time::Duration;

#[path = "common/read.rs"]
mod read;
use read::region_of;
use testkit::outlines::{bezier_chain, POCKET};

fn offset(c: &mut Criterion) {
    let _ = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global();
    let opts = OffsetOptions::default();
    let pocket = region_of(POCKET);
    let axis = medial_axis(&pocket, &MedialOptions::default()).unwrap();
    let steps: Vec<f64> = (1..=12).map(|k| 0.25 * k as f64).collect();
    c.bench_function("offset_pocket_island_step_quarter", |b| {
        b.iter(|| offsets(black_box(&pocket), &axis, &steps, &opts).unwrap())
    });
    // The command's work on the pocket, then with its DXF or SVG paths written.
    let pocket_read =
        curvekit::io::parse_region("pocket.json", None, POCKET.as_bytes(), None).unwrap();
    let step = curvekit::commands::Distances::Step(0.25);
    let command = || {
        curvekit::commands::offset(&pocket_read, &step, &opts, &MedialOptions::default()).unwrap()
    };
    c.bench_function("offset_pocket_command", |b| b.iter(|| black_box(command())));
    c.bench_function("offset_pocket_command_dxf", |b| {
        b.iter(|| black_box(offsets_dxf(&command(), Some("mm")).unwrap()))
    });
    c.bench_function("offset_pocket_command_svg_paths", |b| {
        b.iter(|| black_box(offsets_svg(&command(), Some("mm")).unwrap()))
    });
    let chain = Region::new(bezier_chain(100), Vec::new()).unwrap();
    let axis = medial_axis(&chain, &MedialOptions::default()).unwrap();
    let widest = axis.nodes.iter().map(|n| n.radius).fold(0.0, f64::max);
    let twenty: Vec<f64> = (1..=20).map(|k| widest * k as f64 / 21.0).collect();
    c.bench_function("offset_bezier_chain_100_twenty", |b| {
        b.iter(|| offsets(black_box(&chain), &axis, &twenty, &opts).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = offset
}
criterion_main!(benches);
