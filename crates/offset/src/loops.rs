//! The loops of an offset: the stretches of boundary kept at the distance (where the axis's
//! radius exceeds it), joined across the seams where the two sides of the axis meet.

use crate::seams::Seam;
use crate::walk::{incoming_segment, outgoing_segment, OffsetSource, Walk};
use std::f64::consts::TAU;

/// A run of one boundary, walked from one foot to another (the whole boundary when
/// `whole`), `length` in parameter along the walk (taken from the order of the seams' feet, so
/// that a stretch from a foot round the whole boundary to the same place is the whole length).
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoundaryRun {
    pub(crate) boundary: usize,
    pub(crate) from: OffsetSource,
    pub(crate) to: OffsetSource,
    pub(crate) whole: bool,
    pub(crate) length: f64,
}

/// The loops, and whether the seams made sense together (each kept stretch begins at a seam
/// and ends at the next one along its boundary).
pub(crate) struct Loops {
    pub(crate) loops: Vec<Vec<BoundaryRun>>,
    pub(crate) consistent: bool,
}

/// One seam's foot on a boundary, placed along the walk.
struct Event {
    /// How far along the walk (parameter ahead of 0, then the place in a corner's fan).
    place: (f64, f64),
    seam: usize,
    side: usize,
    begins: bool,
}

/// The loops of the offset with `seams`; a boundary without seams is kept whole where
/// `kept_whole` says so.
pub(crate) fn loops(walks: &[Walk<'_>], seams: &[Seam], kept_whole: &[bool]) -> Loops {
    let mut events: Vec<Vec<Event>> = walks.iter().map(|_| Vec::new()).collect();
    for (s, seam) in seams.iter().enumerate() {
        for side in 0..2 {
            let (b, foot) = seam.feet[side];
            events[b].push(Event {
                place: place(&walks[b], foot),
                seam: s,
                side,
                begins: seam.begins[side],
            });
        }
    }
    let mut consistent = true;
    // The stretch beginning at each (seam, side), and the (seam, side) it ends at.
    let mut stretch_at = vec![[None::<(BoundaryRun, (usize, usize))>; 2]; seams.len()];
    let mut loops = Vec::new();
    for (b, list) in events.iter_mut().enumerate() {
        if list.is_empty() {
            if kept_whole.get(b).copied().unwrap_or(false) {
                // (From where the walk enters a segment: the first one's start, or walking
                // against the parameter, the last one's end.)
                let last = walks[b].profile.segments().len() - 1;
                let start = if walks[b].side > 0.0 {
                    OffsetSource::OnSegment { segment: 0, u: 0.0 }
                } else {
                    OffsetSource::OnSegment {
                        segment: last,
                        u: walks[b].period,
                    }
                };
                loops.push(vec![BoundaryRun {
                    boundary: b,
                    from: start,
                    to: start,
                    whole: true,
                    length: walks[b].period,
                }]);
            }
            continue;
        }
        // (At one place, a stretch ending comes before one beginning: the offset touches
        // itself there, where the axis's radius is the distance exactly.)
        list.sort_by(|a, c| {
            (a.place.0.total_cmp(&c.place.0))
                .then(a.place.1.total_cmp(&c.place.1))
                .then(a.begins.cmp(&c.begins))
        });
        for (k, e) in list.iter().enumerate() {
            if !e.begins {
                continue;
            }
            let at = (k + 1) % list.len();
            let next = &list[at];
            if next.begins {
                consistent = false;
                continue;
            }
            let period = walks[b].period;
            let mut length = (next.place.0 - e.place.0).rem_euclid(period);
            // (The next foot reached only round the whole boundary, at the same place: all of
            // it.)
            if at <= k && length == 0.0 {
                length = period;
            }
            let stretch = BoundaryRun {
                boundary: b,
                from: seams[e.seam].feet[e.side].1,
                to: seams[next.seam].feet[next.side].1,
                whole: false,
                length,
            };
            stretch_at[e.seam][e.side] = Some((stretch, (next.seam, next.side)));
        }
    }
    // Follow stretch, seam, stretch… round each loop (at most every stretch once).
    let mut used = vec![[false; 2]; seams.len()];
    for s in 0..seams.len() {
        for side in 0..2 {
            if used[s][side] || stretch_at[s][side].is_none() {
                continue;
            }
            let mut one = Vec::new();
            let (mut at_seam, mut at_side) = (s, side);
            loop {
                used[at_seam][at_side] = true;
                let Some((stretch, (end_seam, end_side))) = stretch_at[at_seam][at_side] else {
                    consistent = false;
                    break;
                };
                one.push(stretch);
                // (Across the seam, the other side's stretch begins.)
                (at_seam, at_side) = (end_seam, 1 - end_side);
                if (at_seam, at_side) == (s, side) {
                    break;
                }
                if used[at_seam][at_side] {
                    consistent = false;
                    break;
                }
            }
            loops.push(one);
        }
    }
    Loops { loops, consistent }
}

/// Where a foot is along its boundary's walk: the parameter ahead of 0, then, at a reflex
/// corner, the place in its fan (clockwise from the incoming segment's normal; a foot on the
/// outgoing segment after the whole fan).
fn place(walk: &Walk<'_>, foot: OffsetSource) -> (f64, f64) {
    match foot {
        OffsetSource::OnSegment { segment, u } => {
            let along = walk.ahead(0.0, u);
            let outgoing = walk.joint_at(u).is_some() && outgoing_segment(walk, u) == segment;
            (along, if outgoing { 2.0 * TAU } else { 0.0 })
        }
        OffsetSource::Fan { u, angle } => {
            let incoming = incoming_segment(walk, u);
            let start = walk.normal_leaving(incoming).angle();
            (walk.ahead(0.0, u), 1e-9 + (start - angle).rem_euclid(TAU))
        }
    }
}
