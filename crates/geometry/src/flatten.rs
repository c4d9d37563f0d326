//! Polylines within a proven distance of a curve: for drawing, for GeoJSON and shapely, for
//! any program that wants straight pieces.
//!
//! Each segment's exact form is cut into its rational Bézier pieces, and each piece halved
//! (de Casteljau, on the homogeneous points) until its control points all lie within the
//! tolerance of the chord between its ends. With positive weights a rational Bézier lies in the
//! convex hull of its control points, so the piece then lies within the tolerance of its
//! chord: the polyline's every point is within the tolerance of the curve and back. Every
//! vertex is a point of the curve (a piece's end), and comes with its parameter.

use curve::distance_to_segment;
use curve::{ParamCurve, Profile, Segment};
use numeric::rounding::ulps;

/// How near (a share of the size) two consecutive points are one: the contract's joint
/// tolerance, within which one segment's end is the next one's start. Keeping both would give
/// the polyline a spike of rounding's size, which polygon libraries call a self-crossing.
const JOINED: f64 = 1e-9;

/// The finest tolerance taken, as a share of the coordinates' magnitude: a thousand times the
/// rounding of a double.
const FLATTENING_ROUNDING: f64 = ulps(1e3);

/// Most halvings of one Bézier piece: each quarters its control points' distance from the
/// chord, so 2^24 chords reach 4^-24 of the piece's size, beyond [`FLATTENING_ROUNDING`] (the bound ends
/// the recursion on a degenerate piece).
const MAX_FLATTENING_HALVINGS: u32 = 24;

/// [`crate::Flatten::flattened`] of a profile.
pub(crate) fn flattened(profile: &Profile, tol: f64) -> Vec<[f64; 2]> {
    flattened_with_params(profile, tol)
        .into_iter()
        .map(|(p, _)| p)
        .collect()
}

/// [`crate::Flatten::flattened_with_params`] of a profile.
pub(crate) fn flattened_with_params(profile: &Profile, tol: f64) -> Vec<([f64; 2], f64)> {
    let tol = if tol.is_finite() && tol > 0.0 {
        tol
    } else {
        1e-3 * profile.scale()
    };
    // (No finer than the rounding of the coordinates: below it no halving flattens a
    // piece, and the halvings would run to their bound everywhere.)
    let b = profile.bounding_box();
    let far = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let tol = tol.max(FLATTENING_ROUNDING * (profile.scale() + far));
    let joined = JOINED * profile.scale();
    let mut points: Vec<([f64; 2], f64)> = Vec::new();
    for (i, s) in profile.segments().iter().enumerate() {
        let start = points.len();
        flatten_segment(s, tol, joined, &mut points);
        for p in &mut points[start..] {
            p.1 = profile.profile_param(i, p.1);
        }
    }
    // A closed profile's polyline ends exactly where it starts.
    if profile.is_closed() && points.len() > 1 {
        let (first, last) = (points[0].0, points[points.len() - 1].0);
        if (first[0] - last[0]).hypot(first[1] - last[1]) <= joined {
            let end = points.len() - 1;
            points[end].0 = first;
        }
    }
    points
}

/// [`crate::Flatten::flattened`] of a segment.
pub(crate) fn segment_flattened(segment: &Segment, tol: f64) -> Vec<[f64; 2]> {
    // (No finer than the rounding of its coordinates, as for a profile.)
    let far = segment
        .curve()
        .control_points()
        .iter()
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    let tol = if tol.is_finite() && tol > 0.0 {
        tol
    } else {
        0.0
    }
    .max(FLATTENING_ROUNDING * far);
    let mut points = Vec::new();
    flatten_segment(segment, tol, 0.0, &mut points);
    points.into_iter().map(|(p, _)| p).collect()
}

/// Appends the points of `s` within `tol`, each with its parameter on the exact form (its
/// start only when `out` is empty, or when the last point is farther than `joined`).
fn flatten_segment(s: &Segment, tol: f64, joined: f64, out: &mut Vec<([f64; 2], f64)>) {
    for piece in s.curve().curve().homogeneous().bezier_pieces() {
        let control: Vec<[f64; 3]> = piece
            .coefs
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect();
        let first = project(control[0]);
        let apart = |p: &([f64; 2], f64)| (p.0[0] - first[0]).hypot(p.0[1] - first[1]) > joined;
        if out.last().is_none_or(apart) {
            out.push((first, piece.a));
        }
        halve_until_flat(&control, (piece.a, piece.b), tol, 0, out);
    }
}

/// The Euclidean point of a homogeneous one.
fn project(h: [f64; 3]) -> [f64; 2] {
    [h[0] / h[2], h[1] / h[2]]
}

/// Appends the points after the first of the homogeneous Bézier `control` on the parameters
/// `span`, halving it where its control points stray farther than `tol` from its chord.
fn halve_until_flat(
    control: &[[f64; 3]],
    span: (f64, f64),
    tol: f64,
    depth: u32,
    out: &mut Vec<([f64; 2], f64)>,
) {
    let (a, b) = (project(control[0]), project(control[control.len() - 1]));
    let flat = control[1..control.len() - 1]
        .iter()
        .all(|&h| distance_to_segment(project(h), a, b) <= tol);
    if flat || depth >= MAX_FLATTENING_HALVINGS {
        out.push((b, span.1));
        return;
    }
    let middle = 0.5 * (span.0 + span.1);
    let (left, right) = de_casteljau_half(control);
    halve_until_flat(&left, (span.0, middle), tol, depth + 1, out);
    halve_until_flat(&right, (middle, span.1), tol, depth + 1, out);
}

/// The two halves of a Bézier (homogeneous control points) at its middle.
fn de_casteljau_half(control: &[[f64; 3]]) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let n = control.len();
    let mut row = control.to_vec();
    let mut left = Vec::with_capacity(n);
    let mut right = Vec::with_capacity(n);
    left.push(row[0]);
    right.push(row[n - 1]);
    for level in 1..n {
        for i in 0..n - level {
            let next = row[i + 1];
            for (a, b) in row[i].iter_mut().zip(next) {
                *a = 0.5 * (*a + b);
            }
        }
        left.push(row[0]);
        right.push(row[n - level - 1]);
    }
    right.reverse();
    (left, right)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Flatten;
    use curve::{ParamCurve, SegmentKind, SplineCurve};
    use proptest::prelude::*;

    /// The distance from `p` to the polyline.
    fn to_polyline(p: [f64; 2], line: &[[f64; 2]]) -> f64 {
        line.windows(2)
            .map(|w| distance_to_segment(p, w[0], w[1]))
            .fold(f64::INFINITY, f64::min)
    }

    /// A rational cubic on `points` taken in order of x (an x-monotone control polygon:
    /// the curve is x-monotone too, so it never crosses itself).
    fn profile_of(points: &[[f64; 2]], weights: &[f64]) -> Option<Profile> {
        let mut points = points.to_vec();
        points.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let spline = SplineCurve::clamped(3, &points, Some(weights), None).ok()?;
        let segment = Segment::spline(SegmentKind::BSpline, spline).ok()?;
        Profile::new(vec![segment], Some(false)).ok()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Against dense sampling of the exact curve: every sample within the tolerance of the
        /// polyline, and every vertex on the curve (its nearest point at rounding's distance).
        #[test]
        fn the_polyline_and_the_curve_stay_within_the_tolerance(
            points in prop::collection::vec(prop::array::uniform2(-10.0f64..10.0), 4..9),
            weights in prop::collection::vec(0.2f64..5.0, 9),
            tol_exp in -6.0f64..-1.0,
        ) {
            let profile = profile_of(&points, &weights[..points.len()]);
            prop_assume!(profile.is_some());
            let profile = profile.unwrap();
            let tol = 10f64.powf(tol_exp);
            let vertices = flattened_with_params(&profile, tol);
            let line: Vec<[f64; 2]> = vertices.iter().map(|v| v.0).collect();
            prop_assert!(line.len() >= 2);
            let (a, b) = profile.domain();
            let n = 2000;
            let samples: Vec<[f64; 2]> = (0..=n)
                .map(|k| profile.jet_to(a + (b - a) * k as f64 / n as f64, 0).p.arr())
                .collect();
            for (k, p) in samples.iter().enumerate() {
                let d = to_polyline(*p, &line);
                prop_assert!(d <= tol * (1.0 + 1e-9) + 1e-12, "sample {k} is {d:e} from the polyline (tol {tol:e})");
            }
            // And back: each chord's middle within the tolerance of the curve, measured on
            // the samples (to within half the widest gap between two of them).
            let gap = samples
                .windows(2)
                .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
                .fold(0.0, f64::max);
            for w in line.windows(2) {
                let m = [0.5 * (w[0][0] + w[1][0]), 0.5 * (w[0][1] + w[1][1])];
                let d = samples
                    .iter()
                    .map(|q| (q[0] - m[0]).hypot(q[1] - m[1]))
                    .fold(f64::INFINITY, f64::min);
                prop_assert!(d <= tol + 0.5 * gap + 1e-12, "a chord's middle is {d:e} from the curve (tol {tol:e})");
            }
            // (Each vertex, found by halving, against the curve evaluated by de Boor's
            // algorithm at its parameter.)
            for (v, u) in &vertices {
                let p = profile.jet_to(*u, 0).p.arr();
                let off = (p[0] - v[0]).hypot(p[1] - v[1]);
                prop_assert!(off <= 1e-12 * profile.scale(), "a vertex {off:e} off the curve");
            }
        }
    }

    /// Lines stay one chord; an arc's chords each span no more than its tolerance allows, and
    /// a closed profile ends where it starts.
    #[test]
    fn lines_are_one_chord_and_arcs_are_chorded_by_the_tolerance() {
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
        let sides = (0..4)
            .map(|i| Segment::line(square[i], square[(i + 1) % 4]).unwrap())
            .collect();
        let p = Profile::new(sides, None).unwrap();
        assert_eq!(
            p.flattened(1e-6),
            vec![[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0], [0.0, 0.0]]
        );
        let r = 3.0;
        let arc = Profile::new(vec![Segment::arc([1.0, 1.0], r, 0.0, 2.0).unwrap()], None).unwrap();
        let tol = 1e-4;
        let line = arc.flattened(tol);
        let widest = 2.0 * (1.0 - tol / r).acos();
        for w in line.windows(2) {
            let chord = ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt();
            let angle = 2.0 * (0.5 * chord / r).asin();
            assert!(angle <= widest * (1.0 + 1e-9), "{angle} > {widest}");
        }
        // Not needlessly fine: at most four times the fewest chords (halving overshoots by 2×,
        // and the convex hull's test by up to 4/3 of the sag).
        let fewest = (2.0 / widest).ceil() as usize;
        assert!(
            line.len() - 1 <= 4 * fewest,
            "{} chords for {fewest}",
            line.len() - 1
        );
    }
}
