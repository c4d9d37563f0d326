//! Helpers shared by the offset tests: sampling the pieces of an offset loop (an independent
//! de Boor evaluation for its splines) and their ends. (The winding number of a polygon is
//! testkit's, `testkit::boundary_oracle::winding`.)
#![allow(dead_code, unreachable_pub)]

use offset::OffsetSegment;

/// The medial axis of the outside of `region` (for its outward offsets).
pub fn exterior_axis(region: &curve::Region) -> medial::MedialAxis {
    let opts = medial::MedialOptions {
        exterior: true,
        ..medial::MedialOptions::default()
    };
    medial::medial_axis(region, &opts).unwrap()
}

/// The point of a clamped B-spline at `t` by the Cox–de Boor recursion (written here, apart
/// from the crates' evaluation).
pub fn de_boor(p: usize, knots: &[f64], points: &[[f64; 2]], t: f64) -> [f64; 2] {
    assert_eq!(knots.len(), points.len() + p + 1, "a clamped knot vector");
    let n = points.len();
    // (The span holding t; the last non-empty one at the right end.)
    let k = (p..n)
        .rev()
        .find(|&k| knots[k] <= t && knots[k] < knots[k + 1])
        .unwrap_or(p);
    let mut d: Vec<[f64; 2]> = (0..=p).map(|j| points[j + k - p]).collect();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = j + k - p;
            let den = knots[i + p + 1 - r] - knots[i];
            let a = if den > 0.0 { (t - knots[i]) / den } else { 0.0 };
            d[j] = [
                (1.0 - a) * d[j - 1][0] + a * d[j][0],
                (1.0 - a) * d[j - 1][1] + a * d[j][1],
            ];
        }
    }
    d[p]
}

/// Points along an offset segment (its ends included).
pub fn samples(s: &OffsetSegment, n: usize) -> Vec<[f64; 2]> {
    match s {
        OffsetSegment::Line { from, to } => (0..=n)
            .map(|k| {
                let t = k as f64 / n as f64;
                [
                    from[0] + t * (to[0] - from[0]),
                    from[1] + t * (to[1] - from[1]),
                ]
            })
            .collect(),
        OffsetSegment::Arc {
            center,
            r,
            start,
            end,
        } => (0..=n)
            .map(|k| {
                let a = start + (end - start) * k as f64 / n as f64;
                [center[0] + r * a.cos(), center[1] + r * a.sin()]
            })
            .collect(),
        OffsetSegment::BSpline {
            degree,
            knots,
            points,
        } => (0..=n * (points.len() - degree))
            .map(|k| {
                de_boor(
                    *degree,
                    knots,
                    points,
                    k as f64 / (n * (points.len() - degree)) as f64,
                )
            })
            .collect(),
    }
}

pub fn ends(s: &OffsetSegment) -> ([f64; 2], [f64; 2]) {
    let p = samples(s, 1);
    (p[0], p[p.len() - 1])
}

/// The angle the arcs of a loop's pieces sweep, in all.
pub fn arcs_sweep(segments: &[OffsetSegment]) -> f64 {
    segments
        .iter()
        .map(|s| match s {
            OffsetSegment::Arc { start, end, .. } => (end - start).abs(),
            _ => 0.0,
        })
        .sum()
}
