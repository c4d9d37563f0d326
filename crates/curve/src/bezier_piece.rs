//! The Bézier pieces of a chain of segments, for the tests of crossing and winding, halved by
//! de Casteljau's algorithm where a test needs them finer.
//!
//! Two facts about a rational Bézier piece with positive weights bound it without samples:
//! it lies in the convex hull of its Euclidean control points `P_i` (so in their box), and
//! its derivative is a sum of the differences `P_j − P_i` (`i < j`) with factors
//! `w_i w_j (B_i B_j' − B_i' B_j) / w²` that are never negative (`B_j / B_i` grows with the
//! parameter): its tangents lie in the cone of those differences. A piece whose cone lies
//! within a half-turn runs one way along some direction, and so cannot meet itself; two
//! neighbours whose cones together do meet only at their common end.

use crate::geom::V2;
use crate::segment::Segment;
use numeric::rounding::ulps;
use numeric::subdivide::{depth_first, Decision};
use smallvec::SmallVec;
use std::f64::consts::PI;

/// Homogeneous control points `(X, Y, w)` of a piece, held in place up to degree 3 (the
/// offsets' fits, arcs and lines; higher degrees spill to the heap).
type Coefs = SmallVec<[f64; 12]>;

/// Units of rounding of the largest coordinate by which a box is grown: the division
/// `X / w` of each Euclidean point, and the halvings that made the piece.
const BOX_ROUNDING: f64 = ulps(64.0);

/// Tangent cones together must leave this much of a half-turn (radians) to prove a
/// stretch runs one way: the rounding of the differences' directions, far above it.
const CONE_MARGIN: f64 = 1e-9;

/// Halvings of a stretch looked at for a retrace, and parts at most: far below the
/// flatness, and a bound on the work.
const MAX_RETRACE_DEPTH: usize = 40;
const MAX_RETRACE_PARTS: usize = 4096;

/// A Bézier piece of one segment of a chain, or a part of one (a piece halved).
#[derive(Debug, Clone)]
pub(crate) struct BezierPiece {
    pub(crate) chain: usize,
    pub(crate) segment: usize,
    /// Where it lies along its chain, in segments (piece `k` of `m` of segment `i` from
    /// `i + k/m` to `i + (k + 1)/m`, halves at the middle): neighbours share an end exactly.
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    /// Halvings that made it from its piece.
    pub(crate) depth: usize,
    coefs: Coefs,
    /// The box of its Euclidean control points, grown by their rounding; `None` where a
    /// weight is not positive (the hull then says nothing).
    pub(crate) bounds: Option<[V2; 2]>,
    /// Its end points (its first and last control points).
    pub(crate) start: V2,
    pub(crate) end: V2,
}

/// The directions a stretch's tangents lie within: `half` radians either side of `axis`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Cone {
    axis: V2,
    half: f64,
}

impl Cone {
    /// Whether this cone and `other` lie together within less than a half-turn.
    pub(crate) fn joins(self, other: Cone) -> bool {
        let between = self
            .axis
            .cross(other.axis)
            .atan2(self.axis.dot(other.axis))
            .abs();
        between + self.half + other.half < PI - CONE_MARGIN
    }
}

/// The stretches of chain `chain`'s segments: one per Bézier piece, in order, but none for
/// a piece that is a single point (a repeated control point of a polyline spline): its
/// neighbours become each other's, so that their common end is not taken for a touch.
pub(crate) fn pieces_of(chain: usize, segments: &[Segment]) -> Vec<BezierPiece> {
    let mut out: Vec<BezierPiece> = Vec::new();
    let mut point_from: Option<f64> = None;
    for (i, seg) in segments.iter().enumerate() {
        let pieces = seg.curve().bezier_pieces();
        let m = pieces.pieces();
        for k in 0..m {
            let mut s = BezierPiece::new(
                chain,
                i,
                i as f64 + k as f64 / m as f64,
                i as f64 + (k + 1) as f64 / m as f64,
                0,
                Coefs::from_slice(pieces.piece(k)),
            );
            if s.is_point() {
                match out.last_mut() {
                    Some(last) => last.hi = s.hi,
                    None => {
                        point_from.get_or_insert(s.lo);
                    }
                }
                continue;
            }
            if let Some(lo) = point_from.take() {
                s.lo = lo;
            }
            out.push(s);
        }
    }
    out
}

impl BezierPiece {
    fn new(chain: usize, segment: usize, lo: f64, hi: f64, depth: usize, coefs: Coefs) -> Self {
        let points: SmallVec<[V2; 8]> = euclidean(&coefs).collect();
        let positive = coefs.chunks_exact(3).all(|c| c[2] > 0.0);
        let (mut lo_p, mut hi_p) = (points[0], points[0]);
        for p in &points[1..] {
            lo_p = V2::new(lo_p.x.min(p.x), lo_p.y.min(p.y));
            hi_p = V2::new(hi_p.x.max(p.x), hi_p.y.max(p.y));
        }
        let finite = [lo_p.x, lo_p.y, hi_p.x, hi_p.y]
            .iter()
            .all(|v| v.is_finite());
        let bounds = (positive && finite).then(|| {
            let magnitude = lo_p
                .x
                .abs()
                .max(lo_p.y.abs())
                .max(hi_p.x.abs())
                .max(hi_p.y.abs());
            let room = BOX_ROUNDING * magnitude;
            [
                V2::new(lo_p.x - room, lo_p.y - room),
                V2::new(hi_p.x + room, hi_p.y + room),
            ]
        });
        let (start, end) = (points[0], points[points.len() - 1]);
        Self {
            chain,
            segment,
            lo,
            hi,
            depth,
            coefs,
            bounds,
            start,
            end,
        }
    }

    /// The Euclidean control points.
    fn points(&self) -> impl Iterator<Item = V2> + '_ {
        euclidean(&self.coefs)
    }

    /// Whether all its control points are one point.
    fn is_point(&self) -> bool {
        self.bounds.is_some() && self.points().all(|p| p == self.start)
    }

    /// The two halves (de Casteljau at the middle of its parameter).
    pub(crate) fn halves(&self) -> [BezierPiece; 2] {
        let n = self.coefs.len() / 3;
        let mut work = self.coefs.clone();
        let mut left = Coefs::from_slice(&work[..3]);
        let mut right = Coefs::from_elem(0.0, work.len());
        right[3 * (n - 1)..].copy_from_slice(&work[3 * (n - 1)..]);
        for level in 1..n {
            for j in 0..n - level {
                for c in 0..3 {
                    work[3 * j + c] = 0.5 * (work[3 * j + c] + work[3 * (j + 1) + c]);
                }
            }
            left.extend_from_slice(&work[..3]);
            let k = 3 * (n - 1 - level);
            right[k..k + 3].copy_from_slice(&work[k..k + 3]);
        }
        let middle = 0.5 * (self.lo + self.hi);
        let depth = self.depth + 1;
        [
            BezierPiece::new(self.chain, self.segment, self.lo, middle, depth, left),
            BezierPiece::new(self.chain, self.segment, middle, self.hi, depth, right),
        ]
    }

    /// The cone of its tangents where it lies within a half-turn (its weights positive).
    pub(crate) fn cone(&self) -> Option<Cone> {
        self.bounds?;
        let points: SmallVec<[V2; 8]> = self.points().collect();
        let magnitude = points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        // (A difference within rounding has no direction; it adds nothing to a tangent.)
        let noise = BOX_ROUNDING * magnitude;
        let mut directions: SmallVec<[V2; 28]> = SmallVec::new();
        for (i, &p) in points.iter().enumerate() {
            for &q in &points[i + 1..] {
                let d = q - p;
                let length = d.norm();
                if length > noise {
                    directions.push(d * (1.0 / length));
                }
            }
        }
        if directions.is_empty() {
            return None;
        }
        let sum = directions.iter().fold(V2::new(0.0, 0.0), |s, &d| s + d);
        if sum.norm() <= ulps(1.0) * directions.len() as f64 {
            return None;
        }
        let axis = sum.unit();
        let least = directions
            .iter()
            .map(|d| axis.dot(*d))
            .fold(1.0f64, f64::min);
        let half = least.clamp(-1.0, 1.0).acos();
        (half < 0.5 * PI - CONE_MARGIN).then_some(Cone { axis, half })
    }

    /// Whether it lies within `delta` of its chord: every control point does (the hull does
    /// then too).
    pub(crate) fn is_flat(&self, delta: f64) -> bool {
        self.bounds.is_some()
            && self.points().all(|p| {
                crate::geom::distance_to_segment(p.arr(), self.start.arr(), self.end.arr()) <= delta
            })
    }

    /// Where a stretch within `delta` of its chord goes back along it by more than twice
    /// that, over a way it went before (within `rounding`: a retrace, as of a spline whose
    /// control points lie on a line; a cusp's way back parts from its way there, and is
    /// judged by the flatness): a point of the way back. Its parts are halved until each runs
    /// one way along the chord (the chord's components of its control points' differences
    /// not negative) or lies within `delta`, and their ends compared with the parts before.
    pub(crate) fn retrace(&self, delta: f64, rounding: f64) -> Option<V2> {
        let chord = self.end - self.start;
        if chord.norm() <= delta {
            return None;
        }
        let along = chord.unit();
        let reach = |p: V2| (p - self.start).dot(along);
        let mut farthest = 0.0f64;
        let mut before: Vec<(V2, V2)> = Vec::new();
        let mut parts = 0;
        // (The depth bound is the piece's own: its halves count from the stretch it came from.)
        let halvings = MAX_RETRACE_DEPTH.saturating_sub(self.depth);
        depth_first(self.clone(), halvings, |part, visit| {
            parts += 1;
            let reaches: SmallVec<[f64; 8]> = part.points().map(reach).collect();
            let one_way = reaches.windows(2).all(|w| w[1] >= w[0]);
            let settled =
                one_way || part.extent() <= delta || !visit.can_halve || parts > MAX_RETRACE_PARTS;
            if !settled {
                let [h0, h1] = part.halves();
                return Decision::Halve(h0, h1);
            }
            let end = reach(part.end);
            if end < farthest - 2.0 * delta
                && before.iter().any(|&(a, b)| {
                    crate::geom::distance_to_segment(part.end.arr(), a.arr(), b.arr()) <= rounding
                })
            {
                return Decision::Stop(part.end);
            }
            farthest = farthest.max(end);
            before.push((part.start, part.end));
            Decision::Decided
        })
    }

    /// Where neighbours `self` and `next`, each within `delta` of its chord, run back along
    /// each other from their common end by more than twice that, within `rounding` (a
    /// retrace at a knot or where a stretch was halved): the far end of the shorter.
    pub(crate) fn retraced_by(&self, next: &BezierPiece, delta: f64, rounding: f64) -> Option<V2> {
        // (The common end: this one's end, or its start across a closed chain's seam.)
        let (common, mine, theirs) =
            if (self.end - next.start).norm() <= (self.start - next.end).norm() {
                (self.end, self.start, next.end)
            } else {
                (self.start, self.end, next.start)
            };
        let (a, b) = (mine - common, theirs - common);
        if a.dot(b) <= 0.0 {
            return None;
        }
        let (short, long) = if a.norm() <= b.norm() { (a, b) } else { (b, a) };
        (short.norm() > 2.0 * delta
            && crate::geom::distance_to_segment(
                (common + short).arr(),
                common.arr(),
                (common + long).arr(),
            ) <= rounding)
            .then_some(common + short)
    }

    /// Whether its box and `other`'s meet (a stretch without a box meets every one).
    pub(crate) fn boxes_meet(&self, other: &BezierPiece) -> bool {
        match (self.bounds, other.bounds) {
            (Some([a0, a1]), Some([b0, b1])) => {
                a0.x <= b1.x && b0.x <= a1.x && a0.y <= b1.y && b0.y <= a1.y
            }
            _ => true,
        }
    }

    /// Whether its box holds `p` (a stretch without a box holds every point).
    pub(crate) fn box_holds(&self, p: V2) -> bool {
        self.bounds
            .is_none_or(|[lo, hi]| p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)
    }

    /// The length of its box's diagonal (infinite without a box).
    pub(crate) fn extent(&self) -> f64 {
        self.bounds
            .map_or(f64::INFINITY, |[lo, hi]| (hi - lo).norm())
    }
}

/// The Euclidean points `(X / w, Y / w)` of homogeneous control points.
fn euclidean(coefs: &[f64]) -> impl Iterator<Item = V2> + '_ {
    coefs
        .chunks_exact(3)
        .map(|c| V2::new(c[0] / c[2], c[1] / c[2]))
}
