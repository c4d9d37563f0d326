//! Whether a disk holds a point of a profile, decided by bounds rather than samples: each
//! segment's Bézier pieces are halved until the hull of a piece's control points is proven
//! outside the disk, or one of its end points (a point of the curve) is proven inside.
//!
//! A rational Bézier piece with positive weights lies in the convex hull of its Euclidean
//! control points, so the hull's distance from the centre bounds the piece's from below:
//! taken as the larger of the distance to the points' box and the least extent of the points
//! towards the centre (a slab bound, which tightens quadratically as pieces shrink about a
//! point where the circle touches the curve). A piece the hull leaves undecided is tried
//! whole by its squared distance from the centre: positive where its Bernstein coefficients
//! are, and where that polynomial is proven convex its tangent at its least point bounds it
//! (the hull would need pieces down to the square root of the margin). Before any halving,
//! the ends of the pieces near the disk are looked at: most disks a medial axis tests are
//! entered deep, and the deepest end inside is then the witness. Every comparison allows for
//! the rounding of the coefficients and of the arithmetic, so a verdict holds for the exact
//! curve.

use crate::geom::V2;
use crate::param::ParamCurve;
use crate::profile::Profile;
use crate::segment::{Segment, SegmentKind};
use bspline::Piecewise;
use numeric::rounding::ulps;
use smallvec::{smallvec, SmallVec};

/// Halvings of one Bézier piece before it is left undecided: a piece 2^-40 of its span is
/// far below any slack a caller may leave between the disk and the curve.
const MAX_CLEARANCE_DEPTH: usize = 40;

/// Pieces tested in one call before the answer is left undecided: a curve hugging the
/// circle over a long stretch (an arc about the centre) would otherwise be halved into
/// ever more pieces, each still within the slack of the circle.
const MAX_PIECES: usize = 4096;

/// Steps that find where a convex squared distance is least: Newton, or a halving where it
/// would leave the bracket (to 2^-60 of the piece at worst).
const LEAST_STEPS: usize = 60;

/// The search for the least point stops at a step this small (a share of the piece): the
/// tangent there bounds the distance however near the least point it is; nearer makes the
/// bound tighter, and Newton gets there from 1e-8 in one more step.
const LEAST_STEP: f64 = 1e-15;

/// Units of rounding allowed per comparison: the Euclidean points (a division), the bounds
/// (a few products and sums) and one more per halving of the piece.
const CLEARANCE_ROUNDING_ULPS: f64 = 16.0;

/// What a disk holds of a profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clearance {
    /// No point of the profile lies inside the disk (its open interior): proven.
    Clear,
    /// The point of the profile at parameter `u`, at `distance` from the centre, lies inside
    /// the disk by more than the rounding of its computation.
    Entered {
        /// Profile parameter of the point.
        u: f64,
        /// Its distance from the centre.
        distance: f64,
    },
    /// Neither proven: some piece of the profile lies within rounding of the circle (or
    /// carries a weight that is not positive), and none was found inside.
    Unresolved,
}

/// Coefficients of a squared distance held in place (up to degree 30): they are built for
/// tens of pieces in each disk test.
type Row = SmallVec<[f64; 32]>;

/// A Bézier piece under test: its homogeneous control points `(X, Y, w)`, its interval of
/// the segment's parameter, and how many halvings made it.
struct Piece<'a> {
    coefs: &'a [f64],
    lo: f64,
    hi: f64,
    depth: usize,
}

/// The pieces still to test, last in first out, their coefficients in one buffer: a disk
/// test halves tens of pieces, and an allocation for each had been a fifth of a medial
/// axis' time.
#[derive(Default)]
struct Pending {
    coefs: Vec<f64>,
    /// Per piece: its interval and depth.
    spans: Vec<(f64, f64, usize)>,
    /// Coefficients per piece (the same for all pieces of a segment).
    len: usize,
}

impl Pending {
    fn push(&mut self, coefs: &[f64], lo: f64, hi: f64, depth: usize) {
        self.len = coefs.len();
        self.coefs.extend_from_slice(coefs);
        self.spans.push((lo, hi, depth));
    }

    /// Moves the last piece's coefficients into `into`; its interval and depth.
    fn pop(&mut self, into: &mut Vec<f64>) -> Option<(f64, f64, usize)> {
        let span = self.spans.pop()?;
        let start = self.coefs.len() - self.len;
        into.clear();
        into.extend_from_slice(&self.coefs[start..]);
        self.coefs.truncate(start);
        Some(span)
    }
}

impl Profile {
    /// Whether the disk of centre `x` and radius `r` holds a point of the profile.
    ///
    /// ```
    /// use curve::{Clearance, Profile, Segment};
    /// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let box_ = Profile::new(sides, None).unwrap();
    /// assert_eq!(box_.clearance([1.0, 1.0], 0.999), Clearance::Clear);
    /// assert!(matches!(box_.clearance([1.0, 1.0], 1.001), Clearance::Entered { .. }));
    /// ```
    pub fn clearance(&self, x: [f64; 2], r: f64) -> Clearance {
        self.clearance_in(x, r, None)
    }

    /// Whether the disk of centre `x` and radius `r` holds a point of the profile whose
    /// parameter lies in `[lo, hi]` (on a closed profile the window may run past either end
    /// of the domain, once round): the other points are not looked at.
    ///
    /// ```
    /// use curve::{Clearance, Profile, Segment};
    /// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let box_ = Profile::new(sides, None).unwrap();
    /// // The disk about (1, 0.5) of radius 1 holds points of the bottom side (0), not of
    /// // the top side (2) or the left one (3).
    /// assert_eq!(box_.clearance_between([1.0, 0.5], 1.0, 1.9, 3.1), Clearance::Clear);
    /// assert!(matches!(
    ///     box_.clearance_between([1.0, 0.5], 1.0, -0.5, 0.5),
    ///     Clearance::Entered { .. }
    /// ));
    /// ```
    pub fn clearance_between(&self, x: [f64; 2], r: f64, lo: f64, hi: f64) -> Clearance {
        let n = self.segments().len() as f64;
        if lo > hi || lo.is_nan() || hi.is_nan() {
            return Clearance::Clear; // an empty window
        }
        if hi - lo >= n {
            return self.clearance(x, r);
        }
        let window = if self.is_closed() {
            // Shifted into the domain: one interval, or two where it runs past the seam.
            let shift = (lo / n).floor() * n;
            let (a, b) = (lo - shift, hi - shift);
            if b <= n {
                Window::new(&[[a, b]])
            } else {
                Window::new(&[[a, n], [0.0, b - n]])
            }
        } else {
            Window::new(&[[lo.max(0.0), hi.min(n)]])
        };
        self.clearance_in(x, r, Some(&window))
    }

    /// [`Self::clearance`] for the points with parameters in `window` (all where `None`).
    fn clearance_in(&self, x: [f64; 2], r: f64, window: Option<&Window>) -> Clearance {
        let x = V2::from_arr(x);
        let mut unresolved = false;
        let mut pending = Pending::default();
        let (mut current, mut work) = (Vec::new(), Vec::new());
        let mut tested = 0;
        // Nearest boxes first: the point found inside is then likely the deepest.
        let near = 1.0 - ulps(CLEARANCE_ROUNDING_ULPS);
        let mut order: Vec<(f64, usize)> = Vec::new();
        // (The reach a shade beyond r / near: the tree passes over no box the test keeps.)
        self.box_tree()
            .within(x, r / near * (1.0 + ulps(4.0)), |i| {
                let d = box_distance(self.segment_box(i), x) * near;
                if d < r
                    && window.is_none_or(|w| w.cover(i as f64, i as f64 + 1.0) != Cover::None)
                    && !line_passes_by(&self.segments()[i], x, r)
                {
                    order.push((d, i));
                }
            });
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Most disks a caller tests are entered deep: the ends of the Bézier pieces (points
        // of the curve) mostly show it at once, and the deepest of them is the best witness.
        // A piece box's distance rounds by a few units of the centre's and the radius's size,
        // which the boxes' own growth (their coordinates' size) does not cover.
        let far = r + ulps(CLEARANCE_ROUNDING_ULPS) * x.x.abs().max(x.y.abs()).max(r);
        if let Some(entered) = self.deepest_piece_end(x, r, far, &order, window) {
            return entered;
        }
        for (_, i) in order {
            let seg = &self.segments()[i];
            if let Some((c, radius)) = seg.circle() {
                // An arc is decided on its circle, where its hull would be halved for long:
                // a disk about its centre stays within the slack of the whole arc.
                if arc_distance(seg, V2::from_arr(c), radius, x) >= r {
                    continue;
                }
            }
            // How much of a piece lies in the window, and whether its point at segment
            // parameter `v` does.
            let cover = |p: &Piece<'_>| {
                window.map_or(Cover::Whole, |w| {
                    w.cover(self.profile_param(i, p.lo), self.profile_param(i, p.hi))
                })
            };
            let within = |v: f64| window.is_none_or(|w| w.holds(self.profile_param(i, v)));
            let pieces = seg.curve().bezier_pieces();
            let dim = pieces.dim();
            let given = seg.curve().curve().coefficient_error();
            for k in 0..pieces.pieces() {
                if box_distance(self.piece_box(i, k), x) >= far {
                    continue;
                }
                let (lo, hi) = pieces.piece_span(k);
                pending.push(pieces.piece(k), lo, hi, 0);
                let err = coefficient_error(pieces, k, given);
                while let Some((lo, hi, depth)) = pending.pop(&mut current) {
                    let piece = Piece {
                        coefs: &current,
                        lo,
                        hi,
                        depth,
                    };
                    let cover = cover(&piece);
                    if cover == Cover::None {
                        continue;
                    }
                    tested += 1;
                    if tested > MAX_PIECES {
                        return Clearance::Unresolved;
                    }
                    // A piece reaching out of the window is halved until its halves lie in
                    // it or out of it, unless it is proven outside the disk whole.
                    let verdict = match test_piece(&piece, dim, x, r, err) {
                        Verdict::Inside { at_end, distance } => {
                            let v = if at_end { piece.hi } else { piece.lo };
                            if within(v) {
                                return Clearance::Entered {
                                    u: self.profile_param(i, v),
                                    distance,
                                };
                            }
                            Verdict::Split
                        }
                        Verdict::Undecided if cover == Cover::Part => Verdict::Split,
                        other => other,
                    };
                    match verdict {
                        Verdict::Outside => {}
                        Verdict::Split => match distance_verdict(&piece, x, r, err) {
                            Some(Convex::Outside) => {}
                            Some(Convex::Inside(t))
                                if within(piece.lo + t * (piece.hi - piece.lo)) =>
                            {
                                let v = piece.lo + t * (piece.hi - piece.lo);
                                let p = seg.curve().jet_to(v, 0).p;
                                return Clearance::Entered {
                                    u: self.profile_param(i, v),
                                    distance: (p - x).norm(),
                                };
                            }
                            _ if piece.depth < MAX_CLEARANCE_DEPTH => {
                                halve(&piece, dim, &mut work, &mut pending);
                            }
                            _ => unresolved = true,
                        },
                        _ => unresolved = true,
                    }
                }
            }
        }
        if unresolved {
            Clearance::Unresolved
        } else {
            Clearance::Clear
        }
    }
}

impl Profile {
    /// Of the ends of the Bézier pieces of the segments `order` (within `window`), the
    /// nearest `x`, if it lies inside the disk of radius `r` past the rounding of its
    /// coordinates; pieces whose boxes are `far` from `x` are passed over.
    fn deepest_piece_end(
        &self,
        x: V2,
        r: f64,
        far: f64,
        order: &[(f64, usize)],
        window: Option<&Window>,
    ) -> Option<Clearance> {
        let mut best: Option<(f64, f64, f64)> = None; // (distance + room, distance, u)
        for &(_, i) in order {
            let seg = &self.segments()[i];
            let pieces = seg.curve().bezier_pieces();
            let dim = pieces.dim();
            let given = seg.curve().curve().coefficient_error();
            for k in 0..pieces.pieces() {
                if box_distance(self.piece_box(i, k), x) >= far {
                    continue;
                }
                let coefs = pieces.piece(k);
                let err = coefficient_error(pieces, k, given);
                let (lo, hi) = pieces.piece_span(k);
                for (v, c) in [(lo, &coefs[..dim]), (hi, &coefs[coefs.len() - dim..])] {
                    let w = c[2];
                    if w.is_nan() || w <= 2.0 * err.weight {
                        continue;
                    }
                    let p = V2::new(c[0] / w, c[1] / w);
                    let mag = p.x.abs().max(p.y.abs()).max(x.x.abs()).max(x.y.abs());
                    let room = err.room(w, mag, 0);
                    let d = (p - x).norm();
                    let u = self.profile_param(i, v);
                    if d + room < r
                        && best.is_none_or(|b| d + room < b.0)
                        && window.is_none_or(|w| w.holds(u))
                    {
                        best = Some((d + room, d, u));
                    }
                }
            }
        }
        best.map(|(_, distance, u)| Clearance::Entered { u, distance })
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

/// The profile parameters a clearance looks at: one or two closed intervals.
struct Window {
    parts: Vec<[f64; 2]>,
}

/// How much of a stretch of parameters a window holds.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Cover {
    Whole,
    Part,
    None,
}

impl Window {
    fn new(parts: &[[f64; 2]]) -> Self {
        Self {
            parts: parts.to_vec(),
        }
    }

    fn holds(&self, u: f64) -> bool {
        self.parts.iter().any(|&[a, b]| u >= a && u <= b)
    }

    fn cover(&self, lo: f64, hi: f64) -> Cover {
        if self.parts.iter().any(|&[a, b]| lo >= a && hi <= b) {
            Cover::Whole
        } else if self.parts.iter().any(|&[a, b]| hi > a && lo < b) {
            Cover::Part
        } else {
            Cover::None
        }
    }
}

enum Verdict {
    Outside,
    Inside {
        at_end: bool,
        distance: f64,
    },
    Split,
    /// Within rounding of the circle.
    Undecided,
}

/// Bounds on the error of piece `k`'s homogeneous coefficients: of the points' `X, Y` (with
/// `given` added: the curve's own, the rounding of `w·x`) and of the weights.
fn coefficient_error(pieces: &Piecewise, k: usize, given: f64) -> Errors {
    let e = pieces.errors(k);
    Errors {
        point: e[0].max(e[1]) + given,
        weight: e[2],
    }
}

/// Bounds on the error of a piece's homogeneous coefficients.
#[derive(Clone, Copy)]
struct Errors {
    point: f64,
    weight: f64,
}

impl Errors {
    /// What a Euclidean control point `X / w` (coordinates up to `mag`, weights at least
    /// `w`, of a piece halved `depth` times) may be off by: `X / w` moves by
    /// (δX + |X / w| δw) / w for errors δX, δw ≤ w / 2 of its coefficients (to first order;
    /// twice that covers the rest), and the arithmetic's rounding.
    fn room(self, w: f64, mag: f64, depth: usize) -> f64 {
        4.0 * (self.point + mag * self.weight) / w
            + ulps(CLEARANCE_ROUNDING_ULPS + depth as f64) * mag
    }
}

/// The piece's verdict against the disk of centre `x` and radius `r`; `err` bounds the error
/// of its homogeneous coefficients.
fn test_piece(piece: &Piece<'_>, dim: usize, x: V2, r: f64, err: Errors) -> Verdict {
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

/// What the piece's squared distance from the centre proves,
/// `D = |P − x w|² − r² w²` (a polynomial of twice the degree, positive exactly where the
/// curve is outside): outside where its Bernstein coefficients are all positive (a bound
/// that closes in quadratically as pieces shrink, where the hull's closes in linearly on
/// a curved piece); else, where their second differences are all positive it is convex,
/// and it lies above its tangent at its least point, found by halving on the sign of its
/// derivative: outside where that bound is positive, a point inside where the least value
/// is negative. Every comparison allows for the coefficients'
/// errors and the rounding of the arithmetic; `None` where neither is proven.
fn distance_verdict(piece: &Piece<'_>, x: V2, r: f64, err: Errors) -> Option<Convex> {
    let n = piece.coefs.len() / 3;
    if n < 2 {
        return None;
    }
    let (d, m) = (n - 1, 2 * (n - 1));
    let eps = ulps(1.0);
    let (mut h_max, mut w_max) = (0.0f64, 0.0f64);
    for c in piece.coefs.chunks_exact(3) {
        h_max = h_max.max(c[0].abs()).max(c[1].abs());
        w_max = w_max.max(c[2].abs());
    }
    // Errors of the homogeneous coefficients (the halvings' roundings added), then of the
    // coefficients relative to the centre.
    let xm = x.x.abs().max(x.y.abs());
    let halvings = (piece.depth + 2) as f64 * eps;
    let e_w = err.weight + halvings * w_max;
    let e_rel = err.point + halvings * h_max + xm * e_w + 2.0 * eps * (h_max + xm * w_max);
    let rel: SmallVec<[[f64; 3]; 16]> = piece
        .coefs
        .chunks_exact(3)
        .map(|c| [c[0] - x.x * c[2], c[1] - x.y * c[2], r * c[2]])
        .collect();
    let big = rel
        .iter()
        .flat_map(|c| c.iter().map(|v| v.abs()))
        .fold(0.0, f64::max);
    let binomial = |n: usize| {
        let mut row: Row = smallvec![1.0f64; n + 1];
        for k in 1..n {
            row[k] = row[k - 1] * (n + 1 - k) as f64 / k as f64;
        }
        row
    };
    let (cd, cm) = (binomial(d), binomial(m));
    let mut coef: Row = smallvec![0.0; m + 1];
    for (i, a) in rel.iter().enumerate() {
        for (j, b) in rel.iter().enumerate() {
            coef[i + j] += cd[i] * cd[j] * (a[0] * b[0] + a[1] * b[1] - a[2] * b[2]);
        }
    }
    for (c, b) in coef.iter_mut().zip(&cm) {
        *c /= b;
    }
    // Each coefficient is a convex combination of products of magnitude at most `big²`.
    let err_coef =
        2.0 * (4.0 * big * e_rel + 2.0 * big * r * e_w) + 6.0 * (m + 8) as f64 * eps * big * big;
    let round = 8.0 * (m + 2) as f64 * eps * big * big;
    // D lies above its least Bernstein coefficient.
    if coef.iter().fold(f64::INFINITY, |a, &c| a.min(c)) > err_coef + round {
        return Some(Convex::Outside);
    }
    if coef
        .windows(3)
        .any(|w| w[2] - 2.0 * w[1] + w[0] <= 4.0 * err_coef + round)
    {
        return None;
    }
    let slope: Row = coef.windows(2).map(|w| w[1] - w[0]).collect();
    // Where D′ = m Σ slope Bᵐ⁻¹ changes sign (D is convex: D′ rises), by Newton on it,
    // kept in a bracket that halves wherever a step would leave it.
    let t0 = if slope[0] >= 0.0 {
        0.0
    } else if slope[m - 1] <= 0.0 {
        1.0
    } else {
        let (mut lo, mut hi, mut t) = (0.0, 1.0, 0.5);
        for _ in 0..LEAST_STEPS {
            let (s, ds) = value_and_derivative(&slope, t);
            if s < 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let newton = t - s / ds;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let step = (next - t).abs();
            t = next;
            if step <= LEAST_STEP {
                break;
            }
        }
        t
    };
    // D(t) ≥ D(t0) + D′(t0)(t − t0) on [0, 1], D′ = m Σ slope Bᵐ⁻¹.
    let least = value_and_derivative(&coef, t0).0;
    let value = least - err_coef - round;
    let rate = m as f64 * (value_and_derivative(&slope, t0).0.abs() + 2.0 * err_coef + round);
    if value - rate * t0.max(1.0 - t0) > 0.0 {
        Some(Convex::Outside)
    } else if least + err_coef + round < 0.0 {
        // The curve's point there is inside, past every error.
        Some(Convex::Inside(t0))
    } else {
        None
    }
}

/// The value and derivative at `t` of the polynomial with Bernstein coefficients `c` on
/// `[0, 1]`, by de Casteljau's algorithm.
fn value_and_derivative(c: &[f64], t: f64) -> (f64, f64) {
    let n = c.len() - 1;
    if n == 0 {
        return (c[0], 0.0);
    }
    // (In place up to degree 31, as every squared distance of a piece up to degree 15.)
    let mut inline = [0.0; 32];
    let mut spilled = Vec::new();
    let work: &mut [f64] = if c.len() <= inline.len() {
        inline[..c.len()].copy_from_slice(c);
        &mut inline[..c.len()]
    } else {
        spilled.extend_from_slice(c);
        &mut spilled
    };
    for level in 1..n {
        for j in 0..=n - level {
            work[j] += t * (work[j + 1] - work[j]);
        }
    }
    // The last two values span the derivative.
    (
        work[0] + t * (work[1] - work[0]),
        n as f64 * (work[1] - work[0]),
    )
}

/// What a piece's squared distance proves.
enum Convex {
    /// The piece lies outside the disk.
    Outside,
    /// Its point at this share of the piece lies inside.
    Inside(f64),
}

/// The two halves of a piece by de Casteljau's algorithm on its homogeneous coefficients,
/// pushed onto `pending`, the first half last (it is tested first); `work` is scratch.
fn halve(piece: &Piece<'_>, dim: usize, work: &mut Vec<f64>, pending: &mut Pending) {
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

/// Units of rounding allowed between an arc's rational form and its circle: its control
/// points and weights are rounded from the circle's centre, radius and angles.
const ARC_ROUNDING_ULPS: f64 = 64.0;

/// A lower bound on the distance from `x` to the arc `seg` of the circle about `c`: to its
/// nearer end where the circle's nearest point lies clearly off the arc (on the other side
/// of its chord than its middle), else to the circle; less the rounding of the computation
/// and of the arc's form.
fn arc_distance(seg: &Segment, c: V2, radius: f64, x: V2) -> f64 {
    let (a, b) = (seg.start(), seg.end());
    let mag = x.x.abs().max(x.y.abs()) + c.x.abs().max(c.y.abs()) + radius;
    let room = ulps(ARC_ROUNDING_ULPS) * mag + 4.0 * seg.curve().curve().coefficient_error();
    let v = x - c;
    let len = v.norm();
    let to_circle = (len - radius).abs();
    let to_ends = (x - a).norm().min((x - b).norm());
    let (lo, hi) = seg.curve().domain();
    let m = seg.curve().jet_to(0.5 * (lo + hi), 0).p;
    let chord = b - a;
    // The side of the chord of the circle's nearest point, and of the arc's middle, in
    // units of the chord length times the radius (the rounding is ~mag of those).
    let side = |q: V2| chord.cross(q - a);
    let tol = ulps(8.0) * mag * (chord.norm() + radius);
    // The circle's distance bounds the arc's everywhere; where the circle's nearest point
    // lies clearly off the arc, the arc's nearest point is an end.
    let bound = if len <= room || chord.norm() <= room {
        to_circle // at the centre, or a full circle
    } else {
        let q = c + v * (radius / len);
        let (sq, sm) = (side(q), side(m));
        if sq * sm < 0.0 && sq.abs() > tol && sm.abs() > tol {
            to_ends
        } else {
            to_circle
        }
    };
    bound - room
}

/// Whether `seg` is a line whose exact distance from `x` is at least `r`, past its rounding:
/// a wide disk's reach holds the boxes of many lines that pass it by (about a junction of
/// nearly cocircular corners, most of them), which the pieces' tests would each decide at
/// many times the cost.
fn line_passes_by(seg: &Segment, x: V2, r: f64) -> bool {
    if seg.kind() != SegmentKind::Line {
        return false;
    }
    let (a, b) = (seg.start(), seg.end());
    let squared = crate::geom::squared_distance_to_segment(x.arr(), a.arr(), b.arr());
    // (The foot and the difference round by a few units of the coordinates; the squares by
    // a few units of themselves.)
    let room = ulps(CLEARANCE_ROUNDING_ULPS) * (x.norm() + a.norm() + b.norm() + r);
    squared >= (r + room) * (r + room) * (1.0 + ulps(4.0))
}

/// A lower bound on the distance from `x` to a box `[lo x, lo y, hi x, hi y]`.
pub(crate) fn box_distance(b: [f64; 4], x: V2) -> f64 {
    let dx = (b[0] - x.x).max(x.x - b[2]).max(0.0);
    let dy = (b[1] - x.y).max(x.y - b[3]).max(0.0);
    // (The norm rounds by up to two units either way, a square root of a sum of squares:
    // four off keeps it below the true distance. The disk tests call this for every box in
    // reach, and hypot costs several times more.)
    V2::new(dx, dy).norm() * (1.0 - ulps(4.0))
}
