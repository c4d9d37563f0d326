//! Closed intervals of reals and the interval arithmetic the proofs combine ranges with.

/// A closed interval of reals, `[lo, hi]`. Its arithmetic is plain (rounded to nearest): the
/// callers widen the results by the rounding they carry ([`Interval::widened`]), as the proofs
/// of `antipodal` do.
///
/// ```
/// use numeric::Interval;
/// let x = Interval::new(-1.0, 2.0);
/// let square = x.mul(x); // (interval arithmetic forgets that both factors are one x)
/// assert_eq!((square.lo, square.hi), (-2.0, 4.0));
/// assert!(!x.excludes_zero() && Interval::new(0.5, 1.0).recip().is_some());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// The lower end.
    pub lo: f64,
    /// The upper end.
    pub hi: f64,
}

impl Interval {
    /// The interval `[lo, hi]`.
    pub fn new(lo: f64, hi: f64) -> Self {
        Self { lo, hi }
    }

    /// `hi − lo`.
    pub fn width(self) -> f64 {
        self.hi - self.lo
    }

    /// The midpoint, `(lo + hi) / 2`.
    pub fn mid(self) -> f64 {
        0.5 * (self.lo + self.hi)
    }

    /// The interval widened by a relative `margin` of its magnitude: room for the rounding
    /// of the coefficients it was read from and of the operations that combine it.
    pub fn widened(self, margin: f64) -> Self {
        let m = margin * self.lo.abs().max(self.hi.abs());
        Self::new(self.lo - m, self.hi + m)
    }

    /// The least interval holding both.
    pub fn hull(self, o: Interval) -> Self {
        Self::new(self.lo.min(o.lo), self.hi.max(o.hi))
    }

    /// The sum: every `x + y` with `x` in `self`, `y` in `o`.
    #[allow(clippy::should_implement_trait)] // (named calls, as the bounded values have)
    pub fn add(self, o: Interval) -> Self {
        Self::new(self.lo + o.lo, self.hi + o.hi)
    }

    /// The difference: every `x − y`.
    #[allow(clippy::should_implement_trait)]
    pub fn sub(self, o: Interval) -> Self {
        Self::new(self.lo - o.hi, self.hi - o.lo)
    }

    /// The product: every `x y` (the least and greatest of the corner products).
    #[allow(clippy::should_implement_trait)]
    pub fn mul(self, o: Interval) -> Self {
        let c = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        Self::new(
            c.iter().copied().fold(f64::INFINITY, f64::min),
            c.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        )
    }

    /// `1 / x` for an interval that excludes zero (`None` otherwise).
    pub fn recip(self) -> Option<Self> {
        (self.lo > 0.0 || self.hi < 0.0).then(|| Self::new(1.0 / self.hi, 1.0 / self.lo))
    }

    /// The exact range of `f` over the box `a × b × c` when `f` is multilinear (of degree at
    /// most one in each variable, as `xy + yz − xz`): a multilinear function takes its
    /// extremes at corners, where plain interval arithmetic loses whatever a variable
    /// entering twice shares. Widened by `margin` (absolute: the rounding of the terms).
    pub fn multilinear(
        [a, b, c]: [Interval; 3],
        f: impl Fn(f64, f64, f64) -> f64,
        margin: f64,
    ) -> Self {
        let v = [
            f(a.lo, b.lo, c.lo),
            f(a.lo, b.lo, c.hi),
            f(a.lo, b.hi, c.lo),
            f(a.lo, b.hi, c.hi),
            f(a.hi, b.lo, c.lo),
            f(a.hi, b.lo, c.hi),
            f(a.hi, b.hi, c.lo),
            f(a.hi, b.hi, c.hi),
        ];
        if v.iter().any(|x| x.is_nan()) {
            // (It must not pass for a proof.)
            return Self::new(f64::NAN, f64::NAN);
        }
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Self::new(lo - margin, hi + margin)
    }

    /// The greatest magnitude in the interval.
    pub fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// Strictly positive or strictly negative throughout.
    pub fn excludes_zero(self) -> bool {
        self.lo > 0.0 || self.hi < 0.0
    }

    /// Whether `x` lies in the interval to a relative `slack` of the magnitudes of both (for a
    /// value computed in floating point, checked against a range).
    pub fn holds(self, x: f64, slack: f64) -> bool {
        let room = slack * (self.mag() + x.abs());
        x >= self.lo - room && x <= self.hi + room
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// `x` lies in `iv`, to a relative slack of 1e-9 (for values computed in floating point).
    fn inside(x: f64, iv: Interval) -> bool {
        iv.holds(x, 1e-9)
    }

    proptest! {
        /// The corner range of a random multilinear function holds every value sampled on a
        /// grid of its box, and is attained (its ends are values at corners).
        #[test]
        fn multilinear_range_is_exact(
            c in proptest::array::uniform8(-2.0f64..2.0),
            ends in proptest::array::uniform6(-3.0f64..3.0),
        ) {
            let iv = |a: f64, b: f64| Interval::new(a.min(b), a.max(b));
            let boxes = [iv(ends[0], ends[1]), iv(ends[2], ends[3]), iv(ends[4], ends[5])];
            let f = |x: f64, y: f64, z: f64| {
                c[0] + c[1] * x + c[2] * y + c[3] * z
                    + c[4] * x * y + c[5] * y * z + c[6] * x * z + c[7] * x * y * z
            };
            let r = Interval::multilinear(boxes, f, 0.0);
            let at = |b: Interval, k: usize| b.lo + (b.hi - b.lo) * k as f64 / 8.0;
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for i in 0..=8 {
                for j in 0..=8 {
                    for k in 0..=8 {
                        let v = f(at(boxes[0], i), at(boxes[1], j), at(boxes[2], k));
                        prop_assert!(v >= r.lo - 1e-12 && v <= r.hi + 1e-12, "{v} outside {r:?}");
                        (lo, hi) = (lo.min(v), hi.max(v));
                    }
                }
            }
            prop_assert!((lo - r.lo).abs() <= 1e-12 && (hi - r.hi).abs() <= 1e-12);
        }
    }

    #[test]
    fn interval_arithmetic_contains_its_members() {
        let pts = [-2.5, -1.0, -0.25, 0.0, 0.5, 1.0, 3.0];
        for &a0 in &pts {
            for &a1 in pts.iter().filter(|&&x| x >= a0) {
                for &b0 in &pts {
                    for &b1 in pts.iter().filter(|&&x| x >= b0) {
                        let (a, b) = (Interval::new(a0, a1), Interval::new(b0, b1));
                        for x in [a0, 0.5 * (a0 + a1), a1] {
                            for y in [b0, 0.5 * (b0 + b1), b1] {
                                assert!(inside(x + y, a.add(b)));
                                assert!(inside(x - y, a.sub(b)));
                                assert!(inside(x * y, a.mul(b)));
                                if let Some(r) = b.recip() {
                                    assert!(inside(1.0 / y, r));
                                }
                            }
                        }
                    }
                }
            }
        }
        assert!(Interval::new(-1.0, 1.0).recip().is_none());
    }
}
