//! The nearest point of a profile to a point in the plane, global: segments nearest first
//! (those whose control-point box is no nearer than a point already found are passed over),
//! and in each segment a branch and bound on its Bézier pieces, the hull of a piece's
//! control points bounding its distance from below and Newton's method on
//! `⟨C − x, C'⟩ = 0` polishing the point found. No point of the curve is nearer than the
//! point found by more than the rounding of the coordinates and of the pieces' coefficients,
//! where the search ends within its bounds (a piece count and a depth no ordinary drawing
//! reaches).

use crate::pieces::{append_halves, hull_distance, ControlPoints};
use curve::piece_bounds::{box_distance, coefficient_error, Errors};
use curve::{OwnParam, ParamCurve, Profile, Segment, SplineCurve, V2};
use numeric::rounding::ulps;
use std::f64::consts::TAU;

/// Newton steps from a piece's middle.
const NEAREST_NEWTON_STEPS: usize = 20;

/// How much nearer than the point found (relative to the coordinates' magnitude) a piece's
/// hull must come, beyond the rounding its control points may hide, to be halved further:
/// the distances' own rounding, a few units of the coordinates (a point of the curve is
/// evaluated to about that).
const NEAREST_SLACK: f64 = ulps(64.0);

/// Halvings of one Bézier piece at most: 2^-40 of a piece is far below what the slack
/// resolves about a minimum (the hull's distance closes on the curve's quadratically).
const MAX_NEAREST_DEPTH: usize = 40;

/// Pieces looked at in one search of a segment at most (a guard: a segment running along a
/// circle about `x` keeps every piece within the slack).
const MAX_NEAREST_PIECES: usize = 4096;

/// A foot: the nearest point of a profile to a point of the plane (an axis point's, a
/// bisector point's), found by [`crate::NearestPoint`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Foot {
    /// Its distance.
    pub distance: f64,
    /// Its profile parameter.
    pub u: f64,
}

/// [`crate::NearestPoint::nearest`].
pub(crate) fn nearest(profile: &Profile, x: [f64; 2], enough: f64) -> Foot {
    let x = V2::from_arr(x);
    let mut best = Foot {
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
        if let Some((d, v)) = nearest_on(&profile.segments()[i], x, best.distance) {
            best = Foot {
                distance: d,
                u: profile.profile_param(i, v),
            };
            done = d < enough;
        }
        // (Once near enough, no node is nearer than minus infinity: the search ends.)
        if done {
            f64::NEG_INFINITY
        } else {
            best.distance
        }
    });
    best
}

/// [`crate::NearestPoint::nearest_near`].
pub(crate) fn nearest_near(profile: &Profile, x: [f64; 2], u: f64) -> Foot {
    let (i, _) = profile.locate(u);
    let x = V2::from_arr(x);
    let u = polish(profile, x, u, i as f64, (i + 1) as f64);
    Foot {
        distance: (profile.jet_to(u, 0).p - x).norm(),
        u,
    }
}

/// The nearest point of one segment to `x` if it is nearer than `beat` (less the slack): its
/// distance and the segment's own parameter. Branch and bound on the segment's Bézier
/// pieces, nearest bound first: a piece whose hull is proven no nearer than the best point
/// found less the slack is passed over, and with it every piece left (their bounds are no
/// nearer); any other is halved; a piece whose middle comes nearer than the best point
/// found is polished there by Newton's method, so the bound closes on the nearest local
/// minimum at once and the halvings only have to exclude the rest. (Depth first, the
/// pieces about a centre of curvature of the curve, where the distance is flat to third
/// order, were halved until the piece bound ran out before the nearer pieces were reached.)
fn nearest_on(s: &Segment, x: V2, beat: f64) -> Option<(f64, f64)> {
    let c = s.curve();
    let found = if let Some([p, q]) = c.curve().straight_ends() {
        Some(nearest_on_straight(c, [p[0], p[1]], [q[0], q[1]], x))
    } else if let (Some((center, _)), OwnParam::Arc { .. }) = (s.circle(), s.own_param()) {
        Some(nearest_on_arc(s, V2::from_arr(center), x))
    } else {
        nearest_by_pieces(c, x, beat)
    };
    found.filter(|f| f.0 < beat)
}

/// The nearest point of a circular arc to `x`, in closed form: where the ray from the
/// centre through `x` meets the arc, or else the nearer end (the distance grows with the
/// angle from that ray). Every point is as near to the centre itself: the start is taken.
/// Distances are the curve's own at the parameters found, and the ends are always weighed,
/// so a ray at an end within the angle's rounding loses nothing.
fn nearest_on_arc(s: &Segment, center: V2, x: V2) -> (f64, f64) {
    let c = s.curve();
    let (a, b) = c.domain();
    let dist = |u: f64| (c.jet_to(u, 0).p - x).norm();
    let ends = [(dist(a), a), (dist(b), b)];
    let nearer = |m: (f64, f64), e: (f64, f64)| if e.0 < m.0 { e } else { m };
    let best = nearer(ends[0], ends[1]);
    let (v, from) = (x - center, s.start() - center);
    let (own_from, own_to) = s.own_domain();
    let sweep = match s.own_param() {
        OwnParam::Arc {
            pieces,
            piece_sweep,
        } => pieces as f64 * piece_sweep.abs(),
        _ => return best,
    };
    // (The way the arc runs from its tangent: a mirrored or reversed arc keeps the sweep
    // it was defined with, whose sign then no longer says it.)
    let way = from.cross(c.jet_to(a, 1).d1);
    if v.norm() == 0.0 || sweep == 0.0 || way == 0.0 {
        return best;
    }
    // (The angle from the start to the ray, the way the arc runs, in [0, 2π).)
    let turn = (from.cross(v).atan2(from.dot(v)) * way.signum()).rem_euclid(TAU);
    if turn > sweep {
        return best;
    }
    let own = own_from + turn / sweep * (own_to - own_from);
    let u = s.own_param().form(own, (a, b)).clamp(a, b);
    nearer(best, (dist(u), u))
}

/// The nearest point of a straight segment from `p` to `q` to `x`, in closed form: the
/// squared distance is a convex quadratic in the parameter, least at the projection on the
/// line, clamped to the ends. Its distance is the curve's own at the parameter found, as the
/// search's is.
fn nearest_on_straight(c: &SplineCurve, p: [f64; 2], q: [f64; 2], x: V2) -> (f64, f64) {
    let (a, b) = c.domain();
    let d = V2::from_arr(q) - V2::from_arr(p);
    let len2 = d.dot(d);
    let along = if len2 > 0.0 {
        ((x - V2::from_arr(p)).dot(d) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let u = (a + along * (b - a)).clamp(a, b);
    ((c.jet_to(u, 0).p - x).norm(), u)
}

/// [`nearest_on`] by branch and bound, on any segment.
fn nearest_by_pieces(c: &SplineCurve, x: V2, beat: f64) -> Option<(f64, f64)> {
    let pieces = c.bezier_pieces();
    let dim = pieces.dim();
    let dist = |u: f64| (c.jet_to(u, 0).p - x).norm();
    let (a, b) = c.domain();
    let mut best = [(dist(a), a), (dist(b), b)]
        .into_iter()
        .fold((f64::INFINITY, a), |m, e| if e.0 < m.0 { e } else { m });
    // (One bound on the coefficients' errors for all the pieces: the largest.)
    let given = c.curve().coefficient_error();
    let err = (0..pieces.pieces())
        .map(|k| coefficient_error(pieces, k, given))
        .fold(
            Errors {
                point: 0.0,
                weight: 0.0,
            },
            |m, e| Errors {
                point: m.point.max(e.point),
                weight: m.weight.max(e.weight),
            },
        );
    // A piece's key: its proven bound (the hull's distance less what rounding may hide) less
    // the slack; a piece whose key is no nearer than the point found is passed over: a point
    // of it nearer by less is within rounding of the point found. (Without the room, the
    // pieces about the point found, within rounding of it themselves, would be halved to the
    // depth bound.) A weight that may not be positive bounds nothing: such a piece is halved.
    let key = |coefs: &[f64], depth: usize| {
        let control = ControlPoints::of(coefs, dim, x);
        if control.w_min > 2.0 * err.weight {
            let room = err.room(control.w_min, control.mag, depth);
            hull_distance(&control.pts, x) + room - NEAREST_SLACK * control.mag
        } else {
            f64::NEG_INFINITY
        }
    };
    let mut queue = Queue::default();
    for k in 0..pieces.pieces() {
        let (lo, hi) = pieces.piece_span(k);
        let coefs = pieces.piece(k);
        queue.push(coefs, key(coefs, 0), lo, hi, 0);
    }
    let (mut current, mut work) = (Vec::new(), Vec::new());
    let mut tested = 0;
    while let Some(q) = queue.pop(&mut current) {
        if q.key >= best.0.min(beat) {
            break;
        }
        tested += 1;
        if tested > MAX_NEAREST_PIECES {
            break;
        }
        let mid = 0.5 * (q.lo + q.hi);
        let at_mid = dist(mid);
        if at_mid < best.0 {
            let u = polish(c, x, mid, q.lo, q.hi);
            let d = dist(u);
            best = if d < at_mid { (d, u) } else { (at_mid, mid) };
        }
        if q.depth < MAX_NEAREST_DEPTH {
            let halves = queue.halves(&current, dim, &mut work);
            let depth = q.depth + 1;
            let len = current.len();
            let (second, first) = (halves, halves + len);
            let key_of = |queue: &Queue, at: usize| key(&queue.coefs[at..at + len], depth);
            let (k2, k1) = (key_of(&queue, second), key_of(&queue, first));
            queue.enqueue(second, k2, mid, q.hi, depth);
            queue.enqueue(first, k1, q.lo, mid, depth);
        }
    }
    (best.0 < beat).then_some(best)
}

/// A piece waiting in [`Queue`]: its key, where its coefficients start in the queue's
/// buffer, its interval and its depth.
#[derive(Debug, Clone, Copy)]
struct Queued {
    key: f64,
    at: usize,
    lo: f64,
    hi: f64,
    depth: usize,
}

impl PartialEq for Queued {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == std::cmp::Ordering::Equal
    }
}

impl Eq for Queued {}

impl PartialOrd for Queued {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

/// The least key first (a max-heap of the reversed order); among equal keys, the piece
/// queued first.
impl Ord for Queued {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other
            .key
            .total_cmp(&self.key)
            .then_with(|| other.at.cmp(&self.at))
    }
}

/// The pieces still to test, least key first, their coefficients in one buffer (appended
/// to, never moved: a search tests at most [`MAX_NEAREST_PIECES`] pieces).
#[derive(Default)]
struct Queue {
    coefs: Vec<f64>,
    heap: std::collections::BinaryHeap<Queued>,
    /// Coefficients per piece (the same for all pieces of a segment).
    len: usize,
}

impl Queue {
    fn push(&mut self, coefs: &[f64], key: f64, lo: f64, hi: f64, depth: usize) {
        self.len = coefs.len();
        let at = self.coefs.len();
        self.coefs.extend_from_slice(coefs);
        self.enqueue(at, key, lo, hi, depth);
    }

    /// Queues the piece whose coefficients are already in the buffer at `at`.
    fn enqueue(&mut self, at: usize, key: f64, lo: f64, hi: f64, depth: usize) {
        self.heap.push(Queued {
            key,
            at,
            lo,
            hi,
            depth,
        });
    }

    /// The piece of the least key, its coefficients copied into `into`.
    fn pop(&mut self, into: &mut Vec<f64>) -> Option<Queued> {
        let q = self.heap.pop()?;
        into.clear();
        into.extend_from_slice(&self.coefs[q.at..q.at + self.len]);
        Some(q)
    }

    /// The halves of `coefs` appended to the buffer (the second, then the first); where
    /// the second starts.
    fn halves(&mut self, coefs: &[f64], dim: usize, work: &mut Vec<f64>) -> usize {
        let at = self.coefs.len();
        append_halves(coefs, dim, work, &mut self.coefs);
        at
    }
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

    /// A straight segment's closed form against the branch and bound of every other
    /// segment, on random lines (short, long, far from the origin) and points about them:
    /// the same distance to rounding, attained at the parameter found, and the points no
    /// farther apart than a flat minimum allows.
    #[test]
    fn a_straight_segments_closed_form_is_the_searchs_point() {
        let mut rnd = testkit::rng(42);
        for case in 0..2000 {
            let scale = 2f64.powi(case % 41 - 20);
            let far = if case % 3 == 0 { 1e4 * scale } else { 0.0 };
            let mut at = || {
                [
                    far + scale * (2.0 * rnd() - 1.0),
                    scale * (2.0 * rnd() - 1.0),
                ]
            };
            let (p, q, x) = (at(), at(), at());
            let Ok(line) = Segment::line(p, q) else {
                continue;
            };
            let c = line.curve();
            let x = V2::from_arr(x);
            let (d, u) = nearest_on_straight(c, p, q, x);
            let (want, v) = nearest_by_pieces(c, x, f64::INFINITY).unwrap();
            let rounding = 1e-13 * (scale + far);
            testkit::assert_near!(d, want, rounding, "case {case}");
            testkit::assert_near!((c.jet_to(u, 0).p - x).norm(), d, rounding);
            let (a, b) = c.domain();
            assert!((a..=b).contains(&u), "case {case}: {u} off [{a}, {b}]");
            let apart = (c.jet_to(u, 0).p - c.jet_to(v, 0).p).norm();
            assert!(apart <= 1e-6 * (scale + far), "case {case}: {apart}");
        }
    }

    /// An arc's closed form against the branch and bound, on random arcs (either way round,
    /// small and whole turns, small, huge and far from the origin) and points inside and
    /// outside their circles, the centre among them: the same distance to rounding, attained
    /// at the parameter found.
    #[test]
    fn an_arcs_closed_form_is_the_searchs_point() {
        let mut rnd = testkit::rng(43);
        for case in 0..2000 {
            let scale = 2f64.powi(case % 41 - 20);
            let far = if case % 3 == 0 { 1e4 * scale } else { 0.0 };
            let center = [far + scale * rnd(), scale * rnd()];
            let r = scale * (0.1 + rnd());
            let start = TAU * (2.0 * rnd() - 1.0);
            let sweep = match case % 5 {
                0 => TAU,
                1 => -TAU,
                _ => TAU * (2.0 * rnd() - 1.0),
            };
            let Ok(arc) = Segment::arc(center, r, start, start + sweep) else {
                continue;
            };
            // (Reversed and mirrored arcs keep the sweep they were defined with.)
            let arc = match case % 4 {
                0 => arc.reversed().unwrap(),
                // (x ↦ 2 c_x − x: mirrored in the vertical line through the centre.)
                1 => {
                    let mirror = curve::Affine([-1.0, 0.0, 0.0, 1.0, 2.0 * center[0], 0.0]);
                    arc.transformed(&mirror).unwrap()
                }
                _ => arc,
            };
            let x = if case % 7 == 0 {
                V2::from_arr(center)
            } else {
                let (a, l) = (TAU * rnd(), 2.5 * r * rnd());
                V2::from_arr(center) + V2::new(a.cos(), a.sin()) * l
            };
            let c = arc.curve();
            let (d, u) = nearest_on_arc(&arc, V2::from_arr(center), x);
            let (want, _) = nearest_by_pieces(c, x, f64::INFINITY).unwrap();
            let rounding = 1e-13 * (scale + far);
            testkit::assert_near!(d, want, rounding, "case {case}");
            testkit::assert_near!((c.jet_to(u, 0).p - x).norm(), d, rounding);
        }
    }
}
