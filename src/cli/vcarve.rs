//! `curvekit vcarve`: the tool paths of a V-bit over the medial axis, as text, JSON, DXF or
//! a figure.

use super::report::{describe, draw_curve, verdict_lines};
use super::{write_export, Common, Failure};
use curvekit::commands;
use curvekit::export::dxf_file;
use curvekit::io::Curve;
use curvekit::offset::{OffsetOptions, VCarve, VCarveOptions};
use curvekit::svg::{scale_color, Figure, Mark, BOUNDARY, DOT};
use numeric::certificate::Verdict;
use std::fmt::Write as _;
use std::path::Path;

/// Points drawn per arc of a flat pass in the figure.
const ARC_POINTS: usize = 64;

/// Runs `vcarve` on the region at `path` with a bit of included angle `angle` (degrees), at
/// most `max_depth` deep.
pub(super) fn run(
    path: &Path,
    (angle, max_depth): (f64, Option<f64>),
    chord_tol: f64,
    dxf: Option<&Path>,
    common: &Common,
) -> Result<(), Failure> {
    let medial_opts = common.axis_options(chord_tol, (false, false))?;
    let opts = VCarveOptions {
        angle,
        max_depth,
        offset: OffsetOptions {
            settings: medial_opts.settings,
        },
    };
    commands::validate_vcarve_options(&opts)?;
    let curve = common.read_region(path)?;
    let (found, stats) = common.computed(|| commands::vcarve(&curve, &opts, &medial_opts))?;
    common.draw(|| Ok(figure(&curve, &found)))?;
    write_export(dxf, || dxf_file::vcarve_dxf(&found, curve.units()))?;
    common.report(&found, &[&curve], stats.as_ref(), || {
        text(&curve, &found, stats.as_ref())
    })
}

/// The deepest point of the paths (0 for none).
fn deepest(found: &VCarve) -> f64 {
    found
        .paths
        .iter()
        .flat_map(|p| p.xyz.iter().map(|q| q[2]))
        .fold(0.0, f64::min)
}

/// The figure: the region, the paths coloured by depth (surface blue to deepest yellow), the
/// flat passes in grey.
pub(super) fn figure(region: &Curve, found: &VCarve) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, region);
    let deepest = deepest(found);
    for p in &found.paths {
        // (Each step in the shade of its deeper end.)
        for w in p.xyz.windows(2) {
            let z = w[0][2].min(w[1][2]);
            let t = if deepest < 0.0 { z / deepest } else { 0.0 };
            fig.colored(vec![[w[0][0], w[0][1]], [w[1][0], w[1][1]]], scale_color(t));
        }
        if let [q] = p.xyz.as_slice() {
            fig.dot([q[0], q[1]]);
            fig.legend(
                Mark::Dot(DOT.into()),
                "a plunge: the centre of a round part",
            );
        }
    }
    for l in &found.flats {
        fig.thin(l.polyline(ARC_POINTS), "#777777");
    }
    fig.title(format!(
        "{} — vcarve with a {}° bit: {} paths{}",
        region.file,
        found.angle,
        found.paths.len(),
        found
            .max_depth
            .map_or(String::new(), |h| format!(", at most {h} deep"))
    ));
    fig.status(found.certified(), found.reason().as_deref());
    fig.color_bar("depth", 0.0, -deepest, region.units());
    fig.legend(Mark::Line(BOUNDARY.into(), 1.6), "boundary");
    fig.legend(
        Mark::Line(scale_color(0.6), 1.4),
        "tool path, coloured by depth",
    );
    if !found.flats.is_empty() {
        fig.legend(
            Mark::Line("#777777".into(), 0.6),
            "flat pass at the deepest cut",
        );
    }
    fig.render()
}

/// The readable report.
fn text(curve: &Curve, found: &VCarve, stats: Option<&commands::Stats>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "region:      {} ({})", curve.file, describe(curve));
    let points: usize = found.paths.iter().map(|p| p.xyz.len()).sum();
    let _ = writeln!(
        s,
        "paths:       {} ({points} points), deepest {}",
        found.paths.len(),
        deepest(found)
    );
    match found.max_depth {
        Some(h) if !found.flats.is_empty() => {
            let _ = writeln!(
                s,
                "flats:       {} loops at depth {}",
                found.flats.len(),
                -h
            );
        }
        Some(_) => {
            let _ = writeln!(s, "flats:       none (the axis never gets that deep)");
        }
        None => {}
    }
    verdict_lines(&mut s, found, found.complete, stats);
    s
}
