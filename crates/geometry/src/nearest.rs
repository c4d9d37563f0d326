//! The nearest point of a profile to a point in the plane: per segment, dense samples and
//! Newton's method on `⟨C − x, C'⟩ = 0` from every sampled local minimum, the segment's ends
//! included; segments whose control-point box is no nearer than a point already found are
//! skipped. A sampled search: a feature narrower than the sampling can be missed.

use curve::piece_bounds::box_distance;
use curve::ParamCurve;
use curve::Profile;
use curve::Segment;
use curve::V2;
use numeric::minimize::{minimize, Bracket, Limits};
use std::ops::ControlFlow;

/// Samples per Bézier piece of a segment's exact form.
const SAMPLES_PER_PIECE: usize = 32;

/// Newton steps from a sampled minimum.
const NEAREST_NEWTON_STEPS: usize = 20;

/// The minimisation on a window of two sample steps closes it to this share of it (0.618⁴⁸,
/// what 48 golden sections leave): Newton's polish takes over from there, and where it cannot
/// (a flat distance, near a centre of curvature) the parameter matters to the distance only
/// far below rounding.
const NEAREST_BRACKET: f64 = 1e-10;

/// Evaluations of the distance in the minimisation on a window: golden sections alone close
/// it to [`NEAREST_BRACKET`] within 48 (with the middle at a golden section) to 52.
const NEAREST_MIN_STEPS: usize = 96;

/// A parabolic step nearer the bracket's middle than this share of it is a golden section
/// instead ([`Limits::parabola_min_move`]): it keeps the parabola from creeping.
const NEAREST_PARABOLA_MOVE: f64 = 0.1;

/// The nearest point found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// Its distance.
    pub distance: f64,
    /// Its profile parameter.
    pub u: f64,
}

/// [`crate::NearestPoint::nearest`].
pub(crate) fn nearest(profile: &Profile, x: [f64; 2], enough: f64) -> Nearest {
    let x = V2::from_arr(x);
    let mut best = Nearest {
        distance: f64::INFINITY,
        u: 0.0,
    };
    // Nearest boxes first: once a point is found, every segment whose box is no nearer
    // is passed over.
    let mut done = false;
    profile.box_tree().nearest_first(x, |i| {
        if done || box_distance(profile.segment_box(i), x) >= best.distance {
            return f64::INFINITY;
        }
        let (d, v) = nearest_on(&profile.segments()[i], x);
        if d < best.distance {
            best = Nearest {
                distance: d,
                u: profile.profile_param(i, v),
            };
            done = d < enough;
        }
        // (Once near enough, no node is nearer than minus infinity: the search ends.)
        if done {
            f64::NEG_INFINITY
        } else {
            d
        }
    });
    best
}

/// [`crate::NearestPoint::nearest_near`].
pub(crate) fn nearest_near(profile: &Profile, x: [f64; 2], u: f64) -> Nearest {
    let (i, _) = profile.locate(u);
    let x = V2::from_arr(x);
    let u = polish(profile, x, u, i as f64, (i + 1) as f64);
    Nearest {
        distance: (profile.jet_to(u, 0).p - x).norm(),
        u,
    }
}

/// The nearest point of one segment: its distance and the segment's own parameter.
fn nearest_on(s: &Segment, x: V2) -> (f64, f64) {
    let c = s.curve();
    let (a, b) = c.domain();
    let n = SAMPLES_PER_PIECE * c.piece_count().max(1);
    let at = |k: usize| {
        if k == n {
            b
        } else {
            a + (b - a) * k as f64 / n as f64
        }
    };
    let dist = |u: f64| (c.jet_to(u, 0).p - x).norm();
    let ds: Vec<f64> = (0..=n).map(|k| dist(at(k))).collect();
    let mut best = (f64::INFINITY, a);
    for k in 0..=n {
        // A sampled minimum, the ends included (the nearest point may lie between an end
        // sample and its neighbour).
        let below = |j: Option<usize>| j.is_none_or(|j| ds[k] <= ds[j]);
        if !(below(k.checked_sub(1)) && below((k < n).then_some(k + 1))) {
            continue;
        }

        let (lo, hi) = (k.saturating_sub(1), (k + 1).min(n));
        // The sampled minimum and its neighbours bracket a minimum: numeric's minimisation
        // closes the bracket first (near a centre of curvature the distance is flat and
        // Newton's step has no sign to go by); then Newton's method polishes where the
        // distance is convex.
        let bracket = Bracket {
            lo: (at(lo), ds[lo]),
            mid: (at(k), ds[k]),
            hi: (at(hi), ds[hi]),
        };
        let (lo, hi) = (at(lo), at(hi));
        let limits = Limits {
            width: NEAREST_BRACKET * (hi - lo),
            max_steps: NEAREST_MIN_STEPS,
            parabola_min_move: NEAREST_PARABOLA_MOVE,
        };
        let found = match minimize(|u| ControlFlow::<(), _>::Continue(dist(u)), bracket, limits) {
            ControlFlow::Continue(m) => m.bracket.mid.0,
            ControlFlow::Break(()) => at(k),
        };
        let u = polish(c, x, found, lo, hi);
        let d = dist(u);
        if d < best.0 {
            best = (d, u);
        }
        if ds[k] < best.0 {
            best = (ds[k], at(k));
        }
    }
    best
}

/// Newton's method on `⟨C − x, C'⟩ = 0` from `u` within `[lo, hi]`, kept only while it
/// brings the curve nearer ([`numeric::minimize::polish`] on the distance, with the
/// derivatives of half its square).
fn polish(c: &impl ParamCurve, x: V2, u: f64, lo: f64, hi: f64) -> f64 {
    let dist = |u: f64| (c.jet_to(u, 0).p - x).norm();
    let slope = |u: f64| {
        let j = c.jet_to(u, 2);
        let v = j.p - x;
        (v.dot(j.d1), j.d1.dot(j.d1) + v.dot(j.d2))
    };
    numeric::minimize::polish(dist, slope, u, (lo, hi), NEAREST_NEWTON_STEPS)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::NearestPoint;
    use curve::Segment;

    /// Against the exact distance to a closed chain of lines and a half circle, on random
    /// points near and far: the distance agrees to rounding and is attained at `u`.
    #[test]
    fn the_nearest_point_matches_the_exact_distance() {
        use std::f64::consts::FRAC_PI_2;
        let segs = vec![
            Segment::line([0.0, 0.0], [3.0, 0.0]).unwrap(),
            Segment::arc([3.0, 1.0], 1.0, -FRAC_PI_2, FRAC_PI_2).unwrap(),
            Segment::line([3.0, 2.0], [0.0, 2.0]).unwrap(),
            Segment::line([0.0, 2.0], [0.0, 0.0]).unwrap(),
        ];
        let p = Profile::new(segs, None).unwrap();
        let to_line = |x: [f64; 2], a: [f64; 2], b: [f64; 2]| {
            let (d, v) = ([b[0] - a[0], b[1] - a[1]], [x[0] - a[0], x[1] - a[1]]);
            let s = ((v[0] * d[0] + v[1] * d[1]) / (d[0] * d[0] + d[1] * d[1])).clamp(0.0, 1.0);
            (v[0] - s * d[0]).hypot(v[1] - s * d[1])
        };
        let exact = |x: [f64; 2]| {
            let v = [x[0] - 3.0, x[1] - 1.0];
            let arc = if v[0] >= 0.0 {
                (v[0].hypot(v[1]) - 1.0).abs()
            } else {
                (x[0] - 3.0).hypot(x[1]).min((x[0] - 3.0).hypot(x[1] - 2.0))
            };
            arc.min(to_line(x, [0.0, 0.0], [3.0, 0.0]))
                .min(to_line(x, [3.0, 2.0], [0.0, 2.0]))
                .min(to_line(x, [0.0, 2.0], [0.0, 0.0]))
        };
        let mut state = 12345u64;
        let mut rnd = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..2000 {
            let x = [-1.0 + 6.0 * rnd(), -1.0 + 4.0 * rnd()];
            let n = p.nearest(x, 0.0);
            let want = exact(x);
            testkit::assert_near!(n.distance, want, 1e-12, "{x:?}: {} vs {want}", n.distance);
            let q = p.jet_to(n.u, 0).p;
            testkit::assert_near!((q.x - x[0]).hypot(q.y - x[1]), n.distance, 1e-12);
        }
    }
}
