//! Offsets of regions far from the origin, whose smooth joints turn by the rounding of their
//! tangents (a line and an arc meeting tangentially at 1e8 turn by some 1e-8; a fillet of
//! radius 0.01 there, by some 1e-6): each joint's fan must be walked as a corner's is, or the
//! offset of the two segments either side of it leaves a gap (or an overlap) of `d` times the
//! turn at the joint.
//!
//! Judged by an oracle of its own, on every certified offset: the loops closed (each piece
//! starting where the one before ends, to the rounding of the profile's points), and dense
//! samples of every piece at the distance from the boundary (its nearest point by dense
//! samples and golden-section search, `testkit::boundary_oracle`), to the rounding of the
//! points and of the normals over the distance. (Before the fans were walked this held too:
//! the gap is along the offset, and `joints::close` met it as rounding, up to 1e-10 of the
//! coordinates, 1e-2 at 1e8. Far out, the inward axes are not certified yet.)
#![allow(clippy::unwrap_used)]

mod common;
use common::{ends, samples};
use curve::{Profile, Region, Segment};
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use numeric::rounding::ulps;
use offset::{offsets, outward_offsets, OffsetOptions};
use std::f64::consts::{FRAC_PI_2, PI};
use testkit::boundary_oracle::Oracle;

/// Where the shapes are moved.
const FAR: [f64; 2] = [1e8, 1e8];

/// Samples per offset piece.
const PER_PIECE: usize = 40;

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

/// What the oracle finds wrong with the offset loops `loops` of `profile` at `d` (empty:
/// nothing).
fn faults(profile: &Profile, oracle: &Oracle<'_>, d: f64, found: &offset::Offsets) -> Vec<String> {
    let mut bad = Vec::new();
    // Consecutive pieces meet to the rounding of the points (about as large as the profile's
    // own, the points as far out).
    let close = 4.0 * profile.point_rounding();
    // Each point at `d`: to the rounding of the points, and of the normals over `d` (below
    // the turn of the joints: a joint's own turn is no rounding of the offset's).
    let chord = 4.0 * profile.point_rounding() + ulps(64.0) * d;
    for (l, lp) in found.offsets[0].loops.iter().enumerate() {
        let pieces = &lp.segments;
        for (k, s) in pieces.iter().enumerate() {
            let (end, next) = (ends(s).1, ends(&pieces[(k + 1) % pieces.len()]).0);
            let apart = (end[0] - next[0]).hypot(end[1] - next[1]);
            if apart > close {
                bad.push(format!("loop {l}: piece {k} ends {apart:e} from the next"));
            }
            for p in samples(s, PER_PIECE) {
                let off = oracle.nearest(p).0 - d;
                if off.abs() > chord {
                    bad.push(format!("loop {l}: piece {k} {s:?}: a point {off:e} off"));
                    break;
                }
            }
        }
    }
    if found.offsets[0].loops.is_empty() {
        bad.push("no loop".into());
    }
    bad
}

#[test]
fn offsets_round_far_smooth_joints_are_closed_and_at_their_distance() {
    let mut bad = Vec::new();
    let opts = OffsetOptions {
        settings: testkit::settings(1e-6, None),
    };
    for (name, profile, distances) in shapes_at(FAR) {
        let region = Region::new(profile.clone(), vec![]).unwrap();
        let oracle = Oracle::new(&profile);
        let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
        let exterior = medial_axis(
            &region,
            &MedialOptions {
                exterior: true,
                ..MedialOptions::default()
            },
        )
        .unwrap();
        // (Outward also farther out: up to below half the size.)
        let far_out = 0.4 * region.size();
        for &d in distances.iter().chain([&far_out]) {
            let found = offsets(&region, &axis, &[d], &opts).unwrap();
            let grown = outward_offsets(&region, &exterior, &[d], &opts).unwrap();
            let ways = [("inward", &found), ("outward", &grown)];
            for (way, f) in ways
                .into_iter()
                .filter(|(w, _)| d < far_out || *w == "outward")
            {
                let wrong = faults(&profile, &oracle, d, f);
                if !wrong.is_empty() && f.certified() {
                    bad.push(format!(
                        "{name}, {way} d = {d}: certified {} ({:?}); {}",
                        f.certified(),
                        f.reason(),
                        wrong.join("; ")
                    ));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
