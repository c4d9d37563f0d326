//! The pairs of boundary segments that can share an empty disk, found before any bisector
//! is computed: a quadtree over the box the axis lies in keeps, per cell, the segments that
//! may be nearest to some point of it. A point of the axis has its two feet on segments
//! that are both nearest to it, so both are kept in its cell; a pair kept in no cell has no
//! bisector point on the axis.
//!
//! A segment is seen through the chords of short pieces of it and a bound on how far it
//! strays from them (its sag), so the distance from a cell's centre to it is known to
//! within the sag; the distance from any point of the cell to within half the cell's
//! diagonal more (distances are 1-Lipschitz). Halving a cell tightens its bounds until its
//! size is that of the sag. Where more than two segments stay, those whose normal fans miss
//! the cell go too ([`crate::fans`]): beside a smooth boundary the distances part its short
//! segments too slowly for halving to.

use crate::fans::Fan;
use crate::sites::EMPTY_SLACK;
use curve::{distance_to_segment, squared_distance_to_segment, ParamCurve, Profile};
use std::collections::HashSet;

/// Below this many segments in all, every pair is computed: the tree costs more than it
/// saves.
pub(crate) const FEW_SEGMENTS: usize = 8;

/// Chords per segment (at least one per Bézier piece): the sag of a piece shrinks with the
/// square of its length, so eight keep it near a hundredth of a gently curved segment.
const CHORDS: usize = 8;

/// The longest run of consecutive segments of one boundary a cell keeps without halving:
/// a segment and its two neighbours.
const RUN: usize = 3;

/// Depth of the quadtree: cells where three or more segments stay nearest (beside a
/// junction) are halved this often at most.
const MAX_PAIR_DEPTH: usize = 10;

/// A segment of a boundary: boundary index and segment index.
pub(crate) type SegmentId = (usize, usize);

/// The pairs of segments that can share an empty disk.
pub(crate) enum Neighbours {
    /// Every pair (few segments).
    All,
    /// The pairs kept, each in order (smaller first).
    Only(HashSet<(SegmentId, SegmentId)>),
}

impl Neighbours {
    /// Whether segments `a` and `b` can share an empty disk.
    pub(crate) fn keep(&self, a: SegmentId, b: SegmentId) -> bool {
        match self {
            Neighbours::All => true,
            Neighbours::Only(pairs) => a == b || pairs.contains(&(a.min(b), a.max(b))),
        }
    }

    /// How many pairs of distinct segments are kept (`None`: all).
    #[cfg(test)]
    pub(crate) fn count(&self) -> Option<usize> {
        match self {
            Neighbours::All => None,
            Neighbours::Only(pairs) => Some(pairs.len()),
        }
    }
}

/// One segment as the tree sees it: the box holding it, and chords it stays near.
struct Site {
    id: SegmentId,
    bounds: [f64; 4],
    /// The segment's points at the ends of its chords, in order.
    points: Vec<[f64; 2]>,
    /// No point of the segment lies farther than this from its chords, nor any point of a
    /// chord from the segment.
    sag: f64,
    /// Where it can hold a nearest point (`None`: anywhere).
    fan: Option<Fan>,
}

impl Site {
    fn new(boundary: &Profile, k: usize, i: usize, fan: Option<Fan>) -> Self {
        let pieces = boundary.segments()[i].curve().exact_pieces().hom;
        let per_piece = CHORDS.div_ceil(pieces.pieces());
        let pieces = pieces.subdivided(per_piece);
        let mut points = Vec::with_capacity(pieces.pieces() + 1);
        let mut sag = 0.0f64;
        for k in 0..pieces.pieces() {
            let hull = pieces.piece(k);
            // A rational piece lies in the hull of its Euclidean control points only where
            // its weights are positive.
            if hull.chunks_exact(3).any(|c| c[2].is_nan() || c[2] <= 0.0) {
                sag = f64::INFINITY;
            }
            let euclidean: Vec<[f64; 2]> = hull
                .chunks_exact(3)
                .map(|c| [c[0] / c[2], c[1] / c[2]])
                .collect();
            let (a, b) = (euclidean[0], euclidean[euclidean.len() - 1]);
            sag = euclidean
                .iter()
                .map(|&p| distance_to_segment(p, a, b))
                .fold(sag, f64::max);
            if k == 0 {
                points.push(a);
            }
            points.push(b);
        }
        Self {
            id: (k, i),
            bounds: boundary.segment_box(i),
            points,
            sag,
            fan,
        }
    }

    /// Bounds below and above on the distance from `x` to the segment.
    fn distance_bounds(&self, x: [f64; 2]) -> (f64, f64) {
        let d = self
            .points
            .windows(2)
            .map(|w| squared_distance_to_segment(x, w[0], w[1]))
            .fold(f64::INFINITY, f64::min)
            .sqrt();
        (d - self.sag, d + self.sag)
    }
}

/// The pairs of segments of `boundaries` that can share an empty disk centred in `root` (the
/// box the axis lies in: the outer boundary's, or the clip box outside); `size` is the
/// region's.
pub(crate) fn neighbours(boundaries: &[&Profile], size: f64, root: [f64; 4]) -> Neighbours {
    let total: usize = boundaries.iter().map(|b| b.segments().len()).sum();
    if total < FEW_SEGMENTS {
        return Neighbours::All;
    }
    let origin = [0.5 * (root[0] + root[2]), 0.5 * (root[1] + root[3])];
    let all: Vec<Site> = boundaries
        .iter()
        .enumerate()
        .flat_map(|(k, b)| {
            Fan::of_all(b, origin)
                .into_iter()
                .enumerate()
                .map(move |(i, fan)| Site::new(b, k, i, fan))
        })
        .collect();
    // The bounds carry rounding of ~1e-16 of the coordinates; a disk empty to the axis's
    // slack still counts as empty, so a segment that far beyond the nearest is kept.
    let slack = 2.0 * EMPTY_SLACK * size;
    let mut pairs = HashSet::new();
    let mut stack: Vec<([f64; 4], Vec<usize>, usize)> = vec![(root, (0..all.len()).collect(), 0)];
    // Bounded: each cell is popped once, and only cells above MAX_PAIR_DEPTH are split.
    while let Some((cell, parent, depth)) = stack.pop() {
        let centre = [0.5 * (cell[0] + cell[2]), 0.5 * (cell[1] + cell[3])];
        let half = 0.5 * (cell[2] - cell[0]).hypot(cell[3] - cell[1]);
        // Every point of the cell is within `reach` of the boundary; a segment farther
        // than that from the whole cell is nowhere nearest in it. (Only the parent's: a
        // segment dropped there is farther still.) Nearest boxes first: a segment whose
        // box is beyond the reach so far is no nearer.
        let mut gaps: Vec<(f64, usize)> = parent
            .into_iter()
            .map(|s| (box_gap(cell, all[s].bounds), s))
            .collect();
        gaps.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut reach = f64::INFINITY;
        let mut nearest: Vec<(f64, usize)> = Vec::with_capacity(gaps.len());
        for &(gap, s) in &gaps {
            if gap > reach + slack {
                break;
            }
            let (lo, hi) = all[s].distance_bounds(centre);
            reach = reach.min(hi + half);
            nearest.push(((lo - half).max(gap), s));
        }
        let mut kept: Vec<usize> = nearest
            .iter()
            .filter(|(least, _)| *least <= reach + slack)
            .map(|&(_, s)| s)
            .collect();
        // Beside a smooth boundary distances part its segments slowly (module docs of
        // `fans`): those that cannot hold a nearest point of the cell go. (Two or fewer make
        // at most one pair, kept without halving: not worth the test.)
        if kept.len() > 2 {
            kept.retain(|&s| all[s].fan.as_ref().is_none_or(|f| f.may_hold_foot(cell)));
        }
        kept.sort_unstable();
        // A cell smaller than the sag of its segments gains little by halving: its bounds
        // are that loose.
        let sag = kept.iter().map(|&s| all[s].sag).fold(0.0, f64::max);
        let run = kept.len() <= RUN && one_run(&kept, &all, boundaries);
        if kept.len() <= 2 || run || depth == MAX_PAIR_DEPTH || half < sag {
            for (n, &a) in kept.iter().enumerate() {
                for &b in &kept[n + 1..] {
                    let (a, b) = (all[a].id, all[b].id);
                    pairs.insert((a.min(b), a.max(b)));
                }
            }
            continue;
        }
        for q in [
            [cell[0], cell[1], centre[0], centre[1]],
            [centre[0], cell[1], cell[2], centre[1]],
            [cell[0], centre[1], centre[0], cell[3]],
            [centre[0], centre[1], cell[2], cell[3]],
        ] {
            stack.push((q, kept.clone(), depth + 1));
        }
    }
    Neighbours::Only(pairs)
}

/// Whether `kept` are consecutive segments of one boundary (round its seam where closed):
/// beside a smooth boundary a segment's neighbours stay within the samples' looseness of
/// it, so halving on cannot drop them; their pairs are all kept.
fn one_run(kept: &[usize], all: &[Site], boundaries: &[&Profile]) -> bool {
    let k = all[kept[0]].id.0;
    if kept.iter().any(|&s| all[s].id.0 != k) {
        return false;
    }
    let n = boundaries[k].segments().len();
    let mut segs: Vec<usize> = kept.iter().map(|&s| all[s].id.1).collect();
    segs.sort_unstable();
    let gaps = segs.windows(2).filter(|w| w[1] != w[0] + 1).count();
    let wraps = boundaries[k].is_closed() && segs[0] == 0 && segs[segs.len() - 1] == n - 1;
    gaps == 0 || (gaps == 1 && wraps)
}

/// The least distance between two boxes `[lo x, lo y, hi x, hi y]`.
fn box_gap(a: [f64; 4], b: [f64; 4]) -> f64 {
    let dx = (a[0] - b[2]).max(b[0] - a[2]).max(0.0);
    let dy = (a[1] - b[3]).max(b[1] - a[3]).max(0.0);
    dx.hypot(dy)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::candidates::PairSource;
    use crate::test_shapes::{spline_star, star};
    use crate::{axis_of, MedialOptions};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

        /// The same on one B-spline of many spans, cut at its knots (polynomial or rational:
        /// the fans of rational spans are built on their homogeneous form).
        #[test]
        fn pruned_pairs_of_spans_give_the_same_axis(
            radii in proptest::collection::vec(1.0f64..1.6, 10..24),
            weights in proptest::collection::vec(0.4f64..2.5, 24),
            rational in any::<bool>(),
        ) {
            let w = rational.then_some(&weights[..radii.len()]);
            let Some(region) = spline_star(&radii, w) else { return Ok(()) };
            let opts = MedialOptions::default();
            let pruned = axis_of(&region, &opts, PairSource::Bounds).unwrap().0;
            let every = axis_of(&region, &opts, PairSource::All).unwrap().0;
            prop_assert_eq!(pruned, every);
        }

        /// Pruning changes nothing: the axis from the pairs kept is the axis from every pair.
        #[test]
        fn pruned_pairs_give_the_same_axis(
            radii in proptest::collection::vec(1.0f64..1.6, 16..28),
            wobble in proptest::collection::vec(-0.15f64..0.15, 28),
            holes in proptest::collection::vec(([-0.4f64..0.4, -0.4f64..0.4], 0.05f64..0.2), 0..3),
        ) {
            let Some(region) = star(&radii, &wobble[..radii.len()], &holes) else {
                return Ok(());
            };
            for exterior in [false, true] {
                let opts = MedialOptions { exterior, ..Default::default() };
                let pruned = axis_of(&region, &opts, PairSource::Bounds).unwrap().0;
                let every = axis_of(&region, &opts, PairSource::All).unwrap().0;
                prop_assert_eq!(pruned, every);
            }
        }
    }

    /// The tree keeps fewer pairs than all on a long chain, and every pair it keeps is
    /// within its reach: a 40-segment star keeps under a quarter of its 780 pairs (170).
    #[test]
    fn a_long_chain_keeps_few_pairs() {
        let radii: Vec<f64> = (0..40)
            .map(|i| 1.0 + 0.3 * ((i * 7 % 11) as f64 / 11.0))
            .collect();
        let region = star(&radii, &[0.05; 40], &[]).unwrap();
        let sites = crate::sites::Sites::new(&region, false);
        let root = crate::candidates::root_box(&sites);
        let kept = neighbours(&sites.boundaries, sites.size, root)
            .count()
            .unwrap();
        assert!(kept > 40 && kept < 780 / 4, "{kept}");
    }
}
