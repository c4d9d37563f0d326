//! Instruction counts of `antipodal`, `medial_axis` and `grasps` runs, for callgrind: the
//! machine's timings are noisy, the number of instructions one run executes is not.
//! `count-instructions.sh` (beside this file) runs it under callgrind and prints instructions
//! per run; run alone (`cargo bench --bench instructions`) it times the same runs.
//!
//! `instructions FILE MODE N`: `N` runs of `antipodal` on the curve of `FILE`, either `warm`
//! (on one prepared curve, after a first run) or `cold` (preparing the curve read and answering
//! once, each time), or `medial-warm` / `medial-cold`: the medial axis of the file read as a
//! region (warm: the region built once; cold: reading the file's bytes each time). The runs are
//! in the functions `measured` and `measured_medial`, which callgrind's `--toggle-collect`
//! isolates. `instructions grasps polygons|outlines N`: `N` runs of the grasp benchmark's batch
//! of 100 outlines, as polygons or periodic cubics, on one thread (`measured_grasps`).
#![allow(missing_docs, clippy::unwrap_used)]

use antipodal::{prepare, Options, PlaneCurve};
use curvekit::io::{parse_region, CurveKind};
use curvekit::medial::{medial_axis, MedialOptions};
use std::hint::black_box;
use std::time::Instant;

#[path = "common/outlines.rs"]
mod outlines;
use outlines::{cubics, outline_points, polygons};

#[inline(never)]
fn measured(curve: &dyn PlaneCurve, warm: bool, n: usize) {
    let opts = Options::default();
    if warm {
        let p = prepare(curve);
        black_box(p.antipodal(&opts).unwrap());
        for _ in 0..n {
            black_box(p.antipodal(black_box(&opts)).unwrap());
        }
    } else {
        for _ in 0..n {
            black_box(prepare(black_box(curve)).antipodal(&opts).unwrap());
        }
    }
}

/// The region of a file's bytes, as the tool reads it.
fn region_of(file: &str, bytes: &[u8]) -> curve::Region {
    match parse_region(file, None, bytes, None).unwrap().shape {
        CurveKind::Region(r) => *r,
        _ => panic!("{file}: not one region"),
    }
}

#[inline(never)]
fn measured_medial(file: &str, bytes: &[u8], warm: bool, n: usize) {
    let opts = MedialOptions::default();
    if warm {
        let region = region_of(file, bytes);
        black_box(medial_axis(&region, &opts).unwrap());
        for _ in 0..n {
            black_box(medial_axis(black_box(&region), &opts).unwrap());
        }
    } else {
        for _ in 0..n {
            black_box(medial_axis(&region_of(file, black_box(bytes)), &opts).unwrap());
        }
    }
}

/// `n` runs of the grasps of the grasp benchmark's batch of 100 outlines, as polygons or as
/// periodic cubics, one after another on one thread (cold: each curve prepared and answered).
#[inline(never)]
fn measured_grasps<T>(items: &[T], n: usize)
where
    for<'a> &'a T: Into<curve::Boundary<'a>>,
{
    let opts = grasp::GraspOptions::friction(0.3);
    for _ in 0..n {
        for item in items {
            black_box(grasp::grasps(black_box(item), &opts).unwrap());
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let [file, mode, n] = args.as_slice() else {
        // (`cargo bench` runs every bench target without arguments: nothing to do.)
        eprintln!(
            "usage: instructions FILE warm|cold|medial-warm|medial-cold N\n       \
             instructions grasps polygons|outlines N"
        );
        return;
    };
    let n: usize = n.parse().unwrap();
    let t = Instant::now();
    if file == "grasps" {
        let outlines = outline_points();
        if mode == "polygons" {
            measured_grasps(&polygons(&outlines), n);
        } else {
            measured_grasps(&cubics(&outlines), n);
        }
    } else if let Some(medial_mode) = mode.strip_prefix("medial-") {
        let text = std::fs::read_to_string(file).unwrap();
        // One core, as the medial benchmarks run.
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build_global();
        measured_medial(file, text.as_bytes(), medial_mode == "warm", n);
    } else {
        let text = std::fs::read_to_string(file).unwrap();
        let curve = curvekit::io::parse_curve(file, &text).unwrap();
        measured(curve.plane_curve(), mode == "warm", n);
    }
    eprintln!(
        "{mode}: {:.2} µs per run",
        t.elapsed().as_secs_f64() * 1e6 / n as f64
    );
}
