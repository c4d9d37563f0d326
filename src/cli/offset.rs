//! `curvekit offset`: the inward (or outward) offsets of a region at one or several distances, as text,
//! JSON (closed profile documents) or a figure.

use super::report::{draw_curve, time_line};
use super::{print_out, timing, write_file, Common, Failure};
use curvekit::commands::{self, Distances};
use curvekit::io::{read_region, Curve};
use curvekit::medial::MedialOptions;
use curvekit::offset::{OffsetOptions, Offsets};
use curvekit::svg::Figure;
use std::fmt::Write as _;
use std::path::Path;

/// Points drawn per arc of an offset in the figure.
const ARC_POINTS: usize = 64;

/// Runs `offset` on the region at `path` (outward from the exterior axis with `outward`).
pub(super) fn run(
    path: &Path,
    distances: &Distances,
    (chord_tol, outward): (f64, bool),
    common: &Common,
) -> Result<(), Failure> {
    let medial_opts = MedialOptions {
        tol: common.tol,
        chord_tol,
        fit: false,
        exterior: outward,
    };
    commands::validate_medial_options(&medial_opts)?;
    commands::validate_distances(distances)?;
    let opts = OffsetOptions { chord_tol };
    let curve = read_region(path, common.pick)?;
    let compute = || commands::offset(&curve, distances, &opts, &medial_opts);
    let found = compute()?;
    let stats = common.time.then(|| timing::measure(compute));
    if let Some(svg) = &common.svg {
        write_file(svg, &figure(&curve, &found))?;
    }
    print_out(&if common.json {
        commands::json_document(&found, &[&curve], stats.as_ref())
    } else {
        text(&curve.file, &found, stats.as_ref())
    })
}

/// The figure of a region's offsets: the region and each offset loop.
pub(super) fn figure(region: &Curve, found: &Offsets) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, region);
    for o in &found.offsets {
        for l in &o.loops {
            fig.thin(l.polyline(ARC_POINTS), "#c0392b");
        }
    }
    fig.title(format!("{}: {} offsets", region.file, found.offsets.len()));
    fig.render()
}

/// The readable report: per distance, its loops and their pieces.
fn text(file: &str, found: &Offsets, stats: Option<&commands::Stats>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "region:      {file}");
    for o in &found.offsets {
        let pieces: usize = o.loops.iter().map(|l| l.segments.len()).sum();
        let _ = writeln!(
            s,
            "distance {:<10} {} loops, {pieces} pieces",
            o.distance,
            o.loops.len()
        );
    }
    let _ = writeln!(s, "certified:   {}", found.certified);
    if let Some(why) = &found.reason {
        let _ = writeln!(s, "  (why: {why})");
    }
    let _ = writeln!(s, "complete:    {}", found.complete);
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}
