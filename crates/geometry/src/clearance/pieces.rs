//! The Bézier pieces a disk test halves: a piece under test, the stack of those still to
//! test (their coefficients in one buffer), and the halving by de Casteljau's algorithm.

/// A Bézier piece under test: its homogeneous control points `(X, Y, w)`, its interval of
/// the segment's parameter, and how many halvings made it.
pub(super) struct Piece<'a> {
    pub(super) coefs: &'a [f64],
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) depth: usize,
}

/// The pieces still to test, last in first out, their coefficients in one buffer: a disk
/// test halves tens of pieces, and an allocation for each had been a fifth of a medial
/// axis' time.
#[derive(Default)]
pub(super) struct Pending {
    coefs: Vec<f64>,
    /// Per piece: its interval and depth.
    spans: Vec<(f64, f64, usize)>,
    /// Coefficients per piece (the same for all pieces of a segment).
    len: usize,
}

impl Pending {
    pub(super) fn push(&mut self, coefs: &[f64], lo: f64, hi: f64, depth: usize) {
        self.len = coefs.len();
        self.coefs.extend_from_slice(coefs);
        self.spans.push((lo, hi, depth));
    }

    /// Moves the last piece's coefficients into `into`; its interval and depth.
    pub(super) fn pop(&mut self, into: &mut Vec<f64>) -> Option<(f64, f64, usize)> {
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
pub(super) fn halve(piece: &Piece<'_>, dim: usize, work: &mut Vec<f64>, pending: &mut Pending) {
    let len = piece.coefs.len();
    let n = len / dim;
    work.clear();
    work.extend_from_slice(piece.coefs);
    let right = pending.coefs.len();
    let left = right + len;
    pending.coefs.resize(left + len, 0.0);
    let out = &mut pending.coefs;
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
    let mid = 0.5 * (piece.lo + piece.hi);
    let depth = piece.depth + 1;
    pending.len = len;
    pending.spans.push((mid, piece.hi, depth));
    pending.spans.push((piece.lo, mid, depth));
}
