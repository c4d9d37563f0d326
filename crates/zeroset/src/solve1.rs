//! One-dimensional refinement along the tracer's cells: plain Newton steps first (the graph
//! patches are monotone, so they rarely need more), then the workspace's one bracketed solver.

use numeric::rounding::ulps;
use numeric::solve::{bracketed, Accuracy};

/// Newton steps tried before a bracket is set up in [`bracketed_or_end`].
const NEWTON_FIRST: usize = 6;

/// The root of `f` in `[a, b]`, where `f(a)` has the sign of `sa` and `f(b)` the opposite one,
/// started from `x0`: the bracketed solve to a few units of rounding of the interval, stopping
/// where `|f| ≤ noise` (the rounding level of `f`). `f` returns value and derivative.
pub(crate) fn bracketed_from(
    mut f: impl FnMut(f64) -> (f64, f64),
    a: f64,
    b: f64,
    sa: f64,
    x0: f64,
    noise: f64,
) -> f64 {
    bracketed(
        |x| {
            let (v, d) = f(x);
            (v, d, f64::NAN)
        },
        (a, b),
        (sa, -sa),
        Accuracy::param(0.0).noise(noise).hint(x0),
    )
}

/// Like [`bracketed_from`] but tolerant of end values of equal sign (where rounding blurred a
/// sign at the end of an arc): then the end with the smaller `|f|`.
///
/// For a function monotone on `[a, b]` (the graph patches of the tracer), so that a zero
/// inside is the only one: plain Newton from `x0` is tried first, and accepted if it reaches
/// rounding level without leaving the interval; the bracket (two more evaluations) is only
/// set up when it does not.
pub(crate) fn bracketed_or_end(
    mut f: impl FnMut(f64) -> (f64, f64),
    a: f64,
    b: f64,
    x0: f64,
    noise: f64,
) -> f64 {
    let (lo, hi) = (a.min(b), a.max(b));
    let tiny = ulps(4.0) * a.abs().max(b.abs()).max(hi - lo);
    let mut x = x0.clamp(lo, hi);
    for _ in 0..NEWTON_FIRST {
        let (fx, dx) = f(x);
        if fx.abs() <= noise {
            return x;
        }
        let nx = x - fx / dx;
        if !(nx >= lo && nx <= hi) {
            break;
        }
        if (nx - x).abs() <= tiny {
            return nx;
        }
        x = nx;
    }
    let fa = f(a).0;
    let fb = f(b).0;
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    if (fa > 0.0) == (fb > 0.0) {
        return if fa.abs() <= fb.abs() { a } else { b };
    }
    bracketed_from(f, a, b, fa, x0, noise)
}
