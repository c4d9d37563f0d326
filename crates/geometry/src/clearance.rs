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

mod distance;
mod hull;
mod lines_and_arcs;

use crate::pieces::{halve, Pending, Piece};
use curve::piece_bounds::{box_distance, coefficient_error, Errors, CLEARANCE_ROUNDING_ULPS};
use curve::ParamCurve;
use curve::Profile;
use curve::V2;
use distance::{distance_verdict, Convex};
use hull::{test_piece, Verdict};
use lines_and_arcs::{arc_distance, line_passes_by};
use numeric::rounding::ulps;
use std::cmp::Ordering;

/// Halvings of one Bézier piece before it is left undecided: a piece 2^-40 of its span is
/// far below any slack a caller may leave between the disk and the curve.
const MAX_CLEARANCE_DEPTH: usize = 40;

/// Pieces tested in one call before the answer is left undecided: a curve hugging the
/// circle over a long stretch (an arc about the centre) would otherwise be halved into
/// ever more pieces, each still within the slack of the circle.
const MAX_PIECES: usize = 4096;

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

/// [`crate::ProfileClearance::clearance`].
pub(crate) fn clearance(profile: &Profile, x: [f64; 2], r: f64) -> Clearance {
    clearance_in(profile, x, r, None)
}

/// [`crate::ProfileClearance::clearance_between`].
pub(crate) fn clearance_between(
    profile: &Profile,
    x: [f64; 2],
    r: f64,
    lo: f64,
    hi: f64,
) -> Clearance {
    let n = profile.segments().len() as f64;
    if lo > hi || lo.is_nan() || hi.is_nan() {
        return Clearance::Clear; // an empty window
    }
    if hi - lo >= n {
        return clearance(profile, x, r);
    }
    let window = if profile.is_closed() {
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
    clearance_in(profile, x, r, Some(&window))
}

/// [`clearance`] for the points with parameters in `window` (all where `None`).
fn clearance_in(profile: &Profile, x: [f64; 2], r: f64, window: Option<&Window>) -> Clearance {
    let x = V2::from_arr(x);
    let mut unresolved = false;
    let mut pending = Pending::default();
    let (mut current, mut work) = (Vec::new(), Vec::new());
    let mut tested = 0;
    // Nearest boxes first: the point found inside is then likely the deepest.
    let near = 1.0 - ulps(CLEARANCE_ROUNDING_ULPS);
    let mut order: Vec<(f64, usize)> = Vec::new();
    // (The reach a shade beyond r / near: the tree passes over no box the test keeps.)
    profile
        .box_tree()
        .within(x, r / near * (1.0 + ulps(4.0)), |i| {
            let d = box_distance(profile.segment_box(i), x) * near;
            if d < r
                && window.is_none_or(|w| w.cover(i as f64, i as f64 + 1.0) != Cover::None)
                && !line_passes_by(&profile.segments()[i], x, r)
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
    if let Some(entered) = deepest_piece_end(profile, x, r, far, &order, window) {
        return entered;
    }
    for (_, i) in order {
        let seg = &profile.segments()[i];
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
                w.cover(
                    profile.profile_param(i, p.lo),
                    profile.profile_param(i, p.hi),
                )
            })
        };
        let within = |v: f64| window.is_none_or(|w| w.holds(profile.profile_param(i, v)));
        let pieces = seg.curve().bezier_pieces();
        let dim = pieces.dim();
        for (k, err) in near_pieces(profile, i, x, far) {
            let (lo, hi) = pieces.piece_span(k);
            pending.push(pieces.piece(k), lo, hi, 0);
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
                                u: profile.profile_param(i, v),
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
                        Some(Convex::Inside(t)) if within(piece.lo + t * (piece.hi - piece.lo)) => {
                            let v = piece.lo + t * (piece.hi - piece.lo);
                            let p = seg.curve().jet_to(v, 0).p;
                            return Clearance::Entered {
                                u: profile.profile_param(i, v),
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

/// The Bézier pieces of segment `i` whose boxes come nearer `x` than `far`, each with the
/// bound on its coefficients' errors.
fn near_pieces(
    profile: &Profile,
    i: usize,
    x: V2,
    far: f64,
) -> impl Iterator<Item = (usize, Errors)> + '_ {
    let curve = profile.segments()[i].curve();
    let (pieces, given) = (curve.bezier_pieces(), curve.curve().coefficient_error());
    (0..pieces.pieces())
        // (A distance that is not a number is no proof of being far: such a piece is kept.)
        .filter(move |&k| {
            let d = box_distance(profile.piece_box(i, k), x);
            !matches!(
                d.partial_cmp(&far),
                Some(Ordering::Greater | Ordering::Equal)
            )
        })
        .map(move |k| (k, coefficient_error(pieces, k, given)))
}

/// Of the ends of the Bézier pieces of the segments `order` (within `window`), the
/// nearest `x`, if it lies inside the disk of radius `r` past the rounding of its
/// coordinates; pieces whose boxes are `far` from `x` are passed over.
fn deepest_piece_end(
    profile: &Profile,
    x: V2,
    r: f64,
    far: f64,
    order: &[(f64, usize)],
    window: Option<&Window>,
) -> Option<Clearance> {
    let mut best: Option<(f64, f64, f64)> = None; // (distance + room, distance, u)
    for &(_, i) in order {
        let seg = &profile.segments()[i];
        let pieces = seg.curve().bezier_pieces();
        let dim = pieces.dim();
        for (k, err) in near_pieces(profile, i, x, far) {
            let coefs = pieces.piece(k);
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
                let u = profile.profile_param(i, v);
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
