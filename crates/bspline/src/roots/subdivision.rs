//! A stretch of a scalar function under subdivision ([`Part`]), as the spans of the pieces it
//! covers, and where to split it.

use super::{value, SignCount};
use crate::piecewise::Piecewise;

/// A point of `(lo, hi)` near its middle where `f` has a trusted sign, if there is one, else
/// the middle: the interior break nearest the middle (whole pieces on both
/// sides), then points in the middle quarter.
pub(super) fn split_point(f: &Piecewise, lo: f64, hi: f64) -> f64 {
    let mid = 0.5 * (lo + hi);
    let breaks = f.breaks();
    let (first, last) = (
        breaks.partition_point(|&x| x <= lo),
        breaks.partition_point(|&x| x < hi),
    );
    let mut inner: smallvec::SmallVec<[f64; 8]> = smallvec::SmallVec::new();
    if first < last {
        // The few interior breaks nearest the middle.
        let k = breaks[first..last].partition_point(|&x| x < mid) + first;
        for j in [k, k.wrapping_sub(1), k + 1, k.wrapping_sub(2)] {
            if j >= first && j < last {
                inner.push(breaks[j]);
            }
        }
        inner.sort_by(|x, y| (x - mid).abs().total_cmp(&(y - mid).abs()));
    }
    let fractions = [0.5, 0.4375, 0.5625, 0.375, 0.625, 0.3125, 0.6875];
    inner
        .into_iter()
        .chain(fractions.iter().map(|t| lo + (hi - lo) * t))
        .filter(|&u| u > lo && u < hi)
        .find(|&u| {
            let (v, e) = value(f, u);
            v.abs() > 2.0 * e
        })
        .unwrap_or(mid)
}

/// One piece of a [`Part`]: Bernstein coefficients on `[x0, x1]` within `err` of the exact
/// ones, and the order of continuity at `x0` (from the previous span).
#[derive(Clone)]
pub(super) struct Span {
    x0: f64,
    x1: f64,
    pub(super) coefs: smallvec::SmallVec<[f64; 16]>,
    pub(super) err: f64,
    joint: i32,
}

/// A stretch of a scalar function under subdivision, as the spans of the pieces it covers.
/// Spans are cut by de Casteljau's algorithm from their own coefficients, so the rounding of a
/// cut is relative to the stretch's own magnitudes (small close to a root), not the piece's.
pub(super) struct Part {
    pub(super) spans: Vec<Span>,
}

impl Part {
    /// `f` on `[lo, hi]`.
    pub(super) fn of(f: &Piecewise, lo: f64, hi: f64) -> Self {
        let mut spans = Vec::new();
        f.for_each_restricted(&[1.0], lo, hi, |i, x0, x1, c, err| {
            spans.push(Span {
                x0,
                x1,
                coefs: c.iter().copied().collect(),
                err,
                joint: f.continuity(i),
            });
            true
        });
        Self { spans }
    }

    pub(super) fn interval(&self) -> (f64, f64) {
        (self.spans[0].x0, self.spans[self.spans.len() - 1].x1)
    }

    /// The count over the part, and whether every coefficient is within its bound of zero.
    pub(super) fn count(&self) -> (SignCount, bool) {
        let (lo, hi) = self.interval();
        let mut count = SignCount::new(lo, hi);
        let mut flat = true;
        for s in &self.spans {
            flat &= s.coefs.iter().all(|x| x.abs() <= s.err);
            count.piece(s.x0, s.x1, &s.coefs, s.err, s.joint);
        }
        (count, flat)
    }

    /// For a part of one span of degree one (a straight line), the interval where it is
    /// within its error bound of zero, which holds every root of the exact function; `None`
    /// for any other part, or where the line keeps clear of zero.
    pub(super) fn straight_zeros(&self) -> Option<(f64, f64)> {
        let [span] = self.spans.as_slice() else {
            return None;
        };
        let [c0, c1] = span.coefs[..] else {
            return None;
        };
        let (e, slope) = (span.err, c1 - c0);
        // (On the unit interval of the span: |c0 + slope r| ≤ e.)
        let (r0, r1) = if slope == 0.0 {
            if c0.abs() > e {
                return None;
            }
            (0.0, 1.0)
        } else {
            let (a, b) = ((-e - c0) / slope, (e - c0) / slope);
            (a.min(b).max(0.0), a.max(b).min(1.0))
        };
        // (None where rounding left the interval empty or not a number.)
        let width = span.x1 - span.x0;
        (r0 <= r1).then(|| (span.x0 + width * r0, (span.x0 + width * r1).min(span.x1)))
    }

    /// The two parts on either side of `m` (inside the part).
    pub(super) fn split(self, f: &Piecewise, m: f64) -> (Part, Part) {
        let p = f.degree();
        let mut left = Vec::new();
        let mut right = Vec::new();
        for s in self.spans {
            if s.x1 <= m {
                left.push(s);
            } else if s.x0 >= m {
                right.push(s);
            } else {
                let magnitude = s.coefs.iter().fold(0.0f64, |a, x| a.max(x.abs())) + s.err;
                let err = s.err + crate::rounding::casteljau(p, magnitude);
                let r = (m - s.x0) / (s.x1 - s.x0);
                let mut l = s.coefs.clone();
                let mut rt = s.coefs;
                crate::piecewise::split_left(&mut l, r);
                crate::piecewise::split_right(&mut rt, r);
                left.push(Span {
                    x0: s.x0,
                    x1: m,
                    coefs: l,
                    err,
                    joint: s.joint,
                });
                right.push(Span {
                    x0: m,
                    x1: s.x1,
                    coefs: rt,
                    err,
                    joint: i32::MAX,
                });
            }
        }
        (Part { spans: left }, Part { spans: right })
    }
}
