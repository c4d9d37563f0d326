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

/// The rounded slot (a profile of lines and arcs, parallel sides) at μ = 0.3: every boundary
/// resolved, the regions certified.
#[test]
fn grasps_of_the_rounded_slot_at_friction_0_3() {
    let mut doc = curvekit_json(&[
        "grasps",
        &fixture("profile-rounded-slot.json"),
        "--friction",
        "0.3",
    ]);
    assert_eq!(doc["certified"], serde_json::json!(true));
    doc["curve"]["file"] = serde_json::json!("profile-rounded-slot.json");
    insta::assert_json_snapshot!("grasps-rounded-slot-0.3", rounded(&doc));
}
