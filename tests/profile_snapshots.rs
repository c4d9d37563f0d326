//! Snapshots of `curvekit antipodal --json` for every closed profile among the fixtures
//! (numbers rounded to 9 significant digits): pairs with their corners, families with their
//! end points, inflections and corners.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit_json, fixtures_dir, json_files, rounded};
use curvekit::curve::ParamCurve;

#[test]
fn antipodal_pairs_of_every_closed_profile() {
    let mut seen = 0;
    for path in json_files(&fixtures_dir()) {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let curve = curvekit::io::read_curve(&path).unwrap();
        let closed = match &curve.shape {
            curvekit::io::CurveKind::Profile(p) => p.is_closed(),
            _ => continue,
        };
        // (An open chain is refused by `antipodal`, tested in cli_errors.)
        if !closed {
            continue;
        }
        let mut out = curvekit_json(&["antipodal", path.to_str().unwrap()]);
        out["curve"]["file"] = serde_json::json!(format!("{name}.json"));
        insta::assert_json_snapshot!(format!("antipodal-{name}"), rounded(&out));
        seen += 1;
    }
    assert!(seen >= 3, "{seen} closed profiles");
}

/// The same for the drawings among the fixtures (SVG and DXF), each profile of each file.
#[test]
fn antipodal_pairs_of_every_drawing() {
    let mut seen = 0;
    let mut files: Vec<_> = std::fs::read_dir(fixtures_dir())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| matches!(p.extension().and_then(|e| e.to_str()), Some("svg" | "dxf")))
        .collect();
    files.sort();
    for path in files {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        for pick in 0.. {
            let Ok(curve) = curvekit::io::read_curve_picked(&path, Some(pick)) else {
                break;
            };
            let curvekit::io::CurveKind::Profile(p) = &curve.shape else {
                break;
            };
            if !p.is_closed() {
                continue;
            }
            let pick = pick.to_string();
            let mut out = curvekit_json(&["antipodal", "--pick", &pick, path.to_str().unwrap()]);
            out["curve"]["file"] = serde_json::json!(name);
            insta::assert_json_snapshot!(format!("drawing-{name}-{pick}"), rounded(&out));
            seen += 1;
        }
    }
    assert!(seen >= 4, "{seen} drawn profiles");
}
