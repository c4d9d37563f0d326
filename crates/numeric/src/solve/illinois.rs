//! The Illinois stepper: regula falsi on a bracket, for a sign change whose function has no
//! derivative at hand and whose caller does more between steps.

/// Regula falsi with the Illinois modification, as a stepper: the caller asks for the next
/// point ([`Illinois::next`]), evaluates it and reports the value ([`Illinois::update`]), and
/// may do more between steps (carry a second variable along with each end, try a root of its
/// own, stop by a test of its own).
///
/// **The step.** The secant point of the bracket's ends. When one end is kept twice in a row,
/// its value is halved (Illinois), so the secant stops creeping along the other end; every
/// fifth step is a plain halving, and a secant point that is not strictly inside the bracket
/// (rounding, a NaN) is replaced by the midpoint.
///
/// **Convergence and bound.** On a simple root of a smooth function the Illinois steps
/// converge superlinearly (order ≈ 1.44 per evaluation, Dowell & Jarratt 1971). The halving
/// every fifth step bounds the worst case: the width at least halves every five steps, so a
/// bracket of doubles closes within about 5 × 64 steps; the caller bounds its loop and stops
/// when the width is below its tolerance or [`Illinois::next`] finds no double inside.
///
/// Against [`super::Itp`], which bounds the steps to bisection's count plus one, this is the
/// faster one on the antipodal search's θ (measured there: the search was tuned on it), where
/// the caller stops early on a Newton step of its own.
///
/// ```
/// use numeric::solve::Illinois;
/// let f = |x: f64| x * x - 2.0;
/// let mut solve = Illinois::new((1.0, f(1.0)), (2.0, f(2.0)));
/// for _ in 0..100 {
///     let Some(x) = solve.next() else { break };
///     let fx = f(x);
///     if fx == 0.0 {
///         break;
///     }
///     solve.update(x, fx);
///     if solve.width() < 1e-15 {
///         break;
///     }
/// }
/// let ((a, _), (b, _)) = solve.ends();
/// assert!((a - 2f64.sqrt()).abs() < 1e-15 || (b - 2f64.sqrt()).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Illinois {
    /// The first end and its (possibly halved) value: the end whose sign is the first given.
    first: (f64, f64),
    /// The second end and its (possibly halved) value.
    second: (f64, f64),
    /// Which end the last step replaced.
    last: Option<End>,
    /// Steps taken.
    steps: usize,
}

/// One end of an [`Illinois`] bracket.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// The end whose value has the sign of the first end given.
    First,
    /// The other.
    Second,
}

/// Every this many steps, a plain halving: the bound on the worst case.
const HALVING_EVERY: usize = 5;

impl Illinois {
    /// A stepper on the bracket of `first` and `second`, each `(x, f(x))`, whose values have
    /// opposite signs.
    pub fn new(first: (f64, f64), second: (f64, f64)) -> Self {
        Self {
            first,
            second,
            last: None,
            steps: 0,
        }
    }

    /// The ends, as given (the first end keeps the first value's sign), with their values as
    /// the steps weighted them (halved where an end was kept twice).
    pub fn ends(&self) -> ((f64, f64), (f64, f64)) {
        (self.first, self.second)
    }

    /// The width of the bracket.
    pub fn width(&self) -> f64 {
        (self.second.0 - self.first.0).abs()
    }

    /// Steps taken.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// The next point to evaluate, strictly inside the bracket, or `None` when its ends are
    /// neighbouring doubles (it cannot shrink further).
    pub fn next(&self) -> Option<f64> {
        let ((s0, f0), (s1, f1)) = (self.first, self.second);
        let (lo, hi) = (s0.min(s1), s0.max(s1));
        let inside = |x: f64| x > lo && x < hi;
        let secant = if self.steps % HALVING_EVERY == HALVING_EVERY - 1 {
            0.5 * (s0 + s1)
        } else {
            (s0 * f1 - s1 * f0) / (f1 - f0)
        };
        if inside(secant) {
            return Some(secant);
        }
        let half = 0.5 * (s0 + s1);
        inside(half).then_some(half)
    }

    /// Takes `f(x) = fx` into the bracket (`fx` not 0: that is a root): `x` replaces the end
    /// of its sign, and the end kept twice in a row has its value halved. Returns the end
    /// replaced.
    pub fn update(&mut self, x: f64, fx: f64) -> End {
        self.steps += 1;
        if (fx < 0.0) == (self.first.1 < 0.0) {
            self.first = (x, fx);
            if self.last == Some(End::First) {
                self.second.1 *= 0.5;
            }
            self.last = Some(End::First);
            End::First
        } else {
            self.second = (x, fx);
            if self.last == Some(End::Second) {
                self.first.1 *= 0.5;
            }
            self.last = Some(End::Second);
            End::Second
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Steps until the width is below `tol`, or no double is inside; the final bracket.
    fn solve(f: impl Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> (usize, (f64, f64)) {
        let mut it = Illinois::new((a, f(a)), (b, f(b)));
        let mut evaluations = 0;
        while it.width() > tol && evaluations < 400 {
            let Some(x) = it.next() else { break };
            evaluations += 1;
            let fx = f(x);
            if fx == 0.0 {
                return (evaluations, (x, x));
            }
            it.update(x, fx);
        }
        let ((a, _), (b, _)) = it.ends();
        (evaluations, (a.min(b), a.max(b)))
    }

    proptest! {
        /// On a cubic with one root in the bracket (found independently by bisection to the
        /// last double), the bracket closes round that root, within bisection's worst case.
        #[test]
        fn closes_round_the_root(root in -2.0f64..2.0, c in 0.0f64..3.0, d in -1.0f64..1.0) {
            // (x − root)(x² + c x + c² + 1) has one real root (the quadratic has none).
            let q = |x: f64| x * x + c * x + c * c + 1.0 + d * d;
            let f = |x: f64| (x - root) * q(x);
            let (a, b) = (root - 3.0, root + 2.0);
            let (steps, (lo, hi)) = solve(f, a, b, 1e-12);
            prop_assert!(steps <= HALVING_EVERY * 64, "{steps} steps");
            // Bisection to the last double, as the independent answer.
            let (mut x0, mut x1) = (a, b);
            for _ in 0..200 {
                let m = 0.5 * (x0 + x1);
                if m <= x0 || m >= x1 { break; }
                if (f(m) < 0.0) == (f(x0) < 0.0) { x0 = m } else { x1 = m }
            }
            prop_assert!(lo <= x1 + 1e-15 && hi >= x0 - 1e-15, "[{lo}, {hi}] misses {x0}");
            prop_assert!(hi - lo <= 1e-12, "width {}", hi - lo);
        }
    }

    #[test]
    fn a_simple_root_takes_far_fewer_steps_than_bisection() {
        let (steps, (lo, hi)) = solve(|x| x.exp() - 3.0, 0.0, 4.0, 1e-13);
        assert!(hi - lo <= 1e-13 || lo == hi);
        // Bisection needs 46 halvings from a width of 4.
        assert!(steps <= 20, "{steps} steps");
    }

    #[test]
    fn the_kept_end_is_halved_and_neighbouring_doubles_stop_it() {
        let mut it = Illinois::new((0.0, -1.0), (1.0, 1.0));
        assert_eq!(it.update(0.25, -0.5), End::First);
        assert_eq!(it.update(0.3, -0.25), End::First);
        assert_eq!(it.ends().1, (1.0, 0.5));
        let next = 1.0f64.next_up();
        let stuck = Illinois::new((1.0, -1.0), (next, 1.0));
        assert_eq!(stuck.next(), None);
    }
}
