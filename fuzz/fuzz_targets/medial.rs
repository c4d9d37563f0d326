//! `medial` on arbitrary regions: polygons (some corners rounded, some sides bent into
//! Béziers) with round holes, at every scale and offset, through the region reader: an
//! error or a result, never a panic or a hang; finite output, every vertex at its radius
//! from both feet.
#![no_main]

use curvekit::medial::{medial_axis, MedialOptions};
use libfuzzer_sys::fuzz_target;

#[path = "common.rs"]
mod common;

fuzz_target!(|input: common::ArbRegion| {
    let (doc, k, far) = input.document();
    let Some(region) = common::read_region(&doc) else {
        return;
    };
    let region = &region;
    let opts = MedialOptions {
        settings: curvekit::numeric::tolerance::Settings::new(
            curvekit::numeric::tolerance::DEFAULT_PARAM_TOL,
            input.chord_tol(),
            None,
        )
        .expect("settings in range"),
        ..MedialOptions::default()
    };
    let Ok(axis) = medial_axis(region, &opts) else {
        return;
    };
    // The shape's size, and the rounding of its coordinates far from the origin (a shape
    // of a few hundred units of rounding of its position is all rounding).
    let size = 256.0 * k;
    let room = 1e-6 * size + 64.0 * f64::EPSILON * (far + 128.0) * k;
    common::check_axis(region, &axis, room);
});
