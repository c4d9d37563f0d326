//! The Bézier pieces the searches halve: a piece under test, the stack of those still to
//! test (their coefficients in one buffer), the halving by de Casteljau's algorithm, and the
//! bound a piece's control points give on its distance from a point.

use curve::piece_bounds::box_distance;
use curve::V2;
use smallvec::SmallVec;

/// A Bézier piece under test: its homogeneous control points `(X, Y, w)`, its interval of
/// the segment's parameter, and how many halvings made it.
pub(crate) struct Piece<'a> {
    pub(crate) coefs: &'a [f64],
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    pub(crate) depth: usize,
}

/// The pieces still to test, last in first out, their coefficients in one buffer: a disk
/// test halves tens of pieces, and an allocation for each had been a fifth of a medial
/// axis' time.
#[derive(Default)]
pub(crate) struct Pending {
    coefs: Vec<f64>,
    /// Per piece: its interval and depth.
    spans: Vec<(f64, f64, usize)>,
    /// Coefficients per piece (the same for all pieces of a segment).
    len: usize,
}

impl Pending {
    pub(crate) fn push(&mut self, coefs: &[f64], lo: f64, hi: f64, depth: usize) {
        self.len = coefs.len();
        self.coefs.extend_from_slice(coefs);
        self.spans.push((lo, hi, depth));
    }

    /// Moves the last piece's coefficients into `into`; its interval and depth.
    pub(crate) fn pop(&mut self, into: &mut Vec<f64>) -> Option<(f64, f64, usize)> {
        let span = self.spans.pop()?;
        let start = self.coefs.len() - self.len;
        into.clear();
        into.extend_from_slice(&self.coefs[start..]);
        self.coefs.truncate(start);
        Some(span)
    }
}

/// The two halves of a piece by de Casteljau's algorithm on its homogeneous coefficients,
/// pushed onto `pending`, the first half last (it is tested first); `work` is scratch.
pub(crate) fn halve(piece: &Piece<'_>, dim: usize, work: &mut Vec<f64>, pending: &mut Pending) {
    append_halves(piece.coefs, dim, work, &mut pending.coefs);
    let mid = 0.5 * (piece.lo + piece.hi);
    let depth = piece.depth + 1;
    pending.len = piece.coefs.len();
    pending.spans.push((mid, piece.hi, depth));
    pending.spans.push((piece.lo, mid, depth));
}

/// The two halves of the Bézier piece `coefs` (`dim` numbers per control point) by de
/// Casteljau's algorithm at its middle, appended to `out`: the second half, then the
/// first; `work` is scratch.
#[inline]
pub(crate) fn append_halves(coefs: &[f64], dim: usize, work: &mut Vec<f64>, out: &mut Vec<f64>) {
    let len = coefs.len();
    let n = len / dim;
    work.clear();
    work.extend_from_slice(coefs);
    let right = out.len();
    let left = right + len;
    out.resize(left + len, 0.0);
    out[left..left + dim].copy_from_slice(&work[..dim]);
    out[right + (n - 1) * dim..left].copy_from_slice(&work[(n - 1) * dim..]);
    for level in 1..n {
        for j in 0..n - level {
            for c in 0..dim {
                work[j * dim + c] = 0.5 * (work[j * dim + c] + work[(j + 1) * dim + c]);
            }
        }
        let l = left + level * dim;
        out[l..l + dim].copy_from_slice(&work[..dim]);
        let k = (n - 1 - level) * dim;
        out[right + k..right + k + dim].copy_from_slice(&work[k..k + dim]);
    }
}

/// A lower bound on the distance from `x` to the convex hull of `pts` (a rational Bézier
/// piece with positive weights lies in the hull of its Euclidean control points): the larger
/// of the distance to the points' box and the slab bound, the least extent of the points
/// towards `x` from their centroid, which tightens quadratically as pieces shrink about the
/// point of the curve nearest `x` (the box alone only linearly). Rounding is the caller's to
/// allow for.
pub(crate) fn hull_distance(pts: &[V2], x: V2) -> f64 {
    let (mut lo, mut hi) = (
        V2::new(f64::INFINITY, f64::INFINITY),
        -V2::new(f64::INFINITY, f64::INFINITY),
    );
    let mut centroid = V2::new(0.0, 0.0);
    for p in pts {
        lo = V2::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = V2::new(hi.x.max(p.x), hi.y.max(p.y));
        centroid = centroid + *p;
    }
    let boxed = box_distance([lo.x, lo.y, hi.x, hi.y], x);
    let towards = x - centroid * (1.0 / pts.len() as f64);
    let len = towards.norm();
    let slab = if len > 0.0 {
        let d = towards * (1.0 / len);
        pts.iter()
            .map(|p| (x - *p).dot(d))
            .fold(f64::INFINITY, f64::min)
    } else {
        0.0
    };
    boxed.max(slab)
}

/// A piece's Euclidean control points `X / w`, with the least weight and the largest
/// coordinate among them and the point `x` they are measured from (the scale of their
/// rounding).
pub(crate) struct ControlPoints {
    pub(crate) pts: SmallVec<[V2; 16]>,
    pub(crate) w_min: f64,
    pub(crate) mag: f64,
}

impl ControlPoints {
    /// The points of the homogeneous coefficients `coefs` (`dim` per point, the weight
    /// third), seen from `x`.
    pub(crate) fn of(coefs: &[f64], dim: usize, x: V2) -> Self {
        let mut pts: SmallVec<[V2; 16]> = SmallVec::with_capacity(coefs.len() / dim);
        let (mut w_min, mut mag) = (f64::INFINITY, x.x.abs().max(x.y.abs()));
        for c in coefs.chunks_exact(dim) {
            let w = c[2];
            w_min = w_min.min(w);
            let p = V2::new(c[0] / w, c[1] / w);
            mag = mag.max(p.x.abs()).max(p.y.abs());
            pts.push(p);
        }
        Self { pts, w_min, mag }
    }
}
