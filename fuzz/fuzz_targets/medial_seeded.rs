//! `medial` on regions of 48 segments and more, where the pairs of sites come from the
//! topology seed (the Voronoi diagram of the boundaries' chords): star-shaped outlines (so
//! that most draws are simple) whose vertices may be snapped to a coarse grid (collinear
//! runs, repeated directions, nearly touching sides: the seed's degenerate cases), sides
//! bent into Béziers or rounded into arcs, round holes, at every scale and offset. An error
//! or a result, never a panic or a hang; finite output, every vertex at its radius from
//! both feet.
#![no_main]

use arbitrary::Arbitrary;
use curvekit::medial::{medial_axis, MedialOptions};
use libfuzzer_sys::fuzz_target;
use serde_json::json;

#[path = "common.rs"]
mod common;

/// Sides: from the seed's threshold to a few times it (the axis's cost grows with them).
const MIN_SIDES: usize = 48;
const MAX_SIDES: usize = 128;

#[derive(Arbitrary, Debug)]
struct Input {
    /// Per vertex: its distance from the centre (1 + byte / 64) and how to reach the next
    /// (0: a line; odd: a Bézier bent by the byte; else an arc through the bend).
    vertices: Vec<(u8, i8)>,
    /// Snap the vertices to a grid of 2^-(grid mod 8) (0: no grid).
    grid: u8,
    holes: Vec<((i8, i8), u8)>,
    /// Scale by 2^(scale mod 81 − 40).
    scale: u8,
    /// Offset by 2^(offset mod 40) sizes.
    offset: u8,
}

fuzz_target!(|input: Input| {
    let n = input.vertices.len();
    if !(MIN_SIDES..=MAX_SIDES).contains(&n) {
        return;
    }
    let k = 2f64.powi((input.scale % 81) as i32 - 40);
    let far = 2f64.powi((input.offset % 40) as i32) * 8.0;
    let grid = match input.grid % 8 {
        0 => None,
        g => Some(2f64.powi(-(g as i32))),
    };
    let points: Vec<[f64; 2]> = input
        .vertices
        .iter()
        .enumerate()
        .map(|(i, &(r, _))| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 1.0 + r as f64 / 64.0;
            let (x, y) = (r * a.cos(), r * a.sin());
            let snap = |v: f64| grid.map_or(v, |g| (v / g).round() * g);
            [snap(x), snap(y)]
        })
        .collect();
    let at = |p: [f64; 2]| [(p[0] + far) * k, (p[1] + far) * k];
    let segments: Vec<_> = (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            let bend = input.vertices[i].1;
            let mid = [
                0.5 * (a[0] + b[0]) - (b[1] - a[1]) * bend as f64 / 256.0,
                0.5 * (a[1] + b[1]) + (b[0] - a[0]) * bend as f64 / 256.0,
            ];
            match bend {
                0 => json!({"kind": "line", "from": at(a), "to": at(b)}),
                b if b % 2 != 0 => {
                    json!({"kind": "bezier", "points": [at(a), at(mid), at(points[(i + 1) % n])]})
                }
                _ => arc(at(a), at(mid), at(b)),
            }
        })
        .collect();
    let holes: Vec<_> = input
        .holes
        .iter()
        .take(3)
        .map(|&(c, r)| {
            let c = [c.0 as f64 / 256.0, c.1 as f64 / 256.0];
            json!({"kind": "circle", "center": at(c), "r": (0.02 + r as f64 / 1024.0) * k})
        })
        .collect();
    let doc = json!({"kind": "region", "outer": {"kind": "profile", "segments": segments}, "holes": holes});
    let Some(region) = common::read_region(&doc) else {
        return;
    };
    let region = &region;
    let Ok(axis) = medial_axis(region, &MedialOptions::default()) else {
        return;
    };
    // The shape spans about 8 units; its coordinates round by their size far from the origin.
    let room = 1e-6 * 8.0 * k + 64.0 * f64::EPSILON * (far + 8.0) * k;
    common::check_axis(region, &axis, room);
});

/// The arc from `a` through `m` to `b`.
fn arc(a: [f64; 2], m: [f64; 2], b: [f64; 2]) -> serde_json::Value {
    // The circumcentre of the three points.
    let d = 2.0 * (a[0] * (m[1] - b[1]) + m[0] * (b[1] - a[1]) + b[0] * (a[1] - m[1]));
    let sq = |p: [f64; 2]| p[0] * p[0] + p[1] * p[1];
    let cx = (sq(a) * (m[1] - b[1]) + sq(m) * (b[1] - a[1]) + sq(b) * (a[1] - m[1])) / d;
    let cy = (sq(a) * (b[0] - m[0]) + sq(m) * (a[0] - b[0]) + sq(b) * (m[0] - a[0])) / d;
    let angle = |p: [f64; 2]| (p[1] - cy).atan2(p[0] - cx);
    let tau = std::f64::consts::TAU;
    let (ta, tm, tb) = (angle(a), angle(m), angle(b));
    let ccw = (tb - ta).rem_euclid(tau);
    let end = if (tm - ta).rem_euclid(tau) < ccw {
        ta + ccw
    } else {
        ta - (tau - ccw)
    };
    let r = (a[0] - cx).hypot(a[1] - cy);
    json!({"kind": "arc", "center": [cx, cy], "r": r, "start": ta, "end": end})
}
