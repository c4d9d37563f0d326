//! A piece's verdict against a disk from its control points: an end point inside, the hull
//! outside (box and slab bounds), or a piece straight to within rounding that touches the
//! circle.

use crate::pieces::{hull_distance, ControlPoints, Piece};
use curve::piece_bounds::Errors;
use curve::V2;

pub(super) enum Verdict {
    Outside,
    Inside {
        at_end: bool,
        distance: f64,
    },
    Split,
    /// Within rounding of the circle.
    Undecided,
}

/// The piece's verdict against the disk of centre `x` and radius `r`; `err` bounds the error
/// of its homogeneous coefficients.
pub(super) fn test_piece(piece: &Piece<'_>, dim: usize, x: V2, r: f64, err: Errors) -> Verdict {
    let ControlPoints { pts, w_min, mag } = ControlPoints::of(piece.coefs, dim, x);
    let n = pts.len();
    if w_min.is_nan() || w_min <= 2.0 * err.weight {
        // A weight that may not be positive: the hull says nothing.
        return Verdict::Split;
    }
    let room = err.room(w_min, mag, piece.depth);
    // The end points lie on the curve: one inside the disk, past all rounding, decides.
    for (at_end, p) in [(false, pts[0]), (true, pts[n - 1])] {
        let d = (p - x).norm();
        if d + room < r {
            return Verdict::Inside {
                at_end,
                distance: d,
            };
        }
    }
    if hull_distance(&pts, x) - room >= r {
        return Verdict::Outside;
    }
    // A piece straight to within rounding whose chord does not pass clearly inside the disk
    // is where the circle touches the curve to within rounding: halving it again would only
    // make more such pieces.
    let chord = pts[n - 1] - pts[0];
    let len = chord.norm();
    if len > 0.0 {
        let sag = pts
            .iter()
            .map(|p| chord.cross(*p - pts[0]).abs() / len)
            .fold(0.0, f64::max);
        let along = ((x - pts[0]).dot(chord) / (len * len)).clamp(0.0, 1.0);
        let to_chord = (pts[0] + chord * along - x).norm();
        if sag <= room {
            // Within `sag` of its chord: as far as the chord, to that and rounding.
            if to_chord - sag - room >= r {
                return Verdict::Outside;
            }
            if to_chord + sag + room >= r {
                return Verdict::Undecided;
            }
        }
    }
    Verdict::Split
}
