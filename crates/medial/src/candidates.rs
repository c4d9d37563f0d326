//! The candidates the axis is cut from: the untrimmed bisectors of the pairs of boundary
//! pieces (segments, spline segments cut at their knots, corners) that can share an empty
//! disk.

use crate::error::{Error, Result};
use crate::pairs::{neighbours, FEW_SEGMENTS};
use crate::parallel::in_order;
use crate::seed::seed_pairs;
use crate::sites::Sites;
use curve::{ParamCurve, Profile, SpanOf};
use numeric::tolerance::{ChordTol, ParamTol, Settings};
use zeroset::{
    profile_bisector_of_pairs, profile_self_bisector_of_pairs, Bisector, BisectorOptions,
};

/// A vertex of the axis: its foot parameters, point and radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Vertex {
    pub(crate) tr: [f64; 2],
    pub(crate) xy: [f64; 2],
    pub(crate) radius: f64,
}

/// The finest chord tolerance the bisectors take (relative to their box's diagonal): the
/// axis's finest, 1e-9 of the size, scaled to the diagonal may fall below it.
const MIN_CHORD: f64 = 1e-9;

/// One candidate branch (or point): the bisector of two sites.
#[derive(Debug, Clone)]
pub(crate) struct Candidate {
    /// The boundaries of the two sites.
    pub(crate) boundary: [usize; 2],
    /// The segment of each site (for a corner, the segment starting there).
    pub(crate) segment: [usize; 2],
    /// Whether each site is a corner.
    pub(crate) corner: [bool; 2],
    /// The feet's profile parameters per vertex.
    pub(crate) tr: Vec<[f64; 2]>,
    /// The bisector points.
    pub(crate) xy: Vec<[f64; 2]>,
}

/// Which pairs of segments the bisectors are computed for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum PairSource {
    /// Those the Voronoi diagram of the boundaries' chords shows sharing an edge
    /// ([`crate::seed`]): a guess, that the coverage of the feet proves or refutes. Where no
    /// seed can be made, `Bounds`.
    Seed,
    /// Those that can share an empty disk by bounds on the distances ([`crate::pairs`]).
    Bounds,
    /// No pairs: the seed's edges themselves, traced in closed form, where the boundaries are
    /// lines and circular arcs ([`crate::traced_axis`]); [`candidates`] takes it as `Bounds`.
    SeedEdges,
    /// No pairs either: the bisector of every pair of true sites trimmed in closed form,
    /// where the boundaries are few lines and circular arcs ([`crate::pairwise_axis`]);
    /// [`candidates`] takes it as `Bounds`.
    Pairwise,
    /// Every pair (the tests compare the others with it).
    #[cfg(test)]
    All,
}

/// Every candidate branch and isolated point, whether every bisector was complete, and
/// whether the pairs came from the seed (`source` may fall back from `Seed` to `Bounds`).
pub(crate) fn candidates(
    sites: &Sites<'_>,
    (tol, chord_tol): (ParamTol, f64),
    source: PairSource,
) -> Result<(Vec<Candidate>, bool, bool)> {
    // The bisectors' chord tolerance is relative to their own profiles' box diagonal, at
    // most the outer box's; the axis's (`chord_tol`) to the region's max(width, height), or
    // to the size given (of all the parts of an input, which may make it too coarse for a
    // small part's bisectors).
    let chord_tol = (chord_tol * sites.size / sites.diagonal).max(MIN_CHORD);
    let chord_tol = ChordTol::new(chord_tol).map_err(|e| Error::BadOption {
        field: "chord_tol",
        value: e.value,
        why: e.requirement,
    })?;
    let bisector_opts = BisectorOptions {
        settings: Settings {
            tol,
            chord_tol,
            size: None,
        },
        trimmed: false,
        ..BisectorOptions::default()
    };
    // Spline segments of several spans are cut at their knots: the pairs of spans that
    // cannot share an empty disk are then skipped too.
    // (Only where the pieces are then many enough to prune: below that, one bisector of a
    // whole spline costs less than those of all its pairs of spans.)
    let count: usize = sites.boundaries.iter().map(|b| spans_of(b)).sum();
    let cut = count >= FEW_SEGMENTS;
    let pieces: Vec<Pieces<'_>> = sites
        .boundaries
        .iter()
        .map(|b| Pieces::of(b, cut))
        .collect();
    let b: Vec<&Profile> = pieces.iter().map(|p| p.profile()).collect();
    let pairs: Vec<[usize; 2]> = (0..b.len())
        .flat_map(|i| (i..b.len()).map(move |j| [i, j]))
        .collect();
    let seeded = match source {
        PairSource::Seed => {
            let inside_left: Vec<f64> = (0..b.len()).map(|k| sites.inside_left(k)).collect();
            seed_pairs(&b, &inside_left, root_box(sites), sites.size)
        }
        _ => None,
    };
    let from_seed = seeded.is_some();
    let near = match (seeded, source) {
        (Some(near), _) => near,
        #[cfg(test)]
        (None, PairSource::All) => crate::pairs::Neighbours::All,
        (None, _) => neighbours(&b, sites.size, root_box(sites)),
    };
    // (The watch is looked at for every pair of pieces: a cancelled search keeps none
    // more, and its caller answers "cancelled".)
    let stage = curve::watch::stage(match source {
        PairSource::Seed => "medial axis: the seed's pairs",
        _ => "medial axis: every pair the bounds keep",
    });
    let bisect = |&[i, j]: &[usize; 2]| {
        // (Cancellation is looked at before the bounds: a cancelled search skips the rest
        // of its pairs at the cost of a load each.)
        let keep =
            |s: usize, t: usize| !stage.cancelled() && near.keep((i, s), (j, t)) && stage.go_on(1);
        // (Only the axis's side of each boundary: a point on the other side of a foot is
        // outside, where its disk meets the boundary at that foot.)
        let opts = BisectorOptions {
            sides: Some([sites.side(i), sites.side(j)]),
            ..bisector_opts
        };
        if i == j {
            profile_self_bisector_of_pairs(b[i], &opts, &keep)
        } else {
            profile_bisector_of_pairs(b[i], b[j], &opts, &keep)
        }
    };
    let found = in_order(&pairs, bisect);
    let mut out = Vec::new();
    let mut complete = true;
    for (pair, found) in pairs.into_iter().zip(found) {
        let found = found?;
        complete &= found.complete;
        add(&mut out, found, pair, [&pieces[pair[0]], &pieces[pair[1]]]);
    }
    Ok((out, complete, from_seed))
}

/// The box the axis lies in: the outer boundary's (inside), or the clip box (outside).
pub(crate) fn root_box(sites: &Sites<'_>) -> [f64; 4] {
    sites.clip.unwrap_or(sites.outer_box)
}

/// How many pieces `p` has cut at its knots (as [`Profile::split_at_knots`] cuts it).
fn spans_of(p: &Profile) -> usize {
    p.segments()
        .iter()
        .map(|s| s.piece_breaks().len() - 1)
        .sum()
}

/// A boundary as its bisectors are computed on: itself, or cut at its spline knots with
/// where each span lies on it.
struct Pieces<'a> {
    whole: &'a Profile,
    cut: Option<(Profile, Vec<SpanOf>)>,
}

impl<'a> Pieces<'a> {
    /// `p`, with `cut` cut at its knots (left whole where nothing is cut, or where the cut
    /// profile is refused: a span of no length).
    fn of(p: &'a Profile, cut: bool) -> Self {
        Self {
            whole: p,
            cut: cut.then(|| p.split_at_knots().ok().flatten()).flatten(),
        }
    }

    fn profile(&self) -> &Profile {
        self.cut.as_ref().map_or(self.whole, |(p, _)| p)
    }

    /// The segment and profile parameter on the boundary of parameter `w` on segment `i`
    /// of the profile the bisectors were computed on.
    fn on_boundary(&self, i: usize, w: f64) -> (usize, f64) {
        match &self.cut {
            None => (i, w),
            Some((_, spans)) => (spans[i].segment, spans[i].param(i, w)),
        }
    }
}

fn add(out: &mut Vec<Candidate>, found: Bisector, boundary: [usize; 2], pieces: [&Pieces<'_>; 2]) {
    // Back on the boundaries: segments and parameters of the spans' profiles mapped.
    let map = |segment: [usize; 2], tr: [f64; 2]| {
        let (s0, t) = pieces[0].on_boundary(segment[0], tr[0]);
        let (s1, r) = pieces[1].on_boundary(segment[1], tr[1]);
        ([s0, s1], [t, r])
    };
    for br in found.branches {
        let (sites, corner) = (br.segments(), br.corners());
        let segment = map(sites, [0.0; 2]).0;
        let mut tr: Vec<[f64; 2]> = br.tr.iter().map(|&tr| map(sites, tr).1).collect();
        // The bisector of a closed boundary's one segment with itself is traced with its
        // feet in order (t < r): where a foot passes the seam, from the end of the
        // parameter to its start, the two trade places. Each vertex's feet are kept in the
        // order that follows on from the last's (the other two stretches of the axis there
        // would not meet: one ends at the seam with a foot at the end, the next starts with
        // its feet the other way round).
        let whole = pieces[0].whole;
        if boundary[0] == boundary[1]
            && segment[0] == segment[1]
            && corner == [false, false]
            && whole.is_closed()
        {
            let n = whole.domain().1;
            let apart = |a: f64, b: f64| {
                let d = (a - b).abs() % n;
                d.min(n - d)
            };
            for k in 1..tr.len() {
                let (p, q) = (tr[k - 1], tr[k]);
                let kept = apart(p[0], q[0]) + apart(p[1], q[1]);
                let traded = apart(p[0], q[1]) + apart(p[1], q[0]);
                if traded < kept {
                    tr[k] = [q[1], q[0]];
                }
            }
        }
        out.push(Candidate {
            boundary,
            segment,
            corner,
            tr,
            xy: br.xy,
        });
    }
    // Isolated points (the centre of an arc, of arcs of one circle): single-vertex
    // candidates, nodes of their own where no edge reaches them (a disk).
    for p in found.isolated {
        let (segment, tr) = map(p.segments(), p.tr);
        out.push(Candidate {
            boundary,
            segment,
            corner: p.corners(),
            tr: vec![tr],
            xy: vec![p.xy],
        });
    }
}
