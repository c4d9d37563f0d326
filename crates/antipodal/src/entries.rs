//! The crate's commands, one entry each, on a smooth curve or a profile ([`Boundary`]): a
//! curve is answered on its own exact form (prepared once per call; see [`crate::prepare`]
//! to keep it warm), in its own parameter; a profile segment by segment, its corners taking
//! part. A closed profile of one smooth segment is the smooth curve it is, and runs as one.

use crate::error::{Error, Result};
use crate::prepare::{prepare, prepare_pair};
use crate::profile_pairs::profile_antipodal;
use crate::profile_tangents::profile_tangents;
use crate::profiles::profile_inflections;
use crate::types::{Antipodal, Inflections, Options, Tangents};
use curve::{Boundary, Profile};
use std::borrow::Cow;

/// Every pair of antipodal points of a simple closed curve (Jia 2004), or of a closed
/// profile: there with a corner at one end or both where the segment between them lies
/// inside the corner's cone of inward normals (see the contract), and the continua of pairs
/// (facing parallel lines, concentric arcs) as families. Certified where every decision is
/// (the curve kinds of `curve`; lines and arcs are exact rational curves).
///
/// ```
/// use antipodal::{antipodal, shapes::Ellipse, Options};
/// let e = Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap();
/// let r = antipodal(&e, &Options::default()).unwrap();
/// assert_eq!(r.pairs.len(), 2);
/// ```
///
/// ```
/// use antipodal::{antipodal, Options, Verdict};
/// use curve::{Profile, Segment};
/// // A right triangle: the right-angle corner pairs with the foot of its perpendicular on
/// // the hypotenuse; the two sharp corners pair along the hypotenuse (a corner sharper than
/// // a right angle has its edges' directions inside its cone).
/// let c = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
/// let sides = (0..3).map(|i| Segment::line(c[i], c[(i + 1) % 3]).unwrap()).collect();
/// let t = Profile::new(sides, None).unwrap();
/// let r = antipodal(&t, &Options::default()).unwrap();
/// assert!(r.certified());
/// assert_eq!(r.pairs.len(), 2);
/// let foot = &r.pairs[0];
/// assert_eq!((foot.corner, foot.kind), (Some([true, false]), None));
/// assert!((foot.q[0] - 2.0).abs() < 1e-12 && (foot.q[1] - 2.0).abs() < 1e-12);
/// assert_eq!(r.pairs[1].corner, Some([true, true]));
/// ```
pub fn antipodal<'a>(boundary: impl Into<Boundary<'a>>, opts: &Options) -> Result<Antipodal> {
    match boundary.into() {
        Boundary::Curve(c) => prepare(c).antipodal(opts),
        Boundary::Profile(p) => profile_antipodal(p, opts),
    }
}

/// All simple inflections of a curve (Jia §5.1; certified for the curve kinds of `curve`), or
/// of a profile: inside each curved segment, and at smooth joints where the curvature changes
/// sign across the joint (an arc joined tangentially to an arc bent the other way); a
/// profile's corners are listed, and are not inflections. A straight segment has no single
/// inflection: none is reported on it.
///
/// ```
/// use antipodal::{inflections, Options, SplineCurve, Verdict};
/// // An S-shaped cubic Bézier turns left, then right: one inflection, at its middle by
/// // symmetry.
/// let s = SplineCurve::clamped(3, &[[0.0, 0.0], [1.0, 1.0], [2.0, -1.0], [3.0, 0.0]], None, None)
///     .unwrap();
/// let r = inflections(&s, &Options::default()).unwrap();
/// assert!(r.certified());
/// assert_eq!(r.inflections.len(), 1);
/// assert!((r.inflections[0].u - 0.5).abs() < 1e-12);
/// assert!((r.inflections[0].p[0] - 1.5).abs() < 1e-12);
/// ```
///
/// ```
/// use antipodal::{inflections, Options};
/// use curve::{Profile, Segment};
/// use std::f64::consts::PI;
/// // An S of two half circles: one inflection, at the joint.
/// let s = Profile::new(
///     vec![
///         Segment::arc([1.0, 0.0], 1.0, PI, 0.0).unwrap(),
///         Segment::arc([3.0, 0.0], 1.0, PI, 2.0 * PI).unwrap(),
///     ],
///     None,
/// )
/// .unwrap();
/// let r = inflections(&s, &Options::default()).unwrap();
/// assert_eq!(r.inflections.len(), 1);
/// assert_eq!((r.inflections[0].u, r.inflections[0].segment), (1.0, Some(1)));
/// assert!(r.corner_list().is_empty());
/// ```
pub fn inflections<'a>(boundary: impl Into<Boundary<'a>>, opts: &Options) -> Result<Inflections> {
    match boundary.into() {
        Boundary::Curve(c) => prepare(c).inflections(opts),
        Boundary::Profile(p) => profile_inflections(p, opts),
    }
}

/// Every line tangent to both boundaries (Jia §2.5). Two curves are prepared in one frame
/// and answered in their own parameters (see [`crate::Prepared::common_tangents`] to keep
/// them warm); where one is a profile (open or closed), the other is taken as the profile of
/// its one segment, and the lines say which corners and segments they touch.
///
/// ```
/// use antipodal::{common_tangents, shapes::Circle, Options};
/// // Two unit circles apart: two outer tangents (y = ±1) and two crossing between them.
/// let (a, b) = (Circle::new(1.0, [0.0, 0.0]).unwrap(), Circle::new(1.0, [4.0, 0.0]).unwrap());
/// let r = common_tangents(&a, &b, &Options::default()).unwrap();
/// assert_eq!(r.lines.len(), 4);
/// let outer = r.lines.iter().filter(|l| (l.p[1] - l.q[1]).abs() < 1e-12).count();
/// assert_eq!(outer, 2);
/// ```
///
/// ```
/// use antipodal::{common_tangents, Options, Verdict};
/// use curve::{Profile, Segment};
/// // Two squares side by side: the lines through opposite corners (the diagonals' cross
/// // tangents) and the lines along the top and bottom edges (limit cases, left out).
/// let square = |x: f64| {
///     let c = [[x, 0.0], [x + 1.0, 0.0], [x + 1.0, 1.0], [x, 1.0]];
///     Profile::new((0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect(), None)
///         .unwrap()
/// };
/// let r = common_tangents(&square(0.0), &square(3.0), &Options::default()).unwrap();
/// assert!(r.certified());
/// assert_eq!(r.lines.len(), 2);
/// assert!(r.lines.iter().all(|l| l.corner == Some([true, true])));
/// ```
pub fn common_tangents<'a, 'b>(
    first: impl Into<Boundary<'a>>,
    second: impl Into<Boundary<'b>>,
    opts: &Options,
) -> Result<Tangents> {
    match (first.into(), second.into()) {
        (Boundary::Curve(c1), Boundary::Curve(c2)) => {
            let (p1, p2) = prepare_pair(c1, c2);
            p1.common_tangents(&p2, opts)
        }
        (b1, b2) => profile_tangents(&*as_profile(b1, 1)?, &*as_profile(b2, 2)?, opts),
    }
}

/// `boundary` (the `which`-th of a command's) as a profile, a curve as its one segment.
fn as_profile(boundary: Boundary<'_>, which: usize) -> Result<Cow<'_, Profile>> {
    boundary.to_profile()?.ok_or(Error::NoSegment { which })
}
