//! The curve-file reader on arbitrary bytes: an error or a curve, never a panic; a curve it
//! accepts has a finite domain and finite points.
#![no_main]

use curvekit::io::parse_curve;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(curve) = parse_curve("fuzz.json", text) {
        let (a, b) = curve.domain();
        assert!(a.is_finite() && b.is_finite() && a < b, "domain {a}..{b}");
        for p in curve.polyline(16) {
            assert!(p[0].is_finite() && p[1].is_finite(), "point {p:?}");
        }
    }
});
