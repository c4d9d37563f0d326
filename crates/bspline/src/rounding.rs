//! The rounding bounds of the B-spline operations (de Casteljau, Horner, knot insertion,
//! derivatives, products, linear combinations), written with the one rounding model of
//! [`numeric::rounding`] (its unit roundoff, `γ(n)` and bounded values).
//!
//! Bounds are **absolute** and in terms of the magnitudes of the operands, never of the
//! result: where terms cancel (a curve far from the origin, a nearly straight stretch), the
//! result is small but its error is not. Every bound assumes no overflow and no underflow
//! below the normal range; the callers work in a frame where the curve's size is about 1 (see
//! the curve model), far from both.

use numeric::rounding::gamma;

/// The error the B-spline entry points of [`crate::roots`] assume in coefficients handed to
/// them: a function computed by the caller in floating point (by products, say) is known to a
/// few units of rounding per degree of its largest coefficient, and coefficients within that of
/// zero (the residue of a cancellation) have no trusted sign. Functions whose error is tracked
/// come as [`crate::Piecewise`] forms with their own bounds instead.
pub fn computed_coefficients(degree: usize, magnitude: f64) -> f64 {
    gamma(8 * (degree + 2)) * magnitude
}

/// Roundings per level of de Casteljau's step `(1 − s) x + s y` with `s ∈ [0, 1]` (the
/// difference `1 − s`, two products and a sum: three units of the operands' magnitude),
/// counted with the rounding of `s` itself, which moves the result by at most
/// `u |y − x| ≤ 2 u max(|x|, |y|)`: five units per level.
const CASTELJAU_LEVEL: usize = 5;

/// The error de Casteljau's algorithm adds, at one parameter in `[0, 1]`, to Bernstein
/// coefficients of `degree` whose magnitudes (with their own error) are at most `magnitude`:
/// an evaluation, a subdivision, or a restriction's cut at one end. Convex combinations do not
/// grow the coefficients' own errors, which pass through unchanged.
pub fn casteljau(degree: usize, magnitude: f64) -> f64 {
    gamma(CASTELJAU_LEVEL * degree) * magnitude
}

/// The error of Horner's scheme on the binomially weighted Bernstein coefficients of `degree`
/// in the ratio `s/(1 − s) ≤ 1` (or its inverse) and the power of `1 − s` (or `s`) that scales
/// it: about `2 degree + 4` roundings relative to `Σ C(p, j) |c_j| sʲ (1 − s)^(p−j) ≤ max |c_j|`
/// (the binomial weights, exact integers below 2⁵³ up to degree 56, carry their own few units).
pub fn horner(degree: usize, magnitude: f64) -> f64 {
    gamma(3 * degree + 6) * magnitude
}

/// Roundings behind one step of knot insertion, `α q₁ + (1 − α) q₀` with `α ∈ [0, 1]` itself a
/// rounded quotient of knot differences (three roundings, moving the result by `3u |q₁ − q₀|`):
/// the same bound as a de Casteljau level plus the three of `α`.
const INSERTION_STEP: usize = 8;

/// The error one knot-insertion step adds to a coefficient formed from coefficients of
/// magnitude at most `magnitude`.
pub fn insertion(magnitude: f64) -> f64 {
    gamma(INSERTION_STEP) * magnitude
}

/// The error of the Bernstein coefficients of a derivative, `(p / h) (c_{j+1} − c_j)` on a
/// piece of width `h = b − a` (itself rounded), from coefficients of magnitude at most
/// `magnitude` that are in error by at most `err`: the quotient `p/h` (two roundings), the
/// difference and the product.
pub fn derivative(degree: usize, a: f64, b: f64, magnitude: f64, err: f64) -> f64 {
    let scale = degree as f64 / (b - a) * (1.0 + gamma(2));
    scale * (2.0 * err + gamma(4) * 2.0 * magnitude) * (1.0 + gamma(1))
}

/// Roundings of one term of a product of Bernstein polynomials of degrees `p` and `q`: the
/// weight `C(p, i) C(q, j) / C(p + q, k)` (binomials built by `n` products and quotients each
/// carry `2n` roundings, so `2 (p + q) + 4` in all) times a constant and the two factors.
fn product_term(p: usize, q: usize) -> usize {
    2 * (p + q) + 4 + 3
}

/// The error of the coefficients of a bilinear product of two Bernstein polynomials of degrees
/// `p` and `q` (one piece), each coefficient a sum of at most `terms` products `c · a_i · b_j`
/// with `Σ|c| ≤ weight` per output coordinate, from factors with magnitudes `(ma, mb)` and
/// errors `(ea, eb)`: the rounding of every term and of the sum (relative to the sum of the
/// terms' magnitudes, at most `weight · ma · mb` since the Bernstein weights sum to one) and
/// the factors' errors carried through.
pub fn product(
    (p, q): (usize, usize),
    terms: usize,
    weight: f64,
    (ma, mb): (f64, f64),
    (ea, eb): (f64, f64),
) -> f64 {
    let rounding = gamma(product_term(p, q) + terms) * weight * (ma + ea) * (mb + eb);
    let carried = weight * (ma * eb + ea * mb + ea * eb);
    (rounding + carried) * (1.0 + gamma(2))
}

/// The error of a sum `Σ w_c f_c` of `terms` values, each `|w_c f_c|` summing to at most
/// `magnitude` and each `f_c` in error by at most `err_c` (carried as `Σ |w_c| err_c`, given as
/// `carried`).
pub fn linear(terms: usize, magnitude: f64, carried: f64) -> f64 {
    (gamma(terms + 1) * magnitude + carried) * (1.0 + gamma(1))
}
