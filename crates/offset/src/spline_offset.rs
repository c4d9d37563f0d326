//! The offset of a stretch of a spline: a cubic B-spline fitted to points of the exact offset,
//! its distance from the exact offset measured (at the same parameter, so in both directions)
//! at eight points between each two samples; where no cubic gets within the chord tolerance,
//! the polyline through the samples.

use crate::OffsetSegment;
use bspline::fit::fit_samples;
use curve::V2;
use numeric::subdivide::{depth_first, Decision};

/// Halvings of a spline's span before its offset polyline is taken as it is (2^16 chords).
const MAX_OFFSET_HALVINGS: usize = 16;

/// The degree of the fitted offsets.
const DEGREE: usize = 3;

/// Points where a fit is compared with the exact offset in each step between two samples.
const CHECKS_PER_STEP: usize = 8;

/// The share of the chord tolerance a fit or a polyline is held to where measured: between
/// the points measured it may stray a little farther (3 % was seen on random Bézier chains),
/// and held to half, it stays within the tolerance.
const FIT_SHARE: f64 = 0.5;

/// The offset piece of `point` (the exact offset, at profile parameters) from `from` to `to`,
/// within `chord` of it where measured, and the largest distance measured.
pub(crate) fn spline_offset(
    point: &dyn Fn(f64) -> V2,
    from: f64,
    to: f64,
    chord: f64,
) -> (OffsetSegment, f64) {
    let (params, polyline_error) = polyline_parameters(point, from, to, FIT_SHARE * chord);
    // (The polyline's vertices and the middles of its chords: samples enough for the cubic's
    // knots wherever the polyline needed vertices.)
    let mut u = Vec::with_capacity(2 * params.len());
    for w in params.windows(2) {
        u.extend([w[0], 0.5 * (w[0] + w[1])]);
    }
    u.push(to);
    let samples: Vec<[f64; 2]> = u.iter().map(|&v| point(v).arr()).collect();
    let t: Vec<f64> = u.iter().map(|&v| (v - from) / (to - from)).collect();
    let deviation =
        |_: usize, s: f64, p: [f64; 2]| (V2::from_arr(p) - point(from + s * (to - from))).norm();
    match fit_samples(
        &samples,
        &t,
        DEGREE,
        FIT_SHARE * chord,
        CHECKS_PER_STEP,
        &deviation,
    ) {
        Some(fit) => (
            OffsetSegment::BSpline {
                degree: fit.degree,
                knots: fit.knots,
                points: fit.points,
            },
            fit.error,
        ),
        None => {
            let points: Vec<[f64; 2]> = params.iter().map(|&v| point(v).arr()).collect();
            let knots = polyline_knots(&params);
            (
                OffsetSegment::BSpline {
                    degree: 1,
                    knots,
                    points,
                },
                polyline_error,
            )
        }
    }
}

/// The clamped knots of degree 1 of a polyline with vertices at `params`, on `[0, 1]`.
fn polyline_knots(params: &[f64]) -> Vec<f64> {
    let (from, to) = (params[0], params[params.len() - 1]);
    let mut knots = vec![0.0];
    knots.extend(params.iter().map(|&v| (v - from) / (to - from)));
    knots.push(1.0);
    knots
}

/// The parameters of a polyline on the offset from `from` to `to` whose chords are within
/// `chord` of it at each chord's middle and quarter points (measured, halving where they are
/// not), and the largest distance measured.
fn polyline_parameters(
    point: &dyn Fn(f64) -> V2,
    from: f64,
    to: f64,
    chord: f64,
) -> (Vec<f64>, f64) {
    let mut params = vec![from];
    let mut error = 0.0f64;
    depth_first((from, to), MAX_OFFSET_HALVINGS, |(a, b), visit| {
        let (pa, pb) = (point(a), point(b));
        let off = |t: f64| {
            let p = point(a + (b - a) * t);
            curve::distance_to_segment(p.arr(), pa.arr(), pb.arr())
        };
        let deviation = off(0.25).max(off(0.5)).max(off(0.75));
        if deviation > chord && visit.can_halve {
            let m = 0.5 * (a + b);
            Decision::<_, ()>::Halve((a, m), (m, b))
        } else {
            error = error.max(deviation);
            params.push(b);
            Decision::Decided
        }
    });
    (params, error)
}
