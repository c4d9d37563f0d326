//! Where a boundary segment can hold the nearest boundary point of some point of a cell: its
//! normal fan. The nearest point of a boundary to `x` is where `(x − C)·C'` vanishes (on a
//! segment, or at a smooth joint, where the tangent's direction is the same on both sides), or
//! a corner `x` lies ahead of along the segment before it and behind along the one after. A
//! segment whose `(x − C)·C'` keeps one sign over the whole cell, and whose corner ends the
//! cell does not lie beyond, holds no nearest point of it.
//!
//! The pair tree ([`crate::pairs`]) needs this where distances alone cannot part the segments:
//! beside a smooth boundary the distance to it is flat about the nearest point (it grows with
//! the square of the offset along the boundary), so a cell keeps every short segment within
//! the square root of its size of the foot, and halving never brings them down to a pair.
//!
//! With `C = P / W` (homogeneous control points `(P, W)`, weights positive), `(x − C)·C'` has
//! the sign of `G(u) = (x W − P)·(P'W − PW') = x·A(u) − B(u)`, a polynomial of degree
//! `3p − 1` whose Bernstein coefficients `(A_k, B_k)` are affine in `x`: over a box each
//! ranges over an interval, and where all are of one sign, so is `G`.

use bspline::Piecewise;
use curve::Profile;

/// Half-width of the band about zero in which a coefficient's sign is not trusted, relative to
/// its magnitude `|A_k| |x| + |B_k|`, in units of the largest turn a joint of the boundary may
/// have and count as smooth ([`Profile::smooth_turn`]): there `(x − C)·C'` is zero on one side
/// of the joint and up to that turn (relative) on the other; the rounding of the coefficients
/// is far below.
const UNTRUSTED_TURNS: f64 = 4.0;

/// The normal fan of one segment: the coefficients of `G` per Bézier piece, in coordinates
/// relative to `origin`, and at each end that is a corner the neighbour's `G` there.
pub(crate) struct Fan {
    origin: [f64; 2],
    /// The half-width of the untrusted band (see [`UNTRUSTED_TURNS`]).
    untrusted: f64,
    /// Per piece, the Bernstein coefficients `(A_k, B_k)` of `G`.
    pieces: Vec<Vec<Coefficient>>,
    /// At a corner start, the last coefficient of the segment before (its `G` at the
    /// corner); at a corner end, the first of the segment after.
    corner: [Option<Coefficient>; 2],
}

#[derive(Clone, Copy)]
struct Coefficient {
    a: [f64; 2],
    b: f64,
}

impl Fan {
    /// The fans of the segments of `boundary`, in coordinates relative to `origin` (near the
    /// region, so that the coefficients carry no large offset); `None` for a segment with a
    /// weight that is not positive (it is then kept everywhere), and for the segments beside
    /// it across a corner.
    pub(crate) fn of_all(boundary: &Profile, origin: [f64; 2]) -> Vec<Option<Fan>> {
        let n = boundary.segments().len();
        let mut fans: Vec<Option<Fan>> = (0..n).map(|i| Fan::of(boundary, i, origin)).collect();
        // (An open profile's ends are not joints: nothing lies beyond them.)
        for joint in boundary.corners() {
            let after = joint.u.round() as usize % n;
            let before = (after + n - 1) % n;
            let end = fans[before].as_ref().map(|f| {
                let last = &f.pieces[f.pieces.len() - 1];
                last[last.len() - 1]
            });
            let start = fans[after].as_ref().map(|f| f.pieces[0][0]);
            match (end, start) {
                (Some(end), Some(start)) => {
                    if let Some(f) = fans[after].as_mut() {
                        f.corner[0] = Some(end);
                    }
                    if let Some(f) = fans[before].as_mut() {
                        f.corner[1] = Some(start);
                    }
                }
                _ => {
                    fans[after] = None;
                    fans[before] = None;
                }
            }
        }
        fans
    }

    /// The fan of segment `i` of `boundary` (no corners yet).
    fn of(boundary: &Profile, i: usize, origin: [f64; 2]) -> Option<Fan> {
        let hom = boundary.segments()[i].curve().exact_pieces().hom;
        let weights_positive = (0..hom.pieces()).all(|k| {
            hom.piece(k)
                .chunks_exact(3)
                .all(|p| !p[2].is_nan() && p[2] > 0.0)
        });
        if !weights_positive {
            return None;
        }
        // P relative to the origin (X − o W), q = P'W − PW', A = W q, B = P·q.
        let w = hom.components(&[2]).ok()?;
        let along = |c: usize| -> Option<Piecewise> {
            hom.components(&[c]).ok()?.lincomb(1.0, &w, -origin[c]).ok()
        };
        let p = Piecewise::stack(&[&along(0)?, &along(1)?]).ok()?;
        let q = w
            .mul(&p.derivative())
            .ok()?
            .sub(&w.derivative().mul(&p).ok()?)
            .ok()?;
        let (a, b) = (w.mul(&q).ok()?, p.dot(&q).ok()?);
        let pieces = (0..b.pieces())
            .map(|k| {
                a.piece(k)
                    .chunks_exact(2)
                    .zip(b.piece(k))
                    .map(|(a, &b)| Coefficient { a: [a[0], a[1]], b })
                    .collect()
            })
            .collect();
        Some(Fan {
            origin,
            untrusted: UNTRUSTED_TURNS * boundary.smooth_turn(),
            pieces,
            corner: [None, None],
        })
    }

    /// Whether the segment may hold the nearest boundary point of some point of `cell`
    /// (`[lo x, lo y, hi x, hi y]`): `false` only where proven not.
    pub(crate) fn may_hold_foot(&self, cell: [f64; 4]) -> bool {
        let centre = [
            0.5 * (cell[0] + cell[2]) - self.origin[0],
            0.5 * (cell[1] + cell[3]) - self.origin[1],
        ];
        let half = [0.5 * (cell[2] - cell[0]), 0.5 * (cell[3] - cell[1])];
        let reach = centre[0].abs().max(centre[1].abs()) + half[0].max(half[1]);
        // The range of one coefficient over the cell, widened by what is not trusted.
        let range = |c: &Coefficient| {
            let v = c.a[0] * centre[0] + c.a[1] * centre[1] - c.b;
            let spread = c.a[0].abs() * half[0] + c.a[1].abs() * half[1];
            let untrusted = self.untrusted * ((c.a[0].abs() + c.a[1].abs()) * reach + c.b.abs());
            (v - spread - untrusted, v + spread + untrusted)
        };
        // A corner `x` lies ahead of along the segment before it (G ≥ 0 at its end) and
        // behind along the one after (G ≤ 0 at its start): the two conditions are tested on
        // the cell apart (a box meeting both half-planes may miss their wedge: kept).
        let (first, last) = (&self.pieces[0], &self.pieces[self.pieces.len() - 1]);
        // (Written so that a NaN, from coefficients past the range of doubles, keeps the
        // segment: nothing is proven there.)
        let ahead = |c: &Coefficient| {
            let hi = range(c).1;
            hi.is_nan() || hi >= 0.0
        };
        let behind = |c: &Coefficient| {
            let lo = range(c).0;
            lo.is_nan() || lo <= 0.0
        };
        if self.corner[0].is_some_and(|before| ahead(&before) && behind(&first[0]))
            || self.corner[1].is_some_and(|after| ahead(&last[last.len() - 1]) && behind(&after))
        {
            return true;
        }
        // A zero of G inside a piece or at its ends (a smooth joint): coefficients of both
        // signs.
        self.pieces.iter().any(|piece| {
            let (mut up, mut down) = (false, false);
            piece.iter().any(|c| {
                let (lo, hi) = range(c);
                up |= hi.is_nan() || hi >= 0.0;
                down |= lo.is_nan() || lo <= 0.0;
                up && down
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_shapes::{spline_star, star};
    use curve::{ParamCurve, Region, V2};
    use proptest::prelude::*;

    /// The segments of `boundary` nearest `x` (within 1e-9: a foot at a joint is on both):
    /// dense samples on every segment, then golden-section search about the best of each (an
    /// independent distance, not the tree's nor the fans').
    fn nearest_segments(boundary: &Profile, x: V2) -> Vec<usize> {
        let distances: Vec<f64> = boundary
            .segments()
            .iter()
            .map(|seg| {
                let c = seg.curve();
                let (a, b) = c.domain();
                let dist = |u: f64| (c.jet_to(u, 0).p - x).norm();
                let n = 200;
                let k = (0..=n)
                    .min_by(|&i, &j| {
                        let at = |k: usize| a + (b - a) * k as f64 / n as f64;
                        dist(at(i)).total_cmp(&dist(at(j)))
                    })
                    .unwrap_or(0);
                let (mut lo, mut hi) = (
                    a + (b - a) * k.saturating_sub(1) as f64 / n as f64,
                    a + (b - a) * (k + 1).min(n) as f64 / n as f64,
                );
                for _ in 0..100 {
                    let (m1, m2) = (lo + (hi - lo) * 0.382, hi - (hi - lo) * 0.382);
                    if dist(m1) < dist(m2) {
                        hi = m2;
                    } else {
                        lo = m1;
                    }
                }
                dist(0.5 * (lo + hi))
            })
            .collect();
        let least = distances.iter().fold(f64::INFINITY, |m, &d| m.min(d));
        (0..distances.len())
            .filter(|&i| distances[i] <= least + 1e-9)
            .collect()
    }

    /// The boundaries of `region` as the pair tree sees them (spline segments cut at their
    /// knots).
    fn cut(region: &Region) -> Vec<Profile> {
        std::iter::once(region.outer())
            .chain(region.holes())
            .map(|b| match b.split_at_knots() {
                Ok(Some((p, _))) => p,
                _ => b.clone(),
            })
            .collect()
    }

    /// Every point of a random cell has a nearest segment among those whose fans say they
    /// may hold it: a random point and cell size, 5 × 5 points of the cell checked against
    /// the independent nearest segments (a foot at a corner is on both segments it joins, and
    /// the pairs of the corner are kept with either).
    fn feet_are_kept(region: &Region, centre: [f64; 2], half: f64) -> Result<(), TestCaseError> {
        let cell = [
            centre[0] - half,
            centre[1] - half,
            centre[0] + half,
            centre[1] + half,
        ];
        for boundary in cut(region) {
            let fans = Fan::of_all(&boundary, [0.1, -0.2]);
            for i in 0..5 {
                for j in 0..5 {
                    let x = V2::new(
                        cell[0] + (cell[2] - cell[0]) * i as f64 / 4.0,
                        cell[1] + (cell[3] - cell[1]) * j as f64 / 4.0,
                    );
                    let nearest = nearest_segments(&boundary, x);
                    prop_assert!(
                        nearest
                            .iter()
                            .any(|&s| fans[s].as_ref().is_none_or(|f| f.may_hold_foot(cell))),
                        "segments {nearest:?} hold the foot of {x:?} in {cell:?}"
                    );
                }
            }
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

        /// Stars of cubic Béziers with corners and round holes (arcs: rational pieces).
        #[test]
        fn the_nearest_segment_of_a_chain_is_kept(
            radii in proptest::collection::vec(1.0f64..1.6, 5..12),
            wobble in proptest::collection::vec(-0.3f64..0.3, 12),
            holes in proptest::collection::vec(([-0.4f64..0.4, -0.4f64..0.4], 0.05f64..0.3), 0..3),
            centre in [-1.8f64..1.8, -1.8f64..1.8],
            half in 0.001f64..0.5,
        ) {
            let Some(region) = star(&radii, &wobble[..radii.len()], &holes) else {
                return Ok(());
            };
            feet_are_kept(&region, centre, half)?;
        }

        /// Closed B-splines cut at their knots, polynomial and rational.
        #[test]
        fn the_nearest_span_of_a_spline_is_kept(
            radii in proptest::collection::vec(1.0f64..1.6, 6..16),
            weights in proptest::collection::vec(0.3f64..3.0, 16),
            rational in any::<bool>(),
            centre in [-1.8f64..1.8, -1.8f64..1.8],
            half in 0.001f64..0.5,
        ) {
            let w = rational.then_some(&weights[..radii.len()]);
            let Some(region) = spline_star(&radii, w) else { return Ok(()) };
            feet_are_kept(&region, centre, half)?;
        }
    }

    /// The fans part what distances cannot: inside a circle of 24 spans, a small cell on a
    /// knot's normal keeps only the two spans meeting there and their neighbours (the
    /// coefficients bound `G` loosely, by about a span), 4 of 24.
    #[test]
    fn a_cell_beside_a_smooth_boundary_keeps_few_spans() {
        let region = spline_star(&[1.0; 24], None).unwrap();
        let boundary = &cut(&region)[0];
        let fans = Fan::of_all(boundary, [0.0, 0.0]);
        let cell = [0.6, -0.01, 0.62, 0.01];
        let kept = fans
            .iter()
            .filter(|f| f.as_ref().is_none_or(|f| f.may_hold_foot(cell)))
            .count();
        assert!((2..=4).contains(&kept), "{kept} of {}", fans.len());
    }
}
