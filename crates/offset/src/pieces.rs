//! The geometry of a kept stretch at the distance: each segment's offset (a line of a line, an
//! arc of an arc, a curve within the chord tolerance of a spline's) and, at each reflex
//! corner it passes, the arc about the corner.

use crate::loops::BoundaryRun;
use crate::spline_offset::spline_offset;
use crate::walk::{incoming_segment, outgoing_segment};
use crate::walk::{OffsetSource, Walk};
use crate::OffsetSegment;
use curve::{SegmentKind, V2};
use std::f64::consts::TAU;

/// The offset pieces of `stretch` at distance `d`, its spline pieces within `chord` of the
/// exact offset at the points measured; appended to `out`, the largest distance measured
/// raising `error`.
pub(crate) fn pieces(
    walk: &Walk<'_>,
    stretch: &BoundaryRun,
    d: f64,
    chord: f64,
    out: &mut Vec<OffsetSegment>,
    error: &mut f64,
) {
    let n = walk.profile.segments().len();
    let (mut at, mut segment) = match stretch.from {
        OffsetSource::OnSegment { segment, u } => (u, segment),
        OffsetSource::Fan { u, angle } => {
            let outgoing = outgoing_segment(walk, u);
            let end = match stretch.to {
                OffsetSource::Fan { u: v, angle: a } if !stretch.whole && same(walk, u, v) => {
                    if fan_place(walk, u, a) >= fan_place(walk, u, angle) {
                        out.push(corner_arc(walk, u, angle, a, d));
                        return;
                    }
                    walk.normal_entering(outgoing).angle()
                }
                _ => walk.normal_entering(outgoing).angle(),
            };
            out.push(corner_arc(walk, u, angle, end, d));
            (u, outgoing)
        }
    };
    let target = stretch.length;
    let mut walked = 0.0;
    // (Each step is one segment: the walk passes every segment at most once more.)
    for _ in 0..=n + 1 {
        let leave = if walk.side > 0.0 {
            segment as f64 + 1.0
        } else {
            segment as f64
        };
        let enter = if walk.side > 0.0 {
            segment as f64
        } else {
            segment as f64 + 1.0
        };
        // (Standing where a segment is entered, the walk crosses all of it: on a boundary of
        // one segment, entering and leaving are the same parameter.)
        let span = match walk.ahead(at, leave) {
            0.0 if walk.ahead(enter, at) == 0.0 => 1.0,
            span => span,
        };
        let ends_here = match stretch.to {
            OffsetSource::OnSegment { segment: s, .. } => {
                s == segment && walked + span >= target - 1e-12
            }
            OffsetSource::Fan { .. } => false,
        } || (stretch.whole && walked + span >= target - 1e-12);
        if ends_here {
            let to = if stretch.whole {
                leave
            } else {
                param(stretch.to)
            };
            segment_piece(walk, segment, [at, to], d, chord, out, error);
            // (A whole boundary closes at the joint it started from: its corner's arc too.)
            let at = leave.rem_euclid(walk.period);
            if stretch.whole && walk.reflex_corner_at(at).is_some() {
                let from = walk.normal_leaving(segment).angle();
                let next = outgoing_segment(walk, at);
                out.push(corner_arc(
                    walk,
                    at,
                    from,
                    walk.normal_entering(next).angle(),
                    d,
                ));
            }
            return;
        }
        segment_piece(walk, segment, [at, leave], d, chord, out, error);
        walked += span;
        at = leave.rem_euclid(walk.period);
        let next = outgoing_segment(walk, at);
        if walk.reflex_corner_at(at).is_some() {
            let from = walk.normal_leaving(segment).angle();
            match stretch.to {
                OffsetSource::Fan { u, angle } if same(walk, u, at) && walked >= target - 1e-12 => {
                    out.push(corner_arc(walk, at, from, angle, d));
                    return;
                }
                _ => out.push(corner_arc(
                    walk,
                    at,
                    from,
                    walk.normal_entering(next).angle(),
                    d,
                )),
            }
        }
        segment = next;
    }
}

/// Steps over which an arc piece's turn is summed: each turns by less than half a turn (an
/// arc segment turns by at most a whole one).
const SWEEP_STEPS: usize = 8;

/// Parameters this close (in a profile's parameter, one a segment) name the same point.
const PARAMETER_ROUNDING: f64 = 1e-12;

/// A foot's profile parameter.
fn param(foot: OffsetSource) -> f64 {
    match foot {
        OffsetSource::OnSegment { u, .. } | OffsetSource::Fan { u, .. } => u,
    }
}

/// Whether two parameters name the same joint.
fn same(walk: &Walk<'_>, u: f64, v: f64) -> bool {
    let d = (u - v).rem_euclid(walk.period);
    d.min(walk.period - d) < 1e-9
}

/// How far clockwise from the incoming normal `angle` is in the fan at `u`.
fn fan_place(walk: &Walk<'_>, u: f64, angle: f64) -> f64 {
    let start = walk.normal_leaving(incoming_segment(walk, u)).angle();
    (start - angle).rem_euclid(TAU)
}

/// The arc of radius `d` about the corner at `u`, clockwise (the walk turns right there) from
/// the direction `from` to `to`.
fn corner_arc(walk: &Walk<'_>, u: f64, from: f64, to: f64, d: f64) -> OffsetSegment {
    // (Within the corner's own fan: an end an ulp outside it is at its edge, not a turn
    // round.)
    let fan = (walk.normal_leaving(incoming_segment(walk, u)).angle()
        - walk.normal_entering(outgoing_segment(walk, u)).angle())
    .rem_euclid(TAU);
    let sweep = match (from - to).rem_euclid(TAU) {
        s if s <= fan => s,
        s if TAU - s < s - fan => 0.0,
        _ => fan,
    };
    OffsetSegment::Arc {
        center: walk.point(u).arr(),
        r: d,
        start: from,
        end: from - sweep,
    }
}

/// The offset of segment `segment` from `from` to `to` (profile parameters, in the walk's
/// direction); a spline's measured distance from the exact offset raises `error`.
fn segment_piece(
    walk: &Walk<'_>,
    segment: usize,
    [from, to]: [f64; 2],
    d: f64,
    chord: f64,
    out: &mut Vec<OffsetSegment>,
    error: &mut f64,
) {
    // (The walk enters a segment at one end and leaves at the other: a parameter on the
    // period's seam is 0 at the first segment's start and the period at the last one's end.)
    let (enter, leave) = if walk.side > 0.0 {
        (segment as f64, segment as f64 + 1.0)
    } else {
        (segment as f64 + 1.0, segment as f64)
    };
    let on_segment = |u: f64, end: f64| {
        let u = u.rem_euclid(walk.period);
        let v = if (u - end).abs() <= PARAMETER_ROUNDING
            || (u + walk.period - end).abs() <= PARAMETER_ROUNDING
        {
            end
        } else {
            u
        };
        v.clamp(segment as f64, segment as f64 + 1.0)
    };
    let (from, to) = (on_segment(from, enter), on_segment(to, leave));
    // (A stretch that only touches a segment at its end has nothing of it; nor does one that
    // reaches into it by a parameter's rounding, as a seam's foot solved a rounding past a
    // joint does: its piece would be a point, which the reader refuses as singular, and the
    // pieces either side meet within rounding.)
    if (to - from).abs() <= PARAMETER_ROUNDING {
        return;
    }
    let point = |u: f64| walk.offset(OffsetSource::OnSegment { segment, u }, d).0;
    let seg = &walk.profile.segments()[segment];
    match (seg.kind(), seg.circle()) {
        (SegmentKind::Line, _) => out.push(OffsetSegment::Line {
            from: point(from).arr(),
            to: point(to).arr(),
        }),
        (SegmentKind::Arc, Some((center, _))) => {
            let c = V2::from_arr(center);
            let (p, q) = (point(from) - c, point(to) - c);
            // The sweep: the angle between the ends, the turn nearest the one summed over
            // steps of the piece (a whole circle's ends are one point, a nearly whole one's
            // ends a rounding apart: the steps tell a turn from nothing).
            let angles: Vec<f64> = (0..=SWEEP_STEPS)
                .map(|j| (point(from + (to - from) * j as f64 / SWEEP_STEPS as f64) - c).angle())
                .collect();
            let turned: f64 = angles.windows(2).map(|w| curve::wrap_pi(w[1] - w[0])).sum();
            let (a, b) = (p.angle(), q.angle());
            let between = curve::wrap_pi(b - a);
            let turns = ((turned - between) / TAU).round();
            out.push(OffsetSegment::Arc {
                center,
                r: p.norm(),
                start: a,
                end: a + between + turns * TAU,
            });
        }
        _ => {
            let (piece, measured) = spline_offset(&point, from, to, chord);
            out.push(piece);
            *error = error.max(measured);
        }
    }
}
