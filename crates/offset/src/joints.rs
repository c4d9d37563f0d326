//! A loop's joints made exact: each piece ends where the next starts, to the rounding of the
//! coordinates. Two pieces meeting at a seam are built from their own feet, which Newton's
//! method agrees on only to a few units of rounding of the coordinates, and an arc's ends are
//! read from its angles; on a loop of a few millionths of the size (about to vanish) such a
//! gap is more than the reader allows a joint. An arc meeting an arc meets it where their
//! circles cross; an arc meeting a line or a fitted piece gives it its end; two such pieces
//! meet halfway.

use crate::OffsetSegment;

/// The largest gap (relative to the loop's scale, [`scale_of`]) closed: rounding, and
/// Newton's agreement at a seam, are far below it; a gap above it is not a joint's rounding,
/// and is left for the reader to refuse.
const ROUNDING_GAP: f64 = 1e-10;

/// The scale of a loop's rounding: its largest coordinate, or an arc's centre's distance from
/// the origin plus its radius (an arc's ends are rounded as that large, wherever they are: a
/// circle's ends near the origin are a few 1e-16 apart).
fn scale_of(pieces: &[OffsetSegment]) -> f64 {
    pieces
        .iter()
        .map(|s| {
            let (a, b) = (start_of(s), end_of(s));
            let ends = a[0].abs().max(a[1].abs()).max(b[0].abs()).max(b[1].abs());
            match s {
                OffsetSegment::Arc { center, r, .. } => ends.max(center[0].hypot(center[1]) + r),
                _ => ends,
            }
        })
        .fold(f64::MIN_POSITIVE, f64::max)
}

/// Closes the joints of a loop of `pieces` (the last joined to the first).
pub(crate) fn close(pieces: &mut [OffsetSegment]) {
    let n = pieces.len();
    let scale = scale_of(pieces);
    for k in 0..n {
        let next = (k + 1) % n;
        let (end, start) = (end_of(&pieces[k]), start_of(&pieces[next]));
        let gap = (end[0] - start[0]).hypot(end[1] - start[1]);
        if gap == 0.0 || gap > ROUNDING_GAP * scale {
            continue;
        }
        let halfway = [0.5 * (end[0] + start[0]), 0.5 * (end[1] + start[1])];
        let joint = match (&pieces[k], &pieces[next]) {
            (
                OffsetSegment::Arc { center, r, .. },
                OffsetSegment::Arc {
                    center: c2, r: r2, ..
                },
            ) => circles_meet(*center, *r, *c2, *r2, halfway).unwrap_or(end),
            (OffsetSegment::Arc { .. }, _) => end,
            (_, OffsetSegment::Arc { .. }) => start,
            _ => halfway,
        };
        set_end(&mut pieces[k], joint);
        set_start(&mut pieces[next], joint);
    }
}

/// What is left at a loop's joints after [`close`], from best to worst.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Closure {
    /// Every piece ends where the next starts, to rounding.
    Closed,
    /// A gap was bridged by a line.
    Bridged,
    /// A gap wider than the bridge's reach was left: the loop is not one.
    Open,
}

/// Bridges each gap [`close`] left (past rounding) by a line, where it is at most `reach`
/// wide; a wider one leaves the loop [`Closure::Open`]. Such a gap is where the loop's stretches
/// were joined at a seam the axis does not show (a convex corner without its edge, on an
/// uncertified axis), or where a seam's feet did not converge: a line keeps every point of the
/// loop within half its width of the distance, and the loop a closed profile; across a wider
/// gap, it would cut across the region.
pub(crate) fn bridge(pieces: &mut Vec<OffsetSegment>, reach: f64) -> Closure {
    let mut closure = Closure::Closed;
    let scale = scale_of(pieces);
    let mut k = 0;
    // (Each joint once; a bridge added is passed over.)
    while k < pieces.len() {
        let next = (k + 1) % pieces.len();
        let (end, start) = (end_of(&pieces[k]), start_of(&pieces[next]));
        let wide = gap(end, start);
        if wide <= ROUNDING_GAP * scale {
            k += 1;
            continue;
        }
        if wide > reach || wide.is_nan() {
            return Closure::Open;
        }
        pieces.insert(
            k + 1,
            OffsetSegment::Line {
                from: end,
                to: start,
            },
        );
        closure = Closure::Bridged;
        k += 2;
    }
    closure
}

/// Where the circles `(a, ra)` and `(b, rb)` cross nearest to `near`, when that is within
/// rounding of it (circles nearly tangent cross far from any point near both; their arcs
/// then keep their own ends).
fn circles_meet(a: [f64; 2], ra: f64, b: [f64; 2], rb: f64, near: [f64; 2]) -> Option<[f64; 2]> {
    // (From the smaller circle's centre: across the line of centres is then a difference of
    // its own radius's square and a smaller one, not of a large circle's two nearly equal
    // squares.)
    let (a, ra, b, rb) = if ra <= rb {
        (a, ra, b, rb)
    } else {
        (b, rb, a, ra)
    };
    let axis = [b[0] - a[0], b[1] - a[1]];
    let apart = axis[0].hypot(axis[1]);
    if apart == 0.0 {
        return None;
    }
    let unit = [axis[0] / apart, axis[1] / apart];
    // (Along the line of centres from `a`, then across it either way.)
    let along = (apart * apart + ra * ra - rb * rb) / (2.0 * apart);
    let across = (ra * ra - along * along).max(0.0).sqrt();
    let base = [a[0] + along * unit[0], a[1] + along * unit[1]];
    let best = [1.0, -1.0]
        .map(|side| {
            [
                base[0] - side * across * unit[1],
                base[1] + side * across * unit[0],
            ]
        })
        .into_iter()
        .min_by(|p, q| gap(*p, near).total_cmp(&gap(*q, near)))?;
    let scale = near[0].abs().max(near[1].abs()).max(ra).max(rb);
    (gap(best, near) <= ROUNDING_GAP * scale).then_some(best)
}

fn gap(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// The point of the circle about `center` of radius `r` at `angle`.
fn on_circle(center: [f64; 2], r: f64, angle: f64) -> [f64; 2] {
    [center[0] + r * angle.cos(), center[1] + r * angle.sin()]
}

fn start_of(s: &OffsetSegment) -> [f64; 2] {
    match s {
        OffsetSegment::Line { from, .. } => *from,
        OffsetSegment::Arc {
            center, r, start, ..
        } => on_circle(*center, *r, *start),
        OffsetSegment::BSpline { points, .. } => points[0],
    }
}

fn end_of(s: &OffsetSegment) -> [f64; 2] {
    match s {
        OffsetSegment::Line { to, .. } => *to,
        OffsetSegment::Arc { center, r, end, .. } => on_circle(*center, *r, *end),
        OffsetSegment::BSpline { points, .. } => points[points.len() - 1],
    }
}

/// The angle of `p` about `center`, the nearest to `angle` (an arc's sweep moves by as
/// little as its end).
fn angle_near(center: [f64; 2], p: [f64; 2], angle: f64) -> f64 {
    let seen = (p[1] - center[1]).atan2(p[0] - center[0]);
    angle + curve::wrap_pi(seen - angle)
}

fn set_start(s: &mut OffsetSegment, p: [f64; 2]) {
    match s {
        OffsetSegment::Line { from, .. } => *from = p,
        OffsetSegment::Arc { center, start, .. } => *start = angle_near(*center, p, *start),
        OffsetSegment::BSpline { points, .. } => points[0] = p,
    }
}

fn set_end(s: &mut OffsetSegment, p: [f64; 2]) {
    match s {
        OffsetSegment::Line { to, .. } => *to = p,
        OffsetSegment::Arc { center, end, .. } => *end = angle_near(*center, p, *end),
        OffsetSegment::BSpline { points, .. } => {
            let last = points.len() - 1;
            points[last] = p;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use numeric::rounding::ulps;
    use proptest::prelude::*;

    proptest! {
        /// Two arcs ending near where their circles cross (each end moved by up to 1e-13 of
        /// the size, as a seam's two feet leave it), and a line after them: after closing,
        /// every joint is within the reader's rounding allowance (16 units of rounding of the
        /// largest coordinate: each arc's end is read from its angle, a few units off), and no
        /// end has moved by more than the gap it closed.
        #[test]
        fn joints_close_to_rounding(
            ca in prop::array::uniform2(-10.0f64..10.0),
            ra in 0.1f64..5.0,
            turn in 0.3f64..2.8,
            rb in 0.1f64..5.0,
            wobble in prop::array::uniform4(-1.0f64..1.0),
            scale in prop_oneof![Just(1.0), Just(1e-6), Just(1e6)],
        ) {
            // The crossing: a point of circle a; circle b's centre rb from it.
            let (ca, ra, rb) = ([ca[0] * scale, ca[1] * scale], ra * scale, rb * scale);
            let at = on_circle(ca, ra, 0.7);
            let cb = [at[0] + rb * (0.7 + turn).cos(), at[1] + rb * (0.7 + turn).sin()];
            let nudge = 1e-13 * ca[0].abs().max(ca[1].abs()).max(ra + rb);
            let angle = |c: [f64; 2], w: [f64; 2]| {
                let p = [at[0] + w[0] * nudge - c[0], at[1] + w[1] * nudge - c[1]];
                p[1].atan2(p[0])
            };
            let a_end = angle(ca, [wobble[0], wobble[1]]);
            let b_start = angle(cb, [wobble[2], wobble[3]]);
            let line_start = on_circle(cb, rb, b_start + 0.5);
            let mut loop_ = vec![
                OffsetSegment::Arc { center: ca, r: ra, start: a_end - 1.0, end: a_end },
                OffsetSegment::Arc { center: cb, r: rb, start: b_start, end: b_start + 0.5 },
                OffsetSegment::Line { from: line_start, to: on_circle(ca, ra, a_end - 1.0) },
            ];
            let before: Vec<[f64; 2]> = loop_.iter().map(end_of).collect();
            close(&mut loop_);
            let size = ca[0].abs().max(ca[1].abs()).max(cb[0].abs()).max(cb[1].abs()).max(ra + rb);
            for k in 0..3 {
                let (end, start) = (end_of(&loop_[k]), start_of(&loop_[(k + 1) % 3]));
                prop_assert!(gap(end, start) <= ulps(16.0) * size, "joint {k}: {}", gap(end, start));
                prop_assert!(gap(end, before[k]) <= 4.0 * nudge, "joint {k} moved {}", gap(end, before[k]));
            }
        }
    }

    /// A gap past rounding is a real one: left as it is, for the reader to refuse.
    #[test]
    fn a_real_gap_is_left_open() {
        let mut loop_ = vec![
            OffsetSegment::Line {
                from: [0.0, 0.0],
                to: [1.0, 0.0],
            },
            OffsetSegment::Line {
                from: [1.0, 1e-6],
                to: [0.0, 0.0],
            },
        ];
        let before = loop_.clone();
        close(&mut loop_);
        assert_eq!(loop_, before);
    }
}
