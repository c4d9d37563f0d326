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

/// The shipped shapes whose axes are checked against dense samples.
const CHECKED_SHAPES: [&str; 7] = [
    "region-pocket.json",
    "profile-rounded-slot.json",
    "profile-bracket.json",
    "drawing-pocket.svg",
    "drawing-glyph-d.svg",
    "drawing-bracket.dxf",
    "drawing-plate.dxf",
];

/// The region of a shipped shape.
fn shipped_region(name: &str) -> curvekit::curve::Region {
    let path = std::path::PathBuf::from(fixture(name));
    match curvekit::io::read_region(&path, None).unwrap().shape {
        curvekit::io::CurveKind::Region(region) => *region,
        _ => panic!("{name}: no region"),
    }
}

/// Every vertex of every shipped shape's axis is at its radius from the boundary: the
/// distance by dense sampling of every boundary (4,000 samples a segment), which can only
/// overestimate it, by at most what half a sample step adds, √(r² + (h/2)²) − r.
#[test]
fn every_vertex_is_at_its_radius_from_the_boundary() {
    use curvekit::curve::ParamCurve;
    for name in CHECKED_SHAPES {
        let region = &shipped_region(name);
        let mut samples: Vec<[f64; 2]> = Vec::new();
        let mut size = 0.0f64;
        let mut step = 0.0f64;
        for b in std::iter::once(region.outer()).chain(region.holes()) {
            let n = 4000 * b.segments().len();
            let (lo, hi) = b.domain();
            let pts: Vec<[f64; 2]> = (0..=n)
                .map(|k| b.jet(lo + (hi - lo) * k as f64 / n as f64).p.arr())
                .collect();
            for w in pts.windows(2) {
                step = step.max((w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]));
            }
            samples.extend(pts);
            size = size.max(b.scale());
        }
        let out = curvekit_json(&["medial", &fixture(name)]);
        for e in out["edges"].as_array().unwrap() {
            let xy = e["xy"].as_array().unwrap();
            let radius = e["radius"].as_array().unwrap();
            for (p, r) in xy.iter().zip(radius) {
                let p = [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()];
                let r = r.as_f64().unwrap();
                let d = samples
                    .iter()
                    .map(|q| (q[0] - p[0]).hypot(q[1] - p[1]))
                    .fold(f64::INFINITY, f64::min);
                // Sampled: never below the true distance, above it by the sagitta at most.
                assert!(
                    d >= r - 1e-9 * size,
                    "{name}: {p:?} radius {r}, boundary at {d}"
                );
                let slack = r.hypot(0.5 * step) - r + 1e-9 * size;
                assert!(d <= r + slack, "{name}: {p:?} radius {r}, boundary at {d}");
            }
        }
    }
}

/// Every `end` node of every shipped shape's axis is a centre of curvature at a curvature
/// extremum: among dense samples of the boundaries (4,000 a segment), the centre of curvature
/// nearest the node is within 1e-6 of the size of it, the radius of curvature there is the
/// node's radius, and the curvature's rate changes sign within three samples (or vanishes: an
/// arc, whose centre is every point's).
#[test]
fn every_end_is_a_centre_of_curvature_at_an_extremum() {
    for name in CHECKED_SHAPES {
        let region = &shipped_region(name);
        // Per sample: centre of curvature, radius of curvature, curvature rate, and the
        // index of the boundary and of the segment (rates compare within one segment).
        let mut samples = Vec::new();
        let mut size = 0.0f64;
        for (k, b) in std::iter::once(region.outer())
            .chain(region.holes())
            .enumerate()
        {
            size = size.max(b.scale());
            for i in 0..b.segments().len() {
                for s in 0..=4000 {
                    let j = b.jet_on(i, i as f64 + s as f64 / 4000.0, 3);
                    let kappa = j.curvature();
                    if kappa.abs() < 1e-12 {
                        continue;
                    }
                    let c = j.p + j.d1.perp().unit() * (1.0 / kappa);
                    samples.push((c.arr(), 1.0 / kappa.abs(), j.curvature_rate(), (k, i, s)));
                }
            }
        }
        let out = curvekit_json(&["medial", &fixture(name)]);
        for node in out["nodes"].as_array().unwrap() {
            if node["kind"] != "end" {
                continue;
            }
            let p = [
                node["xy"][0].as_f64().unwrap(),
                node["xy"][1].as_f64().unwrap(),
            ];
            let r = node["radius"].as_f64().unwrap();
            let (at, (c, rc, rate, id)) = samples
                .iter()
                .enumerate()
                .min_by(|a, b| {
                    let d = |c: [f64; 2]| (c[0] - p[0]).hypot(c[1] - p[1]);
                    d(a.1 .0).total_cmp(&d(b.1 .0))
                })
                .unwrap();
            let off = (c[0] - p[0]).hypot(c[1] - p[1]);
            assert!(
                off <= 1e-6 * size,
                "{name}: end {p:?} is {off} from the evolute"
            );
            testkit::assert_near!(rc, r, 1e-6 * size, "{name}: end {p:?} radius {r}, {rc}");
            let same = |j: usize| samples.get(j).filter(|s| s.3 .0 == id.0 && s.3 .1 == id.1);
            let turns = (at.saturating_sub(3)..at + 3).any(|j| match (same(j), same(j + 1)) {
                (Some(a), Some(b)) => a.2.signum() != b.2.signum(),
                _ => false,
            });
            assert!(
                turns || rate.abs() <= 1e-9 / (rc * rc),
                "{name}: end {p:?}: the curvature's rate {rate} does not change sign near it"
            );
        }
    }
}
