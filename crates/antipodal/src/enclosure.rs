//! Enclosures of a function given by its symbolic form in pieces: certified ranges over any
//! interval, from the control points of its fine pieces and Taylor models on them.

use crate::taylor::Taylor;
use bspline::rounding;
use bspline::{Piecewise, ValueSlope};
use curve::{wrap_pi, V2};
use numeric::Interval;
use std::f64::consts::PI;

/// Fine pieces per Bézier piece of an [`Enclosure`]: derivative bounds taken over an eighth of
/// a piece are local enough to prove monotone stretches close to a pair.
const FINE: usize = 8;

/// The range of a scalar function, or of the length of a vector one, over an interval: in
/// `O(1)` for each fine piece the interval covers (the hull of the piece's control points)
/// and `O(degree)` for each it overlaps in part, by Taylor's theorem about the middle `m` of
/// the overlap (half-width `δ`): `|f(x) − f(m)| ≤ |f′(m)| δ + M₂ δ²/2` with `M₂` the piece's
/// bound on `|f″|`, widened by the rounding of the two evaluations. Its width exceeds the
/// function's own variation by a second-order term only, so short intervals close to a pair
/// get nearly exact ranges.
#[derive(Debug, Clone)]
pub(crate) struct Enclosure {
    /// The function in its fine pieces.
    pub(crate) pw: Piecewise,
    eval: ValueSlope,
    /// Per fine piece, a bound on `|f″|`.
    second: Vec<f64>,
    /// Per fine piece, the range its control points prove.
    pub(crate) hull: Vec<Interval>,
    /// Per fine piece, the rounding of an evaluation of `f` and of `f′` there.
    rounding: Vec<(f64, f64)>,
    /// Per fine piece of a vector function, the least arc of directions holding its control
    /// points, as the unit vectors of its ends `(start, end)`, counterclockwise and shorter
    /// than π (`None` when there is none, or a point is zero).
    cones: Vec<Option<(V2, V2)>>,
}

impl Enclosure {
    /// `None` for a function of dimension other than 1 and 2.
    pub(crate) fn new(f: &Piecewise) -> Option<Self> {
        let pw = f.subdivided(FINE);
        let deriv = pw.derivative();
        let d = pw.dim();
        let hull = (0..pw.pieces())
            .map(|i| points_range(pw.piece(i), d, pw.errors(i)))
            .collect();
        // Horner's scheme errs by a few units of rounding per degree of the largest control
        // point, beside the pieces' own error (the derivative's carries its differences).
        let rounding = (0..pw.pieces())
            .map(|i| {
                let (m, dm) = (
                    pw.piece_magnitude(i) + pw.error(i),
                    deriv.piece_magnitude(i) + deriv.error(i),
                );
                (
                    pw.error(i) + rounding::horner(pw.degree(), m),
                    deriv.error(i) + rounding::horner(deriv.degree(), dm),
                )
            })
            .collect();
        let cones = match d {
            2 => (0..pw.pieces())
                .map(|i| cone_ends(pw.piece(i), pw.errors(i)))
                .collect(),
            _ => Vec::new(),
        };
        Some(Self {
            second: deriv.derivative().norm_bounds(),
            hull,
            rounding,
            cones,
            eval: ValueSlope::new(&pw, &deriv)?,
            pw,
        })
    }

    /// The fine pieces' breakpoints.
    pub(crate) fn breaks(&self) -> &[f64] {
        self.pw.breaks()
    }

    /// `[lo, hi]` lies in one fine piece whose control points (of a vector function) lie in an
    /// open half-plane, with room for their rounding: the function's direction turns by less
    /// than π there.
    pub(crate) fn in_half_plane(&self, lo: f64, hi: f64) -> bool {
        let i = self.pw.piece_at(lo);
        let (a, b) = self.pw.piece_span(i);
        let h = self.hull[i];
        lo >= a && hi <= b && h.lo > HALF_PLANE_MARGIN * h.hi
    }

    /// The control points of every fine piece overlapping `[lo, hi]` (of a vector function)
    /// lie in the open half-plane `x · axis > 0`, with room for their rounding: the function's
    /// direction turns by less than π over `[lo, hi]` (whole pieces' points: a superset of the
    /// stretch's own, so no subdivision).
    pub(crate) fn in_half_plane_of(&self, lo: f64, hi: f64, axis: V2) -> bool {
        let (first, last) = (self.pw.piece_at(lo), self.pw.piece_at(hi));
        self.pw.dim() == 2
            && self.cones[first..=last]
                .iter()
                .all(|&c| cone_inside(c, axis))
    }

    /// A first-order Taylor model of the function (of its length, in dimension 2) about the
    /// middle of `[x0, x1]`, which lies in fine piece `i`, and the range the piece's hull
    /// proves. `None` where the length may vanish there.
    ///
    /// The remainder is `M₂δ²/2` plus rounding for a scalar; for the length `|f|`,
    /// `|f|″ = (|f′|² + f·f″)/|f| − (f·f′)²/|f|³` is at most `|f′|²/|f| + |f″|`, with `|f′|` and
    /// `|f|` bounded over the interval from the model of `f` itself.
    pub(crate) fn taylor(&self, i: usize, x0: f64, x1: f64) -> Option<(Taylor, Interval)> {
        self.taylor_slope(i, x0, x1).map(|(t, hull, _)| (t, hull))
    }

    /// [`Enclosure::taylor`] and the range of the derivative (of the length's, in dimension
    /// 2) over `[x0, x1]`: within `M δ` of its value at the middle, `M` the bound on the
    /// second derivative behind the model's remainder, widened by rounding.
    pub(crate) fn taylor_slope(
        &self,
        i: usize,
        x0: f64,
        x1: f64,
    ) -> Option<(Taylor, Interval, Interval)> {
        let (a, b) = self.pw.piece_span(i);
        let (m, delta) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
        let (v, g) = self.eval.eval(i, (m - a) / (b - a));
        let (rv, rg) = self.rounding[i];
        let (m2, hull) = (self.second[i], self.hull[i]);
        if self.pw.dim() == 1 {
            let r = 0.5 * m2 * delta * delta + rv + rg * delta;
            let spread = m2 * delta + rg;
            return Some((
                Taylor {
                    v: v[0],
                    g: g[0],
                    r,
                },
                hull,
                Interval::new(g[0] - spread, g[0] + spread),
            ));
        }
        let n = v[0].hypot(v[1]);
        let gn = g[0].hypot(g[1]);
        // Each component errs by `rv` (`rg` for the slope): the length by at most twice that.
        let err = 2.0 * (rv + rg * delta);
        let lower = (n - gn * delta - 0.5 * m2 * delta * delta - err).max(hull.lo);
        // (NaN fails too.)
        if lower.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let slope = gn + rg + m2 * delta;
        let second = slope * slope / lower + m2;
        let model = Taylor {
            v: n,
            g: (v[0] * g[0] + v[1] * g[1]) / n,
            r: 0.5 * second * delta * delta + err,
        };
        // (|f|′ = f·f′/|f| at the middle errs by the slope's rounding and the value's over |f|.)
        let spread = second * delta + 2.0 * (rg + rv * gn / lower);
        Some((
            model,
            hull,
            Interval::new(model.g - spread, model.g + spread),
        ))
    }

    /// The range over `[lo, hi]` (inside the domain), joined into `acc`.
    pub(crate) fn join_range(&self, lo: f64, hi: f64, acc: &mut Interval) {
        let d = self.pw.dim();
        let norm = |v: [f64; 2]| {
            if d == 1 {
                v[0]
            } else {
                (v[0] * v[0] + v[1] * v[1]).sqrt()
            }
        };
        // Over a long interval a covered piece's hull is close enough; over a short one
        // (within two fine pieces, as close to a pair) every piece gets the Taylor bound too.
        let long = self.pw.overlaps(lo, hi).nth(2).is_some();
        for (i, x0, x1) in self.pw.overlaps(lo, hi) {
            let (a, b) = self.pw.piece_span(i);
            let hull = self.hull[i];
            let range = if long && x0 <= a && x1 >= b {
                hull
            } else {
                let (m, delta) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
                let (v, g) = self.eval.eval(i, (m - a) / (b - a));
                let (rv, rg) = self.rounding[i];
                let r = (norm(g).abs() + rg) * delta + 0.5 * self.second[i] * delta * delta + rv;
                let x = norm(v);
                // Both enclose the range: keep their common part.
                Interval::new((x - r).max(hull.lo), (x + r).min(hull.hi))
            };
            *acc = acc.hull(range);
        }
    }
}

/// The least arc of directions holding the 2-d points `c` (point-major), each within `err` of
/// its exact value coordinate by coordinate (so within `|err|` of it: its direction within
/// `asin(|err| / |c|)`), counterclockwise from its start, when it is shorter than π: angles
/// relative to the first point are then unwrapped correctly (and when they span less than π,
/// so do the points). `None` for a point within its error of zero.
fn cone(c: &[f64], err: &[f64]) -> Option<(f64, f64)> {
    let first = V2::new(c[0], c[1]).angle();
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    let reach = err[0].hypot(err[1]);
    for p in c.chunks_exact(2) {
        let v = V2::new(p[0], p[1]);
        let n = v.norm();
        if n <= reach {
            return None;
        }
        let slack = (reach / n).asin();
        let rel = wrap_pi(v.angle() - first);
        lo = lo.min(rel - slack);
        hi = hi.max(rel + slack);
    }
    (hi - lo < PI).then_some((first + lo, first + hi))
}

/// [`cone`]'s two boundary directions, as unit vectors (start, end).
fn cone_ends(c: &[f64], err: &[f64]) -> Option<(V2, V2)> {
    cone(c, err).map(|(a, b)| (V2::polar(a), V2::polar(b)))
}

/// A cone of directions (its unit boundary directions, see [`cone_ends`]) lies in the open
/// half-plane `x · axis > 0`, by the margin `x · axis > HALF_PLANE_MARGIN |x| |axis|`
/// (angles within `π/2 − 1e-9` of the axis): both ends inside. (The cone is narrower than π, so its arc
/// cannot go round the other half-plane, which is as wide as π. Two dot products, where
/// comparing angles took three arctangents per fine piece.)
fn cone_inside(cone: Option<(V2, V2)>, axis: V2) -> bool {
    let room = HALF_PLANE_MARGIN * axis.norm();
    cone.is_some_and(|(a, b)| a.dot(axis) > room && b.dot(axis) > room)
}

/// The range control points (dimension `d`, point-major, each coordinate within its `err` of
/// the exact one) prove for a scalar function, or for the length of a vector one: from below
/// by the projections on the direction of the end points' sum (a narrow hodograph cone), from
/// above by the largest.
fn points_range(c: &[f64], d: usize, err: &[f64]) -> Interval {
    if d == 1 {
        return Interval::new(
            c.iter().copied().fold(f64::INFINITY, f64::min) - err[0],
            c.iter().copied().fold(f64::NEG_INFINITY, f64::max) + err[0],
        );
    }
    let reach = err[0].hypot(err[1]);
    let pts = || c.chunks_exact(d).map(|p| V2::new(p[0], p[1]));
    let (first, last) = (&c[..2], &c[c.len() - d..c.len() - d + 2]);
    let axis = V2::new(first[0] + last[0], first[1] + last[1]).unit();
    Interval::new(
        (pts().map(|p| p.dot(axis)).fold(f64::INFINITY, f64::min) - reach).max(0.0),
        pts().map(|p| p.norm()).fold(0.0, f64::max) + reach,
    )
}

/// The margin by which points must lie inside a half-plane (relative to their length): far
/// above the rounding of the projections, far below any turn a proof needs.
pub(crate) const HALF_PLANE_MARGIN: f64 = 1e-9;

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The cone test of a set of directions agrees with testing every direction against
        /// the half-plane (away from the margin's rounding).
        #[test]
        fn cone_test_matches_pointwise(
            pts in proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 1..12),
            spread in 0.0f64..4.0,
            ax in -4.0f64..4.0,
        ) {
            // Directions within `spread` radians of a random one, scaled randomly.
            let c: Vec<f64> = pts
                .iter()
                .flat_map(|&(a, r)| {
                    let v = V2::polar(ax + 1.3 + spread * a) * (0.1 + r.abs());
                    [v.x, v.y]
                })
                .collect();
            let axis = V2::polar(ax);
            let pointwise = c.chunks_exact(2).all(|p| {
                let v = V2::new(p[0], p[1]);
                v.dot(axis) > 1e-9 * v.norm()
            });
            let near_margin = c.chunks_exact(2).any(|p| {
                let v = V2::new(p[0], p[1]);
                (v.dot(axis) / v.norm()).abs() < 1e-6
            });
            if !near_margin {
                prop_assert_eq!(cone_inside(cone_ends(&c, &[0.0, 0.0]), axis), pointwise);
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

            /// Sampled values of random splines lie in the enclosure of any interval.
            #[test]
            fn enclosure_holds_sampled_values(
                deg in 2usize..=7,
                coefs in proptest::collection::vec(-3.0f64..3.0, 24),
                dim in 1usize..=2,
                a in 0.0f64..1.0,
                len in prop_oneof![1e-6f64..1e-3, 1e-3f64..0.1, 0.1f64..1.0],
    ) {
                let n = coefs.len() / dim;
                let f = bspline::BSpline::clamped_uniform(deg, dim, coefs[..n * dim].to_vec()).unwrap();
                let e = Enclosure::new(&bspline::Piecewise::from_bspline(&f)).unwrap();
                let (lo, hi) = (a.min(1.0 - len.min(1.0)), (a.min(1.0 - len.min(1.0)) + len).min(1.0));
                let mut iv = Interval::new(f64::INFINITY, f64::NEG_INFINITY);
                e.join_range(lo, hi, &mut iv);
                for i in 0..=200 {
                    let u = lo + (hi - lo) * i as f64 / 200.0;
                    let v = f.eval(u);
                    let x = if dim == 1 { v[0] } else { v[0].hypot(v[1]) };
                    prop_assert!(iv.holds(x, 1e-9), "{x} outside {iv:?} at {u} on [{lo}, {hi}]");
                }
            }
    }
}
