//! The grasp section of `curvekit demo`: the force-closure grasps of two of Jia's smooth
//! shapes at the friction the papers' examples take, with their figures.

use super::demo::{failure, fixture_text};
use super::grasps::{figure, title};
use super::{write_file, Common, Failure};
use curvekit::commands::{self, CommandFamily};
use curvekit::grasp::{GraspOptions, Grasps};
use curvekit::io::parse_curve;
use numeric::tolerance::DEFAULT_CHORD_TOL;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::Path;

/// The friction coefficient of the examples (μ = 0.3: a cone of about 17°).
const FRICTION: f64 = 0.3;

/// Name and file text of each example: an elliptic lemniscate (four regions, each holding an
/// antipodal pair) and a curve with three convexities (regions without any antipodal pair).
const SHAPES: &[(&str, &str)] = &[
    (
        "grasps-elliptic-lemniscate",
        fixture_text!("elliptic_lemniscate.json"),
    ),
    (
        "grasps-convexities-m3",
        fixture_text!("convexities_m3.json"),
    ),
];

/// One example's result and its figure.
pub(super) struct GraspRow {
    name: &'static str,
    result: Result<Grasps, String>,
    svg: String,
}

/// Runs every example, writing its figure into `out`.
pub(super) fn rows(out: &Path, common: &Common) -> Result<Vec<GraspRow>, Failure> {
    let opts = GraspOptions {
        settings: commands::settings(CommandFamily::Bisector, common.tol, DEFAULT_CHORD_TOL)?,
        ..GraspOptions::friction(FRICTION)
    };
    SHAPES
        .iter()
        .map(|&(name, text)| {
            let curve = parse_curve(&format!("demo:{name}"), text)?;
            let result = commands::grasps(&curve, &opts).map_err(|e| e.message());
            let svg = out.join(format!("{name}.svg"));
            if let Ok(found) = &result {
                let title = title(&format!("demo {name}"), found);
                write_file(&svg, figure(&curve, found, title))?;
            }
            Ok(GraspRow {
                name,
                result,
                svg: svg.display().to_string(),
            })
        })
        .collect()
}

/// The table of the section.
pub(super) fn table(rows: &[GraspRow]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\n{:<28} {:>8} {:>7} {:>13} {:>9} {:>9}",
        "grasps (μ = 0.3)", "regions", "contact", "best at pair", "certified", "complete"
    );
    for r in rows {
        match &r.result {
            Ok(g) => {
                let yes = |b: bool| if b { "yes" } else { "no" };
                let _ = writeln!(
                    s,
                    "{:<28} {:>8} {:>7} {:>13} {:>9} {:>9}",
                    r.name,
                    g.regions.len(),
                    g.regions.iter().filter(|x| x.contact.is_some()).count(),
                    antipodal_count(g),
                    yes(g.doubts.is_empty()),
                    yes(g.complete)
                );
            }
            Err(e) => {
                let _ = writeln!(s, "{:<28} failed: {e}", r.name);
            }
        }
    }
    s
}

/// The least friction below which a best grasp counts as an antipodal pair in the table:
/// rounding of the pairs' cone angles.
const ANTIPODAL_FRICTION: f64 = 1e-9;

/// The regions whose best grasp is an antipodal pair.
fn antipodal_count(g: &Grasps) -> usize {
    g.regions
        .iter()
        .filter(|r| r.best.min_friction < ANTIPODAL_FRICTION)
        .count()
}

/// The failures of the section, one line each.
pub(super) fn errors(rows: &[GraspRow]) -> Vec<String> {
    rows.iter()
        .filter_map(|r| failure(r.name, "grasps", &r.result))
        .collect()
}

/// The section of the JSON document.
pub(super) fn json(rows: &[GraspRow]) -> Value {
    rows.iter()
        .map(|r| {
            let result = match &r.result {
                Ok(g) => json!({
                    "regions": g.regions.len(),
                    "antipodal": antipodal_count(g),
                    "complete": g.complete,
                    "certified": g.doubts.is_empty(),
                }),
                Err(e) => json!({ "error": e }),
            };
            json!({ "name": r.name, "friction": FRICTION, "grasps": result, "svg": r.svg })
        })
        .collect()
}
