//! How far an arc of a traced zero set strays from its chord, measured from samples of the arc
//! rather than assumed (the tracer's chord tolerance rests on it).

use numeric::minimize::{minimize, Bracket, Limits};
use std::ops::ControlFlow;

/// Below this fraction of the tolerance at the quarter points, an arc is taken to be within
/// it without further samples: its image is a single bump between the chord's ends (the fold
/// and `UNEVEN` tests of the tracer halve anything else), and the image of either half of the parameter
/// holds at least 1/(1 + UNEVEN) of it, so the middle sample sits at a fraction in [0.2, 0.8]
/// of the bump, where a parabolic bump has at least 0.64 of its peak.
const UNSEEN_PEAK: f64 = 0.5;

/// Steps toward the largest deviation of an arc from its chord, after the samples at the
/// quarter points: enough golden-section steps alone to close the bracket to
/// [`DEVIATION_BRACKET`] (0.5 × 0.618⁸ < 1/64).
const DEVIATION_STEPS: usize = 8;

/// The climb stops once the bracket round the largest deviation is this narrow, as a fraction
/// of the segment's parameter.
const DEVIATION_BRACKET: f64 = 1.0 / 64.0;

/// A parabolic step that lands closer than this fraction of the bracket to its middle is
/// replaced by a golden-section step ([`Limits::parabola_min_move`]): it says little (on a
/// skewed bump the parabola's vertex sits next to the largest sample while the peak lies far
/// off, and the step's small gain would end the climb there).
const PARABOLA_MIN_MOVE: f64 = 0.1;

/// The least the maximum is taken to lie above the best sample when the climb ends, as a
/// fraction of the tolerance (the last step's change is used when larger).
const DEVIATION_CONVERGED: f64 = 0.01;

/// The largest deviation of an arc from its chord, measured rather than assumed from three
/// samples when they come near the tolerance: `sampled` holds `deviation` at `w` = 1/4, 1/2,
/// 3/4 (it is 0 at both ends). From the largest sample and its neighbours, a safeguarded
/// climb ([`numeric::minimize`]: the parabola's vertex when it moves far enough, else a
/// golden-section step into the wider side) closes the bracket round the maximum to
/// [`DEVIATION_BRACKET`]; the last step's change is added for what the climb leaves. A climb
/// that cannot close its bracket within [`DEVIATION_STEPS`] reports the tolerance exceeded,
/// so the segment is halved. Returns as soon as the tolerance is exceeded (the segment is halved anyway).
pub(crate) fn measured_deviation(
    deviation: &dyn Fn(f64) -> f64,
    sampled: [f64; 3],
    tol: f64,
) -> f64 {
    let k = (0..3).fold(0, |k, i| if sampled[i] > sampled[k] { i } else { k });
    let mut best = sampled[k];
    if best > tol || best <= UNSEEN_PEAK * tol {
        return best;
    }
    // A bracket (w, f) around the largest sample: its neighbours, the chord's ends giving 0.
    // The climb is numeric's minimisation of the deviation turned over (negating is exact: the
    // same steps, the same comparisons).
    let at = |i: usize| match i {
        0 => (0.0, 0.0),
        4 => (1.0, 0.0),
        i => (0.25 * i as f64, -sampled[i - 1]),
    };
    let bracket = Bracket {
        lo: at(k),
        mid: at(k + 1),
        hi: at(k + 2),
    };
    let limits = Limits {
        width: DEVIATION_BRACKET,
        max_steps: DEVIATION_STEPS,
        parabola_min_move: PARABOLA_MIN_MOVE,
    };
    let climb = minimize(
        |w| {
            let f = deviation(w);
            best = best.max(f);
            // Returns as soon as the tolerance is exceeded.
            if best > tol {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(-f)
            }
        },
        bracket,
        limits,
    );
    match climb {
        ControlFlow::Break(()) => best,
        // The maximum may lie above the best sample by about the last step's change.
        ControlFlow::Continue(m) if m.closed => {
            best + m.last_change.unwrap_or(tol).max(DEVIATION_CONVERGED * tol)
        }
        // Not located: taken as exceeded, so the segment is halved and measured again.
        ControlFlow::Continue(_) => tol * (1.0 + DEVIATION_CONVERGED),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A bump of height 1 on [a, b] (zero outside), peaking at the fraction `peak` of it:
    /// `(s/peak)^p ((1-s)/(1-peak))^q` with `p/(p+q) = peak`, skewed toward either end.
    fn bump(w: f64, a: f64, b: f64, peak: f64, p: f64) -> f64 {
        if w <= a || w >= b {
            return 0.0;
        }
        let s = (w - a) / (b - a);
        let q = p * (1.0 - peak) / peak;
        (s / peak).powf(p) * ((1.0 - s) / (1.0 - peak)).powf(q)
    }

    fn dense_max(f: &dyn Fn(f64) -> f64) -> f64 {
        (0..=20_000)
            .map(|i| f(i as f64 / 20_000.0))
            .fold(0.0, f64::max)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// On one skewed bump, a deviation reported within the tolerance is within it: the
        /// climb finds the peak (to the margin it adds) wherever the samples put it.
        #[test]
        fn a_bump_within_the_tolerance_is_within_it(
            peak in 0.05..0.95f64, p in 1.0..6.0f64, height in 0.55..1.6f64,
        ) {
            let tol = 1.0;
            let f = |w: f64| height * bump(w, 0.0, 1.0, peak, p);
            let sampled = [f(0.25), f(0.5), f(0.75)];
            prop_assume!(sampled.iter().any(|&v| v > UNSEEN_PEAK * tol));
            let measured = measured_deviation(&f, sampled, tol);
            let truth = dense_max(&f);
            prop_assert!(measured <= tol || measured >= truth.min(tol) - 1e-12);
            prop_assert!(truth <= tol * (1.0 + DEVIATION_CONVERGED) || measured > tol,
                "peak {truth} at {peak} (power {p}) measured {measured}");
        }
    }

    /// The skewed bump of a NURBS self-bisector's S-shaped arc (its far half, peak 1.15
    /// tolerances at 7/8 of the segment, 0.83 at the 3/4 sample): the parabola through the
    /// samples at 1/2, 3/4 and 1 puts the peak at 3/4, and a climb stopped by the small gain
    /// of that step reported 0.84.
    #[test]
    fn the_peak_beside_a_sample_is_found() {
        let f = |w: f64| 1.15 * bump(w, 0.49, 1.0, 0.75, 1.5);
        let sampled = [0.0, f(0.5), f(0.75)];
        assert!(sampled[2] > 0.8 && sampled[2] < 1.0, "{sampled:?}");
        assert!(measured_deviation(&f, sampled, 1.0) > 1.0);
    }
}
