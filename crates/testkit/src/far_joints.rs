//! Profiles whose joints are smooth by construction, to be moved far from the origin, where
//! their tangents round apart (a line and an arc meeting tangentially at 1e8 turn by some
//! 1e-8; a fillet of radius 0.01 there, by some 1e-6): stadiums, filleted rectangles, the
//! D-shapes of antipodal's `far_joints.rs`, and ovals of four arcs. The offsets' and the
//! medial axis's tests run on them.
#![allow(clippy::unwrap_used)]

use curve::{Profile, Segment};
use std::f64::consts::{FRAC_PI_2, PI};

fn line(p: [f64; 2], q: [f64; 2]) -> Segment {
    Segment::line(p, q).unwrap()
}

fn at(o: [f64; 2], x: f64, y: f64) -> [f64; 2] {
    [o[0] + x, o[1] + y]
}

/// A stadium about `o`: two sides `2 half` long joined by half circles of radius `r`.
pub fn stadium(o: [f64; 2], half: f64, r: f64) -> Profile {
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
pub fn filleted_rectangle(o: [f64; 2], w: f64, h: f64, f: f64, a: f64) -> Profile {
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
pub fn d_shape(o: [f64; 2], a: f64, off: f64) -> Profile {
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
pub fn oval(o: [f64; 2], big: f64, small: f64, t: f64) -> Profile {
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
pub fn shapes_at(o: [f64; 2]) -> Vec<(String, Profile, Vec<f64>)> {
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
