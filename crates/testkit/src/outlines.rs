//! The benchmarks' parts, which the tests run on too (a fault found on a benchmark shape is
//! tested on that very shape): the pocket, the CAD outline, gears, star polygons and a chain
//! of Béziers.
#![allow(clippy::unwrap_used)] // (the parts are valid by construction)

use curve::{Profile, Region, Segment, SegmentKind, SplineCurve, V2};

/// A closed chain of `n` cubic Béziers round a star, with corners at every joint.
pub fn bezier_chain(n: usize) -> Profile {
    let mut rnd = crate::rng(7);
    let joints: Vec<V2> = (0..n)
        .map(|i| V2::polar(std::f64::consts::TAU * i as f64 / n as f64) * (1.0 + 0.5 * rnd()))
        .collect();
    let segs = (0..n)
        .map(|i| {
            let (a, b) = (joints[i], joints[(i + 1) % n]);
            let w = 0.3 * (rnd() - 0.5);
            let pts = [
                a.arr(),
                (a + (b - a) * 0.3 + (b - a).perp() * w).arr(),
                (a + (b - a) * 0.7 - (b - a).perp() * w).arr(),
                b.arr(),
            ];
            let c = SplineCurve::clamped(3, &pts, None, None).unwrap();
            Segment::spline(SegmentKind::Bezier, c).unwrap()
        })
        .collect();
    Profile::new(segs, None).unwrap()
}

/// The vertices (counter-clockwise) of a star polygon of `n` lines (`n` even): points at
/// radius 1 and notches at radius 0.5, each radius jittered by up to 10 % so that no four
/// vertices are cocircular (the regular star's one junction of n edges is a case of its own).
pub fn star_polygon(n: usize) -> Vec<[f64; 2]> {
    let mut rnd = crate::rng(11);
    (0..n)
        .map(|i| {
            let r = if i % 2 == 0 { 1.0 } else { 0.5 } * (1.0 + 0.1 * rnd());
            (V2::polar(std::f64::consts::TAU * i as f64 / n as f64) * r).arr()
        })
        .collect()
}

/// The polygon through `vertices` as a closed profile of lines.
pub fn polygon(vertices: &[[f64; 2]]) -> Profile {
    let n = vertices.len();
    let sides = (0..n)
        .map(|i| Segment::line(vertices[i], vertices[(i + 1) % n]).unwrap())
        .collect();
    Profile::new(sides, None).unwrap()
}

/// The control points of the medial-axis issue's periodic cubic (`fixtures/periodic_cubic.json`,
/// the medial benchmark's `PERIODIC_CUBIC`): two sharp ends, whose axis ends at their centres
/// of curvature.
pub const PERIODIC_CUBIC_POINTS: [[f64; 2]; 6] = [
    [0.0, 0.0],
    [2.0, -1.0],
    [4.0, 0.0],
    [4.0, 2.0],
    [2.0, 1.2],
    [0.0, 2.0],
];

/// The control points of the periodic cubic NURBS fixture (`fixtures/periodic_nurbs.json`),
/// with [`PERIODIC_NURBS_WEIGHTS`].
pub const PERIODIC_NURBS_POINTS: [[f64; 2]; 8] = [
    [3.0, 0.0],
    [2.5, 2.0],
    [0.5, 1.0],
    [-1.0, 2.5],
    [-3.0, 0.5],
    [-2.5, -2.0],
    [0.0, -0.8],
    [2.0, -2.5],
];

/// The weights of [`PERIODIC_NURBS_POINTS`].
pub const PERIODIC_NURBS_WEIGHTS: [f64; 8] = [1.0, 2.0, 0.5, 1.0, 1.5, 1.0, 0.6, 1.0];

/// The control points of `fixtures/clamped_closed.json`: a cubic B-spline closed by its
/// points (its first and last equal, its end tangents along one line), on
/// [`CLAMPED_CLOSED_KNOTS`].
pub const CLAMPED_CLOSED_POINTS: [[f64; 2]; 9] = [
    [0.0, 0.0],
    [2.0, -1.0],
    [4.0, -0.5],
    [5.0, 1.5],
    [3.0, 1.0],
    [1.5, 3.0],
    [-1.0, 2.0],
    [-1.0, 0.5],
    [0.0, 0.0],
];

/// The knots of `fixtures/clamped_closed.json`: clamped, its interior knots not uniform.
pub const CLAMPED_CLOSED_KNOTS: [f64; 13] =
    [0., 0., 0., 0., 0.15, 0.3, 0.45, 0.6, 0.8, 1., 1., 1., 1.];

/// The control points of the cubic B-spline of Elber & Kim's Fig. 5, a self-bisector
/// (`fixtures/bisector-fig5-cubic-bspline.json`).
pub const FIG5_CUBIC_POINTS: [[f64; 2]; 7] = [
    [0.0, 0.0],
    [1.0, 2.0],
    [3.0, 2.5],
    [4.0, 0.5],
    [3.0, -1.5],
    [1.5, -1.0],
    [2.0, 0.5],
];

/// The 10×6 rounded-rectangle pocket (corner radius 1) with a round island of radius 1, as
/// the tool reads it.
pub const POCKET: &str = r#"{"kind":"region",
 "outer":{"kind":"profile","segments":[
  {"kind":"line","from":[1,0],"to":[9,0]},
  {"kind":"arc","center":[9,1],"r":1,"start":-1.5707963267948966,"end":0},
  {"kind":"line","from":[10,1],"to":[10,5]},
  {"kind":"arc","center":[9,5],"r":1,"start":0,"end":1.5707963267948966},
  {"kind":"line","from":[9,6],"to":[1,6]},
  {"kind":"arc","center":[1,5],"r":1,"start":1.5707963267948966,"end":3.141592653589793},
  {"kind":"line","from":[0,5],"to":[0,1]},
  {"kind":"arc","center":[1,1],"r":1,"start":3.141592653589793,"end":4.71238898038469}]},
 "holes":[{"kind":"circle","center":[6.5,3],"r":1}]}"#;

/// The vertices (counter-clockwise) of a CAD-style dense outline of about `n` lines: a
/// 100 × 60 plate with corners rounded at radius 10 and a 20 × 15 notch in its top side whose
/// two inner (reflex) corners are rounded at radius 3, every arc exported as chords and every
/// straight side as a run of collinear pieces, as DXF polylines come out of CAD programs.
pub fn dense_outline(n: usize) -> Vec<[f64; 2]> {
    use std::f64::consts::{FRAC_PI_2, PI};
    enum Piece {
        Line([f64; 2], [f64; 2]),
        Arc {
            centre: [f64; 2],
            r: f64,
            from: f64,
            to: f64,
        },
    }
    let pieces = [
        Piece::Line([10.0, 0.0], [90.0, 0.0]),
        Piece::Arc {
            centre: [90.0, 10.0],
            r: 10.0,
            from: -FRAC_PI_2,
            to: 0.0,
        },
        Piece::Line([100.0, 10.0], [100.0, 50.0]),
        Piece::Arc {
            centre: [90.0, 50.0],
            r: 10.0,
            from: 0.0,
            to: FRAC_PI_2,
        },
        Piece::Line([90.0, 60.0], [60.0, 60.0]),
        Piece::Line([60.0, 60.0], [60.0, 48.0]),
        Piece::Arc {
            centre: [57.0, 48.0],
            r: 3.0,
            from: 0.0,
            to: -FRAC_PI_2,
        },
        Piece::Line([57.0, 45.0], [43.0, 45.0]),
        Piece::Arc {
            centre: [43.0, 48.0],
            r: 3.0,
            from: -FRAC_PI_2,
            to: -PI,
        },
        Piece::Line([40.0, 48.0], [40.0, 60.0]),
        Piece::Line([40.0, 60.0], [10.0, 60.0]),
        Piece::Arc {
            centre: [10.0, 50.0],
            r: 10.0,
            from: FRAC_PI_2,
            to: PI,
        },
        Piece::Line([0.0, 50.0], [0.0, 10.0]),
        Piece::Arc {
            centre: [10.0, 10.0],
            r: 10.0,
            from: PI,
            to: 1.5 * PI,
        },
    ];
    // A quarter of the pieces to the arcs (6 of them), the rest to the sides by length.
    let per_arc = (n / 24).max(2);
    let straight: f64 = pieces
        .iter()
        .map(|p| match p {
            Piece::Line(a, b) => (V2::from_arr(*b) - V2::from_arr(*a)).norm(),
            Piece::Arc { .. } => 0.0,
        })
        .sum();
    let per_length = (n - 6 * per_arc) as f64 / straight;
    let mut out = Vec::with_capacity(n + 16);
    for p in &pieces {
        match *p {
            Piece::Line(a, b) => {
                let (a, b) = (V2::from_arr(a), V2::from_arr(b));
                let k = (((b - a).norm() * per_length).round() as usize).max(1);
                out.extend((0..k).map(|i| (a + (b - a) * (i as f64 / k as f64)).arr()));
            }
            Piece::Arc {
                centre,
                r,
                from,
                to,
            } => {
                let c = V2::from_arr(centre);
                out.extend((0..per_arc).map(|i| {
                    let t = from + (to - from) * (i as f64 / per_arc as f64);
                    (c + V2::polar(t) * r).arr()
                }));
            }
        }
    }
    out
}

/// The pitch and the tip's half-angle of a gear of `n` teeth, and its radii: tip, root and
/// the round hole at its middle.
fn gear_teeth(n: usize) -> (f64, f64, [f64; 3]) {
    let pitch = std::f64::consts::TAU / n as f64;
    (pitch, 0.18 * pitch, [10.0, 9.2, 3.0])
}

/// The CAD outline of about `n` lines ([`dense_outline`]) turned by 0.3 rad and its
/// coordinates rounded to 1e-6: every joint of its straight runs a corner of ~1e-6 rad,
/// beyond the seed's grid, so its axis is sought from every pair the bounds keep (seconds:
/// the work that cancellation is tested and measured on).
pub fn rounded_outline(n: usize) -> Region {
    let (c, s) = (0.3f64.cos(), 0.3f64.sin());
    let points: Vec<[f64; 2]> = dense_outline(n)
        .into_iter()
        .map(|p| [c * p[0] - s * p[1], s * p[0] + c * p[1]].map(|x| (x * 1e6).round() / 1e6))
        .collect();
    Region::new(polygon(&points), vec![]).unwrap()
}

/// A gear of `n` teeth about the origin, as a DXF part draws it: per tooth a tip arc
/// (radius 10), a flank down, a root arc (radius 9.2) and a flank up, the arcs meeting the
/// flanks at corners; with a round hole of radius 3 at the middle (one whole arc).
pub fn gear(n: usize) -> Region {
    let (pitch, half, [tip, root, hole]) = gear_teeth(n);
    let at = |r: f64, a: f64| (V2::polar(a) * r).arr();
    let mut segments = Vec::with_capacity(4 * n);
    for k in 0..n {
        let a = k as f64 * pitch;
        let (b, c, d) = (
            a + 0.5 * pitch - half,
            a + 0.5 * pitch + half,
            a + pitch - half,
        );
        segments.push(Segment::arc([0.0, 0.0], tip, a - half, a + half).unwrap());
        segments.push(Segment::line(at(tip, a + half), at(root, b)).unwrap());
        segments.push(Segment::arc([0.0, 0.0], root, b, c).unwrap());
        segments.push(Segment::line(at(root, c), at(tip, d)).unwrap());
    }
    let outer = Profile::new(segments, None).unwrap();
    let hole = Segment::arc([0.0, 0.0], hole, 0.0, std::f64::consts::TAU).unwrap();
    Region::new(outer, vec![Profile::new(vec![hole], None).unwrap()]).unwrap()
}

/// The gear of [`gear`] as closed polylines (its outline counter-clockwise, its hole
/// clockwise), every arc cut into equal chords within `sag` of it.
pub fn gear_chords(n: usize, sag: f64) -> [Vec<[f64; 2]>; 2] {
    let (pitch, half, [tip, root, hole]) = gear_teeth(n);
    // (The chords of an arc of radius r and angle θ within the sag: θ / (2 acos(1 − sag/r)).)
    // (Both ends of an arc of the outline; a whole circle's start once.)
    let arc = |r: f64, from: f64, angle: f64, ends: usize| -> Vec<[f64; 2]> {
        let k = (angle.abs() / (2.0 * (1.0 - sag / r).acos()))
            .ceil()
            .max(1.0) as usize;
        (0..k + ends - 1)
            .map(|j| (V2::polar(from + angle * j as f64 / k as f64) * r).arr())
            .collect()
    };
    let mut outline = Vec::new();
    for k in 0..n {
        let a = k as f64 * pitch;
        outline.extend(arc(tip, a - half, 2.0 * half, 2));
        outline.extend(arc(root, a + 0.5 * pitch - half, 2.0 * half, 2));
    }
    [outline, arc(hole, 0.0, -std::f64::consts::TAU, 1)]
}
