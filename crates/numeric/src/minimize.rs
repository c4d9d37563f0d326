//! The one bracketed minimisation of a scalar function of one variable, for the nearest points
//! and the deviations of the workspace: [`minimize`] closes a bracket round a local minimum
//! by parabolic steps safeguarded by golden sections, and [`polish`] finishes a minimum by
//! Newton's method on the derivative where one is at hand.
//!
//! **The bracket.** Three points `lo ≤ mid ≤ hi` with `f(mid) ≤ f(lo), f(hi)`: a local minimum
//! of a continuous `f` lies in `[lo, hi]` (at an end when `mid` is that end). Each step
//! evaluates one new point `w` inside and keeps a bracket: the lower of `w` and `mid` becomes
//! the middle, and the other one the end on its side.
//!
//! **The step.** The vertex of the parabola through the three points when it lies strictly
//! inside and at least [`Limits::parabola_min_move`] of the bracket's width away from `mid`
//! (a vertex next to `mid` says little: on a skewed minimum it sits beside the best sample
//! while the minimum lies farther off); else the golden section `(3 − √5)/2` of the wider
//! side, measured from `mid`.
//!
//! **Convergence and bound.** A golden step leaves at most `0.618` of the bracket's width
//! once `mid` sits at a golden section of it; parabolic steps converge superlinearly (order
//! about 1.3) on a smooth minimum with `f″ > 0`. Parabolic steps alone may creep, taking
//! slivers off one end, which the least move of a parabolic step
//! ([`Limits::parabola_min_move`], a tenth of the width, say) stops on smooth functions. The
//! search stops once the width is at most [`Limits::width`] (`closed`), after
//! [`Limits::max_steps`] evaluations (the bound), or where the function's caller breaks off
//! (`f` returns [`ControlFlow::Break`]).

use std::ops::ControlFlow;

/// The golden-section fraction `(3 − √5)/2`: the share of the wider side a golden step takes.
pub const GOLDEN: f64 = 0.381_966_011_250_105_1;

/// A point of the function: `(x, f(x))`.
pub type Sample = (f64, f64);

/// Three samples round a local minimum: `lo.0 ≤ mid.0 ≤ hi.0` and `mid.1 ≤ lo.1, hi.1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    /// The lower end.
    pub lo: Sample,
    /// The lowest sample so far.
    pub mid: Sample,
    /// The upper end.
    pub hi: Sample,
}

impl Bracket {
    /// The width `hi − lo`.
    pub fn width(&self) -> f64 {
        self.hi.0 - self.lo.0
    }
}

/// How far [`minimize`] closes its bracket, and how its steps are chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// The search stops once the bracket is at most this wide.
    pub width: f64,
    /// The bound: evaluations before the search stops, closed or not.
    pub max_steps: usize,
    /// A parabolic step nearer `mid` than this share of the width is replaced by a golden one.
    pub parabola_min_move: f64,
}

/// Where [`minimize`] stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Minimum {
    /// The last bracket; its `mid` is the lowest sample.
    pub bracket: Bracket,
    /// Whether the bracket closed to [`Limits::width`].
    pub closed: bool,
    /// `|f(w) − f(mid)|` of the last step (against the middle it was compared with): about
    /// what the search leaves unmeasured of the minimum's value. `None` without a step.
    pub last_change: Option<f64>,
}

/// Closes `bracket` round a local minimum of `f` (the module's documentation gives the step,
/// its convergence and the stopping rule). `f` may break off the search, with a value of its
/// own, after any evaluation.
///
/// ```
/// use numeric::minimize::{minimize, Bracket, Limits};
/// use std::ops::ControlFlow;
/// // The minimum of (x − 0.3)² + 1 on [0, 1], from its samples at 0, ½ and 1.
/// let f = |x: f64| (x - 0.3) * (x - 0.3) + 1.0;
/// let bracket = Bracket { lo: (0.0, f(0.0)), mid: (0.5, f(0.5)), hi: (1.0, f(1.0)) };
/// let limits = Limits { width: 1e-6, max_steps: 60, parabola_min_move: 0.0 };
/// let search = minimize(|x| ControlFlow::<(), _>::Continue(f(x)), bracket, limits);
/// let ControlFlow::Continue(m) = search else { unreachable!() };
/// assert!(m.closed && (m.bracket.mid.0 - 0.3).abs() < 1e-6);
/// ```
pub fn minimize<B>(
    mut f: impl FnMut(f64) -> ControlFlow<B, f64>,
    bracket: Bracket,
    limits: Limits,
) -> ControlFlow<B, Minimum> {
    let Bracket {
        mut lo,
        mut mid,
        mut hi,
    } = bracket;
    let mut last_change = None;
    for _ in 0..limits.max_steps {
        let width = hi.0 - lo.0;
        if width <= limits.width {
            break;
        }
        // The parabola's vertex, from the differences to the middle.
        let (d1, d2) = (mid.0 - lo.0, mid.0 - hi.0);
        let (g1, g2) = (mid.1 - lo.1, mid.1 - hi.1);
        let den = d1 * g2 - d2 * g1;
        let vertex = mid.0 - 0.5 * (d1 * d1 * g2 - d2 * d2 * g1) / den;
        let w = if den != 0.0
            && vertex > lo.0
            && vertex < hi.0
            && (vertex - mid.0).abs() >= limits.parabola_min_move * width
        {
            vertex
        } else if hi.0 - mid.0 > mid.0 - lo.0 {
            mid.0 + GOLDEN * (hi.0 - mid.0)
        } else {
            mid.0 - GOLDEN * (mid.0 - lo.0)
        };
        let fw = f(w)?;
        last_change = Some((fw - mid.1).abs());
        // The lower of the new point and the middle is the new middle.
        if fw <= mid.1 {
            if w < mid.0 {
                hi = mid;
            } else {
                lo = mid;
            }
            mid = (w, fw);
        } else if w < mid.0 {
            lo = (w, fw);
        } else {
            hi = (w, fw);
        }
    }
    ControlFlow::Continue(Minimum {
        bracket: Bracket { lo, mid, hi },
        closed: hi.0 - lo.0 <= limits.width,
        last_change,
    })
}

/// Newton's method toward a minimum of `f` from `x` within `[lo, hi]`, for at most
/// `max_steps` steps: `slope(x)` gives the first and second derivatives of `f` (or of any
/// function with the same minima and the same sign of slope, such as `f²/2` for a distance).
/// A step is taken only while the second derivative is positive and the step lowers `f` (or
/// keeps it): the polish never leaves a minimum the bracket found for a worse point.
/// Converges quadratically near a minimum with `f″ > 0`; stops where a step no longer moves.
///
/// ```
/// use numeric::minimize::polish;
/// let f = |x: f64| (x - 0.3).powi(2) + 1.0;
/// let x = polish(f, |x| (2.0 * (x - 0.3), 2.0), 0.9, (0.0, 1.0), 10);
/// assert!((x - 0.3).abs() < 1e-15);
/// ```
pub fn polish(
    f: impl Fn(f64) -> f64,
    mut slope: impl FnMut(f64) -> (f64, f64),
    mut x: f64,
    (lo, hi): (f64, f64),
    max_steps: usize,
) -> f64 {
    let mut fx = None;
    for _ in 0..max_steps {
        let (d1, d2) = slope(x);
        if d2.is_nan() || d2 <= 0.0 {
            break;
        }
        let next = (x - d1 / d2).clamp(lo, hi);
        if next == x {
            break;
        }
        let here = *fx.get_or_insert_with(|| f(x));
        let there = f(next);
        if there > here {
            break;
        }
        x = next;
        fx = Some(there);
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The search on plain values, never broken off.
    fn closed(f: impl Fn(f64) -> f64, bracket: Bracket, limits: Limits) -> Minimum {
        match minimize(|x| ControlFlow::<(), f64>::Continue(f(x)), bracket, limits) {
            ControlFlow::Continue(m) => m,
            ControlFlow::Break(()) => unreachable!(),
        }
    }

    /// A bracket from three abscissae.
    fn bracket(f: &impl Fn(f64) -> f64, lo: f64, mid: f64, hi: f64) -> Bracket {
        Bracket {
            lo: (lo, f(lo)),
            mid: (mid, f(mid)),
            hi: (hi, f(hi)),
        }
    }

    /// The least of dense samples of `f` on `[lo, hi]` and where it lies.
    fn dense_min(f: &impl Fn(f64) -> f64, lo: f64, hi: f64) -> (f64, f64) {
        (0..=20_000)
            .map(|i| lo + (hi - lo) * i as f64 / 20_000.0)
            .map(|x| (x, f(x)))
            .fold((lo, f64::INFINITY), |b, s| if s.1 < b.1 { s } else { b })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// On a unimodal function (a skewed power bump, turned over), from a bracket round its
        /// minimum, the search closes to the width within the golden bound and lands within
        /// the width of the minimum that dense sampling finds; the bracket stays one.
        #[test]
        fn closes_on_the_minimum_of_a_unimodal_function(
            peak in 0.05f64..0.95,
            power in 1.0f64..6.0,
            mid in 0.05f64..0.95,
            min_move in prop_oneof![Just(0.1), Just(0.3)],
        ) {
            let q = power * (1.0 - peak) / peak;
            let f = move |x: f64| -((x / peak).powf(power) * ((1.0 - x) / (1.0 - peak)).powf(q));
            let b = bracket(&f, 0.0, mid, 1.0);
            let width: f64 = 1e-6;
            // Twice the count of golden steps alone, from a middle at a golden section.
            let bound = 2 * ((width.ln() / (1.0 - GOLDEN).ln()).ceil() as usize + 2);
            let limits = Limits { width, max_steps: bound, parabola_min_move: min_move };
            let m = closed(f, b, limits);
            prop_assert!(m.closed, "{m:?}");
            let (lo, mid, hi) = (m.bracket.lo, m.bracket.mid, m.bracket.hi);
            prop_assert!(lo.0 <= mid.0 && mid.0 <= hi.0 && mid.1 <= lo.1 && mid.1 <= hi.1);
            let (x, _) = dense_min(&f, 0.0, 1.0);
            prop_assert!((mid.0 - peak).abs() <= width + 1e-4 && (x - peak).abs() <= 1e-4);
        }

        /// On a cubic with a local minimum inside a bracket made from its samples (as the
        /// nearest point's), the search and the polish agree with the closed form of the
        /// minimum, `f′ = 0`, to rounding; the polish alone from the bracket's middle too.
        #[test]
        fn agrees_with_the_closed_form_on_a_cubic(
            root in -1.0f64..1.0,
            curvature in 0.5f64..4.0,
            skew in -0.3f64..0.3,
            left in 0.05f64..1.0,
            right in 0.05f64..1.0,
            at in -0.5f64..0.5,
        ) {
            // f(x) = c (x − root)²/2 + s (x − root)³/3: f′ = (x − root)(c + s (x − root)).
            let f = move |x: f64| {
                let y = x - root;
                y * y * (0.5 * curvature + skew * y / 3.0)
            };
            let slope = move |x: f64| {
                let y = x - root;
                (y * (curvature + skew * y), curvature + 2.0 * skew * y)
            };
            let (lo, hi) = (root - left, root + right);
            let mid = root + at * left.min(right);
            let b = bracket(&f, lo, mid, hi);
            prop_assume!(b.mid.1 <= b.lo.1 && b.mid.1 <= b.hi.1);
            let limits = Limits { width: 1e-9, max_steps: 100, parabola_min_move: 0.1 };
            let m = closed(f, b, limits);
            prop_assert!(m.closed);
            prop_assert!((m.bracket.mid.0 - root).abs() <= 1e-9 + 1e-7, "{m:?}");
            let x = polish(f, slope, m.bracket.mid.0, (lo, hi), 20);
            prop_assert!((x - root).abs() <= 1e-14 * (1.0 + root.abs()), "{x} vs {root}");
            let x = polish(f, slope, mid, (lo, hi), 40);
            prop_assert!((x - root).abs() <= 1e-14 * (1.0 + root.abs()), "{x} vs {root}");
        }

        /// With the minimum at an end (the middle at that end), the search walks to it.
        #[test]
        fn finds_a_minimum_at_the_end(slope in 0.1f64..10.0, hi in 0.1f64..4.0) {
            let f = move |x: f64| slope * x;
            let b = Bracket { lo: (0.0, 0.0), mid: (0.0, 0.0), hi: (hi, f(hi)) };
            let limits = Limits { width: 1e-8 * hi, max_steps: 100, parabola_min_move: 0.1 };
            let m = closed(f, b, limits);
            prop_assert!(m.closed && m.bracket.mid.0 == 0.0 && m.bracket.hi.0 <= 1e-8 * hi);
        }
    }

    /// The caller breaks off after any evaluation, and the break comes back; the bound stops
    /// an unclosed search.
    #[test]
    fn breaks_off_and_stops_at_the_bound() {
        let f = |x: f64| (x - 0.7).abs();
        let b = bracket(&f, 0.0, 0.5, 1.0);
        let limits = Limits {
            width: 1e-12,
            max_steps: 5,
            parabola_min_move: 0.1,
        };
        let calls = std::cell::Cell::new(0);
        let stopped = minimize(
            |x| {
                calls.set(calls.get() + 1);
                if calls.get() == 3 {
                    ControlFlow::Break(x)
                } else {
                    ControlFlow::Continue(f(x))
                }
            },
            b,
            limits,
        );
        assert!(matches!(stopped, ControlFlow::Break(_)));
        assert_eq!(calls.get(), 3);
        let m = closed(f, b, limits);
        assert!(!m.closed && m.last_change.is_some());
    }
}
