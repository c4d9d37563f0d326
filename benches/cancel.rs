//! How soon long work stops once cancelled (issue 39: within 0.1 s), one core: each input's
//! medial axis, and its offsets, run under a watch that another thread cancels at a tenth,
//! two tenths, … of the run's uncancelled time; the time from the cancel to the return is
//! the latency. Printed as a table (worst and median latency per input, and the stage the
//! worst fell in), since it is the worst case that matters, not a mean.
//!
//! `cargo bench --bench cancel [-- TEXT]`: the rows whose name holds TEXT, or all.
#![allow(missing_docs, clippy::unwrap_used)]

use curve::watch::Watch;
use curve::Region;
use curvekit::medial::{medial_axis, MedialAxis, MedialOptions};
use curvekit::offset::{offsets, OffsetOptions};
use std::sync::Arc;
use std::time::{Duration, Instant};

use testkit::outlines::{dense_outline, polygon, rounded_outline, star_polygon};

/// Cancels at each of these shares of the uncancelled run.
const SHARES: usize = 10;

/// A closed polygon through `points`, as a region.
fn region(points: &[[f64; 2]]) -> Region {
    Region::new(polygon(points), vec![]).unwrap()
}

/// The worst and the median latency of `work` cancelled at each share of its time, the
/// stage the worst fell in, and the uncancelled time. `work` answers whether it was
/// cancelled.
fn latency(work: &(dyn Fn() -> bool + Sync)) -> (Duration, Duration, &'static str, Duration) {
    let start = Instant::now();
    assert!(!work(), "uncancelled work says it was cancelled");
    let total = start.elapsed();
    let mut seen: Vec<(Duration, &'static str)> = Vec::new();
    for k in 1..SHARES {
        let watch = Arc::new(Watch::default());
        let at = total.mul_f64(k as f64 / SHARES as f64);
        let (stopped, cancelled_at, stage) = std::thread::scope(|scope| {
            let canceller = {
                let watch = Arc::clone(&watch);
                scope.spawn(move || {
                    std::thread::sleep(at);
                    let stage = watch.progress().stage;
                    watch.cancel();
                    (Instant::now(), stage)
                })
            };
            // (Work that does not look at its watch runs to its end: its latency is the
            // rest of its time.)
            let _ = watch.run(work);
            let stopped = Instant::now();
            let (cancelled_at, stage) = canceller.join().unwrap();
            (stopped, cancelled_at, stage)
        });
        // (Work that ended before the cancel has no latency to show.)
        if stopped > cancelled_at {
            seen.push((stopped - cancelled_at, stage));
        }
    }
    seen.sort();
    let (worst, stage) = seen.last().copied().unwrap_or_default();
    let median = seen.get(seen.len() / 2).map_or(Duration::ZERO, |s| s.0);
    (worst, median, stage, total)
}

fn main() {
    // One core, as every other figure is given.
    let _ = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global();
    let opts = MedialOptions::default();
    let axis_cancelled = |r: &Region| match medial_axis(r, &opts) {
        Err(curvekit::medial::Error::Cancelled) => true,
        found => {
            found.unwrap();
            false
        }
    };
    let inputs: Vec<(String, Region)> = vec![
        (
            "star polygon, 1,600 lines".into(),
            region(&star_polygon(1600)),
        ),
        (
            "CAD outline, 5,000 lines".into(),
            region(&dense_outline(5000)),
        ),
        (
            "CAD outline, 1,500 lines at 1e-6".into(),
            rounded_outline(1500),
        ),
    ];
    println!("| work | uncancelled | worst latency | median | stage of the worst |");
    println!("| --- | ---: | ---: | ---: | --- |");
    let row = |name: &str, (worst, median, stage, total): (Duration, Duration, &str, Duration)| {
        println!(
            "| {name} | {:.1} ms | {:.2} ms | {:.2} ms | {stage} |",
            total.as_secs_f64() * 1e3,
            worst.as_secs_f64() * 1e3,
            median.as_secs_f64() * 1e3
        );
    };
    // (Cargo passes `--bench` too: the filter is the first argument not a flag.)
    let filter = std::env::args().skip(1).find(|a| !a.starts_with("--"));
    let chosen = |name: &str| filter.as_deref().is_none_or(|f| name.contains(f));
    for (name, r) in &inputs {
        let name = format!("medial axis, {name}");
        if chosen(&name) {
            row(&name, latency(&|| axis_cancelled(r)));
        }
    }
    let name = "offsets at step 0.05, star polygon, 400 lines";
    if !chosen(name) {
        return;
    }
    // Offsets of the star of 400 lines at ten steps of 0.05 (as the peers bench takes them),
    // its axis computed beforehand.
    let star = region(&star_polygon(400));
    let axis: MedialAxis = medial_axis(&star, &opts).unwrap();
    let steps: Vec<f64> = (1..=10).map(|k| 0.05 * k as f64).collect();
    let offset_cancelled = || match offsets(&star, &axis, &steps, &OffsetOptions::default()) {
        Err(curvekit::offset::Error::Cancelled) => true,
        found => {
            found.unwrap();
            false
        }
    };
    row(name, latency(&offset_cancelled));
}
