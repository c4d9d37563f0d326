//! The SVG reader on arbitrary bytes (as regions, and as the first profile), and `antipodal`
//! on the small closed profiles it accepts: an error or an answer, never a panic or a hang;
//! answers have finite points.
#![no_main]

mod common;

use curvekit::io::{CurveKind, DrawingFormat};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some(curve) = common::read_drawing("fuzz.svg", DrawingFormat::Svg, data) else {
        return;
    };
    let CurveKind::Profile(profile) = &curve.shape else {
        return;
    };
    if profile.segments().len() > 12 {
        return;
    }
    let opts = curvekit::antipodal::Options::default()
        .tolerance(curvekit::numeric::tolerance::ParamTol::new(1e-10).expect("in range"));
    if let Ok(r) = curvekit::antipodal::antipodal(profile.as_ref(), &opts) {
        for pair in &r.pairs {
            assert!(
                pair.p.iter().chain(&pair.q).all(|x| x.is_finite()),
                "{pair:?}"
            );
        }
    }
});
