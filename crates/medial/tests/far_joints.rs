//! The medial axis of regions far from the origin, whose smooth joints turn by the rounding of
//! their tangents (a line and an arc meeting tangentially at 1e8 turn by some 1e-8; a fillet
//! of radius 0.01 there, by some 1e-6): the coverage by the feet must hold each such joint's
//! fan, and the axis is certified only where the independent oracle agrees (dense boundary
//! distances, the sampled Voronoi diagram: every vertex inside at its radius, to the rounding
//! of the points; no medial point off the axis).

#![allow(clippy::unwrap_used, missing_docs)]

#[path = "common/sampled_voronoi.rs"]
mod sampled_voronoi;
#[path = "common/traced.rs"]
mod traced;

use curve::{Profile, Region, Segment};
use numeric::certificate::Verdict;
use sampled_voronoi::sampled_medial_points;
use std::f64::consts::{FRAC_PI_2, PI};
use testkit::boundary_oracle::{winding, Oracle};
use traced::{axis, off_axis, CHORD};

/// Where the shapes are moved.
const FAR: [f64; 2] = [1e8, 1e8];

fn line(p: [f64; 2], q: [f64; 2]) -> Segment {
    Segment::line(p, q).unwrap()
}

fn at(o: [f64; 2], x: f64, y: f64) -> [f64; 2] {
    [o[0] + x, o[1] + y]
}

/// A stadium about `o`: two sides `2 half` long joined by half circles of radius `r`.
fn stadium(o: [f64; 2], half: f64, r: f64) -> Profile {
    Profile::new(
        vec![
            line(at(o, -half, -r), at(o, half, -r)),
            Segment::arc(at(o, half, 0.0), r, -FRAC_PI_2, FRAC_PI_2).unwrap(),
            line(at(o, half, r), at(o, -half, r)),
            Segment::arc(at(o, -half, 0.0), r, FRAC_PI_2, 3.0 * FRAC_PI_2).unwrap(),
        ],
        None,
    )
    .unwrap()
}

/// A `w × h` rectangle about `o`, turned by `a`, with its corners rounded by fillets of
/// radius `f`.
fn filleted_rectangle(o: [f64; 2], w: f64, h: f64, f: f64, a: f64) -> Profile {
    let (x, y) = (0.5 * w, 0.5 * h);
    let (c, s) = (a.cos(), a.sin());
    let m = |x: f64, y: f64| [o[0] + c * x - s * y, o[1] + s * x + c * y];
    let arc = |cx: f64, cy: f64, from: f64| {
        Segment::arc(m(cx, cy), f, from + a, from + a + FRAC_PI_2).unwrap()
    };
    Profile::new(
        vec![
            line(m(-x + f, -y), m(x - f, -y)),
            arc(x - f, -y + f, -FRAC_PI_2),
            line(m(x, -y + f), m(x, y - f)),
            arc(x - f, y - f, 0.0),
            line(m(x - f, y), m(-x + f, y)),
            arc(-x + f, y - f, FRAC_PI_2),
            line(m(-x, y - f), m(-x, -y + f)),
            arc(-x + f, -y + f, PI),
        ],
        None,
    )
    .unwrap()
}

/// A D-like convex shape (`antipodal`'s `far_joints.rs`) turned by `a` about `o`: a bottom
/// line into `o`, a quarter arc about (0, 1) leaving it tangentially, a side, a top half
/// circle about (−off, 2), a side back.
fn d_shape(o: [f64; 2], a: f64, off: f64) -> Profile {
    let (c, s) = (a.cos(), a.sin());
    let m = |x: f64, y: f64| [o[0] + c * x - s * y, o[1] + s * x + c * y];
    Profile::new(
        vec![
            line(m(-1.0, 0.0), m(0.0, 0.0)),
            Segment::arc(m(0.0, 1.0), 1.0, -FRAC_PI_2 + a, a).unwrap(),
            line(m(1.0, 1.0), m(1.0 - off, 2.0)),
            Segment::arc(m(-off, 2.0), 1.0, a, PI + a).unwrap(),
            line(m(-1.0 - off, 2.0), m(-1.0, 0.0)),
        ],
        Some(true),
    )
    .unwrap()
}

/// An oval of four arcs joined tangentially (an ellipse as drafting draws it): two of radius
/// `small` about (±(big − small) cos t, 0) spanning `2 t`, two of radius `big` about
/// (0, ∓(big − small) sin t); neighbours' centres on a line through their joint.
fn oval(o: [f64; 2], big: f64, small: f64, t: f64) -> Profile {
    let k = big - small;
    let (sx, by) = (k * t.cos(), k * t.sin());
    Profile::new(
        vec![
            Segment::arc(at(o, sx, 0.0), small, -t, t).unwrap(),
            Segment::arc(at(o, 0.0, -by), big, t, PI - t).unwrap(),
            Segment::arc(at(o, -sx, 0.0), small, PI - t, PI + t).unwrap(),
            Segment::arc(at(o, 0.0, by), big, PI + t, 2.0 * PI - t).unwrap(),
        ],
        None,
    )
    .unwrap()
}

/// The shapes about `o`, with a name, and the distances their offsets are taken at (below
/// the inscribed radius).
fn shapes_at(o: [f64; 2]) -> Vec<(String, Profile, Vec<f64>)> {
    let mut out = Vec::new();
    for r in [1e-2, 0.1, 1.0, 10.0] {
        out.push((
            format!("stadium r = {r}"),
            stadium(o, 3.0 * r, r),
            vec![0.05 * r, 0.5 * r, 0.9 * r],
        ));
    }
    for f in [1e-2f64, 0.1, 1.0, 10.0] {
        let (w, h) = (6.0 * f.max(1.0), 4.0 * f.max(1.0));
        out.push((
            format!("filleted rectangle f = {f}"),
            filleted_rectangle(o, w, h, f, 0.0),
            vec![0.01 * h, 0.2 * h, 0.45 * h],
        ));
    }
    // (Large, with tiny fillets: their joints turn by up to 1e-4, and `d` times that is more
    // than the rounding of a loop's points.)
    for f in [1e-4, 1e-3] {
        out.push((
            format!("large turned filleted rectangle f = {f}"),
            filleted_rectangle(o, 300.0, 200.0, f, 0.4),
            vec![1.0, 30.0, 90.0],
        ));
    }
    for a in [0.3, 1.1] {
        for off in [2e-4, 0.3] {
            out.push((
                format!("D a = {a} off = {off}"),
                d_shape(o, a, off),
                vec![0.01, 0.3, 0.8],
            ));
        }
    }
    for (big, small) in [(5.0, 1.0), (0.5, 0.02)] {
        out.push((
            format!("oval {big}/{small}"),
            oval(o, big, small, 0.6),
            vec![0.1 * small, 0.9 * small, 2.0 * small],
        ));
    }
    out
}

/// What the oracle finds wrong with the certified axis of `region` (bounded by `profile`).
fn faults(profile: &Profile, region: &Region) -> Option<String> {
    let a = axis(region);
    if !a.certified() {
        return None;
    }
    let oracle = Oracle::new(profile);
    let size = region.size();
    // (A vertex's radius is as exact as the points are far out.)
    let radius_room = 1e-9 * size + 8.0 * profile.point_rounding();
    let distance = |x: [f64; 2]| oracle.nearest(x).0;
    let inside = |x: [f64; 2]| winding(&oracle.pts, x) != 0;
    for e in &a.edges {
        for (&x, &r) in e.xy.iter().zip(&e.radius) {
            let d = distance(x);
            if (d - r).abs() > radius_room {
                return Some(format!("vertex {x:?}: radius {r}, distance {d}"));
            }
        }
    }
    let sampled = sampled_medial_points(&[profile], size, distance, inside);
    for z in &sampled.points {
        let off = off_axis(&a, z.xy);
        if off > CHORD * size + 1e-6 * size {
            return Some(format!(
                "medial point {:?} (radius {}) is {off:e} off the axis",
                z.xy, z.radius
            ));
        }
    }
    None
}

#[test]
fn a_certified_axis_round_far_smooth_joints_is_the_oracles() {
    let bad: Vec<String> = shapes_at(FAR)
        .into_iter()
        .filter_map(|(name, profile, _)| {
            let region = Region::new(profile.clone(), vec![]).unwrap();
            faults(&profile, &region).map(|why| format!("{name}: {why}"))
        })
        .collect();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
