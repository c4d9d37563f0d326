//! A region's least friction, proven: the set at a friction just below its best grasp's has
//! no pair in the region. The sets grow with the friction, so every pair of the region then
//! needs at least that much, and the best grasp is the most robust to within that gap.
//!
//! The lower set is traced only on the box of each of the region's parts (its functions
//! restricted there): its boundary pieces must all keep clear of the region, and where none
//! crosses the box, one point tells whether the box is all in it or all out.

use crate::assemble::RawRegion;
use crate::cones::functions;
use crate::corners::{corner_lines, CornerLine, PairBox};
use crate::error::Result;
use crate::model::Model;
use crate::near::NearContacts;
use crate::options::GraspOptions;
use crate::polyline::bounds;
use crate::quality::{force_closure, min_friction};
use crate::region_set::{depth, held_inside, holds};
use crate::spared::{Spared, Witness};
use curve::distance_to_segment;
use numeric::certificate::Doubts;
use numeric::tolerance::Size;
use zeroset::{nonnegative_set, NonNegativeOptions, ZeroSetOptions};

/// The share of its friction below a best grasp's at which the set is traced again: the best
/// grasp is proven the most robust of its region to this share.
pub(crate) const BEST_GAP: f64 = 1e-4;

/// Samples along a corner line of the lower set, each tested against the region.
const LINE_SAMPLES: usize = 16;

/// What the set at a lower friction says of a region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Below {
    /// No pair of the region is force closure at the lower friction.
    None,
    /// This pair of the region, a chord inside it, is (and needs less friction than the best
    /// grasp).
    Beaten([f64; 2]),
    /// Not proven either way (the lower set left unresolved, a part beside a point where
    /// the contacts meet, or a piece of the lower set within a chord of the region's edge).
    Unknown,
}

/// The set at a friction [`BEST_GAP`] below a best grasp's, as far as a proof has traced it:
/// round each part of one region, and its corner lines near the region. A proof that fails
/// and is tried again with spared stretches reads the same traces.
pub(crate) struct LowerSets {
    /// The least friction of the best grasp.
    pub(crate) least: f64,
    /// Per part of the region: not traced yet, or the boundary there (`None`: unresolved).
    parts: Vec<Option<Option<LowerSet>>>,
    /// The corner lines that may meet the region's box (`None`: an end left unproven).
    lines: Option<Option<Vec<CornerLine>>>,
}

impl LowerSets {
    /// Nothing traced yet, below the best grasp's friction `least` in `region`.
    pub(crate) fn new(least: f64, region: &RawRegion) -> Self {
        Self {
            least,
            parts: (0..region.parts.len()).map(|_| None).collect(),
            lines: None,
        }
    }
}

/// Whether any pair of `region` (a region of the set at `opts.friction`, whose best grasp
/// needs the friction `lower.least`) is force closure at a friction [`BEST_GAP`] below,
/// leaving out the pairs with a finger in a stretch `spared`.
pub(crate) fn none_below(
    model: &Model<'_>,
    opts: &GraspOptions,
    widths: [Option<f64>; 2],
    region: &RawRegion,
    traced: &mut LowerSets,
    chord: f64,
    spared: &Spared,
) -> Result<Below> {
    let least = traced.least;
    let friction = least * (1.0 - BEST_GAP);
    let lower = GraspOptions { friction, ..*opts };
    let n = model.n();
    let near = NearContacts::new(model, friction);
    // A pair the lower set holds beats the best grasp where it lies a chord inside the
    // region; one clearly outside says nothing of it.
    let beats = |p: [f64; 2]| {
        !spared.spares(n, p)
            && held_inside(region, n, p, chord)
            && min_friction(model, p[0], p[1]) < least
    };
    let outside = |p: [f64; 2]| {
        spared.spares(n, p) || !holds(region, n, p[0], p[1]) && depth(region, p) > 2.0 * chord
    };
    let edges: Vec<[[f64; 2]; 2]> = region
        .parts
        .iter()
        .chain(&region.holes)
        .flat_map(|l| l.windows(2).map(|w| [w[0], w[1]]))
        .collect();
    for (part, memo) in region.parts.iter().zip(traced.parts.iter_mut()) {
        if memo.is_none() {
            *memo = Some(lower_set_round(model, &lower, widths, &near, part, chord)?);
        }
        let Some(Some(lower_set)) = memo.as_ref() else {
            return Ok(Below::Unknown);
        };
        // Of the lower set's pairs in the region, the best; and the middle of them, nearer
        // its least friction where the lower set there is a small blob round it.
        let inside: Vec<[f64; 2]> = lower_set
            .pieces
            .iter()
            .flatten()
            .chain(&lower_set.points)
            .copied()
            .filter(|&p| beats(p))
            .collect();
        if !inside.is_empty() {
            let k = inside.len() as f64;
            let middle = inside
                .iter()
                .fold([0.0; 2], |m, p| [m[0] + p[0] / k, m[1] + p[1] / k]);
            let friction_at = |p: &[f64; 2]| min_friction(model, p[0], p[1]);
            let best = inside
                .iter()
                .copied()
                .chain(beats(middle).then_some(middle))
                .min_by(|a, b| friction_at(a).total_cmp(&friction_at(b)))
                .unwrap_or(inside[0]);
            return Ok(Below::Beaten(best));
        }
        for p in &lower_set.points {
            if !outside(*p) {
                return Ok(Below::Unknown);
            }
        }
        for piece in &lower_set.pieces {
            // Each chord of the piece (within the tolerance of the lower set's boundary) keeps
            // clear of the region: its ends outside, and apart from every edge of the region;
            // or it lies in a spared stretch.
            for w in piece.windows(2) {
                let clear = spared.spares_segment(n, w[0], w[1], chord)
                    || outside(w[0])
                        && outside(w[1])
                        && edges
                            .iter()
                            .all(|e| segments_apart(w[0], w[1], e[0], e[1]) > 2.0 * chord);
                if !clear {
                    return Ok(Below::Unknown);
                }
            }
        }
        let crossed = !(lower_set.pieces.is_empty() && lower_set.points.is_empty());
        if !crossed || !spared.is_empty() {
            // No boundary crosses the box outside the spared stretches: the part outside
            // them is all in the lower set or all out, as one point of it is (where that
            // rest is one piece).
            let p = match spared.witness(n, part, &region.holes) {
                Witness::Pair(p) => p,
                Witness::Spared => continue,
                Witness::Unknown => return Ok(Below::Unknown),
            };
            if force_closure(model, friction.atan(), widths, p) {
                return Ok(if beats(p) {
                    Below::Beaten(p)
                } else {
                    Below::Unknown
                });
            }
        }
    }
    // Fingers at a corner, and single pairs of corners, that hold at the lower friction (only
    // those that may meet the region's box).
    let (lo, hi) = bounds(
        &region
            .parts
            .iter()
            .flatten()
            .chain(region.lines.iter().flatten())
            .chain(&region.points)
            .copied()
            .collect::<Vec<_>>(),
    );
    let reach = PairBox {
        s: [lo[0] - chord, hi[0] + chord],
        t: [lo[1] - chord, hi[1] + chord],
    };
    if traced.lines.is_none() {
        let mut doubts = Doubts::none();
        let lines = corner_lines(model, friction, widths, Some(reach), &mut doubts)?;
        traced.lines = Some(doubts.is_empty().then_some(lines));
    }
    let Some(Some(lines)) = traced.lines.as_ref() else {
        return Ok(Below::Unknown);
    };
    for line in lines {
        let u = line.joint as f64;
        for piece in &line.pieces {
            for k in 0..=LINE_SAMPLES {
                let v = piece[0] + k as f64 / LINE_SAMPLES as f64 * (piece[1] - piece[0]);
                let p = [u.min(v), u.max(v)];
                if holds(region, n, p[0], p[1]) && !spared.spares(n, p) {
                    return Ok(if min_friction(model, p[0], p[1]) < least {
                        Below::Beaten(p)
                    } else {
                        Below::Unknown
                    });
                }
            }
        }
    }
    Ok(Below::None)
}

/// The boundary of the set at a lower friction on a box, in the profile's parameter.
struct LowerSet {
    /// Its pieces.
    pieces: Vec<Vec<[f64; 2]>>,
    /// Its single pairs.
    points: Vec<[f64; 2]>,
}

/// The lower set's boundary on the box of one part of a region (grown by two chords, inside
/// the part's cell): `None` where it is not resolved there, or the box reaches a point where
/// the contacts meet (the diagonal, a joint, the seam).
fn lower_set_round(
    model: &Model<'_>,
    lower: &GraspOptions,
    widths: [Option<f64>; 2],
    near: &NearContacts<'_>,
    part: &[[f64; 2]],
    chord: f64,
) -> Result<Option<LowerSet>> {
    let n = model.n();
    let (lo, hi) = bounds(part);
    let cell = |x: f64| ((x.floor().max(0.0)) as usize).min(n - 1);
    let (i, j) = (cell(0.5 * (lo[0] + hi[0])), cell(0.5 * (lo[1] + hi[1])));
    let grow = 2.0 * chord;
    let (s0, s1) = (
        (lo[0] - grow).max(i as f64),
        (hi[0] + grow).min((i + 1) as f64),
    );
    let (t0, t1) = (
        (lo[1] - grow).max(j as f64),
        (hi[1] + grow).min((j + 1) as f64),
    );
    let meets_diagonal = i == j && s1 >= t0;
    let meets_joint = j == i + 1 && s1 >= (i + 1) as f64 && t0 <= j as f64;
    let meets_seam = i == 0 && j == n - 1 && s0 <= 0.0 && t1 >= n as f64;
    if i > j || !(s0 < s1 && t0 < t1) || meets_diagonal || meets_joint || meets_seam {
        return Ok(None);
    }
    let (fi, fj) = (model.forms[i].domain(), model.forms[j].domain());
    let form = |(a, b): (f64, f64), k: usize, u: f64| a + (u - k as f64) * (b - a);
    // (From the contacts' stretches: the whole cell's functions cost as many times more as the
    // segments have spans beyond the box's.)
    let fs = functions(
        &model.forms[i].restrict(form(fi, i, s0), form(fi, i, s1))?,
        &model.forms[j].restrict(form(fj, j, t0), form(fj, j, t1))?,
        lower.friction,
        widths,
    )?;
    // (The cell's own chord tolerance, not one relative to the small box.)
    let diagonal = (fi.1 - fi.0).hypot(fj.1 - fj.0);
    let mut settings = lower.settings;
    if settings.size.is_none() {
        let Ok(size) = Size::new(diagonal) else {
            return Ok(None);
        };
        settings.size = Some(size);
    }
    let options = NonNegativeOptions {
        zero: ZeroSetOptions {
            settings,
            max_patches: lower.max_patches,
        },
        pairs: false,
        meets: Vec::new(),
    };
    let set = nonnegative_set(&fs, &options, &|bx| near.excluded(i, j, bx))?;
    if !set.complete || !set.unresolved.is_empty() {
        return Ok(None);
    }
    let to_profile = |p: [f64; 2]| [model.profile_param(i, p[0]), model.profile_param(j, p[1])];
    Ok(Some(LowerSet {
        pieces: set
            .pieces
            .iter()
            .map(|p| p.pts.iter().map(|&q| to_profile(q)).collect())
            .collect(),
        points: set.points.iter().map(|&q| to_profile(q)).collect(),
    }))
}

/// The distance between the segments `ab` and `cd` (0 where they cross).
fn segments_apart(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    let side = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    };
    let crosses = side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0;
    if crosses {
        return 0.0;
    }
    distance_to_segment(a, c, d)
        .min(distance_to_segment(b, c, d))
        .min(distance_to_segment(c, a, b))
        .min(distance_to_segment(d, a, b))
}
