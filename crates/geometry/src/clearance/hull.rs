//! A piece's verdict against a disk from its control points: an end point inside, the hull
//! outside (box and slab bounds), or a piece straight to within rounding that touches the
//! circle.

use super::pieces::Piece;
use curve::piece_bounds::{box_distance, Errors};
use curve::V2;
use smallvec::SmallVec;

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
    let n = piece.coefs.len() / dim;
    let mut pts: SmallVec<[V2; 16]> = SmallVec::with_capacity(n);
    let (mut w_min, mut mag) = (f64::INFINITY, x.x.abs().max(x.y.abs()));
    for c in piece.coefs.chunks_exact(dim) {
        let w = c[2];
        w_min = w_min.min(w);
        let p = V2::new(c[0] / w, c[1] / w);
        mag = mag.max(p.x.abs()).max(p.y.abs());
        pts.push(p);
    }
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
    let (mut lo, mut hi) = (
        V2::new(f64::INFINITY, f64::INFINITY),
        -V2::new(f64::INFINITY, f64::INFINITY),
    );
    let mut centroid = V2::new(0.0, 0.0);
    for p in &pts {
        lo = V2::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = V2::new(hi.x.max(p.x), hi.y.max(p.y));
        centroid = centroid + *p;
    }
    let boxed = box_distance([lo.x, lo.y, hi.x, hi.y], x);
    // The slab bound: every hull point lies at least this far along the direction from the
    // points' centroid to the centre.
    let towards = x - centroid * (1.0 / n as f64);
    let len = towards.norm();
    let slab = if len > 0.0 {
        let d = towards * (1.0 / len);
        pts.iter()
            .map(|p| (x - *p).dot(d))
            .fold(f64::INFINITY, f64::min)
    } else {
        0.0
    };
    if boxed.max(slab) - room >= r {
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
