//! The one two-dimensional Newton's method: a root of a map `F: X → ℝ²` from a start near it,
//! on `nalgebra`'s fixed-size [`Matrix2`] and [`Vector2`] (nothing is allocated).
//!
//! Each iteration linearises `F` at the iterate `x` (its value `F(x)` and Jacobian `J(x)`,
//! from the caller) and solves `J δ = F` by Cramer's rule ([`newton_step`]); the next iterate
//! is `x − δ`, or, with [`Newton2::halvings`], `x − δ/2ᵏ` for the least `k` that lowers the
//! largest component of `F` (a damped step). The iterate need not be a point of the plane:
//! the caller moves it by the step ([`newton2`]'s `advance`), so a parameter that wraps or changes chart
//! (a foot passing a joint) is moved its own way.
//!
//! **Convergence.** Where `J` is regular at a simple root `x*` and Lipschitz near it, the
//! iterates from a start close enough converge quadratically: `‖x − x*‖` is about squared at
//! each step (Kantorovich), so a start with one correct digit reaches the rounding level in
//! about six steps. A Jacobian only approximated (by differences) converges linearly, at the
//! rate of its relative error. Far from a root nothing is promised; the damped step then only
//! keeps the residual from growing.
//!
//! **Stopping rule.** The solve stops, in this order of tests per iteration:
//! - *converged* where the residual test `‖F(x)‖ ≤ Newton2::residual` holds (Euclidean; 0: only at an exact zero), or
//!   where the caller's `judge` says so after a step (its step test: typically the step is
//!   down to the rounding level of the iterate or of `F`);
//! - *singular* where `J` is singular to the tolerance [`Newton2::singular`]
//!   (`|det J| ≤ singular · ‖J e₁‖ ‖J e₂‖`, and always where `det J` is 0 or not finite);
//! - *abandoned* where the `judge` rejects the step (typically: it left the region of the
//!   search);
//! - *exhausted* after [`Newton2::max_steps`] linearisations, the iteration bound.
//!
//! Every outcome carries the last iterate.
//!
//! **The polish, keeping the best point met.** [`polish`] is the same iteration for a finish
//! from a start already near a root, where rounding sets the floor: the caller's
//! linearisation also measures a residual of its own (any measure that is 0 at a root, such
//! as sines of angles that a root makes 0), and the iteration keeps the iterate of least
//! residual met and stops as soon as the residual rises. At the rounding floor a Newton step
//! divides noise by noise; the iterate it reaches may be worse than the one it left, and the
//! polish returns the one it left. Its convergence is Newton's (quadratic near a simple root);
//! its bound is [`Newton2::max_steps`] linearisations, each measuring the end of the step
//! before it. Its steps are undamped (`halvings` is not used: the kept best is its guard).
//! It stops, in this order of tests per linearisation: where the residual rose (the best is
//! the iterate before); where the residual test holds; where `J` is singular; where the judge
//! says converged (the step's start is the answer: its end was never measured) or abandons
//! the step (the step's end is returned, as [`newton2`] does); after the bound (the best).

pub use nalgebra::{Matrix2, Vector2};

/// The limits of one [`newton2`] solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Newton2 {
    /// The iteration bound: linearisations of `F` before the solve gives up.
    pub max_steps: usize,
    /// The residual test: converged where `‖F(x)‖` (Euclidean: a gap between two points is
    /// tested as its length) is at most this (0: only an exact zero).
    pub residual: f64,
    /// `J` is singular where `|det J| ≤ singular · ‖J e₁‖₂ ‖J e₂‖₂` (0: only where `det J` is
    /// 0 or not finite).
    pub singular: f64,
    /// Halvings of a step that does not lower `‖F‖∞` (the largest component: each component's progress counts, where
    /// the Euclidean norm's descent crawls while one of them is far from zero) before it is taken anyway (0: the full
    /// step, undamped).
    pub halvings: u32,
}

impl Newton2 {
    /// Undamped Newton with no residual test, singular only at a zero determinant, for at
    /// most `max_steps` linearisations.
    pub const fn steps(max_steps: usize) -> Self {
        Self {
            max_steps,
            residual: 0.0,
            singular: 0.0,
            halvings: 0,
        }
    }
}

/// One step of [`newton2`], shown to its `judge`.
#[derive(Debug, Clone, Copy)]
pub struct Iterate<X> {
    /// The iterate the step starts from.
    pub from: X,
    /// The iterate it reaches.
    pub to: X,
    /// The step taken: `to` is `from` moved by `−step`.
    pub step: Vector2<f64>,
    /// `F(from)`.
    pub value: Vector2<f64>,
    /// `J(from)`.
    pub jacobian: Matrix2<f64>,
}

/// What a `judge` makes of a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepVerdict {
    /// Go on from the step's end.
    Continue,
    /// The step's end is the root.
    Converged,
    /// Give up: the step's end is of no use (it left the region of the search).
    Abandon,
}

/// How a [`newton2`] solve ended, each with the last iterate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Outcome<X> {
    /// The residual test or the judge's step test held.
    Converged(X),
    /// The Jacobian was singular at the iterate.
    Singular(X),
    /// The judge rejected a step; the iterate is the step's end.
    Abandoned(X),
    /// The iteration bound was reached.
    Exhausted(X),
}

impl<X> Outcome<X> {
    /// The iterate of a converged solve.
    pub fn converged(self) -> Option<X> {
        match self {
            Outcome::Converged(x) => Some(x),
            _ => None,
        }
    }
}

/// The Newton step `δ = J⁻¹ F` by Cramer's rule, `None` where `J` is singular to the relative
/// tolerance `singular` ([`Newton2::singular`]).
#[inline]
pub fn newton_step(
    value: Vector2<f64>,
    jacobian: Matrix2<f64>,
    singular: f64,
) -> Option<Vector2<f64>> {
    let j = jacobian;
    let det = j[(0, 0)] * j[(1, 1)] - j[(0, 1)] * j[(1, 0)];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    if singular > 0.0 && det.abs() <= singular * j.column(0).norm() * j.column(1).norm() {
        return None;
    }
    Some(Vector2::new(
        (value[0] * j[(1, 1)] - j[(0, 1)] * value[1]) / det,
        (j[(0, 0)] * value[1] - value[0] * j[(1, 0)]) / det,
    ))
}

/// A root of `F` by Newton's method from `start` (the module's documentation gives its
/// convergence and stopping rule). `linearize(x)` returns `(F(x), J(x))`; `advance(x, δ)`
/// moves an iterate by `−δ`; `judge` sees each step taken and says whether to go on. At most
/// [`Newton2::max_steps`] linearisations, plus those of the damping's trial points.
///
/// ```
/// use nalgebra::{Matrix2, Vector2};
/// use numeric::newton2::{newton2, Newton2, StepVerdict};
/// // The unit circle meets the line y = x at (√½, √½).
/// let f = |p: &Vector2<f64>| {
///     let value = Vector2::new(p.x * p.x + p.y * p.y - 1.0, p.y - p.x);
///     (value, Matrix2::new(2.0 * p.x, 2.0 * p.y, -1.0, 1.0))
/// };
/// let limits = Newton2 { residual: 1e-15, ..Newton2::steps(20) };
/// let root = newton2(Vector2::new(1.0, 0.5), limits, f, |x, d| x - d, |_| StepVerdict::Continue)
///     .converged()
///     .unwrap();
/// assert!((root.x - 0.5f64.sqrt()).abs() < 1e-15 && (root.y - root.x).abs() < 1e-15);
/// ```
pub fn newton2<X: Copy>(
    start: X,
    limits: Newton2,
    mut linearize: impl FnMut(&X) -> (Vector2<f64>, Matrix2<f64>),
    mut advance: impl FnMut(&X, Vector2<f64>) -> X,
    mut judge: impl FnMut(&Iterate<X>) -> StepVerdict,
) -> Outcome<X> {
    let mut x = start;
    let mut steps = 0;
    // A linearisation already made (at a damping's accepted trial point).
    let mut known: Option<(Vector2<f64>, Matrix2<f64>)> = None;
    while steps < limits.max_steps {
        let (value, jacobian) = match known.take() {
            Some(at_x) => at_x,
            None => {
                steps += 1;
                linearize(&x)
            }
        };
        let residual = value.norm();
        if residual <= limits.residual {
            return Outcome::Converged(x);
        }
        let Some(mut step) = newton_step(value, jacobian, limits.singular) else {
            return Outcome::Singular(x);
        };
        let mut to = advance(&x, step);
        // The damped step: halved while it raises the residual.
        for _ in 0..limits.halvings {
            if steps >= limits.max_steps {
                break;
            }
            steps += 1;
            let at_to = linearize(&to);
            if at_to.0.amax() < value.amax() {
                known = Some(at_to);
                break;
            }
            step *= 0.5;
            to = advance(&x, step);
        }
        let verdict = judge(&Iterate {
            from: x,
            to,
            step,
            value,
            jacobian,
        });
        x = to;
        match verdict {
            StepVerdict::Continue => {}
            StepVerdict::Converged => return Outcome::Converged(x),
            StepVerdict::Abandon => return Outcome::Abandoned(x),
        }
    }
    if let Some((value, _)) = known {
        if value.norm() <= limits.residual {
            return Outcome::Converged(x);
        }
    }
    Outcome::Exhausted(x)
}

/// How a [`polish`] ended. Every outcome but [`Polished::Abandoned`] carries the best
/// iterate met: the one of least residual among those linearised.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Polished<X> {
    /// The residual test held at the best iterate, or the judge's step test on the step from
    /// it.
    Converged(X),
    /// The residual rose at the end of the step from the best iterate.
    Rose(X),
    /// The Jacobian was singular at the best iterate.
    Singular(X),
    /// The judge rejected a step; the iterate is the step's end.
    Abandoned(X),
    /// The iteration bound was reached.
    Exhausted(X),
}

impl<X> Polished<X> {
    /// The best iterate met, unless the judge abandoned the polish.
    pub fn best(self) -> Option<X> {
        match self {
            Polished::Converged(x)
            | Polished::Rose(x)
            | Polished::Singular(x)
            | Polished::Exhausted(x) => Some(x),
            Polished::Abandoned(_) => None,
        }
    }
}

/// Newton's finish from `start`, keeping the best iterate met (the module's documentation
/// gives its stopping rule). `linearize(x)` returns `(F(x), J(x), residual(x))`, the residual
/// the caller's own measure of how far `x` is from a root; `advance(x, δ)` moves an iterate
/// by `−δ`; `judge` sees each step and says whether to go on. At most
/// [`Newton2::max_steps`] linearisations; [`Newton2::halvings`] is not used.
///
/// ```
/// use nalgebra::{Matrix2, Vector2};
/// use numeric::newton2::{polish, Newton2, StepVerdict};
/// // The unit circle meets the line y = x at (√½, √½); the residual is the largest component.
/// let f = |p: &Vector2<f64>| {
///     let value = Vector2::new(p.x * p.x + p.y * p.y - 1.0, p.y - p.x);
///     (value, Matrix2::new(2.0 * p.x, 2.0 * p.y, -1.0, 1.0), value.amax())
/// };
/// let root = polish(Vector2::new(0.8, 0.6), Newton2::steps(20), f, |x, d| x - d,
///     |_| StepVerdict::Continue)
///     .best()
///     .unwrap();
/// assert!((root.x - 0.5f64.sqrt()).abs() < 1e-15 && (root.y - root.x).abs() < 1e-15);
/// ```
pub fn polish<X: Copy>(
    start: X,
    limits: Newton2,
    mut linearize: impl FnMut(&X) -> (Vector2<f64>, Matrix2<f64>, f64),
    mut advance: impl FnMut(&X, Vector2<f64>) -> X,
    mut judge: impl FnMut(&Iterate<X>) -> StepVerdict,
) -> Polished<X> {
    debug_assert_eq!(limits.halvings, 0, "the polish does not damp its steps");
    let mut x = start;
    // The best iterate and its residual: the residual falls at every step taken, so the best
    // is the last iterate measured (a NaN residual is kept: no test can tell it is worse).
    let (mut best, mut least) = (start, f64::INFINITY);
    for _ in 0..limits.max_steps {
        let (value, jacobian, residual) = linearize(&x);
        if residual > least {
            return Polished::Rose(best);
        }
        (best, least) = (x, residual);
        if residual <= limits.residual {
            return Polished::Converged(x);
        }
        let Some(step) = newton_step(value, jacobian, limits.singular) else {
            return Polished::Singular(x);
        };
        let to = advance(&x, step);
        match judge(&Iterate {
            from: x,
            to,
            step,
            value,
            jacobian,
        }) {
            StepVerdict::Continue => x = to,
            StepVerdict::Converged => return Polished::Converged(x),
            StepVerdict::Abandon => return Polished::Abandoned(to),
        }
    }
    Polished::Exhausted(best)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The plain iteration on points of the plane.
    fn minus(x: &Vector2<f64>, d: Vector2<f64>) -> Vector2<f64> {
        x - d
    }

    /// `F(x) = A x + q (x ⊙ x) − b`, a linear map bent by a small quadratic term, with its
    /// Jacobian.
    fn bent(
        a: Matrix2<f64>,
        q: f64,
        b: Vector2<f64>,
    ) -> impl Fn(&Vector2<f64>) -> (Vector2<f64>, Matrix2<f64>) {
        move |x| {
            let value = a * x + q * x.component_mul(x) - b;
            let jacobian = a + Matrix2::from_diagonal(&(2.0 * q * x));
            (value, jacobian)
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(5000))]

        /// The Cramer step solves `J δ = F` as LU with partial pivoting does (nalgebra's
        /// general solver), to the rounding the condition of `J` allows.
        #[test]
        fn the_step_solves_the_linear_system(
            m in proptest::array::uniform4(-4.0f64..4.0),
            v in proptest::array::uniform2(-4.0f64..4.0),
        ) {
            let j = Matrix2::new(m[0], m[1], m[2], m[3]);
            let f = Vector2::new(v[0], v[1]);
            let det = j.determinant();
            prop_assume!(det.abs() > 1e-3);
            let step = newton_step(f, j, 0.0).unwrap();
            let lu = j.lu().solve(&f).unwrap();
            let cond = j.norm() * j.try_inverse().unwrap().norm();
            prop_assert!((step - lu).amax() <= 1e-14 * cond * (1.0 + lu.amax()), "{step} vs {lu}");
        }

        /// On a linear map bent a little, from a start anywhere in the unit box, Newton's
        /// iteration reaches the root that the undamped, unbent linear solve and a dense
        /// fixed-point check agree on: the residual at the result is at the rounding level,
        /// within the iteration bound, and (bent by nothing) in one step.
        #[test]
        fn converges_to_the_root_of_a_bent_linear_map(
            turns in proptest::array::uniform2(0.0f64..6.3),
            sizes in proptest::array::uniform2(0.5f64..2.0),
            flip in proptest::bool::ANY,
            root in proptest::array::uniform2(-1.0f64..1.0),
            start in proptest::array::uniform2(-1.0f64..1.0),
            q in -0.05f64..0.05,
        ) {
            // A = U Σ V (rotations, one perhaps a reflection): well conditioned, its smallest
            // singular value at least 0.5.
            let rotation = |a: f64| Matrix2::new(a.cos(), -a.sin(), a.sin(), a.cos());
            let sign = if flip { -1.0 } else { 1.0 };
            let a = rotation(turns[0])
                * Matrix2::new(sizes[0], 0.0, 0.0, sign * sizes[1])
                * rotation(turns[1]);
            let svd = a.svd(false, false);
            let root = Vector2::new(root[0], root[1]);
            let b = a * root + q * root.component_mul(&root);
            let f = bent(a, q, b);
            let limits = Newton2 { residual: 1e-13, ..Newton2::steps(30) };
            let start = Vector2::new(start[0], start[1]);
            let calls = std::cell::Cell::new(0);
            let out = newton2(start, limits, |x| { calls.set(calls.get() + 1); f(x) }, minus,
                |_| StepVerdict::Continue);
            let x = out.converged().unwrap();
            prop_assert!(f(&x).0.amax() <= 1e-13);
            // The root is unique near `root` (the bend is small against A): found it.
            prop_assert!((x - root).amax() <= 1e-12 / svd.singular_values.min() * 4.0,
                "{x} vs {root}");
            // Quadratic convergence: a handful of linearisations.
            prop_assert!(calls.get() <= 8, "{} linearisations", calls.get());
            if q == 0.0 {
                prop_assert!(calls.get() <= 2);
            }
        }

        /// The damped step never raises the residual where a lower one lies along the step
        /// (a descent direction of ‖F‖² for regular J): on the arctangent, whose undamped
        /// iteration diverges from |x| > 1.39, the damped one converges from anywhere.
        #[test]
        fn the_damped_step_converges_where_the_full_one_diverges(
            start in proptest::array::uniform2(-20.0f64..20.0),
            scale in 0.5f64..2.0,
        ) {
            let f = |x: &Vector2<f64>| {
                let value = Vector2::new(x[0].atan(), (scale * x[1]).atan());
                let jacobian = Matrix2::new(
                    1.0 / (1.0 + x[0] * x[0]), 0.0,
                    0.0, scale / (1.0 + scale * scale * x[1] * x[1]),
                );
                (value, jacobian)
            };
            let start = Vector2::new(start[0], start[1]);
            let limits = Newton2 { residual: 1e-14, halvings: 40, ..Newton2::steps(200) };
            let mut residuals = Vec::new();
            let out = newton2(start, limits, f, minus, |it| {
                residuals.push(it.value.amax());
                StepVerdict::Continue
            });
            let x = out.converged().unwrap();
            prop_assert!(x.amax() <= 1e-13, "{x}");
            prop_assert!(residuals.windows(2).all(|w| w[1] < w[0]), "{residuals:?}");
        }
    }

    /// The judge's verdicts end the solve, each with the step's end; a singular Jacobian and
    /// the iteration bound end it with the iterate where they were met.
    #[test]
    fn every_outcome_carries_its_iterate() {
        let f = bent(Matrix2::identity(), 0.0, Vector2::new(1.0, 2.0));
        let start = Vector2::zeros();
        let root = Vector2::new(1.0, 2.0);
        let limits = Newton2::steps(5);
        let converged = newton2(start, limits, &f, minus, |_| StepVerdict::Converged);
        assert_eq!(converged, Outcome::Converged(root));
        let abandoned = newton2(start, limits, &f, minus, |_| StepVerdict::Abandon);
        assert_eq!(abandoned, Outcome::Abandoned(root));
        let flat = |_: &Vector2<f64>| (Vector2::new(1.0, 1.0), Matrix2::new(1.0, 2.0, 2.0, 4.0));
        let singular = newton2(start, limits, flat, minus, |_| StepVerdict::Continue);
        assert_eq!(singular, Outcome::Singular(start));
        let count = std::cell::Cell::new(0);
        let far = |x: &Vector2<f64>| {
            count.set(count.get() + 1);
            (Vector2::new(1.0, 1.0) + 0.0 * x, Matrix2::identity())
        };
        let exhausted = newton2(start, limits, far, minus, |_| StepVerdict::Continue);
        assert_eq!(exhausted, Outcome::Exhausted(Vector2::new(-5.0, -5.0)));
        assert_eq!(count.get(), 5);
        // Near-singular to a relative tolerance.
        let thin = |_: &Vector2<f64>| {
            (
                Vector2::new(1.0, 1.0),
                Matrix2::new(1.0, 1.0, 1.0, 1.0 + 1e-12),
            )
        };
        let loose = Newton2 {
            singular: 1e-9,
            ..limits
        };
        assert!(matches!(
            newton2(start, loose, thin, minus, |_| StepVerdict::Converged),
            Outcome::Singular(_)
        ));
        assert!(matches!(
            newton2(start, limits, thin, minus, |_| StepVerdict::Converged),
            Outcome::Converged(_)
        ));
    }

    /// The circle of radius `radius` about the origin and the line through it at angle `phi`,
    /// with a deterministic noise of amplitude `noise` on the first component (a residual
    /// with a rounding floor); the residual is the largest component.
    fn circle_and_line(
        radius: f64,
        phi: f64,
        noise: f64,
    ) -> impl Fn(&Vector2<f64>) -> (Vector2<f64>, Matrix2<f64>, f64) {
        let (sin, cos) = phi.sin_cos();
        move |p| {
            let wobble = noise * (1e9 * (p.x + 2.0 * p.y)).sin();
            let value = Vector2::new(
                p.norm_squared() - radius * radius + wobble,
                cos * p.y - sin * p.x,
            );
            let jacobian = Matrix2::new(2.0 * p.x, 2.0 * p.y, -sin, cos);
            (value, jacobian, value.amax())
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(5000))]

        /// From a start within a fifth of the radius of where a line through the centre meets
        /// a circle, the polish reaches the closed-form point to rounding (without noise) or
        /// to the noise's reach (with it), and what it returns is the least residual it
        /// measured, every residual before it no lower than the one after.
        #[test]
        fn polish_keeps_the_least_residual_and_reaches_the_closed_form(
            radius in 0.5f64..2.0,
            phi in 0.0f64..6.3,
            off in proptest::array::uniform2(-0.14f64..0.14),
            noise in prop_oneof![Just(0.0), Just(1e-10)],
        ) {
            let f = circle_and_line(radius, phi, noise);
            let root = Vector2::new(radius * phi.cos(), radius * phi.sin());
            let start = root + radius * Vector2::new(off[0], off[1]);
            let mut measured = Vec::new();
            let out = polish(start, Newton2::steps(30), |x| {
                let l = f(x);
                measured.push((*x, l.2));
                l
            }, minus, |_| StepVerdict::Continue);
            let best = out.best().unwrap();
            let least = measured.iter().map(|m| m.1).fold(f64::INFINITY, f64::min);
            prop_assert_eq!(f(&best).2, least, "{:?}", out);
            // The residuals fall until the last one measured, which may have risen.
            let kept = &measured[..measured.len() - usize::from(matches!(out, Polished::Rose(_)))];
            prop_assert!(kept.windows(2).all(|w| w[1].1 <= w[0].1), "{measured:?}");
            prop_assert!(kept.last().unwrap().0 == best);
            // The line's residual is a distance, the circle's one a gap of squares: the point
            // is within a few units of rounding of the root, or of the noise over 2 radius.
            let reach = crate::rounding::ulps(8.0) * radius + 4.0 * noise / radius;
            prop_assert!((best - root).amax() <= reach, "{best} vs {root} ({out:?})");
        }
    }

    /// Each way a polish ends: the rise of the residual returns the iterate before it; the
    /// judge's convergence returns the step's start; its rejection the step's end; the
    /// singular Jacobian and the bound the best iterate.
    #[test]
    fn every_polish_outcome_carries_its_iterate() {
        let start = Vector2::new(1.0, 1.0);
        let limits = Newton2::steps(5);
        // F(x) = x, the residual |x|∞ and, past the first step, a residual that rises.
        let linear = |x: &Vector2<f64>| (*x, Matrix2::identity(), x.amax());
        let rising = |x: &Vector2<f64>| (*x, Matrix2::identity(), 1.0 + x.amax());
        let halving = |x: &Vector2<f64>, d: Vector2<f64>| x - 0.5 * d;
        let go_on = |_: &Iterate<Vector2<f64>>| StepVerdict::Continue;
        assert_eq!(
            polish(start, limits, linear, minus, go_on),
            Polished::Converged(Vector2::zeros())
        );
        let rose = polish(
            start,
            limits,
            |x: &Vector2<f64>| {
                let l = linear(x);
                (l.0, l.1, if x.amax() < 1.0 { 3.0 } else { 2.0 })
            },
            halving,
            go_on,
        );
        assert_eq!(rose, Polished::Rose(start));
        let converged = polish(start, limits, rising, halving, |_| StepVerdict::Converged);
        assert_eq!(converged, Polished::Converged(start));
        let abandoned = polish(start, limits, rising, halving, |_| StepVerdict::Abandon);
        assert_eq!(abandoned, Polished::Abandoned(Vector2::new(0.5, 0.5)));
        let flat = |_: &Vector2<f64>| {
            (
                Vector2::new(1.0, 1.0),
                Matrix2::new(1.0, 2.0, 2.0, 4.0),
                1.0,
            )
        };
        assert_eq!(
            polish(start, limits, flat, minus, go_on),
            Polished::Singular(start)
        );
        // Five linearisations, the residual falling: the fifth iterate measured is the best
        // (the step from it is taken but never measured).
        let exhausted = polish(start, limits, linear, halving, go_on);
        assert_eq!(
            exhausted,
            Polished::Exhausted(Vector2::new(1.0, 1.0) / 16.0)
        );
        assert_eq!(exhausted.best(), Some(Vector2::new(1.0, 1.0) / 16.0));
        assert_eq!(abandoned.best(), None);
    }
}
