//! Chaining: the drawing's open pieces joined end to end into chains, with branch points and
//! near-miss gaps refused.

use super::pieces::{DrawingPiece, Tolerance};
use super::Failure;
use crate::io::drawing::Chain;
use crate::io::Problem;
use curve::{FillRule, Segment, V2};
use std::collections::VecDeque;

/// Open ends are a gap only when also nearer than this, relative to the size of the chains
/// they end: an outline that misses closing by a thousandth of itself is a gap; a short line
/// whose two ends are its whole length apart is not.
pub(super) const NEAR_MISS_OWN: f64 = 1e-3;

// ---------------------------------------------------------------------------------------------
// Chaining.

/// One end of an open piece: which piece, and whether it is its end (or its start).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct End {
    piece: usize,
    at_end: bool,
}

/// A chain of open pieces in order, each taken forwards (`true`) or reversed.
type Run = VecDeque<(usize, bool)>;

/// A grid of square cells over points: their cell keys, sorted (no hashing: the work is
/// `O(n log n)` whatever the coordinates).
struct Grid {
    cell: f64,
    /// `(cell key, point index)`, sorted.
    keys: Vec<((i64, i64), usize)>,
}

impl Grid {
    fn new(cell: f64, points: &[V2]) -> Self {
        let mut g = Self {
            cell,
            keys: Vec::with_capacity(points.len()),
        };
        g.keys = points
            .iter()
            .enumerate()
            .map(|(i, &p)| (g.key(p), i))
            .collect();
        g.keys.sort_unstable();
        g
    }

    fn key(&self, p: V2) -> (i64, i64) {
        // (Saturating casts: a key is only a place to look, every match is measured.)
        (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        )
    }

    /// The points of each cell that holds more than `most`.
    fn crowded(&self, most: usize) -> Option<Vec<usize>> {
        self.keys
            .chunk_by(|a, b| a.0 == b.0)
            .find(|run| run.len() > most)
            .map(|run| run.iter().map(|&(_, i)| i).collect())
    }

    /// The points in the cells within two of `p`'s (all points within `2 · cell` of `p`).
    fn around(&self, p: V2) -> impl Iterator<Item = usize> + '_ {
        let (kx, ky) = self.key(p);
        (-2i64..=2).flat_map(move |dx| {
            let row = kx.saturating_add(dx);
            let (lo, hi) = ((row, ky.saturating_sub(2)), (row, ky.saturating_add(2)));
            let a = self.keys.partition_point(|(k, _)| *k < lo);
            let b = self.keys.partition_point(|(k, _)| *k <= hi);
            self.keys
                .get(a..b.max(a))
                .unwrap_or_default()
                .iter()
                .map(|&(_, i)| i)
        })
    }
}

/// The box `[x0, y0, x1, y1]` of the segments' control points.
fn box_of(segments: &[Segment]) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in segments.iter().flat_map(|s| s.curve().control_points()) {
        b = [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ];
    }
    b
}

fn point_text(p: V2) -> String {
    format!("({}, {})", p.x, p.y)
}

/// The chains of the drawing's pieces (see the module documentation).
pub(super) fn chain_pieces(
    pieces: Vec<Option<DrawingPiece>>,
    tol: &Tolerance,
) -> Result<Vec<Chain>, Failure> {
    let mut chains: Vec<(usize, Chain)> = Vec::new();
    let mut open: Vec<DrawingPiece> = Vec::new();
    for p in pieces.into_iter().flatten() {
        match p.closed {
            Some(false) => open.push(p),
            closed => chains.push((
                p.order,
                Chain {
                    name: p.name,
                    segments: p.segments,
                    closed,
                    group: 0,
                    rule: FillRule::EvenOdd,
                },
            )),
        }
    }
    // End 2k is piece k's start, 2k + 1 its end.
    let points: Vec<V2> = open.iter().flat_map(|p| [p.start, p.end]).collect();
    let end = |i: usize| End {
        piece: i / 2,
        at_end: i % 2 == 1,
    };
    let name_of = |i: usize| open.get(i / 2).map_or("", |p| p.name.as_str());

    // Cells of half the tolerance: two ends in one cell are within 0.71 of it, so a third end
    // in a cell is a branch, and every cell holds at most two.
    let branch = |ids: &[usize], at: V2| -> Failure {
        let mut ids = ids.to_vec();
        ids.sort_unstable();
        let names: Vec<&str> = ids.iter().map(|&i| name_of(i)).collect();
        (
            name_of(ids.first().copied().unwrap_or(0)).to_string(),
            Problem::Geometry(format!(
                "a branch point: {} meet at {} (a profile joins two entities at each point)",
                names.join(", "),
                point_text(at)
            )),
        )
    };
    let grid = Grid::new(tol.join * 0.5, &points);
    if let Some(ids) = grid.crowded(2) {
        let at = ids.first().and_then(|&i| points.get(i)).copied();
        return Err(branch(&ids, at.unwrap_or_default()));
    }
    let mut partner: Vec<Option<usize>> = vec![None; points.len()];
    for (i, &p) in points.iter().enumerate() {
        let mut found: Vec<usize> = grid
            .around(p)
            .filter(|&j| j != i && j / 2 != i / 2)
            .filter(|&j| points.get(j).is_some_and(|&q| (q - p).norm() <= tol.join))
            .take(2)
            .collect();
        match found.len() {
            0 => {}
            1 => {
                if let (Some(slot), Some(&j)) = (partner.get_mut(i), found.first()) {
                    *slot = Some(j);
                }
            }
            _ => {
                found.push(i);
                return Err(branch(&found, p));
            }
        }
    }

    let mut used = vec![false; open.len()];
    let mut loose_chains: Vec<(usize, Run, bool)> = Vec::new();
    for start in 0..open.len() {
        if used.get(start) != Some(&false) {
            continue;
        }
        if let Some(u) = used.get_mut(start) {
            *u = true;
        }
        let mut run: Run = VecDeque::from([(start, true)]);
        let mut closed = false;
        // Forwards from the start piece's end.
        let mut tip = 2 * start + 1;
        for _ in 0..open.len() {
            let Some(j) = partner.get(tip).copied().flatten() else {
                break;
            };
            if j == 2 * start {
                closed = true;
                break;
            }
            let e = end(j);
            if used.get(e.piece) != Some(&false) {
                break;
            }
            if let Some(u) = used.get_mut(e.piece) {
                *u = true;
            }
            // Entered at its start: taken forwards, leaving at its end; else reversed.
            run.push_back((e.piece, !e.at_end));
            tip = if e.at_end {
                2 * e.piece
            } else {
                2 * e.piece + 1
            };
        }
        if !closed {
            // Backwards from the start piece's start.
            let mut tip = 2 * start;
            for _ in 0..open.len() {
                let Some(j) = partner.get(tip).copied().flatten() else {
                    break;
                };
                let e = end(j);
                if used.get(e.piece) != Some(&false) {
                    break;
                }
                if let Some(u) = used.get_mut(e.piece) {
                    *u = true;
                }
                // Met at its end: taken forwards, arriving at the chain's start; else reversed.
                run.push_front((e.piece, e.at_end));
                tip = if e.at_end {
                    2 * e.piece
                } else {
                    2 * e.piece + 1
                };
            }
        }
        loose_chains.push((start, run, closed));
    }

    // Open ends nearer than the near-miss distance: a gap. (Each chain's own size bounds it
    // too: a short open line's two ends are not a gap.)
    let mut free: Vec<(usize, V2, f64)> = Vec::new();
    for (_, run, closed) in &loose_chains {
        if *closed {
            continue;
        }
        let b = run
            .iter()
            .filter_map(|&(k, _)| open.get(k).map(|p| box_of(&p.segments)))
            .fold(
                [
                    f64::INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                ],
                curve::box_union,
            );
        let size = (b[2] - b[0]).hypot(b[3] - b[1]);
        if let (Some(&(first, fwd_first)), Some(&(last, fwd_last))) = (run.front(), run.back()) {
            let start_end = if fwd_first { 2 * first } else { 2 * first + 1 };
            let last_end = if fwd_last { 2 * last + 1 } else { 2 * last };
            for i in [start_end, last_end] {
                if let Some(&p) = points.get(i) {
                    free.push((i, p, size));
                }
            }
        }
    }
    let free_points: Vec<V2> = free.iter().map(|&(_, p, _)| p).collect();
    let near = Grid::new(tol.near * 0.5, &free_points);
    for (k, &(i, p, own)) in free.iter().enumerate() {
        let other = near
            .around(p)
            .filter(|&m| m != k)
            .filter_map(|m| free.get(m))
            .find(|(_, q, other)| (*q - p).norm() <= tol.near.min(NEAR_MISS_OWN * own.min(*other)))
            .map(|&(j, q, _)| (j, q));
        if let Some((j, q)) = other {
            let (a, b) = if i < j { (i, j) } else { (j, i) };
            let (pa, pb) = if i < j { (p, q) } else { (q, p) };
            let gap = (pb - pa).norm();
            let which = |x: usize| if x % 2 == 1 { "end" } else { "start" };
            return Err((
                name_of(a).to_string(),
                Problem::Geometry(format!(
                    "a gap of {gap:e} between the {} of {} at {} and the {} of {} at {}, \
                     beyond the drawing's tolerance of {:e}: the outline does not close",
                    which(a),
                    name_of(a),
                    point_text(pa),
                    which(b),
                    name_of(b),
                    point_text(pb),
                    tol.join,
                )),
            ));
        }
    }

    // (Each piece is in one chain: its segments move there.)
    let mut parts: Vec<(usize, String, Vec<Segment>)> = open
        .into_iter()
        .map(|p| (p.order, p.name, p.segments))
        .collect();
    for (start, run, closed) in loose_chains {
        let mut segments = Vec::new();
        for (k, forwards) in run {
            let Some((_, name, piece)) = parts.get_mut(k) else {
                continue;
            };
            let piece = std::mem::take(piece);
            if forwards {
                segments.extend(piece);
            } else {
                for s in piece.iter().rev() {
                    segments.push(
                        s.reversed()
                            .map_err(|e| (name.clone(), Problem::Geometry(e.to_string())))?,
                    );
                }
            }
        }
        let Some((order, name, _)) = parts.get(start) else {
            continue;
        };
        chains.push((
            *order,
            Chain {
                name: name.clone(),
                segments,
                closed: closed.then_some(true),
                group: 0,
                rule: FillRule::EvenOdd,
            },
        ));
    }
    chains.sort_by_key(|(order, _)| *order);
    Ok(chains.into_iter().map(|(_, c)| c).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A piece of one segment.
    fn piece(order: usize, seg: Segment) -> Option<DrawingPiece> {
        Some(DrawingPiece {
            order,
            name: format!("LINE #{}", order + 1),
            start: seg.start(),
            end: seg.end(),
            segments: vec![seg],
            closed: Some(false),
        })
    }

    fn tol(join: f64) -> Tolerance {
        Tolerance {
            join,
            near: join * 1e5,
        }
    }

    #[test]
    fn chaining_reverses_pieces_and_closes() {
        let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
        let pieces = vec![
            piece(0, l([0.0, 0.0], [1.0, 0.0])),
            piece(1, l([0.0, 1.0], [1.0, 1.0])), // backwards
            piece(2, l([1.0, 0.0], [1.0, 1.0])),
            piece(3, l([0.0, 0.0], [0.0, 1.0])), // backwards
        ];
        let chains = chain_pieces(pieces, &tol(1e-9)).unwrap();
        assert_eq!(chains.len(), 1);
        let c = &chains[0];
        assert_eq!((c.name.as_str(), c.closed), ("LINE #1", Some(true)));
        let ends: Vec<[f64; 2]> = c.segments.iter().map(|s| s.start().arr()).collect();
        assert_eq!(ends, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        // An open chain grows at both ends of its first piece.
        let pieces = vec![
            piece(0, l([1.0, 0.0], [2.0, 0.0])),
            piece(1, l([0.0, 0.0], [1.0, 0.0])),
            piece(2, l([3.0, 0.0], [2.0, 0.0])),
        ];
        let chains = chain_pieces(pieces, &tol(1e-9)).unwrap();
        assert_eq!(chains.len(), 1);
        assert_eq!(chains[0].closed, None);
        assert_eq!(chains[0].segments[0].start().arr(), [0.0, 0.0]);
        assert_eq!(chains[0].segments[2].end().arr(), [3.0, 0.0]);
    }

    #[test]
    fn three_ends_at_a_point_are_a_branch() {
        let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
        // Three ends in one cell of the grid, and three ends in neighbouring cells.
        for eps in [0.0, 0.9e-9] {
            let pieces = vec![
                piece(0, l([0.0, 0.0], [1.0, 0.0])),
                piece(1, l([1.0 + eps, 0.0], [2.0, 0.0])),
                piece(2, l([1.0, eps], [1.0, 1.0])),
            ];
            let (field, p) = chain_pieces(pieces, &tol(1e-9)).unwrap_err();
            assert_eq!(field, "LINE #1");
            assert!(p.to_string().contains("branch"), "{p}");
        }
    }

    #[test]
    fn near_misses_are_gaps_and_far_ends_are_open() {
        let l = |a: [f64; 2], b: [f64; 2]| Segment::line(a, b).unwrap();
        let open = || {
            vec![
                piece(0, l([0.0, 0.0], [1.0, 0.0])),
                piece(1, l([1.0, 0.0], [1.0, 1.0])),
                piece(2, l([1.0, 1.0], [0.0, 1e-6])),
            ]
        };
        let (field, p) = chain_pieces(open(), &tol(1e-9)).unwrap_err();
        assert_eq!(field, "LINE #1");
        assert!(p.to_string().contains("gap of 1e-6"), "{p}");
        // With a looser near-miss distance below the gap: an open chain.
        let t = Tolerance {
            join: 1e-9,
            near: 1e-7,
        };
        let chains = chain_pieces(open(), &t).unwrap();
        assert_eq!(chains.len(), 1);
        assert_eq!(chains[0].closed, None);
    }
}
