//! V-carving: the tool path of a V-bit, from the medial axis.
//!
//! A V-bit of included angle `A` plunged to depth `z` cuts a disk of radius `|z|·tan(A/2)`
//! at the surface. Centred on a point of the medial axis with radius `r`, at depth
//! `z = −r / tan(A/2)`, it cuts the largest disk of the region centred there: nothing outside
//! the region, and, swept along the whole axis, every point of the region (every point lies
//! in some maximal disk). With a largest depth `H` the bit cannot reach the disks wider than
//! `R = H·tan(A/2)`: the paths over the axis stop where its radius reaches `R`, at depth `−H`,
//! on the offset at distance `R` (where the axis's radius is exactly `R`); that offset is the
//! *flat* pass at that depth, a path of its own and listed apart. The surface then keeps,
//! uncut, the points farther than `2R` from the boundary: a flat-bottomed pocket for another
//! tool.

use crate::{Error, OffsetLoop, OffsetOptions};
use curve::Region;
use medial::MedialAxis;
use numeric::certificate::Doubts;
use serde::{Deserialize, Serialize};

/// Options of [`vcarve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VCarveOptions {
    /// The bit's included angle, in degrees (strictly between 0 and 180).
    pub angle: f64,
    /// The deepest cut, in the drawing's units (`None`: as deep as the axis goes).
    pub max_depth: Option<f64>,
    /// The options of the flat pass's offset.
    pub offset: OffsetOptions,
}

/// One tool path: points over the medial axis, each at its depth (`z ≤ 0`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VCarvePath {
    /// The points `[x, y, z]`, in cutting order.
    pub xyz: Vec<[f64; 3]>,
    /// The part of a multi-part input it belongs to (0 for one part).
    pub part: usize,
}

/// The V-carving tool paths of a region.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VCarve {
    /// The bit's included angle (degrees).
    pub angle: f64,
    /// The deepest cut asked for.
    pub max_depth: Option<f64>,
    /// The paths: over the axis, then along each flat pass at `−max_depth`.
    pub paths: Vec<VCarvePath>,
    /// The flat passes at depth `−max_depth`: the offset at `max_depth·tan(angle/2)` (none
    /// where the axis never gets that deep).
    pub flats: Vec<OffsetLoop>,
    /// The doubts met (none: the axis and the flat passes' offset are certified): the
    /// axis's own first, then the flat passes'. Read with
    /// [`Verdict`](numeric::certificate::Verdict): `certified()`, and `reason()` (the first
    /// doubt, stated: where the axis is not certified, its own reason); the document writes
    /// them as its `certified` and, when it is false, `reason` fields.
    #[serde(flatten)]
    pub doubts: Doubts,
    /// Whether the axis (and the offset) are complete.
    pub complete: bool,
}

numeric::impl_verdict!(VCarve);

impl VCarveOptions {
    /// The options checked: the angle in (0°, 180°), the depth finite and positive.
    pub fn validate(&self) -> Result<(), Error> {
        if !(self.angle.is_finite() && self.angle > 0.0 && self.angle < 180.0) {
            return Err(Error::BadOption {
                field: "angle",
                value: self.angle,
                why: "must be an included angle in degrees, strictly between 0 and 180",
            });
        }
        // (A bit so narrow that tan(A/2) is no normal number would cut at infinite depth.)
        if !self.spread().is_normal() {
            return Err(Error::BadOption {
                field: "angle",
                value: self.angle,
                why: "is too narrow: its depths are not finite numbers",
            });
        }
        if let Some(h) = self.max_depth {
            if !(h.is_finite() && h > 0.0) {
                return Err(Error::BadOption {
                    field: "max_depth",
                    value: h,
                    why: "must be a finite depth > 0",
                });
            }
        }
        Ok(())
    }

    /// `tan(A/2)`: the radius the bit cuts at the surface per unit of depth.
    pub fn spread(&self) -> f64 {
        (0.5 * self.angle).to_radians().tan()
    }

    /// The widest disk the bit reaches: `H·tan(A/2)` (infinite without a depth limit).
    pub fn widest(&self) -> f64 {
        self.max_depth.map_or(f64::INFINITY, |h| h * self.spread())
    }
}

/// The V-carving tool paths of `region` from its medial axis `axis` (the inner one, as
/// [`medial::medial_axis`] computes it).
///
/// ```
/// use curve::{Profile, Region, Segment};
/// use medial::{medial_axis, MedialOptions};
/// use offset::{vcarve, OffsetOptions, VCarveOptions, Verdict};
/// // A 4 × 2 rectangle with a 90° bit: 1 deep along the middle line, 0 at the corners.
/// let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]];
/// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
/// let region = Region::new(Profile::new(sides, None).unwrap(), vec![]).unwrap();
/// let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
/// let opts = VCarveOptions { angle: 90.0, max_depth: None, offset: OffsetOptions::default() };
/// let carve = vcarve(&region, &axis, &opts).unwrap();
/// let deepest = carve.paths.iter().flat_map(|p| &p.xyz).map(|p| p[2]).fold(0.0, f64::min);
/// assert!((deepest + 1.0).abs() < 1e-9);
/// assert!(carve.flats.is_empty() && carve.certified());
/// ```
pub fn vcarve(region: &Region, axis: &MedialAxis, opts: &VCarveOptions) -> Result<VCarve, Error> {
    opts.validate()?;
    crate::check_axis(region, axis)?;
    let spread = opts.spread();
    let widest = opts.widest();
    let pieces = clipped_pieces(axis, widest);
    // (The depth of the widest disk, `−r / tan(A/2)`, may round below `−H`: held there.)
    let deepest_cut = opts.max_depth.map_or(f64::NEG_INFINITY, |h| -h);
    let mut paths: Vec<VCarvePath> = chained(pieces)
        .into_iter()
        .map(|points| VCarvePath {
            xyz: points
                .into_iter()
                .map(|(xy, r)| [xy[0], xy[1], (-r / spread).max(deepest_cut)])
                .collect(),
            part: 0,
        })
        .collect();
    let mut complete = axis.complete;
    // (The axis's doubts as values, first: where the axis is not certified the carve states
    // its reason, as it did when that reason was a string. The flat passes' follow.)
    let mut doubts = axis.doubts.clone();
    let mut flats = Vec::new();
    if let Some(depth) = opts.max_depth {
        // (Asked whenever there is a limit: where the axis never reaches it the region has
        // no offset there and the loops are none; the offset's own doubts, a neck between
        // vertices, say whether it does.)
        let found = crate::offsets_on(region, axis, &[widest], &opts.offset, false)?;
        complete &= found.complete;
        doubts.join(found.doubts);
        flats = found.offsets.into_iter().flat_map(|o| o.loops).collect();
        // Where the axis is deeper, the path follows the flat pass at −H (the contract's
        // "Output files and V-carving"), within the chord tolerance of it.
        let size = opts
            .offset
            .settings
            .size
            .map_or_else(|| region.size(), numeric::tolerance::Size::get);
        for l in &flats {
            let ring = l
                .flattened(opts.offset.settings.chord_tol.get() * size)
                .map_err(|e| Error::BadAxis(format!("a flat pass is no loop of curves: {e}")))?;
            paths.push(VCarvePath {
                xyz: ring.into_iter().map(|p| [p[0], p[1], -depth]).collect(),
                part: l.part.unwrap_or(0),
            });
        }
    }
    Ok(VCarve {
        angle: opts.angle,
        max_depth: opts.max_depth,
        paths,
        flats,
        doubts,
        complete,
    })
}

/// A run of axis points `(xy, radius)`, and the nodes it starts and ends at (`None` where it
/// was clipped).
struct AxisRun {
    points: Vec<([f64; 2], f64)>,
    ends: [Option<usize>; 2],
}

/// The runs of the axis's edges where the radius is at most `widest`, each cut where it
/// crosses `widest` (between two vertices, linearly: the polyline is the axis within its
/// chord tolerance, and the radius along it).
fn clipped_pieces(axis: &MedialAxis, widest: f64) -> Vec<AxisRun> {
    let mut pieces = Vec::new();
    for e in &axis.edges {
        let n = e.xy.len().min(e.radius.len());
        let mut run: Vec<([f64; 2], f64)> = Vec::new();
        let mut start = Some(e.from);
        for i in 0..n {
            let (xy, r) = (e.xy[i], e.radius[i]);
            if r <= widest {
                if run.is_empty() && i > 0 {
                    // (Entering from beyond: the crossing first, unless this is it.)
                    start = None;
                    if r < widest {
                        run.push(crossing((e.xy[i - 1], e.radius[i - 1]), (xy, r), widest));
                    }
                }
                run.push((xy, r));
            } else if !run.is_empty() {
                let last = run[run.len() - 1];
                if last.1 < widest {
                    run.push(crossing(last, (xy, r), widest));
                }
                // (A vertex exactly at the widest disk between two beyond it is no path:
                // the flat pass goes through it.)
                if run.len() >= 2 {
                    pieces.push(AxisRun {
                        points: std::mem::take(&mut run),
                        ends: [start, None],
                    });
                }
                run.clear();
            }
        }
        if run.len() >= 2 {
            pieces.push(AxisRun {
                points: run,
                ends: [start, Some(e.to)],
            });
        }
    }
    // (A node no edge reaches, the centre of a disk, is one plunge.)
    let reached: std::collections::HashSet<usize> =
        axis.edges.iter().flat_map(|e| [e.from, e.to]).collect();
    for n in &axis.nodes {
        if !reached.contains(&n.id) && n.radius <= widest {
            pieces.push(AxisRun {
                points: vec![(n.xy, n.radius)],
                ends: [None, None],
            });
        }
    }
    pieces
}

/// The point between `a` (radius at most `widest`) and `b` (beyond it) where the radius is
/// `widest`.
fn crossing(a: ([f64; 2], f64), b: ([f64; 2], f64), widest: f64) -> ([f64; 2], f64) {
    let f = ((widest - a.1) / (b.1 - a.1)).clamp(0.0, 1.0);
    (
        [
            a.0[0] + f * (b.0[0] - a.0[0]),
            a.0[1] + f * (b.0[1] - a.0[1]),
        ],
        widest,
    )
}

/// The pieces joined end to end through the nodes they share, so that the tool lifts less:
/// each path starts with the first piece not yet cut and goes on, at its end node, along the
/// first piece there not yet cut (turned round where it ends there), as long as there is one.
fn chained(pieces: Vec<AxisRun>) -> Vec<Vec<([f64; 2], f64)>> {
    let mut at_node: std::collections::HashMap<usize, Vec<usize>> = Default::default();
    for (i, p) in pieces.iter().enumerate() {
        for node in p.ends.iter().flatten() {
            at_node.entry(*node).or_default().push(i);
        }
    }
    let mut used = vec![false; pieces.len()];
    let mut paths = Vec::new();
    for first in 0..pieces.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let mut path = pieces[first].points.clone();
        let mut end = pieces[first].ends[1];
        // (Each step takes a piece not yet used: at most as many steps as pieces.)
        while let Some(node) = end {
            let next = at_node
                .get(&node)
                .and_then(|list| list.iter().copied().find(|&j| !used[j]));
            let Some(j) = next else { break };
            used[j] = true;
            let p = &pieces[j];
            if p.ends[0] == Some(node) {
                path.extend(p.points.iter().skip(1).copied());
                end = p.ends[1];
            } else {
                path.extend(p.points.iter().rev().skip(1).copied());
                end = p.ends[0];
            }
        }
        paths.push(path);
    }
    paths
}

#[cfg(test)]
mod tests {
    use super::*;
    use medial::{Edge, Node, NodeKind};

    fn node(id: usize, xy: [f64; 2], radius: f64) -> Node {
        Node {
            id,
            xy,
            radius,
            kind: NodeKind::Junction,
            part: None,
        }
    }

    fn edge(from: usize, to: usize, xy: Vec<[f64; 2]>, radius: Vec<f64>) -> Edge {
        let n = xy.len();
        Edge {
            from,
            to,
            xy,
            radius,
            feet: vec![[0.0; 2]; n],
            boundary: vec![[0; 2]; n],
            bspline: None,
            part: None,
        }
    }

    /// A path that rises over a hump beyond the widest disk is cut in two, each cut at the
    /// radius `widest` where the polyline crosses it.
    #[test]
    fn an_edge_deeper_than_allowed_is_cut_at_the_widest_disk() {
        let axis = MedialAxis {
            nodes: vec![node(0, [0.0, 0.0], 0.0), node(1, [4.0, 0.0], 0.0)],
            edges: vec![edge(
                0,
                1,
                vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0], [4.0, 0.0]],
                vec![0.0, 1.0, 2.0, 1.0, 0.0],
            )],
            doubts: Doubts::none(),
            complete: true,
        };
        let pieces = clipped_pieces(&axis, 1.5);
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0].ends, [Some(0), None]);
        assert_eq!(pieces[1].ends, [None, Some(1)]);
        assert_eq!(pieces[0].points.last().copied(), Some(([1.5, 0.0], 1.5)));
        assert_eq!(pieces[1].points.first().copied(), Some(([2.5, 0.0], 1.5)));
        // Without a limit: one piece, the whole edge.
        let whole = clipped_pieces(&axis, f64::INFINITY);
        assert_eq!(whole.len(), 1);
        assert_eq!(whole[0].points.len(), 5);
    }

    /// Three edges at a junction become two paths: one through the junction, one from it.
    #[test]
    fn pieces_sharing_a_node_are_cut_in_one_path() {
        let axis = MedialAxis {
            nodes: vec![
                node(0, [0.0, 0.0], 1.0),
                node(1, [-1.0, 0.0], 0.0),
                node(2, [1.0, 1.0], 0.0),
                node(3, [1.0, -1.0], 0.0),
            ],
            edges: vec![
                edge(1, 0, vec![[-1.0, 0.0], [0.0, 0.0]], vec![0.0, 1.0]),
                edge(2, 0, vec![[1.0, 1.0], [0.0, 0.0]], vec![0.0, 1.0]),
                edge(0, 3, vec![[0.0, 0.0], [1.0, -1.0]], vec![1.0, 0.0]),
            ],
            doubts: Doubts::none(),
            complete: true,
        };
        let paths = chained(clipped_pieces(&axis, f64::INFINITY));
        assert_eq!(paths.len(), 2);
        let xy: Vec<[f64; 2]> = paths[0].iter().map(|p| p.0).collect();
        assert_eq!(xy, vec![[-1.0, 0.0], [0.0, 0.0], [1.0, 1.0]]);
        let xy: Vec<[f64; 2]> = paths[1].iter().map(|p| p.0).collect();
        assert_eq!(xy, vec![[0.0, 0.0], [1.0, -1.0]]);
    }

    #[test]
    fn options_out_of_range_are_refused() {
        let ok = VCarveOptions {
            angle: 60.0,
            max_depth: Some(1.0),
            offset: OffsetOptions::default(),
        };
        assert!(ok.validate().is_ok());
        for angle in [0.0, 180.0, -30.0, f64::NAN, 200.0] {
            let e = VCarveOptions { angle, ..ok }.validate().unwrap_err();
            assert!(
                matches!(e, Error::BadOption { field: "angle", .. }),
                "{angle}"
            );
        }
        for h in [0.0, -1.0, f64::INFINITY] {
            let e = VCarveOptions {
                max_depth: Some(h),
                ..ok
            }
            .validate()
            .unwrap_err();
            assert!(
                matches!(
                    e,
                    Error::BadOption {
                        field: "max_depth",
                        ..
                    }
                ),
                "{h}"
            );
        }
    }
}
