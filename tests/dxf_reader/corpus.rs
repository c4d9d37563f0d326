//! What a drawing says besides its outlines, and the corpus of drawings made by another
//! program (ezdxf, `fixtures/corpus/dxf/`, described by `fixtures/corpus/manifest.json`):
//! `$INSUNITS` reported as `units`; every entity not read counted in `skipped`, those that
//! could be part of an outline (a 3D polyline off the plane, an entity tilted out of it)
//! making answers uncertified, naming them; closed splines with corners read with them.

use super::common::{curvekit, curvekit_json, fixture};
use super::splines::spline_entity;
use super::written::{circle, entity, file, line, num, rectangle, Written};
use super::{add, drawing, p3, saved, temp_dxf};
use curve::{ParamCurve, Region, V2};
use curvekit::io::{read_region, Curve, CurveFileError};
use dxf::entities::{Circle, EntityType, Polyline, Vertex};
use dxf::Point;
use serde_json::Value;
use std::collections::BTreeMap;

fn v(x: f64, y: f64) -> V2 {
    V2::new(x, y)
}

fn read_file(text: &str) -> Result<Curve, CurveFileError> {
    read_region(&temp_dxf(text.as_bytes()), None)
}

fn parts(c: &Curve) -> Vec<&Region> {
    c.parts()
}

/// A square plate with a round hole, in a file whose header says `units` (`$INSUNITS`).
fn plate_in(units: Option<&str>) -> String {
    file(
        units,
        &[],
        &[
            rectangle(v(0.0, 0.0), v(10.0, 10.0)),
            circle(v(5.0, 5.0), 1.0),
        ],
    )
}

#[test]
fn insunits_names_the_unit_and_unitless_or_absent_is_none() {
    let names = [
        "in", "ft", "mi", "mm", "cm", "m", "km", "uin", "mil", "yd", "angstrom", "nm", "um", "dm",
        "dam", "hm", "Gm", "au", "ly", "pc",
    ];
    for (code, name) in (1..=20).zip(names) {
        let c = read_file(&plate_in(Some(&code.to_string()))).unwrap();
        let units = c.drawing.and_then(|d| d.units);
        assert_eq!(units.as_deref(), Some(name), "$INSUNITS {code}");
    }
    for text in [plate_in(Some("0")), plate_in(None)] {
        let c = read_file(&text).unwrap();
        assert_eq!(c.drawing.and_then(|d| d.units), None);
    }
    // A value that is no unit code: refused, naming the variable.
    for bad in ["99", "-1", "mm"] {
        let e = read_file(&plate_in(Some(bad))).unwrap_err();
        assert!(e.field.contains("$INSUNITS"), "{bad}: {e}");
    }
}

#[test]
fn units_and_skipped_are_in_the_json() {
    let mm = temp_dxf(plate_in(Some("4")).as_bytes());
    let j = curvekit_json(&["medial", mm.to_str().unwrap()]);
    assert_eq!(j["units"], "mm", "{j}");
    assert_eq!(j["skipped"], serde_json::json!([]), "{j}");
    let none = temp_dxf(plate_in(None).as_bytes());
    let j = curvekit_json(&["medial", none.to_str().unwrap()]);
    assert!(j.get("units").is_none(), "{j}");
    let j = curvekit_json(&["medial", &fixture("corpus/dxf/plate_inches.dxf")]);
    assert_eq!(j["units"], "in", "{j}");
}

#[test]
fn text_is_counted_as_skipped_and_the_answer_stays_certified() {
    let j = curvekit_json(&["medial", &fixture("corpus/dxf/text_and_notes.dxf")]);
    assert_eq!(
        j["skipped"],
        serde_json::json!([{"type": "TEXT", "count": 2}, {"type": "MTEXT", "count": 1}]),
        "{j}"
    );
    assert_eq!(j["certified"], true, "{j}");
    assert_eq!(j["units"], "mm");
}

#[test]
fn a_3d_polyline_off_the_plane_is_skipped_and_the_answer_uncertified() {
    let path = fixture("corpus/dxf/polyline3d_off_plane.dxf");
    let c = read_region(std::path::Path::new(&path), None).unwrap();
    // The region is the rest: the plate and its hole, no phantom hole.
    assert_eq!(parts(&c).len(), 1);
    assert_eq!(parts(&c)[0].holes().len(), 1);
    let j = curvekit_json(&["medial", &path]);
    assert_eq!(j["certified"], false, "{j}");
    let reason = j["reason"].as_str().unwrap_or_default();
    assert!(
        reason.contains("POLYLINE") && reason.contains("off the drawing's plane"),
        "{j}"
    );
    assert!(reason.contains("z from 0 to 5"), "{reason}");
    assert_eq!(
        j["skipped"],
        serde_json::json!([{"type": "POLYLINE", "count": 1}])
    );
}

/// A closed 3D polyline (a square of side 2 about `(x, 0)`) at heights `z`, one per vertex.
fn polyline_3d(d: &mut dxf::Drawing, x: f64, z: [f64; 4]) -> String {
    let mut p = Polyline {
        flags: 1 | 8,
        ..Default::default()
    };
    for (k, (dx, dy)) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .into_iter()
        .enumerate()
    {
        p.add_vertex(d, Vertex::new(Point::new(x + dx, dy, z[k])));
    }
    add(d, EntityType::Polyline(p))
}

#[test]
fn a_3d_polyline_in_a_plane_parallel_to_the_drawing_is_read() {
    let mut d = drawing();
    add(&mut d, EntityType::Circle(Circle::new(p3(0.0, 0.0), 20.0)));
    polyline_3d(&mut d, 0.0, [5.0; 4]);
    let h = polyline_3d(&mut d, 10.0, [0.0, 0.0, 3.0, 0.0]);
    let c = read_region(&saved(&d), None).unwrap();
    assert_eq!(parts(&c)[0].holes().len(), 1, "the level square is a hole");
    let doubt = c.drawing_doubt().unwrap();
    assert!(doubt.contains(&format!("POLYLINE {h}")), "{doubt}");
    // When all there is is off the plane: refused, naming it.
    let mut d = drawing();
    let h = polyline_3d(&mut d, 0.0, [0.0, 0.0, 3.0, 0.0]);
    let e = read_region(&saved(&d), None).unwrap_err();
    assert!(e.to_string().contains(&format!("POLYLINE {h}")), "{e}");
    assert!(e.to_string().contains("off the drawing's plane"), "{e}");
}

#[test]
fn an_entity_tilted_out_of_the_plane_is_skipped_and_the_rest_read() {
    // A LINE rising out of the plane, a circle with a tilted extrusion direction.
    let rising = line(v(0.0, 0.0), v(1.0, 0.0)).with(&[(30, "0"), (31, "4")]);
    let tilted =
        circle(v(0.0, 0.0), 1.0)
            .handle("2C")
            .with(&[(210, "0.0"), (220, "0.6"), (230, "0.8")]);
    let text = file(
        None,
        &[],
        &[
            rectangle(v(-10.0, -10.0), v(10.0, 10.0)),
            circle(v(5.0, 5.0), 1.0),
            rising.handle("2B"),
            tilted,
        ],
    );
    let c = read_file(&text).unwrap();
    assert_eq!(parts(&c)[0].holes().len(), 1);
    let skipped = &c.drawing.as_ref().unwrap().skipped;
    let counts: Vec<(&str, usize, bool)> = skipped
        .iter()
        .map(|s| (s.kind.as_str(), s.count, s.outline))
        .collect();
    assert_eq!(counts, [("LINE", 1, true), ("CIRCLE", 1, true)]);
    let doubt = c.drawing_doubt().unwrap();
    assert!(
        doubt.contains("LINE 2B") && doubt.contains("CIRCLE 2C"),
        "{doubt}"
    );
    // Through the command line: an answer, uncertified, naming the circle.
    let path = temp_dxf(text.as_bytes());
    let j = curvekit_json(&["medial", path.to_str().unwrap()]);
    assert_eq!(j["certified"], false);
    assert!(j["reason"].as_str().unwrap().contains("CIRCLE 2C"), "{j}");
}

#[test]
fn entities_not_read_are_counted_by_type_and_paper_space_apart() {
    let text_entity = |s: &str| {
        entity(
            "TEXT",
            vec![
                (10, num(1.0)),
                (20, num(1.0)),
                (40, num(1.0)),
                (1, s.to_string()),
            ],
        )
    };
    let point = entity("POINT", vec![(10, num(2.0)), (20, num(2.0))]);
    let solid = entity("SOLID", vec![(10, num(2.0)), (20, num(2.0))]).handle("5D");
    let paper = circle(v(50.0, 50.0), 3.0).with(&[(67, "1")]);
    let entities: Vec<Written> = vec![
        rectangle(v(-10.0, -10.0), v(10.0, 10.0)),
        text_entity("A"),
        point,
        text_entity("B"),
        paper,
        solid,
    ];
    let c = read_file(&file(None, &[], &entities)).unwrap();
    let skipped: BTreeMap<&str, (usize, bool)> = c
        .drawing
        .as_ref()
        .unwrap()
        .skipped
        .iter()
        .map(|s| (s.kind.as_str(), (s.count, s.outline)))
        .collect();
    let want: BTreeMap<&str, (usize, bool)> = [
        ("TEXT", (2, false)),
        ("POINT", (1, false)),
        ("paper space", (1, false)),
        ("SOLID", (1, true)),
    ]
    .into_iter()
    .collect();
    assert_eq!(skipped, want);
    // A SOLID is a filled area: it could be part of the outline.
    assert!(c.drawing_doubt().unwrap().contains("SOLID 5D"));
    // A drawing of text only: refused, saying what it held.
    let e = read_file(&file(None, &[], &[text_entity("A")])).unwrap_err();
    assert!(e.to_string().contains("TEXT"), "{e}");
}

#[test]
fn closed_splines_with_corner_knots_keep_their_corners() {
    // Outer corners of each spline fixture: a star of ten (cubic, interior knots of
    // multiplicity 3), a seam (clamped, closed by its points), a hexagon of bulging sides
    // (quadratic, multiplicity 2), a polygon (degree 1), none (periodic cubic).
    for (name, corners) in [
        ("spline_c0_star.dxf", 10),
        ("spline_closed_by_points.dxf", 1),
        ("spline_c0_quadratic.dxf", 6),
        ("spline_degree1.dxf", 6),
        ("spline_periodic.dxf", 0),
    ] {
        let path = fixture(&format!("corpus/dxf/{name}"));
        let c = read_region(std::path::Path::new(&path), None).unwrap();
        let outer = parts(&c)[0].outer();
        assert_eq!(outer.corners().count(), corners, "{name}");
    }
    let path = fixture("corpus/dxf/spline_degree1.dxf");
    let c = read_region(std::path::Path::new(&path), None).unwrap();
    assert_eq!(parts(&c)[0].holes()[0].corners().count(), 3);
    // A periodic degree-1 spline (its first point repeated at the end, uniform knots, flagged
    // closed and periodic): a square with four corners.
    let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [0.0, 0.0]];
    let knots: Vec<f64> = (0..square.len() + 2).map(|i| i as f64).collect();
    let mut d = drawing();
    add(&mut d, spline_entity(1, &knots, &square, &[], 1 | 2 | 8));
    let c = read_region(&saved(&d), None).unwrap();
    let outer = parts(&c)[0].outer();
    let mut at: Vec<[f64; 2]> = outer.corners().map(|j| outer.jet(j.u).p.arr()).collect();
    at.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(at, [[0.0, 0.0], [0.0, 4.0], [4.0, 0.0], [4.0, 4.0]]);
}

/// The expectations of the manifest's DXF entries, by file.
fn manifest() -> Vec<(String, Value)> {
    let text = std::fs::read_to_string(fixture("corpus/manifest.json")).unwrap();
    let m: Value = serde_json::from_str(&text).unwrap();
    m["files"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["kind"] == "dxf")
        .map(|f| (f["file"].as_str().unwrap().to_string(), f["expect"].clone()))
        .collect()
}

#[test]
fn the_corpus_reads_as_its_manifest_says() {
    let entries = manifest();
    assert!(entries.len() >= 38, "{}", entries.len());
    for (file, expect) in entries {
        let path = fixture(&format!("corpus/{file}"));
        let read = read_region(std::path::Path::new(&path), None);
        if expect["valid"] == false {
            let e = read.expect_err(&file);
            let cause = expect["cause"].as_str().unwrap();
            assert!(e.to_string().contains(cause), "{file}: {e}");
            continue;
        }
        let c = read.unwrap_or_else(|e| panic!("{file}: {e}"));
        let mut holes: Vec<u64> = parts(&c).iter().map(|r| r.holes().len() as u64).collect();
        let mut want: Vec<u64> = expect["holes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|h| h.as_u64().unwrap())
            .collect();
        holes.sort_unstable();
        want.sort_unstable();
        assert_eq!(holes, want, "{file}: holes");
        assert_eq!(parts(&c).len() as u64, expect["parts"].as_u64().unwrap());
        let info = c.drawing.clone().unwrap();
        assert_eq!(info.units.as_deref(), expect["units"].as_str(), "{file}");
        let skipped: BTreeMap<String, u64> = info
            .skipped
            .iter()
            .map(|s| (s.kind.clone(), s.count as u64))
            .collect();
        let want: BTreeMap<String, u64> = expect["skipped"]
            .as_object()
            .map(|o| {
                o.iter()
                    .map(|(k, n)| (k.clone(), n.as_u64().unwrap()))
                    .collect()
            })
            .unwrap_or_default();
        assert_eq!(skipped, want, "{file}: skipped");
        let uncertified = expect["uncertified"].as_bool().unwrap_or(false);
        assert_eq!(c.drawing_doubt().is_some(), uncertified, "{file}");
    }
}

#[test]
fn the_corpus_blocks_through_the_command_line() {
    // Drawings of block references answer through the command line certified, with nothing
    // skipped (their holes are counted above).
    for name in [
        "plate_holes_block.dxf",
        "minsert_grid.dxf",
        "nested_blocks.dxf",
        "plate_mirrored_insert.dxf",
        "plate_nonuniform_insert.dxf",
    ] {
        let r = curvekit(&["medial", &fixture(&format!("corpus/dxf/{name}")), "--json"]);
        assert_eq!(r.code, 0, "{name}: {}", r.stderr);
        let j: Value = serde_json::from_str(&r.stdout).unwrap();
        assert_eq!(j["certified"], true, "{name}: {}", j["reason"]);
        assert_eq!(j["skipped"], serde_json::json!([]), "{name}");
        assert_eq!(j["units"], "mm", "{name}");
    }
}
