//! The profile section of `curvekit demo`: part outlines with corners, from curve files and
//! drawings (embedded), with their antipodal pairs (corner pairs included), families,
//! inflections and corners.

use super::demo::{embedded_input, failure, EmbeddedInput};
use super::report::antipodal_figure;
use super::{write_file, Common, Failure};
use antipodal::Antipodal;
use curvekit::commands::CurveSummary;
use curvekit::io::{parse_curve, parse_drawing, Curve, CurveKind};
use numeric::certificate::Verdict;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::Path;

/// The examples: curve files, then drawings as design tools write them.
const PROFILES: &[EmbeddedInput] = &[
    embedded_input!("profile-cam", "profile-cam.json"),
    embedded_input!("profile-bracket", "profile-bracket.json"),
    embedded_input!("profile-rounded-slot", "profile-rounded-slot.json"),
    embedded_input!("drawing-glyph-d", Svg, "drawing-glyph-d.svg"),
    embedded_input!("drawing-pocket", Svg, "drawing-pocket.svg"),
    embedded_input!("drawing-gear", Svg, "drawing-gear.svg"),
    embedded_input!("drawing-bracket", Dxf, "drawing-bracket.dxf"),
    embedded_input!("drawing-plate", Dxf, "drawing-plate.dxf"),
];

/// One example's results.
pub(super) struct ProfileRow {
    name: &'static str,
    curve: Curve,
    result: Result<Antipodal, String>,
    svg: String,
}

/// Runs every profile example, writing its figure into `out`.
pub(super) fn rows(out: &Path, common: &Common) -> Result<Vec<ProfileRow>, Failure> {
    PROFILES
        .iter()
        .map(|&(name, format, text)| {
            let file = format!("demo:{name}");
            // (A drawing's first profile: the outer contour of the glyph and the pocket.)
            let curve = match format {
                None => parse_curve(&file, text)?,
                Some(f) => parse_drawing(&file, f, text.as_bytes(), Some(0))?,
            };
            let result = match &curve.shape {
                CurveKind::Profile(p) => {
                    antipodal::antipodal(p.as_ref(), &common.options()?).map_err(|e| e.to_string())
                }
                _ => Err("not a profile".to_string()),
            };
            let svg = out.join(format!("{name}.svg"));
            if let Ok(r) = &result {
                let title = format!(
                    "demo {name} — antipodal: {} pairs, {} families, {} corners",
                    r.pairs.len(),
                    r.families.len(),
                    r.corner_list().len()
                );
                write_file(&svg, antipodal_figure(&curve, r, title))?;
            }
            Ok(ProfileRow {
                name,
                curve,
                result,
                svg: svg.display().to_string(),
            })
        })
        .collect()
}

/// The table of the profile section.
pub(super) fn table(rows: &[ProfileRow]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\n{:<22} {:>8} {:>7} {:>11} {:>5} {:>12} {:>8} {:>9}",
        "profile",
        "segments",
        "corners",
        "inflections",
        "pairs",
        "corner pairs",
        "families",
        "certified"
    );
    for r in rows {
        let segments = match &r.curve.shape {
            CurveKind::Profile(p) => p.segments().len(),
            _ => 0,
        };
        match &r.result {
            Ok(a) => {
                let corner_pairs = a.pairs.iter().filter(|p| p.has_corner()).count();
                let _ = writeln!(
                    s,
                    "{:<22} {:>8} {:>7} {:>11} {:>5} {:>12} {:>8} {:>9}",
                    r.name,
                    segments,
                    a.corner_list().len(),
                    a.inflections.len(),
                    a.pairs.len(),
                    corner_pairs,
                    a.families.len(),
                    if a.certified() { "yes" } else { "no" }
                );
            }
            Err(e) => {
                let _ = writeln!(s, "{:<22} {:>8} failed: {e}", r.name, segments);
            }
        }
    }
    s
}

/// The failures of the profile section, one line each.
pub(super) fn errors(rows: &[ProfileRow]) -> Vec<String> {
    rows.iter()
        .filter_map(|r| failure(r.name, "antipodal", &r.result))
        .collect()
}

/// The profile section of the JSON document.
pub(super) fn json(rows: &[ProfileRow]) -> Value {
    rows.iter()
        .map(|r| {
            let result = match &r.result {
                Ok(a) => json!({
                    "pairs": a.pairs.len(),
                    "corner_pairs": a.pairs.iter().filter(|p| p.has_corner()).count(),
                    "families": a.families.len(),
                    "inflections": a.inflections.len(),
                    "corners": a.corner_list().len(),
                    "certified": a.certified(),
                }),
                Err(e) => json!({ "error": e }),
            };
            json!({
                "name": r.name,
                "curve": CurveSummary::of(&r.curve),
                "antipodal": result,
                "svg": r.svg,
            })
        })
        .collect()
}
