//! How arc ends are linked (to a partner end, to a singular point, through a crossing) and
//! the polylines that following the links gives: the bookkeeping that the matching rules of
//! `assemble` only fill in.

use crate::extract::Arc;

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Link {
    Free,
    End(usize),
    Node(usize),
    /// Continues through singular point `.1` into end `.0` (the opposite arm of a crossing).
    Via(usize, usize),
}

/// Distance from a singular point (relative to the domain) at which an arm's direction is
/// measured: far enough that the vertex positions (noisy like rounding / distance near a
/// crossing, where |∇F| vanishes) give the angle to ~1e-8, near enough to be a tangent.
const ARM_REACH: f64 = 1e-4;

/// Unit direction (in coordinates scaled by the domain) from `node` to the chain of arcs
/// leaving it through end `e`, measured at about [`ARM_REACH`] or at the chain's end.
pub(super) fn arm_direction(
    arcs: &[Arc],
    link: &[Link],
    e: usize,
    node: [f64; 2],
    ext: [f64; 2],
) -> [f64; 2] {
    let rel = |q: [f64; 2]| [(q[0] - node[0]) / ext[0], (q[1] - node[1]) / ext[1]];
    let mut entry = e;
    let mut far = rel(arcs[e / 2].ends[e % 2].p);
    // Bounded by the number of arcs (and in practice by the reach).
    'chain: for _ in 0..arcs.len() {
        let a = &arcs[entry / 2].pts;
        let pts: Box<dyn Iterator<Item = &[f64; 2]>> = if entry.is_multiple_of(2) {
            Box::new(a.iter())
        } else {
            Box::new(a.iter().rev())
        };
        for q in pts {
            far = rel(*q);
            if far[0].hypot(far[1]) >= ARM_REACH {
                break 'chain;
            }
        }
        match link[entry ^ 1] {
            Link::End(next) if next / 2 != e / 2 => entry = next,
            _ => break,
        }
    }
    let len = far[0].hypot(far[1]);
    if len > 0.0 {
        [far[0] / len, far[1] / len]
    } else {
        [0.0, 0.0]
    }
}

/// Joins ends of `ids` in pairs: each, in turn, with the closest still unpaired later one
/// that `close` accepts (`close` gives the distance). Returns which were paired.
///
/// `close` accepts no two ends whose `key`s differ by more than `reach`: only those within it
/// are tried (the ends sorted by key), so that tens of thousands of ends, as along two zero
/// sets nearly coinciding over a whole cell, are paired in `n log n`, not `n²`.
pub(super) fn pair_closest(
    ids: &[usize],
    close: &dyn Fn(usize, usize) -> Option<f64>,
    key: &dyn Fn(usize) -> f64,
    reach: f64,
    link: &mut [Link],
) -> Vec<bool> {
    let keys: Vec<f64> = ids.iter().map(|&id| key(id)).collect();
    let mut by_key: Vec<usize> = (0..ids.len()).collect();
    by_key.sort_by(|&a, &b| keys[a].total_cmp(&keys[b]));
    let sorted: Vec<f64> = by_key.iter().map(|&k| keys[k]).collect();
    let mut paired = vec![false; ids.len()];
    for x in 0..ids.len() {
        if paired[x] {
            continue;
        }
        let lo = sorted.partition_point(|&k| k < keys[x] - reach);
        let hi = sorted.partition_point(|&k| k <= keys[x] + reach);
        let mut best = None::<(f64, usize)>;
        for &y in &by_key[lo..hi] {
            if y <= x || paired[y] {
                continue;
            }
            if let Some(d) = close(ids[x], ids[y]) {
                // (Ties go to the earlier end, as in `ids`' order.)
                if best.is_none_or(|b| d < b.0 || (d == b.0 && y < b.1)) {
                    best = Some((d, y));
                }
            }
        }
        if let Some((_, y)) = best {
            paired[x] = true;
            paired[y] = true;
            link[ids[x]] = Link::End(ids[y]);
            link[ids[y]] = Link::End(ids[x]);
        }
    }
    paired
}

/// Follows links from free or node ends, then closes the remaining cycles.
pub(super) fn walk(
    arcs: &[Arc],
    link: &[Link],
    nodes: &[[f64; 2]],
    dropped: Vec<bool>,
) -> Vec<(Vec<[f64; 2]>, bool)> {
    let mut seen = dropped;
    let mut out = Vec::new();
    let follow = |start: usize, seen: &mut Vec<bool>| -> (Vec<[f64; 2]>, bool) {
        let mut pts: Vec<[f64; 2]> = Vec::new();
        if let Link::Node(n) = link[start] {
            pts.push(nodes[n]);
        }
        let mut entry = start;
        let mut closed = false;
        let mut shared_joint = !pts.is_empty();
        // Each step consumes one unseen arc, so this ends after at most arcs.len() steps.
        loop {
            let i = entry / 2;
            seen[i] = true;
            let a = &arcs[i].pts;
            let iter: Box<dyn Iterator<Item = &[f64; 2]>> = if entry.is_multiple_of(2) {
                Box::new(a.iter())
            } else {
                Box::new(a.iter().rev())
            };
            for (k, q) in iter.enumerate() {
                if k == 0 && shared_joint {
                    continue; // the joint was already added from the previous arc
                }
                pts.push(*q);
            }
            let exit = entry ^ 1;
            let (next, via) = match link[exit] {
                Link::Free => break,
                Link::Node(n) => {
                    pts.push(nodes[n]);
                    break;
                }
                Link::End(e) => (e, None),
                Link::Via(e, n) => (e, Some(n)),
            };
            if let Some(n) = via {
                pts.push(nodes[n]);
            }
            shared_joint = via.is_none();
            if next / 2 == start / 2 {
                closed = true;
                if via.is_some() {
                    // Closed through a singular point: the node is the last vertex, the
                    // first arc's start follows it.
                    if let Some(&f) = pts.first() {
                        pts.push(f);
                    }
                }
                break;
            }
            if seen[next / 2] {
                break;
            }
            entry = next;
        }
        if closed && shared_joint {
            // The last arc ends where the first began: make the loop exactly closed.
            if let Some(&f) = pts.first() {
                if let Some(l) = pts.last_mut() {
                    *l = f;
                }
            }
        }
        (pts, closed)
    };
    for i in 0..arcs.len() {
        for j in 0..2 {
            let id = 2 * i + j;
            if !seen[i] && matches!(link[id], Link::Free | Link::Node(_)) {
                out.push(follow(id, &mut seen));
            }
        }
    }
    for i in 0..arcs.len() {
        if !seen[i] {
            out.push(follow(2 * i, &mut seen));
        }
    }
    out
}
