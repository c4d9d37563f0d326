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
            curvekit::io::Shape::Profile(p) => p.is_closed(),
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
