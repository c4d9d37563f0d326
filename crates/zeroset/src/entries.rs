//! The bisector commands, one entry each, on smooth curves or profiles ([`Boundary`]).
//!
//! Splines are answered by the curve engine (Elber & Kim's functions on their rational forms),
//! in their own parameters. A profile is answered site by site, its corners point sites
//! inside their cones; an analytic shape, or a spline beside a profile, is taken as the
//! profile of its one segment. A profile of one spline segment without a corner is the curve
//! it is, and runs on the curve engine.

use crate::bisector::{curve_bisector, curve_self_bisector, Bisector, BisectorOptions};
use crate::error::{Error, Result};
use crate::profile_bisector::{profile_bisector, profile_self_bisector};
use bspline::Rational;
use curve::{Boundary, Exact, Profile};
use std::borrow::Cow;

/// The bisector of two curves or profiles: every point with a foot point on each, at equal
/// distance, on the normal of a curve or segment or inside the cone of a corner, as branches
/// of matched foot parameters `(t, r)` and their points.
///
/// ```
/// use bspline::{BSpline, Rational};
/// use curve::SplineCurve;
/// use zeroset::{bisector, BisectorOptions};
/// // Two segments on the axes, c1(t) = (1 + 2t, 0) and c2(r) = (0, 1 + 2r): the points
/// // equidistant from both with perpendicular feet are those of the diagonal, their feet at
/// // t = r.
/// let on = |points| SplineCurve::new(Rational::polynomial(&BSpline::bezier(2, points).unwrap()));
/// let c1 = on(vec![1.0, 0.0, 3.0, 0.0]).unwrap();
/// let c2 = on(vec![0.0, 1.0, 0.0, 3.0]).unwrap();
/// let b = bisector(&c1, &c2, &BisectorOptions::default()).unwrap();
/// assert!(b.complete && !b.branches.is_empty());
/// for br in &b.branches {
///     for (tr, xy) in br.tr.iter().zip(&br.xy) {
///         assert!((tr[0] - tr[1]).abs() < 1e-9 && (xy[0] - xy[1]).abs() < 1e-9);
///     }
/// }
/// ```
///
/// ```
/// use curve::{Profile, Segment};
/// use zeroset::{bisector, BisectorOptions};
/// // Two right angles 4 apart, their corners' cones both above: their bisector is a ray of x = 2.
/// let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
/// let left = Profile::new(vec![l([0., -1.], [0., 0.]), l([0., 0.], [-1., 0.])], None).unwrap();
/// let right = Profile::new(vec![l([4., -1.], [4., 0.]), l([4., 0.], [5., 0.])], None).unwrap();
/// let b = bisector(&left, &right, &BisectorOptions::default()).unwrap();
/// assert!(b.complete);
/// let corners = b.branches.iter().find(|br| br.corners() == [true, true]).unwrap();
/// assert!(corners.xy.iter().all(|p| (p[0] - 2.0).abs() < 1e-12));
/// ```
pub fn bisector<'a, 'b>(
    first: impl Into<Boundary<'a>>,
    second: impl Into<Boundary<'b>>,
    opts: &BisectorOptions,
) -> Result<Bisector> {
    let (first, second) = (first.into(), second.into());
    if let (Some(c1), Some(c2)) = (spline_of(first), spline_of(second)) {
        return curve_bisector(c1, c2, opts);
    }
    profile_bisector(&*as_profile(first, 1)?, &*as_profile(second, 2)?, opts)
}

/// The self-bisector of a curve or profile: pairs of distinct foot points on it (`t < r`), on
/// different sites or on one segment.
///
/// ```
/// use bspline::{BSpline, Rational};
/// use curve::SplineCurve;
/// use zeroset::{self_bisector, BisectorOptions};
/// // A symmetric arch: its mirrored points, t and 1 − t, are equidistant from the points of
/// // its axis of symmetry x = 0.
/// let points = vec![-1.0, 0.0, 0.0, 2.0, 1.0, 0.0];
/// let arch = SplineCurve::new(Rational::polynomial(&BSpline::bezier(2, points).unwrap())).unwrap();
/// let b = self_bisector(&arch, &BisectorOptions::default()).unwrap();
/// assert!(b.complete && !b.branches.is_empty());
/// let on_axis = |br: &zeroset::Branch| {
///     br.tr.iter().zip(&br.xy).all(|(tr, xy)| {
///         (tr[0] + tr[1] - 1.0).abs() < 1e-9 && xy[0].abs() < 1e-9
///     })
/// };
/// assert!(b.branches.iter().any(on_axis));
/// ```
///
/// ```
/// use curve::{Profile, Segment, SegmentKind, SplineCurve};
/// use zeroset::{self_bisector, BisectorOptions};
/// // A periodic cubic as a profile of its one segment is its whole curve: the profile's
/// // self-bisector is the curve's, its parameters the profile's (the curve's on [0, 4) over 4).
/// let ring = [[2.0, 0.0], [0.0, 1.0], [-2.0, 0.0], [0.0, -1.0]];
/// let spline = SplineCurve::periodic(3, &ring, None).unwrap();
/// let segment = Segment::periodic_spline(SegmentKind::BSpline, &spline).unwrap();
/// let profile = Profile::of_curve(segment, (0.0, 4.0)).unwrap();
/// let opts = BisectorOptions::default();
/// let on_profile = self_bisector(&profile, &opts).unwrap().without_sites();
/// let on_curve = self_bisector(&spline, &opts).unwrap();
/// assert!(!on_curve.branches.is_empty());
/// for (p, c) in on_profile.branches.iter().zip(&on_curve.branches) {
///     assert_eq!(p.xy, c.xy);
///     assert!(p.tr.iter().zip(&c.tr).all(|(p, c)| p == &[c[0] / 4.0, c[1] / 4.0]));
/// }
/// ```
///
/// ```
/// use curve::{Profile, Segment};
/// use zeroset::{self_bisector, BisectorOptions};
/// // An L-shaped room: its reflex corner is a point site inside.
/// let c = [[0., 0.], [4., 0.], [4., 2.], [2., 2.], [2., 4.], [0., 4.]];
/// let sides = (0..6).map(|i| Segment::line(c[i], c[(i + 1) % 6]).unwrap()).collect();
/// let room = Profile::new(sides, None).unwrap();
/// let opts = BisectorOptions { trimmed: true, ..Default::default() };
/// let b = self_bisector(&room, &opts).unwrap();
/// assert!(b.branches.iter().any(|br| br.corners().contains(&true)));
/// ```
pub fn self_bisector<'a>(
    boundary: impl Into<Boundary<'a>>,
    opts: &BisectorOptions,
) -> Result<Bisector> {
    let boundary = boundary.into();
    match spline_of(boundary) {
        Some(c) => curve_self_bisector(c, opts),
        None => profile_self_bisector(&*as_profile(boundary, 1)?, opts),
    }
}

/// The rational form of a spline given as a curve.
fn spline_of(boundary: Boundary<'_>) -> Option<&Rational> {
    match boundary {
        Boundary::Curve(c) => match c.exact() {
            Some(Exact::Spline(s)) => Some(s.curve()),
            Some(Exact::Shape(_)) | None => None,
        },
        Boundary::Profile(_) => None,
    }
}

/// `boundary` (the `which`-th of the command's) as a profile, a curve as its one segment.
fn as_profile(boundary: Boundary<'_>, which: usize) -> Result<Cow<'_, Profile>> {
    boundary.to_profile()?.ok_or(Error::NotExact { which })
}
