//! The bounding box of a profile's points, and the size every relative tolerance is taken of
//! (the contract's "Size": max(width, height) of the bounding box of the input's curves).
//! A Bézier piece lies in the box of its control points, and its end points are on it: pieces
//! whose box sticks out of the box of the end points found so far are halved (de Casteljau)
//! until their boxes lie within it, or are within [`BOX_FLATNESS`] of it.

use crate::bezier_piece::{pieces_of, BezierPiece};
use crate::profile::Profile;
use crate::region::Region;
use crate::V2;
use numeric::subdivide::{depth_first, Decision};

/// How far (relative to the box found) a piece's box may stick out and be taken as on the
/// box: a size is a scale for tolerances, needed to a few digits only.
const BOX_FLATNESS: f64 = 1e-9;

/// Halvings of a piece at most (each halves a piece's distance from its chord by four).
const MAX_EXTENT_DEPTH: usize = 30;

/// A box `[lo x, lo y, hi x, hi y]`.
pub type Box2 = [f64; 4];

/// The smallest box holding both.
pub fn union(a: Box2, b: Box2) -> Box2 {
    [
        a[0].min(b[0]),
        a[1].min(b[1]),
        a[2].max(b[2]),
        a[3].max(b[3]),
    ]
}

/// max(width, height) of a box.
///
/// ```
/// assert_eq!(curve::box_size([1.0, -2.0, 4.0, 5.0]), 7.0);
/// ```
pub fn box_size(b: Box2) -> f64 {
    (b[2] - b[0]).max(b[3] - b[1])
}

/// The box of the points of rational B-spline curves together, `[lo x, lo y, hi x, hi y]`, to
/// within `1e-9` of its size (never smaller than the points): what the contract's size of a
/// command's input curves is taken of.
///
/// ```
/// use bspline::{BSpline, Rational};
/// // A quadratic arch whose middle control point (at height 2) lies above the curve, which
/// // rises to 1: the box is the curve's, not the control points'.
/// let points = vec![-1.0, 0.0, 0.0, 2.0, 1.0, 0.0];
/// let arch = Rational::polynomial(&BSpline::bezier(2, points).unwrap());
/// let b = curve::curves_box(&[&arch]).unwrap();
/// // (Each side at or beyond the curve's, within 1e-9 of the size, 2.)
/// let sides = [(b[0], -1.0, -1.0), (b[1], 0.0, -1.0), (b[2], 1.0, 1.0), (b[3], 1.0, 1.0)];
/// for (got, want, out) in sides {
///     assert!((got - want) * out >= 0.0 && (got - want).abs() <= 1e-9 * 2.0);
/// }
/// ```
pub fn curves_box(curves: &[&bspline::Rational]) -> crate::Result<Box2> {
    let segments = curves
        .iter()
        .map(|c| {
            let curve = crate::SplineCurve::new((*c).clone())?;
            Ok(crate::Segment::from_parts(
                crate::SegmentKind::BSpline,
                curve,
                None,
                crate::OwnParam::Same,
            ))
        })
        .collect::<crate::Result<Vec<_>>>()?;
    Ok(segments_box(&segments))
}

/// The box of the points of `segments` (see [`Profile::bounding_box`]).
fn segments_box(segments: &[crate::Segment]) -> Box2 {
    let pieces: Vec<BezierPiece> = pieces_of(0, segments);
    let mut found = pieces.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, s| union(b, ends(s)),
    );
    // (The last piece first, and of two halves the second first, as the box was always
    // grown: the flatness allowed is relative to the box found so far.)
    for piece in pieces.into_iter().rev() {
        depth_first(piece, MAX_EXTENT_DEPTH, |s, visit| {
            grow_box(&mut found, s, visit.can_halve)
        });
    }
    found
}

/// Grows `found` by piece `s` where its control box sticks out of it: by the control box
/// where that is within the flatness (or `s` may not be halved), else by the ends of its
/// halves, which are then visited.
fn grow_box(found: &mut Box2, s: BezierPiece, can_halve: bool) -> Decision<BezierPiece, ()> {
    let Some([lo, hi]) = s.bounds else {
        // (A weight not positive: no hull to bound it; its ends are on it.)
        return Decision::Decided;
    };
    let control = [lo.x, lo.y, hi.x, hi.y];
    let room = BOX_FLATNESS * box_size(*found);
    let beyond = |by: f64| {
        control[0] < found[0] - by
            || control[1] < found[1] - by
            || control[2] > found[2] + by
            || control[3] > found[3] + by
    };
    if !beyond(0.0) {
        return Decision::Decided;
    }
    // (Within the flatness, or halved as far as it goes: its control box, which holds
    // it, is taken.)
    if !beyond(room) || !can_halve {
        *found = union(*found, control);
        return Decision::Decided;
    }
    let [first, second] = s.halves();
    *found = union(union(*found, ends(&first)), ends(&second));
    Decision::Halve(second, first)
}

impl Profile {
    /// The box of the profile's points, `[lo x, lo y, hi x, hi y]`, to within `1e-9` of its
    /// size (never smaller than the points).
    ///
    /// ```
    /// use curve::{Profile, Segment};
    /// let c = Segment::arc([1.0, 2.0], 3.0, 0.0, std::f64::consts::TAU).unwrap();
    /// let b = Profile::new(vec![c], None).unwrap().bounding_box();
    /// // (The arc's control points reach 3√2 out; its points, 3.)
    /// assert!((b[0] + 2.0).abs() < 1e-8 && (b[3] - 5.0).abs() < 1e-8);
    /// ```
    pub fn bounding_box(&self) -> Box2 {
        segments_box(self.segments())
    }
}

/// The box of a stretch's end points (which lie on the curve).
fn ends(s: &BezierPiece) -> Box2 {
    let (a, b): (V2, V2) = (s.start, s.end);
    [a.x.min(b.x), a.y.min(b.y), a.x.max(b.x), a.y.max(b.y)]
}

impl Region {
    /// The box of the region (of its outer boundary, which holds the holes).
    pub fn bounding_box(&self) -> Box2 {
        self.outer().bounding_box()
    }

    /// The size the region's relative tolerances are taken of: max(width, height) of its box.
    pub fn size(&self) -> f64 {
        box_size(self.bounding_box())
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::param::ParamCurve;
    use crate::segment::{Segment, SegmentKind};
    use crate::spline::SplineCurve;
    use proptest::prelude::*;

    proptest! {
        /// The box of a closed chain of cubics holds every sampled point and is within 1e-8
        /// of the box of a dense sampling refined at its extremes (the sampled box is inside
        /// the true one; the true one is inside the box found).
        #[test]
        fn boxes_hold_the_points_and_no_more(
            pts in proptest::collection::vec((0.1f64..3.0, -10.0f64..10.0), 10),
        ) {
            // (Rising in x: an open chain that cannot cross itself.)
            let p: Vec<[f64; 2]> = pts
                .iter()
                .scan(0.0, |x, &(dx, y)| {
                    *x += dx;
                    Some([*x, y])
                })
                .collect();
            let seg = |a: usize| {
                let c = SplineCurve::clamped(3, &p[a..a + 4], None, None).unwrap();
                Segment::spline(SegmentKind::Bezier, c).unwrap()
            };
            let profile = Profile::new(vec![seg(0), seg(3), seg(6)], Some(false)).unwrap();
            let b = profile.bounding_box();
            let (lo, hi) = profile.domain();
            // Dense samples (joints included), each extreme refined by ternary search on the
            // samples' neighbourhood.
            let n = 20_000;
            let at = |u: f64| profile.jet(u.clamp(lo, hi)).p;
            let mut us: Vec<f64> = (0..=n).map(|k| lo + (hi - lo) * k as f64 / n as f64).collect();
            us.extend([1.0, 2.0]);
            let mut sampled = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
            let step = (hi - lo) / n as f64;
            for (c, sign) in [(0usize, 1.0f64), (1, 1.0), (0, -1.0), (1, -1.0)] {
                let f = |u: f64| sign * at(u).arr()[c];
                let best = us.iter().copied().min_by(|a, b| f(*a).total_cmp(&f(*b))).unwrap();
                let (mut a, mut b2) = (best - step, best + step);
                for _ in 0..100 {
                    let (m1, m2) = (a + (b2 - a) / 3.0, b2 - (b2 - a) / 3.0);
                    if f(m1) < f(m2) { b2 = m2 } else { a = m1 }
                }
                let v = f(best).min(f(0.5 * (a + b2)));
                let k = if sign > 0.0 { c } else { c + 2 };
                sampled[k] = sign * v;
            }
            let size = box_size(b);
            for k in 0..2 {
                prop_assert!(b[k] <= sampled[k] + 1e-12 * size, "{b:?} {sampled:?}");
                prop_assert!(b[k + 2] >= sampled[k + 2] - 1e-12 * size, "{b:?} {sampled:?}");
                prop_assert!(sampled[k] - b[k] <= 1e-8 * size, "{b:?} {sampled:?}");
                prop_assert!(b[k + 2] - sampled[k + 2] <= 1e-8 * size, "{b:?} {sampled:?}");
            }
        }
    }
}
