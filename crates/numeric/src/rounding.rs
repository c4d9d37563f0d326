//! The one rounding model of the certified numerics: every bound on the difference between a
//! computed value and the exact one is written with these, from IEEE 754 binary64 arithmetic
//! with round-to-nearest. (The bounds of the B-spline operations, built on them, are in
//! `bspline::rounding`.)
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

/// `k` units in the last place of 1 (`k ε`, with `ε = 2u` the gap between 1 and the next
/// double): the relative room a caller grants a value that went through a few roundings, or
/// the smallest relative step of a parameter worth taking. The one spelling of `k ×
/// f64::EPSILON` in the workspace, so that every such room is found from here.
pub const fn ulps(k: f64) -> f64 {
    k * f64::EPSILON
}

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

/// A value computed in floating point with a bound on its distance from the exact value it
/// stands for: `|value − exact| ≤ error`. Sums and products carry the operands' errors and
/// add their own rounding, so a sign read off the result ([`Bounded::sign`]) holds for the
/// exact value.
///
/// ```
/// use numeric::rounding::Bounded;
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

    #[test]
    fn ulps_are_units_of_epsilon() {
        assert_eq!(ulps(1.0), f64::EPSILON);
        assert_eq!(1.0 + ulps(1.0), f64::from_bits(1.0f64.to_bits() + 1));
        assert_eq!(ulps(0.5), UNIT_ROUNDOFF);
    }
}
