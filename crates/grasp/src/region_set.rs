//! A region as a set of pairs: which pairs it holds, on the whole torus of parameters.

use crate::assemble::RawRegion;
use crate::polyline::{bounds, inside, signed_area};
use curve::{distance_to_segment, squared_distance_to_segment};

/// How close (in the profile's parameter) a pair must lie to a corner line or a single pair
/// of a region to be on it, and a polyline's vertex to a joint's line (a cell's border).
pub(crate) const ON_LINE: f64 = 1e-9;

/// The pair `(s, t)` (any reals, read modulo `n`, in either order) as the point of the
/// triangle `s ≤ t` of `[0, n)`.
pub(crate) fn in_triangle(n: usize, s: f64, t: f64) -> [f64; 2] {
    let n = n as f64;
    let wrap = |u: f64| {
        let x = crate::model::wrap(u, n);
        if x >= n {
            0.0
        } else {
            x
        }
    };
    let (s, t) = (wrap(s), wrap(t));
    if s <= t {
        [s, t]
    } else {
        [t, s]
    }
}

/// Whether the region holds the pair `(s, t)` (by its polylines: exact up to the chord
/// tolerance of their boundaries).
pub(crate) fn holds(region: &RawRegion, n: usize, s: f64, t: f64) -> bool {
    let p = in_triangle(n, s, t);
    let in_parts = region.parts.iter().any(|part| inside(part, p))
        && !region.holes.iter().any(|h| inside(h, p));
    in_parts
        || region
            .lines
            .iter()
            .any(|l| distance_to_segment(p, l[0], l[1]) <= ON_LINE)
        || region
            .points
            .iter()
            .any(|q| (q[0] - p[0]).hypot(q[1] - p[1]) <= ON_LINE)
}

/// Whether the region holds the pair `p` or passes within `by` of it (its polylines being
/// within that of its exact edge).
pub(crate) fn holds_or_touches(region: &RawRegion, n: usize, p: [f64; 2], by: f64) -> bool {
    let [s, t] = in_triangle(n, p[0], p[1]);
    // (A pair with a finger at the seam is also the point `(t, n)` of the triangle.)
    holds(region, n, s, t) || depth(region, [s, t]) <= by || depth(region, [t, s + n as f64]) <= by
}

/// Whether the region holds the pair `p` at least `by` inside its traced polylines (so
/// whichever side of the exact edge a polyline passes, within its chord tolerance, the exact
/// region holds it). Edges along a joint's line are exact (a cell's border), and may be
/// approached as near as any pair: beyond them lies the next cell, another part of the region
/// where the joint is smooth.
pub(crate) fn held_inside(region: &RawRegion, n: usize, p: [f64; 2], by: f64) -> bool {
    holds(region, n, p[0], p[1]) && traced_depth(region, p) >= by
}

/// How far `p` lies from the region's polylines but for their edges along a joint's line.
fn traced_depth(region: &RawRegion, p: [f64; 2]) -> f64 {
    let on_border = |a: [f64; 2], b: [f64; 2]| {
        (0..2).any(|d| {
            let k = a[d].round();
            (a[d] - k).abs() <= ON_LINE && (b[d] - k).abs() <= ON_LINE
        })
    };
    distance_to_edges(region, p, |a, b| !on_border(a, b))
}

/// How far `p` lies from the region's polylines (in the profile's parameter).
pub(crate) fn depth(region: &RawRegion, p: [f64; 2]) -> f64 {
    distance_to_edges(region, p, |_, _| true)
}

/// How far `p` lies from the edges of the region's polylines that `counted` keeps.
fn distance_to_edges(
    region: &RawRegion,
    p: [f64; 2],
    counted: impl Fn([f64; 2], [f64; 2]) -> bool,
) -> f64 {
    region
        .parts
        .iter()
        .chain(&region.holes)
        .flat_map(|l| l.windows(2).filter(|w| counted(w[0], w[1])))
        .map(|w| squared_distance_to_segment(p, w[0], w[1]))
        .fold(f64::INFINITY, f64::min)
        .sqrt()
}

/// Samples across a part's box for its deepest points.
const DEPTH_SAMPLES: usize = 12;

/// Depths tried inside a thin part's edges: a quarter of its box, then each a quarter of the
/// one before.
const INWARD_STEPS: usize = 10;

/// The `count` sampled points of `r`'s parts farthest from their boundaries, with their
/// depths: from a grid across each part's box, or, for parts too thin for it, from points a
/// little inside each edge's middle.
pub(crate) fn deepest(r: &RawRegion, count: usize) -> Vec<([f64; 2], f64)> {
    let mut found: Vec<([f64; 2], f64)> = Vec::new();
    let keep = |found: &mut Vec<([f64; 2], f64)>, part: &[[f64; 2]], p: [f64; 2]| {
        if inside(part, p) && !r.holes.iter().any(|h| inside(h, p)) {
            found.push((p, depth(r, p)));
        }
    };
    for part in &r.parts {
        let (lo, hi) = bounds(part);
        for i in 0..DEPTH_SAMPLES {
            for j in 0..DEPTH_SAMPLES {
                let at = |k: usize, d: usize| {
                    lo[d] + (k as f64 + 0.5) / DEPTH_SAMPLES as f64 * (hi[d] - lo[d])
                };
                keep(&mut found, part, [at(i, 0), at(j, 1)]);
            }
        }
    }
    if found.is_empty() {
        for part in &r.parts {
            let inward = signed_area(part).signum();
            let (lo, hi) = bounds(part);
            let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
            for w in part.windows(2) {
                let (a, b) = (w[0], w[1]);
                let len = (b[0] - a[0]).hypot(b[1] - a[1]);
                if len <= 0.0 {
                    continue;
                }
                let normal = [-(b[1] - a[1]) / len * inward, (b[0] - a[0]) / len * inward];
                let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                for k in 1..=INWARD_STEPS {
                    let d = size * 0.5f64.powi(2 * k as i32);
                    keep(
                        &mut found,
                        part,
                        [mid[0] + d * normal[0], mid[1] + d * normal[1]],
                    );
                }
            }
        }
    }
    found.sort_by(|a, b| b.1.total_cmp(&a.1));
    found.truncate(count);
    found
}
