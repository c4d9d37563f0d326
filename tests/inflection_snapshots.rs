//! Snapshots of `curvekit inflections --json` for every fixture (numbers rounded to 9
//! significant digits, so they survive floating-point noise but not a changed answer).
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit_json, fixtures_dir, json_files, rounded};

#[test]
fn inflections_of_every_fixture() {
    let files = json_files(&fixtures_dir());
    assert!(files.len() >= 15);
    for path in files {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        // (A region is no curve: `inflections` refuses it, tested in cli_errors.)
        if name.starts_with("region-") {
            continue;
        }
        let mut doc = curvekit_json(&["inflections", path.to_str().unwrap()]);
        // The absolute path differs between machines.
        doc["curve"]["file"] = serde_json::json!(format!("{name}.json"));
        insta::assert_json_snapshot!(name, rounded(&doc));
    }
}
