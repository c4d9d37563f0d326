//! Horn cusps of a loop. Where a passage is exactly twice the distance wide, it is taken as
//! closed (see [`crate::necks::TOUCHING`]), and the loop on either side of it turns back at
//! the touching point, between two pieces tangent there: a horn whose tip is narrower than
//! any width. A profile cannot turn back (which side its turn is on is undecided), so the
//! tip is cut by a chord across the horn where it is `width` wide.

use crate::OffsetSegment;
use bspline::BSpline;
use curve::V2;
use numeric::rounding::ulps;

/// A joint whose direction turns by more than π less this (radians) turns back. The profile
/// reader refuses turns within 1e-9 of π; a margin above it catches every one it would.
const TURNS_BACK: f64 = 1e-7;

/// Where a horn is cut, relative to the region's size: ten times the width of the passages
/// taken as closed, far below the chord tolerance.
pub(crate) const HORN_CUT: f64 = 10.0 * crate::necks::TOUCHING;

/// Doublings of the cut's distance from the tip before a horn is left as it is.
const MOST_DOUBLINGS: usize = 80;

/// Halvings of the cut's distance from the tip between the last two doublings: to 2^-40 of
/// it, a few roundings.
const CUT_HALVINGS: usize = 40;

/// Cuts the tip of every horn of the closed loop `segments` by a chord where it is `width`
/// wide (taken back from the tip by one length along both pieces, at most half of either).
pub(crate) fn blunt(segments: &mut Vec<OffsetSegment>, width: f64) {
    let mut k = 0;
    // (Each joint is looked at once; a chord added is passed over.)
    while k < segments.len() && segments.len() > 1 {
        let next = (k + 1) % segments.len();
        let (din, dout) = (
            direction(&segments[k], true),
            direction(&segments[next], false),
        );
        let turn = din.cross(dout).atan2(din.dot(dout));
        if turn.abs() < std::f64::consts::PI - TURNS_BACK {
            k += 1;
            continue;
        }
        // (The same length back from the tip along both pieces, so that the chord runs
        // across the horn: at the same share of two pieces of unequal lengths it would run
        // along the horn, back over the longer one's end, and turn back itself.)
        // Doubled until the horn is that wide there, then bisected to where it is: the cut
        // is where the geometry puts it, not where the pieces' lengths do (a loop offset
        // again, whose pieces are split otherwise, is cut at the same place).
        let lengths = [length(&segments[k]), length(&segments[next])];
        let shortest = lengths[0].min(lengths[1]);
        let shares = |back: f64| [back / lengths[0], back / lengths[1]];
        let wide = |back: f64| {
            let [a, b] = shares(back);
            (point_at(&segments[k], 1.0 - a) - point_at(&segments[next], b)).norm() >= width
        };
        let mut back = ulps(1.0).sqrt() * shortest;
        let mut cut = None;
        for _ in 0..MOST_DOUBLINGS {
            // (Also where a length is not a number.)
            if back.partial_cmp(&(0.5 * shortest)) != Some(std::cmp::Ordering::Less) {
                break;
            }
            if wide(back) {
                cut = Some(back);
                break;
            }
            back *= 2.0;
        }
        let Some(mut wide_at) = cut else {
            k += 1;
            continue;
        };
        let mut narrow_at = 0.5 * wide_at;
        for _ in 0..CUT_HALVINGS {
            let middle = 0.5 * (narrow_at + wide_at);
            if wide(middle) {
                wide_at = middle;
            } else {
                narrow_at = middle;
            }
        }
        let [share_in, share_out] = shares(wide_at);
        let before = trimmed(&segments[k], 0.0, 1.0 - share_in);
        let after = trimmed(&segments[next], share_out, 1.0);
        let (Some(before), Some(after)) = (before, after) else {
            k += 1;
            continue;
        };
        let chord = OffsetSegment::Line {
            from: point_at(&before, 1.0).arr(),
            to: point_at(&after, 0.0).arr(),
        };
        segments[k] = before;
        segments[next] = after;
        segments.insert(k + 1, chord);
        k += 2;
    }
}

/// Points a fitted piece's length is summed over (by chords: a horn's cut needs lengths
/// only to a few percent).
const LENGTH_CHORDS: usize = 32;

/// The length of a piece (a fitted one's by chords).
fn length(s: &OffsetSegment) -> f64 {
    match s {
        OffsetSegment::Line { from, to } => (V2::from_arr(*to) - V2::from_arr(*from)).norm(),
        OffsetSegment::Arc { r, start, end, .. } => r * (end - start).abs(),
        OffsetSegment::BSpline { .. } => (0..LENGTH_CHORDS)
            .map(|j| {
                let t = |j: usize| j as f64 / LENGTH_CHORDS as f64;
                (point_at(s, t(j + 1)) - point_at(s, t(j))).norm()
            })
            .sum(),
    }
}

/// The point of a piece at `t ∈ [0, 1]` along it (by its own parameter).
fn point_at(s: &OffsetSegment, t: f64) -> V2 {
    match s {
        OffsetSegment::Line { from, to } => {
            V2::from_arr(*from) + (V2::from_arr(*to) - V2::from_arr(*from)) * t
        }
        OffsetSegment::Arc {
            center,
            r,
            start,
            end,
        } => {
            let a = start + (end - start) * t;
            V2::new(center[0] + r * a.cos(), center[1] + r * a.sin())
        }
        OffsetSegment::BSpline {
            degree,
            knots,
            points,
        } => spline(*degree, knots, points).map_or(V2::new(f64::NAN, f64::NAN), |b| {
            let p = b.eval(t);
            V2::new(p[0], p[1])
        }),
    }
}

/// The direction a piece starts in (`at_end` false) or ends in, exactly: a clamped B-spline
/// is tangent to its control polygon at its ends.
fn direction(s: &OffsetSegment, at_end: bool) -> V2 {
    match s {
        OffsetSegment::Line { from, to } => V2::from_arr(*to) - V2::from_arr(*from),
        OffsetSegment::Arc { start, end, .. } => {
            let a = if at_end { *end } else { *start };
            V2::new(-a.sin(), a.cos()) * (end - start).signum()
        }
        OffsetSegment::BSpline { points, .. } => {
            let n = points.len();
            let (p, q) = if at_end {
                (points[n.saturating_sub(2)], points[n - 1])
            } else {
                (points[0], points[1.min(n - 1)])
            };
            V2::from_arr(q) - V2::from_arr(p)
        }
    }
}

/// The piece between `a` and `b` of its own parameter, as a piece of the same kind; `None`
/// where a B-spline cannot be cut.
fn trimmed(s: &OffsetSegment, a: f64, b: f64) -> Option<OffsetSegment> {
    Some(match s {
        OffsetSegment::Line { .. } => OffsetSegment::Line {
            from: point_at(s, a).arr(),
            to: point_at(s, b).arr(),
        },
        OffsetSegment::Arc {
            center,
            r,
            start,
            end,
        } => OffsetSegment::Arc {
            center: *center,
            r: *r,
            start: start + (end - start) * a,
            end: start + (end - start) * b,
        },
        OffsetSegment::BSpline {
            degree,
            knots,
            points,
        } => {
            let cut = spline(*degree, knots, points)?.restrict(a, b).ok()?;
            let (lo, hi) = (a, b);
            OffsetSegment::BSpline {
                degree: *degree,
                knots: cut.knots().iter().map(|k| (k - lo) / (hi - lo)).collect(),
                points: cut.coefs().chunks(2).map(|c| [c[0], c[1]]).collect(),
            }
        }
    })
}

/// A piece's B-spline.
fn spline(degree: usize, knots: &[f64], points: &[[f64; 2]]) -> Option<BSpline> {
    let coefs = points.iter().flat_map(|p| p.iter().copied()).collect();
    BSpline::new(degree, knots.to_vec(), 2, coefs).ok()
}
