//! Whether a chain of segments crosses itself: each segment flattened into a polyline within
//! [`FLATNESS`] of the profile's size, and the polylines' edges tested pairwise over a sweep
//! of their boxes. Two stretches that come closer than the flatness without crossing may be
//! judged either way; anything farther apart is judged right.

use crate::geom::V2;
use crate::param::ParamCurve;
use crate::segment::Segment;
use std::f64::consts::{PI, TAU};

/// How far (relative to the profile's size) a flattened edge may stray from its segment.
pub(crate) const FLATNESS: f64 = 1e-7;

/// Samples per Bézier piece a segment starts its flattening with (a wiggle narrower than an
/// eighth of a piece and shallower than the flatness can escape it).
const FIRST_SAMPLES: usize = 8;

/// Halvings of a parameter interval in the flattening.
const MAX_DEPTH: usize = 24;

/// A crossing: the two segments (of chains `chains`, the same for a chain crossing itself)
/// and a point where they meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Crossing {
    pub(crate) chains: (usize, usize),
    pub(crate) first: usize,
    pub(crate) second: usize,
    pub(crate) at: [f64; 2],
}

/// One edge of a flattened chain: its ends and its position along the chain.
#[derive(Debug, Clone, Copy)]
struct Edge {
    a: V2,
    b: V2,
    chain: usize,
    segment: usize,
    /// Index along its chain (neighbours share an end).
    index: usize,
}

/// A chain to test: its segments' polylines (from [`flattened`]) and whether its last
/// segment joins its first.
pub(crate) type Chain<'a> = (&'a [Vec<V2>], bool);

/// The polylines of `segments`, each within [`FLATNESS`] of `size` of its segment (and no
/// finer than the rounding of the coordinates), without repeated points.
pub(crate) fn flattened(segments: &[Segment], size: f64) -> Vec<Vec<V2>> {
    let delta = flatness(segments.iter(), size);
    segments
        .iter()
        .map(|s| {
            let mut points = flatten(s, delta);
            // (A repeated point would make its neighbours' edges touch without being
            // neighbours.)
            points.dedup();
            points
        })
        .collect()
}

/// The first crossing of a chain with itself (`closed`: its last segment joins its first).
pub(crate) fn first_crossing(polylines: &[Vec<V2>], closed: bool) -> Option<Crossing> {
    first_crossing_among(&[(polylines, closed)], false)
}

/// The first crossing among chains (first by chain, then by segment): of one with itself
/// or of two with each other, or only the latter (`apart`: each chain is known simple).
pub(crate) fn first_crossing_among(chains: &[Chain<'_>], apart: bool) -> Option<Crossing> {
    let mut edges = Vec::new();
    let mut lengths = Vec::with_capacity(chains.len());
    for (c, &(polylines, _)) in chains.iter().enumerate() {
        let start = edges.len();
        for (i, points) in polylines.iter().enumerate() {
            for (a, b) in points.windows(2).map(|w| (w[0], w[1])) {
                let index = edges.len() - start;
                edges.push(Edge {
                    a,
                    b,
                    chain: c,
                    segment: i,
                    index,
                });
            }
        }
        lengths.push(edges.len() - start);
    }
    let neighbours = |e: &Edge, f: &Edge| {
        let (n, closed) = (lengths[e.chain], chains[e.chain].1);
        let d = e.index.abs_diff(f.index);
        e.chain == f.chain && (d <= 1 || (closed && d == n - 1))
    };
    // Sweep along x over the edges' boxes.
    let lo_x = |e: &Edge| e.a.x.min(e.b.x);
    let hi_x = |e: &Edge| e.a.x.max(e.b.x);
    // (Keys beside the indices: the sort reads no edge. Any order of equal keys finds the
    // same first crossing.)
    let mut order: Vec<(f64, usize)> = edges.iter().map(lo_x).zip(0..).collect();
    order.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let mut active: Vec<usize> = Vec::new();
    let mut found: Option<Crossing> = None;
    for &(_, i) in &order {
        let e = edges[i];
        active.retain(|&j| hi_x(&edges[j]) >= lo_x(&e));
        for &j in &active {
            let f = edges[j];
            if neighbours(&e, &f) || (apart && e.chain == f.chain) {
                continue;
            }
            if let Some(at) = meet(e.a, e.b, f.a, f.b) {
                let (x, y) = if (e.chain, e.segment) <= (f.chain, f.segment) {
                    (e, f)
                } else {
                    (f, e)
                };
                let c = Crossing {
                    chains: (x.chain, y.chain),
                    first: x.segment,
                    second: y.segment,
                    at: at.arr(),
                };
                let key = |c: &Crossing| (c.chains, c.first, c.second);
                // (The first along the chains, whatever the sweep's order.)
                if found.is_none_or(|f| key(&c) < key(&f)) {
                    found = Some(c);
                }
            }
        }
        active.push(i);
    }
    found
}

/// The closed polygon of a closed chain's polylines (from [`flattened`]).
pub(crate) fn polygon(polylines: &[Vec<V2>]) -> Vec<V2> {
    let mut out: Vec<V2> = Vec::new();
    for pts in polylines {
        out.extend(pts.iter().skip(usize::from(!out.is_empty())));
    }
    out
}

/// The winding number of `polygon` (closed, last point joined to the first) about `p`.
pub(crate) fn winding(polygon: &[V2], p: V2) -> i32 {
    let n = polygon.len();
    let mut w = 0;
    for k in 0..n {
        let (a, b) = (polygon[k], polygon[(k + 1) % n]);
        let side = (b - a).cross(p - a);
        if a.y <= p.y {
            if b.y > p.y && side > 0.0 {
                w += 1;
            }
        } else if b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

/// The flattening tolerance for segments of `size`: [`FLATNESS`] of it, but never below what
/// the coordinates' rounding resolves (far from the origin a curve's points are known only
/// to a few units of rounding of their coordinates: finer chords never meet the tolerance and
/// the halving would run to its depth limit everywhere).
fn flatness<'s>(segments: impl Iterator<Item = &'s Segment>, size: f64) -> f64 {
    let magnitude = segments
        .flat_map(|s| s.curve().control_points())
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    (FLATNESS * size).max(FLAT_ROUNDING * magnitude)
}

/// Units of rounding of the largest coordinate below which a flattening's tolerance is noise.
const FLAT_ROUNDING: f64 = 64.0 * f64::EPSILON;

/// Most points of one segment's polyline: a bound on the work whatever the curve.
const MAX_POINTS: usize = 1 << 16;

/// The points of a polyline within `delta` of the segment (its chords' midpoints checked
/// against the curve, halving where they stray).
fn flatten(s: &Segment, delta: f64) -> Vec<V2> {
    let c = s.curve();
    let (a, b) = c.domain();
    if s.kind() == crate::segment::SegmentKind::Line {
        return vec![s.start(), s.end()];
    }
    if let Some((center, radius)) = s.circle() {
        return flatten_arc(s, V2::from_arr(center), radius, delta);
    }
    let pieces = c.control_points().len().max(2);
    let first = FIRST_SAMPLES * pieces;
    let at = |u: f64| c.jet_to(u, 0).p;
    let mut out = vec![at(a)];
    for k in 0..first {
        let (u0, u1) = (
            a + (b - a) * k as f64 / first as f64,
            a + (b - a) * (k + 1) as f64 / first as f64,
        );
        refine(&at, (u0, at(u0)), (u1, at(u1)), delta, 0, &mut out);
    }
    out
}

/// Parameter steps over which an arc's sweep is summed: each step turns by less than half a
/// turn (an arc turns at most a full turn, and its Bézier spans less than half of one).
const SWEEP_STEPS: usize = 8;

/// The polyline of an arc in closed form: points of its circle at equal angles, as many as
/// keep the sagitta `r (1 − cos(θ/2))` of each chord within `delta`, its ends the curve's own.
fn flatten_arc(s: &Segment, center: V2, radius: f64, delta: f64) -> Vec<V2> {
    let c = s.curve();
    let (a, b) = c.domain();
    let angle = |p: V2| (p.y - center.y).atan2(p.x - center.x);
    let at = |k: usize| c.jet_to(a + (b - a) * k as f64 / SWEEP_STEPS as f64, 0).p;
    let (start, end) = (at(0), at(SWEEP_STEPS));
    let a0 = angle(start);
    let mut sweep = 0.0;
    let mut prev = a0;
    for k in 1..=SWEEP_STEPS {
        let next = angle(at(k));
        sweep += (next - prev + PI).rem_euclid(TAU) - PI;
        prev = next;
    }
    let step = 2.0 * (1.0 - (delta / radius).min(1.0)).acos();
    let n = ((sweep.abs() / step).ceil() as usize).clamp(1, MAX_POINTS);
    let mut out = Vec::with_capacity(n + 1);
    out.push(start);
    for k in 1..n {
        let (sin, cos) = (a0 + sweep * k as f64 / n as f64).sin_cos();
        out.push(center + V2::new(cos, sin) * radius);
    }
    out.push(end);
    out
}

/// Appends the points after `p0` up to `p1` of the flattening of `[u0, u1]`.
fn refine(
    at: &impl Fn(f64) -> V2,
    (u0, p0): (f64, V2),
    (u1, p1): (f64, V2),
    delta: f64,
    depth: usize,
    out: &mut Vec<V2>,
) {
    let um = 0.5 * (u0 + u1);
    let pm = at(um);
    // Distance of the middle point from the chord (from its end where the chord is a point).
    let chord = p1 - p0;
    let off = match chord.norm() {
        0.0 => (pm - p0).norm(),
        len => chord.cross(pm - p0).abs() / len,
    };
    if off <= delta || depth >= MAX_DEPTH || out.len() >= MAX_POINTS {
        out.push(p1);
        return;
    }
    refine(at, (u0, p0), (um, pm), delta, depth + 1, out);
    refine(at, (um, pm), (u1, p1), delta, depth + 1, out);
}

/// Where edges `ab` and `cd` meet, when they do (touching or overlapping included).
fn meet(a: V2, b: V2, c: V2, d: V2) -> Option<V2> {
    let (lo1, hi1) = (
        V2::new(a.x.min(b.x), a.y.min(b.y)),
        V2::new(a.x.max(b.x), a.y.max(b.y)),
    );
    let (lo2, hi2) = (
        V2::new(c.x.min(d.x), c.y.min(d.y)),
        V2::new(c.x.max(d.x), c.y.max(d.y)),
    );
    if hi1.x < lo2.x || hi2.x < lo1.x || hi1.y < lo2.y || hi2.y < lo1.y {
        return None;
    }
    let side = |p: V2, q: V2, r: V2| (q - p).cross(r - p);
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        let t = d1 / (d1 - d2);
        return Some(a + (b - a) * t);
    }
    // Touching or collinear: an end on the other edge.
    let on = |p: V2, q: V2, r: V2| {
        side(p, q, r) == 0.0
            && r.x >= p.x.min(q.x)
            && r.x <= p.x.max(q.x)
            && r.y >= p.y.min(q.y)
            && r.y <= p.y.max(q.y)
    };
    [(c, d, a), (c, d, b), (a, b, c), (a, b, d)]
        .into_iter()
        .find(|&(p, q, r)| on(p, q, r))
        .map(|(_, _, r)| r)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The edge test agrees with solving for the meet in exact-enough arithmetic away from
        /// touching configurations.
        #[test]
        fn edges_meet_where_their_lines_cross_inside_both(
            p in proptest::collection::vec(-10.0f64..10.0, 8),
        ) {
            let (a, b, c, d) = (V2::new(p[0], p[1]), V2::new(p[2], p[3]), V2::new(p[4], p[5]), V2::new(p[6], p[7]));
            let den = (b - a).cross(d - c);
            prop_assume!(den.abs() > 1e-6);
            let t = (c - a).cross(d - c) / den;
            let u = (c - a).cross(b - a) / den;
            prop_assume!((t - 0.5).abs() < 0.5 - 1e-6 || (t - 0.5).abs() > 0.5 + 1e-6);
            prop_assume!((u - 0.5).abs() < 0.5 - 1e-6 || (u - 0.5).abs() > 0.5 + 1e-6);
            let inside = (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u);
            let got = meet(a, b, c, d);
            prop_assert_eq!(got.is_some(), inside);
            if let Some(m) = got {
                let want = a + (b - a) * t;
                prop_assert!((m - want).norm() < 1e-9 * (1.0 + want.norm()));
            }
        }

        /// An arc's closed-form polyline starts and ends at the curve's ends, has its points
        /// on the circle in order along the arc, and chords within the flatness of it: every
        /// point of the curve (sampled densely) is within `delta` of the polyline, and the
        /// chords are no shorter than needed by more than one step in the count.
        #[test]
        fn an_arc_is_flattened_within_the_flatness_in_closed_form(
            center in (-1e3f64..1e3, -1e3f64..1e3),
            radius in 1e-3f64..1e2,
            start in -7.0f64..7.0,
            sweep in prop_oneof![-6.3f64..-0.01, 0.01f64..6.3, Just(TAU), Just(-TAU)],
            flat in 1e-8f64..1e-2,
        ) {
            let c = [center.0, center.1];
            // (A full turn from a start whose sum rounds past 2π is refused.)
            let Ok(s) = Segment::arc(c, radius, start, start + sweep) else { return Ok(()) };
            let sweep = (start + sweep) - start;
            let delta = flat * radius;
            let pts = flatten_arc(&s, V2::from_arr(c), radius, delta);
            let curve = s.curve();
            let (a, b) = curve.domain();
            prop_assert_eq!(pts[0], curve.jet_to(a, 0).p);
            prop_assert_eq!(*pts.last().unwrap(), curve.jet_to(b, 0).p);
            let size = radius + c[0].abs().max(c[1].abs());
            let rounding = 1e-12 * size;
            let mut turned = 0.0;
            for w in pts.windows(2) {
                let (u, v) = (w[0] - V2::from_arr(c), w[1] - V2::from_arr(c));
                prop_assert!((v.norm() - radius).abs() <= rounding);
                turned += u.cross(v).atan2(u.dot(v));
            }
            prop_assert!((turned - sweep).abs() <= 1e-9, "turned {turned} of {sweep}");
            let step = 2.0 * (1.0 - flat.min(1.0)).acos();
            prop_assert!(pts.len() - 1 <= (sweep.abs() / step).ceil() as usize);
            // The curve between the points: within delta of its chord.
            let steps = 4000;
            let mut k = 0;
            for j in 0..=steps {
                let p = curve.jet_to(a + (b - a) * j as f64 / steps as f64, 0).p;
                let off = |k: usize| {
                    let (x, y) = (pts[k], pts[k + 1]);
                    let d = y - x;
                    let t = ((p - x).dot(d) / d.dot(d)).clamp(0.0, 1.0);
                    (p - (x + d * t)).norm()
                };
                // The nearest chord is this one or a later one (the points are in order).
                while k + 2 < pts.len() && off(k + 1) < off(k) {
                    k += 1;
                }
                prop_assert!(off(k) <= delta + rounding, "{} off at {j}", off(k));
            }
        }
    }
}
