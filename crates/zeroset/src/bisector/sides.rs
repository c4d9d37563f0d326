//! Bisector points sought on one side of each curve only (the medial axis of a region wants
//! those on its inner side): a patch of the zero set is skipped where a foot's other point
//! is proven on the wrong side of its tangent, for every pair of parameters in it.
//!
//! A bisector point `P = C1(t) + λ N1(t)` on the normal `N1` of the left side lies on the
//! left (`λ > 0`) exactly where `C1'(t) × (C2(r) − C1(t)) > 0`: the sign of `λ` is that of
//! `⟨N1, C2 − C1⟩`. Over a patch the tangent lies in the hull of the piece's hodograph
//! points and the chord in the differences of the two pieces' hulls; the cross product is
//! bilinear, so its largest value there is at a pair of those points.

use crate::patch::Patch;
use bspline::{Piecewise, Rational};
use smallvec::SmallVec;

/// Control points of a piece, in place up to degree 7.
type Points = SmallVec<[[f64; 2]; 8]>;

/// A side of a curve, as it runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// To the left of the direction of travel.
    Left,
    /// To the right.
    Right,
}

/// Below this share of the products' size a cross product is not trusted negative.
const CROSS_ROUNDING: f64 = 1e-12;

/// The two curves' Bézier pieces and the wanted side of each.
pub(super) struct SideFilter<'a> {
    pieces: [&'a Piecewise; 2],
    /// +1 for the left, −1 for the right.
    signs: [f64; 2],
}

impl<'a> SideFilter<'a> {
    /// For the curves `curves` with homogeneous Bézier pieces `pieces` (the ones their
    /// points are evaluated on); `None` for rational curves (their hodographs are not the
    /// hull's differences).
    pub(super) fn new(
        curves: [&Rational; 2],
        pieces: [&'a Piecewise; 2],
        sides: [Side; 2],
    ) -> Option<Self> {
        if curves.iter().any(|c| c.is_rational()) {
            return None;
        }
        let sign = |s: Side| if s == Side::Left { 1.0 } else { -1.0 };
        Some(Self {
            pieces,
            signs: [sign(sides[0]), sign(sides[1])],
        })
    }

    /// False where no bisector point with feet in the patch is on the wanted sides.
    pub(super) fn may_hold(&self, p: &Patch) -> bool {
        let (a, b) = (
            self.control_points(0, p.t0, p.t1),
            self.control_points(1, p.r0, p.r1),
        );
        !(wrong_side(&a, &b, self.signs[0]) || wrong_side(&b, &a, self.signs[1]))
    }

    /// The Euclidean control points of curve `k` over `[lo, hi]` (within one piece).
    fn control_points(&self, k: usize, lo: f64, hi: f64) -> Points {
        let pieces = self.pieces[k];
        let i = pieces.piece_at(0.5 * (lo + hi));
        let (a, b) = pieces.piece_span(i);
        let mut pts: Points = pieces
            .piece(i)
            .chunks_exact(3)
            .map(|c| [c[0] / c[2], c[1] / c[2]])
            .collect();
        let (s0, s1) = ((lo - a) / (b - a), (hi - a) / (b - a));
        if s1 < 1.0 {
            split_keep_left(&mut pts, s1);
        }
        if s0 > 0.0 {
            split_keep_right(&mut pts, s0 / s1);
        }
        pts
    }
}

/// Whether every point of the curve with control points `own` has every point of `other` on
/// the side opposite to `sign` of its tangent: for each hodograph point `h`, the cross
/// product `h × (q − p)` is largest with `h × q` largest over `other` and `h × p` least
/// over `own`.
fn wrong_side(own: &[[f64; 2]], other: &[[f64; 2]], sign: f64) -> bool {
    let magnitude = |pts: &[[f64; 2]]| {
        pts.iter()
            .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()))
    };
    let reach = magnitude(own).max(magnitude(other));
    own.windows(2).all(|w| {
        let h = [sign * (w[1][0] - w[0][0]), sign * (w[1][1] - w[0][1])];
        let cross = |p: &[f64; 2]| h[0] * p[1] - h[1] * p[0];
        let most = other.iter().map(cross).fold(f64::NEG_INFINITY, f64::max);
        let least = own.iter().map(cross).fold(f64::INFINITY, f64::min);
        most - least < -CROSS_ROUNDING * h[0].abs().max(h[1].abs()) * reach
    })
}

/// De Casteljau at `s`, keeping the part before it.
fn split_keep_left(pts: &mut [[f64; 2]], s: f64) {
    let n = pts.len();
    for level in 1..n {
        for j in (level..n).rev() {
            pts[j] = lerp(pts[j - 1], pts[j], s);
        }
    }
}

/// De Casteljau at `s`, keeping the part after it.
fn split_keep_right(pts: &mut [[f64; 2]], s: f64) {
    let n = pts.len();
    for level in 1..n {
        for j in 0..n - level {
            pts[j] = lerp(pts[j], pts[j + 1], s);
        }
    }
}

/// `(1 − s) a + s b`.
fn lerp(a: [f64; 2], b: [f64; 2], s: f64) -> [f64; 2] {
    [(1.0 - s) * a[0] + s * b[0], (1.0 - s) * a[1] + s * b[1]]
}
