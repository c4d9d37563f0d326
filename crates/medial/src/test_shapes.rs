//! Regions the unit tests share: stars of cubic Béziers or of lines, with corners and round
//! holes, and closed B-splines round a star.

use crate::candidates::PairSource;
use crate::{axis_of, MedialAxis, MedialOptions, Verdict};
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

/// How a path's axis is judged against the bounds' axis of the same region: `Err` with how
/// they differ.
pub(crate) type Judge = fn(&MedialAxis, &MedialAxis, &Region) -> Result<(), String>;

/// A differential test of paths to the axis against the bounds' pairs: on 1,000 regions
/// `make` draws (from `rnd`, by case number), the axis each of `paths` builds, wherever it
/// stands, is the bounds' axis as its judge decides; and each stands on at least 95 % of
/// those the bounds certify (a path that stood nowhere would pass the first half alone).
/// The bounds' axis, the costly one, is built once per region for all the paths.
pub(crate) fn stands_as_the_bounds(
    rnd: &mut impl FnMut() -> f64,
    paths: &[(PairSource, Judge)],
    mut make: impl FnMut(&mut dyn FnMut() -> f64, usize) -> Option<Region>,
) {
    let opts = MedialOptions::default();
    let (mut tried, mut certified) = (0, 0);
    let mut stood = vec![0; paths.len()];
    for case in 0..1000 {
        let Some(region) = make(rnd, case) else {
            continue;
        };
        tried += 1;
        let bounds = axis_of(&region, &opts, PairSource::Bounds).unwrap().0;
        certified += usize::from(bounds.certified());
        for (&(source, same), stood) in paths.iter().zip(&mut stood) {
            let (found, stands) = axis_of(&region, &opts, source).unwrap();
            if stands {
                *stood += 1;
                if let Err(why) = same(&found, &bounds, &region) {
                    panic!("case {case}: the {source:?} axis stands and differs: {why}");
                }
            }
        }
    }
    assert!(tried > 900, "{tried}");
    for (&(source, _), stood) in paths.iter().zip(stood) {
        assert!(
            stood * 100 >= certified * 95,
            "the {source:?} axis stood on {stood} of {certified} certified"
        );
    }
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
/// The distance from `x` to the polyline `p`.
pub(crate) fn to_polyline(x: [f64; 2], p: &[[f64; 2]]) -> f64 {
    if p.len() == 1 {
        return (V2::from_arr(x) - V2::from_arr(p[0])).norm();
    }
    p.windows(2)
        .map(|w| curve::distance_to_segment(x, w[0], w[1]))
        .fold(f64::INFINITY, f64::min)
}

/// Whether two axes are the same graph: nodes of one kind within `near` of each other
/// (one to one), edges between matching nodes, each one's vertices within `near` of
/// the other's polyline, with the same boundaries at their ends.
pub(crate) fn same_graph(a: &MedialAxis, b: &MedialAxis, near: f64) -> Result<(), String> {
    if a.nodes.len() != b.nodes.len() || a.edges.len() != b.edges.len() {
        return Err(format!(
            "{} nodes, {} edges against {} and {}",
            a.nodes.len(),
            a.edges.len(),
            b.nodes.len(),
            b.edges.len()
        ));
    }
    let apart = |p: [f64; 2], q: [f64; 2]| (V2::from_arr(p) - V2::from_arr(q)).norm();
    let mut match_of = vec![usize::MAX; a.nodes.len()];
    let mut taken = vec![false; b.nodes.len()];
    for n in &a.nodes {
        let m = b
            .nodes
            .iter()
            .filter(|m| !taken[m.id] && m.kind == n.kind)
            .min_by(|p, q| apart(p.xy, n.xy).total_cmp(&apart(q.xy, n.xy)))
            .ok_or(format!("no node for {n:?}"))?;
        if apart(m.xy, n.xy) > near || (m.radius - n.radius).abs() > near {
            return Err(format!("node {n:?} against {m:?}"));
        }
        taken[m.id] = true;
        match_of[n.id] = m.id;
    }
    let mut used = vec![false; b.edges.len()];
    for e in &a.edges {
        let ends = [match_of[e.from], match_of[e.to]];
        let mut ends_sorted = ends;
        ends_sorted.sort_unstable();
        let boundaries = |x: &[[usize; 2]]| {
            let mut v = [x[0], x[x.len() - 1]].concat();
            v.sort_unstable();
            v
        };
        let found = b.edges.iter().enumerate().find(|(k, f)| {
            let mut f_ends = [f.from, f.to];
            f_ends.sort_unstable();
            !used[*k]
                && f_ends == ends_sorted
                && boundaries(&f.boundary) == boundaries(&e.boundary)
                && e.xy.iter().all(|&x| to_polyline(x, &f.xy) <= near)
                && f.xy.iter().all(|&x| to_polyline(x, &e.xy) <= near)
        });
        match found {
            Some((k, _)) => used[k] = true,
            None => return Err(format!("no edge for {} -> {} ({:?})", e.from, e.to, e.xy)),
        }
    }
    Ok(())
}

/// A random polygon round a star of 5 to 15 points (sides bent at their middles: convex
/// and reflex corners), with up to two polygonal holes.
pub(crate) fn random_polygon(rnd: &mut dyn FnMut() -> f64) -> Option<Region> {
    let n = 5 + (10.0 * rnd()) as usize;
    let radii: Vec<f64> = (0..n).map(|_| 1.0 + 0.6 * rnd()).collect();
    let wobble: Vec<f64> = (0..n).map(|_| 0.4 * rnd() - 0.2).collect();
    let holes: Vec<([f64; 2], f64, usize, f64)> = (0..(3.0 * rnd()) as usize)
        .map(|_| {
            let centre = [0.8 * rnd() - 0.4, 0.8 * rnd() - 0.4];
            (
                centre,
                0.05 + 0.15 * rnd(),
                3 + (6.0 * rnd()) as usize,
                rnd(),
            )
        })
        .collect();
    polygon_star_with_polygon_holes(&radii, &wobble, &holes)
}

/// A random star of 5 to 15 corners, about half of them rounded by tangent arcs and
/// about a third of its sides bulging in or out as arcs, with up to two round holes.
pub(crate) fn random_rounded(rnd: &mut dyn FnMut() -> f64) -> Option<Region> {
    let n = 5 + (10.0 * rnd()) as usize;
    let radii: Vec<f64> = (0..n).map(|_| 1.0 + 0.6 * rnd()).collect();
    let fillet: Vec<f64> = (0..n)
        .map(|_| if rnd() < 0.5 { 0.02 + 0.2 * rnd() } else { 0.0 })
        .collect();
    let bulge: Vec<f64> = (0..n)
        .map(|_| match rnd() {
            x if x < 0.15 => 0.03 + 0.15 * rnd(),
            x if x < 0.3 => -0.03 - 0.15 * rnd(),
            _ => 0.0,
        })
        .collect();
    let holes: Vec<([f64; 2], f64)> = (0..(3.0 * rnd()) as usize)
        .map(|_| ([0.8 * rnd() - 0.4, 0.8 * rnd() - 0.4], 0.05 + 0.15 * rnd()))
        .collect();
    rounded_star(&radii, &fillet, &bulge, &holes)
}

/// `axis` with every edge whose two nodes lie within `within` of each other contracted (its
/// nodes made one, the first's), as the bounds' path merges the ends of its stretches: two
/// junctions closer than that are one node there.
pub(crate) fn merged(axis: &MedialAxis, within: f64) -> MedialAxis {
    let mut root: Vec<usize> = (0..axis.nodes.len()).collect();
    fn find(root: &mut [usize], mut k: usize) -> usize {
        while root[k] != k {
            k = root[k];
        }
        k
    }
    let apart = |a: usize, b: usize| {
        let (p, q) = (axis.nodes[a].xy, axis.nodes[b].xy);
        (p[0] - q[0]).hypot(p[1] - q[1])
    };
    let short = |e: &crate::Edge| e.from != e.to && apart(e.from, e.to) <= within;
    for e in axis.edges.iter().filter(|e| short(e)) {
        let (a, b) = (find(&mut root, e.from), find(&mut root, e.to));
        root[a.max(b)] = a.min(b);
    }
    let kept: Vec<usize> = (0..axis.nodes.len())
        .filter(|&k| find(&mut root, k) == k)
        .collect();
    let mut id = vec![usize::MAX; axis.nodes.len()];
    for (new, &k) in kept.iter().enumerate() {
        id[k] = new;
    }
    let nodes = kept
        .iter()
        .enumerate()
        .map(|(new, &k)| crate::Node {
            id: new,
            ..axis.nodes[k]
        })
        .collect();
    let edges = axis
        .edges
        .iter()
        .filter(|e| !short(e))
        .map(|e| crate::Edge {
            from: id[find(&mut root, e.from)],
            to: id[find(&mut root, e.to)],
            ..e.clone()
        })
        .collect();
    MedialAxis {
        nodes,
        edges,
        ..axis.clone()
    }
}
