//! Searches on curvekit's curve model: what a medial axis, an offset, a figure or a reader
//! asks of a profile, answered by bounds on its exact form rather than by samples where the
//! answer is certified.
//!
//! - [`ProfileClearance`]: whether a disk, or a convex polygon, holds a point of a profile
//!   ([`clearance`](ProfileClearance::clearance), proven by halving Bézier pieces until
//!   their hulls decide; [`misses_convex_polygon`](ProfileClearance::misses_convex_polygon),
//!   by separating axes).
//! - [`NearestPoint`]: the nearest point of a profile to a point, its [`Foot`] (global: a
//!   branch and bound on the Bézier pieces' hulls, polished by Newton's method), and the
//!   nearest point near a known parameter.
//! - [`Flatten`]: polylines within a proven distance of a profile or a segment.
//!
//! The model (`curve`) keeps, as data, what these searches read fast: the boxes of the
//! segments and of their Bézier pieces, grown by what rounding may hide, and the hierarchy
//! over them. Bring a trait into scope to call its searches as methods:
//!
//! ```
//! use curve::{Profile, Segment};
//! use geometry::{Clearance, NearestPoint, ProfileClearance};
//! let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
//! let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
//! let box_ = Profile::new(sides, None).unwrap();
//! assert_eq!(box_.clearance([1.0, 1.0], 0.999), Clearance::Clear);
//! assert_eq!(box_.nearest([1.0, 0.5], 0.0).distance, 0.5);
//! ```

mod clearance;
mod flatten;
mod nearest;
mod pieces;
mod polygon_clearance;

pub use clearance::Clearance;
pub use nearest::Foot;

use curve::{Profile, Segment};

/// Whether a disk or a convex polygon holds a point of a profile, proven.
pub trait ProfileClearance {
    /// Whether the disk of centre `x` and radius `r` holds a point of the profile.
    ///
    /// ```
    /// use curve::{Profile, Segment};
    /// use geometry::{Clearance, ProfileClearance};
    /// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let box_ = Profile::new(sides, None).unwrap();
    /// assert_eq!(box_.clearance([1.0, 1.0], 0.999), Clearance::Clear);
    /// assert!(matches!(box_.clearance([1.0, 1.0], 1.001), Clearance::Entered { .. }));
    /// ```
    fn clearance(&self, x: [f64; 2], r: f64) -> Clearance;

    /// Whether the disk of centre `x` and radius `r` holds a point of the profile whose
    /// parameter lies in `[lo, hi]` (on a closed profile the window may run past either end
    /// of the domain, once round): the other points are not looked at.
    ///
    /// ```
    /// use curve::{Profile, Segment};
    /// use geometry::{Clearance, ProfileClearance};
    /// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let box_ = Profile::new(sides, None).unwrap();
    /// // The disk about (1, 0.5) of radius 1 holds points of the bottom side (0), not of
    /// // the top side (2) or the left one (3).
    /// assert_eq!(box_.clearance_between([1.0, 0.5], 1.0, 1.9, 3.1), Clearance::Clear);
    /// assert!(matches!(
    ///     box_.clearance_between([1.0, 0.5], 1.0, -0.5, 0.5),
    ///     Clearance::Entered { .. }
    /// ));
    /// ```
    fn clearance_between(&self, x: [f64; 2], r: f64, lo: f64, hi: f64) -> Clearance;

    /// Whether no point of the profile lies in the closed convex polygon `corners` (in either
    /// turning order): `true` where every segment near it is a line proven apart from it by
    /// a separating axis, with room for rounding. `false` where that is not proven: a
    /// segment meets the polygon or comes within rounding of it, a curved segment lies near
    /// it, or the polygon has fewer than three corners or is not finite.
    ///
    /// ```
    /// use curve::{Profile, Segment};
    /// use geometry::ProfileClearance;
    /// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let box_ = Profile::new(sides, None).unwrap();
    /// assert!(box_.misses_convex_polygon(&[[1.0, 0.5], [3.0, 0.5], [2.0, 1.5]]));
    /// assert!(!box_.misses_convex_polygon(&[[1.0, 0.5], [3.0, 0.5], [2.0, 2.5]]));
    /// ```
    fn misses_convex_polygon(&self, corners: &[[f64; 2]]) -> bool;
}

impl ProfileClearance for Profile {
    fn clearance(&self, x: [f64; 2], r: f64) -> Clearance {
        clearance::clearance(self, x, r)
    }

    fn clearance_between(&self, x: [f64; 2], r: f64, lo: f64, hi: f64) -> Clearance {
        clearance::clearance_between(self, x, r, lo, hi)
    }

    fn misses_convex_polygon(&self, corners: &[[f64; 2]]) -> bool {
        polygon_clearance::misses_convex_polygon(self, corners)
    }
}

/// The nearest point of a profile.
pub trait NearestPoint {
    /// The nearest point of the profile to `x`; the search stops early once a point nearer
    /// than `enough` is found (pass 0 for the nearest point itself).
    ///
    /// ```
    /// use curve::{Profile, Segment};
    /// use geometry::NearestPoint;
    /// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let box_ = Profile::new(sides, None).unwrap();
    /// let n = box_.nearest([1.0, 0.5], 0.0);
    /// assert!((n.distance - 0.5).abs() < 1e-15 && (n.u - 0.25).abs() < 1e-15);
    /// ```
    fn nearest(&self, x: [f64; 2], enough: f64) -> Foot;

    /// The nearest point to `x` near the parameter `u`: Newton's method on the foot-point
    /// condition from `u`, inside the segment holding it (a local search, for a point known
    /// to be near: a junction's third contact, followed as the disk moves).
    fn nearest_near(&self, x: [f64; 2], u: f64) -> Foot;
}

impl NearestPoint for Profile {
    fn nearest(&self, x: [f64; 2], enough: f64) -> Foot {
        nearest::nearest(self, x, enough)
    }

    fn nearest_near(&self, x: [f64; 2], u: f64) -> Foot {
        nearest::nearest_near(self, x, u)
    }
}

/// Polylines within a proven distance of a curve: for drawing, for GeoJSON and shapely, for
/// any program that wants straight pieces.
pub trait Flatten {
    /// The profile as a polyline within `tol` of it (both ways), from its start to its end
    /// (for a closed profile, its start again at the end); every vertex on the profile. A
    /// `tol` that is not finite and positive is taken as the profile's size × 1e-3, and none
    /// finer than the rounding of its coordinates (1e3 ε of their magnitude) is taken.
    ///
    /// ```
    /// use curve::{Profile, Segment};
    /// use geometry::Flatten;
    /// let circle = Profile::new(vec![Segment::arc([0.0, 0.0], 1.0, 0.0, std::f64::consts::TAU).unwrap()], None).unwrap();
    /// let ring = circle.flattened(1e-3);
    /// assert_eq!(ring.first(), ring.last());
    /// // Each chord of a circle of radius 1 within 1e-3 spans at most 2·acos(1 − 1e-3) ≈ 0.0895 rad.
    /// assert!(ring.len() >= (std::f64::consts::TAU / 0.0895) as usize);
    /// ```
    ///
    /// For a [`Segment`] (one that is no profile's: an offset loop's piece) the same, with no
    /// default tolerance: a `tol` that is not finite and positive is taken as the rounding of
    /// its coordinates.
    fn flattened(&self, tol: f64) -> Vec<[f64; 2]>;
}

impl Flatten for Profile {
    fn flattened(&self, tol: f64) -> Vec<[f64; 2]> {
        flatten::flattened(self, tol)
    }
}

impl Flatten for Segment {
    fn flattened(&self, tol: f64) -> Vec<[f64; 2]> {
        flatten::segment_flattened(self, tol)
    }
}

/// [`Flatten::flattened`] of a profile, each vertex with its parameter on the profile.
///
/// ```
/// use curve::{ParamCurve, Profile, Segment};
/// use geometry::flattened_with_params;
/// // A half circle within 1e-3: every vertex is the profile's point at its parameter.
/// let arc = Segment::arc([0.0, 0.0], 1.0, 0.0, std::f64::consts::PI).unwrap();
/// let p = Profile::new(vec![arc], None).unwrap();
/// let points = flattened_with_params(&p, 1e-3);
/// assert!(points.len() > 10);
/// for (v, u) in points {
///     let on = p.jet(u).p;
///     assert!((on.x - v[0]).hypot(on.y - v[1]) < 1e-12);
/// }
/// ```
pub fn flattened_with_params(profile: &Profile, tol: f64) -> Vec<([f64; 2], f64)> {
    flatten::flattened_with_params(profile, tol)
}
