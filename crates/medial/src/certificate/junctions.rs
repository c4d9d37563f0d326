//! The proofs of junctions' places: the map of the distances' differences winding round
//! zero along a polygon about the junction (Brouwer's degree), or, for three lines or reflex
//! corners, Krawczyk's test in closed form.

use super::{distance, DiskContact, JUNCTION_ROOM};
use crate::junction_proof::{closed_site_at, proven_within, ClosedSite};
use crate::sites::Sites;
use crate::Node;
use curve::{ParamCurve, V2};
use geometry::{Clearance, ProfileClearance};
use numeric::rounding::ulps;

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
/// times the disk tests' own allowance ([`geometry::ProfileClearance::clearance`] allows 16).
const ENCLOSURE_ULPS: f64 = 64.0;

/// The widest enclosure of a distance a polygon is tried with, as a share of its radius.
const MOST_ENCLOSURE: f64 = 0.25;

/// Corners of the first polygon about a junction.
const FIRST_CORNERS: usize = 8;

/// Whether a point equidistant from three stretches of the boundary about three of the
/// junction's feet is proven within `JUNCTION_ROOM` of it.
pub(super) fn junction_proven(sites: &Sites<'_>, node: &Node, feet: &[DiskContact]) -> bool {
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
pub(super) fn closed_form_junction_proven(
    sites: &Sites<'_>,
    node: &Node,
    feet: &[DiskContact],
) -> bool {
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
    fn new(sites: &Sites<'_>, f: &DiskContact, feet: &[DiskContact]) -> Self {
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
struct RingCorner {
    angle: f64,
    xy: [f64; 2],
    map: [[f64; 2]; 2],
    /// Whether the corner, without a quadrant, is passed over: one component of the map
    /// keeps one sign along both sides at it (see [`winds_round_zero`]).
    passed: bool,
}

impl RingCorner {
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
    let corner = |angle: f64| -> Option<RingCorner> {
        let xy = [centre[0] + h * angle.cos(), centre[1] + h * angle.sin()];
        let d: Vec<[f64; 2]> = contacts
            .iter()
            .map(|c| c.enclose(sites, xy, room))
            .collect::<Option<_>>()?;
        let minus = |a: [f64; 2], b: [f64; 2]| [a[0] - b[1], a[1] - b[0]];
        Some(RingCorner {
            angle,
            xy,
            map: [minus(d[0], d[1]), minus(d[0], d[2])],
            passed: false,
        })
    };
    let tau = std::f64::consts::TAU;
    let mut ring: Vec<RingCorner> = Vec::with_capacity(most_corners);
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
            let fits = |c: &RingCorner| c.quadrant().is_some() && !c.passed;
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
        .filter_map(RingCorner::quadrant)
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
fn side_keeps_a_sign(a: &RingCorner, b: &RingCorner) -> bool {
    kept_signs(a, b).iter().any(Option::is_some)
}

/// Per component of the map, the sign it keeps along the side from `a` to `b` (`true`
/// positive), if proven: each distance is 1-Lipschitz, so each component changes by at
/// most twice the way along.
fn kept_signs(a: &RingCorner, b: &RingCorner) -> [Option<bool>; 2] {
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
