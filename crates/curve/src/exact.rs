//! Exact predicates on the data: signs of determinants of given coordinates, decided without
//! rounding. A floating-point evaluation decides where it is clear of its error bound (almost
//! always); exact rational arithmetic decides the rest (the degenerate cases these predicates
//! exist for: collinear control points, parallel straight stretches).

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use numeric::rounding::UNIT_ROUNDOFF;
use std::cmp::Ordering;

/// The sign of `(b − a) × (d − c)`: `Less` when turning from the first direction to the second
/// is clockwise, `Equal` when they are exactly parallel (or either is zero). `None` for
/// coordinates that are not finite.
///
/// ```
/// use curve::exact::cross_sign;
/// use std::cmp::Ordering;
/// let (o, u) = ([0.0, 0.0], [0.1, 0.3]);
/// // Twice a direction is parallel to it; one ulp off, it is not (and the sign says which
/// // way).
/// assert_eq!(cross_sign(o, u, o, [2.0 * 0.1, 2.0 * 0.3]), Some(Ordering::Equal));
/// let off = f64::from_bits((2.0 * 0.3f64).to_bits() + 1);
/// assert_eq!(cross_sign(o, u, o, [2.0 * 0.1, off]), Some(Ordering::Greater));
/// ```
pub fn cross_sign(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<Ordering> {
    if ![a, b, c, d].iter().flatten().all(|x| x.is_finite()) {
        return None;
    }
    let (ux, uy, vx, vy) = (b[0] - a[0], b[1] - a[1], d[0] - c[0], d[1] - c[1]);
    // (A difference of doubles is zero exactly when they are equal: a zero direction is
    // parallel to any, without the exact path.)
    if (ux == 0.0 && uy == 0.0) || (vx == 0.0 && vy == 0.0) {
        return Some(Ordering::Equal);
    }
    // (Nor the same pair of points twice.)
    if a == c && b == d {
        return Some(Ordering::Equal);
    }
    let (left, right) = (ux * vy, uy * vx);
    let det = left - right;
    // Each difference is within UNIT_ROUNDOFF of its value, each product within 3 UNIT_ROUNDOFF (and the
    // rounding of the products themselves), the difference within one more: 8 UNIT_ROUNDOFF of the
    // terms' magnitudes bounds the error with room (and underflow is caught by the exact
    // path: a bound of zero decides nothing).
    let bound = 8.0 * UNIT_ROUNDOFF * (left.abs() + right.abs());
    if det.abs() > bound && bound > f64::MIN_POSITIVE {
        return det.partial_cmp(&0.0);
    }
    if let Some(sign) = exact_by_expansion(a, b, c, d) {
        return Some(sign);
    }
    let q = |x: f64| BigRational::from_float(x);
    let (ax, ay, bx, by) = (q(a[0])?, q(a[1])?, q(b[0])?, q(b[1])?);
    let (cx, cy, dx, dy) = (q(c[0])?, q(c[1])?, q(d[0])?, q(d[1])?);
    let exact = (bx - ax) * (dy - cy) - (by - ay) * (dx - cx);
    Some(if exact.is_zero() {
        Ordering::Equal
    } else if exact.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    })
}

/// `(x + y, error)` with `x + y = sum + error` exactly (Knuth's two-sum).
fn two_sum(x: f64, y: f64) -> (f64, f64) {
    let sum = x + y;
    let v = sum - x;
    (sum, (x - (sum - v)) + (y - v))
}

/// Products whose fused rounding error is exact (no underflow of the error term) and that
/// do not overflow: the expansion path's range.
const EXPANSION_RANGE: (f64, f64) = (1e-280, 1e280);

/// The sign of `(b − a) × (d − c)` in double arithmetic without rounding, where the four
/// differences are exact (as for coordinates within a factor two of each other, or on a
/// common grid): each product as a value and its exact error (a fused multiply-add), the
/// four terms summed into a non-overlapping expansion (Shewchuk), whose largest component
/// has the sum's sign. `None` where a difference rounds or a product leaves the range in
/// which its error is exact.
fn exact_by_expansion(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<Ordering> {
    let diff = |x: f64, y: f64| match two_sum(x, -y) {
        (v, 0.0) => Some(v),
        _ => None,
    };
    let (ux, uy) = (diff(b[0], a[0])?, diff(b[1], a[1])?);
    let (vx, vy) = (diff(d[0], c[0])?, diff(d[1], c[1])?);
    let product = |x: f64, y: f64| {
        let p = x * y;
        // (A zero product is exact only from a zero factor: underflow gives zeros too.)
        let fine =
            x == 0.0 || y == 0.0 || (EXPANSION_RANGE.0..EXPANSION_RANGE.1).contains(&p.abs());
        fine.then(|| (p, x.mul_add(y, -p)))
    };
    let ((p1, e1), (p2, e2)) = (product(ux, vy)?, product(uy, vx)?);
    // Grow the expansion one term at a time: each two-sum passes the rounding error down.
    let mut expansion: Vec<f64> = Vec::with_capacity(4);
    for term in [e1, -e2, p1, -p2] {
        let mut q = term;
        for h in expansion.iter_mut() {
            let (sum, err) = two_sum(q, *h);
            *h = err;
            q = sum;
        }
        expansion.push(q);
    }
    let top = expansion
        .iter()
        .rev()
        .find(|&&x| x != 0.0)
        .copied()
        .unwrap_or(0.0);
    top.partial_cmp(&0.0)
}

/// The orientation of the triangle `a, b, c`: `Greater` counterclockwise, `Less` clockwise,
/// `Equal` collinear, exactly. `None` for coordinates that are not finite.
///
/// ```
/// use curve::exact::orientation;
/// use std::cmp::Ordering;
/// assert_eq!(orientation([0.0, 0.0], [1.0, 1.0], [3.0, 3.0]), Some(Ordering::Equal));
/// assert_eq!(orientation([0.0, 0.0], [1.0, 0.0], [0.0, 1e-300]), Some(Ordering::Greater));
/// ```
pub fn orientation(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<Ordering> {
    cross_sign(a, b, a, c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The exact sign by rational arithmetic alone (the oracle).
    fn rational(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Ordering {
        let q = |x: f64| BigRational::from_float(x).unwrap_or_default();
        let det =
            (q(b[0]) - q(a[0])) * (q(d[1]) - q(c[1])) - (q(b[1]) - q(a[1])) * (q(d[0]) - q(c[0]));
        det.cmp(&BigRational::zero())
    }

    proptest! {
        /// The filtered sign is the exact one: on random directions, on exactly parallel
        /// ones (the same difference moved by a multiple), on nearly parallel ones (one ulp
        /// off), at every scale.
        #[test]
        fn cross_sign_is_exact(
            p in proptest::array::uniform8(-1.0f64..1.0),
            k in -300i32..300,
            along in -4.0f64..4.0,
            nudge in 0usize..3,
        ) {
            let s = 2f64.powi(k);
            let (a, b, c) = ([p[0] * s, p[1] * s], [p[2] * s, p[3] * s], [p[4] * s, p[5] * s]);
            let d_random = [p[6] * s, p[7] * s];
            // c + t (b − a), rounded: parallel, one ulp off, or as rounded.
            let mut d_near = [c[0] + along * (b[0] - a[0]), c[1] + along * (b[1] - a[1])];
            if nudge == 1 { d_near[0] = f64::from_bits(d_near[0].to_bits() + 1); }
            for d in [d_random, d_near] {
                prop_assert_eq!(cross_sign(a, b, c, d), Some(rational(a, b, c, d)));
                if let Some(sign) = exact_by_expansion(a, b, c, d) {
                    prop_assert_eq!(sign, rational(a, b, c, d));
                }
            }
            // Exactly parallel: points on a grid (their differences exact) and a whole
            // multiple of one difference.
            let g = |x: f64| (x * 1024.0).round() / 1024.0 * s;
            let (a, b, c) = ([g(p[0]), g(p[1])], [g(p[2]), g(p[3])], [g(p[4]), g(p[5])]);
            let m = along.round();
            let d = [c[0] + m * (b[0] - a[0]), c[1] + m * (b[1] - a[1])];
            prop_assert_eq!(cross_sign(a, b, c, d), Some(Ordering::Equal));
            prop_assert_eq!(rational(a, b, c, d), Ordering::Equal);
            // On the grid the differences are exact: the expansion decides.
            let mut off = d;
            off[nudge % 2] = f64::from_bits(off[nudge % 2].to_bits() + 1);
            // (It declines where a difference rounds, as one ulp off may, or a product leaves
            // its range.)
            prop_assert_eq!(exact_by_expansion(a, b, c, d), Some(Ordering::Equal));
            let by_expansion = exact_by_expansion(a, b, c, off);
            prop_assert!(by_expansion.is_none_or(|e| e == rational(a, b, c, off)));
        }
    }

    #[test]
    fn not_finite_is_none() {
        assert_eq!(orientation([f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]), None);
        assert_eq!(
            orientation([f64::INFINITY, 0.0], [1.0, 0.0], [0.0, 1.0]),
            None
        );
    }
}
