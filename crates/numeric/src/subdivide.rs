//! The one halve-until-decided driver. A search over an interval, a rectangle or a Bézier
//! piece visits a part, decides it (proven, kept, passed over) or halves it, and goes on with
//! the halves: depth first, the first half before the second, so that the parts a search
//! keeps come out in order along the parameter. The driver owns the stack and the bound on
//! the depth; what a part is, how it halves and what a visit records are the caller's.
//!
//! ```
//! use numeric::subdivide::{depth_first, Decision};
//! // The dyadic points where x ↦ x² on [0, 1] needs chords within 1/64 of it, in order.
//! let mut ends = vec![0.0];
//! depth_first((0.0f64, 1.0f64), 20, |(a, b), visit| {
//!     let sag = (b - a) * (b - a) / 4.0; // x² lies within this of its chord on [a, b]
//!     if sag > 1.0 / 64.0 && visit.can_halve {
//!         let m = 0.5 * (a + b);
//!         Decision::<_, ()>::Halve((a, m), (m, b))
//!     } else {
//!         ends.push(b);
//!         Decision::Decided
//!     }
//! });
//! assert_eq!(ends, [0.0, 0.25, 0.5, 0.75, 1.0]);
//! ```

/// Where a visited part lies in the halving.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Visit {
    /// Halvings from the root to this part.
    pub depth: usize,
    /// Whether the part may still be halved (its depth is below the search's bound): a part
    /// that may not is decided as it is, with what that leaves unproven.
    pub can_halve: bool,
}

/// What a visit decides about its part.
#[derive(Debug, Clone, PartialEq)]
pub enum Decision<P, B> {
    /// Done with the part: the visit has recorded what the search needs of it.
    Decided,
    /// Visit the two halves, the first before the second (and before any part visited
    /// later than this one).
    Halve(P, P),
    /// End the whole search with this value.
    Stop(B),
}

/// Visits `root` and, depth first, the halves the visits ask for, a part `max_depth` halvings
/// deep being visited with [`Visit::can_halve`] false (a halving asked of it anyway is not
/// made: the part counts as decided). Returns the value a visit stopped the search with.
///
/// At most `2^(max_depth + 1) − 1` parts are visited; a search that must bound its work more
/// tightly counts its visits and stops.
pub fn depth_first<P, B>(
    root: P,
    max_depth: usize,
    mut visit: impl FnMut(P, Visit) -> Decision<P, B>,
) -> Option<B> {
    // The part to visit next: the root, then each first half, goes straight to its visit;
    // only the second halves wait on the stack (a root decided at once allocates nothing).
    let mut next = Some((root, 0usize));
    let mut stack = Vec::new();
    while let Some((part, depth)) = next.take().or_else(|| stack.pop()) {
        let can_halve = depth < max_depth;
        match visit(part, Visit { depth, can_halve }) {
            Decision::Decided => {}
            Decision::Halve(first, second) => {
                debug_assert!(can_halve, "a part at the depth bound was asked to halve");
                if can_halve {
                    stack.push((second, depth + 1));
                    next = Some((first, depth + 1));
                }
            }
            Decision::Stop(value) => return Some(value),
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Against a recursive halving, on random depths at which parts are decided: the same
        /// leaves in the same order, none beyond the bound, and a stop ends the search where
        /// the recursion's first such leaf is.
        #[test]
        fn the_leaves_come_in_order_as_a_recursion_finds_them(
            seed in any::<u64>(),
            max_depth in 0usize..12,
            stop_at in prop::option::of(0usize..64),
        ) {
            // A part is decided when a hash of its start says so.
            let decided = |lo: f64, depth: usize| {
                let h = (lo.to_bits() ^ seed).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 60;
                depth >= 1 && h < 6
            };
            let mut all = Vec::new();
            recurse((0.0, 1.0), 0, max_depth, &decided, &mut all);
            let mut got = Vec::new();
            let mut deepest = 0;
            let stopped = depth_first((0.0f64, 1.0f64), max_depth, |(lo, hi), visit| {
                deepest = deepest.max(visit.depth);
                if decided(lo, visit.depth) || !visit.can_halve {
                    if Some(got.len()) == stop_at {
                        return Decision::Stop(got.len());
                    }
                    got.push((lo, hi));
                    Decision::Decided
                } else {
                    let m = 0.5 * (lo + hi);
                    Decision::Halve((lo, m), (m, hi))
                }
            });
            prop_assert!(deepest <= max_depth);
            match stop_at.filter(|&k| k < all.len()) {
                Some(k) => {
                    prop_assert_eq!(stopped, Some(k));
                    prop_assert_eq!(&got[..], &all[..k]);
                }
                None => {
                    prop_assert_eq!(stopped, None);
                    prop_assert_eq!(&got, &all);
                }
            }
        }
    }

    /// The leaves of the halving of `part` (decided by `decided`, or at `max_depth`), in order.
    fn recurse(
        (lo, hi): (f64, f64),
        depth: usize,
        max_depth: usize,
        decided: &dyn Fn(f64, usize) -> bool,
        out: &mut Vec<(f64, f64)>,
    ) {
        if decided(lo, depth) || depth >= max_depth {
            out.push((lo, hi));
        } else {
            let m = 0.5 * (lo + hi);
            recurse((lo, m), depth + 1, max_depth, decided, out);
            recurse((m, hi), depth + 1, max_depth, decided, out);
        }
    }
}
