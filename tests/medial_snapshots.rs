//! Snapshots of `curvekit medial --json` on the shipped regions, closed outlines and
//! drawings (the gear's is left out until its bisectors complete): the
//! nodes (position, radius, kind) and per edge its nodes, length and end radii, numbers
//! rounded to 9 significant digits (the polylines' vertices are the chord tolerance's
//! business, checked against an oracle in the medial crate's tests).
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit_json, fixture, rounded};
use serde_json::{json, Value};

fn summary(out: &Value) -> Value {
    let edges: Vec<Value> = out["edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            let xy: Vec<[f64; 2]> = e["xy"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()])
                .collect();
            let length: f64 = xy
                .windows(2)
                .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
                .sum();
            let r = e["radius"].as_array().unwrap();
            json!({
                "from": e["from"],
                "to": e["to"],
                "length": length,
                "radius": [r[0], r[r.len() - 1]],
            })
        })
        .collect();
    json!({
        "nodes": out["nodes"],
        "edges": edges,
        "certified": out["certified"],
        "complete": out["complete"],
    })
}

#[test]
fn medial_axes_of_the_shipped_shapes() {
    for name in [
        "region-pocket.json",
        "profile-rounded-slot.json",
        "profile-bracket.json",
        "periodic_cubic.json",
        "circle.json",
        "drawing-pocket.svg",
        "drawing-glyph-d.svg",
        "drawing-bracket.dxf",
        "drawing-plate.dxf",
    ] {
        let out = curvekit_json(&["medial", &fixture(name)]);
        assert_eq!(out["complete"], true, "{name}");
        insta::assert_json_snapshot!(format!("medial-{name}"), rounded(&summary(&out)));
    }
}
