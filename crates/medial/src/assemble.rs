//! The graph of the axis from its stretches: ends that meet become one node (a junction
//! where three or more meet, a leaf at a centre of curvature or a convex corner), and
//! stretches that continue each other through a node of two are joined into one edge.

use crate::candidates::Candidate;
use crate::candidates::Vertex;
use crate::sites::Sites;
use crate::stretches::Stretch;
use crate::{Edge, MedialAxis, Node, NodeKind};
use curve::ParamCurve;

/// Ends of stretches whose feet lie within this share of their radius of each other are
/// beside a centre of curvature, where the feet are ill-conditioned: stretches of
/// neighbouring pieces (cut at a knot or a joint) end up to ~2e-5 of the size apart there,
/// every one of their vertices on the axis. Two such ends within `TIP_MERGE` of the size
/// whose feet close in on one foot (their stretches of the boundary between the feet meet)
/// are one node: two leaves' tips beside one smooth joint stay two.
const TIP_FEET: f64 = 0.05;
const TIP_MERGE: f64 = 1e-4;

/// A stretch whose two ends are one node, with an end beside a centre of curvature and its
/// vertices within this share of the size of its first, is no cycle (a hole's cycle runs
/// round the hole, its feet on two boundaries): it is the tip of a leaf whose ends fell into
/// one node (twice `TIP_MERGE`: two ends that far apart can be one node through a third).
const STUB: f64 = 2.0 * TIP_MERGE;

/// A join whose feet differ by more than this share of the size (the rounding of the ends'
/// feet) may hide a leaf whose feet stay within [`FEET_JOIN`] all along it: the seed's axis
/// with such a join is not taken on the coverage's word.
const TIGHT_JOIN: f64 = 1e-9;

/// Feet of two stretches at their common end within this share of the size are one foot:
/// ten times the reach within which ends are one node.
const FEET_JOIN: f64 = 1e-5;

/// A leaf whose radius is at most this share of the size is a corner of the boundary.
const CORNER_RADIUS: f64 = 1e-9;

/// A leaf within this share of the size of the box the exterior axis is clipped to ends
/// there: the stretch's end is bracketed to 2^-32 of a polyline step from the box.
const ON_CLIP: f64 = 1e-9;

/// Whether `x` lies on the edge of the box the exterior axis is clipped to.
fn on_clip(sites: &Sites<'_>, x: [f64; 2]) -> bool {
    sites.clip.is_some_and(|c| {
        let room = ON_CLIP * sites.size;
        let near = |a: f64, b: f64| (a - b).abs() <= room;
        near(x[0], c[0]) || near(x[0], c[2]) || near(x[1], c[1]) || near(x[1], c[3])
    })
}

/// One edge while the graph is assembled: its nodes (clusters) and vertices.
struct Chain {
    ends: [usize; 2],
    /// Whether an end is beside a centre of curvature (its feet within `TIP_FEET`).
    at_tip: bool,
    vertices: Vec<Vertex>,
    boundary: Vec<[usize; 2]>,
}

/// The graph of the axis, ends within `merge` (a share of the size) one node; whether some
/// stretches were joined through a node of two with feet
/// that differ there by more than their rounding ([`TIGHT_JOIN`]).
pub(crate) fn assemble(
    sites: &Sites<'_>,
    pieces: Vec<Stretch>,
    found: &[Candidate],
    merge: f64,
) -> (MedialAxis, bool) {
    let merge = merge * sites.size;
    // A stretch within one node's reach is a point: the bisector of an arc and the line
    // tangent to it at their joint maps a whole run of feet to the arc's centre.
    let pieces: Vec<Stretch> = pieces
        .into_iter()
        .map(|mut p| {
            let first = p.vertices[0].xy;
            let spread = p.vertices.iter().fold(0.0f64, |m, v| {
                m.max((v.xy[0] - first[0]).hypot(v.xy[1] - first[1]))
            });
            if spread <= merge {
                p.vertices.truncate(1);
            }
            p
        })
        // A single point on the boundary (radius 0) is no node unless an edge reaches it.
        .filter(|p| p.vertices.len() > 1 || p.vertices[0].radius > CORNER_RADIUS * sites.size)
        .collect();
    // Every end (two per stretch, one per single point), clustered by distance.
    let mut points: Vec<Vertex> = Vec::new();
    let mut point_boundary: Vec<[usize; 2]> = Vec::new();
    // Per end, the other end of its stretch where that stretch is longer than a stub.
    let mut far_partner: Vec<Option<usize>> = Vec::new();
    for p in &pieces {
        let b = found[p.candidate].boundary;
        let k = points.len();
        points.push(p.vertices[0]);
        point_boundary.push(b);
        if p.vertices.len() > 1 {
            points.push(p.vertices[p.vertices.len() - 1]);
            point_boundary.push(b);
            let long = extent(&p.vertices) > STUB * sites.size;
            far_partner.push(long.then_some(k + 1));
            far_partner.push(long.then_some(k));
        } else {
            far_partner.push(None);
        }
    }
    // Beside a centre of curvature the feet are ill-conditioned: ends there (feet within
    // `TIP_FEET` of the radius) meet within `TIP_MERGE`.
    let tip_end: Vec<bool> = points
        .iter()
        .zip(&point_boundary)
        .map(|(v, b)| {
            let (p, q) = (sites.foot(b[0], v.tr[0]), sites.foot(b[1], v.tr[1]));
            // (Not a corner's end: radius and feet's gap both nil there.)
            v.radius > CORNER_RADIUS * sites.size
                && (p[0] - q[0]).hypot(p[1] - q[1]) <= TIP_FEET * v.radius
        })
        .collect();
    // Where a tip end's feet lie along its boundary (the short way round): ends beside one
    // centre of curvature have feet closing in on one foot from either side.
    let feet_span: Vec<Option<FeetSpan>> = points
        .iter()
        .zip(&point_boundary)
        .zip(&tip_end)
        .map(|((v, b), &tip)| (tip && b[0] == b[1]).then(|| FeetSpan::new(sites, b[0], v.tr)))
        .collect();
    let cluster = clusters(
        &points,
        &feet_span,
        &far_partner,
        merge,
        TIP_MERGE * sites.size,
    );
    let mut chains: Vec<Option<Chain>> = Vec::new();
    let mut k = 0;
    let mut lone: Vec<usize> = Vec::new(); // single points, by index in `points`
    for p in pieces {
        if p.vertices.len() == 1 {
            lone.push(k);
            k += 1;
            continue;
        }
        let b = found[p.candidate].boundary;
        chains.push(Some(Chain {
            ends: [cluster[k], cluster[k + 1]],
            at_tip: tip_end[k] || tip_end[k + 1],
            boundary: vec![b; p.vertices.len()],
            vertices: p.vertices,
        }));
        k += 2;
    }
    let clusters_n = cluster.iter().copied().max().map_or(0, |m| m + 1);
    // Stubs go; the tip of each (its least radius: the leaf's end) becomes its node's point.
    let mut stub_tip: Vec<Option<(Vertex, [usize; 2])>> = vec![None; clusters_n];
    for slot in chains.iter_mut() {
        let Some(c) = slot else { continue };
        if c.ends[0] == c.ends[1] && c.at_tip && extent(&c.vertices) <= STUB * sites.size {
            stub_tip[c.ends[0]] = c
                .vertices
                .iter()
                .zip(&c.boundary)
                .min_by(|a, b| a.0.radius.total_cmp(&b.0.radius))
                .map(|(v, b)| (*v, *b));
            *slot = None;
        }
    }
    // The chains at a stub's node run on to its tip.
    for c in chains.iter_mut().flatten() {
        for end in 0..2 {
            let Some((t, b)) = stub_tip[c.ends[end]] else {
                continue;
            };
            if end == 0 && c.vertices[0] != t {
                c.vertices.insert(0, t);
                c.boundary.insert(0, b);
            } else if end == 1 && c.vertices[c.vertices.len() - 1] != t {
                c.vertices.push(t);
                c.boundary.push(b);
            }
        }
    }
    let mut kinds: Vec<Option<NodeKind>> = vec![None; clusters_n];
    let loose = join_through_twos(sites, &mut chains, clusters_n, &mut kinds);
    let mut chains: Vec<Chain> = chains.into_iter().flatten().collect();

    // Nodes: the clusters still in use, numbered in order of first use.
    let mut degree = vec![0usize; clusters_n];
    for c in &chains {
        degree[c.ends[0]] += 1;
        degree[c.ends[1]] += 1;
    }
    let mut id = vec![usize::MAX; clusters_n];
    let mut nodes: Vec<Node> = Vec::new();
    let mut node_of = |c: usize, at: Vertex, nodes: &mut Vec<Node>| -> usize {
        if id[c] == usize::MAX {
            id[c] = nodes.len();
            let at = stub_tip[c].map_or(at, |t| t.0);
            let kind = kinds[c].unwrap_or(match degree[c] {
                0 => NodeKind::End,
                1 if at.radius <= CORNER_RADIUS * sites.size => NodeKind::Corner,
                1 if on_clip(sites, at.xy) => NodeKind::Clip,
                1 => NodeKind::End,
                _ => NodeKind::Junction,
            });
            nodes.push(Node {
                id: nodes.len(),
                xy: at.xy,
                radius: at.radius,
                kind,
                part: None,
            });
        }
        id[c]
    };
    let mut edges = Vec::with_capacity(chains.len());
    for c in &mut chains {
        orient_feet(sites, c);
    }
    for c in &chains {
        let first = c.vertices[0];
        let last = c.vertices[c.vertices.len() - 1];
        let from = node_of(c.ends[0], first, &mut nodes);
        let to = node_of(c.ends[1], last, &mut nodes);
        edges.push(Edge {
            from,
            to,
            xy: c.vertices.iter().map(|v| v.xy).collect(),
            radius: c.vertices.iter().map(|v| v.radius).collect(),
            feet: c.vertices.iter().map(|v| v.tr).collect(),
            boundary: c.boundary.clone(),
            bspline: None,
            part: None,
        });
    }
    // Single points make the axis only where it has no edge (the centre of a disk): the
    // axis is connected, so with edges a single point lies on one of them.
    if edges.is_empty() {
        for &k in &lone {
            node_of(cluster[k], points[k], &mut nodes);
        }
    }
    (
        MedialAxis {
            nodes,
            edges,
            // (Stated where the axis is finished, once its proofs have run.)
            doubts: crate::Doubts::none(),
            complete: true,
        },
        loose,
    )
}

/// Puts each vertex's two feet in the order that follows on from the previous vertex's:
/// the stretches joined into one edge come from bisectors computed with their sites either
/// way round, and the feet of one side of an edge run along one boundary, in order.
fn orient_feet(sites: &Sites<'_>, c: &mut Chain) {
    let apart = |b: [usize; 2], p: f64, q: f64| {
        if b[0] != b[1] {
            return f64::INFINITY;
        }
        let boundary = sites.boundaries[b[0]];
        let d = (p - q).abs();
        if boundary.is_closed() {
            let n = boundary.domain().1;
            let d = d % n;
            d.min(n - d)
        } else {
            d
        }
    };
    for k in 1..c.vertices.len() {
        let (prev, prev_b) = (c.vertices[k - 1].tr, c.boundary[k - 1]);
        let (tr, b) = (c.vertices[k].tr, c.boundary[k]);
        let kept =
            apart([prev_b[0], b[0]], prev[0], tr[0]) + apart([prev_b[1], b[1]], prev[1], tr[1]);
        let traded =
            apart([prev_b[0], b[1]], prev[0], tr[1]) + apart([prev_b[1], b[0]], prev[1], tr[0]);
        if traded < kept {
            c.vertices[k].tr = [tr[1], tr[0]];
            c.boundary[k] = [b[1], b[0]];
        }
    }
}

/// How far a stretch's vertices reach from its first.
fn extent(vertices: &[Vertex]) -> f64 {
    let first = vertices[0].xy;
    vertices.iter().fold(0.0f64, |m, v| {
        m.max((v.xy[0] - first[0]).hypot(v.xy[1] - first[1]))
    })
}

/// The stretch of a boundary between an end's two feet, the short way round on a closed
/// one.
#[derive(Debug, Clone, Copy)]
struct FeetSpan {
    boundary: usize,
    lo: f64,
    hi: f64,
    /// The boundary's parameter length where it is closed.
    period: Option<f64>,
}

impl FeetSpan {
    fn new(sites: &Sites<'_>, boundary: usize, tr: [f64; 2]) -> Self {
        let b = sites.boundaries[boundary];
        let n = b.domain().1;
        let (mut lo, mut hi) = (tr[0].min(tr[1]), tr[0].max(tr[1]));
        if b.is_closed() && hi - lo > 0.5 * n {
            (lo, hi) = (hi, lo + n);
        }
        Self {
            boundary,
            lo,
            hi,
            period: b.is_closed().then_some(n),
        }
    }

    /// Whether the two stretches share a point (both ends close in on one foot).
    fn meets(&self, o: &FeetSpan) -> bool {
        if self.boundary != o.boundary {
            return false;
        }
        let shifts: &[f64] = match self.period {
            Some(n) => &[-n, 0.0, n],
            None => &[0.0],
        };
        shifts
            .iter()
            .any(|s| o.lo + s <= self.hi && o.hi + s >= self.lo)
    }
}

/// Cluster indices of points, those within `merge` of each other (transitively) together,
/// and two tips (with their feet's stretches, `feet`) within `tip_merge` whose feet close in
/// on one foot, numbered in order of first appearance.
fn clusters(
    points: &[Vertex],
    feet: &[Option<FeetSpan>],
    far_partner: &[Option<usize>],
    merge: f64,
    tip_merge: f64,
) -> Vec<usize> {
    let n = points.len();
    let mut parent: Vec<usize> = (0..n).collect();
    // Sorted by x, each point is compared with those within reach in x after it.
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| points[a].xy[0].total_cmp(&points[b].xy[0]));
    let reach = merge.max(tip_merge);
    for (k, &a) in order.iter().enumerate() {
        for &b in &order[k + 1..] {
            if points[b].xy[0] - points[a].xy[0] > reach {
                break;
            }
            let (p, q) = (points[a].xy, points[b].xy);
            // (Not the two ends of one stretch longer than a stub: they would close it into
            // a loop; two junctions that near each other are joined by it.)
            let one_tip = far_partner[a] != Some(b)
                && match (&feet[a], &feet[b]) {
                    (Some(x), Some(y)) => x.meets(y),
                    _ => false,
                };
            let within = if one_tip { reach } else { merge };
            if (p[0] - q[0]).hypot(p[1] - q[1]) <= within {
                let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                parent[ra.max(rb)] = ra.min(rb);
            }
        }
    }
    let mut number = vec![usize::MAX; n];
    let mut next = 0;
    (0..n)
        .map(|i| {
            let r = root(&mut parent, i);
            if number[r] == usize::MAX {
                number[r] = next;
                next += 1;
            }
            number[r]
        })
        .collect()
}

/// The representative of `i`'s set in the disjoint-set forest `parent` (paths halved on
/// the way).
pub(crate) fn root(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// Joins the chains meeting at a node of two into one; a cycle left with one node of two (an
/// annulus's) keeps it as a joint. Whether some join's feet differed by more than
/// [`TIGHT_JOIN`] of the size (a leaf whose feet stay that near could be hidden there).
fn join_through_twos(
    sites: &Sites<'_>,
    chains: &mut [Option<Chain>],
    clusters: usize,
    kinds: &mut [Option<NodeKind>],
) -> bool {
    let mut loose = false;
    // The chains ending at each node (a chain twice where both its ends are there). A join
    // at a node changes no other node's count, only which chain ends at the far node of the
    // second: the nodes are taken once each, in order.
    let mut at: Vec<Vec<usize>> = vec![Vec::new(); clusters];
    for (i, c) in chains.iter().enumerate() {
        if let Some(c) = c {
            at[c.ends[0]].push(i);
            at[c.ends[1]].push(i);
        }
    }
    for node in 0..clusters {
        let [a, b] = at[node][..] else {
            continue;
        };
        if a == b || kinds[node].is_some() {
            continue;
        }
        let (Some(mut first), Some(mut second)) = (chains[a].take(), chains[b].take()) else {
            break;
        };
        // first ends at the node, second starts there.
        if first.ends[1] != node {
            reverse(&mut first);
        }
        if second.ends[0] != node {
            reverse(&mut second);
        }
        debug_assert!(first.ends[1] == node && second.ends[0] == node);
        if !feet_continue(sites, &first, &second) {
            // A third site touched the disk here and its branch was not found: the node
            // stays, a junction of two, for the coverage of the feet to refuse.
            kinds[node] = Some(NodeKind::Junction);
            chains[a] = Some(first);
            chains[b] = Some(second);
            continue;
        }
        loose |= !feet_meet(sites, &first, &second, TIGHT_JOIN * sites.size);
        first.vertices.extend_from_slice(&second.vertices[1..]);
        first.boundary.extend_from_slice(&second.boundary[1..]);
        first.ends[1] = second.ends[1];
        at[node].clear();
        let far = &mut at[second.ends[1]];
        for c in far.iter_mut().filter(|c| **c == b) {
            *c = a;
        }
        far.sort_unstable(); // (by chain, as the chains are listed: the first is joined to)
        chains[a] = Some(first);
    }
    // A chain from a node back to it, the node's only chain: a cycle without junctions.
    for c in chains.iter().flatten() {
        if c.ends[0] == c.ends[1] {
            let others = chains
                .iter()
                .flatten()
                .filter(|d| d.ends.contains(&c.ends[0]))
                .count();
            if others == 1 {
                kinds[c.ends[0]] = Some(NodeKind::Joint);
            }
        }
    }
    loose
}

/// Whether the feet of two stretches at their common end pair up (either way round) so that
/// `agree(boundary, foot before, foot after, distance apart)` holds for both pairs.
fn feet_pair_up(
    sites: &Sites<'_>,
    first: &Chain,
    second: &Chain,
    agree: impl Fn(usize, f64, f64, f64) -> bool,
) -> bool {
    let (p, pb) = (
        first.vertices[first.vertices.len() - 1],
        first.boundary[first.boundary.len() - 1],
    );
    let (q, qb) = (second.vertices[0], second.boundary[0]);
    let pair = |s: usize, t: usize| {
        pb[s] == qb[t] && {
            let (a, b) = (sites.foot(pb[s], p.tr[s]), sites.foot(qb[t], q.tr[t]));
            agree(pb[s], p.tr[s], q.tr[t], (a[0] - b[0]).hypot(a[1] - b[1]))
        }
    };
    (pair(0, 0) && pair(1, 1)) || (pair(0, 1) && pair(1, 0))
}

/// Whether the feet of two stretches at their common end lie within `room` of each other.
fn feet_meet(sites: &Sites<'_>, first: &Chain, second: &Chain, room: f64) -> bool {
    feet_pair_up(sites, first, second, |_, _, _, apart| apart <= room)
}

/// Two stretches meeting at a node of two continue each other where the feet at their
/// common end agree (either way round) to [`FEET_JOIN`] of the size with no convex corner
/// between them (whose leaf would end there), or where the boundary between those that
/// differ is an arc about the node.
fn feet_continue(sites: &Sites<'_>, first: &Chain, second: &Chain) -> bool {
    let room = FEET_JOIN * sites.size;
    let node = second.vertices[0];
    let centre = curve::V2::from_arr(node.xy);
    feet_pair_up(sites, first, second, |k, u, v, apart| {
        (apart <= room && !crate::coverage::convex_corner_between(sites, k, u, v))
            || crate::coverage::arc_between(sites, k, u, v, centre, node.radius)
    })
}

fn reverse(c: &mut Chain) {
    c.vertices.reverse();
    c.boundary.reverse();
    c.ends.reverse();
}
