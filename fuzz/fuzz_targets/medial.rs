//! `medial` on arbitrary regions: polygons (some corners rounded, some sides bent into
//! Béziers) with round holes, at every scale and offset, through the region reader: an
//! error or a result, never a panic or a hang; finite output, every vertex at its radius
//! from both feet.
#![no_main]

use arbitrary::Arbitrary;
use curvekit::medial::{medial_axis, MedialOptions};
use libfuzzer_sys::fuzz_target;

#[path = "common.rs"]
mod common;
use serde_json::json;

/// The most sides: the axis's cost grows with the square of the sites.
const MAX_SIDES: usize = 8;

#[derive(Arbitrary, Debug)]
struct Side {
    to: (i8, i8),
    /// Bend the side into a quadratic Bézier through a control point this far off (0: a line).
    bend: i8,
}

#[derive(Arbitrary, Debug)]
struct Input {
    start: (i8, i8),
    sides: Vec<Side>,
    holes: Vec<((i8, i8), u8)>,
    /// Scale by 2^(scale mod 121 − 60).
    scale: u8,
    /// Offset by 2^(offset mod 48) sizes.
    offset: u8,
    chord: u8,
}

fuzz_target!(|input: Input| {
    let k = 2f64.powi((input.scale % 121) as i32 - 60);
    let far = 2f64.powi((input.offset % 48) as i32) * 256.0;
    let at = |p: (i8, i8)| [(p.0 as f64 + far) * k, (p.1 as f64 + far) * k];
    let mut from = input.start;
    let mut segments = Vec::new();
    let n = input.sides.len().min(MAX_SIDES);
    for (i, s) in input.sides.iter().take(n).enumerate() {
        let to = if i + 1 == n { input.start } else { s.to };
        if s.bend == 0 {
            segments.push(json!({"kind": "line", "from": at(from), "to": at(to)}));
        } else {
            let mid = (
                ((from.0 as i16 + to.0 as i16) / 2
                    - (to.1 as i16 - from.1 as i16) * s.bend as i16 / 64) as f64,
                ((from.1 as i16 + to.1 as i16) / 2
                    + (to.0 as i16 - from.0 as i16) * s.bend as i16 / 64) as f64,
            );
            let c = [(mid.0 + far) * k, (mid.1 + far) * k];
            segments.push(json!({"kind": "bezier", "points": [at(from), c, at(to)]}));
        }
        from = to;
    }
    let holes: Vec<_> = input
        .holes
        .iter()
        .take(3)
        .map(|&(c, r)| json!({"kind": "circle", "center": at(c), "r": (1.0 + r as f64 / 16.0) * k}))
        .collect();
    let doc = json!({"kind": "region", "outer": {"kind": "profile", "segments": segments}, "holes": holes});
    let Some(region) = common::read_region(&doc) else {
        return;
    };
    let region = &region;
    let opts = MedialOptions {
        chord_tol: 0.5 / 2f64.powi((input.chord % 8) as i32),
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
