//! Reading real drawings (issue 38): the corpus sample's SVG and DXF files read as regions, as
//! `medial` and `offset` read them, in bytes per second; and on the sample's median file (by
//! size) reading against the medial axis it is read for. Target: reading at most 10 % of
//! `medial` on the median file.
#![allow(missing_docs, clippy::unwrap_used)]

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use curvekit::io::{parse_region, DrawingFormat};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// The sample's drawings of one format, with their bytes.
fn drawings(format: DrawingFormat) -> Vec<(String, Vec<u8>)> {
    let ext = match format {
        DrawingFormat::Svg => "svg",
        DrawingFormat::Dxf => "dxf",
    };
    let mut found = Vec::new();
    let mut dirs = vec![PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fixtures/corpus")];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == ext) {
                found.push((path.display().to_string(), std::fs::read(&path).unwrap()));
            }
        }
    }
    found.sort();
    // (Only those read as regions: the invalid ones are refused at once.)
    found.retain(|(name, bytes)| parse_region(name, Some(format), bytes, None).is_ok());
    found
}

fn format_of(name: &str) -> DrawingFormat {
    if Path::new(name).extension().is_some_and(|e| e == "dxf") {
        DrawingFormat::Dxf
    } else {
        DrawingFormat::Svg
    }
}

fn reading(c: &mut Criterion) {
    let mut g = c.benchmark_group("reading");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    let mut all = Vec::new();
    for (label, format) in [("svg", DrawingFormat::Svg), ("dxf", DrawingFormat::Dxf)] {
        let files = drawings(format);
        let bytes: usize = files.iter().map(|(_, b)| b.len()).sum();
        g.throughput(Throughput::Bytes(bytes as u64));
        g.bench_function(format!("{label} sample ({} files)", files.len()), |b| {
            b.iter(|| {
                for (name, bytes) in &files {
                    black_box(parse_region(name, Some(format), black_box(bytes), None).unwrap());
                }
            })
        });
        all.extend(files);
    }
    // The median file by size, read, and its medial axis.
    all.sort_by_key(|(_, b)| b.len());
    let (name, bytes) = all[all.len() / 2].clone();
    let format = format_of(&name);
    let short = Path::new(&name)
        .file_name()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    g.throughput(Throughput::Bytes(bytes.len() as u64));
    g.bench_function(format!("median file {short}: read"), |b| {
        b.iter(|| black_box(parse_region(&name, Some(format), black_box(&bytes), None).unwrap()))
    });
    let region = parse_region(&name, Some(format), &bytes, None).unwrap();
    let opts = medial::MedialOptions::default();
    g.bench_function(format!("median file {short}: medial"), |b| {
        b.iter(|| black_box(curvekit::commands::medial(black_box(&region), &opts).unwrap()))
    });
    g.finish();
}

criterion_group!(benches, reading);
criterion_main!(benches);
