//! Inward offsets of planar regions from their medial axis: the boundary of the points of the
//! region at distance at least `d` from its boundary, as closed loops of lines, arcs and
//! curves.
//!
//! The medial axis knows the offset's shape before any curve is drawn. A point of the axis
//! with radius `d` is where the offset meets itself (a *seam*): there the offsets of the two
//! boundary points nearest to it coincide. Every boundary point whose inscribed disk (the
//! largest empty one touching it) is wider than `d` offsets to a point of the result, and no
//! other does. So each loop is made of stretches of boundary between seams, each offset as it
//! is (a line stays a line, an arc an arc about the same centre, a reflex corner becomes an
//! arc of radius `d` about it), joined across the seams. Nothing is intersected, and nothing
//! can cross.
//!
//! ```
//! use curve::{Profile, Region, Segment};
//! use medial::{medial_axis, MedialOptions};
//! use offset::{offsets, OffsetOptions};
//! // A 4 × 2 rectangle offset by 0.5: a 3 × 1 rectangle of four lines.
//! let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
//! let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
//! let region = Region::new(Profile::new(sides, None).unwrap(), vec![]).unwrap();
//! let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
//! let found = offsets(&region, &axis, &[0.5], &OffsetOptions::default()).unwrap();
//! assert_eq!(found.offsets[0].loops.len(), 1);
//! assert_eq!(found.offsets[0].loops[0].segments.len(), 4);
//! ```

mod cusps;
mod joints;
mod loops;
mod necks;
mod offset_loop;
mod pieces;
mod read_back;
mod seams;
mod spline_offset;
mod vcarve;
mod walk;
mod widest;

pub use offset_loop::{OffsetLoop, OffsetSegment};
pub use vcarve::{vcarve, VCarve, VCarveOptions, VCarvePath};

use curve::{ParamCurve, Profile, Region};
use medial::MedialAxis;
pub use numeric::certificate::{Doubt, Doubts, Verdict};
use numeric::tolerance::{Settings, Size};
use read_back::{read_back, ReadBack};
use serde::{Deserialize, Serialize};
use thiserror::Error;
use walk::Walk;
use widest::{encloses, isolated_nodes, widest_per_boundary};

/// Times the chord tolerance is quartered for a loop whose fitted pieces cross.
const REFITS: usize = 6;

/// Options of the offsets: the settings, valid by construction. The chord tolerance
/// (`settings.chord_tol`) is the largest distance between an offset curve of a spline and
/// the exact offset (lines and arcs are offset exactly), relative to the size
/// (`settings.size`: the contract's, max(width, height) of the bounding box of all the
/// input's curves, for one part of a multi-part input; `None`: the region's own,
/// [`curve::Region::size`]).
///
/// ```
/// use numeric::tolerance::Settings;
/// use offset::OffsetOptions;
/// assert_eq!(OffsetOptions::default().settings.chord_tol.get(), 1e-3);
/// // A chord tolerance out of range is refused where the settings are made.
/// assert_eq!(Settings::new(1e-12, 1e-12, None).unwrap_err().field, "chord_tol");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OffsetOptions {
    /// The tolerances and the size.
    pub settings: Settings,
}

/// The offset at one distance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Offset {
    /// The distance.
    pub distance: f64,
    /// The loops (none: the region vanishes at this distance).
    pub loops: Vec<OffsetLoop>,
    /// The largest distance measured between a spline's offset piece and the exact offset
    /// (0 where every piece is a line or an arc, which are exact).
    pub error: f64,
}

/// The offsets at several distances of one region.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Offsets {
    /// One per distance asked, in the order asked.
    pub offsets: Vec<Offset>,
    /// The doubts met (none: the axis was certified and every seam closed by Newton's
    /// method). Where the axis is not certified, [`Doubt::AxisUncertified`] comes first and
    /// the axis's own doubts after it. Read with
    /// [`Verdict`]: `certified()`, and `reason()` (the first
    /// doubt, stated); the document writes them as its `certified` and, when it is false,
    /// `reason` fields.
    #[serde(flatten)]
    pub doubts: Doubts,
    /// Whether the axis was complete and the seams joined into loops.
    pub complete: bool,
}

numeric::impl_verdict!(Offsets);

/// Why offsets could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A distance or an option out of range.
    #[error("{field}: {value} is out of range: {why}")]
    BadOption {
        /// The option.
        field: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        why: &'static str,
    },
    /// An axis that is not one of this region's (arrays of unequal lengths, numbers not
    /// finite, a boundary or a foot out of range).
    #[error("the medial axis does not fit the region: {0}")]
    BadAxis(String),
    /// The work was cancelled through its watch ([`curve::watch`]).
    #[error("cancelled")]
    Cancelled,
}

/// The inward offsets of `region` at each of `distances`, from its medial axis `axis`
/// (computed by [`medial::medial_axis`], not the exterior one).
///
/// ```
/// use curve::{Profile, Region, Segment};
/// use medial::{medial_axis, MedialOptions};
/// use offset::{offsets, OffsetOptions, OffsetSegment, Verdict};
/// // A disk of radius 2 offset by 0.5 and by 3: a circle of radius 1.5, then nothing.
/// let circle = Segment::arc([1.0, -1.0], 2.0, 0.0, std::f64::consts::TAU).unwrap();
/// let region = Region::new(Profile::new(vec![circle], None).unwrap(), vec![]).unwrap();
/// let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
/// let found = offsets(&region, &axis, &[0.5, 3.0], &OffsetOptions::default()).unwrap();
/// assert!(found.certified());
/// let ring = &found.offsets[0].loops[0];
/// assert!(ring.segments.iter().all(|s| matches!(s, OffsetSegment::Arc { r, .. }
///     if (r - 1.5).abs() < 1e-12)));
/// assert!(found.offsets[1].loops.is_empty());
/// ```
pub fn offsets(
    region: &Region,
    axis: &MedialAxis,
    distances: &[f64],
    opts: &OffsetOptions,
) -> Result<Offsets, Error> {
    offsets_on(region, axis, distances, opts, false)
}

/// The outward offsets of `region` at each of `distances` (the boundary of the points within
/// the distance of the region: round its outer boundary, and inside its holes), from its
/// exterior medial axis `exterior` (computed by [`medial::medial_axis`] with
/// `exterior: true`). That axis is clipped to the region's box grown by half its size, so the
/// distances must stay below half the size.
///
/// ```
/// use curve::{Profile, Region, Segment};
/// use medial::{medial_axis, MedialOptions};
/// use offset::{outward_offsets, OffsetOptions, OffsetSegment};
/// // A 4 × 2 rectangle grown by 0.5: its four sides moved out, joined by quarter circles
/// // about its corners.
/// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
/// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
/// let region = Region::new(Profile::new(sides, None).unwrap(), vec![]).unwrap();
/// let opts = MedialOptions { exterior: true, ..MedialOptions::default() };
/// let exterior = medial_axis(&region, &opts).unwrap();
/// let found = outward_offsets(&region, &exterior, &[0.5], &OffsetOptions::default()).unwrap();
/// let grown = &found.offsets[0].loops[0];
/// let arcs = grown.segments.iter().filter(|s| matches!(s, OffsetSegment::Arc { .. }));
/// assert_eq!((grown.segments.len(), arcs.count()), (8, 4));
/// ```
pub fn outward_offsets(
    region: &Region,
    exterior: &MedialAxis,
    distances: &[f64],
    opts: &OffsetOptions,
) -> Result<Offsets, Error> {
    let half = 0.5 * region.size();
    if let Some(&far) = distances.iter().find(|&&d| d >= half) {
        return Err(Error::BadOption {
            field: "distance",
            value: far,
            why: "outward, must stay below half the region's size (the exterior axis's margin)",
        });
    }
    let mut found = offsets_on(region, exterior, distances, opts, true)?;
    // (Walked with the outside on the left: turned round, the grown region is on the left.)
    for o in &mut found.offsets {
        for l in &mut o.loops {
            l.segments.reverse();
            for s in &mut l.segments {
                match s {
                    OffsetSegment::Line { from, to } => std::mem::swap(from, to),
                    OffsetSegment::Arc { start, end, .. } => std::mem::swap(start, end),
                    OffsetSegment::BSpline { knots, points, .. } => {
                        points.reverse();
                        knots.reverse();
                        for k in knots.iter_mut() {
                            *k = 1.0 - *k;
                        }
                    }
                }
            }
        }
    }
    Ok(found)
}

/// The offsets inward, or `outward`, from the axis on that side, with the doubts met (the
/// axis's among them).
pub(crate) fn offsets_on(
    region: &Region,
    axis: &MedialAxis,
    distances: &[f64],
    opts: &OffsetOptions,
    outward: bool,
) -> Result<Offsets, Error> {
    if let Some(&bad) = distances.iter().find(|d| !(d.is_finite() && **d > 0.0)) {
        return Err(Error::BadOption {
            field: "distance",
            value: bad,
            why: "must be a finite number > 0",
        });
    }
    check_axis(region, axis)?;
    let walks: Vec<Walk<'_>> = std::iter::once(Walk::new(region.outer(), false, outward))
        .chain(region.holes().iter().map(|h| Walk::new(h, true, outward)))
        .collect();
    let size = opts.settings.size.map_or_else(|| region.size(), Size::get);
    let chord = opts.settings.chord_tol.get() * size;
    let mut widest = widest_per_boundary(axis, walks.len(), outward);
    if outward {
        // (A round hole's part of the exterior axis is one node at its centre, with no edge to
        // say which boundary it touches: the hole holding it.)
        for node in isolated_nodes(axis) {
            if let Some(k) = region.holes().iter().position(|h| encloses(h, node.xy)) {
                widest[k + 1] = node.radius;
            }
        }
        // (The exterior axis may leave that node out: a round hole's widest disk is itself.)
        for (k, hole) in region.holes().iter().enumerate() {
            if let ([only], true) = (hole.segments(), widest[k + 1].is_infinite()) {
                if let Some((_, r)) = only.circle() {
                    widest[k + 1] = r;
                }
            }
        }
    }
    let mut all_closed = true;
    let mut necks_resolved = true;
    let mut widest_error = 0.0f64;
    let mut not_a_profile: Option<curve::Error> = None;
    let mut loops_apart = true;
    let mut consistent = true;
    let mut loops_bridged = false;
    let mut loops_left_out = false;
    let mut found = Vec::with_capacity(distances.len());
    let stage = curve::watch::stage("offsets: one distance each");
    for &d in distances {
        if !stage.go_on(1) {
            return Err(Error::Cancelled);
        }
        let Some((seams, neck_resolved)) = seams::seams(axis, &walks, d, size) else {
            consistent = false;
            found.push(Offset {
                distance: d,
                loops: Vec::new(),
                error: 0.0,
            });
            continue;
        };
        all_closed &= seams.iter().all(|s| s.refined);
        let neck_here = !neck_resolved;
        necks_resolved &= neck_resolved;
        let kept_whole: Vec<bool> = widest
            .iter()
            .map(|&w| w > d + necks::TOUCHING * size)
            .collect();
        let assembled = loops::loops(&walks, &seams, &kept_whole);
        consistent &= assembled.consistent;
        // The loops within `tolerance` of the exact offset where measured, and that distance;
        // a loop whose pieces do not meet is bridged, or left out (see `joints::bridge`).
        let mut gaps = joints::Closure::Closed;
        let mut build = |tolerance: f64| {
            let mut error = 0.0;
            gaps = joints::Closure::Closed;
            let loops: Vec<OffsetLoop> = assembled
                .loops
                .iter()
                .filter_map(|stretches| {
                    let mut segments = Vec::new();
                    for stretch in stretches {
                        let walk = &walks[stretch.boundary];
                        pieces::pieces(walk, stretch, d, tolerance, &mut segments, &mut error);
                    }
                    cusps::blunt(&mut segments, cusps::HORN_CUT * size);
                    joints::close(&mut segments);
                    let closure = joints::bridge(&mut segments, tolerance);
                    gaps = gaps.max(closure);
                    (closure != joints::Closure::Open).then_some(OffsetLoop {
                        segments,
                        part: None,
                    })
                })
                .collect();
            (loops, error)
        };
        // A fitted piece strays from the exact offset by up to the tolerance: across a sliver
        // narrower than that (between nearly parallel sides) it may cross the piece opposite.
        // Such loops are fitted again, finer, up to 4^-REFITS of the tolerance. (Loops of lines
        // and arcs are exact offsets, simple by construction: only loops with fitted pieces
        // are read back as the reader would.)
        let (mut loops, mut error) = build(chord);
        let mut verdict = read_back(&loops);
        let mut tolerance = chord;
        // (Not where a neck may pinch the loops: they cross there however fine the fit.)
        for _ in 0..REFITS {
            if verdict != ReadBack::Crossing || neck_here {
                break;
            }
            tolerance *= 0.25;
            (loops, error) = build(tolerance);
            verdict = read_back(&loops);
        }
        match verdict {
            ReadBack::Simple => {}
            ReadBack::Crossing => loops_apart = false,
            ReadBack::Refused(bad) => {
                not_a_profile.get_or_insert(bad);
            }
        }
        match gaps {
            joints::Closure::Closed => {}
            joints::Closure::Bridged => loops_bridged = true,
            joints::Closure::Open => {
                loops_left_out = true;
                consistent = false;
            }
        }
        widest_error = widest_error.max(error);
        found.push(Offset {
            distance: d,
            loops,
            error,
        });
    }
    // The doubts in the order they are stated: the first is the reason.
    let mut doubts = Doubts::none();
    if !axis.certified() {
        // (The axis's own doubts after it, as values: the reason stays this one.)
        doubts.add(Doubt::AxisUncertified);
        doubts.join(axis.doubts.clone());
    }
    if !all_closed {
        doubts.add(Doubt::SeamUnconverged);
    }
    if loops_left_out {
        doubts.add(Doubt::LoopLeftOut);
    }
    if loops_bridged {
        doubts.add(Doubt::LoopBridged);
    }
    if widest_error > chord {
        doubts.add(Doubt::OffsetError {
            error: widest_error,
        });
    }
    if let Some(bad) = not_a_profile {
        doubts.add(Doubt::LoopNotAProfile {
            why: bad.to_string(),
        });
    }
    // (Before the loops' crossings: across an unresolved neck they cross in truth.)
    if !necks_resolved {
        doubts.add(Doubt::NeckUnresolved);
    }
    if !loops_apart {
        doubts.add(Doubt::LoopsCross);
    }
    Ok(Offsets {
        offsets: found,
        doubts,
        complete: axis.complete && consistent,
    })
}

/// Checks that `axis` can be one of `region`'s, so that reading it cannot fail: per edge,
/// one radius, pair of feet and pair of boundaries per vertex, all numbers finite, radii not
/// negative, boundaries the region's and feet within their parameter domains.
pub(crate) fn check_axis(region: &Region, axis: &MedialAxis) -> Result<(), Error> {
    let boundaries: Vec<&Profile> = std::iter::once(region.outer())
        .chain(region.holes())
        .collect();
    let bad = |what: String| Err(Error::BadAxis(what));
    for (i, n) in axis.nodes.iter().enumerate() {
        if !(n.xy.iter().all(|c| c.is_finite()) && n.radius.is_finite() && n.radius >= 0.0) {
            return bad(format!(
                "node {i}: a coordinate or its radius is not a finite number"
            ));
        }
    }
    for (i, e) in axis.edges.iter().enumerate() {
        let n = e.xy.len();
        if e.radius.len() != n || e.feet.len() != n || e.boundary.len() != n {
            return bad(format!(
                "edge {i}: {n} vertices, {} radii, {} feet, {} boundaries",
                e.radius.len(),
                e.feet.len(),
                e.boundary.len()
            ));
        }
        if e.from >= axis.nodes.len() || e.to >= axis.nodes.len() {
            return bad(format!("edge {i}: a node out of range"));
        }
        for k in 0..n {
            let finite = e.xy[k].iter().all(|c| c.is_finite()) && e.radius[k].is_finite();
            if !finite || e.radius[k] < 0.0 {
                return bad(format!(
                    "edge {i}, vertex {k}: not a finite point and radius"
                ));
            }
            for (b, u) in e.boundary[k].iter().zip(e.feet[k]) {
                let Some(profile) = boundaries.get(*b) else {
                    return bad(format!("edge {i}, vertex {k}: no boundary {b}"));
                };
                let (lo, hi) = profile.domain();
                if !(lo..=hi).contains(&u) {
                    return bad(format!(
                        "edge {i}, vertex {k}: foot {u} outside boundary {b}'s [{lo}, {hi}]"
                    ));
                }
            }
        }
    }
    Ok(())
}
