//! A bounding-volume hierarchy over a profile's segment boxes: the disk tests and nearest-point
//! searches of a boundary of thousands of segments look at the O(log n) segments near the
//! point, not at all of them.
//!
//! The tree is built once per profile by halving the boxes at the median of their centres
//! along the longer side of their common box; every node's box holds its children's, so its
//! distance from a point bounds theirs from below and a node beyond the reach of a query
//! is passed over whole.

use crate::geom::V2;
use crate::piece_bounds::box_distance;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// Boxes in a leaf: below this a scan of the boxes costs less than another level.
const LEAF: usize = 4;

/// One node: its box, and either its two children or a run of the boxes' order.
#[derive(Debug, Clone, PartialEq)]
struct TreeNode {
    bounds: [f64; 4],
    kind: NodeKind,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum NodeKind {
    /// The children's indices in the node list.
    Inner(u32, u32),
    /// `order[start..start + len]` are the boxes of this leaf.
    Leaf { start: u32, len: u32 },
}

/// The hierarchy over a list of boxes `[lo x, lo y, hi x, hi y]`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BoxTree {
    nodes: Vec<TreeNode>,
    /// The boxes' indices, leaf by leaf.
    order: Vec<u32>,
}

impl BoxTree {
    /// The tree over `boxes` (indices as given).
    pub(crate) fn new(boxes: &[[f64; 4]]) -> Self {
        let mut tree = Self {
            nodes: Vec::with_capacity(2 * boxes.len().div_ceil(LEAF)),
            order: (0..boxes.len() as u32).collect(),
        };
        if !boxes.is_empty() {
            tree.build(boxes, 0, boxes.len());
        }
        tree
    }

    /// Builds the node over `order[start..end]`; its index.
    fn build(&mut self, boxes: &[[f64; 4]], start: usize, end: usize) -> u32 {
        let run = &mut self.order[start..end];
        let bounds = run.iter().fold(
            [
                f64::INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NEG_INFINITY,
            ],
            |b, &i| {
                let c = boxes[i as usize];
                [
                    b[0].min(c[0]),
                    b[1].min(c[1]),
                    b[2].max(c[2]),
                    b[3].max(c[3]),
                ]
            },
        );
        let id = self.nodes.len();
        self.nodes.push(TreeNode {
            bounds,
            kind: NodeKind::Leaf {
                start: start as u32,
                len: (end - start) as u32,
            },
        });
        if end - start > LEAF {
            let axis = usize::from(bounds[3] - bounds[1] > bounds[2] - bounds[0]);
            let centre = |i: &u32| {
                let b = boxes[*i as usize];
                b[axis] + b[axis + 2]
            };
            let middle = (end - start) / 2;
            run.select_nth_unstable_by(middle, |a, b| centre(a).total_cmp(&centre(b)));
            let left = self.build(boxes, start, start + middle);
            let right = self.build(boxes, start + middle, end);
            self.nodes[id].kind = NodeKind::Inner(left, right);
        }
        id as u32
    }

    /// Calls `visit(i)` for every box `i` whose distance from `x` is below `reach`, and for
    /// some others of the same leaves (in no particular order; the caller tests each).
    pub fn within(&self, x: V2, reach: f64, mut visit: impl FnMut(usize)) {
        if self.nodes.is_empty() {
            return;
        }
        // (A tree over boxes halved at medians is at most log2(n) + 1 deep.)
        let mut stack: Vec<u32> = Vec::with_capacity(64);
        stack.push(0);
        while let Some(k) = stack.pop() {
            let node = &self.nodes[k as usize];
            if box_distance(node.bounds, x) >= reach {
                continue;
            }
            match node.kind {
                NodeKind::Inner(a, b) => stack.extend([a, b]),
                NodeKind::Leaf { start, len } => {
                    for &i in &self.order[start as usize..(start + len) as usize] {
                        visit(i as usize);
                    }
                }
            }
        }
    }

    /// The boxes in order of their nodes' distance from `x`, nearest first, for a search that
    /// stops once `visit(i)` has returned a distance no box left can beat: `visit` is called
    /// for box `i` while the least distance from `x` of the nodes left is below the least
    /// value `visit` has returned.
    pub fn nearest_first(&self, x: V2, mut visit: impl FnMut(usize) -> f64) {
        if self.nodes.is_empty() {
            return;
        }
        let mut best = f64::INFINITY;
        let mut heap = BinaryHeap::new();
        heap.push(Near(box_distance(self.nodes[0].bounds, x), 0));
        while let Some(Near(d, k)) = heap.pop() {
            if d >= best {
                break;
            }
            match self.nodes[k as usize].kind {
                NodeKind::Inner(a, b) => {
                    for c in [a, b] {
                        heap.push(Near(box_distance(self.nodes[c as usize].bounds, x), c));
                    }
                }
                NodeKind::Leaf { start, len } => {
                    for &i in &self.order[start as usize..(start + len) as usize] {
                        best = best.min(visit(i as usize));
                    }
                }
            }
        }
    }
}

/// A node and its distance from the query point, the nearest first out of the heap.
struct Near(f64, u32);

impl PartialEq for Near {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Near {}
impl PartialOrd for Near {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Near {
    fn cmp(&self, other: &Self) -> Ordering {
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn boxes_from(raw: &[(f64, f64, f64, f64)]) -> Vec<[f64; 4]> {
        raw.iter()
            .map(|&(x, y, w, h)| [x, y, x + w, y + h])
            .collect()
    }

    proptest! {
        /// The boxes within reach are those a scan of all of them finds.
        #[test]
        fn within_finds_what_a_scan_finds(
            raw in prop::collection::vec((-10.0..10.0f64, -10.0..10.0f64, 0.0..3.0f64, 0.0..3.0f64), 0..200),
            x in -12.0..12.0f64, y in -12.0..12.0f64, reach in 0.0..6.0f64,
        ) {
            let boxes = boxes_from(&raw);
            let tree = BoxTree::new(&boxes);
            let p = V2::new(x, y);
            let mut found = Vec::new();
            tree.within(p, reach, |i| found.push(i));
            found.sort_unstable();
            let scan: Vec<usize> = (0..boxes.len())
                .filter(|&i| box_distance(boxes[i], p) < reach)
                .collect();
            // (The tree may hand over boxes of a leaf beyond reach: the caller tests each.)
            prop_assert!(scan.iter().all(|i| found.binary_search(i).is_ok()));
            let mut unique = found.clone();
            unique.dedup();
            prop_assert_eq!(unique.len(), found.len());
        }

        /// The least distance a nearest-first search finds is the least over all boxes.
        #[test]
        fn nearest_first_finds_the_least(
            raw in prop::collection::vec((-10.0..10.0f64, -10.0..10.0f64, 0.0..3.0f64, 0.0..3.0f64), 1..200),
            x in -12.0..12.0f64, y in -12.0..12.0f64,
        ) {
            let boxes = boxes_from(&raw);
            let tree = BoxTree::new(&boxes);
            let p = V2::new(x, y);
            // (The boxes' centres stand for the segments in them.)
            let centre = |b: [f64; 4]| V2::new(0.5 * (b[0] + b[2]), 0.5 * (b[1] + b[3]));
            let mut best = f64::INFINITY;
            let mut visited = 0;
            tree.nearest_first(p, |i| {
                visited += 1;
                let d = (centre(boxes[i]) - p).norm();
                best = best.min(d);
                d
            });
            let scan = boxes.iter().map(|&b| (centre(b) - p).norm()).fold(f64::INFINITY, f64::min);
            prop_assert_eq!(best, scan);
            prop_assert!(visited <= boxes.len());
        }
    }
}
