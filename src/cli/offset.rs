//! `curvekit offset`: the inward (or outward) offsets of a region at one or several distances, as text,
//! JSON (closed profile documents) or a figure.

use super::report::{describe, draw_curve, verdict_lines};
use super::{Common, Failure, OutFiles};
use curvekit::commands::{self, Distances};
use curvekit::export::{dxf_file, svg_paths};
use curvekit::io::Curve;
use curvekit::offset::{OffsetOptions, Offsets};
use curvekit::svg::{scale_color, Figure, Mark, BOUNDARY};
use numeric::certificate::Verdict;
use std::fmt::Write as _;
use std::path::Path;

/// Points drawn per arc of an offset in the figure.
const ARC_POINTS: usize = 64;

/// Runs `offset` on the region at `path` (outward from the exterior axis with `outward`).
pub(super) fn run(
    path: &Path,
    distances: &Distances,
    (chord_tol, outward): (f64, bool),
    out: &OutFiles,
    common: &Common,
) -> Result<(), Failure> {
    let medial_opts = common.axis_options(chord_tol, (false, outward))?;
    commands::validate_offset(distances, outward)?;
    let opts = OffsetOptions {
        settings: medial_opts.settings,
    };
    let curve = common.read_region(path)?;
    let (found, stats) =
        common.computed(|| commands::offset(&curve, distances, &opts, &medial_opts))?;
    common.draw(|| Ok(figure(&curve, &found)))?;
    out.write(
        &found,
        curve.units(),
        dxf_file::offsets_dxf,
        svg_paths::offsets_svg,
    )?;
    common.report(&found, &[&curve], stats.as_ref(), || {
        text(&curve, &found, stats.as_ref())
    })
}

/// The figure of a region's offsets: the region, and each offset's loops coloured by its
/// distance (the scale of the medial axis's figure, from 0 to the largest distance, with its
/// colour bar); the header names the file and says whether the offsets are certified.
pub(super) fn figure(region: &Curve, found: &Offsets) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, region);
    let largest = found.offsets.iter().map(|o| o.distance).fold(0.0, f64::max);
    for o in &found.offsets {
        let color = scale_color(if largest > 0.0 {
            o.distance / largest
        } else {
            0.0
        });
        for l in &o.loops {
            fig.colored(l.polyline(ARC_POINTS), color.clone());
        }
    }
    let loops: usize = found.offsets.iter().map(|o| o.loops.len()).sum();
    fig.title(format!(
        "{} — offset: {} distances, {loops} loops",
        region.file,
        found.offsets.len()
    ));
    fig.status(found.certified(), found.reason().as_deref());
    fig.color_bar("distance", 0.0, largest, region.units());
    fig.legend(Mark::Line(BOUNDARY.into(), 1.6), "boundary");
    if loops > 0 {
        fig.legend(
            Mark::Line(scale_color(0.6), 1.4),
            "offset loops, coloured by distance",
        );
    }
    fig.render()
}

/// The readable report: per distance, its loops and their pieces.
fn text(curve: &Curve, found: &Offsets, stats: Option<&commands::Stats>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "region:      {} ({})", curve.file, describe(curve));
    for o in &found.offsets {
        let pieces: usize = o.loops.iter().map(|l| l.segments.len()).sum();
        let _ = writeln!(
            s,
            "distance {:<10} {} loops, {pieces} pieces",
            o.distance,
            o.loops.len()
        );
    }
    verdict_lines(&mut s, found, found.complete, stats);
    s
}
