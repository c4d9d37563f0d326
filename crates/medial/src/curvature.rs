//! Where a boundary's curvature peaks between two points: where the feet of a branch close
//! in, the axis ends at the centre of curvature there.

use curve::{Jet, ParamCurve, Profile};
use numeric::rounding::Bounded;
use numeric::solve::{bracketed_free, Accuracy};

/// The width a curvature extremum is found to, as a share of the gap between the points
/// it lies between (2^-60, as many halvings once took): below the parameter's rounding
/// for any gap, so the solve closes on neighbouring doubles.
const EXTREMUM_WIDTH: f64 = 1.0 / (1u64 << 60) as f64;

/// Steps of each segment's stretch of a window on which the curvature's rate is sampled
/// for its changes from rising to falling: a cubic's curvature may have two maxima in one
/// segment, with a minimum between.
const PEAK_STEPS: usize = 8;

/// Where `f` changes sign between `a` and `b` (of different signs; 0 counts as positive, as
/// [`f64::signum`] has it, and NaN as the sign `b` has), by the derivative-free bracketed
/// solve ([`bracketed_free`]) to [`EXTREMUM_WIDTH`] of the gap.
pub(crate) fn sign_change(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let at_a = f(a).signum();
    // Turned so that `a`'s side is negative and the other side (NaN too) positive, never 0
    // (a zero's side is its sign bit's).
    let turned = |x: f64| {
        let v = f(x);
        let size = v.abs().max(f64::MIN_POSITIVE);
        if v.signum() == at_a {
            -size
        } else {
            size
        }
    };
    let ends = (turned(a), turned(b));
    let width = EXTREMUM_WIDTH * (b - a).abs();
    bracketed_free(turned, (a, b), ends, Accuracy::param(width))
}

/// The peak of the curvature's magnitude inside `[a, b]` along `boundary` (on a closed
/// boundary the parameters may run past its ends), with the jet there: the largest of the
/// maxima inside its segments (where the magnitude's rate, sampled at `PEAK_STEPS` steps of
/// each segment's stretch, changes from rising to falling)
/// and of the one-sided values at the joints between them. At a smooth joint where the
/// curvature jumps the peak is the larger side's value, and the jet is that side's.
/// `None` where the largest value is at `a` or `b` (the peak lies beyond them).
pub(crate) fn curvature_peak(boundary: &Profile, a: f64, b: f64) -> Option<(f64, Jet)> {
    let segments = boundary.segments().len();
    let period = segments as f64;
    // The joints inside (a, b): at most one a segment round a closed boundary, so the
    // window holds at most that many and a turn more.
    let mut cuts = vec![a];
    cuts.extend(
        (1..=2 * segments + 1)
            .map(|k| a.floor() + k as f64)
            .take_while(|&j| j < b),
    );
    cuts.push(b);
    // (magnitude, inside the window, parameter, jet); an inside value wins a tie with the
    // window's ends (at a joint met by both feet the ends are within rounding of it).
    let mut best: Option<(f64, bool, f64, Jet)> = None;
    let mut offer = |u: f64, j: Jet, inside: bool| {
        let k = j.curvature().abs();
        if k.is_nan() {
            return;
        }
        if best
            .as_ref()
            .is_none_or(|&(m, i, _, _)| k > m || (k == m && inside && !i))
        {
            best = Some((k, inside, u, j));
        }
    };
    for w in cuts.windows(2) {
        let (t0, t1) = (w[0], w[1]);
        let whole = (0.5 * (t0 + t1)).floor();
        let seg = if boundary.is_closed() {
            (whole as i64).rem_euclid(segments as i64) as usize
        } else {
            (whole.max(0.0) as usize).min(segments - 1)
        };
        let shift = whole - seg as f64;
        let jet = |t: f64| boundary.jet_on(seg, t - shift, 3);
        let rising = |t: f64| {
            let j = jet(t);
            j.curvature().signum() * j.curvature_rate()
        };
        offer(t0, jet(t0), t0 > a);
        offer(t1, jet(t1), t1 < b);
        let steps: Vec<(f64, f64)> = (0..=PEAK_STEPS)
            .map(|k| {
                let s = t0 + (t1 - t0) * k as f64 / PEAK_STEPS as f64;
                (s, rising(s))
            })
            .collect();
        for w in steps.windows(2) {
            let ((s0, r0), (s1, r1)) = (w[0], w[1]);
            if s1 > s0 && r0 > 0.0 && r1 <= 0.0 {
                let u = sign_change(&rising, s0, s1);
                offer(u, jet(u), true);
            }
        }
    }
    let (_, inside, u, j) = best?;
    inside.then(|| (u.rem_euclid(period), j))
}

/// The sign of the rate of the curvature's magnitude along segment `i` of `boundary` at
/// profile parameter `u` (+1 where it rises as `u` grows), where bounds on the rounding prove
/// it: from the segment's exact homogeneous form `H = (X, Y, w)` with bounded coefficients,
/// its derivatives at `u` with their errors, and the rate's numerator in them carried by
/// [`Bounded`] arithmetic.
///
/// With `P = (X, Y)`, `Q = wP′ − w′P` (the tangent's numerator), `D = det[H, H′, H″]` and
/// `D′ = det[H, H′, H‴]`, the curvature is `D w³ / |Q|³`, and `d ln|κ| / du` has the sign of
/// `D · R` with `R = D′ w |Q|² + 3 w′ D |Q|² − 3 D w (Q · Q′)` (for `w > 0`).
pub(crate) fn proven_rate_sign(boundary: &Profile, i: usize, u: f64) -> Option<f64> {
    let curve = boundary.segments()[i].curve();
    let hom = curve.exact_pieces().hom;
    let (a, b) = curve.domain();
    let v = a + (u - i as f64).clamp(0.0, 1.0) * (b - a);
    let piece = hom.piece_at(v);
    let mut jet = [0.0; 12];
    hom.eval_derivs(v, 3, &mut jet);
    let h = |k: usize, c: usize| Bounded::new(jet[3 * k + c], hom.eval_error_of(piece, k, c));
    let w: Vec<Bounded> = (0..4).map(|k| h(k, 2)).collect();
    if w[0].sign() != Some(1.0) {
        return None;
    }
    // Moved to the curve's point there (exactly the same rate: D, Q and R do not change
    // when P becomes P − c w), so that the products do not carry the coordinates' size.
    let c = [jet[0] / jet[2], jet[1] / jet[2]];
    let p: Vec<[Bounded; 2]> = (0..4)
        .map(|k| {
            let moved = |x: usize| h(k, x).sub(Bounded::exact(c[x]).mul(w[k]));
            [moved(0), moved(1)]
        })
        .collect();
    let cross = |a: [Bounded; 2], b: [Bounded; 2]| a[0].mul(b[1]).sub(a[1].mul(b[0]));
    let dot = |a: [Bounded; 2], b: [Bounded; 2]| a[0].mul(b[0]).add(a[1].mul(b[1]));
    let lin = |s: Bounded, a: [Bounded; 2], t: Bounded, b: [Bounded; 2]| {
        [s.mul(a[0]).sub(t.mul(b[0])), s.mul(a[1]).sub(t.mul(b[1]))]
    };
    let det = |third: usize| {
        w[0].mul(cross(p[1], p[third]))
            .sub(w[1].mul(cross(p[0], p[third])))
            .add(w[third].mul(cross(p[0], p[1])))
    };
    let (d, d_rate) = (det(2), det(3));
    let q = lin(w[0], p[1], w[1], p[0]);
    let q_rate = lin(w[0], p[2], w[2], p[0]);
    let q2 = dot(q, q);
    let three = Bounded::exact(3.0);
    let r = d_rate
        .mul(w[0])
        .mul(q2)
        .add(three.mul(w[1]).mul(d).mul(q2))
        .sub(three.mul(d).mul(w[0]).mul(dot(q, q_rate)));
    Some(d.sign()? * r.sign()?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use curve::{Segment, SegmentKind, SplineCurve};
    use proptest::prelude::*;

    /// A closed chain of cubics with tangent-continuous joints (the curvature jumps there).
    fn smooth_chain(points: &[[f64; 2]]) -> Option<Profile> {
        let n = points.len();
        let at = |i: usize| points[i % n];
        let mid = |a: [f64; 2], b: [f64; 2]| [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        let segs = (0..n)
            .map(|i| {
                let (p, q, r) = (at(i), at(i + 1), at(i + 2));
                let pts = [mid(p, q), q, mid(q, r)];
                // A quadratic lifted to a cubic with its middle points pulled apart.
                let c1 = [
                    pts[0][0] + 0.6 * (q[0] - pts[0][0]),
                    pts[0][1] + 0.6 * (q[1] - pts[0][1]),
                ];
                let c2 = [
                    pts[2][0] + 0.6 * (q[0] - pts[2][0]),
                    pts[2][1] + 0.6 * (q[1] - pts[2][1]),
                ];
                let c = SplineCurve::clamped(3, &[pts[0], c1, c2, pts[2]], None, None).ok()?;
                Segment::spline(SegmentKind::Bezier, c).ok()
            })
            .collect::<Option<Vec<_>>>()?;
        Profile::new(segs, None).ok()
    }

    /// The largest |κ| on `[a, b]` by dense sampling, each segment's stretch on its own side
    /// of the joints, and whether it is at `a` or `b`.
    fn sampled_peak(p: &Profile, a: f64, b: f64) -> (f64, f64) {
        let n = p.segments().len();
        let mut best = (0.0f64, a);
        let steps = 4000;
        for k in 0..=steps {
            let u = a + (b - a) * k as f64 / steps as f64;
            let seg = (u.floor() as usize).min(n - 1);
            for s in [seg, seg.saturating_sub(1)] {
                if u >= s as f64 && u <= (s + 1) as f64 {
                    let kappa = p.jet_on(s, u, 2).curvature().abs();
                    if kappa > best.0 {
                        best = (kappa, u);
                    }
                }
            }
        }
        best
    }

    proptest! {
        /// The peak is the sampled largest |κ| (never below it), inside the window; where it
        /// is `None` the sampled largest is at an end of the window.
        #[test]
        fn the_peak_is_the_sampled_largest_curvature(
            radii in proptest::collection::vec(1.0f64..2.0, 5..8),
            from in 0.0f64..1.0,
            width in 0.01f64..0.99,
        ) {
            let n = radii.len();
            let points: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let t = std::f64::consts::TAU * i as f64 / n as f64;
                    [radii[i] * t.cos(), radii[i] * t.sin()]
                })
                .collect();
            let Some(p) = smooth_chain(&points) else { return Ok(()) };
            let len = n as f64;
            let (a, b) = (from * len * 0.5, (from * 0.5 + width * 0.5) * len);
            let (top, at) = sampled_peak(&p, a, b);
            match curvature_peak(&p, a, b) {
                Some((u, j)) => {
                    prop_assert!(u >= a - 1e-12 && u <= b + 1e-12);
                    let k = j.curvature().abs();
                    prop_assert!(k >= top * (1.0 - 1e-9), "{k} below the sampled {top} at {at}");
                    let q = p.jet(u).p.arr();
                    prop_assert!((j.p.arr()[0] - q[0]).hypot(j.p.arr()[1] - q[1]) < 1e-9);
                }
                None => {
                    let step = (b - a) / 4000.0;
                    prop_assert!((at - a).abs() <= step || (at - b).abs() <= step,
                        "no peak, yet the sampled largest {top} is at {at} in [{a}, {b}]");
                }
            }
        }
    }

    proptest! {
        /// Where the bounds prove the sign of the curvature's rate, |κ| moves that way:
        /// central differences of the jets' curvature an eighth of a millionth apart agree
        /// wherever they are clear of their rounding; on rational cubics (weights 0.2 to 5)
        /// far from the origin, and most signs are proven.
        #[test]
        fn a_proven_rate_sign_is_the_way_the_curvature_moves(
            points in proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 4),
            weights in proptest::collection::vec(0.2f64..5.0, 4),
            far in prop_oneof![Just(0.0), Just(1e3), Just(1e6)],
            at in proptest::collection::vec(0.02f64..0.98, 16),
        ) {
            let pts: Vec<[f64; 2]> = points
                .iter()
                .enumerate()
                .map(|(i, &(x, y))| [far + i as f64 + 0.5 * x, -far + y])
                .collect();
            let c = SplineCurve::clamped(3, &pts, Some(&weights), None).unwrap();
            let Ok(seg) = Segment::spline(SegmentKind::Bezier, c) else { return Ok(()) };
            let Ok(p) = Profile::new(vec![seg], Some(false)) else { return Ok(()) };
            let kappa = |u: f64| p.jet_on(0, u, 2).curvature().abs();
            let (mut proven, mut clear) = (0, 0);
            for &u in &at {
                let h = 1.25e-7;
                let change = kappa(u + h) - kappa(u - h);
                // (The jets' rounding, far from the origin: ~1e-16 of the coordinates over
                // the speed, twice, relative to the curvature.)
                let noise = 1e-12 * (1.0 + far) * kappa(u).max(1.0);
                let Some(sign) = proven_rate_sign(&p, 0, u) else { continue };
                proven += 1;
                if change.abs() > noise {
                    clear += 1;
                    prop_assert_eq!(sign, change.signum(), "at {}: change {:e}", u, change);
                }
            }
            prop_assert!(
                far > 0.0 || (proven >= at.len() / 2 && clear > 0),
                "{proven} of {} proven, {clear} compared",
                at.len()
            );
        }
    }
}
