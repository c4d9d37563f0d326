//! Offsets of regions far from the origin, whose smooth joints turn by the rounding of their
//! tangents (a line and an arc meeting tangentially at 1e8 turn by some 1e-8; a fillet of
//! radius 0.01 there, by some 1e-6): the offsets of the two segments either side of such a
//! joint end `d` times its turn apart.
//!
//! Judged by an oracle of its own, on every certified offset: the loops closed (each piece
//! starting where the one before ends, to the rounding of the profile's points), and dense
//! samples of every piece at the distance from the boundary (its nearest point by dense
//! samples and golden-section search, `testkit::boundary_oracle`), to the rounding of the
//! points and of the normals over the distance. (The gap lies along the offset, and
//! `joints::close` meets it as rounding, up to 1e-10 of the coordinates, 1e-2 at 1e8; a wider
//! one is bridged by a line and the offsets say so, uncertified. Far out, the inward axes
//! are not certified yet, so the outward offsets are the ones checked there.)
#![allow(clippy::unwrap_used)]

mod common;
use common::{ends, exterior_axis, samples};
use curve::{Profile, Region};
use medial::{medial_axis, MedialOptions};
use numeric::certificate::Verdict;
use numeric::rounding::ulps;
use offset::{offsets, outward_offsets, OffsetOptions};
use testkit::boundary_oracle::Oracle;
use testkit::far_joints::shapes_at;

/// Where the shapes are moved.
const FAR: [f64; 2] = [1e8, 1e8];

/// Samples per offset piece.
const PER_PIECE: usize = 40;

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
        let exterior = exterior_axis(&region);
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
