//! What an axis's `certified` rests on, node by node, decided by sign tests on bounds.
//!
//! - A **junction**: a disk about it of radius `h` (a tiny share of the size) holds a point
//!   equidistant from three stretches of the boundary, one about each of three of its feet.
//!   With `dA, dB, dC` the distances to those stretches (each 1-Lipschitz), the map
//!   `(dA − dB, dA − dC)` is shown to wind round zero along a polygon in that disk (Brouwer's
//!   degree): every distance at a polygon's corner is enclosed by proven disks (one clear of
//!   the stretch, one entered by it), and along each side one component keeps its sign
//!   within the Lipschitz bound.
//! - An **end** on an arc: at the arc's centre, its radius the arc's (exact data). An end on
//!   a spline: at the centre of curvature of one of its feet, the curvature's magnitude
//!   proven rising `tol` (the parameter tolerance) before that foot and falling `tol` after
//!   it, by bounds on the rate's numerator ([`proven_rate_sign`]): a peak lies within `tol`
//!   of the foot. At a corner, where the leaf ends as the foot on one segment closes in on
//!   the corner's point, on that segment's side only.
//! - A **corner**, the **joint** of an annulus and a **clip** leaf: at a corner of the
//!   boundary, anywhere on a cycle, on the clip box (exact data or no claim of place).

use crate::assemble::root;
use crate::coverage::within_in_x;
use crate::curvature::proven_rate_sign;
use crate::junction_proof::{closed_site_at, proven_within, ClosedSite};
use crate::sites::{Disk, Sites};
use crate::{MedialAxis, Node, NodeKind};
use curve::{Clearance, ParamCurve, V2};
use numeric::rounding::ulps;
use std::collections::HashSet;

/// Radii of the disks about a junction searched for its exact point, as shares of the size:
/// the first well above the enclosures' rounding (~1e-15 of the coordinates), the second
/// for junctions far from the origin; no more than the contract's claim of place for a
/// vertex.
pub(crate) const JUNCTION_ROOM: [f64; 2] = [1e-10, 1e-9];

/// The polygons a junction is proven with, tried in turn: the share of the room about it
/// by which every enclosure of a distance is wider than the distance to the foot (its
/// proven disks lie that far inside and outside), and the most corners the polygon may be
/// refined to (sides where no component of the map is proven of one sign are halved). Most
/// junctions are proven by the first. Where two feet are close as seen from the junction (a
/// foot beside a corner that is a third), the difference of their distances changes over
/// the polygon only by their angle times the room, a few hundredths of it: its sign needs
/// enclosures narrower still (at 1e-4 of the smaller room, still 45 units of rounding of
/// the coordinates wide), and only sides shorter than half its value keep it, so the sides
/// about where the other component changes sign are halved some ten times more.
const POLYGONS: [Polygon; 2] = [
    Polygon {
        enclosure: 1e-3,
        most_corners: 64,
    },
    Polygon {
        enclosure: 1e-4,
        most_corners: 256,
    },
];

/// How a junction's polygon is built: see [`POLYGONS`].
#[derive(Clone, Copy)]
struct Polygon {
    enclosure: f64,
    most_corners: usize,
}

/// The narrowest enclosure of a distance, in units of rounding of the coordinates: four
/// times the disk tests' own allowance ([`curve::Profile::clearance`] allows 16).
const ENCLOSURE_ULPS: f64 = 64.0;

/// The widest enclosure of a distance a polygon is tried with, as a share of its radius.
const MOST_ENCLOSURE: f64 = 0.25;

/// Corners of the first polygon about a junction.
const FIRST_CORNERS: usize = 8;

/// Feet of a node's edges within this share of the size are one contact with the boundary
/// (the stretches meeting at a junction found it to ~1e-12 of the size each).
const SAME_FOOT: f64 = 1e-6;

/// Why an axis is not certified.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Doubt {
    /// A disk was decided by the nearest point found (within rounding of the boundary).
    Disk,
    /// A junction's exact point was not proven near it.
    Junction,
    /// An end's curvature extremum was not proven.
    End,
    /// A corner leaf is not at a corner convex for the region.
    Corner,
    /// The graph is not one piece with a cycle per hole (the axis inside a region is).
    Graph,
    /// The feet of the edges do not cover the boundaries once round ([`crate::coverage`]):
    /// a piece of the axis may be missing.
    Coverage,
    /// A search limit was hit.
    SearchLimit,
    /// The work was cancelled before every node was proven (no such axis is answered: its
    /// caller says "cancelled").
    Cancelled,
}

impl Doubt {
    /// The reason, as the result states it.
    pub(crate) fn reason(self) -> &'static str {
        match self {
            Doubt::Disk => {
                "a disk's emptiness was decided by the nearest point found, within rounding of \
                 the boundary"
            }
            Doubt::Junction => {
                "a junction's tri-tangent disk was not proven within 1e-9 of the size of it"
            }
            Doubt::Graph => "the graph is not one connected piece with one cycle per hole",
            Doubt::Coverage => {
                "the feet of the edges do not cover the boundaries once round: a piece of the \
                 axis may be missing"
            }
            Doubt::Corner => {
                "a corner leaf is not at a corner of the boundary convex for the region"
            }
            Doubt::End => {
                "an end was not proven at an arc's centre, or at a centre of curvature within \
                 the tolerance of a proven peak of the curvature"
            }
            Doubt::SearchLimit => "a search limit was hit",
            Doubt::Cancelled => "the work was cancelled before the axis was proven",
        }
    }

    /// The reason as the result states it for `axis` of `sites`: where a piece may be
    /// missing (the graph's shape or the feet's gap), with the first convex corner no leaf
    /// reaches, if any.
    pub(crate) fn stated(self, sites: &Sites<'_>, axis: &MedialAxis) -> String {
        let reason = self.reason();
        if !matches!(self, Doubt::Graph | Doubt::Coverage) {
            return reason.to_string();
        }
        let unreached = crate::coverage::unreached_convex_corners(sites, axis);
        let Some(first) = unreached.first() else {
            return reason.to_string();
        };
        let more = match unreached.len() - 1 {
            0 => String::new(),
            1 => " (and 1 more such corner)".to_string(),
            m => format!(" (and {m} more such corners)"),
        };
        format!(
            "{reason}: no leaf reaches the convex corner at ({}, {}) of boundary {}, which turns \
             by {:.1e} rad{more}",
            first.xy[0], first.xy[1], first.boundary, first.turn,
        )
    }
}

/// The first node of `axis` whose place is not proven, as a doubt; `tol` is the parameter
/// tolerance an end's peak of curvature is proven to. Junctions at the places in `proven`
/// (bits of their coordinates) were proven by the caller, disk and place.
pub(crate) fn doubt(
    sites: &Sites<'_>,
    axis: &MedialAxis,
    tol: f64,
    proven: &HashSet<[u64; 2]>,
) -> Option<Doubt> {
    // The edges at each node, for its feet.
    let mut edges_at: Vec<Vec<usize>> = vec![Vec::new(); axis.nodes.len()];
    for (k, e) in axis.edges.iter().enumerate() {
        edges_at[e.from].push(k);
        if e.to != e.from {
            edges_at[e.to].push(k);
        }
    }
    let corners = Corners::of(sites);
    // (A node's proof may take milliseconds: the watch is looked at for each.)
    let stage = curve::watch::stage("medial axis: the certificate, node by node");
    axis.nodes.iter().find_map(|node| {
        if !stage.go_on(1) {
            return Some(Doubt::Cancelled);
        }
        // A junction's or an end's disk is empty (to the slack): the node is on the axis.
        let empty = || sites.disk(node.xy, node.radius) == Disk::Empty;
        let same = SAME_FOOT * sites.size;
        let feet = || feet_of(sites, axis, &edges_at[node.id], node.id, same);
        let proven = match node.kind {
            NodeKind::Junction => {
                proven.contains(&node.xy.map(f64::to_bits))
                    || (empty()
                        && (junction_proven(sites, node, &feet())
                            || closed_form_junction_proven(
                                sites,
                                node,
                                &feet_of(sites, axis, &edges_at[node.id], node.id, 0.0),
                            )))
            }
            NodeKind::End => {
                let feet = feet();
                empty()
                    && (end_on_arc(sites, node, &feet)
                        || end_at_curvature_peak(sites, node, &feet, tol))
            }
            NodeKind::Corner => corners.at_corner(sites, node),
            NodeKind::Joint | NodeKind::Clip => true,
        };
        (!proven).then_some(match node.kind {
            NodeKind::Junction => Doubt::Junction,
            NodeKind::Corner => Doubt::Corner,
            _ => Doubt::End,
        })
    })
}

/// Whether the graph is connected with `holes` independent cycles, as the axis inside a
/// region with that many holes is (a deformation retract of it).
pub(crate) fn shaped_like_the_region(axis: &MedialAxis, holes: usize) -> bool {
    let n = axis.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    for e in &axis.edges {
        let (a, b) = (root(&mut parent, e.from), root(&mut parent, e.to));
        parent[a] = b;
    }
    let pieces = (0..n).filter(|&i| root(&mut parent, i) == i).count();
    pieces == 1 && axis.edges.len() + 1 == n + holes
}

/// A contact of a node's disk with the boundary: boundary, profile parameter, point.
#[derive(Debug, Clone, Copy)]
struct Foot {
    boundary: usize,
    u: f64,
    xy: [f64; 2],
}

/// The feet of the ends at node `id` of `edges` (the axis's edges that end there), those on
/// one boundary within `same` of each other as one.
fn feet_of(
    sites: &Sites<'_>,
    axis: &MedialAxis,
    edges: &[usize],
    id: usize,
    same: f64,
) -> Vec<Foot> {
    let mut out: Vec<Foot> = Vec::new();
    for e in edges.iter().map(|&k| &axis.edges[k]) {
        let ends = [(e.from == id, 0), (e.to == id, e.feet.len() - 1)];
        for (at, k) in ends {
            if !at {
                continue;
            }
            for s in 0..2 {
                let (b, u) = (e.boundary[k][s], e.feet[k][s]);
                let xy = sites.foot(b, u);
                if !out
                    .iter()
                    .any(|f| f.boundary == b && distance(f.xy, xy) <= same)
                {
                    out.push(Foot { boundary: b, u, xy });
                }
            }
        }
    }
    out
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Whether an end lies at the centre of an arc one of its feet is on (at a joint, either
/// segment there), with its radius; where it has no edge (the whole axis), at the centre of
/// every arc of the boundary, which is then one circle.
fn end_on_arc(sites: &Sites<'_>, node: &Node, feet: &[Foot]) -> bool {
    let room = JUNCTION_ROOM[1] * sites.size;
    let centre_of = |s: &curve::Segment| {
        s.circle()
            .is_some_and(|(c, r)| distance(c, node.xy) <= room && (r - node.radius).abs() <= room)
    };
    if feet.is_empty() {
        // (A node with no edge is the whole axis: the disk touches the whole boundary.)
        return sites
            .boundaries
            .iter()
            .all(|b| b.segments().iter().all(centre_of));
    }
    feet.iter().any(|f| {
        let b = sites.boundaries[f.boundary];
        let (i, n) = (b.locate(f.u).0, b.segments().len());
        // A foot at a joint is on both segments there (which one its parameter locates is
        // a matter of rounding): the neighbour across is tried too.
        let seg = &b.segments()[i];
        let at = |p: curve::V2| distance(p.arr(), f.xy) <= room;
        let before = (i > 0 || b.is_closed()).then(|| (i + n - 1) % n);
        let after = (i + 1 < n || b.is_closed()).then(|| (i + 1) % n);
        [
            Some(i),
            before.filter(|_| at(seg.start())),
            after.filter(|_| at(seg.end())),
        ]
        .into_iter()
        .flatten()
        .any(|j| centre_of(&b.segments()[j]))
    })
}

/// Whether an end lies at the centre of curvature of one of its feet (on either segment at
/// a joint), with that radius, where the curvature's magnitude is proven to rise `tol`
/// before the foot and to fall `tol` after it; at a corner, on that segment's side only.
fn end_at_curvature_peak(sites: &Sites<'_>, node: &Node, feet: &[Foot], tol: f64) -> bool {
    let room = JUNCTION_ROOM[1] * sites.size;
    feet.iter().any(|f| {
        let b = sites.boundaries[f.boundary];
        let n = b.domain().1;
        let (i, _) = b.locate(f.u);
        let beside = if f.u == i as f64 && (i > 0 || b.is_closed()) {
            Some((i + b.segments().len() - 1) % b.segments().len())
        } else {
            None
        };
        let at_centre = |s: usize| {
            let j = b.jet_on(s, f.u, 2);
            let k = j.curvature();
            let centre = j.p + j.d1.perp().unit() * (1.0 / k);
            k != 0.0
                && distance(centre.arr(), node.xy) <= room
                && (1.0 / k.abs() - node.radius).abs() <= room
        };
        // At a corner the branch ends as the foot on one segment closes in on the corner's
        // point: the curvature need peak on that segment's side only.
        let corner = f.u == i as f64 && b.corners().any(|j| j.u == f.u);
        let (before, after) = (f.u - tol, f.u + tol);
        let on = |u: f64| {
            if b.is_closed() {
                Some(u.rem_euclid(n))
            } else {
                (0.0..=n).contains(&u).then_some(u)
            }
        };
        let rate = |u: Option<f64>| u.and_then(|u| proven_rate_sign(b, b.locate(u).0, u));
        let rises_before = || rate(on(before)) == Some(1.0);
        let falls_after = || rate(on(after)) == Some(-1.0);
        // On the segment holding the foot (starting there at a corner), or on the one
        // ending there.
        let on_this = at_centre(i) && (corner || rises_before()) && falls_after();
        let on_beside =
            beside.is_some_and(at_centre) && rises_before() && (corner || falls_after());
        on_this || on_beside
    })
}

/// The corners of the boundaries (boundary, profile parameter), sorted by their points' x.
struct Corners(Vec<([f64; 2], usize, f64)>);

impl Corners {
    fn of(sites: &Sites<'_>) -> Self {
        let mut all: Vec<([f64; 2], usize, f64)> = sites
            .boundaries
            .iter()
            .enumerate()
            .flat_map(|(k, b)| b.corners().map(move |j| (b.jet(j.u).p.arr(), k, j.u)))
            .collect();
        all.sort_by(|a, b| a.0[0].total_cmp(&b.0[0]));
        Self(all)
    }

    /// Whether a corner leaf lies at a corner of the boundary that is convex for the part
    /// of the plane whose axis is sought (a reflex one's cone points into it: no leaf ends
    /// there).
    fn at_corner(&self, sites: &Sites<'_>, node: &Node) -> bool {
        let room = JUNCTION_ROOM[1] * sites.size;
        within_in_x(&self.0, |c| c.0, node.xy, room).any(|&(p, k, u)| {
            distance(p, node.xy) <= room && !sites.inside_of(k, 0, u, true, node.xy)
        })
    }
}

/// Whether a point equidistant from three stretches of the boundary about three of the
/// junction's feet is proven within `JUNCTION_ROOM` of it.
fn junction_proven(sites: &Sites<'_>, node: &Node, feet: &[Foot]) -> bool {
    if feet.len() < 3 {
        return false;
    }
    let contacts: Vec<Contact> = feet[..3]
        .iter()
        .map(|f| Contact::new(sites, f, feet))
        .collect();
    POLYGONS.iter().any(|polygon| {
        JUNCTION_ROOM.iter().any(|&room| {
            let h = room * sites.size;
            winds_round_zero(sites, node.xy, h, polygon, &contacts)
        })
    })
}

/// Whether the sites about the feet of a junction (all its edges' ends there, unmerged) are
/// three lines or reflex corners and Krawczyk's test proves a point equidistant from them
/// within `JUNCTION_ROOM` of it ([`proven_within`]): where the distances' differences are
/// nearly parallel (two sides meeting at a corner that turns by 1e-6 rad, their feet closer
/// than feet are merged), which the winding test cannot part.
fn closed_form_junction_proven(sites: &Sites<'_>, node: &Node, feet: &[Foot]) -> bool {
    let x = V2::from_arr(node.xy);
    JUNCTION_ROOM.iter().any(|&room| {
        let reach = room * sites.size;
        let mut closed: Vec<ClosedSite> = Vec::new();
        for f in feet {
            match closed_site_at(sites, f.boundary, f.u, x, reach) {
                Some(site) if !closed.contains(&site) => closed.push(site),
                Some(_) => {}
                None => return false,
            }
        }
        // (The box's half-width: its corners within the room of its centre.)
        <[ClosedSite; 3]>::try_from(closed)
            .is_ok_and(|c| proven_within(c, x, reach / std::f64::consts::SQRT_2))
    })
}

/// A stretch of the boundary about one foot: from halfway to the feet beside it on its
/// boundary (the whole boundary where it has no other), so the three are apart.
struct Contact {
    boundary: usize,
    lo: f64,
    hi: f64,
    xy: [f64; 2],
}

impl Contact {
    fn new(sites: &Sites<'_>, f: &Foot, feet: &[Foot]) -> Self {
        let b = sites.boundaries[f.boundary];
        let n = b.domain().1;
        let apart = |u: f64| {
            let d = (u - f.u).abs();
            if b.is_closed() {
                d.min(n - d)
            } else {
                d
            }
        };
        let half = feet
            .iter()
            .filter(|g| g.boundary == f.boundary && g.u != f.u)
            .map(|g| 0.5 * apart(g.u))
            .fold(n, f64::min);
        Self {
            boundary: f.boundary,
            lo: f.u - half,
            hi: f.u + half,
            xy: f.xy,
        }
    }

    /// Bounds on the distance from `x` to the stretch: disks proven clear of it and entered
    /// by it, `room` inside and outside the distance to the foot (`None` where either is not
    /// proven).
    fn enclose(&self, sites: &Sites<'_>, x: [f64; 2], room: f64) -> Option<[f64; 2]> {
        let b = sites.boundaries[self.boundary];
        let d = distance(x, self.xy);
        let clear = b.clearance_between(x, d - room, self.lo, self.hi) == Clearance::Clear;
        let entered = matches!(
            b.clearance_between(x, d + room, self.lo, self.hi),
            Clearance::Entered { .. }
        );
        (clear && entered).then_some([d - room, d + room])
    }
}

/// A corner of the polygon about the junction: its angle, point and the enclosures of the
/// map's two components there.
#[derive(Clone, Copy)]
struct Corner {
    angle: f64,
    xy: [f64; 2],
    map: [[f64; 2]; 2],
    /// Whether the corner, without a quadrant, is passed over: one component of the map
    /// keeps one sign along both sides at it (see [`winds_round_zero`]).
    passed: bool,
}

impl Corner {
    /// The quadrant of the map's value (0 to 3, counterclockwise from both positive), if
    /// both components are proven of one sign.
    fn quadrant(&self) -> Option<i32> {
        let sign = |e: [f64; 2]| {
            if e[0] > 0.0 {
                Some(true)
            } else if e[1] < 0.0 {
                Some(false)
            } else {
                None
            }
        };
        Some(match (sign(self.map[0])?, sign(self.map[1])?) {
            (true, true) => 0,
            (false, true) => 1,
            (false, false) => 2,
            (true, false) => 3,
        })
    }
}

/// Whether the map `(dA − dB, dA − dC)` winds round zero along a polygon inscribed in the
/// circle of radius `h` about `centre`: a zero inside, the point equidistant from the three.
fn winds_round_zero(
    sites: &Sites<'_>,
    centre: [f64; 2],
    h: f64,
    polygon: &Polygon,
    contacts: &[Contact],
) -> bool {
    // (No narrower than the disk tests can tell: far from the origin a share of the room
    // is below the coordinates' rounding, and no disk that close to the distance is proven.)
    let magnitude = centre[0].abs().max(centre[1].abs()).max(h);
    let room = (polygon.enclosure * h).max(ulps(ENCLOSURE_ULPS) * magnitude);
    if room > MOST_ENCLOSURE * h {
        return false; // (the map's sign then holds at too few of the polygon's corners)
    }
    let most_corners = polygon.most_corners;
    let corner = |angle: f64| -> Option<Corner> {
        let xy = [centre[0] + h * angle.cos(), centre[1] + h * angle.sin()];
        let d: Vec<[f64; 2]> = contacts
            .iter()
            .map(|c| c.enclose(sites, xy, room))
            .collect::<Option<_>>()?;
        let minus = |a: [f64; 2], b: [f64; 2]| [a[0] - b[1], a[1] - b[0]];
        Some(Corner {
            angle,
            xy,
            map: [minus(d[0], d[1]), minus(d[0], d[2])],
            passed: false,
        })
    };
    let tau = std::f64::consts::TAU;
    let mut ring: Vec<Corner> = Vec::with_capacity(most_corners);
    for k in 0..FIRST_CORNERS {
        match corner(tau * k as f64 / FIRST_CORNERS as f64) {
            Some(c) => ring.push(c),
            None => return false,
        }
    }
    // Refined until every corner has a quadrant or is passed over (one that is neither is
    // moved) and every side keeps one component's sign (one that does not is halved).
    let (mut k, mut evaluations) = (0, FIRST_CORNERS);
    while k < ring.len() {
        let next = (k + 1) % ring.len();
        let angle_after = |j: usize| {
            let after = ring[(j + 1) % ring.len()].angle;
            if j + 1 == ring.len() {
                after + tau
            } else {
                after
            }
        };
        let (a, b) = (ring[k], ring[next]);
        if a.passed || b.passed {
            k += 1; // (its sides were proven when it was passed over)
            continue;
        }
        // A corner without a quadrant (the map crosses an axis there within the
        // enclosures' width) between two with one is passed over where one component keeps
        // one sign along both its sides: the map stays in that half-plane from one
        // neighbour to the other, whose quadrants tell the turn.
        let lacking = [k, next]
            .into_iter()
            .find(|&j| ring[j].quadrant().is_none());
        if let Some(j) = lacking {
            let n = ring.len();
            let (p, x, q) = (&ring[(j + n - 1) % n], &ring[j], &ring[(j + 1) % n]);
            let fits = |c: &Corner| c.quadrant().is_some() && !c.passed;
            if fits(p) && fits(q) {
                let (before, after) = (kept_signs(p, x), kept_signs(x, q));
                if (0..2).any(|i| before[i].is_some() && before[i] == after[i]) {
                    ring[j].passed = true;
                    continue;
                }
            }
        }
        // (Otherwise moved a third of the way to its farther neighbour: towards a near one
        // it may stay on one point, far from the origin where the polygon's corners are a
        // few units of rounding of the coordinates apart.)
        let moved_from = |j: usize| {
            let n = ring.len();
            let before = ring[(j + n - 1) % n].angle - if j == 0 { tau } else { 0.0 };
            let (angle, after) = (ring[j].angle, angle_after(j));
            if after - angle >= angle - before {
                angle + (after - angle) / 3.0
            } else {
                angle - (angle - before) / 3.0
            }
        };
        let (at, moved) = if a.quadrant().is_none() {
            (k, moved_from(k))
        } else if b.quadrant().is_none() {
            (next, moved_from(next))
        } else if !side_keeps_a_sign(&a, &b) {
            (usize::MAX, 0.5 * (a.angle + angle_after(k)))
        } else {
            k += 1;
            continue;
        };
        evaluations += 1;
        if ring.len() >= most_corners || evaluations > 2 * most_corners {
            return false;
        }
        let Some(c) = corner(moved) else {
            return false;
        };
        if at == usize::MAX {
            ring.insert(k + 1, c);
        } else {
            ring[at] = c;
        }
    }
    // Each side moves the map to the same or a neighbouring quadrant (from one neighbour
    // of a corner passed over to the other within a half-plane: the same or a neighbouring
    // one too).
    let quadrants: Vec<i32> = ring
        .iter()
        .filter(|c| !c.passed)
        .filter_map(Corner::quadrant)
        .collect();
    let turns: i32 = (0..quadrants.len())
        .map(|k| {
            let (a, b) = (quadrants[k], quadrants[(k + 1) % quadrants.len()]);
            match (b - a).rem_euclid(4) {
                1 => 1,
                3 => -1,
                _ => 0,
            }
        })
        .sum();
    turns != 0
}

/// Whether one component of the map keeps its sign along the side from `a` to `b`.
fn side_keeps_a_sign(a: &Corner, b: &Corner) -> bool {
    kept_signs(a, b).iter().any(Option::is_some)
}

/// Per component of the map, the sign it keeps along the side from `a` to `b` (`true`
/// positive), if proven: each distance is 1-Lipschitz, so each component changes by at
/// most twice the way along.
fn kept_signs(a: &Corner, b: &Corner) -> [Option<bool>; 2] {
    // (The length's rounding allowed for, generously.)
    let length = distance(a.xy, b.xy) * (1.0 + 1e-12);
    [0, 1].map(|i| {
        if a.map[i][0] + b.map[i][0] > 2.0 * length {
            Some(true)
        } else if a.map[i][1] + b.map[i][1] < -2.0 * length {
            Some(false)
        } else {
            None
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{medial_axis, MedialOptions};
    use curve::{Profile, Region, Segment};

    const TOL: f64 = zeroset::DEFAULT_TOL;

    /// A 10 × 6 pocket with rounded corners of radius 1: four ends at the arcs' centres, two
    /// junctions.
    fn pocket() -> Region {
        let (w, h, r) = (10.0, 6.0, 1.0);
        let q = std::f64::consts::FRAC_PI_2;
        let segs = vec![
            Segment::line([r, 0.0], [w - r, 0.0]),
            Segment::arc([w - r, r], r, -q, 0.0),
            Segment::line([w, r], [w, h - r]),
            Segment::arc([w - r, h - r], r, 0.0, q),
            Segment::line([w - r, h], [r, h]),
            Segment::arc([r, h - r], r, q, 2.0 * q),
            Segment::line([0.0, h - r], [0.0, r]),
            Segment::arc([r, r], r, 2.0 * q, 3.0 * q),
        ];
        let segs = segs
            .into_iter()
            .collect::<Result<Vec<_>, _>>()
            .expect("segments");
        Region::new(Profile::new(segs, None).expect("profile"), vec![]).expect("region")
    }

    #[test]
    fn a_pocket_of_lines_and_arcs_is_certified() {
        let region = pocket();
        let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
        assert!(axis.certified, "{:?}", axis.reason);
        assert_eq!(
            doubt(&Sites::new(&region, false), &axis, TOL, &HashSet::new()),
            None
        );
    }

    #[test]
    fn a_junction_moved_off_its_place_is_not_proven() {
        let region = pocket();
        let sites = Sites::new(&region, false);
        let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
        let j = axis
            .nodes
            .iter()
            .position(|n| n.kind == NodeKind::Junction)
            .expect("a junction");
        // 2e-9 of the size off: the exact point lies outside both disks searched about it.
        let mut moved = axis.clone();
        moved.nodes[j].xy[1] += 2e-9 * sites.size;
        assert_eq!(
            doubt(&sites, &moved, TOL, &HashSet::new()),
            Some(Doubt::Junction)
        );
        // Within the first disk's room it stays proven.
        let mut nudged = axis.clone();
        nudged.nodes[j].xy[1] += 0.2 * JUNCTION_ROOM[0] * sites.size;
        assert_eq!(doubt(&sites, &nudged, TOL, &HashSet::new()), None);
    }

    /// A 10 × 6 box whose bottom side bends outwards at its middle by `turn` (rad): a convex
    /// corner whose leaf meets the two bottom sides' bisectors with the top's at a junction
    /// whose two equations of the bottom sides are nearly one.
    fn bent_box(turn: f64) -> Region {
        let dip = 5.0 * (0.5 * turn).tan();
        let c = [
            [0.0, 0.0],
            [5.0, -dip],
            [10.0, 0.0],
            [10.0, 6.0],
            [0.0, 6.0],
        ];
        let sides = (0..5)
            .map(|i| Segment::line(c[i], c[(i + 1) % 5]))
            .collect::<Result<Vec<_>, _>>()
            .expect("sides");
        Region::new(Profile::new(sides, None).expect("profile"), vec![]).expect("box")
    }

    /// Beside a convex corner that turns by 1e-3 to 1e-5 rad, the junction on its leaf is
    /// proven in closed form (Krawczyk's test) where the winding test cannot part its
    /// equations (from 1e-4 rad on), and lies where the closed form puts it: on the leaf
    /// `x = 5`, as far from the top as from the bottom sides' lines.
    #[test]
    fn a_junction_beside_a_nearly_flat_corner_is_proven_in_closed_form() {
        for turn in [1e-3, 1e-4, 1e-5] {
            let region = bent_box(turn);
            let sites = Sites::new(&region, false);
            let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
            assert!(axis.certified, "{turn}: {:?}", axis.reason);
            let node = axis
                .nodes
                .iter()
                .find(|n| n.kind == NodeKind::Junction && (n.xy[0] - 5.0).abs() < 0.5)
                .expect("the leaf's junction");
            // (The bottom-left side's unit normal, and the distance from it equal to 6 − y.)
            let dip = 5.0 * (0.5 * turn).tan();
            let normal = V2::new(dip, 5.0) * (1.0 / dip.hypot(5.0));
            let y = (6.0 - 5.0 * normal.x) / (normal.y + 1.0);
            let off = (V2::from_arr(node.xy) - V2::new(5.0, y)).norm();
            assert!(off < JUNCTION_ROOM[1] * sites.size, "{turn}: {off:e}");
            if turn <= 1e-4 {
                let mut edges: Vec<usize> = Vec::new();
                for (k, e) in axis.edges.iter().enumerate() {
                    if e.from == node.id || e.to == node.id {
                        edges.push(k);
                    }
                }
                let same = SAME_FOOT * sites.size;
                let merged = feet_of(&sites, &axis, &edges, node.id, same);
                assert!(!junction_proven(&sites, node, &merged), "{turn}");
                let all = feet_of(&sites, &axis, &edges, node.id, 0.0);
                assert!(closed_form_junction_proven(&sites, node, &all), "{turn}");
            }
        }
    }

    #[test]
    fn a_graph_missing_an_edge_or_with_a_cycle_too_many_is_no_region_axis() {
        let axis = medial_axis(&pocket(), &MedialOptions::default()).expect("axis");
        assert!(shaped_like_the_region(&axis, 0));
        let mut cut = axis.clone();
        cut.edges.pop();
        assert!(!shaped_like_the_region(&cut, 0));
        let mut looped = axis.clone();
        let twin = looped.edges[0].clone();
        looped.edges.push(twin);
        assert!(!shaped_like_the_region(&looped, 0));
        assert!(shaped_like_the_region(&looped, 1));
    }

    #[test]
    fn a_corner_leaf_at_a_reflex_corner_is_not_proven() {
        let c = [[0., 0.], [4., 0.], [4., 2.], [2., 2.], [2., 4.], [0., 4.]];
        let sides = (0..6)
            .map(|i| Segment::line(c[i], c[(i + 1) % 6]))
            .collect::<Result<Vec<_>, _>>()
            .expect("sides");
        let room = Region::new(Profile::new(sides, None).expect("profile"), vec![]).expect("room");
        let sites = Sites::new(&room, false);
        let mut axis = medial_axis(&room, &MedialOptions::default()).expect("axis");
        assert!(axis.certified, "{:?}", axis.reason);
        let k = axis
            .nodes
            .iter()
            .position(|n| n.kind == NodeKind::Corner)
            .expect("a corner");
        axis.nodes[k].xy = [2.0, 2.0]; // the reflex corner
        assert_eq!(
            doubt(&sites, &axis, TOL, &HashSet::new()),
            Some(Doubt::Corner)
        );
    }

    #[test]
    fn an_end_off_its_arcs_centre_is_not_proven() {
        let region = pocket();
        let sites = Sites::new(&region, false);
        let mut axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
        let e = axis
            .nodes
            .iter()
            .position(|n| n.kind == NodeKind::End)
            .expect("an end");
        axis.nodes[e].xy[0] += 2e-9 * sites.size;
        assert_eq!(doubt(&sites, &axis, TOL, &HashSet::new()), Some(Doubt::End));
    }

    /// The periodic cubic: two ends at centres of curvature of its sharpest points.
    fn periodic_cubic() -> Region {
        let pts = [
            [0.0, 0.0],
            [2.0, -1.0],
            [4.0, 0.0],
            [4.0, 2.0],
            [2.0, 1.2],
            [0.0, 2.0],
        ];
        let periodic = curve::SplineCurve::periodic(3, &pts, None).expect("spline");
        let (a, b) = periodic.domain();
        let one_turn = periodic.curve().restrict(a, b).expect("restricted");
        let c = curve::SplineCurve::new(one_turn).expect("spline");
        let seg = Segment::spline(curve::SegmentKind::BSpline, c).expect("segment");
        let outline = Profile::new(vec![seg], Some(true)).expect("profile");
        Region::new(outline, vec![]).expect("region")
    }

    #[test]
    fn ends_at_proven_peaks_of_a_splines_curvature_are_certified() {
        let region = periodic_cubic();
        let sites = Sites::new(&region, false);
        let axis = medial_axis(&region, &MedialOptions::default()).expect("axis");
        assert!(axis.certified, "{:?}", axis.reason);
        assert_eq!(axis.nodes.len(), 2);
        // The same end moved to the centre of curvature 1e-6 along the boundary from its
        // foot: a centre of curvature, but no peak within the tolerance of its foot.
        let mut moved = axis.clone();
        let (e, edge) = (0, &mut moved.edges[0]);
        let (k, u) = if edge.from == e {
            (0, edge.feet[0][0])
        } else {
            (edge.feet.len() - 1, edge.feet[edge.feet.len() - 1][0])
        };
        let b = sites.boundaries[0];
        let v = u + 1e-6;
        let j = b.jet_on(b.locate(v).0, v, 2);
        let centre = j.p + j.d1.perp().unit() * (1.0 / j.curvature());
        edge.feet[k] = [v, v];
        moved.nodes[e].xy = centre.arr();
        moved.nodes[e].radius = 1.0 / j.curvature().abs();
        assert_eq!(
            doubt(&sites, &moved, TOL, &HashSet::new()),
            Some(Doubt::End)
        );
        // Its disk is still empty: the rates decided.
        assert_eq!(
            sites.disk(moved.nodes[e].xy, moved.nodes[e].radius),
            Disk::Empty
        );
    }
}
