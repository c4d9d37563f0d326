//! The medial-axis section of `curvekit demo`: the skeletons of the shipped pockets and
//! outlines (embedded), with their figures.

use super::demo::{embedded_input, failure, EmbeddedInput};
use super::medial::axis_figure;
use super::offset::figure as offset_figure;
use super::{write_file, Common, Failure};
use curvekit::io::{parse_region, Curve, CurveKind};
use curvekit::medial::{medial_axis, MedialAxis, MedialOptions, NodeKind};
use curvekit::offset::{offsets, OffsetOptions};
use numeric::certificate::Verdict;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::Path;

const REGIONS: &[EmbeddedInput] = &[
    embedded_input!("medial-region-pocket", "region-pocket.json"),
    embedded_input!("medial-drawing-pocket", Svg, "drawing-pocket.svg"),
    embedded_input!("medial-drawing-glyph-d", Svg, "drawing-glyph-d.svg"),
    embedded_input!("medial-drawing-plate", Dxf, "drawing-plate.dxf"),
    embedded_input!("medial-periodic-cubic", "periodic_cubic.json"),
];

/// Pocketing passes drawn per example: offsets at every multiple of the widest inscribed
/// disk's radius over this.
const PASSES: f64 = 6.0;

/// One example's results.
pub(super) struct MedialRow {
    name: &'static str,
    result: Result<MedialAxis, String>,
    svg: String,
    /// The pocketing offsets (loops per pass), and their figure.
    pocketing: Result<Vec<usize>, String>,
    pocketing_svg: String,
}

/// Runs every example, writing its figure into `out`.
pub(super) fn rows(out: &Path, common: &Common) -> Result<Vec<MedialRow>, Failure> {
    REGIONS
        .iter()
        .map(|&(name, format, text)| {
            let curve: Curve =
                parse_region(&format!("demo:{name}"), format, text.as_bytes(), None)?;
            let opts = MedialOptions {
                settings: common.options()?.settings,
                ..MedialOptions::default()
            };
            let result = match &curve.shape {
                CurveKind::Region(r) => medial_axis(r, &opts).map_err(|e| e.to_string()),
                _ => Err("not a region".to_string()),
            };
            let svg = out.join(format!("{name}.svg"));
            if let Ok(axis) = &result {
                write_file(&svg, axis_figure(&curve, axis))?;
            }
            let pocketing_svg = out.join(format!("{}.svg", name.replace("medial-", "pocketing-")));
            let pocketing = match (&result, &curve.shape) {
                (Ok(axis), CurveKind::Region(r)) => {
                    let widest = axis.nodes.iter().map(|n| n.radius).fold(0.0, f64::max);
                    let step = widest / PASSES;
                    let distances: Vec<f64> =
                        (1..PASSES as usize).map(|k| k as f64 * step).collect();
                    match offsets(r, axis, &distances, &OffsetOptions::default()) {
                        Ok(found) => {
                            write_file(&pocketing_svg, offset_figure(&curve, &found))?;
                            Ok(found.offsets.iter().map(|o| o.loops.len()).collect())
                        }
                        Err(e) => Err(e.to_string()),
                    }
                }
                (Err(e), _) => Err(e.clone()),
                _ => Err("not a region".to_string()),
            };
            Ok(MedialRow {
                name,
                result,
                svg: svg.display().to_string(),
                pocketing,
                pocketing_svg: pocketing_svg.display().to_string(),
            })
        })
        .collect()
}

fn count(a: &MedialAxis, k: NodeKind) -> usize {
    a.nodes.iter().filter(|n| n.kind == k).count()
}

/// The table of the section.
pub(super) fn table(rows: &[MedialRow]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\n{:<24} {:>5} {:>5} {:>9} {:>4} {:>7} {:>6} {:>9}  pocketing loops per pass",
        "medial axis", "nodes", "edges", "junctions", "ends", "corners", "cycles", "complete",
    );
    for r in rows {
        match &r.result {
            Ok(a) => {
                let passes = match &r.pocketing {
                    Ok(loops) => format!("{loops:?}"),
                    Err(e) => format!("failed: {e}"),
                };
                let _ = writeln!(
                    s,
                    "{:<24} {:>5} {:>5} {:>9} {:>4} {:>7} {:>6} {:>9}  {passes}",
                    r.name,
                    a.nodes.len(),
                    a.edges.len(),
                    count(a, NodeKind::Junction),
                    count(a, NodeKind::End),
                    count(a, NodeKind::Corner),
                    (a.edges.len() + 1).saturating_sub(a.nodes.len()),
                    if a.complete { "yes" } else { "no" }
                );
            }
            Err(e) => {
                let _ = writeln!(s, "{:<24} failed: {e}", r.name);
            }
        }
    }
    s
}

/// The failures of the section, one line each.
pub(super) fn errors(rows: &[MedialRow]) -> Vec<String> {
    rows.iter()
        .filter_map(|r| failure(r.name, "medial", &r.result))
        .collect()
}

/// The section of the JSON document.
pub(super) fn json(rows: &[MedialRow]) -> Value {
    rows.iter()
        .map(|r| {
            let result = match &r.result {
                Ok(a) => json!({
                    "nodes": a.nodes.len(),
                    "edges": a.edges.len(),
                    "junctions": count(a, NodeKind::Junction),
                    "complete": a.complete,
                    "certified": a.certified(),
                }),
                Err(e) => json!({ "error": e }),
            };
            let pocketing = match &r.pocketing {
                Ok(loops) => json!({ "loops_per_pass": loops, "svg": r.pocketing_svg }),
                Err(e) => json!({ "error": e }),
            };
            json!({ "name": r.name, "medial": result, "svg": r.svg, "pocketing": pocketing })
        })
        .collect()
}
