//! Snapshot of `curvekit grasps --json` on a shipped curve at μ = 0.3 (numbers rounded to 9
//! significant digits, so they survive floating-point noise but not a changed answer): the
//! ellipse's two regions, the one round the major axis in two parts across the seam.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit_json, fixture, rounded};

#[test]
fn grasps_of_the_ellipse_at_friction_0_3() {
    let mut doc = curvekit_json(&["grasps", &fixture("ellipse.json"), "--friction", "0.3"]);
    // The absolute path differs between machines.
    doc["curve"]["file"] = serde_json::json!("ellipse.json");
    insta::assert_json_snapshot!("grasps-ellipse-0.3", rounded(&doc));
}
