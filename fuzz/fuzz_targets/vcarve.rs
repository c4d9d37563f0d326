//! `vcarve` and the files written for CAD/CAM on arbitrary regions (as `medial`'s target draws
//! them) and bits: an error or a result, never a panic or a hang; every path point finite, at
//! or above the surface and no deeper than asked; the DXF and SVG writers take every axis,
//! offset and carving and give files their own crates read back.
#![no_main]

use arbitrary::Arbitrary;
use curvekit::export::{dxf_file, svg_paths};
use curvekit::medial::{medial_axis, MedialOptions};
use curvekit::offset::{offsets, vcarve, OffsetOptions, VCarveOptions};
use libfuzzer_sys::fuzz_target;

#[path = "common.rs"]
mod common;

#[derive(Arbitrary, Debug)]
struct Input {
    region: common::ArbRegion,
    /// The bit's angle: 1° to 179° (0 and 180 are refused: tested as such).
    angle: u8,
    /// The depth limit, in 1/16 of the shape's size units, where given (0: refused).
    depth: Option<u8>,
}

fuzz_target!(|input: Input| {
    let (doc, k, _) = input.region.document();
    let Some(region) = common::read_region(&doc) else {
        return;
    };
    let opts = MedialOptions {
        settings: curvekit::numeric::tolerance::Settings::new(
            curvekit::numeric::tolerance::DEFAULT_PARAM_TOL,
            input.region.chord_tol(),
            None,
        )
        .expect("settings in range"),
        ..MedialOptions::default()
    };
    let Ok(axis) = medial_axis(&region, &opts) else {
        return;
    };
    let carve_opts = VCarveOptions {
        angle: (input.angle % 181) as f64,
        max_depth: input.depth.map(|d| d as f64 / 16.0 * k),
        offset: OffsetOptions::default(),
    };
    let refused = carve_opts.validate().is_err();
    let Ok(carve) = vcarve(&region, &axis, &carve_opts) else {
        return;
    };
    assert!(!refused, "refused options were taken: {carve_opts:?}");
    let floor = carve_opts.max_depth.map_or(f64::NEG_INFINITY, |h| -h);
    for p in carve.paths.iter().flat_map(|p| &p.xyz) {
        assert!(p.iter().all(|v| v.is_finite()), "{p:?}");
        assert!(
            p[2] <= 0.0 && p[2] >= floor,
            "depth {} beyond [{floor}, 0]",
            p[2]
        );
    }
    // The writers take whatever the library computes, and their output reads back.
    let dxf = dxf_file::vcarve_dxf(&carve, Some("mm")).unwrap();
    assert!(dxf::Drawing::load(&mut dxf.as_slice()).is_ok());
    let dxf = dxf_file::medial_dxf(&axis, None).unwrap();
    assert!(dxf::Drawing::load(&mut dxf.as_slice()).is_ok());
    let svg = svg_paths::medial_svg(&axis, None).unwrap();
    assert!(roxmltree::Document::parse(&svg).is_ok());
    if carve_opts.max_depth.is_some() {
        let widest = carve_opts.widest();
        if let Ok(found) = offsets(&region, &axis, &[widest], &OffsetOptions::default()) {
            let dxf = dxf_file::offsets_dxf(&found, None).unwrap();
            assert!(dxf::Drawing::load(&mut dxf.as_slice()).is_ok());
            let svg = svg_paths::offsets_svg(&found, None).unwrap();
            assert!(roxmltree::Document::parse(&svg).is_ok());
        }
    }
});
