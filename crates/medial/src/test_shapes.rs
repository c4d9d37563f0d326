//! Regions the unit tests share: stars of cubic Béziers or of lines, with corners and round
//! holes, and closed B-splines round a star.

use crate::candidates::PairSource;
use crate::{axis_of, MedialAxis, MedialOptions};
use curve::{Profile, Region, Segment, SegmentKind, SplineCurve, V2};

/// The points of a star: at `radii[i]` from the origin, at equal angles.
fn star_points(radii: &[f64]) -> Vec<V2> {
    let n = radii.len();
    (0..n)
        .map(|i| V2::polar(std::f64::consts::TAU * i as f64 / n as f64) * radii[i])
        .collect()
}

/// A closed chain of cubic Béziers round a star (corners at the joints), with round
/// holes near its middle where they fit.
pub(crate) fn star(radii: &[f64], wobble: &[f64], holes: &[([f64; 2], f64)]) -> Option<Region> {
    let n = radii.len();
    let joints = star_points(radii);
    let segs = (0..n)
        .map(|i| {
            let (a, b) = (joints[i], joints[(i + 1) % n]);
            let w = wobble[i];
            let pts = [
                a.arr(),
                (a + (b - a) * 0.3 + (b - a).perp() * w).arr(),
                (a + (b - a) * 0.7 - (b - a).perp() * w).arr(),
                b.arr(),
            ];
            let c = SplineCurve::clamped(3, &pts, None, None).ok()?;
            Segment::spline(SegmentKind::Bezier, c).ok()
        })
        .collect::<Option<Vec<_>>>()?;
    with_round_holes(Profile::new(segs, None).ok()?, holes)
}

/// A closed cubic B-spline through control points round a star, clamped (one segment
/// of many spans, cut at its knots for the bisectors).
pub(crate) fn spline_star(radii: &[f64], weights: Option<&[f64]>) -> Option<Region> {
    let n = radii.len();
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|i| (V2::polar(std::f64::consts::TAU * i as f64 / n as f64) * radii[i]).arr())
        .collect();
    let periodic = SplineCurve::periodic(3, &pts, weights).ok()?;
    let (a, b) = curve::ParamCurve::domain(&periodic);
    let clamped = SplineCurve::new(periodic.curve().restrict(a, b).ok()?).ok()?;
    let seg = Segment::spline(SegmentKind::BSpline, clamped).ok()?;
    Region::new(Profile::new(vec![seg], Some(true)).ok()?, vec![]).ok()
}

/// A polygon of lines round a star at `radii`, each side bent at its middle by `wobble` of
/// its length (a corner there, convex or reflex), with round holes near its middle where
/// they fit.
pub(crate) fn polygon_star(
    radii: &[f64],
    wobble: &[f64],
    holes: &[([f64; 2], f64)],
) -> Option<Region> {
    let n = radii.len();
    let joints = star_points(radii);
    let mut points = Vec::with_capacity(2 * n);
    for i in 0..n {
        let (a, b) = (joints[i], joints[(i + 1) % n]);
        points.push(a);
        points.push((a + b) * 0.5 + (b - a).perp() * wobble[i]);
    }
    let m = points.len();
    let sides = (0..m)
        .map(|i| Segment::line(points[i].arr(), points[(i + 1) % m].arr()).ok())
        .collect::<Option<Vec<_>>>()?;
    with_round_holes(Profile::new(sides, None).ok()?, holes)
}

/// [`polygon_star`] with holes that are regular polygons: centre, radius, number of sides and
/// turn (a share of a side's angle) each.
pub(crate) fn polygon_star_with_polygon_holes(
    radii: &[f64],
    wobble: &[f64],
    holes: &[([f64; 2], f64, usize, f64)],
) -> Option<Region> {
    let outer = polygon_star(radii, wobble, &[])?.outer().clone();
    let mut kept = Vec::new();
    for &(c, r, n, turn) in holes {
        let corner = |i: usize| {
            let angle = std::f64::consts::TAU * (turn - (i % n) as f64) / n as f64;
            (V2::new(c[0], c[1]) + V2::polar(angle) * r).arr()
        };
        // (Clockwise: a hole runs against the outer boundary.)
        let sides = (0..n)
            .map(|i| Segment::line(corner(i), corner(i + 1)).ok())
            .collect::<Option<Vec<_>>>()?;
        let mut trial = kept.clone();
        trial.push(Profile::new(sides, None).ok()?);
        if Region::new(outer.clone(), trial.clone()).is_ok() {
            kept = trial;
        }
    }
    Region::new(outer, kept).ok()
}

/// `outer` with round holes of the given centres and radii, those the region accepts.
fn with_round_holes(outer: Profile, holes: &[([f64; 2], f64)]) -> Option<Region> {
    let mut kept = Vec::new();
    for &(c, r) in holes {
        let hole = Profile::new(
            vec![Segment::arc(c, r, 0.0, std::f64::consts::TAU).ok()?],
            None,
        )
        .ok()?;
        let mut trial = kept.clone();
        trial.push(hole);
        if Region::new(outer.clone(), trial.clone()).is_ok() {
            kept = trial;
        }
    }
    Region::new(outer, kept).ok()
}

/// A differential test of a path to the axis against the bounds' pairs: on 1,000 regions
/// `make` draws (from `rnd`, by case number), the axis `source` builds, wherever it stands,
/// is the bounds' axis as `same` judges (`Err` with how they differ); and it stands on at
/// least 95 % of those the bounds certify (a path that stood nowhere would pass the first
/// half alone).
pub(crate) fn stands_as_the_bounds(
    rnd: &mut impl FnMut() -> f64,
    source: PairSource,
    mut make: impl FnMut(&mut dyn FnMut() -> f64, usize) -> Option<Region>,
    same: impl Fn(&MedialAxis, &MedialAxis, &Region) -> Result<(), String>,
) {
    let opts = MedialOptions::default();
    let (mut tried, mut stood, mut certified) = (0, 0, 0);
    for case in 0..1000 {
        let Some(region) = make(rnd, case) else {
            continue;
        };
        tried += 1;
        let (found, stands) = axis_of(&region, &opts, source).unwrap();
        let bounds = axis_of(&region, &opts, PairSource::Bounds).unwrap().0;
        certified += usize::from(bounds.certified);
        if stands {
            stood += 1;
            if let Err(why) = same(&found, &bounds, &region) {
                panic!("case {case}: the {source:?} axis stands and differs: {why}");
            }
        }
    }
    assert!(tried > 900, "{tried}");
    assert!(
        stood * 100 >= certified * 95,
        "the {source:?} axis stood on {stood} of {certified} certified"
    );
}

/// A polygon round a star at `radii` (counter-clockwise) whose corners are rounded by
/// tangent arcs of radius `fillet[i]` where it is positive and fits (convex and reflex
/// corners alike), and whose sides between bulge by circular arcs of sagitta `bulge[i]` times
/// their length where it is not nil (inward where positive; corners at their ends); with
/// round holes near its middle where they fit.
pub(crate) fn rounded_star(
    radii: &[f64],
    fillet: &[f64],
    bulge: &[f64],
    holes: &[([f64; 2], f64)],
) -> Option<Region> {
    let n = radii.len();
    let corners = star_points(radii);
    // Per corner, where its sides leave it and the arc between (if any).
    let mut ends: Vec<(V2, V2, Option<Segment>)> = Vec::with_capacity(n);
    for i in 0..n {
        let p = corners[i];
        let (q, r) = (corners[(i + n - 1) % n], corners[(i + 1) % n]);
        let (u, v) = ((q - p).unit(), (r - p).unit());
        let half = 0.5 * u.cross(v).abs().atan2(u.dot(v));
        let d = fillet[i] / half.tan();
        if fillet[i] <= 0.0 || d > 0.4 * (q - p).norm().min((r - p).norm()) {
            ends.push((p, p, None));
            continue;
        }
        let (t1, t2) = (p + u * d, p + v * d);
        let c = p + (u + v).unit() * (fillet[i] / half.sin());
        let a1 = (t1 - c).angle();
        let sweep = curve::wrap_pi((t2 - c).angle() - a1);
        ends.push((
            t1,
            t2,
            Some(Segment::arc(c.arr(), fillet[i], a1, a1 + sweep).ok()?),
        ));
    }
    let mut segments = Vec::with_capacity(3 * n);
    for i in 0..n {
        let (_, a, _) = &ends[i];
        let b = ends[(i + 1) % n].0;
        let length = (b - *a).norm();
        let h = bulge[i] * length;
        if h == 0.0 {
            segments.push(Segment::line(a.arr(), b.arr()).ok()?);
        } else {
            let radius = (0.25 * length * length + h * h) / (2.0 * h.abs());
            let normal = (b - *a).perp() * (1.0 / length);
            let middle = (*a + b) * 0.5;
            let c = middle + normal * (h - h.signum() * radius);
            let a1 = (*a - c).angle();
            let sweep = 2.0 * curve::wrap_pi((middle + normal * h - c).angle() - a1);
            segments.push(Segment::arc(c.arr(), radius, a1, a1 + sweep).ok()?);
        }
        if let Some(arc) = &ends[(i + 1) % n].2 {
            segments.push(arc.clone());
        }
    }
    // (The first corner's arc closes the chain: it was pushed last.)
    with_round_holes(Profile::new(segments, None).ok()?, holes)
}
