//! The bisector of one pair of a profile's sites (two segments, a corner and a segment, two
//! corners, or a segment with itself), in the profiles' parameters.

use super::arcs::{arc_bisector, Carrier};
use super::lines;
use super::point_site::{corner_corner, corner_curve, Corner, SharedEnd};
use super::run::Run;
use super::tangent_centre::tangent_circle_centres;
use super::Site;
use crate::bisector::{curve_bisector, curve_self_bisector, Bisector, BisectorPoint, Branch};
use crate::error::Result;
use bspline::Rational;
use curve::{ParamCurve, Profile, Segment, SegmentKind};

/// Two straight segments are on one line when the cross products of their directions with
/// each other and with the line between them are this small relative to their lengths.
const COLLINEAR: f64 = 1e-12;

/// A branch of two segments' bisector whose vertices all lie within this share of the
/// profiles' size of one another is one point (reported as isolated): the contract's
/// tolerance for points of a drawing that meet.
const POINT_EXTENT: f64 = 1e-9;

impl Run<'_> {
    /// The bisector of one pair of sites (`one_profile` when both are sites of one profile:
    /// a corner is then an end of its two segments).
    pub(super) fn pair(
        &self,
        x: &Site<'_>,
        y: &Site<'_>,
        one_profile: bool,
        out: &mut Bisector,
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
                    out.branches.push(Branch {
                        tr: vec![[*u1, *u2]; 2],
                        xy: ends.to_vec(),
                        segment: Some([*i, *j]),
                        corner: Some([true, true]),
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
        out: &mut Bisector,
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
                out.isolated.push(BisectorPoint {
                    tr: [self.param(0, i, mid(c1)), self.param(1, j, mid(c2))],
                    xy: k1.0,
                    segment: Some([i, j]),
                    corner: Some([false, false]),
                });
                return Ok(());
            }
        }
        if let (Some(k1), Some(k2)) = (carrier(s1), carrier(s2)) {
            if let Some(mut found) = arc_bisector(c1, k1, c2, k2, &self.reach())? {
                found.isolated.extend(tangent_circle_centres(s1, s2));
                self.add(found, [i, j], Determinate::ApartFeet, out);
                return Ok(());
            }
        }
        let found = curve_bisector(c1, c2, &self.pair_options(&[c1, c2]))?;
        self.add(found, [i, j], Determinate::ApartFeet, out);
        Ok(())
    }

    pub(super) fn segment_self(
        &self,
        i: usize,
        c: &Rational,
        p: &Profile,
        out: &mut Bisector,
    ) -> Result<()> {
        let s = &p.segments()[i];
        match (s.kind(), s.circle()) {
            (SegmentKind::Line, _) => Ok(()),
            (_, Some((centre, _))) => {
                out.isolated.push(BisectorPoint {
                    // Any two points of the arc are feet of its centre: a quarter and three
                    // quarters along (distinct, also on a full circle).
                    tr: [i as f64 + 0.25, i as f64 + 0.75],
                    xy: centre,
                    segment: Some([i, i]),
                    corner: Some([false, false]),
                });
                Ok(())
            }
            _ => {
                let found = curve_self_bisector(c, &self.pair_options(&[c]))?;
                self.add(found, [i, i], Determinate::ApartFeet, out);
                Ok(())
            }
        }
    }

    /// A bisector of two segments, in the profiles' parameters.
    fn add(&self, found: Bisector, seg: [usize; 2], determinate: Determinate, out: &mut Bisector) {
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
            let mut cur = Branch::of_curves(Vec::new(), Vec::new());
            for (tr, xy) in b.tr.into_iter().zip(b.xy) {
                if determined(tr, xy) {
                    cur.tr.push(tr);
                    cur.xy.push(xy);
                } else if !cur.xy.is_empty() {
                    runs.push(std::mem::replace(
                        &mut cur,
                        Branch::of_curves(Vec::new(), Vec::new()),
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
                out.isolated.push(BisectorPoint {
                    tr: map(b.tr[0]),
                    xy: first,
                    segment: Some(seg),
                    corner: Some([false, false]),
                });
                continue;
            }
            out.branches.push(Branch {
                tr: b.tr.into_iter().map(map).collect(),
                xy: b.xy,
                segment: Some(seg),
                corner: Some([false, false]),
            });
        }
        let point = |p: BisectorPoint| BisectorPoint {
            tr: map(p.tr),
            segment: Some(seg),
            corner: Some([false, false]),
            ..p
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
        out: &mut Bisector,
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
            out.branches.push(Branch {
                tr,
                xy,
                segment: Some(segment),
                corner: Some(is_corner),
            });
        }
        Ok(())
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
