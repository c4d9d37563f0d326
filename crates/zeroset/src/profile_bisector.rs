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

mod arcs;
#[cfg(test)]
mod closed_form_checks;
mod lines;
mod point_site;
mod polyline;
mod stretches;

use crate::bisector::{bbox_of_points, bisector, self_bisector, FAR};
use crate::bisector::{Bisector, BisectorOptions, Branch, TRIM_SLACK};
use crate::error::Result;
use arcs::{arc_bisector, Carrier};
use bspline::Rational;
use curve::{JointKind, ParamCurve, Profile, Segment, SegmentKind};
use numeric::tolerance::ChordTol;
use point_site::{corner_corner, corner_curve, Corner, Reach, SharedEnd};
use serde::{Deserialize, Serialize};

/// Two straight segments are on one line when the cross products of their directions with
/// each other and with the line between them are this small relative to their lengths.
const COLLINEAR: f64 = 1e-12;

/// A branch of two segments' bisector whose vertices all lie within this share of the
/// profiles' size of one another is one point (reported as isolated): the contract's
/// tolerance for points of a drawing that meet.
const POINT_EXTENT: f64 = 1e-9;

/// One branch of a profile bisector.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ProfileBranch {
    /// `[t, r]` per vertex: the foot points' profile parameters (a corner's is constant).
    pub tr: Vec<[f64; 2]>,
    /// The bisector point per vertex.
    pub xy: Vec<[f64; 2]>,
    /// The segment of each foot point (for a corner, the segment starting there).
    pub segment: [usize; 2],
    /// Whether each foot point is a corner.
    pub corner: [bool; 2],
}

/// A special point of a profile bisector.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ProfilePoint {
    /// Foot-point parameters.
    pub tr: [f64; 2],
    /// The bisector point.
    pub xy: [f64; 2],
    /// The segment of each foot point.
    pub segment: [usize; 2],
    /// Whether each foot point is a corner (always false: special points come from segments).
    pub corner: [bool; 2],
}

/// The bisector of two profiles, or the self-bisector of one.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ProfileBisector {
    /// The branches, site pair by site pair.
    pub branches: Vec<ProfileBranch>,
    /// Where branches of one pair of segments cross.
    pub singular: Vec<ProfilePoint>,
    /// Isolated bisector points (among them the centres of arcs of one circle).
    pub isolated: Vec<ProfilePoint>,
    /// False when a search limit was hit.
    pub complete: bool,
}

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
/// ```
/// use curve::{Profile, Segment};
/// use zeroset::{profile_bisector, BisectorOptions};
/// // Two right angles 4 apart, their corners' cones both above: their bisector is a ray of x = 2.
/// let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
/// let left = Profile::new(vec![l([0., -1.], [0., 0.]), l([0., 0.], [-1., 0.])], None).unwrap();
/// let right = Profile::new(vec![l([4., -1.], [4., 0.]), l([4., 0.], [5., 0.])], None).unwrap();
/// let b = profile_bisector(&left, &right, &BisectorOptions::default()).unwrap();
/// assert!(b.complete);
/// let corners = b.branches.iter().find(|br| br.corner == [true, true]).unwrap();
/// assert!(corners.xy.iter().all(|p| (p[0] - 2.0).abs() < 1e-12));
/// ```
pub fn profile_bisector(
    a: &Profile,
    b: &Profile,
    opts: &BisectorOptions,
) -> Result<ProfileBisector> {
    profile_bisector_of_pairs(a, b, opts, &|_, _| true)
}

/// [`profile_bisector`] restricted to the pairs of segments `keep(i, j)` accepts (segment `i`
/// of `a`, `j` of `b`); a corner counts as each of the two segments it joins. For callers
/// that have shown which pairs can matter (the medial axis keeps the pairs that can share an
/// empty disk).
pub fn profile_bisector_of_pairs(
    a: &Profile,
    b: &Profile,
    opts: &BisectorOptions,
    keep: &dyn Fn(usize, usize) -> bool,
) -> Result<ProfileBisector> {
    opts.validate()?;
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
/// ```
/// use curve::{Profile, Segment};
/// use zeroset::{profile_self_bisector, BisectorOptions};
/// // An L-shaped room: its reflex corner is a point site inside.
/// let c = [[0., 0.], [4., 0.], [4., 2.], [2., 2.], [2., 4.], [0., 4.]];
/// let sides = (0..6).map(|i| Segment::line(c[i], c[(i + 1) % 6]).unwrap()).collect();
/// let room = Profile::new(sides, None).unwrap();
/// let opts = BisectorOptions { trimmed: true, ..Default::default() };
/// let b = profile_self_bisector(&room, &opts).unwrap();
/// assert!(b.branches.iter().any(|br| br.corner.contains(&true)));
/// ```
pub fn profile_self_bisector(p: &Profile, opts: &BisectorOptions) -> Result<ProfileBisector> {
    profile_self_bisector_of_pairs(p, opts, &|_, _| true)
}

/// [`profile_self_bisector`] restricted to the pairs of segments `keep(i, j)` accepts (`i ≤
/// j`; a segment's own bisector is `keep(i, i)`); a corner counts as each of the two
/// segments it joins.
pub fn profile_self_bisector_of_pairs(
    p: &Profile,
    opts: &BisectorOptions,
    keep: &dyn Fn(usize, usize) -> bool,
) -> Result<ProfileBisector> {
    opts.validate()?;
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

/// What one computation shares: the options, the profiles' size and reach.
struct Run<'a> {
    profiles: [&'a Profile; 2],
    opts: BisectorOptions,
    center: [f64; 2],
    /// The diagonal of the box of the control points: how far branches run before they are
    /// clipped.
    diag: f64,
    /// The size the chord tolerance is relative to (the contract's).
    size: f64,
}

impl<'a> Run<'a> {
    fn new(profiles: &[&'a Profile], opts: &BisectorOptions) -> Self {
        let pts: Vec<[f64; 2]> = profiles
            .iter()
            .flat_map(|p| p.segments())
            .flat_map(|s| s.curve().control_points())
            .collect();
        let (center, diag) = bbox_of_points(&pts);
        // (The contract's size: max(width, height) of the profiles' points together.)
        let size = profiles
            .iter()
            .map(|p| p.bounding_box())
            .reduce(curve::box_union)
            .map(curve::box_size)
            .filter(|s| *s > 0.0 && s.is_finite())
            .unwrap_or(diag);
        Self {
            profiles: [profiles[0], profiles[profiles.len() - 1]],
            opts: *opts,
            center,
            diag,
            size,
        }
    }

    fn empty(&self) -> ProfileBisector {
        ProfileBisector {
            branches: Vec::new(),
            singular: Vec::new(),
            isolated: Vec::new(),
            complete: true,
        }
    }

    fn reach(&self) -> Reach {
        Reach {
            center: self.center,
            far: FAR * self.diag,
            chord: self.opts.chord_tol * self.size,
            tol: self.opts.tol,
        }
    }

    /// Options for the bisector of two segments: untrimmed (trimming is the profiles'), the
    /// chord tolerance relative to the profiles' size rather than the pair's.
    fn pair_options(&self, curves: &[&Rational]) -> BisectorOptions {
        let pair = crate::bisector::chord_size(curves);
        let chord =
            (self.opts.chord_tol * self.size / pair).clamp(self.opts.chord_tol, ChordTol::COARSEST);
        BisectorOptions {
            chord_tol: chord,
            trimmed: false,
            ..self.opts
        }
    }

    /// The profile parameter of segment `i`'s own parameter `v` on profile `which`.
    fn param(&self, which: usize, i: usize, v: f64) -> f64 {
        self.profiles[which].profile_param(i, v)
    }

    /// The bisector of one pair of sites (`one_profile` when both are sites of one profile:
    /// a corner is then an end of its two segments).
    fn pair(
        &self,
        x: &Site<'_>,
        y: &Site<'_>,
        one_profile: bool,
        out: &mut ProfileBisector,
    ) -> Result<()> {
        match (x, y) {
            (
                Site::Segment {
                    index: i,
                    curve: c1,
                },
                Site::Segment {
                    index: j,
                    curve: c2,
                },
            ) => self.segments(*i, c1, *j, c2, out),
            (
                Site::Corner {
                    index,
                    before,
                    u,
                    corner,
                },
                Site::Segment { index: j, curve },
            ) => {
                let shared = one_profile
                    .then(|| shared_end(*index, *before, *j))
                    .flatten();
                self.corner_segment(*index, *u, corner, *j, curve, shared, false, out)
            }
            (
                Site::Segment { index: j, curve },
                Site::Corner {
                    index,
                    before,
                    u,
                    corner,
                },
            ) => {
                let shared = one_profile
                    .then(|| shared_end(*index, *before, *j))
                    .flatten();
                self.corner_segment(*index, *u, corner, *j, curve, shared, true, out)
            }
            (
                Site::Corner {
                    index: i,
                    u: u1,
                    corner: k1,
                    ..
                },
                Site::Corner {
                    index: j,
                    u: u2,
                    corner: k2,
                    ..
                },
            ) => {
                if let Some(ends) = corner_corner(k1, k2, &self.reach()) {
                    out.branches.push(ProfileBranch {
                        tr: vec![[*u1, *u2]; 2],
                        xy: ends.to_vec(),
                        segment: [*i, *j],
                        corner: [true, true],
                    });
                }
                Ok(())
            }
        }
    }

    fn segments(
        &self,
        i: usize,
        c1: &Rational,
        j: usize,
        c2: &Rational,
        out: &mut ProfileBisector,
    ) -> Result<()> {
        let (s1, s2) = (
            &self.profiles[0].segments()[i],
            &self.profiles[1].segments()[j],
        );
        if s1.kind() == SegmentKind::Line && s2.kind() == SegmentKind::Line {
            if collinear(c1, c2) {
                return Ok(());
            }
            if let Some(found) = lines::line_bisector(c1, c2, &self.reach()) {
                self.add(found, [i, j], Determinate::Everywhere, out);
                return Ok(());
            }
        }
        if let (Some(k1), Some(k2)) = (s1.circle(), s2.circle()) {
            if k1 == k2 {
                out.isolated.push(ProfilePoint {
                    tr: [self.param(0, i, mid(c1)), self.param(1, j, mid(c2))],
                    xy: k1.0,
                    segment: [i, j],
                    corner: [false, false],
                });
                return Ok(());
            }
        }
        if let (Some(k1), Some(k2)) = (carrier(s1), carrier(s2)) {
            if let Some(found) = arc_bisector(c1, k1, c2, k2, &self.reach())? {
                self.add(found, [i, j], Determinate::ApartFeet, out);
                return Ok(());
            }
        }
        let found = bisector(c1, c2, &self.pair_options(&[c1, c2]))?;
        self.add(found, [i, j], Determinate::ApartFeet, out);
        Ok(())
    }

    fn segment_self(
        &self,
        i: usize,
        c: &Rational,
        p: &Profile,
        out: &mut ProfileBisector,
    ) -> Result<()> {
        let s = &p.segments()[i];
        match (s.kind(), s.circle()) {
            (SegmentKind::Line, _) => Ok(()),
            (_, Some((centre, _))) => {
                out.isolated.push(ProfilePoint {
                    // Any two points of the arc are feet of its centre: a quarter and three
                    // quarters along (distinct, also on a full circle).
                    tr: [i as f64 + 0.25, i as f64 + 0.75],
                    xy: centre,
                    segment: [i, i],
                    corner: [false, false],
                });
                Ok(())
            }
            _ => {
                let found = self_bisector(c, &self.pair_options(&[c]))?;
                self.add(found, [i, i], Determinate::ApartFeet, out);
                Ok(())
            }
        }
    }

    /// A bisector of two segments, in the profiles' parameters.
    fn add(
        &self,
        found: Bisector,
        seg: [usize; 2],
        determinate: Determinate,
        out: &mut ProfileBisector,
    ) {
        let map = |tr: [f64; 2]| [self.param(0, seg[0], tr[0]), self.param(1, seg[1], tr[1])];
        out.complete &= found.complete;
        let extent = POINT_EXTENT * self.diag;
        let feet = |tr: [f64; 2]| {
            [
                self.profiles[0].jet_to(tr[0], 0).p,
                self.profiles[1].jet_to(tr[1], 0).p,
            ]
        };
        // Feet that coincide leave the bisector point undetermined (0/0): where two
        // segments meet smoothly the zero set reaches the joint with an arbitrary point.
        // Such a vertex is dropped unless it is the feet's point itself (a corner's).
        let determined = |tr: [f64; 2], xy: [f64; 2]| {
            if determinate == Determinate::Everywhere {
                return true;
            }
            let [p, q] = feet(map(tr));
            (p - q).norm() > extent || (curve::V2::from_arr(xy) - p).norm() <= extent
        };
        let pieces = found.branches.into_iter().flat_map(|b| {
            let mut runs: Vec<Branch> = Vec::new();
            let mut cur = Branch {
                tr: Vec::new(),
                xy: Vec::new(),
            };
            for (tr, xy) in b.tr.into_iter().zip(b.xy) {
                if determined(tr, xy) {
                    cur.tr.push(tr);
                    cur.xy.push(xy);
                } else if !cur.xy.is_empty() {
                    runs.push(std::mem::replace(
                        &mut cur,
                        Branch {
                            tr: Vec::new(),
                            xy: Vec::new(),
                        },
                    ));
                }
            }
            runs.push(cur);
            runs
        });
        for b in pieces {
            let Some(&first) = b.xy.first() else {
                continue;
            };
            let spread = b.xy.iter().fold(0.0f64, |m, p| {
                m.max((p[0] - first[0]).hypot(p[1] - first[1]))
            });
            if spread <= extent {
                // Two straight segments whose feet meet at one end of each (parallel lines
                // whose spans touch), an arc and the line tangent to it at their joint (every
                // foot on the arc with the joint): one point.
                out.isolated.push(ProfilePoint {
                    tr: map(b.tr[0]),
                    xy: first,
                    segment: seg,
                    corner: [false, false],
                });
                continue;
            }
            out.branches.push(ProfileBranch {
                tr: b.tr.into_iter().map(map).collect(),
                xy: b.xy,
                segment: seg,
                corner: [false, false],
            });
        }
        let point = |p: crate::BisectorPoint| ProfilePoint {
            tr: map(p.tr),
            xy: p.xy,
            segment: seg,
            corner: [false, false],
        };
        out.singular.extend(found.singular.into_iter().map(point));
        out.isolated.extend(found.isolated.into_iter().map(point));
    }

    /// The bisector of a corner (site `index`, at `u`) and segment `j`; `swapped` when the
    /// segment is the first site.
    #[allow(clippy::too_many_arguments)]
    fn corner_segment(
        &self,
        index: usize,
        u: f64,
        corner: &Corner,
        j: usize,
        c: &Rational,
        shared: Option<SharedEnd>,
        swapped: bool,
        out: &mut ProfileBisector,
    ) -> Result<()> {
        let (which, corner_side) = if swapped { (0, 1) } else { (1, 0) };
        let side = self.opts.sides.map(|s| s[which]);
        let (runs, complete) = corner_curve(corner, c, shared, side, &self.reach())?;
        out.complete &= complete;
        for run in runs {
            let mut tr = Vec::with_capacity(run.len());
            let mut xy = Vec::with_capacity(run.len());
            for (r, x) in run {
                let v = self.param(which, j, r);
                tr.push(if swapped { [v, u] } else { [u, v] });
                xy.push(x);
            }
            let mut segment = [0; 2];
            let mut is_corner = [false; 2];
            segment[corner_side] = index;
            segment[which] = j;
            is_corner[corner_side] = true;
            out.branches.push(ProfileBranch {
                tr,
                xy,
                segment,
                corner: is_corner,
            });
        }
        Ok(())
    }

    /// With `trimmed`, keeps only the vertices whose foot points are nearest points of the
    /// profiles, splitting branches where others are dropped.
    fn trim(&self, out: &mut ProfileBisector, profiles: [&Profile; 2]) {
        if !self.opts.trimmed {
            return;
        }
        let slack = TRIM_SLACK * self.diag;
        let foot = |k: usize, u: f64| profiles[k].jet(u).p.arr();
        let keeps = |tr: [f64; 2], x: [f64; 2]| {
            let f = foot(0, tr[0]);
            let rho = (x[0] - f[0]).hypot(x[1] - f[1]);
            profiles
                .iter()
                .all(|p| p.nearest(x, rho - slack).distance >= rho - slack)
        };
        let mut branches = Vec::new();
        for b in out.branches.drain(..) {
            let mut cur: Option<ProfileBranch> = None;
            for (tr, xy) in b.tr.iter().zip(&b.xy) {
                if keeps(*tr, *xy) {
                    let c = cur.get_or_insert_with(|| ProfileBranch {
                        tr: Vec::new(),
                        xy: Vec::new(),
                        ..b.clone()
                    });
                    c.tr.push(*tr);
                    c.xy.push(*xy);
                } else if let Some(c) = cur.take() {
                    if c.xy.len() >= 2 {
                        branches.push(c);
                    }
                }
            }
            if let Some(c) = cur.filter(|c| c.xy.len() >= 2) {
                branches.push(c);
            }
        }
        out.branches = branches;
        for list in [&mut out.singular, &mut out.isolated] {
            list.retain(|p| keeps(p.tr, p.xy));
        }
    }
}

/// Where a bisector's points are determined by their feet.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Determinate {
    /// Everywhere: two lines' bisector in closed form, whose every point is solved for (no
    /// two lines meet smoothly). At a nearly flat corner the feet of its points near the
    /// corner are closer together than the joint's slack while the points stand the feet's
    /// gap over the turn away (five thousand times, at a turn of 1.6e-4): taken for
    /// undetermined, the point at the corner was dropped and the axis lost the corner's
    /// edge.
    Everywhere,
    /// Only where the feet are apart (or the point is their common point): a traced zero
    /// set reaches a smooth joint with an arbitrary point.
    ApartFeet,
}

/// Which end of segment `j` is the corner between segments `before` and `index`.
fn shared_end(index: usize, before: usize, j: usize) -> Option<SharedEnd> {
    if j == index {
        Some(SharedEnd::Start)
    } else if j == before {
        Some(SharedEnd::End)
    } else {
        None
    }
}

/// What a line or an arc lies on (`None` for other segments).
fn carrier(s: &Segment) -> Option<Carrier> {
    match (s.kind(), s.circle()) {
        (SegmentKind::Line, _) => Some(Carrier::Line),
        (_, Some((center, radius))) => Some(Carrier::Circle { center, radius }),
        _ => None,
    }
}

/// The middle of a curve's domain.
fn mid(c: &Rational) -> f64 {
    let (a, b) = c.domain();
    0.5 * (a + b)
}

/// Whether two straight curves lie on one line.
fn collinear(c1: &Rational, c2: &Rational) -> bool {
    let ends = |c: &Rational| {
        let (a, b) = c.domain();
        let (p, q) = (c.point(a), c.point(b));
        ([p[0], p[1]], [q[0], q[1]])
    };
    let ((p1, q1), (p2, q2)) = (ends(c1), ends(c2));
    let d1 = [q1[0] - p1[0], q1[1] - p1[1]];
    let len = d1[0].hypot(d1[1]);
    let off = |p: [f64; 2]| ((p[0] - p1[0]) * d1[1] - (p[1] - p1[1]) * d1[0]).abs() / len;
    let size = len.max((p2[0] - p1[0]).hypot(p2[1] - p1[1]));
    off(p2) <= COLLINEAR * size && off(q2) <= COLLINEAR * size
}
