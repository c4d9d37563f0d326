//! Joints toward which a region's least friction falls without reaching it.
//!
//! A region beside a reflex corner's line (the corner takes no part) or beside a pair of
//! joints at one point (no chord) may need less and less friction toward it: its infimum is
//! not attained. The best grasp found approaches it, but where the search stops a chord
//! short (a traced edge beside the corner) or the set at a friction just below is finer
//! there than its trace resolves, the proof fails. What can be proven then is that every
//! pair of the region needing less friction has a finger within a stretch round such a
//! joint: those pairs are spared by the proof.

use crate::assemble::RawRegion;
use crate::model::{Cone, Model};
use crate::polyline::bounds;
use crate::region_set::{deepest, ON_LINE};

/// A best grasp is taken to approach a joint's line when it lies this many chords from it
/// (the search keeps a chord inside traced polylines, themselves a chord from the edge).
const APPROACH_CHORDS: f64 = 4.0;

/// The stretch spared round each joint, in units of the best grasp's distance from its line
/// (the pairs needing less friction than it lie nearer the line than it does, to first order,
/// where the friction grows away from the line; along it they may reach as far again).
const STRETCH_PER_DISTANCE: f64 = 4.0;

/// How far (in chords) a traced piece's chord keeps inside a stretch's edges to be spared:
/// the piece itself lies within a chord of it.
const PIECE_CLEARANCE: f64 = 2.0;

/// Joints whose stretches (in the profile's parameter) are left out of a best grasp's proof.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Spared {
    /// The joints' profile parameters (integers in `[0, n)`).
    pub(crate) joints: Vec<f64>,
    /// How far either side of a joint its stretch reaches.
    pub(crate) by: f64,
}

impl Spared {
    /// The joints that `best` (a pair of `region`'s, in the triangle) approaches: those
    /// within [`APPROACH_CHORDS`] chords of it in either finger, that are corners and whose
    /// own pairs (a convex corner's line) the region does not hold. Empty where there is none.
    pub(crate) fn toward(
        model: &Model<'_>,
        region: &RawRegion,
        best: [f64; 2],
        chord: f64,
    ) -> Self {
        let n = model.n() as f64;
        let mut joints = Vec::new();
        let mut reach = chord;
        for x in best {
            let k = x.round();
            let distance = (x - k).abs();
            if distance > APPROACH_CHORDS * chord {
                continue;
            }
            let joint = k.rem_euclid(n);
            let corner = model
                .joint_at(joint)
                .is_some_and(|j| j.cone != Cone::Smooth);
            let on_line =
                |p: &[f64; 2]| p[0] == joint || p[1] == joint || p[1] == n && joint == 0.0;
            let held = region
                .lines
                .iter()
                .any(|l| on_line(&l[0]) && on_line(&l[1]))
                || region.points.iter().any(on_line);
            if corner && !held && !joints.contains(&joint) {
                joints.push(joint);
                reach = reach.max(distance);
            }
        }
        // (And the clearance the lower set's traced pieces need inside the stretch.)
        Self {
            joints,
            by: STRETCH_PER_DISTANCE * reach + PIECE_CLEARANCE * chord,
        }
    }

    /// Whether there is nothing to spare.
    pub(crate) fn is_empty(&self) -> bool {
        self.joints.is_empty()
    }

    /// The middle lines of the stretches in the square: each finger (the axis) at each
    /// joint's copies (modulo `n`).
    fn lines(&self, n: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let n = n as f64;
        (0..2).flat_map(move |d| {
            self.joints
                .iter()
                .flat_map(move |&k| [k - n, k, k + n].map(|at| (d, at)))
        })
    }

    /// Whether the pair `p` has a finger in a spared stretch.
    pub(crate) fn spares(&self, n: usize, p: [f64; 2]) -> bool {
        self.lines(n).any(|(d, at)| (p[d] - at).abs() < self.by)
    }

    /// Whether the segment from `a` to `b` (a chord of a traced piece, within `chord` of the
    /// piece) lies in one spared stretch with the piece: both ends in the band of one finger
    /// round one joint (which is convex), [`PIECE_CLEARANCE`] chords inside its edges.
    pub(crate) fn spares_segment(&self, n: usize, a: [f64; 2], b: [f64; 2], chord: f64) -> bool {
        let inner = self.by - PIECE_CLEARANCE * chord;
        self.lines(n)
            .any(|(d, at)| (a[d] - at).abs() < inner && (b[d] - at).abs() < inner)
    }

    /// A pair of `part` (a closed polyline in one cell, with the region's `holes`) outside
    /// every spared stretch, where the part outside them is connected (so one pair tells
    /// whether all of it lies in a set whose boundary in the part is spared).
    pub(crate) fn witness(&self, n: usize, part: &[[f64; 2]], holes: &[Vec<[f64; 2]>]) -> Witness {
        let mut rest = part.to_vec();
        for (d, at) in self.lines(n) {
            let (lo, hi) = (at - self.by, at + self.by);
            if !rest.iter().any(|p| p[d] > lo && p[d] < hi) {
                continue;
            }
            // (A part lies in one cell: on one side of the joint's line, to rounding.)
            let (lo_part, hi_part) = bounds(&rest);
            let above = 0.5 * (lo_part[d] + hi_part[d]) >= at;
            let beside = if above {
                lo_part[d] >= at - ON_LINE
            } else {
                hi_part[d] <= at + ON_LINE
            };
            if !beside {
                return Witness::Unknown;
            }
            let keep = if above {
                |x: f64, edge: f64| x >= edge
            } else {
                |x: f64, edge: f64| x <= edge
            };
            let edge = if above { hi } else { lo };
            let Some(cut) = clip_once(&rest, d, edge, keep) else {
                return Witness::Unknown;
            };
            if cut.is_empty() {
                return Witness::Spared;
            }
            rest = cut;
        }
        // A hole reaching a stretch could part what is left.
        if holes.iter().flatten().any(|p| self.spares(n, *p)) {
            return Witness::Unknown;
        }
        let single = RawRegion {
            parts: vec![rest],
            holes: holes.to_vec(),
            ..RawRegion::default()
        };
        match deepest(&single, 1).first() {
            Some(&(p, _)) if !self.spares(n, p) => Witness::Pair(p),
            _ => Witness::Unknown,
        }
    }
}

/// What [`Spared::witness`] finds of a part.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Witness {
    /// A pair outside the stretches, standing for the whole part outside them.
    Pair([f64; 2]),
    /// The part lies within the stretches.
    Spared,
    /// The part outside them is not shown to be one piece.
    Unknown,
}

/// The closed polyline `pts` cut to the side of the line `x[d] = edge` that `keep` says, where
/// its boundary crosses that line at most twice (the piece kept is then one polygon): `None`
/// where it crosses more often.
fn clip_once(
    pts: &[[f64; 2]],
    d: usize,
    edge: f64,
    keep: fn(f64, f64) -> bool,
) -> Option<Vec<[f64; 2]>> {
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(pts.len() + 2);
    let mut crossings = 0;
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (ka, kb) = (keep(a[d], edge), keep(b[d], edge));
        if ka {
            out.push(a);
        }
        if ka != kb {
            crossings += 1;
            let f = (edge - a[d]) / (b[d] - a[d]);
            let mut x = [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])];
            x[d] = edge;
            out.push(x);
        }
    }
    if crossings > 2 {
        return None;
    }
    if let Some(&first) = out.first() {
        out.push(first);
    }
    // (A sliver of fewer than three corners has no inside.)
    if out.len() < 4 {
        out.clear();
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_cut_by_a_band_keeps_its_far_side() {
        let square = vec![[1.0, 5.0], [1.5, 5.0], [1.5, 5.5], [1.0, 5.5], [1.0, 5.0]];
        let spared = Spared {
            joints: vec![1.0],
            by: 0.1,
        };
        let Witness::Pair(p) = spared.witness(8, &square, &[]) else {
            panic!("no witness");
        };
        assert!(
            p[0] >= 1.1 && p[0] <= 1.5 && p[1] > 5.0 && p[1] < 5.5,
            "{p:?}"
        );
        assert!(spared.spares(8, [1.05, 5.2]));
        assert!(!spared.spares(8, [1.2, 5.2]));
        assert!(spared.spares_segment(8, [1.05, 5.2], [1.07, 5.4], 0.01));
        assert!(!spared.spares_segment(8, [1.05, 5.2], [1.09, 5.4], 0.01));
        assert!(!spared.spares_segment(8, [1.05, 5.2], [1.2, 5.4], 0.01));
    }

    #[test]
    fn a_part_crossing_the_band_s_edge_four_times_gets_no_witness() {
        // Two teeth reaching into the band from x = 2 toward the joint at 1 (what is left
        // is connected, but more than two crossings are not trusted to say so).
        let comb = vec![
            [1.05, 5.0],
            [2.0, 5.0],
            [2.0, 6.0],
            [1.05, 6.0],
            [1.05, 5.7],
            [1.5, 5.7],
            [1.5, 5.3],
            [1.05, 5.3],
            [1.05, 5.0],
        ];
        let spared = Spared {
            joints: vec![1.0],
            by: 0.1,
        };
        assert_eq!(spared.witness(8, &comb, &[]), Witness::Unknown);
        let thin = vec![[1.0, 5.0], [1.05, 5.0], [1.05, 6.0], [1.0, 6.0], [1.0, 5.0]];
        assert_eq!(spared.witness(8, &thin, &[]), Witness::Spared);
    }

    #[test]
    fn the_seam_s_joint_spares_both_ends_of_the_square() {
        let spared = Spared {
            joints: vec![0.0],
            by: 0.01,
        };
        assert!(spared.spares(8, [0.005, 3.0]));
        assert!(spared.spares(8, [3.0, 7.995]));
        assert!(!spared.spares(8, [3.0, 7.98]));
    }
}
