//! The one rounding model of the certified numerics: every bound on the difference between a
//! computed coefficient (or value) and the exact one is written here, once, from IEEE 754
//! binary64 arithmetic with round-to-nearest.
//!
//! Each operation `x ∘ y` rounds to `(x ∘ y)(1 + δ)` with `|δ| ≤ u`, the unit roundoff, and `n`
//! such roundings in a chain stay within `γ(n) = n u / (1 − n u)` relative (Higham, *Accuracy
//! and Stability of Numerical Algorithms*, §3.1). Bounds are **absolute** and in terms of the
//! magnitudes of the operands, never of the result: where terms cancel (a curve far from the
//! origin, a nearly straight stretch), the result is small but its error is not.
//!
//! Every bound assumes no overflow and no underflow below the normal range; the callers work in
//! a frame where the curve's size is about 1 (see the curve model), far from both.

/// Unit roundoff of binary64 round-to-nearest: `|fl(x ∘ y) − x ∘ y| ≤ u |x ∘ y|`.
pub const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// `γ(n) = n u / (1 − n u)`: the relative error of `n` roundings in a chain (infinite once
/// `n u ≥ 1`, where nothing can be bounded).
pub fn gamma(n: usize) -> f64 {
    let nu = n as f64 * UNIT_ROUNDOFF;
    if nu >= 1.0 {
        f64::INFINITY
    } else {
        // (Rounded up by a relative 4u: the bound must not itself round below the truth.)
        nu / (1.0 - nu) * (1.0 + 4.0 * UNIT_ROUNDOFF)
    }
}

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

/// A value computed in floating point with a bound on its distance from the exact value it
/// stands for: `|value − exact| ≤ error`. Sums and products carry the operands' errors and
/// add their own rounding, so a sign read off the result ([`Bounded::sign`]) holds for the
/// exact value.
///
/// ```
/// use bspline::rounding::Bounded;
/// // 0.1 is stored within half an ulp of one tenth; 3 × 0.1 − 0.3 is then known only to a
/// // few units of rounding, with no trusted sign.
/// let tenth = Bounded::new(0.1, 0.1 * f64::EPSILON);
/// let d = Bounded::exact(3.0).mul(tenth).sub(Bounded::new(0.3, 0.3 * f64::EPSILON));
/// assert_eq!(d.sign(), None);
/// assert_eq!(Bounded::exact(2.0).mul(tenth).sign(), Some(1.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounded {
    /// The computed value.
    pub value: f64,
    /// The bound on its error.
    pub error: f64,
}

impl Bounded {
    /// A value known to within `error`.
    pub fn new(value: f64, error: f64) -> Self {
        Self { value, error }
    }

    /// A value known exactly.
    pub fn exact(value: f64) -> Self {
        Self::new(value, 0.0)
    }

    /// The sum: the operands' errors and the sum's rounding.
    #[allow(clippy::should_implement_trait)] // (named calls read as the bounds they carry)
    pub fn add(self, o: Bounded) -> Bounded {
        let value = self.value + o.value;
        Self::new(
            value,
            up(self.error + o.error + UNIT_ROUNDOFF * value.abs()),
        )
    }

    /// The difference.
    #[allow(clippy::should_implement_trait)]
    pub fn sub(self, o: Bounded) -> Bounded {
        self.add(Bounded::new(-o.value, o.error))
    }

    /// The product: `|a| e_b + |b| e_a + e_a e_b` carried, and the product's rounding.
    #[allow(clippy::should_implement_trait)]
    pub fn mul(self, o: Bounded) -> Bounded {
        let value = self.value * o.value;
        let carried =
            self.value.abs() * o.error + o.value.abs() * self.error + self.error * o.error;
        Self::new(value, up(carried + UNIT_ROUNDOFF * value.abs()))
    }

    /// The sign of the exact value (+1 or −1) where the bound proves it.
    pub fn sign(self) -> Option<f64> {
        if self.value > self.error {
            Some(1.0)
        } else if self.value < -self.error {
            Some(-1.0)
        } else {
            None
        }
    }
}

/// A bound computed in floating point, raised past its own rounding (a few operations, each
/// within `u`, and the `|value|` it was taken from within `u` of the exact result).
fn up(bound: f64) -> f64 {
    bound * (1.0 + 8.0 * UNIT_ROUNDOFF)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_grows_and_saturates() {
        assert!(gamma(0) == 0.0);
        assert!(gamma(1) > UNIT_ROUNDOFF);
        assert!(gamma(10) > 10.0 * UNIT_ROUNDOFF && gamma(10) < 11.0 * UNIT_ROUNDOFF);
        assert!(gamma(1 << 53) == f64::INFINITY);
    }
}
