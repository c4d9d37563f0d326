//! `curvekit vcarve`: the contract's document, judged against the tool's own medial axis and
//! offsets (the swept cut is judged by the independent oracle in `corpus/oracle.py`), the
//! depth limit, the options refused, the DXF written.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit, curvekit_json, fixture};
use serde_json::Value;

fn xyz(doc: &Value) -> Vec<[f64; 3]> {
    doc["paths"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|p| p["xyz"].as_array().unwrap())
        .map(|q| {
            let q = q.as_array().unwrap();
            [0, 1, 2].map(|k| q[k].as_f64().unwrap())
        })
        .collect()
}

/// Every path point is an axis vertex at the depth its disk is cut from, and every axis
/// vertex is on a path: without a limit the paths are the axis, depth for radius.
#[test]
fn the_paths_are_the_axis_at_the_depth_of_its_disks() {
    let pocket = fixture("region-pocket.json");
    let doc = curvekit_json(&["vcarve", &pocket, "--angle", "90"]);
    assert_eq!(doc["angle"], 90.0);
    assert_eq!(doc["max_depth"], Value::Null);
    assert_eq!(doc["flats"].as_array().unwrap().len(), 0);
    assert_eq!(
        (doc["certified"].clone(), doc["complete"].clone()),
        (Value::Bool(true), Value::Bool(true))
    );
    assert!(doc["paths"]
        .as_array()
        .unwrap()
        .iter()
        .all(|p| p["part"] == 0));
    let axis = curvekit_json(&["medial", &pocket]);
    let mut vertices: Vec<[f64; 3]> = Vec::new();
    for e in axis["edges"].as_array().unwrap() {
        for (xy, r) in e["xy"]
            .as_array()
            .unwrap()
            .iter()
            .zip(e["radius"].as_array().unwrap())
        {
            let (x, y) = (xy[0].as_f64().unwrap(), xy[1].as_f64().unwrap());
            // (A 90° bit: the depth equals the radius.)
            vertices.push([x, y, -r.as_f64().unwrap()]);
        }
    }
    let points = xyz(&doc);
    let key = |p: &[f64; 3]| p.map(|v| (v * 1e9).round() as i64);
    let mut a: Vec<_> = points.iter().map(key).collect();
    let mut b: Vec<_> = vertices.iter().map(key).collect();
    a.sort_unstable();
    a.dedup();
    b.sort_unstable();
    b.dedup();
    assert_eq!(a, b);
    // Joined at their nodes: fewer paths than edges.
    assert!(doc["paths"].as_array().unwrap().len() < axis["edges"].as_array().unwrap().len());
}

/// A narrower bit cuts the same disks deeper, by the ratio of the half-angles' tangents.
#[test]
fn the_depth_scales_with_the_angle() {
    let pocket = fixture("region-pocket.json");
    let wide = xyz(&curvekit_json(&["vcarve", &pocket, "--angle", "90"]));
    let narrow = xyz(&curvekit_json(&["vcarve", &pocket, "--angle", "60"]));
    assert_eq!(wide.len(), narrow.len());
    let ratio = 45f64.to_radians().tan() / 30f64.to_radians().tan();
    for (w, n) in wide.iter().zip(&narrow) {
        assert_eq!([w[0], w[1]], [n[0], n[1]]);
        testkit::assert_near!(n[2], w[2] * ratio, 1e-12 * w[2].abs().max(1.0));
    }
}

/// With a depth limit no point is deeper, the paths stop at the limit's radius, and the flats
/// are the offset at that radius, loop for loop.
#[test]
fn a_depth_limit_clips_the_paths_onto_the_flat_pass() {
    let pocket = fixture("region-pocket.json");
    let (angle, depth) = (60.0f64, 3.0f64);
    let doc = curvekit_json(&["vcarve", &pocket, "--angle", "60", "--max-depth", "3"]);
    assert_eq!(doc["max_depth"], depth);
    let points = xyz(&doc);
    assert!(points.iter().all(|p| p[2] >= -depth));
    let at_limit = points
        .iter()
        .filter(|p| (p[2] + depth).abs() <= 1e-12 * depth)
        .count();
    assert!(at_limit >= 2, "the paths end on the flat pass");
    let radius = depth * (angle / 2.0).to_radians().tan();
    let offset = curvekit_json(&["offset", &pocket, "--distance", &radius.to_string()]);
    assert_eq!(doc["flats"], offset["offsets"][0]["loops"]);
    assert!(!doc["flats"].as_array().unwrap().is_empty());
    // Deeper than the axis goes: no flat.
    let deep = curvekit_json(&["vcarve", &pocket, "--angle", "60", "--max-depth", "100"]);
    assert!(deep["flats"].as_array().unwrap().is_empty());
    assert_eq!(
        xyz(&deep),
        xyz(&curvekit_json(&["vcarve", &pocket, "--angle", "60"]))
    );
}

/// A drawing of two parts: every path and flat says its part.
#[test]
fn the_parts_of_a_drawing_are_carved_each() {
    let plate = fixture("corpus/dxf/island_in_hole.dxf");
    let doc = curvekit_json(&["vcarve", &plate, "--angle", "90", "--max-depth", "9"]);
    let parts: std::collections::BTreeSet<i64> = doc["paths"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["part"].as_i64().unwrap())
        .collect();
    assert_eq!(parts.into_iter().collect::<Vec<_>>(), [0, 1]);
    let flats = doc["flats"].as_array().unwrap();
    assert!(!flats.is_empty() && flats.iter().all(|l| l["part"].is_i64()));
}

#[test]
fn options_out_of_range_are_usage_errors() {
    let pocket = fixture("region-pocket.json");
    for (args, named) in [
        (vec!["--angle", "0"], "--angle"),
        (vec!["--angle", "180"], "--angle"),
        (vec!["--angle", "-30"], "--angle"),
        (vec!["--angle", "NaN"], "--angle"),
        (vec!["--angle", "60", "--max-depth", "0"], "--max-depth"),
        (vec!["--angle", "60", "--max-depth", "-1"], "--max-depth"),
        (vec!["--angle", "60", "--max-depth", "inf"], "--max-depth"),
    ] {
        let mut all = vec!["vcarve", pocket.as_str()];
        all.extend(&args);
        let run = curvekit(&all);
        assert_eq!(run.code, 2, "{args:?}: {}", run.stderr);
        assert!(run.stderr.contains(named), "{args:?}: {}", run.stderr);
    }
    let run = curvekit(&["vcarve", &pocket]);
    assert_eq!(run.code, 2, "the angle is required");
}

/// The DXF holds the paths as 3D polylines and the flats at the limit's depth (ezdxf reads it
/// in the Python tests).
#[test]
fn the_dxf_holds_the_paths_and_the_flats() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("carve.dxf");
    let doc = curvekit_json(&[
        "vcarve",
        &fixture("region-pocket.json"),
        "--angle",
        "60",
        "--max-depth",
        "3",
        "--dxf",
        out.to_str().unwrap(),
    ]);
    let drawing = dxf::Drawing::load_file(&out).unwrap();
    let on = |layer: &str| {
        drawing
            .entities()
            .filter(|e| e.common.layer == layer)
            .count()
    };
    assert!(!doc["paths"].as_array().unwrap().is_empty());
    assert_eq!(on("vcarve_paths"), doc["paths"].as_array().unwrap().len());
    let pieces: usize = doc["flats"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["segments"].as_array().unwrap().len())
        .sum();
    assert_eq!(on("vcarve_flats"), pieces);
}

/// Outward offsets never vanish: `--step` has no last pass there, and says so.
#[test]
fn a_step_outward_is_a_usage_error() {
    let run = curvekit(&[
        "offset",
        &fixture("region-pocket.json"),
        "--step",
        "0.5",
        "--outward",
    ]);
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert!(run.stderr.contains("--step"), "{}", run.stderr);
}
