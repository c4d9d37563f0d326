//! Random profiles for the property tests: polygons with some corners rounded by arcs, and
//! closed chains of cubic Béziers with corners; and a profile reassembled from another
//! segment, or run backwards (the metamorphic tests' moves).
#![allow(clippy::unwrap_used)] // (the segments given are valid: a failure is the test's own)

use curve::{ParamCurve, SegmentKind, SplineCurve, V2};
use curve::{Profile, Segment};
use proptest::prelude::*;
use std::f64::consts::TAU;

/// The angles of a star's vertices spaced round one turn in proportion to `steps` (step `i`
/// from vertex `i` to the next), the first at 0.
pub fn step_angles(steps: &[f64]) -> Vec<f64> {
    let total: f64 = steps.iter().sum();
    let mut acc = 0.0;
    steps
        .iter()
        .map(|s| {
            let a = TAU * acc / total;
            acc += s;
            a
        })
        .collect()
}

/// A [`filleted_polygon`] with its vertices spaced by `steps` (see [`step_angles`]); the
/// first `steps.len()` of `radii` and `round` are its own (a property test draws them for
/// the most vertices).
pub fn stepped_polygon(steps: &[f64], radii: &[f64], round: &[f64]) -> Option<Vec<Segment>> {
    let n = steps.len();
    filleted_polygon(&step_angles(steps), &radii[..n], &round[..n])
}

/// A star-shaped polygon (vertex `i` at angle `angles[i]` and radius `radii[i]`) with the
/// corners where `round[i] > 0` rounded by a tangent arc of that share of the shorter edge.
pub fn filleted_polygon(angles: &[f64], radii: &[f64], round: &[f64]) -> Option<Vec<Segment>> {
    let n = angles.len();
    let v: Vec<V2> = (0..n).map(|i| V2::polar(angles[i]) * radii[i]).collect();
    // Per corner: where the incoming edge ends and the outgoing one starts, and the arc.
    let mut cuts: Vec<(V2, V2, Option<Segment>)> = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b, c) = (v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
        let (din, dout) = ((b - a).unit(), (c - b).unit());
        let turn = din.cross(dout).atan2(din.dot(dout));
        if round[i] <= 0.0 || turn.abs() < 0.05 {
            cuts.push((b, b, None));
            continue;
        }
        let reach = round[i] * 0.45 * (b - a).norm().min((c - b).norm());
        let r = reach / (0.5 * turn.abs()).tan();
        let (p0, p1) = (b - din * reach, b + dout * reach);
        let center = p0 + din.perp() * (r * turn.signum());
        let start = (p0 - center).angle();
        let arc = Segment::arc(center.arr(), r, start, start + turn).ok()?;
        cuts.push((p0, p1, Some(arc)));
    }
    let mut segs = Vec::new();
    for i in 0..n {
        let (_, from, _) = cuts[i];
        let (to, _, _) = cuts[(i + 1) % n];
        segs.push(Segment::line(from.arr(), to.arr()).ok()?);
        if let Some(arc) = cuts[(i + 1) % n].2.clone() {
            segs.push(arc);
        }
    }
    Some(segs)
}

/// A closed chain of cubic Béziers round a star (joint `i` at radius `radii[i]`), smooth
/// (G1) at joint `i` where `smooth[i]`, its inner control points pushed off the chord by
/// `wobble`.
pub fn bezier_chain(radii: &[f64], wobble: &[(f64, f64)], smooth: &[bool]) -> Option<Vec<Segment>> {
    let n = radii.len();
    let joint = |i: usize| V2::polar(TAU * (i % n) as f64 / n as f64) * radii[i % n];
    let dir = |i: usize| (joint(i + 1) - joint(i + n - 1)).unit();
    let mut segs = Vec::new();
    for i in 0..n {
        let (a, b) = (joint(i), joint(i + 1));
        let len = (b - a).norm();
        let (w0, w1) = wobble[i];
        let c1 = if smooth[i] {
            a + dir(i) * (0.3 * len)
        } else {
            a + (b - a) * 0.3 + (b - a).perp() * w0
        };
        let c2 = if smooth[(i + 1) % n] {
            b - dir(i + 1) * (0.3 * len)
        } else {
            a + (b - a) * 0.7 + (b - a).perp() * w1
        };
        let pts = [a.arr(), c1.arr(), c2.arr(), b.arr()];
        let c = SplineCurve::clamped(3, &pts, None, None).ok()?;
        segs.push(Segment::spline(SegmentKind::Bezier, c).ok()?);
    }
    Some(segs)
}

/// A [`bezier_chain`] as a profile, started at segment `start`, run backwards when `reverse`
/// (see [`assemble`]); `None` where it is none (a wobble makes it cross itself).
pub fn bezier_chain_profile(
    radii: &[f64],
    wobble: &[(f64, f64)],
    smooth: &[bool],
    start: usize,
    reverse: bool,
) -> Option<Profile> {
    assemble(bezier_chain(radii, wobble, smooth)?, start, reverse)
}

/// A closed chain of five cubic Béziers ([`bezier_chain_profile`]), smooth
/// at the joints where `smooth` says: the radii of its joints and the pushes of its inner
/// control points, as the medial axis's and the bisectors' tests of a whole chain draw it.
pub fn five_cubics(smooth: [bool; 5]) -> Profile {
    let radii = [1.5, 1.0, 1.8, 1.2, 1.6];
    let wobble = [
        (0.2, -0.3),
        (0.3, 0.25),
        (-0.2, 0.1),
        (0.35, -0.1),
        (0.1, 0.3),
    ];
    bezier_chain_profile(&radii, &wobble, &smooth, 0, false).unwrap()
}

/// An inner control point's push off the chord for [`bezier_chain`] (relative to its
/// length): from 0.05 to `most`, either side (a push near zero leaves a cubic straight within
/// rounding).
pub fn wobble(most: f64) -> impl Strategy<Value = f64> {
    prop_oneof![-most..-0.05, 0.05..most]
}

/// The spline `c` as a profile of one B-spline segment (a closed one without a corner at its
/// seam is a smooth closed profile).
pub fn one_spline(c: SplineCurve) -> Profile {
    Profile::new(
        vec![Segment::spline(SegmentKind::BSpline, c).unwrap()],
        None,
    )
    .unwrap()
}

/// Random [`stepped_polygon`]s as profiles ([`assemble`]d): `vertices` vertices at radii 1
/// to 2 (spaced by steps of 0.5 to 1.5), about half of them rounded, started at a segment
/// below `starts`, either way round; `None` where one is no profile.
pub fn filleted_polygons(
    vertices: std::ops::Range<usize>,
    starts: usize,
) -> impl Strategy<Value = Option<Profile>> {
    let most = vertices.end;
    (
        proptest::collection::vec(0.5f64..1.5, vertices),
        proptest::collection::vec(1.0f64..2.0, most),
        proptest::collection::vec(prop_oneof![Just(0.0), 0.2f64..1.0], most),
        0..starts,
        any::<bool>(),
    )
        .prop_map(|(steps, radii, round, start, reverse)| {
            assemble(stepped_polygon(&steps, &radii, &round)?, start, reverse)
        })
}

/// Random [`bezier_chain_profile`]s: `joints` joints at radii 1 to 2, their inner control
/// points pushed by [`wobble`]`(most)`, smooth or not at random, started at any segment,
/// either way round; `None` where one is no profile. (`slots`, at least the most joints, is
/// how many pushes and kinds are drawn, and bounds the start.)
pub fn bezier_chains(
    joints: std::ops::Range<usize>,
    slots: usize,
    most: f64,
) -> impl Strategy<Value = Option<Profile>> {
    (
        proptest::collection::vec(1.0f64..2.0, joints),
        proptest::collection::vec((wobble(most), wobble(most)), slots),
        proptest::collection::vec(any::<bool>(), slots),
        0..slots,
        any::<bool>(),
    )
        .prop_map(|(radii, wobble, smooth, start, reverse)| {
            let n = radii.len();
            bezier_chain_profile(&radii, &wobble[..n], &smooth[..n], start, reverse)
        })
}

/// The segments as a profile, started at segment `start`, run backwards when `reverse`.
pub fn assemble(mut segs: Vec<Segment>, start: usize, reverse: bool) -> Option<Profile> {
    let n = segs.len();
    segs.rotate_left(start % n);
    if reverse {
        segs = segs.into_iter().rev().map(|s| reversed(&s)).collect();
    }
    Profile::new(segs, None).ok()
}

/// A segment run backwards (same kind; an arc on the same circle, which the bisectors of
/// arcs of one circle need).
pub fn reversed(s: &Segment) -> Segment {
    if s.circle().is_some() {
        return s.reversed().unwrap();
    }
    let c = s.curve();
    let mut pts = c.control_points();
    pts.reverse();
    let mut w = c.curve().weights();
    w.reverse();
    let (a, b) = c.domain();
    let knots: Vec<f64> = c
        .curve()
        .homogeneous()
        .knots()
        .iter()
        .rev()
        .map(|k| a + b - k)
        .collect();
    let degree = c.curve().degree();
    let weights = c.curve().is_rational().then_some(&w[..]);
    let rc = SplineCurve::clamped(degree, &pts, weights, Some(knots)).unwrap();
    Segment::spline(s.kind(), rc).unwrap()
}
