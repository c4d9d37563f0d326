//! The topology seed: the Voronoi diagram of a linear approximation of the boundaries, read for
//! the pairs of boundary segments whose bisectors carry the axis. It names O(n) pairs in
//! O(n log n), where the bounds of [`crate::pairs`] keep every pair that distances alone
//! cannot part (beside a wide disk, most of them).
//!
//! The diagram is boostvoronoi's (Boost.Polygon's sweep line, ported): segments on integer
//! coordinates with exact predicates, so its topology is that of the snapped chords whatever
//! their configuration. (spade, the other candidate, triangulates points under constraints; the
//! dual of that triangulation is the Voronoi diagram of points, not of segments, and would need
//! every line sampled densely to stand for its segment, with the pairs read back from samples.)
//! Lines are one chord each; arcs and splines are chords within [`CHORD_SAG`] of the size and
//! [`CHORD_TURN`] of turn. Every chord end is a point site of the diagram: at a joint of two
//! segments it stands for both (a reflex corner, whose bisectors the bisector code computes as
//! the corner of either segment).
//!
//! The seed is a guess: the snapped chords are not the boundary, and the port has known faults
//! of its own. The axis built from it is proven complete by its feet covering the boundary
//! ([`crate::coverage`]); where they do not, the axis is built again from every pair the bounds
//! keep. A seed that cannot be made (a boundary snapped to fewer than three points, a
//! diagram the port refuses) is `None`, and the bounds are used from the start. Snapped
//! chords that cross (a hole nearer a curved side than the chords' sag) are not yet looked
//! for before the diagram is built: the port's diagram of them is a guess like any other,
//! refused by the coverage where it misleads.

use crate::pairs::{Neighbours, SegmentId};
use boostvoronoi::prelude::{Builder, Diagram, EdgeIndex, Line, SourceCategory};
use curve::{Profile, SegmentKind, V2};
use numeric::subdivide::{depth_first, Decision};
use std::collections::HashSet;
use std::f64::consts::PI;
use std::sync::mpsc;
use std::time::Duration;

/// The grid the chords are snapped to: the box's larger side spans 2^29 units, so coordinates
/// and their differences stay well inside the 32-bit integers the exact predicates are made
/// for; features closer than ~2e-9 of the size fall together (and the seed may then miss
/// their pairs, which the coverage shows).
const GRID: f64 = (1u64 << 29) as f64;

/// How far a chord may stray from its piece of the boundary, as a share of the size, where
/// the seed names pairs: the seed's edges stray about as far from the axis's. Finer costs
/// chords (the diagram takes ~20 µs a segment), coarser misses more short pieces of the axis
/// (each miss costs the axis built again from the bounds' pairs).
pub(crate) const CHORD_SAG: f64 = 1e-3;

/// The most the tangent may turn along one chord: the chords' normals then fan out as the
/// piece's do, so a disk touching it is seen touching its chords.
pub(crate) const CHORD_TURN: f64 = PI / 8.0;

/// Halvings of a curve's parameter made before its chords are judged: an S-shaped cubic has
/// its middle on its chord and parallel end tangents, and would pass the tests whole.
const MIN_CHORD_DEPTH: usize = 2;

/// Halvings of a segment's parameter while its chords are made (2^12 chords at most).
const MAX_SEED_CHORD_DEPTH: usize = 12;

/// What a point of the approximation stands for: a point inside one segment, or the joint
/// where one segment ends and the next starts.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Owner {
    Inside(SegmentId),
    Joint { before: SegmentId, after: SegmentId },
}

/// The chained points of every boundary, snapped; the chord starting at point `j` runs to
/// point `next[j]` and approximates the segment `chord_segment(j)`.
pub(crate) struct Approximation {
    pub(crate) points: Vec<[i32; 2]>,
    pub(crate) owner: Vec<Owner>,
    /// The boundary of each point.
    pub(crate) boundary: Vec<usize>,
    /// The next and the previous point along its boundary.
    pub(crate) next: Vec<usize>,
    prev: Vec<usize>,
    /// The point of the plane at the grid's origin, and grid units per unit of length.
    origin: [f64; 2],
    scale: f64,
}

impl Approximation {
    /// The point of the plane at grid coordinates `g`.
    pub(crate) fn unsnap(&self, g: [f64; 2]) -> [f64; 2] {
        [
            self.origin[0] + g[0] / self.scale,
            self.origin[1] + g[1] / self.scale,
        ]
    }

    /// The segment the chord starting at point `j` approximates.
    pub(crate) fn chord_segment(&self, j: usize) -> SegmentId {
        match self.owner[j] {
            Owner::Inside(s) => s,
            Owner::Joint { after, .. } => after,
        }
    }
}

/// The pairs of segments (of `boundaries`, as [`Neighbours`] names them) that the Voronoi
/// diagram of their chords shows sharing an edge on the axis's side (left of boundary `k`
/// as it runs where `inside_left[k] > 0`); `bounds` is the box the boundaries lie in.
/// `None` where no seed can be made.
pub(crate) fn seed_pairs(
    boundaries: &[&Profile],
    inside_left: &[f64],
    bounds: [f64; 4],
    size: f64,
) -> Option<Neighbours> {
    let (approx, diagram) = chord_diagram(boundaries, inside_left, bounds, size, CHORD_SAG)?;
    pairs_on_side(&approx, &diagram, inside_left).map(Neighbours::Only)
}

/// The boundaries' chords (see [`seed_pairs`]), within `sag` of the size of their pieces,
/// and their Voronoi diagram; `None` where no seed can be made.
pub(crate) fn chord_diagram(
    boundaries: &[&Profile],
    inside_left: &[f64],
    bounds: [f64; 4],
    size: f64,
    sag: f64,
) -> Option<(Approximation, Diagram)> {
    let approx = approximate(boundaries, inside_left, bounds, size, sag)?;
    let lines: Vec<Line<i32>> = (0..approx.points.len())
        .map(|j| {
            let (p, q) = (approx.points[j], approx.points[approx.next[j]]);
            Line::from([p[0], p[1], q[0], q[1]])
        })
        .collect();
    let diagram = diagram_of(lines)?;
    Some((approx, diagram))
}

/// From this many chords on, a watched diagram is built on a thread of its own
/// ([`diagram_of`]): boostvoronoi takes ~20 µs a segment, so 0.1 s from ~5,000, and
/// spawning the thread costs tens of microseconds.
const WATCHED_DIAGRAM_CHORDS: usize = 1000;

/// How often the watch is looked at while the diagram is built on its own thread.
const DIAGRAM_POLL: Duration = Duration::from_millis(5);

/// The Voronoi diagram of `lines`; `None` where boostvoronoi refuses them (or fails), or
/// the work is cancelled. The build cannot look at the watch: where the work is watched
/// and large, it runs on a thread of its own while this one looks at the watch, and on a
/// cancel it is left to finish alone, its diagram dropped, so that the cancel is answered
/// within [`DIAGRAM_POLL`].
fn diagram_of(lines: Vec<Line<i32>>) -> Option<Diagram> {
    let large = lines.len() >= WATCHED_DIAGRAM_CHORDS;
    let build = move || {
        Builder::<i32>::default()
            .with_segments(lines.iter())
            .ok()?
            .build()
            .ok()
    };
    let stage = curve::watch::stage("medial axis: the Voronoi diagram of the chords");
    if !(stage.is_watched() && large) {
        return build();
    }
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(build());
    });
    loop {
        match receive.recv_timeout(DIAGRAM_POLL) {
            Ok(diagram) => return diagram,
            Err(mpsc::RecvTimeoutError::Timeout) if !stage.cancelled() => {}
            // (Cancelled; or the build ended without a diagram: refused, as it would be.)
            Err(_) => return None,
        }
    }
}

/// The boundaries' chords, snapped to the grid over `bounds` (consecutive points that snap
/// together are one); `None` where the grid is degenerate or a boundary falls to fewer than
/// three points.
fn approximate(
    boundaries: &[&Profile],
    inside_left: &[f64],
    bounds: [f64; 4],
    size: f64,
    sag: f64,
) -> Option<Approximation> {
    let span = (bounds[2] - bounds[0]).max(bounds[3] - bounds[1]);
    if !(span > 0.0 && span.is_finite()) {
        return None;
    }
    let (cx, cy) = (0.5 * (bounds[0] + bounds[2]), 0.5 * (bounds[1] + bounds[3]));
    let scale = GRID / span;
    let snap = |p: V2| -> [i32; 2] {
        [
            ((p.x - cx) * scale).round() as i32,
            ((p.y - cy) * scale).round() as i32,
        ]
    };
    let sag = sag * size;
    let mut approx = Approximation {
        points: Vec::new(),
        owner: Vec::new(),
        boundary: Vec::new(),
        next: Vec::new(),
        prev: Vec::new(),
        origin: [cx, cy],
        scale,
    };
    for (k, b) in boundaries.iter().enumerate() {
        let n = b.segments().len();
        let first = approx.points.len();
        let mut push = |q: [i32; 2], owner: Owner| {
            if approx.points.len() > first && approx.points.last() == Some(&q) {
                // (A joint keeps its standing where an inner point falls onto it.)
                if let Owner::Joint { .. } = owner {
                    *approx.owner.last_mut().expect("a point was pushed") = owner;
                }
                return;
            }
            approx.points.push(q);
            approx.owner.push(owner);
        };
        for i in 0..n {
            let joint = Owner::Joint {
                before: (k, (i + n - 1) % n),
                after: (k, i),
            };
            push(snap(b.segments()[i].start()), joint);
            for p in inner_points(b, i, sag, inside_left[k]) {
                push(snap(p), Owner::Inside((k, i)));
            }
        }
        while approx.points.len() > first + 1 && approx.points.last() == approx.points.get(first) {
            approx.points.pop();
            approx.owner.pop();
        }
        let end = approx.points.len();
        if end - first < 3 {
            return None;
        }
        for j in first..end {
            approx.boundary.push(k);
            approx.next.push(if j + 1 < end { j + 1 } else { first });
            approx.prev.push(if j > first { j - 1 } else { end - 1 });
        }
    }
    Some(approx)
}

/// The points inside segment `i` of `b` where its chords meet. An arc whose centre lies on
/// the axis's side (`inside_left`) is circumscribed: its chords are tangent to it where the
/// inscribed chords would meet, so the disk at its centre touches them all, and the
/// segments tangent to it at its ends, as it touches the arc (inscribed chords would stand
/// nearer the centre than those segments, and the bisector of the two that starts there on
/// the axis would start late, or not at all, in the seed). Other curves are inscribed.
fn inner_points(b: &Profile, i: usize, sag: f64, inside_left: f64) -> Vec<V2> {
    let params = chord_params(b, i, sag);
    let seg = &b.segments()[i];
    if let Some((c, r)) = seg.circle() {
        let c = V2::from_arr(c);
        let middle = b.jet_on(i, i as f64 + 0.5, 1);
        if middle.d1.cross(c - middle.p) * inside_left > 0.0 {
            let touch: Vec<V2> = std::iter::once(seg.start())
                .chain(params.iter().map(|&u| b.jet_on(i, u, 0).p))
                .chain(std::iter::once(seg.end()))
                .collect();
            // Where the tangents at two points of the circle meet: along the sum of their
            // radii, at r / cos(half the angle between them) from the centre.
            return touch
                .windows(2)
                .map(|w| {
                    let s = (w[0] - c) + (w[1] - c);
                    c + s * (2.0 * r * r / s.dot(s))
                })
                .collect();
        }
    }
    params.iter().map(|&u| b.jet_on(i, u, 0).p).collect()
}

/// The profile parameters inside segment `i` (in order) where its chords meet: none for a
/// line; for a curve, its parameter halved [`MIN_CHORD_DEPTH`] times, then until each chord
/// is within `sag` of the curve at its middle and the tangent turns by at most
/// [`CHORD_TURN`] along it.
fn chord_params(b: &Profile, i: usize, sag: f64) -> Vec<f64> {
    let mut out = Vec::new();
    if b.segments()[i].kind() == SegmentKind::Line {
        return out;
    }
    let lo = i as f64;
    // (The first half first, so the params come in order.)
    depth_first((lo, lo + 1.0), MAX_SEED_CHORD_DEPTH, |(u0, u1), visit| {
        let depth = visit.depth;
        let (a, m, c) = (
            b.jet_on(i, u0, 1),
            b.jet_on(i, 0.5 * (u0 + u1), 0),
            b.jet_on(i, u1, 1),
        );
        let chord = c.p - a.p;
        let off = if chord.norm() > 0.0 {
            (m.p - a.p).cross(chord).abs() / chord.norm()
        } else {
            (m.p - a.p).norm()
        };
        let turn = a.d1.cross(c.d1).atan2(a.d1.dot(c.d1)).abs();
        if visit.can_halve && (depth < MIN_CHORD_DEPTH || off > sag || turn > CHORD_TURN) {
            let mid = 0.5 * (u0 + u1);
            return Decision::<_, ()>::Halve((u0, mid), (mid, u1));
        }
        if u1 < lo + 1.0 {
            out.push(u1);
        }
        Decision::Decided
    });
    out
}

/// The pairs of segments whose chords' cells share a primary edge on the axis's side.
fn pairs_on_side(
    approx: &Approximation,
    diagram: &Diagram,
    inside_left: &[f64],
) -> Option<HashSet<(SegmentId, SegmentId)>> {
    let mut pairs = HashSet::new();
    for edge in diagram.edges() {
        let id = edge.id();
        let twin = diagram.edge_get_twin(id).ok()?;
        // (Each edge once, from the half with the smaller index.)
        if twin.usize() < id.usize() || !edge.is_primary() {
            continue;
        }
        let [a, b] = edge_sites(approx, diagram, id)?;
        let ends = [edge.vertex0(), diagram.edge_get_vertex1(id).ok()?].map(|v| {
            v.and_then(|v| diagram.vertex(v).ok())
                .map(|v| [v.x(), v.y()])
        });
        if !on_side(approx, a, ends, inside_left) {
            continue;
        }
        for s in a.segments(approx) {
            for t in b.segments(approx) {
                if s != t {
                    pairs.insert((s.min(t), s.max(t)));
                }
            }
        }
    }
    Some(pairs)
}

/// The sites on either side of edge `id` of the diagram: its cell's, then its twin's.
pub(crate) fn edge_sites(
    approx: &Approximation,
    diagram: &Diagram,
    id: EdgeIndex,
) -> Option<[Site; 2]> {
    let edge = diagram.edge(id).ok()?;
    let twin = diagram.edge(edge.twin().ok()?).ok()?;
    Some([
        cell_site(approx, diagram, edge.cell().ok()?.usize())?,
        cell_site(approx, diagram, twin.cell().ok()?.usize())?,
    ])
}

/// The site of cell `cell` of the diagram: a chord (by index) or a point of the
/// approximation.
fn cell_site(approx: &Approximation, diagram: &Diagram, cell: usize) -> Option<Site> {
    let c = diagram.cells().get(cell)?;
    let chord = c.source_index().usize();
    let end = *approx.next.get(chord)?;
    Some(match c.source_category() {
        SourceCategory::Segment => Site::Chord(chord),
        SourceCategory::SegmentStart => Site::Point(chord),
        SourceCategory::SegmentEnd => Site::Point(end),
        SourceCategory::SinglePoint => return None,
    })
}

/// A site of the diagram: a chord, or a point of the approximation (a chord's end).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Site {
    Chord(usize),
    Point(usize),
}

impl Site {
    /// The segments the site stands for (two at a joint).
    fn segments(self, approx: &Approximation) -> impl Iterator<Item = SegmentId> {
        let owners: [Option<SegmentId>; 2] = match self {
            Site::Chord(c) => [Some(approx.chord_segment(c)), None],
            Site::Point(p) => match approx.owner[p] {
                Owner::Inside(s) => [Some(s), None],
                Owner::Joint { before, after } => [Some(before), Some(after)],
            },
        };
        owners.into_iter().flatten()
    }
}

/// Whether the edge with ends `ends` (grid coordinates; `None` at infinity) lies on the axis's
/// side of the boundary near site `a`, one of its two sites: a point of the edge is nearest
/// `a`, so it lies on the axis's side of the boundary there. It is judged at the end farthest
/// from `a` (an end on the boundary, at a joint, says nothing).
pub(crate) fn on_side(
    approx: &Approximation,
    a: Site,
    ends: [Option<[f64; 2]>; 2],
    inside_left: &[f64],
) -> bool {
    let p = |i: usize| {
        let q = approx.points[i];
        [f64::from(q[0]), f64::from(q[1])]
    };
    let cross = |o: [f64; 2], d: [f64; 2], x: [f64; 2]| {
        (d[0] - o[0]) * (x[1] - o[1]) - (d[1] - o[1]) * (x[0] - o[0])
    };
    // Signed distance-like measure: positive on the axis's side.
    let side = |x: [f64; 2]| -> f64 {
        match a {
            Site::Chord(c) => cross(p(c), p(approx.next[c]), x) * inside_left[approx.boundary[c]],
            Site::Point(q) => {
                // The chords before and after the point: the side is that of both at a
                // convex turn, of either at a reflex one.
                let k = approx.boundary[q];
                let (b0, a1) = (approx.prev[q], approx.next[q]);
                let (s0, s1) = (
                    cross(p(b0), p(q), x) * inside_left[k],
                    cross(p(q), p(a1), x) * inside_left[k],
                );
                let convex = cross(p(b0), p(q), p(a1)) * inside_left[k] > 0.0;
                if convex {
                    s0.min(s1)
                } else {
                    s0.max(s1)
                }
            }
        }
    };
    ends.into_iter()
        .flatten()
        .map(side)
        .max_by(|x, y| x.abs().total_cmp(&y.abs()))
        .is_some_and(|s| s > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::candidates::PairSource;
    use crate::test_shapes::{polygon_star, stands_as_the_bounds, star};
    use curve::Region;
    use testkit::rng;

    /// A random star of `n` sides (lines bent at their middles, or Béziers) with up to two
    /// round holes.
    fn random_region(rnd: &mut dyn FnMut() -> f64, n: usize, lines: bool) -> Option<Region> {
        let radii: Vec<f64> = (0..n).map(|_| 1.0 + 0.6 * rnd()).collect();
        let wobble: Vec<f64> = (0..n).map(|_| 0.4 * rnd() - 0.2).collect();
        let holes: Vec<([f64; 2], f64)> = (0..(3.0 * rnd()) as usize)
            .map(|_| ([0.8 * rnd() - 0.4, 0.8 * rnd() - 0.4], 0.05 + 0.15 * rnd()))
            .collect();
        if lines {
            polygon_star(&radii, &wobble, &holes)
        } else {
            star(&radii, &wobble, &holes)
        }
    }

    /// The nodes and the edges' ends and feet of an axis, one line each.
    fn summary(a: &crate::MedialAxis) -> String {
        let nodes = a
            .nodes
            .iter()
            .map(|n| format!("{:?} {:?} r {:.6}", n.kind, n.xy, n.radius));
        let edges = a.edges.iter().map(|e| {
            format!(
                "{}->{} feet {:?} .. {:?} on {:?}",
                e.from,
                e.to,
                e.feet[0],
                e.feet[e.feet.len() - 1],
                e.boundary[0]
            )
        });
        nodes.chain(edges).collect::<Vec<_>>().join("\n")
    }

    /// The differential test of the seed: on 1,000 random regions (stars of lines with
    /// reflex corners, and of Béziers, with round holes) the axis built from the seed's pairs,
    /// wherever it stands (certified, its feet covering the boundaries), is the very axis
    /// built from every pair the bounds keep; and it stands on nearly all of them (a seed
    /// that stood nowhere would pass the first half alone).
    #[test]
    fn the_seeded_axis_is_the_bounds_axis() {
        let make = |rnd: &mut dyn FnMut() -> f64, case: usize| {
            let n = 5 + (10.0 * rnd()) as usize;
            random_region(rnd, n, case % 4 != 3)
        };
        fn same(
            seeded: &crate::MedialAxis,
            bounds: &crate::MedialAxis,
            _: &Region,
        ) -> Result<(), String> {
            (seeded == bounds)
                .then_some(())
                .ok_or_else(|| format!("\n{}\n{}", summary(seeded), summary(bounds)))
        }
        stands_as_the_bounds(&mut rng(39), &[(PairSource::Seed, same)], make);
    }

    /// The seed names O(n) pairs: on star polygons of 100 to 1,600 lines, under three per
    /// segment (each segment's Voronoi cell has a few neighbours across the region).
    #[test]
    fn the_seed_names_few_pairs() {
        for n in [100usize, 400, 1600] {
            let mut rnd = rng(n as u64);
            let radii: Vec<f64> = (0..n / 2)
                .map(|i| if i % 2 == 0 { 1.0 } else { 0.5 } * (1.0 + 0.1 * rnd()))
                .collect();
            let region = polygon_star(&radii, &vec![0.0; n / 2], &[]).unwrap();
            let sites = crate::sites::Sites::new(&region, false);
            let Some(Neighbours::Only(pairs)) = seed_pairs(
                &sites.boundaries,
                &[sites.inside_left(0)],
                crate::candidates::root_box(&sites),
                sites.size,
            ) else {
                panic!("no seed for the star of {n}");
            };
            assert!(
                pairs.len() >= n && pairs.len() < 3 * n,
                "{n} lines: {} pairs",
                pairs.len()
            );
        }
    }
}
