//! The medial axis (skeleton) of a planar region bounded by profiles: every point inside with
//! at least two nearest boundary points, as a graph whose points carry the radius of the
//! largest inscribed disk centred there.
//!
//! The axis is made of pieces of bisectors (Elber & Kim): between two segments of the
//! boundary, a segment and a reflex corner, or two reflex corners. The candidates are the
//! bisectors of every pair of sites of every boundary and of every pair of boundaries
//! ([`zeroset::self_bisector`], [`zeroset::bisector`]); a point of one lies on
//! the axis where it is inside the region and its disk is empty (no boundary point nearer than
//! its foot points). Each candidate branch is cut to its stretches with empty disks; where a
//! stretch ends inside a branch a third boundary point reached the disk: the end is refined on
//! the exact branch to that tri-tangent disk, a junction. The stretches are joined into a graph
//! at their common ends: junctions, ends at centres of curvature, convex corners; stretches
//! that continue each other (a foot passing from one segment to the next) are one edge.
//!
//! Emptiness is proven on the boundaries' control hulls ([`geometry::ProfileClearance::clearance`]);
//! where rounding leaves a disk undecided, the nearest point found decides it and the
//! result is not certified. Junctions are solved numerically (regula falsi on the third
//! contact) and then proven: a disk of radius 1e-10 (or 1e-9) of the size about each holds a
//! point equidistant from three stretches of the boundary, by the winding of the distances'
//! differences round it. Ends at arcs' centres and corners are exact data; an end at a
//! spline's centre of curvature is proven by the sign of the curvature's rate, with bounds,
//! on either side of its foot. No piece is missing where the feet of the edges cover every
//! boundary once round, in order: asked of every axis inside a region. Where a proof fails the
//! axis says `certified: false`, with the reason.
//!
//! With [`MedialOptions::fit`] each edge also comes as one B-spline of the axis and the radius
//! ([`EdgeSpline`]), fitted by least squares within the chord tolerance.

mod assemble;
mod candidates;
mod certificate;
mod corners;
mod coverage;
mod curvature;
#[cfg(test)]
mod differential;
mod error;
mod fans;
mod fit;
mod junction_proof;
mod lines_and_arcs;
mod pairs;
mod pairwise_axis;
mod parallel;
mod seed;
mod sites;
mod stretches;
#[cfg(test)]
mod test_shapes;
mod traced_axis;
mod true_sites;

pub use error::{Error, Result};
pub use fit::EdgeSpline;

use candidates::PairSource;
use curve::Region;
pub use numeric::certificate::{Doubt, Doubts, Verdict};
use numeric::tolerance::Settings;
use serde::{Deserialize, Serialize};
use std::collections::HashSet;

/// Points of the axis within this share of the region's size are one point: ends of
/// stretches (junctions found on different branches, and branches continuing each other,
/// agree to ~1e-12 of the size) are one node, vertices of an edge one vertex.
pub(crate) const SAME_NODE: f64 = 1e-6;

/// Options of [`medial_axis`]: the settings, valid by construction (a tolerance out of range
/// is refused where they are made), and the axis's own choices.
///
/// ```
/// use medial::MedialOptions;
/// use numeric::tolerance::Settings;
/// assert_eq!(Settings::new(1e-12, 0.6, None).unwrap_err().field, "chord_tol");
/// let fine = MedialOptions { settings: Settings::new(1e-12, 1e-4, None).unwrap(), ..MedialOptions::default() };
/// assert_eq!(fine.settings.chord_tol.get(), 1e-4);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MedialOptions {
    /// The tolerances, valid by construction: the parameter tolerance relative to the
    /// domains (default 1e-12, as the bisectors'); the chord tolerance of the edges'
    /// polylines (default 1e-3) relative to the size, the contract's (max(width, height) of
    /// the bounding box of all the input's curves, for one part of a multi-part input), or
    /// without one the region's own ([`curve::Region::size`]).
    pub settings: Settings,
    /// Whether each edge also comes as a B-spline ([`Edge::bspline`]), within the chord
    /// tolerance of the axis: the polylines are then traced to half of it, and the fit kept
    /// within the other half of them.
    pub fit: bool,
    /// Whether the axis sought is the exterior one: of the plane outside the region (beyond
    /// its outer boundary and inside its holes), clipped to the region's box grown by half
    /// its size on every side.
    pub exterior: bool,
}

/// What a node of the axis is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NodeKind {
    /// Three or more edges meet: a disk touching the boundary at three or more points.
    Junction,
    /// A leaf at a centre of curvature of a curvature maximum (or the centre of a disk).
    End,
    /// A leaf at a convex corner.
    Corner,
    /// The one node of a cycle without junctions (an annulus).
    Joint,
    /// A leaf where the exterior axis leaves the box it is clipped to.
    Clip,
}

/// A node of the axis.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Node {
    /// Its index in [`MedialAxis::nodes`].
    pub id: usize,
    /// Where it is.
    pub xy: [f64; 2],
    /// The radius of the largest inscribed disk there.
    pub radius: f64,
    /// What it is.
    pub kind: NodeKind,
    /// The part of a multi-part input it belongs to (absent for one part).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub part: Option<usize>,
}

/// An edge of the axis: a polyline from one node to another.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Edge {
    /// The node it starts at.
    pub from: usize,
    /// The node it ends at.
    pub to: usize,
    /// The vertices.
    pub xy: Vec<[f64; 2]>,
    /// The radius at each vertex.
    pub radius: Vec<f64>,
    /// Per vertex, the parameters of its two nearest boundary points.
    pub feet: Vec<[f64; 2]>,
    /// Per vertex, the boundaries of those points (0 outer, 1.. holes).
    pub boundary: Vec<[usize; 2]>,
    /// The edge as a B-spline of the axis and the radius (with [`MedialOptions::fit`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bspline: Option<EdgeSpline>,
    /// The part of a multi-part input it belongs to (absent for one part).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub part: Option<usize>,
}

/// The medial axis of a region.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MedialAxis {
    /// The nodes.
    pub nodes: Vec<Node>,
    /// The edges.
    pub edges: Vec<Edge>,
    /// The doubts met (none: every trimming decision and the place of every node followed
    /// from sign tests on bounds, see the crate's documentation). Read with
    /// [`Verdict`]: `certified()`, and `reason()` (the first
    /// doubt, stated); the document writes them as its `certified` and, when it is false,
    /// `reason` fields.
    #[serde(flatten)]
    pub doubts: Doubts,
    /// False when a search limit was hit.
    pub complete: bool,
}

numeric::impl_verdict!(
    /// Whether the axis is certified, and why not, read off its doubts.
    ///
    /// ```
    /// use curve::{Profile, Region, Segment};
    /// use medial::{medial_axis, Doubt, MedialOptions, Verdict};
    /// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let region = Region::new(Profile::new(sides, None).unwrap(), vec![]).unwrap();
    /// let mut axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    /// assert!(axis.certified() && axis.reason().is_none());
    /// // A doubt met makes it not certified; the first one met is its reason.
    /// axis.doubts.add(Doubt::SearchLimit);
    /// assert!(!axis.certified());
    /// assert_eq!(axis.reason().as_deref(), Some("a search limit was hit"));
    /// ```
    MedialAxis
);

/// The medial axis of `region`.
///
/// Run under a [`curve::watch::Watch`] ([`curve::watch::Watch::run`]), it reports its stage
/// and units of work there, and stops with [`Error::Cancelled`] soon after the watch is
/// cancelled (at its next pair of pieces, candidate, point tested, step of a search, edge or
/// node of the certificate; a large Voronoi diagram of the seed is left to finish alone on
/// a thread of its own): 13 ms at worst on the inputs of `benches/cancel.rs`, one core.
///
/// ```
/// use curve::{Profile, Region, Segment};
/// use medial::{medial_axis, MedialOptions, NodeKind};
/// // A 4 × 2 rectangle: two junctions joined by the middle line, four corner leaves.
/// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
/// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
/// let region = Region::new(Profile::new(sides, None).unwrap(), vec![]).unwrap();
/// let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
/// let count = |k| axis.nodes.iter().filter(|n| n.kind == k).count();
/// assert_eq!((count(NodeKind::Junction), count(NodeKind::Corner)), (2, 4));
/// assert_eq!(axis.edges.len(), 5);
/// ```
pub fn medial_axis(region: &Region, opts: &MedialOptions) -> Result<MedialAxis> {
    let segments: usize = std::iter::once(region.outer())
        .chain(region.holes())
        .map(|b| b.segments().len())
        .sum();
    if !opts.exterior && segments < SEED_SEGMENTS {
        // (Few lines and arcs: every pair of sites in closed form, standing where certified.)
        let found = axis_of(region, opts, PairSource::Pairwise);
        if curve::watch::cancelled() {
            return Err(Error::Cancelled);
        }
        if let Ok((axis, true)) = found {
            return Ok(axis);
        }
    }
    if !opts.exterior && segments >= SEED_SEGMENTS {
        // (The seed's pairs are a guess: its axis stands where it is certified and its feet
        // cover the boundaries, and is built again from the pairs the bounds keep where not.)
        // (An error on a pair only the seed proposed is no answer either.)
        for source in [PairSource::SeedEdges, PairSource::Seed] {
            let found = axis_of(region, opts, source);
            if curve::watch::cancelled() {
                return Err(Error::Cancelled);
            }
            if let Ok((axis, true)) = found {
                return Ok(axis);
            }
        }
    }
    let axis = axis_of(region, opts, PairSource::Bounds)?.0;
    // (A cancelled search stopped early: what it found is no answer.)
    if curve::watch::cancelled() {
        return Err(Error::Cancelled);
    }
    Ok(axis)
}

/// An axis of nothing, uncertified (what a path that cannot be taken returns, with "does
/// not stand").
fn empty_axis() -> MedialAxis {
    MedialAxis {
        nodes: Vec::new(),
        edges: Vec::new(),
        doubts: Doubt::SearchLimit.into(),
        complete: false,
    }
}

/// From this many boundary segments on, the pairs come from the seed: below, the bounds'
/// tree costs less than the Voronoi diagram of the chords (~20 µs a chord).
const SEED_SEGMENTS: usize = 48;

/// The medial axis of `region` from the bisectors of the pairs of segments `source` gives;
/// whether it stands: its pairs were not guessed (by the seed, or by the closed-form paths'
/// own search), or it is certified (its feet covering the boundaries, [`coverage`]) and no
/// stretches were joined across feet that differ.
fn axis_of(
    region: &Region,
    opts: &MedialOptions,
    source: PairSource,
) -> Result<(MedialAxis, bool)> {
    let mut sites = sites::Sites::new(region, opts.exterior);
    if let Some(size) = opts.settings.size {
        sites.size = size.get();
    }
    // (With a fit, the polylines are traced to half the tolerance: it may be finer than a
    // chord tolerance can be set.)
    let chord_tol = opts.settings.chord_tol.get() * if opts.fit { 0.5 } else { 1.0 };
    let closed_form = match source {
        PairSource::SeedEdges => Some(traced_axis::trace(&sites, chord_tol)),
        PairSource::Pairwise => Some(pairwise_axis::pairwise(&sites, chord_tol)),
        _ => None,
    };
    let (found, pieces, complete, guessed, proven, merge) = if let Some(traced) = closed_form {
        match traced {
            Some(t) => (
                t.candidates,
                t.stretches,
                true,
                true,
                t.proven,
                lines_and_arcs::SAME_SEED_NODE,
            ),
            None => return Ok((empty_axis(), false)),
        }
    } else {
        let (found, complete, guessed) =
            candidates::candidates(&sites, (opts.settings.tol, chord_tol), source)?;
        let pieces = stretches::stretches(&sites, &found);
        (found, pieces, complete, guessed, HashSet::new(), SAME_NODE)
    };
    // (A cancelled search found a part: nothing is built from it, its caller answers
    // "cancelled".)
    if curve::watch::cancelled() {
        // (What was found may be large, and freeing it takes tens of milliseconds: that is
        // done off the caller's path, which must answer the cancel at once.)
        std::thread::spawn(move || drop((found, pieces)));
        return Ok((empty_axis(), false));
    }
    let _stage = curve::watch::stage("medial axis: the edges joined at their nodes");
    let (mut axis, loose_join) = assemble::assemble(&sites, pieces, &found, merge);
    axis.complete &= complete;
    // (The first doubt met is the one the axis states: the checks run in that order.)
    let doubt = if !axis.complete {
        Some(Doubt::SearchLimit)
    } else if !opts.exterior && !certificate::shaped_like_the_region(&axis, region.holes().len()) {
        Some(Doubt::AxisGraph { unreached: None })
    } else {
        // (The nodes' proofs test disks too: whether any disk was undecided is asked after.)
        let at_node = certificate::doubt(&sites, &axis, opts.settings.tol.get(), &proven);
        if sites.some_disk_undecided() {
            Some(Doubt::DiskByNearest)
        } else if at_node.is_some() {
            at_node
        } else if !opts.exterior
            && !axis.edges.is_empty()
            && coverage::feet_cover(&sites, &axis).is_err()
        {
            // (Whatever path found the pairs: a bisector the candidates missed leaves a gap.
            // An axis of one node and no edge has no feet: its node is proven at the centre
            // of a boundary that is one circle.)
            Some(Doubt::Coverage { unreached: None })
        } else {
            None
        }
    };
    if curve::watch::cancelled() {
        return Ok((empty_axis(), false));
    }
    // (Where a piece may be missing, the reason names the first corner no leaf reaches.)
    let doubts: Doubts = doubt
        .map(|d| certificate::placed(d, &sites, &axis))
        .into_iter()
        .collect();
    axis.doubts = doubts;
    if opts.fit {
        let tol = chord_tol * sites.size;
        for e in &mut axis.edges {
            e.bspline = Some(fit::fit_edge(&e.xy, &e.radius, tol));
        }
    }
    let stands = !guessed || (axis.certified() && !loose_join);
    Ok((axis, stands))
}
