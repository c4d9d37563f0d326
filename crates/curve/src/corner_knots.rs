//! Corners inside spline segments: a knot of full multiplicity (the degree) leaves a B-spline
//! only C⁰ there, and where its tangent turns the curve has a corner, as CAD systems write
//! them (a closed `SPLINE` with sharp corners, a degree-1 spline: a polyline). A profile's
//! corners are its joints, so such a segment is cut there into segments joined at the corner
//! (the same curve: restricting a B-spline to knot spans is exact).

use crate::error::{Error, Result};
use crate::param::ParamCurve;
use crate::segment::{Segment, SegmentKind};
use crate::spline::SplineCurve;
use crate::V2;
use numeric::rounding::ulps;

/// The jump of the tangent direction (radians) above which a joint is a corner: the interface
/// contract's, far above the rounding of tangents computed from control points near the
/// origin (far from it, see [`smooth_turn`]).
pub const CORNER_TURN: f64 = 1e-9;

/// How far (relative to the largest coordinate of the point where two legs of a control
/// polygon meet) rounding may move a leg from the one its author meant: each of its two
/// points rounded by up to half an ulp of the coordinates there (`ε/2` relative at most), or,
/// computed (an arc's from its centre, radius and angles), by about an ulp; measured on line
/// to arc joints out to 5e8, at most `1.4 ε` over both legs.
const LEG_ROUNDING: f64 = ulps(2.0);

/// The most turn the rounding of a joint's legs is taken to explain: a joint turning more is a
/// corner whatever its legs. Far above what a drawn fillet rounds by where drawings lie (one
/// of radius 1e-3 at 1e8: some 1e-4), far below any drawn corner's angle (a chamfer of 1e-6 at
/// 1e8, whose legs' directions round by 0.1 rad, stays a corner). Segments so short, so far
/// out, that their directions round by more are beyond what the contract's corner can decide.
const ROUNDED_TURN_CAP: f64 = 1e-3;

/// The largest turn between the tangents along the legs `before` (arriving at `at`) and
/// `after` (leaving it) that is no corner: the contract's [`CORNER_TURN`], beyond what the
/// rounding of the legs' points can turn them by (taken at most 1e-3 rad). Near the
/// origin that rounding is negligible; far from it, on short legs, it is not: a fillet of
/// radius 0.01 at 1e8 has its tangents rounded 1.5e-6 apart, and a line and an arc of radius
/// 1 meeting tangentially there, some 1e-8.
///
/// ```
/// use curve::{smooth_turn, CORNER_TURN, V2};
/// // Near the origin, the contract's turn.
/// let near = smooth_turn(V2::new(1.0, 2.0), V2::new(1.0, 0.0), V2::new(0.0, 1.0));
/// assert!(near - CORNER_TURN < 1e-14);
/// // At 1e8 with legs of 0.1: the legs' rounding, some 9e-7.
/// let far = smooth_turn(V2::new(1e8, 1e8), V2::new(0.1, 0.0), V2::new(0.0, 0.1));
/// assert!(far > 100.0 * CORNER_TURN && far < 1e-6);
/// // With legs of 1e-6 it would be 0.09 rad: capped at 1e-3, far below a drawn corner.
/// let tiny = smooth_turn(V2::new(1e8, 1e8), V2::new(1e-6, 0.0), V2::new(0.0, 1e-6));
/// assert!(tiny <= CORNER_TURN + 1e-3);
/// ```
pub fn smooth_turn(at: V2, before: V2, after: V2) -> f64 {
    let magnitude = at.x.abs().max(at.y.abs());
    let rounding = LEG_ROUNDING * magnitude * (1.0 / before.norm() + 1.0 / after.norm());
    CORNER_TURN + rounding.min(ROUNDED_TURN_CAP)
}

/// Where a segment of a profile lies in the parameter its document gives the profile: a
/// `profile` document's `[0, n)` (segment `i` on `[i, i + 1]`, at its own parameter mapped
/// linearly), or a curve's own domain (a spline's knots, an analytic shape's angle) for a
/// curve taken as a profile ([`crate::Profile::of_curve`]). A segment cut at a corner inside it
/// (a knot of full multiplicity) covers its share of the whole segment's span.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DocumentSpan {
    /// The document's segment it belongs to.
    pub segment: usize,
    /// The document parameter where it starts.
    pub lo: f64,
    /// The document parameter where it ends.
    pub hi: f64,
}

/// The segments cut at their corner knots, with where each piece lies in the segments as
/// given: segment `i` on `[i, i + 1]`, a piece on its share of its segment's own domain.
pub(crate) fn cut_at_corner_knots(
    segments: Vec<Segment>,
) -> Result<(Vec<Segment>, Vec<DocumentSpan>)> {
    let mut out = Vec::with_capacity(segments.len());
    let mut spans = Vec::with_capacity(segments.len());
    for (i, s) in segments.into_iter().enumerate() {
        let corners = corner_knots(&s);
        let whole = DocumentSpan {
            segment: i,
            lo: i as f64,
            hi: (i + 1) as f64,
        };
        if corners.is_empty() {
            out.push(straightened(s)?);
            spans.push(whole);
            continue;
        }
        let (a, b) = s.curve().domain();
        let share = |v: f64| i as f64 + (v - a) / (b - a);
        let cuts: Vec<f64> = std::iter::once(a)
            .chain(corners)
            .chain(std::iter::once(b))
            .collect();
        for w in cuts.windows(2) {
            let piece = SplineCurve::new(s.curve().curve().restrict(w[0], w[1])?)?;
            out.push(straightened(Segment::spline(SegmentKind::BSpline, piece)?)?);
            spans.push(DocumentSpan {
                segment: i,
                lo: share(w[0]),
                hi: share(w[1]),
            });
        }
    }
    Ok((out, spans))
}

/// A polynomial spline segment of degree 1 with two control points is a straight line (the same
/// points at the same parameters, up to the affine map of its domain onto `[0, 1]`): made one,
/// so that it is known to be straight.
fn straightened(s: Segment) -> Result<Segment> {
    let c = s.curve();
    if !matches!(s.kind(), SegmentKind::BSpline | SegmentKind::Bezier)
        || c.curve().degree() != 1
        || c.curve().is_rational()
    {
        return Ok(s);
    }
    match c.control_points()[..] {
        [from, to] if from != to => Segment::line(from, to),
        _ => Ok(s),
    }
}

/// The interior knots of a spline segment where it is only C⁰ (multiplicity at least its
/// degree) and its tangent direction turns by more than [`smooth_turn`] allows, in order. At such a
/// knot, first at index `j` of the clamped knot vector, the curve passes through control point
/// `j − 1`; the tangents arriving and leaving point along the control polygon's legs there
/// (the nearest points that differ, where points repeat).
fn corner_knots(s: &Segment) -> Vec<f64> {
    if !matches!(s.kind(), SegmentKind::Bezier | SegmentKind::BSpline) {
        return Vec::new();
    }
    let hom = s.curve().curve().homogeneous();
    let (p, knots) = (hom.degree(), hom.knots());
    let (a, b) = s.curve().domain();
    let points: Vec<V2> = s
        .curve()
        .control_points()
        .into_iter()
        .map(V2::from_arr)
        .collect();
    let mut out = Vec::new();
    let mut j = p + 1;
    while j < knots.len() {
        let k = knots[j];
        let m = knots[j..].iter().take_while(|&&x| x == k).count();
        if k > a && k < b && m >= p && j >= 1 && j - 1 < points.len() {
            let at = points[j - 1];
            let before = points[..j - 1]
                .iter()
                .rev()
                .map(|&q| at - q)
                .find(|d| d.norm() > 0.0);
            let after = points[j..].iter().map(|&q| q - at).find(|d| d.norm() > 0.0);
            if let (Some(din), Some(dout)) = (before, after) {
                let turn = din.cross(dout).atan2(din.dot(dout));
                if turn.abs() > smooth_turn(at, din, dout) {
                    out.push(k);
                }
            }
        }
        j += m.max(1);
    }
    out
}

/// An error of the profile of cut segments, naming segments as given (`given(i)` of cut
/// segment `i`).
pub(crate) fn named_as_given(e: Error, given: impl Fn(usize) -> usize) -> Error {
    match e {
        Error::Gap { segment, gap, at } => Error::Gap {
            segment: given(segment),
            gap,
            at,
        },
        Error::ZeroLength { segment } => Error::ZeroLength {
            segment: given(segment),
        },
        Error::Cusp { segment, at } => Error::Cusp {
            segment: given(segment),
            at,
        },
        Error::SelfCrossing { first, second, at } => Error::SelfCrossing {
            first: given(first),
            second: given(second),
            at,
        },
        e => e,
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::param::ParamCurve;
    use crate::profile::{JointKind, Profile};
    use proptest::prelude::*;

    fn spline(degree: usize, points: &[[f64; 2]], knots: Option<Vec<f64>>) -> Segment {
        let c = SplineCurve::clamped(degree, points, None, knots).unwrap();
        Segment::spline(SegmentKind::BSpline, c).unwrap()
    }

    #[test]
    fn a_degree_one_spline_is_a_polygon_with_its_corners() {
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [0.0, 0.0]];
        let seg = spline(1, &square, None);
        let p = Profile::of_curve(seg, (0.0, 1.0)).unwrap();
        assert!(p.is_closed());
        assert_eq!(p.segments().len(), 4);
        assert_eq!(p.corners().count(), 4);
        assert!(p.corners().all(|j| j.kind == JointKind::Convex));
        // The corners sit at the knots, in the spline's own parameter.
        for (k, j) in p.joints().iter().enumerate() {
            assert_eq!(p.document_param(j.u), 0.25 * k as f64);
        }
        assert_eq!(p.document_domain(), (0.0, 1.0));
    }

    #[test]
    fn a_full_multiplicity_knot_is_a_corner_only_where_the_tangent_turns() {
        // A cubic with a triple knot at 0.5 where it turns by 63 degrees, then one where the
        // legs either side are collinear.
        let turn = 63f64.to_radians();
        let legs = |t: f64| {
            [
                [0.0, 0.0],
                [1.0, 0.0],
                [2.0, 0.0],
                [3.0, 0.0],
                [3.0 + t.cos(), t.sin()],
                [3.0 + 2.0 * t.cos(), 2.0 * t.sin()],
                [3.0 + 3.0 * t.cos(), 3.0 * t.sin()],
            ]
        };
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
        let sharp = Profile::new(vec![spline(3, &legs(turn), Some(knots.clone()))], None).unwrap();
        assert_eq!(sharp.segments().len(), 2);
        let corner: Vec<_> = sharp.corners().collect();
        assert_eq!(corner.len(), 1);
        testkit::assert_near!(corner[0].turn, turn, 1e-12, "{corner:?}");
        assert_eq!(sharp.document_param(corner[0].u), 0.5);
        assert_eq!(sharp.document_segment(1), 0);
        let straight = Profile::new(vec![spline(3, &legs(0.0), Some(knots))], None).unwrap();
        assert_eq!(straight.segments().len(), 1);
    }

    proptest! {
        /// A clamped spline with corner knots, cut, is the same curve: at every document
        /// parameter the profile's point is the spline's point there, and the document
        /// parameter of the profile parameter found is the one asked for.
        #[test]
        fn cut_splines_keep_their_points_and_parameters(
            pts in proptest::collection::vec((0.1f64..1.0, -5.0f64..5.0), 7),
            degree in 1usize..=3,
            d in 0.0f64..=1.0,
        ) {
            // (Rising in x: an open curve that cannot cross itself.)
            let points: Vec<[f64; 2]> = pts
                .iter()
                .scan(0.0, |x, &(dx, y)| {
                    *x += dx;
                    Some([*x, y])
                })
                .collect();
            // Knots of full multiplicity at 0.4 (and, for degree 1, every knot).
            let n = points.len();
            let inner = n - degree - 1;
            let mut knots = vec![0.0; degree + 1];
            let at = |i: usize| 0.4 * (i / degree + 1) as f64 / (inner / degree + 1) as f64;
            knots.extend((0..inner).map(|i| if degree == 1 { (i + 1) as f64 / (inner + 1) as f64 } else { at(i) }));
            knots.sort_by(f64::total_cmp);
            knots.extend(vec![1.0; degree + 1]);
            prop_assume!(knots.windows(2).all(|w| w[0] <= w[1]));
            let c = SplineCurve::clamped(degree, &points, None, Some(knots)).unwrap();
            let seg = Segment::spline(SegmentKind::BSpline, c.clone()).unwrap();
            let p = Profile::of_curve(seg, (0.0, 1.0)).unwrap();
            let u = p.internal_param(d);
            let size = 10.0;
            prop_assert!((p.jet(u).p - c.jet(d).p).norm() <= 1e-12 * size);
            testkit::prop_assert_near!(p.document_param(u), d, 1e-14);
        }
    }
}
