//! Profiles far from the origin, whose smooth joints turn by the rounding of their tangents
//! (a line and an arc meeting tangentially at 1e8 turn by some 1e-8): each joint's fan of
//! normals is searched for the pairs the segments' searches miss there, widened by that
//! joint's own rounding only. One short segment elsewhere (whose own joints round by far
//! more) must not widen the fan of another joint: a fan widened by 1e-3 took a pair 2.5e-4
//! off the joint's normal, certified.
#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use antipodal::{antipodal, Options, Profile, Segment, Verdict};
use curve::V2;
use std::f64::consts::PI;

/// A D-like convex shape turned by `a` about `o` and moved there: a bottom line into `J = o`,
/// a quarter arc about (0, 1) leaving `J` tangentially, a side, a top half circle about
/// (−off, 2), a side back. `short` splits a side by a collinear piece 1e-4 long (0: none,
/// 1: the bottom, 2: the left side).
fn d_shape(o: [f64; 2], a: f64, short: u8, off: f64) -> Profile {
    let (c, s) = (a.cos(), a.sin());
    let m = |x: f64, y: f64| [o[0] + c * x - s * y, o[1] + s * x + c * y];
    let line = |p: [f64; 2], q: [f64; 2]| Segment::line(p, q).unwrap();
    let mut segs = vec![];
    if short == 1 {
        segs.push(line(m(-1.0, 0.0), m(-0.9999, 0.0)));
        segs.push(line(m(-0.9999, 0.0), m(0.0, 0.0)));
    } else {
        segs.push(line(m(-1.0, 0.0), m(0.0, 0.0)));
    }
    segs.push(Segment::arc(m(0.0, 1.0), 1.0, -PI / 2.0 + a, a).unwrap());
    segs.push(line(m(1.0, 1.0), m(1.0 - off, 2.0)));
    segs.push(Segment::arc(m(-off, 2.0), 1.0, a, PI + a).unwrap());
    let (x0, y0) = (-1.0 - off, 2.0);
    if short == 2 {
        let t = 1e-4 / (off * off + 4.0).sqrt();
        let (x1, y1) = (x0 + (-1.0 - x0) * t, y0 - y0 * t);
        segs.push(line(m(x0, y0), m(x1, y1)));
        segs.push(line(m(x1, y1), m(-1.0, 0.0)));
    } else {
        segs.push(line(m(x0, y0), m(-1.0, 0.0)));
    }
    Profile::new(segs, Some(true)).unwrap()
}

#[test]
fn a_pair_at_a_smooth_joint_lies_along_its_normal() {
    let mut bad = vec![];
    for a in [0.3, 0.7, 1.1] {
        for off in [2e-4, 5e-4] {
            for short in [0u8, 1, 2] {
                let o = [1e8, 1e8];
                let p = d_shape(o, a, short, off);
                let joint = V2::new(o[0], o[1]);
                let r = antipodal(&p, &Options::default()).unwrap();
                // The inward normal at the joint is (−sin a, cos a) (it turns by ~1e-8): a
                // pair with an end there points along it.
                let normal = V2::new(-a.sin(), a.cos());
                for x in &r.pairs {
                    for (e, f) in [(x.p, x.q), (x.q, x.p)] {
                        let (e, f) = (V2::from_arr(e), V2::from_arr(f));
                        if (e - joint).norm() < 1e-6 {
                            let miss = normal.cross((f - e).unit()).abs();
                            if miss > 1e-6 {
                                bad.push(format!(
                                    "a = {a}, off = {off:e}, short = {short}: a pair at the \
                                     joint {miss:e} off its normal, certified {}",
                                    r.certified()
                                ));
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
