//! Helpers the medial axis tests share: regions (circles, round holes, closed splines, the
//! pocket) made and checked, and what an axis has (nodes of a kind, an end's foot).

use crate::oracle::check;
use curve::{ParamCurve, Profile, Region, Segment};
use medial::{MedialAxis, NodeKind};
use std::f64::consts::TAU;

pub(crate) fn circle(c: [f64; 2], r: f64) -> Profile {
    Profile::new(vec![Segment::arc(c, r, 0.0, TAU).unwrap()], None).unwrap()
}

pub(crate) fn kinds(a: &MedialAxis, k: NodeKind) -> usize {
    a.nodes.iter().filter(|n| n.kind == k).count()
}

/// The foot (parameter, boundary) of the edge's end at node `id`.
pub(crate) fn end_foot(a: &MedialAxis, id: usize) -> Option<(f64, usize)> {
    a.edges.iter().find_map(|e| {
        let k = if e.from == id {
            0
        } else if e.to == id {
            e.feet.len() - 1
        } else {
            return None;
        };
        Some((e.feet[k][0], e.boundary[k][0]))
    })
}

/// Round holes of the given centres (in the unit disk, scaled by 0.5) and radii, kept where
/// the region accepts them with a clear margin.
pub(crate) fn with_holes(outer: Profile, holes: &[([f64; 2], f64)]) -> Option<Region> {
    let mut kept: Vec<Profile> = Vec::new();
    for &(c, r) in holes {
        let hole = circle([0.5 * c[0], 0.5 * c[1]], r);
        let mut trial = kept.clone();
        trial.push(hole.clone());
        if Region::new(outer.clone(), trial).is_ok() {
            kept.push(hole);
        }
    }
    Region::new(outer, kept).ok()
}

/// The region inside `outer` with the round `holes` (as [`with_holes`] places them), every
/// one of them kept, once [`check`] has found its axis right.
pub(crate) fn checked_region(outer: Profile, holes: &[([f64; 2], f64)]) -> Region {
    let region = with_holes(outer, holes).unwrap();
    assert_eq!(region.holes().len(), holes.len(), "a hole was refused");
    check(&region).unwrap();
    region
}

/// A closed cubic B-spline (NURBS with `weights`) through control points round a star at
/// `radii`, clamped from its periodic form as the readers do.
pub(crate) fn closed_spline(radii: &[f64], weights: Option<&[f64]>) -> Option<Profile> {
    let n = radii.len();
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            [radii[i] * a.cos(), radii[i] * a.sin()]
        })
        .collect();
    closed_cubic(&pts, weights)
}

/// The closed profile of the periodic cubic B-spline of control points `pts`: one turn of
/// it, clamped.
pub(crate) fn closed_cubic(pts: &[[f64; 2]], weights: Option<&[f64]>) -> Option<Profile> {
    let periodic = curve::SplineCurve::periodic(3, pts, weights).ok()?;
    let (a, b) = periodic.domain();
    let clamped = curve::SplineCurve::new(periodic.curve().restrict(a, b).ok()?).ok()?;
    let seg = Segment::spline(curve::SegmentKind::BSpline, clamped).ok()?;
    Profile::new(vec![seg], Some(true)).ok()
}

/// The 10 × 6 pocket outline with corners of radius 1.
pub(crate) fn pocket_outline() -> Profile {
    let h = std::f64::consts::FRAC_PI_2;
    let outline = vec![
        Segment::line([1.0, 0.0], [9.0, 0.0]).unwrap(),
        Segment::arc([9.0, 1.0], 1.0, -h, 0.0).unwrap(),
        Segment::line([10.0, 1.0], [10.0, 5.0]).unwrap(),
        Segment::arc([9.0, 5.0], 1.0, 0.0, h).unwrap(),
        Segment::line([9.0, 6.0], [1.0, 6.0]).unwrap(),
        Segment::arc([1.0, 5.0], 1.0, h, 2.0 * h).unwrap(),
        Segment::line([0.0, 5.0], [0.0, 1.0]).unwrap(),
        Segment::arc([1.0, 1.0], 1.0, 2.0 * h, 3.0 * h).unwrap(),
    ];
    Profile::new(outline, None).unwrap()
}
