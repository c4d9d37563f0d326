//! The DXF reader on arbitrary bytes, as regions and as the first profile: an error or an
//! answer, never a panic or a hang; what it accepts has finite points, and a profile has
//! segments.
#![no_main]

use curvekit::io::{parse_drawing, parse_region, CurveKind, DrawingFormat};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // As the regions `medial` and `offset` read (outlines nested, filled, checked for
    // crossings): an error or regions with finite points.
    if let Ok(region) = parse_region("fuzz.dxf", Some(DrawingFormat::Dxf), data, None) {
        for p in region.polyline(16) {
            assert!(p[0].is_finite() && p[1].is_finite(), "region point {p:?}");
        }
    }
    let Ok(curve) = parse_drawing("fuzz.dxf", DrawingFormat::Dxf, data, Some(0)) else {
        return;
    };
    for p in curve.polyline(16) {
        assert!(p[0].is_finite() && p[1].is_finite(), "point {p:?}");
    }
    let CurveKind::Profile(profile) = &curve.shape else {
        panic!("a drawing gives a profile: {:?}", curve.shape);
    };
    assert!(!profile.segments().is_empty());
});
