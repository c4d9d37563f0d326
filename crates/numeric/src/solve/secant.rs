//! Secant steps without a bracket: for a root that may lie outside the interval its two
//! starting points span, within a bound the caller states.

use crate::rounding::ulps;

/// A root of `f` by secant steps from the two starting points `starts`, unbracketed: each
/// step goes to where the line through the last two iterates and their values crosses zero,
/// wherever that is, so the iterates may leave the interval of the starts (a root past both,
/// as where a medial branch turns between its vertices and its foot goes past both of theirs
/// and back). The answer is the iterate of least `|f|` met (the starts included), and it is
/// returned only if it lies in `within`; the iterates between may wander outside it.
///
/// **Convergence.** On a simple root of a smooth `f`, from starts close enough, the error
/// falls with order `(1 + √5)/2 ≈ 1.618` per evaluation. Far from a root nothing is promised;
/// at the rounding floor of `f` a step divides noise by noise and may throw the next iterate
/// anywhere, which the least `|f|` kept guards against.
///
/// **Stopping rule and bound.** The steps stop where the last value is 0, the last two values
/// are equal (a flat secant), the last two iterates are within a unit of rounding of each
/// other, or a step or a value is not finite; and after `max_steps` steps, the bound: at most
/// `max_steps + 2` evaluations.
///
/// ```
/// use numeric::solve::secant;
/// // The root of x² − 2 lies past both starts 1 and 1.2, within [0, 2].
/// let x = secant(|x| x * x - 2.0, (1.0, 1.2), 30, (0.0, 2.0)).unwrap();
/// assert!((x - 2f64.sqrt()).abs() < 1e-15);
/// assert_eq!(secant(|x| x * x - 2.0, (1.0, 1.2), 30, (0.0, 1.2)), None);
/// ```
pub fn secant(
    mut f: impl FnMut(f64) -> f64,
    (mut x0, mut x1): (f64, f64),
    max_steps: usize,
    (lo, hi): (f64, f64),
) -> Option<f64> {
    let (mut f0, mut f1) = (f(x0), f(x1));
    // The iterate of least |f| (a NaN value is never the least: then the second start).
    let mut best = (f64::INFINITY, x1);
    for (x, fx) in [(x0, f0), (x1, f1)] {
        if fx.abs() < best.0 {
            best = (fx.abs(), x);
        }
    }
    for _ in 0..max_steps {
        if f1 == 0.0 || f1 == f0 || (x1 - x0).abs() <= ulps(1.0) * x1.abs().max(1.0) {
            break;
        }
        let next = x1 - f1 * (x1 - x0) / (f1 - f0);
        if !next.is_finite() {
            break;
        }
        (x0, f0) = (x1, f1);
        x1 = next;
        f1 = f(x1);
        if !f1.is_finite() {
            break;
        }
        if f1.abs() < best.0 {
            best = (f1.abs(), x1);
        }
    }
    // (NaN is outside.)
    let x = best.1;
    (x >= lo && x <= hi).then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(5000))]

        /// On a cubic with one simple root (the other two complex), from starts near it on
        /// one side or straddling it, the secant reaches the root that bisection to the last
        /// double finds (the independent method), within 20 evaluations (its bound: 32).
        #[test]
        fn reaches_the_root_bisection_finds(
            root in -2.0f64..2.0,
            c in 0.0f64..3.0,
            d in 0.1f64..1.0,
            starts in proptest::array::uniform2(-0.3f64..0.3),
        ) {
            // (x − root)(x² + c x + c² + d²): the quadratic has no real root.
            let f = |x: f64| (x - root) * (x * x + c * x + c * c + d * d);
            let (s0, s1) = (root + starts[0], root + starts[1]);
            prop_assume!((s0 - s1).abs() > 1e-3);
            let calls = std::cell::Cell::new(0);
            let x = secant(|x| { calls.set(calls.get() + 1); f(x) }, (s0, s1), 30, (-5.0, 5.0));
            let x = x.unwrap();
            let (mut a, mut b) = (root - 1.0, root + 1.0);
            for _ in 0..200 {
                let m = 0.5 * (a + b);
                if m <= a || m >= b { break; }
                if (f(m) < 0.0) == (f(a) < 0.0) { a = m } else { b = m }
            }
            let scale = 1.0 + root.abs();
            prop_assert!(x >= a - ulps(4.0) * scale && x <= b + ulps(4.0) * scale,
                "{x} vs [{a}, {b}]");
            prop_assert!(calls.get() <= 20, "{} evaluations", calls.get());
        }

        /// Whatever it meets, the answer is the iterate of least |f| among those evaluated,
        /// and it is given only inside the bound.
        #[test]
        fn answers_the_least_value_met_inside_the_bound(
            k in 1.0f64..20.0,
            starts in proptest::array::uniform2(-3.0f64..3.0),
            bound in proptest::array::uniform2(-3.0f64..3.0),
        ) {
            let f = |x: f64| (k * x).sin() + 0.3 * x;
            let mut met = Vec::new();
            let (lo, hi) = (bound[0].min(bound[1]), bound[0].max(bound[1]));
            let x = secant(|x| { met.push((x, f(x).abs())); f(x) }, (starts[0], starts[1]), 30,
                (lo, hi));
            prop_assert!(met.len() <= 32);
            let least = met.iter().copied()
                .fold((f64::INFINITY, f64::NAN), |b, (x, v)| if v < b.0 { (v, x) } else { b });
            match x {
                Some(x) => prop_assert!(x == least.1 && x >= lo && x <= hi),
                None => prop_assert!(!(least.1 >= lo && least.1 <= hi)),
            }
        }
    }

    #[test]
    fn stops_on_a_flat_secant_and_a_zero() {
        // Equal values: no step, and of equal values the first start's is kept.
        assert_eq!(secant(|x| x * x, (-1.0, 1.0), 30, (-1.0, 1.0)), Some(-1.0));
        // A start at the root.
        let calls = std::cell::Cell::new(0);
        let at = secant(
            |x| {
                calls.set(calls.get() + 1);
                x - 0.5
            },
            (0.0, 0.5),
            30,
            (0.0, 1.0),
        );
        assert_eq!((at, calls.get()), (Some(0.5), 2));
    }
}
