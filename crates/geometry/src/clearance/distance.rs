//! What a piece's squared distance from the disk's centre proves, from its Bernstein
//! coefficients: outside where they are all positive, else, where it is convex, by its
//! tangent at its least point.

use crate::pieces::Piece;
use curve::piece_bounds::Errors;
use curve::V2;
use numeric::rounding::ulps;
use smallvec::{smallvec, SmallVec};

/// Steps that find where a convex squared distance is least: Newton, or a halving where it
/// would leave the bracket (to 2^-60 of the piece at worst).
const LEAST_STEPS: usize = 60;

/// The search for the least point stops at a step this small (a share of the piece): the
/// tangent there bounds the distance however near the least point it is; nearer makes the
/// bound tighter, and Newton gets there from 1e-8 in one more step.
const LEAST_STEP: f64 = 1e-15;

/// Coefficients of a squared distance held in place (up to degree 30): they are built for
/// tens of pieces in each disk test.
type Row = SmallVec<[f64; 32]>;

/// What the piece's squared distance from the centre proves,
/// `D = |P − x w|² − r² w²` (a polynomial of twice the degree, positive exactly where the
/// curve is outside): outside where its Bernstein coefficients are all positive (a bound
/// that closes in quadratically as pieces shrink, where the hull's closes in linearly on
/// a curved piece); else, where their second differences are all positive it is convex,
/// and it lies above its tangent at its least point, found by halving on the sign of its
/// derivative: outside where that bound is positive, a point inside where the least value
/// is negative. Every comparison allows for the coefficients'
/// errors and the rounding of the arithmetic; `None` where neither is proven.
pub(super) fn distance_verdict(piece: &Piece<'_>, x: V2, r: f64, err: Errors) -> Option<Convex> {
    let n = piece.coefs.len() / 3;
    if n < 2 {
        return None;
    }
    let (d, m) = (n - 1, 2 * (n - 1));
    let eps = ulps(1.0);
    let (mut h_max, mut w_max) = (0.0f64, 0.0f64);
    for c in piece.coefs.chunks_exact(3) {
        h_max = h_max.max(c[0].abs()).max(c[1].abs());
        w_max = w_max.max(c[2].abs());
    }
    // Errors of the homogeneous coefficients (the halvings' roundings added), then of the
    // coefficients relative to the centre.
    let xm = x.x.abs().max(x.y.abs());
    let halvings = (piece.depth + 2) as f64 * eps;
    let e_w = err.weight + halvings * w_max;
    let e_rel = err.point + halvings * h_max + xm * e_w + 2.0 * eps * (h_max + xm * w_max);
    let rel: SmallVec<[[f64; 3]; 16]> = piece
        .coefs
        .chunks_exact(3)
        .map(|c| [c[0] - x.x * c[2], c[1] - x.y * c[2], r * c[2]])
        .collect();
    let big = rel
        .iter()
        .flat_map(|c| c.iter().map(|v| v.abs()))
        .fold(0.0, f64::max);
    let binomial = |n: usize| {
        let mut row: Row = smallvec![1.0f64; n + 1];
        for k in 1..n {
            row[k] = row[k - 1] * (n + 1 - k) as f64 / k as f64;
        }
        row
    };
    let (cd, cm) = (binomial(d), binomial(m));
    let mut coef: Row = smallvec![0.0; m + 1];
    for (i, a) in rel.iter().enumerate() {
        for (j, b) in rel.iter().enumerate() {
            coef[i + j] += cd[i] * cd[j] * (a[0] * b[0] + a[1] * b[1] - a[2] * b[2]);
        }
    }
    for (c, b) in coef.iter_mut().zip(&cm) {
        *c /= b;
    }
    // Each coefficient is a convex combination of products of magnitude at most `big²`.
    let err_coef =
        2.0 * (4.0 * big * e_rel + 2.0 * big * r * e_w) + 6.0 * (m + 8) as f64 * eps * big * big;
    let round = 8.0 * (m + 2) as f64 * eps * big * big;
    // D lies above its least Bernstein coefficient.
    if coef.iter().fold(f64::INFINITY, |a, &c| a.min(c)) > err_coef + round {
        return Some(Convex::Outside);
    }
    if coef
        .windows(3)
        .any(|w| w[2] - 2.0 * w[1] + w[0] <= 4.0 * err_coef + round)
    {
        return None;
    }
    let slope: Row = coef.windows(2).map(|w| w[1] - w[0]).collect();
    // Where D′ = m Σ slope Bᵐ⁻¹ changes sign (D is convex: D′ rises), by Newton on it,
    // kept in a bracket that halves wherever a step would leave it.
    let t0 = if slope[0] >= 0.0 {
        0.0
    } else if slope[m - 1] <= 0.0 {
        1.0
    } else {
        let (mut lo, mut hi, mut t) = (0.0, 1.0, 0.5);
        for _ in 0..LEAST_STEPS {
            let (s, ds) = value_and_derivative(&slope, t);
            if s < 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let newton = t - s / ds;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let step = (next - t).abs();
            t = next;
            if step <= LEAST_STEP {
                break;
            }
        }
        t
    };
    // D(t) ≥ D(t0) + D′(t0)(t − t0) on [0, 1], D′ = m Σ slope Bᵐ⁻¹.
    let least = value_and_derivative(&coef, t0).0;
    let value = least - err_coef - round;
    let rate = m as f64 * (value_and_derivative(&slope, t0).0.abs() + 2.0 * err_coef + round);
    if value - rate * t0.max(1.0 - t0) > 0.0 {
        Some(Convex::Outside)
    } else if least + err_coef + round < 0.0 {
        // The curve's point there is inside, past every error.
        Some(Convex::Inside(t0))
    } else {
        None
    }
}

/// The value and derivative at `t` of the polynomial with Bernstein coefficients `c` on
/// `[0, 1]`, by de Casteljau's algorithm.
fn value_and_derivative(c: &[f64], t: f64) -> (f64, f64) {
    let n = c.len() - 1;
    if n == 0 {
        return (c[0], 0.0);
    }
    // (In place up to degree 31, as every squared distance of a piece up to degree 15.)
    let mut inline = [0.0; 32];
    let mut spilled = Vec::new();
    let work: &mut [f64] = if c.len() <= inline.len() {
        inline[..c.len()].copy_from_slice(c);
        &mut inline[..c.len()]
    } else {
        spilled.extend_from_slice(c);
        &mut spilled
    };
    for level in 1..n {
        for j in 0..=n - level {
            work[j] += t * (work[j + 1] - work[j]);
        }
    }
    // The last two values span the derivative.
    (
        work[0] + t * (work[1] - work[0]),
        n as f64 * (work[1] - work[0]),
    )
}

/// What a piece's squared distance proves.
pub(super) enum Convex {
    /// The piece lies outside the disk.
    Outside,
    /// Its point at this share of the piece lies inside.
    Inside(f64),
}
