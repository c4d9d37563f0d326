//! The SVG reader on arbitrary bytes, and `antipodal` on the small closed profiles it
//! accepts: an error or an answer, never a panic or a hang; answers have finite points.
#![no_main]

use curvekit::io::{parse_drawing, DrawingFormat, Shape};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(curve) = parse_drawing("fuzz.svg", DrawingFormat::Svg, data, Some(0)) else {
        return;
    };
    for p in curve.polyline(16) {
        assert!(p[0].is_finite() && p[1].is_finite(), "point {p:?}");
    }
    let Shape::Profile(profile) = &curve.shape else {
        return;
    };
    if profile.segments().len() > 12 {
        return;
    }
    let opts = curvekit::antipodal::Options::default().tolerance(1e-10);
    if let Ok(r) = curvekit::antipodal::profile_antipodal(profile, &opts) {
        for pair in &r.pairs {
            assert!(pair.p.iter().chain(&pair.q).all(|x| x.is_finite()), "{pair:?}");
        }
    }
});
