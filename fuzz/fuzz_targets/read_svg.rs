//! The SVG reader on arbitrary bytes (as regions, and as the first profile), and `antipodal`
//! on the small closed profiles it accepts: an error or an answer, never a panic or a hang;
//! answers have finite points.
#![no_main]

use curvekit::io::{parse_drawing, parse_region, CurveKind, DrawingFormat};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // As the regions `medial` and `offset` read (outlines nested, filled, checked for
    // crossings): an error or regions with finite points.
    if let Ok(region) = parse_region("fuzz.svg", Some(DrawingFormat::Svg), data, None) {
        for p in region.polyline(16) {
            assert!(p[0].is_finite() && p[1].is_finite(), "region point {p:?}");
        }
    }
    let Ok(curve) = parse_drawing("fuzz.svg", DrawingFormat::Svg, data, Some(0)) else {
        return;
    };
    for p in curve.polyline(16) {
        assert!(p[0].is_finite() && p[1].is_finite(), "point {p:?}");
    }
    let CurveKind::Profile(profile) = &curve.shape else {
        return;
    };
    if profile.segments().len() > 12 {
        return;
    }
    let opts = curvekit::antipodal::Options::default()
        .tolerance(curvekit::numeric::tolerance::ParamTol::new(1e-10).expect("in range"));
    if let Ok(r) = curvekit::antipodal::profile_antipodal(profile, &opts) {
        for pair in &r.pairs {
            assert!(
                pair.p.iter().chain(&pair.q).all(|x| x.is_finite()),
                "{pair:?}"
            );
        }
    }
});
