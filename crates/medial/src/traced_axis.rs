//! The axis of a region bounded by lines and circular arcs, edge by edge from the seed's
//! diagram.
//!
//! There the diagram's topology is the axis's up to the snapping and the arcs' chords: every
//! primary edge on the axis's side lies on the bisector of two true sites (lines, arcs, and
//! reflex corners as points), and the edges between the chords of one arc are none of the
//! axis's. A run of edges between one pair of true sites, through vertices about no third
//! (where the chords of an arc take turns), is one edge of the axis; a vertex about three
//! true sites or more is a node, a disk touching three of them (or an arc's centre, touching
//! the whole arc). Each node is solved again on the true sites by Newton's method from the
//! diagram's point, and each edge traced in closed form between its ends
//! ([`crate::lines_and_arcs`]): the bisector of two lines or two points is straight, any
//! other a conic, whose points come in closed form from the feet on one of its sites. No
//! bisector is traced beyond its stretch and no stretch is searched for: the cost is O(n)
//! beyond the diagram's, and the disk tests'.
//!
//! The seed still proves nothing. Every node's disk is tested for emptiness and every foot for
//! lying on its segment, as on the other paths; the axis is then certified and its feet's
//! coverage of the boundaries checked ([`crate::coverage`]) like the seeded candidates'. A
//! diagram that disagrees with the true coordinates anywhere (a node Newton cannot place near
//! the diagram's, a foot off its segment, an entered disk, a run of edges that does not end at
//! two nodes) yields `None`, and the axis is built on the slower paths.

use crate::lines_and_arcs::{Equation, LinesAndArcs, Solved, Traced};
use crate::parallel::in_order;
use crate::seed::{chord_diagram, edge_sites, on_side, Approximation, Owner, Site, CHORD_TURN};
use crate::sites::Sites;
use crate::stretches::Stretch;
use crate::true_sites::TrueSite;
use boostvoronoi::prelude::{Diagram, EdgeIndex, VertexIndex};
use curve::V2;
use std::collections::{HashMap, HashSet};

/// How far an arc's chords may stray from it, as a share of the size. The diagram's nodes
/// about an arc are the chords', and a disk the chords keep out of may enter the arc by up
/// to this: at the seed's own sag ([`crate::seed::CHORD_SAG`], 1e-3) 57 of the 982 random
/// rounded regions of the differential test went to the slower paths, most for such a node;
/// at 1e-4 (about three times the chords) 28.
const ARC_CHORD_SAG: f64 = 1e-4;

/// How far (a share of the size) a vertex may move from the diagram's point: the snapping
/// moves the sites by 1e-9 of the size, which a vertex follows magnified by its conditioning
/// (a junction of a side 1e-6 of the size long with far ones turns with that side, by
/// 2e-3 rad), and an arc's chords stray from it by the seed's sag (1e-3 of the size; their
/// turn from it is allowed for apart, see [`Tracer::solve_vertex`]). A
/// vertex Newton's method takes farther has left the diagram's neighbourhood (another root of
/// a point's equation): the other paths decide. (A vertex within reach but wrong is refused
/// by its disk's test, its feet's, or the coverage.)
const SEED_REACH: f64 = 1e-2;

/// Most edges round one vertex of the diagram (a bound on its walk round the vertex).
const MAX_DEGREE: usize = 64;

/// An edge of the axis to trace: its two true sites and the vertices of the diagram it runs
/// between, each with the diagram's edge that leaves it along the run.
struct Job {
    sites: [TrueSite; 2],
    ends: [(VertexIndex, EdgeIndex); 2],
}

/// A primary edge of the diagram on the axis's side between two true sites: the sites
/// (ordered), its ends and the edges leaving them along it (the edge, then its twin).
struct Kept {
    sites: [TrueSite; 2],
    ends: [VertexIndex; 2],
    out: [EdgeIndex; 2],
}

/// The segments of the boundaries, the diagram, and the vertices solved.
struct Tracer<'s, 'a> {
    model: LinesAndArcs<'s, 'a>,
    approx: Approximation,
    diagram: Diagram,
    solved: HashMap<usize, Option<Solved>>,
}

/// The candidates and stretches of the axis of `sites`' region (inside), every boundary made
/// of lines and circular arcs: one candidate per edge (two where an edge's feet pass the
/// joint of a whole circle), each its own stretch. `None` where some boundary has other
/// curves, no diagram can be made, or the diagram disagrees with the true coordinates.
pub(crate) fn trace(sites: &Sites<'_>, chord_tol: f64) -> Option<Traced> {
    if sites.clip.is_some() {
        return None;
    }
    let inside_left: Vec<f64> = (0..sites.boundaries.len())
        .map(|k| sites.inside_left(k))
        .collect();
    // (Before the diagram: a boundary with another kind of curve is refused at once.)
    let model = LinesAndArcs::new(sites, chord_tol)?;
    let (approx, diagram) = chord_diagram(
        &sites.boundaries,
        &inside_left,
        crate::candidates::root_box(sites),
        sites.size,
        ARC_CHORD_SAG,
    )?;
    // Every joint kept its point through the snapping: each line is then one chord, each arc
    // a chain of them.
    let segments: usize = sites.boundaries.iter().map(|b| b.segments().len()).sum();
    let joints = approx
        .owner
        .iter()
        .filter(|o| matches!(o, Owner::Joint { .. }))
        .count();
    if joints != segments {
        return None;
    }
    let mut tracer = Tracer {
        model,
        approx,
        diagram,
        solved: HashMap::new(),
    };
    tracer.edges(&inside_left)
}

impl Tracer<'_, '_> {
    /// Every edge on the axis's side, traced: the runs of the diagram's edges between nodes
    /// and the nodes they need listed in the diagram's order, every node solved once, then
    /// every edge traced (both in parallel where the feature is on; the output in the
    /// diagram's order, never the threads').
    fn edges(&mut self, inside_left: &[f64]) -> Option<Traced> {
        let stage = curve::watch::stage("medial axis: the seed's edges");
        let jobs = self.runs(inside_left)?;
        // (Each vertex solved from the first edge that reaches it, as a serial walk would.)
        let mut vertices: Vec<(VertexIndex, EdgeIndex)> = Vec::new();
        let mut listed = HashSet::new();
        for job in &jobs {
            for (v, from) in job.ends {
                if listed.insert(v.usize()) {
                    vertices.push((v, from));
                }
            }
        }
        let solved = in_order(&vertices, |&(v, from)| {
            stage.go_on(0).then(|| self.solve_vertex(v, from)).flatten()
        });
        self.solved = vertices
            .iter()
            .map(|(v, _)| v.usize())
            .zip(solved)
            .collect();
        let traced = in_order(&jobs, |job| {
            if !stage.go_on(1) {
                return None; // (the caller answers "cancelled")
            }
            let solved = |v: VertexIndex| self.solved.get(&v.usize()).copied().flatten();
            let ends = [solved(job.ends[0].0)?, solved(job.ends[1].0)?];
            self.model.trace_edge(job.sites, ends)
        });
        let mut candidates = Vec::new();
        let mut stretches = Vec::new();
        for found in traced {
            for (candidate, vertices) in found? {
                stretches.push(Stretch {
                    candidate: candidates.len(),
                    vertices,
                });
                candidates.push(candidate);
            }
        }
        let proven = self
            .solved
            .values()
            .flatten()
            .filter(|s| s.proven)
            .map(|s| s.xy.arr().map(f64::to_bits))
            .collect();
        Some(Traced {
            candidates,
            stretches,
            proven,
        })
    }

    /// The edges of the axis as runs of the diagram's primary edges on the axis's side, each
    /// between one pair of true sites from node to node through vertices about those two
    /// sites alone; `None` where a run does not end at two nodes.
    fn runs(&self, inside_left: &[f64]) -> Option<Vec<Job>> {
        let mut kept: Vec<Kept> = Vec::new();
        for k in 0..self.diagram.edges().len() {
            let edge = &self.diagram.edges()[k];
            let id = edge.id();
            let twin = self.diagram.edge_get_twin(id).ok()?;
            if twin.usize() < id.usize() || !edge.is_primary() {
                continue;
            }
            let [a, b] = edge_sites(&self.approx, &self.diagram, id)?;
            let ends = [edge.vertex0(), self.diagram.edge_get_vertex1(id).ok()?];
            let grid = ends.map(|v| {
                v.and_then(|v| self.diagram.vertex(v).ok())
                    .map(|v| [v.x(), v.y()])
            });
            if !on_side(&self.approx, a, grid, inside_left) {
                continue;
            }
            let (a, b) = (self.true_site(a)?, self.true_site(b)?);
            // (Chords of one arc have no axis between them; two segments across a smooth
            // joint have one foot there, and a segment and its own end too: no axis between
            // them, and no ends to solve for it.)
            if a == b
                || self.model.smooth_joint_between(a, b).is_some()
                || self.model.own_end(a, b).is_some()
            {
                continue;
            }
            // (Inside a closed boundary every edge is finite.)
            let [Some(v0), Some(v1)] = ends else {
                return None;
            };
            kept.push(Kept {
                sites: [a.min(b), a.max(b)],
                ends: [v0, v1],
                out: [id, twin],
            });
        }
        let mut at: HashMap<usize, Vec<(usize, usize)>> = HashMap::new();
        for (k, e) in kept.iter().enumerate() {
            for end in 0..2 {
                at.entry(e.ends[end].usize()).or_default().push((k, end));
            }
        }
        let mut node: HashMap<usize, bool> = HashMap::new();
        for e in &kept {
            for end in 0..2 {
                let v = e.ends[end];
                if let std::collections::hash_map::Entry::Vacant(slot) = node.entry(v.usize()) {
                    slot.insert(self.is_node(v, e.out[end])?);
                }
            }
        }
        let mut used = vec![false; kept.len()];
        let mut jobs = Vec::new();
        for first in 0..kept.len() {
            for first_end in 0..2 {
                let start = kept[first].ends[first_end];
                if used[first] || !node[&start.usize()] {
                    continue;
                }
                let (mut k, mut from) = (first, first_end);
                // (A run passes each kept edge once.)
                for _ in 0..kept.len() {
                    used[k] = true;
                    let far = kept[k].ends[1 - from];
                    if node[&far.usize()] {
                        jobs.push(Job {
                            sites: kept[first].sites,
                            ends: [
                                (start, kept[first].out[first_end]),
                                (far, kept[k].out[1 - from]),
                            ],
                        });
                        break;
                    }
                    // Through a vertex about these two sites alone: the one other edge of
                    // the run there.
                    let next: Vec<(usize, usize)> = at[&far.usize()]
                        .iter()
                        .copied()
                        .filter(|&(j, _)| j != k)
                        .collect();
                    match next[..] {
                        [(j, end)] if !used[j] && kept[j].sites == kept[first].sites => {
                            (k, from) = (j, end);
                        }
                        _ => return None,
                    }
                }
            }
        }
        // (A run with no node, a cycle, is left: the other paths make its joint.)
        used.iter().all(|&u| u).then_some(jobs)
    }

    /// Whether vertex `v` of the diagram (`from` one of its edges) is a node of the axis: on
    /// the boundary, or about three true sites or more.
    fn is_node(&self, v: VertexIndex, from: EdgeIndex) -> Option<bool> {
        if self.diagram.vertex(v).ok()?.is_site_point() {
            return Some(true);
        }
        let mut about: Vec<TrueSite> = Vec::new();
        for e in self.diagram.edge_rot_next_iterator(from).take(MAX_DEGREE) {
            for s in edge_sites(&self.approx, &self.diagram, e)? {
                let t = self.true_site(s)?;
                if !about.contains(&t) {
                    about.push(t);
                }
            }
        }
        Some(about.len() >= 3)
    }

    /// The true site of a site of the diagram: a chord's segment, a point inside an arc's
    /// chain its arc, a joint's point the corner there.
    fn true_site(&self, s: Site) -> Option<TrueSite> {
        Some(match s {
            Site::Chord(c) => {
                let (boundary, segment) = self.approx.chord_segment(c);
                TrueSite {
                    boundary,
                    segment,
                    corner: false,
                }
            }
            Site::Point(p) => match self.approx.owner[p] {
                Owner::Joint { before, after } => {
                    let site = |(boundary, segment): (usize, usize), corner| TrueSite {
                        boundary,
                        segment,
                        corner,
                    };
                    // (A smooth joint of an arc is no corner: the point stands for the feet
                    // about it, which its chords' reflex turn there gives a cell of its own.)
                    let arc = [before, after]
                        .iter()
                        .any(|&s| self.model.arc(site(s, false)).is_some());
                    site(after, !(arc && self.model.smooth_at(after)))
                }
                Owner::Inside((boundary, segment)) => {
                    let site = TrueSite {
                        boundary,
                        segment,
                        corner: false,
                    };
                    self.model.arc(site)?;
                    site
                }
            },
        })
    }

    /// The node at vertex `v` of the diagram (`from` one of its edges).
    fn solve_vertex(&self, v: VertexIndex, from: EdgeIndex) -> Option<Solved> {
        let vertex = self.diagram.vertex(v).ok()?;
        let grid = [vertex.x(), vertex.y()];
        let mut equations: Vec<Equation> = Vec::new();
        let mut corners: Vec<(usize, TrueSite)> = Vec::new();
        let mut about: Vec<TrueSite> = Vec::new();
        for e in self.diagram.edge_rot_next_iterator(from).take(MAX_DEGREE) {
            let edge = self.diagram.edge(e).ok()?;
            let [sa, sb] = edge_sites(&self.approx, &self.diagram, e)?;
            for s in [sa, sb] {
                if let Site::Point(p) = s {
                    if let Owner::Joint { .. } = self.approx.owner[p] {
                        corners.push((p, self.true_site(s)?));
                    }
                }
            }
            let (a, b) = (self.true_site(sa)?, self.true_site(sb)?);
            about.extend([a, b]);
            if a == b {
                continue;
            }
            // (A secondary edge parts a segment from its own end, or an arc's chords from
            // its end: the edge is the normal at the end.)
            let eq = self.model.equation_between(a, b);
            if matches!(eq, Equation::Equal(..)) && !edge.is_primary() {
                return None;
            }
            if !equations.contains(&eq) {
                equations.push(eq);
            }
        }
        // A vertex at a point of the boundary: a convex corner, where its two segments'
        // bisector starts with a disk of radius nil.
        if vertex.is_site_point() {
            let at = |p: usize| {
                let q = self.approx.points[p];
                [f64::from(q[0]), f64::from(q[1])] == grid
            };
            let &(_, corner) = corners.iter().find(|(p, _)| at(*p))?;
            return Some(Solved {
                xy: self.model.start(corner),
                radius: 0.0,
                proven: false,
            });
        }
        let start = V2::from_arr(self.approx.unsnap(grid));
        let size = self.model.sites.size;
        // (An arc's chords, and so their normals, turn from the arc's by up to half a chord's
        // turn: on them the diagram's vertex of a disk of radius ρ may stand ρ·turn/2 off.)
        let reach = match about.iter().find(|&&s| self.model.arc(s).is_some()) {
            Some(&s) => {
                SEED_REACH * size + 0.5 * CHORD_TURN * self.model.shape(s).distance(start).0.abs()
            }
            None => SEED_REACH * size,
        };
        self.model.solve_node(start, &equations, &about, reach)
    }
}

#[cfg(test)]
mod tests {
    use crate::candidates::PairSource;
    use crate::test_shapes::{random_rounded, same_graph};
    use crate::{axis_of, MedialAxis, MedialOptions, Verdict};
    use curve::{Region, V2};
    use testkit::outlines::{polygon, star_polygon};
    use testkit::rng;

    /// Case 379 of the traced path's differential test on arcs
    /// ([`crate::differential`]): two arcs meet at a
    /// convex corner of 0.012 rad, whose leaf is short. The bounds' pairs miss that leaf,
    /// and their axis is then not certified for its feet's gap (it was, before every axis
    /// was asked to cover its boundaries); the traced axis has the leaf and is certified.
    #[test]
    fn a_missed_leaf_leaves_the_axis_uncertified() {
        let mut rnd = rng(3902);
        let region = (0..=379).filter_map(|_| random_rounded(&mut rnd)).last();
        let region = region.unwrap();
        let opts = MedialOptions::default();
        let bounds = axis_of(&region, &opts, PairSource::Bounds).unwrap().0;
        assert!(!bounds.certified());
        // (The reason names the corner.)
        let reason = bounds.reason().unwrap_or_default();
        let coverage = numeric::certificate::Doubt::Coverage { unreached: None }.to_string();
        assert!(
            reason.starts_with(&coverage)
                && reason.contains("(-0.5443380122571256, 0.9428210937203926)"),
            "{reason}"
        );
        let (traced, stands) = axis_of(&region, &opts, PairSource::SeedEdges).unwrap();
        assert!(stands && traced.certified(), "{:?}", traced.reason());
        let corner = [-0.5443380122571256, 0.9428210937203926];
        assert!(traced
            .nodes
            .iter()
            .any(|n| n.kind == crate::NodeKind::Corner
                && (V2::from_arr(n.xy) - V2::from_arr(corner)).norm() < 1e-9));
        assert_eq!(traced.nodes.len(), bounds.nodes.len() + 1);
    }

    /// A closed polygon through `points`, as a region.
    fn region_of(points: &[[f64; 2]]) -> Region {
        Region::new(polygon(points), vec![]).unwrap()
    }

    /// The traced path's axis of `region` (named `what`), which must stand, be certified and
    /// be the seed's pairs' axis.
    fn traced_as_seeded(region: &Region, opts: &MedialOptions, what: &str) -> MedialAxis {
        let (traced, stands) = axis_of(region, opts, PairSource::SeedEdges).unwrap();
        assert!(
            stands && traced.certified(),
            "{what}: {:?}",
            traced.reason()
        );
        let seeded = axis_of(region, opts, PairSource::Seed).unwrap().0;
        same_graph(&traced, &seeded, same_graph_tol(region, opts)).unwrap();
        traced
    }

    /// How near two axes of `region` by different routes must be: two chord tolerances.
    fn same_graph_tol(region: &Region, opts: &MedialOptions) -> f64 {
        2.0 * opts.settings.chord_tol.get() * region.size()
    }

    /// The traced path stands on gears of 12 and 25 teeth (arcs about one centre meeting
    /// lines at corners, round a hole: nodes of nearly cocircular chords), certified, with the
    /// seed's pairs' axis; and a gear turned, scaled and moved (far from the origin, a
    /// thousand times larger) gives the same graph moved.
    #[test]
    fn the_traced_path_stands_on_gears() {
        let opts = MedialOptions::default();
        for n in [12usize, 25] {
            let region = testkit::outlines::gear(n);
            let traced = traced_as_seeded(&region, &opts, &format!("gear {n}"));
            assert_eq!((traced.nodes.len(), traced.edges.len()), (4 * n, 4 * n));
            // (Turned about the origin, scaled and moved; then moved back, scaled back and
            // turned back: a little, and far from the origin at a thousand times the size.)
            for (turn, scale, shift) in [(0.3f64, 1.0, [0.5, -0.2]), (-1.1, 1e3, [1e5, -3e5])] {
                let (c, s) = (scale * turn.cos(), scale * turn.sin());
                let moved = region
                    .transformed(&curve::Affine([c, s, -s, c, shift[0], shift[1]]))
                    .unwrap();
                let (again, stands) = axis_of(&moved, &opts, PairSource::SeedEdges).unwrap();
                assert!(
                    stands && again.certified(),
                    "gear {n} moved by {turn}, {scale}: {:?}",
                    again.reason()
                );
                let undo = |x: [f64; 2]| {
                    let (u, v) = (x[0] - shift[0], x[1] - shift[1]);
                    [
                        (c * u + s * v) / (scale * scale),
                        (-s * u + c * v) / (scale * scale),
                    ]
                };
                let mut back = again.clone();
                for node in &mut back.nodes {
                    node.xy = undo(node.xy);
                    node.radius /= scale;
                }
                for e in &mut back.edges {
                    e.xy.iter_mut().for_each(|x| *x = undo(*x));
                }
                same_graph(&back, &traced, same_graph_tol(&region, &opts)).unwrap();
            }
        }
    }

    /// The traced path stands on the benchmarks' stars of 100 and 400 lines (certified, its
    /// feet covering the boundary), with the seed's pairs' axis.
    #[test]
    fn the_traced_path_stands_on_the_stars() {
        for n in [100usize, 400] {
            let region = region_of(&star_polygon(n));
            let opts = MedialOptions::default();
            traced_as_seeded(&region, &opts, &format!("star {n}"));
        }
    }
}
