//! What the rounding of a segment's Bézier pieces may hide, bounded: the error of each
//! piece's homogeneous coefficients, the room it gives its Euclidean control points, and the
//! box each piece lies in. The profile keeps these boxes; the disk tests of
//! `geometry`'s clearance and nearest-point searches and the box hierarchy read them.

use crate::geom::V2;
use crate::segment::Segment;
use bspline::Piecewise;
use numeric::rounding::ulps;

/// Units of rounding allowed per comparison: the Euclidean points (a division), the bounds
/// (a few products and sums) and one more per halving of the piece.
pub const CLEARANCE_ROUNDING_ULPS: f64 = 16.0;

/// Bounds on the error of a piece's homogeneous coefficients.
#[derive(Clone, Copy)]
pub struct Errors {
    /// Of the points' coordinates `X, Y`.
    pub point: f64,
    /// Of the weights.
    pub weight: f64,
}

impl Errors {
    /// What a Euclidean control point `X / w` (coordinates up to `mag`, weights at least
    /// `w`, of a piece halved `depth` times) may be off by: `X / w` moves by
    /// (δX + |X / w| δw) / w for errors δX, δw ≤ w / 2 of its coefficients (to first order;
    /// twice that covers the rest), and the arithmetic's rounding.
    pub fn room(self, w: f64, mag: f64, depth: usize) -> f64 {
        4.0 * (self.point + mag * self.weight) / w
            + ulps(CLEARANCE_ROUNDING_ULPS + depth as f64) * mag
    }
}

/// Bounds on the error of piece `k`'s homogeneous coefficients: of the points' `X, Y` (with
/// `given` added: the curve's own, the rounding of `w·x`) and of the weights.
pub fn coefficient_error(pieces: &Piecewise, k: usize, given: f64) -> Errors {
    let e = pieces.errors(k);
    Errors {
        point: e[0].max(e[1]) + given,
        weight: e[2],
    }
}

/// Per Bézier piece of `seg`, the box of its Euclidean control points grown by the room their
/// rounding may take ([`Errors::room`]): the piece lies in it, so a disk farther from it
/// holds no point of the piece. Unbounded where a weight may not be positive.
pub(crate) fn piece_boxes(seg: &Segment) -> Vec<[f64; 4]> {
    let pieces = seg.curve().bezier_pieces();
    let given = seg.curve().curve().coefficient_error();
    let dim = pieces.dim();
    (0..pieces.pieces())
        .map(|k| {
            let err = coefficient_error(pieces, k, given);
            let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
            let mut w_min = f64::INFINITY;
            for c in pieces.piece(k).chunks_exact(dim) {
                w_min = w_min.min(c[2]);
                for j in 0..2 {
                    let v = c[j] / c[2];
                    lo[j] = lo[j].min(v);
                    hi[j] = hi[j].max(v);
                }
            }
            if w_min.is_nan()
                || w_min <= 2.0 * err.weight
                || lo.iter().chain(&hi).any(|v| v.is_nan())
            {
                return [
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::INFINITY,
                ];
            }
            let mag = lo.iter().chain(&hi).fold(0.0f64, |m, v| m.max(v.abs()));
            // (The rounding of a box's distance from a centre, a few units of the centre's
            // and the radius's size, is allowed for where the box is used.)
            let room = 2.0 * err.room(w_min, mag, 0);
            [lo[0] - room, lo[1] - room, hi[0] + room, hi[1] + room]
        })
        .collect()
}

/// A lower bound on the distance from `x` to a box `[lo x, lo y, hi x, hi y]`.
pub fn box_distance(b: [f64; 4], x: V2) -> f64 {
    let dx = (b[0] - x.x).max(x.x - b[2]).max(0.0);
    let dy = (b[1] - x.y).max(x.y - b[3]).max(0.0);
    // (The norm rounds by up to two units either way, a square root of a sum of squares:
    // four off keeps it below the true distance. The disk tests call this for every box in
    // reach, and hypot costs several times more.)
    V2::new(dx, dy).norm() * (1.0 - ulps(4.0))
}
