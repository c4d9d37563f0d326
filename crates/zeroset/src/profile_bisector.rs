//! Bisectors of profiles: chains of lines, arcs and splines joined at corners or smoothly
//! ([`curve::Profile`]).
//!
//! A profile's sites are its segments and its corners. A segment contributes foot points on
//! its normals, as a smooth curve does; a corner is a point site for the directions of its
//! cone, the wedge between the normals of its two segments on the side the chain bends away
//! from (for the region a closed profile encloses: its reflex corners; outside it: its convex
//! ones). The bisector of two profiles is the union of the bisectors of every site of one
//! with every site of the other; the self-bisector of a profile that of every pair of its
//! sites and the self-bisector of each segment. Each branch says which sites its two foot
//! points lie on; its parameters are the profiles' (`[0, n)`, a corner at its joint's `u`).
//!
//! Two pieces of one circle have every normal through its centre: their bisector is that one
//! point (reported as isolated), as is the self-bisector of an arc. Two pieces of one line
//! have none.
//!
//! A profile of one spline segment without a corner is the curve it is: `profile_bisector`
//! (of two such) and `profile_self_bisector` run the curve's bisector on it (`whole_curve`).

mod arcs;
#[cfg(test)]
mod closed_form_checks;
mod lines;
mod point_site;
mod polyline;
mod run;
mod site_pairs;
mod stretches;
mod tangent_centre;
mod whole_curve;

use crate::bisector::{Bisector, BisectorOptions};
use crate::error::Result;
use bspline::Rational;
use curve::{JointKind, Profile};
use point_site::Corner;
use run::Run;
use whole_curve::{one_spline, spline_bisector, spline_self_bisector};

/// A site of a profile.
#[derive(Debug, Clone, Copy)]
enum Site<'a> {
    Segment {
        index: usize,
        curve: &'a Rational,
    },
    Corner {
        /// The segment starting at the corner.
        index: usize,
        /// The segment arriving there.
        before: usize,
        u: f64,
        corner: Corner,
    },
}

impl Site<'_> {
    /// The segments the site belongs to: its own, or the two a corner joins.
    fn segments(&self) -> [usize; 2] {
        match self {
            Site::Segment { index, .. } => [*index; 2],
            Site::Corner { index, before, .. } => [*index, *before],
        }
    }

    /// Whether `keep` accepts some segment of this site with some segment of `other`.
    fn kept_with(&self, other: &Site<'_>, keep: &dyn Fn(usize, usize) -> bool) -> bool {
        let (a, b) = (self.segments(), other.segments());
        a.iter().any(|&i| b.iter().any(|&j| keep(i, j)))
    }
}

fn sites(p: &Profile) -> Vec<Site<'_>> {
    let segs = p.segments();
    let n = segs.len();
    let mut out: Vec<Site<'_>> = segs
        .iter()
        .enumerate()
        .map(|(index, s)| Site::Segment {
            index,
            curve: s.curve().curve(),
        })
        .collect();
    for j in p.joints().iter().filter(|j| j.kind != JointKind::Smooth) {
        let index = (j.u as usize).min(n - 1);
        let before = (index + n - 1) % n;
        let (Some(arriving), Some(leaving)) =
            (segs[before].end_direction(), segs[index].start_direction())
        else {
            continue;
        };
        out.push(Site::Corner {
            index,
            before,
            u: j.u,
            corner: Corner {
                p: segs[index].start().arr(),
                arriving: arriving.arr(),
                leaving: leaving.arr(),
            },
        });
    }
    out
}

/// The bisector of two profiles: every point with a foot point on each, at equal distance,
/// on the normal of a segment or inside the cone of a corner.
///
/// Two profiles that are each one Bézier or B-spline segment without a corner (open, or
/// closed with a smooth seam; not an analytic shape's form) are the curves they are: their
/// bisector is the curve engine's, on the segments' splines (a periodic spline's whole
/// curve), its parameters the profiles', every foot on segment 0 and no corner
/// ([`crate::Bisector::without_sites`] drops those again).
pub(crate) fn profile_bisector(
    a: &Profile,
    b: &Profile,
    opts: &BisectorOptions,
) -> Result<Bisector> {
    if let (Some(a), Some(b)) = (one_spline(a), one_spline(b)) {
        return spline_bisector(&a, &b, opts);
    }
    profile_bisector_of_pairs(a, b, opts, &|_, _| true)
}

/// The bisector of two profiles restricted to the pairs of segments `keep(i, j)` accepts
/// (segment `i` of `a`, `j` of `b`); a corner counts as each of the two segments it joins. For
/// callers that have shown which pairs can matter (the medial axis keeps the pairs that can
/// share an empty disk).
///
/// ```
/// use curve::{Profile, Segment};
/// use zeroset::{bisector, profile_bisector_of_pairs, BisectorOptions};
/// // Two L-shaped walls, each a vertical segment then a horizontal one: kept to the pair of
/// // their vertical segments, the bisector is theirs alone (x = 2 between x = 0 and 4); the
/// // whole one also has the left top's bisector with the right side (on y = x − 1).
/// let wall = |x: f64, to: f64| {
///     let segs = vec![
///         Segment::line([x, 0.0], [x, 3.0]).unwrap(),
///         Segment::line([x, 3.0], [to, 3.0]).unwrap(),
///     ];
///     Profile::new(segs, None).unwrap()
/// };
/// let (left, right) = (wall(0.0, 2.0), wall(4.0, 3.0));
/// let opts = BisectorOptions::default();
/// let kept = profile_bisector_of_pairs(&left, &right, &opts, &|i, j| i == 0 && j == 0).unwrap();
/// let all = bisector(&left, &right, &opts).unwrap();
/// let on_middle = |br: &zeroset::Branch| br.xy.iter().all(|p| (p[0] - 2.0).abs() < 1e-9);
/// assert!(!kept.branches.is_empty() && kept.branches.iter().all(on_middle));
/// assert!(!all.branches.iter().all(on_middle));
/// ```
pub fn profile_bisector_of_pairs(
    a: &Profile,
    b: &Profile,
    opts: &BisectorOptions,
    keep: &dyn Fn(usize, usize) -> bool,
) -> Result<Bisector> {
    let run = Run::new(&[a, b], opts);
    let (sa, sb) = (sites(a), sites(b));
    let mut out = run.empty();
    for s in &sa {
        for t in &sb {
            if s.kept_with(t, keep) {
                run.pair(s, t, false, &mut out)?;
            }
        }
    }
    run.trim(&mut out, [a, b]);
    Ok(out)
}

/// The self-bisector of a profile: pairs of distinct foot points on it, on different sites
/// or on one segment.
///
/// A profile of one Bézier or B-spline segment without a corner (as for
/// [`profile_bisector`]) is the curve it is: its self-bisector is the curve engine's, on the
/// segment's spline (a periodic spline's whole curve), in the profile's parameter.
pub(crate) fn profile_self_bisector(p: &Profile, opts: &BisectorOptions) -> Result<Bisector> {
    if let Some(spline) = one_spline(p) {
        return spline_self_bisector(&spline, opts);
    }
    profile_self_bisector_of_pairs(p, opts, &|_, _| true)
}

/// The self-bisector of a profile restricted to the pairs of segments `keep(i, j)` accepts
/// (`i ≤ j`; a segment's own bisector is `keep(i, i)`); a corner counts as each of the two
/// segments it joins.
///
/// ```
/// use curve::{Profile, Segment};
/// use zeroset::{profile_self_bisector_of_pairs, BisectorOptions};
/// // A 4 × 2 rectangle, kept to its two long sides (segments 0 and 2): their bisector is the
/// // middle line y = 1.
/// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
/// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
/// let rect = Profile::new(sides, None).unwrap();
/// let keep = |i: usize, j: usize| (i, j) == (0, 2);
/// let b = profile_self_bisector_of_pairs(&rect, &BisectorOptions::default(), &keep).unwrap();
/// assert!(!b.branches.is_empty());
/// assert!(b.branches.iter().all(|br| br.xy.iter().all(|p| (p[1] - 1.0).abs() < 1e-9)));
/// ```
pub fn profile_self_bisector_of_pairs(
    p: &Profile,
    opts: &BisectorOptions,
    keep: &dyn Fn(usize, usize) -> bool,
) -> Result<Bisector> {
    let run = Run::new(&[p], opts);
    let s = sites(p);
    let mut out = run.empty();
    let ordered = |i: usize, j: usize| keep(i.min(j), i.max(j));
    for (i, x) in s.iter().enumerate() {
        if let Site::Segment { index, curve } = x {
            if keep(*index, *index) {
                run.segment_self(*index, curve, p, &mut out)?;
            }
        }
        for y in &s[i + 1..] {
            if x.kept_with(y, &ordered) {
                run.pair(x, y, true, &mut out)?;
            }
        }
    }
    run.trim(&mut out, [p, p]);
    Ok(out)
}
