//! The axis of a region of few lines and circular arcs, with no diagram: the bisector of
//! every pair of its true sites (segments, and reflex corners as points), trimmed to where
//! its disks hold no point of the boundary nearer than their two feet.
//!
//! Below [`crate::SEED_SEGMENTS`] segments a Voronoi diagram of the chords costs more than
//! the whole axis (about 20 µs a chord, and one round hole takes dozens of chords), and the
//! quadtree's pairs trace B-spline bisectors. Here every distance is in closed form. Along
//! the normal ray at a foot on one site of a pair, the bisector's point comes from the other
//! site ([`crate::true_sites::SiteShape::radius_on_ray`]); its disk is empty where every other
//! site is as far as the feet. A segment's distance counts only where its foot falls on it:
//! the boundary's distance is the least of those and the joints'. The kept stretches of a
//! pair are found on samples of its feet and their ends by bisection; each end is solved as
//! a node on the pair's equation and the one that ends the stretch there
//! ([`LinesAndArcs::solve_node`]). A node names the pairs whose edges meet there, and a pair
//! with no stretch ending at it is followed from it, so that a stretch shorter than the
//! samples' spacing is found too. Each stretch is traced between its ends as the seed's
//! edges are. The cost is O(n³) in the sites, meant for a few dozen.
//!
//! Nothing here proves the axis. A stretch missed (shorter than the first step a pair is
//! followed by from a node) leaves its feet's gap, and the coverage of the feet
//! ([`crate::coverage`]) refuses the axis, which is then built on the quadtree's pairs.

mod empty_disks;
mod feet;
mod nodes;
mod search;

use crate::lines_and_arcs::{LinesAndArcs, Solved, Traced};
use crate::sites::Sites;
use crate::stretches::Stretch;
use crate::true_sites::TrueSite;
use curve::V2;
use feet::Feet;
use std::cell::Cell;
use std::collections::{HashMap, HashSet};

/// Halvings of a sample step that place a stretch's end: 2⁻²⁸ of it, ~1e-10 of the
/// segment, a thousandth of [`ABOUT`] (the sites found touching there are those of the
/// node) and far within the [`REACH`] Newton's method polishes the node from, which it
/// does to rounding in two or three steps.
const END_HALVINGS: usize = 28;

/// Sites whose distance at a stretch's end exceeds the disk's radius by less than this share
/// of the size touch the node there: its equations hold there to the bisection's precision.
const ABOUT: f64 = 1e-7;

/// How far (a share of the size) Newton's method may move a node from the end the bisection
/// found.
const REACH: f64 = 1e-6;

/// The region's true sites with the closed forms.
struct Pairwise<'m, 's, 'a> {
    model: &'m LinesAndArcs<'s, 'a>,
    /// The true sites: every segment, every reflex corner.
    sites: Vec<TrueSite>,
    /// Every joint (a corner site, convex or reflex) and its point: with the segments'
    /// distances where their feet fall on them, the distances to these are the distance to
    /// the boundary from anywhere.
    joints: Vec<(TrueSite, V2)>,
    /// The fan of normals at each reflex corner (see [`Fan`]).
    fans: HashMap<TrueSite, Fan>,
    /// The site (an index into `sites`, then `joints`) that last refused a point's disk.
    last_refusal: Cell<usize>,
}

/// The directions in which a reflex corner is the nearest point: from the normal into the
/// axis's side of the segment that ends there, `from`, turning by `turn` (under half a turn)
/// to that of the segment that starts there, `to`.
#[derive(Clone, Copy)]
struct Fan {
    from: V2,
    to: V2,
    turn: f64,
}

impl Fan {
    /// Whether direction `d` lies in the fan.
    fn holds(&self, d: V2) -> bool {
        let sign = self.turn.signum();
        sign * self.from.cross(d) >= 0.0 && sign * d.cross(self.to) >= 0.0
    }
}

/// The candidates and stretches of the axis of `sites`' region (inside), every boundary made
/// of lines and circular arcs, from every pair of true sites: one candidate per stretch
/// (two where its feet pass the joint of a whole circle). `None` where some boundary has
/// other curves, an end cannot be solved or a stretch traced, a pair's axis is a cycle
/// without nodes, or the work is cancelled.
pub(crate) fn pairwise(sites: &Sites<'_>, chord_tol: f64) -> Option<Traced> {
    if sites.clip.is_some() {
        return None;
    }
    let model = LinesAndArcs::new(sites, chord_tol)?;
    let mut all = Vec::new();
    let mut joints = Vec::new();
    let mut fans = HashMap::new();
    for (boundary, b) in sites.boundaries.iter().enumerate() {
        let n = b.segments().len();
        for segment in 0..n {
            let site = TrueSite {
                boundary,
                segment,
                corner: false,
            };
            let corner = TrueSite {
                corner: true,
                ..site
            };
            all.push(site);
            joints.push((corner, model.start(corner)));
            // (A corner on the axis's side is a reflex one; its point is a site.)
            if sites.inside_of(boundary, segment, segment as f64, true, [0.0; 2]) {
                all.push(corner);
                // (A segment's distance has the unit normal into the axis's side as its
                // gradient on it.)
                let at = model.start(corner);
                let normal = |s: TrueSite| model.shape(s).distance(at).1;
                let before = TrueSite {
                    segment: (segment + n - 1) % n,
                    ..site
                };
                let (from, to) = (normal(before), normal(site));
                let turn = from.cross(to).atan2(from.dot(to));
                fans.insert(corner, Fan { from, to, turn });
            }
        }
    }
    let pairwise = Pairwise {
        model: &model,
        sites: all,
        joints,
        fans,
        last_refusal: Cell::new(0),
    };
    let stage = curve::watch::stage("medial axis: every pair of sites");
    let found = pairwise.stretches(&stage)?;
    let mut candidates = Vec::new();
    let mut stretches = Vec::new();
    let mut proven = HashSet::new();
    for Found { pair, ends, .. } in found {
        if !stage.go_on(1) {
            return None;
        }
        for e in ends.iter().filter(|e| e.proven) {
            proven.insert(e.xy.arr().map(f64::to_bits));
        }
        for (candidate, vertices) in model.trace_edge(pair, ends)? {
            stretches.push(Stretch {
                candidate: candidates.len(),
                vertices,
            });
            candidates.push(candidate);
        }
    }
    Some(Traced {
        candidates,
        stretches,
        proven,
    })
}

/// A stretch of the bisector of `pair` with empty disks: its span of the parametrising
/// site's feet, and its ends solved, with the true sites about each.
struct Found {
    pair: [TrueSite; 2],
    span: [f64; 2],
    ends: [Solved; 2],
    about: [Vec<TrueSite>; 2],
}

/// One end of a span of kept feet: the last parameter kept, and the first not kept beyond it
/// (none where the span runs to the end of the feet).
#[derive(Clone, Copy)]
struct Bound {
    kept: f64,
    beyond: Option<f64>,
}

/// How the bisector of a pair is followed: by the feet on `along` (its ray at each), the
/// other site being `other`; `whole` where the feet run round a whole circle.
#[derive(Clone, Copy)]
struct Param {
    along: TrueSite,
    other: TrueSite,
    feet: Feet,
    whole: bool,
}
