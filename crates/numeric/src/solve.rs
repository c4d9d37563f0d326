//! The one bracketed solver: the root of a scalar function inside an interval whose ends have
//! opposite signs, by Newton's (or Halley's) step safeguarded by bisection, so that it never
//! leaves the bracket and converges for any continuous function.
//!
//! Every one-dimensional refinement of the workspace goes through [`bracketed`]: a root the
//! certified counters have isolated, a primitive of Jia's method on a monotone segment, a
//! crossing of a zero set with a cell edge. Without a bracket, two finishes: [`newton_within`]
//! (Newton's steps clamped into an interval, for a root located but not bracketed, as a
//! cluster's) and [`secant`] (secant steps that may leave the starts' interval, the answer
//! held to a stated bound).

mod illinois;
mod newton;
mod secant;
pub use illinois::{End, Illinois};
pub use newton::newton_within;
pub use secant::secant;

/// How far [`bracketed`] refines, and where it starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accuracy {
    /// Parameter tolerance: the solve stops once a step is below half of it (never below a few
    /// units of rounding of the bracket's ends, where steps are noise).
    pub tol: f64,
    /// The solve also stops where `|f| ≤ noise` (the rounding level of `f`; 0 for none).
    pub noise: f64,
    /// A starting point inside the bracket (NaN for none: then the secant of the end values).
    pub hint: f64,
}

impl Accuracy {
    /// Refinement to the parameter tolerance `tol`, no value noise, no hint.
    pub fn param(tol: f64) -> Self {
        Self {
            tol,
            noise: 0.0,
            hint: f64::NAN,
        }
    }
    /// Also stops where `|f| ≤ noise`.
    pub fn noise(mut self, noise: f64) -> Self {
        self.noise = noise;
        self
    }
    /// Starts from `hint` when it lies inside the bracket.
    pub fn hint(mut self, hint: f64) -> Self {
        self.hint = hint;
        self
    }
}

/// Steps before the solve gives up on a bracket (bisection alone needs about 64 for any
/// interval of doubles; Newton's steps only shorten that).
const MAX_STEPS: usize = 200;

/// The root of `f` in `bracket`, where the end values `ends` have opposite signs (or one is
/// zero). `f(x)` returns the value, the derivative and the second derivative (NaN where it is
/// not at hand: then Newton's step, else Halley's). A bisection step replaces Newton's
/// whenever Newton's would leave the bracket or is not at least halving the step (the classic
/// `rtsafe` safeguard). Once a step falls below the tolerance, the point it starts from
/// (evaluated already) is returned.
///
/// ```
/// use numeric::solve::{bracketed, Accuracy};
/// // x³ − 2 on [0, 2].
/// let f = |x: f64| (x * x * x - 2.0, 3.0 * x * x, 6.0 * x);
/// let x = bracketed(f, (0.0, 2.0), (-2.0, 6.0), Accuracy::param(1e-14));
/// assert!((x - 2f64.cbrt()).abs() < 1e-14);
/// ```
pub fn bracketed(
    mut f: impl FnMut(f64) -> (f64, f64, f64),
    (mut lo, mut hi): (f64, f64),
    (flo, fhi): (f64, f64),
    acc: Accuracy,
) -> f64 {
    if flo == 0.0 {
        return lo;
    }
    if fhi == 0.0 {
        return hi;
    }
    let tol = acc
        .tol
        .max(4.0 * f64::EPSILON * lo.abs().max(hi.abs()).max((hi - lo).abs()));
    // Start from the hint when it is inside (a nearby previous solution converges in a few
    // steps), else where the chord of the end values crosses zero (from the middle, the first
    // Newton steps tend to overshoot and halve instead).
    let inside = |x: f64| x > lo.min(hi) && x < lo.max(hi);
    let secant = lo - flo * (hi - lo) / (fhi - flo);
    let mut x = if inside(acc.hint) {
        acc.hint
    } else if inside(secant) {
        secant
    } else {
        0.5 * (lo + hi)
    };
    // Orient so that f(lo) < 0.
    if flo > 0.0 {
        std::mem::swap(&mut lo, &mut hi);
    }
    let mut dx_old = (hi - lo).abs();
    let mut dx = dx_old;
    let (mut fx, mut dfx, mut ddfx) = f(x);
    for _ in 0..MAX_STEPS {
        if fx == 0.0 || fx.abs() <= acc.noise {
            return x;
        }
        let out = ((x - hi) * dfx - fx) * ((x - lo) * dfx - fx) > 0.0;
        if out || (2.0 * fx).abs() > (dx_old * dfx).abs() {
            dx_old = dx;
            dx = 0.5 * (hi - lo);
            x = lo + dx;
            if dx.abs() <= 0.5 * tol {
                return x;
            }
        } else {
            dx_old = dx;
            dx = fx / dfx;
            // Halley's correction of the Newton step (which stays inside the bracket), unless
            // it is large (far from the root, where the local quadratic model is no better
            // than the line) or leaves the bracket.
            let shrink = 1.0 - 0.5 * dx * ddfx / dfx;
            if (0.5..=2.0).contains(&shrink) {
                let to = x - dx / shrink;
                if to > lo.min(hi) && to < lo.max(hi) {
                    dx /= shrink;
                }
            }
            // A step below the tolerance: the point it starts from, already evaluated (its
            // error is about the step), is returned, and the caller finds its value cached.
            if dx.abs() <= 0.5 * tol {
                return x;
            }
            x -= dx;
        }
        (fx, dfx, ddfx) = f(x);
        if fx < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
    }
    x
}

/// The derivative-free step of a bracketed solve, for functions with no derivative at hand:
/// ITP, *interpolate, truncate, project* (Oliveira and Takahashi, *An enhancement of the
/// bisection method average performance preserving minmax optimality*, ACM TOMS 47, 2020).
///
/// A stepper: the caller asks for the next point ([`Itp::next`]), evaluates it and reports
/// the value ([`Itp::update`]), so that it may do more between steps (try a root of its own,
/// carry along a second variable, stop by a test of its own).
///
/// **The step.** The regula falsi point of the bracket's ends, moved toward the midpoint by
/// `κ₁ w^κ₂` (`w` the width; this truncation keeps the secant from creeping along one end as
/// plain regula falsi does), then projected into the ball of radius `r = ε 2^(n_max − j) − w/2`
/// round the midpoint.
///
/// **Convergence and bound.** With `n_½ = ⌈log₂(w₀ / 2ε)⌉` and `n_max = n_½ + n₀`, the
/// projection keeps the bracket after `j` steps within `2ε 2^(n_max − j)`: the width is at
/// most `2ε` within `n_max` steps, never more than `n₀` steps beyond bisection. (The paper
/// proves superlinear convergence on a simple root for `κ₂ > 1` once the secant steps take
/// over; its speed here against Illinois is not yet measured on the workspace's functions.)
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Itp {
    /// The end where `f < 0`, and its value.
    neg: (f64, f64),
    /// The end where `f > 0`, and its value.
    pos: (f64, f64),
    /// `ε`: the half-width the projection aims at.
    eps: f64,
    /// `κ₁`, per unit of the first width.
    k1: f64,
    /// `n_max`: steps within which the width is at most `2ε`.
    n_max: i32,
    /// Steps taken.
    steps: i32,
}

/// `κ₁ w₀`: the truncation's scale against the first width (kurbo's and the paper's choice).
const ITP_K1: f64 = 0.2;

/// `n₀`: the steps ITP may take beyond bisection's count for its secant steps.
const ITP_SLACK: i32 = 1;

impl Itp {
    /// A stepper on `bracket`, whose end values `ends` have opposite signs (neither zero), to
    /// the parameter tolerance `tol` (the width it closes to within `n_max` steps).
    pub fn new((a, b): (f64, f64), (fa, fb): (f64, f64), tol: f64) -> Self {
        let (neg, pos) = if fa < 0.0 {
            ((a, fa), (b, fb))
        } else {
            ((b, fb), (a, fa))
        };
        let width = (b - a).abs();
        let eps = 0.5 * tol.max(f64::MIN_POSITIVE);
        let halvings = (width / (2.0 * eps)).log2().ceil().max(0.0);
        Self {
            neg,
            pos,
            eps,
            k1: ITP_K1 / width,
            n_max: halvings.min(f64::from(i32::MAX / 2)) as i32 + ITP_SLACK,
            steps: 0,
        }
    }

    /// The bracket's ends in increasing order, with their values.
    pub fn ends(&self) -> ((f64, f64), (f64, f64)) {
        if self.neg.0 < self.pos.0 {
            (self.neg, self.pos)
        } else {
            (self.pos, self.neg)
        }
    }

    /// The width of the bracket.
    pub fn width(&self) -> f64 {
        (self.pos.0 - self.neg.0).abs()
    }

    /// The next point to evaluate, strictly inside the bracket unless its ends are
    /// neighbouring doubles (then `None`: it cannot shrink further).
    pub fn next(&self) -> Option<f64> {
        let ((a, fa), (b, fb)) = self.ends();
        let w = b - a;
        let half = a + 0.5 * w;
        // Interpolate: regula falsi.
        let falsi = (fb * a - fa * b) / (fb - fa);
        // Truncate: toward the midpoint by κ₁ w².
        let toward = if half >= falsi { 1.0 } else { -1.0 };
        let delta = self.k1 * w * w;
        let truncated = if delta <= (half - falsi).abs() {
            falsi + toward * delta
        } else {
            half
        };
        // Project: within r of the midpoint.
        let r = (self.eps * 2f64.powi(self.n_max - self.steps) - 0.5 * w).max(0.0);
        let x = if (truncated - half).abs() <= r {
            truncated
        } else {
            half - toward * r
        };
        // (NaN values, from NaN ends, take the midpoint.)
        let x = if x > a && x < b { x } else { half };
        (x > a && x < b).then_some(x)
    }

    /// Takes `f(x) = fx` into the bracket: `x` replaces the end of its sign (`fx` should not
    /// be 0: that is a root).
    pub fn update(&mut self, x: f64, fx: f64) {
        if fx < 0.0 {
            self.neg = (x, fx);
        } else {
            self.pos = (x, fx);
        }
        self.steps += 1;
    }
}

/// The root of `f` in `bracket` without derivatives, where the end values `ends` have
/// opposite signs (or one is zero), by [`Itp`]: to a width of `acc.tol` within about `n_max`
/// evaluations (one or two beyond bisection's, the second for the rounding of the widths),
/// stopping early where `|f| ≤ acc.noise`.
/// Returns the end of the final bracket with the smaller `|f|`.
///
/// ```
/// use numeric::solve::{bracketed_free, Accuracy};
/// let f = |x: f64| x.cos() - x;
/// let x = bracketed_free(f, (0.0, 1.0), (f(0.0), f(1.0)), Accuracy::param(1e-14));
/// assert!((x - 0.739_085_133_215_160_6).abs() < 1e-14);
/// ```
pub fn bracketed_free(
    mut f: impl FnMut(f64) -> f64,
    bracket: (f64, f64),
    (flo, fhi): (f64, f64),
    acc: Accuracy,
) -> f64 {
    if flo == 0.0 {
        return bracket.0;
    }
    if fhi == 0.0 {
        return bracket.1;
    }
    let mut itp = Itp::new(bracket, (flo, fhi), acc.tol);
    while itp.width() > acc.tol {
        let Some(x) = itp.next() else { break };
        let fx = f(x);
        if fx == 0.0 || fx.abs() <= acc.noise {
            return x;
        }
        itp.update(x, fx);
    }
    let ((a, fa), (b, fb)) = itp.ends();
    if fa.abs() <= fb.abs() {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The coefficients `c₀..c₃` of the cubic whose upper three are `upper` and which vanishes
    /// at `x0`.
    fn with_root(upper: [f64; 3], x0: f64) -> [f64; 4] {
        let [c1, c2, c3] = upper;
        [-((c3 * x0 + c2) * x0 + c1) * x0, c1, c2, c3]
    }

    /// `f(x) = Σ cₖ xᵏ` (degree 3) with its first two derivatives.
    fn cubic(c: [f64; 4]) -> impl Fn(f64) -> (f64, f64, f64) {
        move |x| {
            let f = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
            let d = (3.0 * c[3] * x + 2.0 * c[2]) * x + c[1];
            (f, d, 6.0 * c[3] * x + 2.0 * c[2])
        }
    }

    /// Newton's step only: the second derivative withheld.
    fn newton_only(f: impl Fn(f64) -> (f64, f64, f64)) -> impl Fn(f64) -> (f64, f64, f64) {
        move |x| {
            let (v, d, _) = f(x);
            (v, d, f64::NAN)
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 50000, max_global_rejects: 100_000, ..ProptestConfig::default() })]

        /// On any bracket of a random cubic (one, two or three roots inside), the solve
        /// returns a point where the sign changes within the tolerance, inside the bracket,
        /// from any hint, with Halley's step and with Newton's.
        #[test]
        fn lands_on_a_sign_change(
            c in proptest::array::uniform3(-2.0f64..2.0),
            lo in -2.0f64..0.0,
            hi in 0.0f64..2.0,
            at in 0.0f64..1.0,
            hint in -3.0f64..3.0,
        ) {
            // A root inside the bracket (the sign may still not change: two more).
            let c = with_root(c, lo + at * (hi - lo));
            let f = cubic(c);
            let (flo, fhi) = (f(lo).0, f(hi).0);
            prop_assume!((flo < 0.0) != (fhi < 0.0) && flo != 0.0 && fhi != 0.0);
            let tol = 1e-12;
            let acc = Accuracy::param(tol).hint(hint);
            let by_halley = bracketed(&f, (lo, hi), (flo, fhi), acc);
            let by_newton = bracketed(newton_only(&f), (lo, hi), (flo, fhi), acc);
            for (k, x) in [by_halley, by_newton].into_iter().enumerate() {
                prop_assert!(x >= lo && x <= hi, "{x} outside [{lo}, {hi}]");
                let (a, b) = (f((x - tol).max(lo)).0, f((x + tol).min(hi)).0);
                let scale = c.iter().map(|v| v.abs()).sum::<f64>();
                prop_assert!((a < 0.0) != (b < 0.0) || f(x).0.abs() <= 1e-14 * scale,
                    "solver {k}: no sign change at {x}: {a} {b}");
            }
        }

        /// The same on an oscillating function, where the steps overshoot most: the solve
        /// never leaves the bracket, and ends on one of its sign changes.
        #[test]
        fn stays_in_the_bracket(
            k in 1.0f64..30.0,
            phase in 0.0f64..6.3,
            c in -3.0f64..3.0,
            lo in -2.0f64..0.0,
            hi in 0.0f64..2.0,
            hint in -2.0f64..2.0,
        ) {
            // An oscillation on a tilted exponential (the steps overshoot on its flat side).
            let f = |x: f64| {
                let (s, co) = (k * x + phase).sin_cos();
                let e = (c * x).exp();
                (s + e - 1.0, k * co + c * e, -k * k * s + c * c * e)
            };
            let (flo, fhi) = (f(lo).0, f(hi).0);
            prop_assume!((flo < 0.0) != (fhi < 0.0) && flo != 0.0 && fhi != 0.0);
            let tol = 1e-12;
            let acc = Accuracy::param(tol).hint(hint);
            let by_halley = bracketed(f, (lo, hi), (flo, fhi), acc);
            let by_newton = bracketed(newton_only(f), (lo, hi), (flo, fhi), acc);
            for (k, x) in [by_halley, by_newton].into_iter().enumerate() {
                prop_assert!(x >= lo && x <= hi, "solver {k}: {x} outside [{lo}, {hi}]");
                let (a, b) = (f((x - tol).max(lo)).0, f((x + tol).min(hi)).0);
                prop_assert!((a < 0.0) != (b < 0.0) || f(x).0.abs() <= 1e-14,
                    "solver {k}: no sign change at {x}: {a} {b}");
            }
        }

        /// From a start within a tenth of the bracket of a simple root, Halley's iteration
        /// reaches the tolerance in at most four evaluations (the last one confirms) and
        /// Newton's in at most six.
        #[test]
        fn halley_converges_cubically(
            root in -1.0f64..1.0,
            slope in 0.5f64..2.0,
            curve in proptest::array::uniform2(-0.5f64..0.5),
            off in -0.1f64..0.1,
        ) {
            // (x − root)(slope + curve₀ (x − root) + curve₁ (x − root)²): monotone on the
            // bracket [root − 0.5, root + 0.5].
            let g = move |x: f64| {
                let y = x - root;
                let f = y * (slope + y * (curve[0] + y * curve[1]));
                let d = slope + y * (2.0 * curve[0] + 3.0 * y * curve[1]);
                (f, d, 2.0 * curve[0] + 6.0 * y * curve[1])
            };
            let (lo, hi) = (root - 0.5, root + 0.5);
            let ends = (g(lo).0, g(hi).0);
            let acc = Accuracy::param(1e-12).hint(root + off);
            let count = std::cell::Cell::new(0);
            let x = bracketed(|x| { count.set(count.get() + 1); g(x) }, (lo, hi), ends, acc);
            testkit::prop_assert_near!(x, root, 1e-12);
            prop_assert!(count.get() <= 4, "{} evaluations", count.get());
            count.set(0);
            let x = bracketed(|x| { count.set(count.get() + 1); newton_only(g)(x) },
                (lo, hi), ends, acc);
            testkit::prop_assert_near!(x, root, 1e-12);
            prop_assert!(count.get() <= 6, "{} evaluations", count.get());
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: 20000, max_global_rejects: 100_000, ..ProptestConfig::default()
        })]

        /// Without derivatives, on the same random cubics as Newton's: the bracket closes on
        /// a sign change within the tolerance, never using more evaluations than bisection
        /// plus two (`n₀` and the rounding of the widths); and on a simple root it agrees with
        /// Newton's solve (the independent method).
        #[test]
        fn itp_closes_within_the_bisection_bound(
            c in proptest::array::uniform3(-2.0f64..2.0),
            lo in -2.0f64..0.0,
            hi in 0.0f64..2.0,
            at in 0.0f64..1.0,
        ) {
            let c = with_root(c, lo + at * (hi - lo));
            let f = cubic(c);
            let (flo, fhi) = (f(lo).0, f(hi).0);
            prop_assume!((flo < 0.0) != (fhi < 0.0) && flo != 0.0 && fhi != 0.0);
            let tol = 1e-12;
            let count = std::cell::Cell::new(0);
            let x = bracketed_free(|x| { count.set(count.get() + 1); f(x).0 }, (lo, hi),
                (flo, fhi), Accuracy::param(tol));
            prop_assert!(x >= lo && x <= hi);
            let (a, b) = (f((x - tol).max(lo)).0, f((x + tol).min(hi)).0);
            let scale = c.iter().map(|v| v.abs()).sum::<f64>();
            prop_assert!((a < 0.0) != (b < 0.0) || f(x).0.abs() <= 1e-14 * scale,
                "no sign change at {x}: {a} {b}");
            let bisections = ((hi - lo) / tol).log2().ceil() as usize;
            prop_assert!(count.get() <= bisections + 2, "{} > {bisections} + 2", count.get());
            let by_newton = bracketed(&f, (lo, hi), (flo, fhi), Accuracy::param(tol));
            // A simple root (a clear slope): the two agree, and ITP is superlinear there.
            let slope = f(by_newton).1.abs();
            let sign = f(lo).1.signum();
            if slope > 1e-2 * scale && f(lo).0.abs().min(f(hi).0.abs()) > 1e-3 * scale
                && (0..=256).all(|i| {
                    let d = f(lo + (hi - lo) * i as f64 / 256.0).1;
                    d * sign > 1e-2 * scale
                }) {
                prop_assert!((x - by_newton).abs() <= 4.0 * tol, "{x} vs {by_newton}");
            }
        }
    }

    /// The noise stop: where |f| falls to the noise the point is returned at once.
    #[test]
    fn stops_at_the_noise_level() {
        let f = |x: f64| (x - 0.3, 1.0, 0.0);
        let calls = std::cell::Cell::new(0);
        let x = bracketed(
            |x| {
                calls.set(calls.get() + 1);
                f(x)
            },
            (0.0, 1.0),
            (-0.3, 0.7),
            Accuracy::param(1e-15).noise(0.5),
        );
        assert_eq!(calls.get(), 1);
        testkit::assert_near!(x, 0.3, 0.5);
    }
}
