//! The pieces a boundary is made of, how they end, and the joining of pieces traced apart
//! (on either side of a line the subdivision did not cross) that meet end to start.

use numeric::Rect;
use serde::{Deserialize, Serialize};

/// How close (relative to the domain) an end must lie to the domain's border to end there.
const ON_BORDER: f64 = 1e-9;

/// How a piece of the boundary ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum PieceEnd {
    /// Where the zero set of the function with this index crosses it: the boundary goes on
    /// along that function's zero set.
    Crossing(usize),
    /// On the border of the domain.
    Border,
    /// Inside the domain, where the subdivision did not resolve the zero set (a singular
    /// point or a patch at the size limit): the boundary is not known beyond it.
    Loose,
}

/// One piece of the boundary: part of one function's zero set, with the set on its left.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BoundaryPiece {
    /// The index of the function whose zero set it is.
    pub function: usize,
    /// Its vertices `[t, r]`, on that zero set to rounding; the set lies on the left.
    pub pts: Vec<[f64; 2]>,
    /// How it starts and ends; `None` for a closed loop (first vertex repeated at the end).
    pub ends: Option<[PieceEnd; 2]>,
}

/// How a piece ending at `p` ends there, when no other zero set crosses it: on the border of
/// `dom`, or inside it, [`PieceEnd::Loose`].
pub(crate) fn end_at(dom: Rect, p: [f64; 2]) -> PieceEnd {
    let tol_t = ON_BORDER * dom.t.width();
    let tol_r = ON_BORDER * dom.r.width();
    let on = (p[0] - dom.t.lo).abs() <= tol_t
        || (p[0] - dom.t.hi).abs() <= tol_t
        || (p[1] - dom.r.lo).abs() <= tol_r
        || (p[1] - dom.r.hi).abs() <= tol_r;
    if on {
        PieceEnd::Border
    } else {
        PieceEnd::Loose
    }
}

/// `pieces` with every loose end joined to a loose start of the same function within `tol`
/// (per axis), the nearest first: pieces traced apart on two sides of a line become one, or a
/// closed loop. An end finding no such start stays loose.
pub(crate) fn join_loose(pieces: Vec<BoundaryPiece>, tol: [f64; 2]) -> Vec<BoundaryPiece> {
    let n = pieces.len();
    let loose = |p: &BoundaryPiece, k: usize| p.ends.is_some_and(|e| e[k] == PieceEnd::Loose);
    let first = |i: usize| pieces[i].pts[0];
    let last = |i: usize| pieces[i].pts[pieces[i].pts.len() - 1];
    let gap = |a: [f64; 2], b: [f64; 2]| {
        ((a[0] - b[0]).abs() <= tol[0] && (a[1] - b[1]).abs() <= tol[1])
            .then(|| (a[0] - b[0]).hypot(a[1] - b[1]))
    };
    let mut next: Vec<Option<usize>> = vec![None; n];
    let mut has_prev = vec![false; n];
    for i in (0..n).filter(|&i| loose(&pieces[i], 1)) {
        let found = (0..n)
            .filter(|&j| !has_prev[j] && pieces[j].function == pieces[i].function)
            .filter(|&j| loose(&pieces[j], 0))
            .filter_map(|j| gap(last(i), first(j)).map(|d| (j, d)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((j, _)) = found {
            next[i] = Some(j);
            has_prev[j] = true;
        }
    }
    let mut used = vec![false; n];
    let mut out = Vec::with_capacity(n);
    // Chains from a piece nothing joins onto, then the loops left (every piece in one has a
    // predecessor).
    let starts: Vec<usize> = (0..n)
        .filter(|&i| !has_prev[i])
        .chain((0..n).filter(|&i| has_prev[i]))
        .collect();
    for start in starts {
        if used[start] {
            continue;
        }
        let mut piece = pieces[start].clone();
        used[start] = true;
        let mut at = start;
        // (Each step uses a piece: at most n.)
        while let Some(j) = next[at] {
            if j == start {
                let p0 = piece.pts[0];
                piece.pts.push(p0);
                piece.ends = None;
                break;
            }
            if used[j] {
                break;
            }
            used[j] = true;
            piece.pts.extend_from_slice(&pieces[j].pts[1..]);
            if let (Some(e), Some(f)) = (piece.ends.as_mut(), pieces[j].ends) {
                e[1] = f[1];
            }
            at = j;
        }
        out.push(piece);
    }
    out
}

/// Pieces that retrace another one dropped: the same function's zero set between the same
/// two ends, every vertex of either within `tol` of the other where `map` sends them (the
/// cells on either side of a corner the zero set passes within rounding of each trace that
/// stretch). Two such pieces bound the same stretch twice: the set on the left of both would
/// lie on either side of the one curve.
pub(crate) fn drop_retraced(
    pieces: Vec<BoundaryPiece>,
    tol: f64,
    map: &dyn Fn(f64, f64) -> Option<[f64; 2]>,
) -> Vec<BoundaryPiece> {
    let mapped = |p: &BoundaryPiece| -> Option<Vec<[f64; 2]>> {
        p.pts.iter().map(|q| map(q[0], q[1])).collect()
    };
    let within = |a: &[[f64; 2]], b: &[[f64; 2]]| {
        a.iter().all(|&q| {
            b.windows(2)
                .map(|w| curve::distance_to_segment(q, w[0], w[1]))
                .fold(f64::INFINITY, f64::min)
                <= tol
        })
    };
    // (Mapped only for the few pieces of one function with the same ends.)
    let retraces = |i: usize, j: usize| {
        let (p, q) = (&pieces[i], &pieces[j]);
        if p.function != q.function || p.ends.is_none() || p.ends != q.ends {
            return false;
        }
        let (Some(a), Some(b)) = (mapped(p), mapped(q)) else {
            return false;
        };
        a.len() >= 2 && b.len() >= 2 && within(&a, &b) && within(&b, &a)
    };
    let mut dropped = vec![false; pieces.len()];
    for i in 0..pieces.len() {
        dropped[i] = (0..i).any(|j| !dropped[j] && retraces(i, j));
    }
    pieces
        .into_iter()
        .zip(dropped)
        .filter(|(_, d)| !d)
        .map(|(p, _)| p)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn piece(function: usize, pts: Vec<[f64; 2]>, ends: [PieceEnd; 2]) -> BoundaryPiece {
        BoundaryPiece {
            function,
            pts,
            ends: Some(ends),
        }
    }

    /// Three pieces of one zero set, cut apart at two lines, join in order; a piece of
    /// another function at the same point does not; two halves of a loop close it.
    #[test]
    fn loose_ends_join_end_to_start_by_function() {
        use PieceEnd::{Border, Crossing, Loose};
        let pieces = vec![
            piece(0, vec![[0.5, 0.0], [0.5, 0.5]], [Loose, Loose]),
            piece(0, vec![[0.0, 0.0], [0.5, 0.0]], [Border, Loose]),
            piece(1, vec![[0.5, 0.5], [1.0, 1.0]], [Loose, Crossing(0)]),
            piece(0, vec![[0.5, 0.5 + 1e-12], [0.5, 1.0]], [Loose, Border]),
            piece(2, vec![[2.0, 2.0], [3.0, 2.0]], [Loose, Loose]),
            piece(2, vec![[3.0, 2.0], [2.0, 2.0]], [Loose, Loose]),
        ];
        let joined = join_loose(pieces, [1e-9, 1e-9]);
        assert_eq!(joined.len(), 3, "{joined:?}");
        let zero = joined.iter().find(|p| p.function == 0).unwrap();
        assert_eq!(
            zero.pts,
            vec![[0.0, 0.0], [0.5, 0.0], [0.5, 0.5], [0.5, 1.0]]
        );
        assert_eq!(zero.ends, Some([Border, Border]));
        let one = joined.iter().find(|p| p.function == 1).unwrap();
        assert_eq!(one.ends, Some([Loose, Crossing(0)]));
        let two = joined.iter().find(|p| p.function == 2).unwrap();
        assert_eq!(two.ends, None);
        assert_eq!(two.pts.first(), two.pts.last());
    }

    /// A stretch traced twice (once through a vertex on a cell's line) is kept once; pieces
    /// of one function between the same ends but apart, of two functions, or with other
    /// ends, all stay.
    #[test]
    fn a_retraced_piece_is_kept_once() {
        use PieceEnd::{Border, Crossing};
        let same = |p: &BoundaryPiece| (p.function, p.ends, p.pts.len());
        let identity = |t: f64, r: f64| Some([t, r]);
        let ends = [Crossing(2), Crossing(3)];
        let once = piece(0, vec![[0.0, 0.0], [1.0, 1e-12]], ends);
        let again = piece(0, vec![[0.0, 0.0], [0.5, 1e-11], [1.0, 1e-12]], ends);
        let kept = drop_retraced(vec![once.clone(), again.clone()], 1e-9, &identity);
        assert_eq!(kept.len(), 1);
        assert_eq!(same(&kept[0]), same(&once));
        let apart = piece(0, vec![[0.0, 0.0], [0.5, 1e-6], [1.0, 1e-12]], ends);
        assert_eq!(
            drop_retraced(vec![once.clone(), apart], 1e-9, &identity).len(),
            2
        );
        let other = BoundaryPiece {
            function: 1,
            ..again.clone()
        };
        assert_eq!(
            drop_retraced(vec![once.clone(), other], 1e-9, &identity).len(),
            2
        );
        let bordered = BoundaryPiece {
            ends: Some([Border, Crossing(3)]),
            ..again.clone()
        };
        assert_eq!(
            drop_retraced(vec![once.clone(), bordered], 1e-9, &identity).len(),
            2
        );
        // Measured where the map sends the pairs: stretched a million times, apart.
        let stretched = |t: f64, r: f64| Some([t, 1e6 * r]);
        assert_eq!(drop_retraced(vec![once, again], 1e-9, &stretched).len(), 2);
    }
}
