//! Common tangent lines of two profiles (the contract's definition): lines tangent to both at
//! smooth points (Jia §2.5, segment by segment), and lines through a corner whose direction,
//! either way along the line, lies strictly between the corner's incoming and outgoing
//! tangent directions (its tangent cone), convex and reflex corners alike: through a corner of
//! one profile and tangent to the other at a smooth point (a root of `(Q(t) − C) × Q′(t)`,
//! isolated by certified root finding), or through a corner of each.
//!
//! A straight segment's tangent line is the segment's own line: it takes part through its end
//! corners only (a line along a straight segment and tangent elsewhere is a limit case). A
//! tangency at a segment's end where the profile has a corner has its direction on the cone's
//! edge: a limit case, left out.

use crate::error::{Error, Result};
use crate::prepare::common_tangents_run;
use crate::profiles::{at_corner, FAN_NOISE};
use crate::types::{Options, Provenance, TangentLine, Tangents};
use bspline::roots::{find_roots, RootKind, RootOptions};
use curve::{Frame, JointKind, ParamCurve, Profile, SegmentKind, SplineCurve, V2};
use numeric::certificate::{Certified, Doubt, Doubts};

/// How far inside a corner's tangent cone (the sine of the angle to its nearer edge) a
/// direction must be: far above the rounding of unit directions, far below any drawn angle.
const CONE_EDGE: f64 = 1e-9;

/// Most pairs of curved segments searched for common tangents (each pair is one run of the
/// two-curve search, some tens of microseconds): keeps a run within seconds.
pub const MAX_SEGMENT_PAIRS: usize = 40_000;

/// Two lines whose points of tangency are this close (relative to the size; and never less
/// than the rounding of the profiles' points, [`Profile::point_rounding`]) are one.
const SAME_LINE: f64 = 1e-7;

/// How close (in the frame) two points of tangency are one ([`SAME_LINE`]).
fn same_line_room(a: &Profile, b: &Profile, frame: &Frame) -> f64 {
    let room = a
        .same_point_room(SAME_LINE)
        .max(b.same_point_room(SAME_LINE));
    frame.length_to_local(room)
}

/// A corner in the frame, or a smooth joint whose tangents turn by rounding (its fan, searched
/// as a corner's cone is: see [`FAN_NOISE`]): where, and its incoming and outgoing unit
/// tangents.
struct ConeCorner {
    u: f64,
    segment: usize,
    at: V2,
    tangents: [V2; 2],
    /// A corner; else a smooth joint.
    corner: bool,
    /// How far (radians) a smooth joint's fan is widened: the turn the rounding of its
    /// tangents may hide.
    widening: f64,
}

impl ConeCorner {
    /// Whether the line along `d` (either way) lies inside the tangent cone: a corner's
    /// strictly, a smooth joint's fan widened by its rounding.
    fn holds(&self, d: V2) -> bool {
        let [tin, tout] = self.tangents;
        let turn = tin.cross(tout).atan2(tin.dot(tout));
        let edge = if self.corner {
            CONE_EDGE.asin()
        } else {
            -self.widening
        };
        let inside = |u: V2| {
            let u = u.unit();
            let a = tin.cross(u).atan2(tin.dot(u));
            // (Angles measured from the incoming tangent the way the corner turns.)
            let a = a * turn.signum();
            a > edge && a < turn.abs() - edge
        };
        inside(d) || inside(-d)
    }
}

/// One side: its segments in the frame and its corners.
struct Side<'p> {
    profile: &'p Profile,
    curves: Vec<SplineCurve>,
    corners: Vec<ConeCorner>,
}

impl<'p> Side<'p> {
    fn new(profile: &'p Profile, frame: &Frame) -> Self {
        let curves: Vec<SplineCurve> = profile
            .segments()
            .iter()
            .map(|s| s.curve().in_frame(frame))
            .collect();
        let n = curves.len();
        let corners = profile
            .joints()
            .iter()
            .filter(|j| j.kind != JointKind::Smooth || j.turn.abs() > FAN_NOISE)
            .filter_map(|j| {
                let i = j.u as usize;
                let segs = profile.segments();
                let (tin, tout) = (
                    segs[(i + n - 1) % n].end_direction()?,
                    segs[i].start_direction()?,
                );
                let c = &curves[i];
                Some(ConeCorner {
                    u: j.u,
                    segment: i,
                    at: c.jet(c.domain().0).p,
                    tangents: [tin, tout],
                    corner: j.kind != JointKind::Smooth,
                    widening: j.smooth_turn,
                })
            })
            .collect();
        Self {
            profile,
            curves,
            corners,
        }
    }
}

/// Every common tangent line of two profiles (open or closed), with its corners and
/// segments; certified where every decision is.
pub(crate) fn profile_tangents(a: &Profile, b: &Profile, opts: &Options) -> Result<Tangents> {
    opts.validate()?;
    use crate::whole_curve::{tangents, whole_curve};
    if let (Some(wa), Some(wb)) = (whole_curve(a), whole_curve(b)) {
        return tangents(&wa, &wb, opts);
    }
    let curved = |p: &Profile| {
        p.segments()
            .iter()
            .filter(|s| s.kind() != SegmentKind::Line)
            .count()
    };
    let pairs = curved(a).saturating_mul(curved(b));
    if pairs > MAX_SEGMENT_PAIRS {
        return Err(Error::TooManySegmentPairs {
            pairs,
            limit: MAX_SEGMENT_PAIRS,
        });
    }
    let points: Vec<[f64; 2]> = [a, b]
        .iter()
        .flat_map(|p| p.segments().iter().flat_map(|s| s.curve().control_points()))
        .collect();
    let frame = Frame::for_points(&points);
    let (sa, sb) = (Side::new(a, &frame), Side::new(b, &frame));
    let mut out = Tangents {
        lines: Vec::new(),
        doubts: Doubts::none(),
    };
    // (The smooth lines' doubts first, then the corners' in turn.)
    let mut doubts = Doubts::none();
    let room = same_line_room(a, b, &frame);
    smooth_lines(&sa, &sb, &frame, opts, &mut out, &mut doubts)?;
    for (from, to, flip) in [(&sa, &sb, false), (&sb, &sa, true)] {
        corner_lines(from, to, &frame, opts, room, flip, &mut out, &mut doubts)?;
    }
    for ca in &sa.corners {
        for cb in &sb.corners {
            let d = cb.at - ca.at;
            if d.norm() > room && ca.holds(d) && cb.holds(d) {
                push(
                    &mut out,
                    line(
                        &frame,
                        (ca.u, ca.at),
                        (cb.u, cb.at),
                        [ca.corner, cb.corner],
                        [ca.segment, cb.segment],
                    ),
                    room,
                    &frame,
                );
            }
        }
    }
    out.lines
        .sort_by(|x, y| x.s.total_cmp(&y.s).then(x.t.total_cmp(&y.t)));
    Ok(Provenance::finished(Certified { value: out, doubts }))
}

/// Lines tangent to both at smooth points: each pair of curved segments by Jia's method.
fn smooth_lines(
    sa: &Side,
    sb: &Side,
    frame: &Frame,
    opts: &Options,
    out: &mut Tangents,
    doubts: &mut Doubts,
) -> Result<()> {
    let room = same_line_room(sa.profile, sb.profile, frame);
    let curved = |s: &Side, i: usize| s.profile.segments()[i].kind() != SegmentKind::Line;
    for i in (0..sa.curves.len()).filter(|&i| curved(sa, i)) {
        for j in (0..sb.curves.len()).filter(|&j| curved(sb, j)) {
            let found = common_tangents_run(&sa.curves[i], &sb.curves[j], opts).map_err(|e| {
                Error::InSegment {
                    segment: i,
                    source: Box::new(e),
                }
            })?;
            let found = doubts.absorb(found);
            for l in found.lines {
                if at_corner(sa.profile, i, l.s) || at_corner(sb.profile, j, l.t) {
                    continue;
                }
                let (s, t) = (
                    sa.profile.profile_param(i, l.s),
                    sb.profile.profile_param(j, l.t),
                );
                let new = line(
                    frame,
                    (s, V2::from_arr(l.p)),
                    (t, V2::from_arr(l.q)),
                    [false, false],
                    [i, j],
                );
                push(out, new, room, frame);
            }
        }
    }
    Ok(())
}

/// Lines through a corner of `from` tangent to `to` at a smooth point (`flip`: `from` is the
/// second profile).
// (The corner, the profiles, the frame and what is found: each its own.)
#[allow(clippy::too_many_arguments)]
fn corner_lines(
    from: &Side,
    to: &Side,
    frame: &Frame,
    opts: &Options,
    room: f64,
    flip: bool,
    out: &mut Tangents,
    doubts: &mut Doubts,
) -> Result<()> {
    let ropts = RootOptions::default().tolerance(opts.settings.tol.get());
    for c in &from.corners {
        for (j, curve) in to.curves.iter().enumerate() {
            if to.profile.segments()[j].kind() == SegmentKind::Line {
                continue;
            }
            let f = bspline::symbolic::tangency_from(curve.curve(), c.at.arr()).map_err(|e| {
                Error::InSegment {
                    segment: j,
                    source: Box::new(e.into()),
                }
            })?;
            let (lo, hi) = curve.domain();
            let roots = find_roots(&f, lo, hi, &ropts).map_err(|e| Error::InSegment {
                segment: j,
                source: Box::new(e.into()),
            })?;
            for r in roots {
                if at_corner(to.profile, j, r.u) {
                    continue;
                }
                let q = curve.jet(r.u).p;
                let d = q - c.at;
                if d.norm() <= room || !c.holds(d) {
                    continue;
                }
                if !(r.kind == RootKind::Simple && r.certified) && opts.certify {
                    doubts.add(if c.corner {
                        Doubt::TangencyFromCorner { u: c.u, segment: j }
                    } else {
                        Doubt::TangencyFromJoint { u: c.u, segment: j }
                    });
                }
                let t = to.profile.profile_param(j, r.u);
                let new = if flip {
                    line(
                        frame,
                        (t, q),
                        (c.u, c.at),
                        [false, c.corner],
                        [j, c.segment],
                    )
                } else {
                    line(
                        frame,
                        (c.u, c.at),
                        (t, q),
                        [c.corner, false],
                        [c.segment, j],
                    )
                };
                push(out, new, room, frame);
            }
        }
    }
    Ok(())
}

/// The line through the first profile's point at `s` and the second's at `t` (frame points).
fn line(
    frame: &Frame,
    (s, p): (f64, V2),
    (t, q): (f64, V2),
    corner: [bool; 2],
    segment: [usize; 2],
) -> TangentLine {
    TangentLine {
        s,
        t,
        p: frame.to_global(p.arr()),
        q: frame.to_global(q.arr()),
        corner: Some(corner),
        segment: Some(segment),
    }
}

/// Adds `l` unless it is already there (found from both segments at a smooth joint): its
/// points within `room` (in the frame, [`same_line_room`]) of another's.
fn push(out: &mut Tangents, l: TangentLine, room: f64, frame: &Frame) {
    let room = frame.length_to_global(room);
    let near = |x: [f64; 2], y: [f64; 2]| (V2::from_arr(x) - V2::from_arr(y)).norm() <= room;
    if !out.lines.iter().any(|m| near(m.p, l.p) && near(m.q, l.q)) {
        out.lines.push(l);
    }
}
