//! The DXF reader on arbitrary bytes, as regions and as the first profile: an error or an
//! answer, never a panic or a hang; what it accepts has finite points, and a profile has
//! segments.
#![no_main]

mod common;

use curvekit::io::{CurveKind, DrawingFormat};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some(curve) = common::read_drawing("fuzz.dxf", DrawingFormat::Dxf, data) else {
        return;
    };
    let CurveKind::Profile(profile) = &curve.shape else {
        panic!("a drawing gives a profile: {:?}", curve.shape);
    };
    assert!(!profile.segments().is_empty());
});
