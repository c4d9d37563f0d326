//! First-order Taylor models: `f(m + h) ∈ v + g·h + [−r, r]` for `|h| ≤ δ`.
//!
//! Interval arithmetic on the ranges of `K`, `w` and `|D|` loses that they move together:
//! where a parametrisation speeds up (as on the rational circle) the curvature numerator and
//! the cube of the speed grow alike, and the quotient of their ranges is many times wider than
//! the range of the curvature itself (25 % against 2 % over a stretch of the limaçon). A
//! Taylor model carries the common linear part through products and reciprocals exactly, so
//! only second-order terms widen the result.

use numeric::Interval;

/// `f(m + h) ∈ v + g·h + [−r, r]` for `|h| ≤ δ` (the half-width `δ` is the caller's, the same
/// for every model combined).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Taylor {
    pub(crate) v: f64,
    pub(crate) g: f64,
    pub(crate) r: f64,
}

impl Taylor {
    /// A constant.
    pub(crate) fn constant(v: f64) -> Self {
        Self { v, g: 0.0, r: 0.0 }
    }

    /// The product: the linear part of `(a + e_a)(b + e_b)`, every other term in the remainder.
    pub(crate) fn mul(self, o: Self, delta: f64) -> Self {
        let (ga, gb) = (self.g.abs() * delta, o.g.abs() * delta);
        Self {
            v: self.v * o.v,
            g: self.v * o.g + self.g * o.v,
            r: ga * gb
                + self.v.abs() * o.r
                + o.v.abs() * self.r
                + ga * o.r
                + gb * self.r
                + self.r * o.r,
        }
    }

    /// The cube.
    pub(crate) fn cube(self, delta: f64) -> Self {
        self.mul(self, delta).mul(self, delta)
    }

    /// `1 / f`, from `1/(v + e) = 1/v − e/v² + e²/(v² (v + e))` with `|e| ≤ E = |g|δ + r`;
    /// `None` unless `E < |v|` (the model may reach zero).
    pub(crate) fn recip(self, delta: f64) -> Option<Self> {
        let e = self.g.abs() * delta + self.r;
        let a = self.v.abs();
        // (NaN fails too.)
        if e.partial_cmp(&a) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        let v2 = self.v * self.v;
        Some(Self {
            v: 1.0 / self.v,
            g: -self.g / v2,
            r: self.r / v2 + e * e / (v2 * (a - e)),
        })
    }

    /// The range over `|h| ≤ δ`.
    pub(crate) fn range(self, delta: f64) -> Interval {
        let spread = self.g.abs() * delta + self.r;
        Interval::new(self.v - spread, self.v + spread)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use proptest::prelude::*;

    /// A model of `f` about `m` with half-width `delta`: value and slope exact at `m`, the
    /// remainder from dense sampling plus a margin (so it holds for the samples tested).
    fn model(f: &dyn Fn(f64) -> f64, df: f64, m: f64, delta: f64) -> Taylor {
        let (v, g) = (f(m), df);
        let r = (0..=400)
            .map(|k| {
                let h = delta * (2.0 * k as f64 / 400.0 - 1.0);
                (f(m + h) - v - g * h).abs()
            })
            .fold(0.0, f64::max);
        Taylor {
            v,
            g,
            r: r * 1.01 + 1e-14,
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

        /// Products, cubes and reciprocals of models of random smooth functions contain the
        /// functions' own values, and their ranges are only second-order wider than the range
        /// of a linear function.
        #[test]
        fn operations_enclose_their_functions(
            a in -3.0f64..3.0, b in -2.0f64..2.0, c in -1.0f64..1.0,
            p in 0.5f64..3.0, q in -2.0f64..2.0, w in 0.2f64..4.0,
            m in -1.0f64..1.0, delta in prop_oneof![1e-6f64..1e-3, 1e-3f64..0.3],
        ) {
            let f = move |x: f64| a + b * x + c * x * x;
            let g = move |x: f64| p + q * (w * x).sin() * 0.3;
            let tf = model(&f, b + 2.0 * c * m, m, delta);
            let tg = model(&g, 0.3 * q * w * (w * m).cos(), m, delta);
            let prod = tf.mul(tg, delta);
            let cube = tg.cube(delta);
            let inv = tg.recip(delta);
            let slack = |iv: Interval| 1e-12 * (iv.lo.abs() + iv.hi.abs() + 1.0);
            let inside = |x: f64, t: Taylor, h: f64| {
                let lin = t.v + t.g * h;
                (x - lin).abs() <= t.r + 1e-12 * (x.abs() + 1.0)
            };
            for k in 0..=100 {
                let h = delta * (2.0 * k as f64 / 100.0 - 1.0);
                let x = m + h;
                prop_assert!(inside(f(x) * g(x), prod, h), "product at {x}");
                prop_assert!(inside(g(x).powi(3), cube, h), "cube at {x}");
                let iv = prod.range(delta);
                prop_assert!(f(x) * g(x) >= iv.lo - slack(iv) && f(x) * g(x) <= iv.hi + slack(iv));
                if let Some(inv) = inv {
                    prop_assert!(inside(1.0 / g(x), inv, h), "reciprocal at {x}");
                }
            }
            // Wherever the model's range excludes zero, so does the reciprocal's existence.
            let gr = tg.range(delta);
            if gr.lo > 0.0 {
                prop_assert!(inv.is_some());
            }
        }
    }

    #[test]
    fn tighter_than_interval_arithmetic_on_a_constant_quotient() {
        // f = x³ + 1 over g = x³ + 1 (so f/g ≡ 1): the quotient of ranges is wide, the
        // model's range is not.
        let (m, delta) = (1.0, 0.05);
        let f = |x: f64| x.powi(3) + 1.0;
        let t = model(&f, 3.0, m, delta);
        let q = t.mul(t.recip(delta).unwrap(), delta).range(delta);
        let r = t.range(delta);
        let naive = r.mul(r.recip().unwrap());
        assert!(q.lo <= 1.0 && q.hi >= 1.0);
        assert!(
            q.hi - q.lo < 0.25 * (naive.hi - naive.lo),
            "{q:?} vs {naive:?}"
        );
    }
}
