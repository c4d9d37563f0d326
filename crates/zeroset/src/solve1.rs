//! Bracketed one-dimensional root refinement: Newton steps that never leave the bracket.

/// Newton steps tried before a bracket is set up in [`bracketed_or_end`].
const NEWTON_FIRST: usize = 6;

/// The root of `f` in `[a, b]` where `f(a)` and `f(b)` have opposite signs (`sa` is the sign
/// at `a`), starting from `x0`. `f` returns value and derivative. Stops when `|f| ≤ noise`
/// (the rounding level of `f`), when a Newton step would be below a few ulps, or when the
/// bracket is that narrow; at most 100 steps (bisection alone needs ~64 for a double interval).
pub(crate) fn bracketed(
    mut f: impl FnMut(f64) -> (f64, f64),
    a: f64,
    b: f64,
    sa: f64,
    x0: f64,
    noise: f64,
) -> f64 {
    let (mut lo, mut hi) = (a, b);
    // Steps below this are rounding noise.
    let tiny = 4.0 * f64::EPSILON * a.abs().max(b.abs()).max((b - a).abs());
    let mut x = if x0 > a.min(b) && x0 < a.max(b) {
        x0
    } else {
        0.5 * (lo + hi)
    };
    for _ in 0..100 {
        let (fx, dx) = f(x);
        // At rounding level the value cannot improve; a step below a few ulps neither.
        if fx.abs() <= noise || (dx != 0.0 && (fx / dx).abs() <= tiny) {
            return x;
        }
        if (fx > 0.0) == (sa > 0.0) {
            lo = x;
        } else {
            hi = x;
        }
        if (hi - lo).abs() <= tiny {
            break;
        }
        let newton = x - fx / dx;
        let (l, h) = if lo < hi { (lo, hi) } else { (hi, lo) };
        if dx != 0.0 && newton.is_finite() && newton > l && newton < h {
            x = newton;
        } else {
            x = 0.5 * (lo + hi);
        }
    }
    x
}

/// Like [`bracketed`] but tolerant of end values of equal sign (where rounding blurred a sign
/// at the end of an arc): then the end with the smaller `|f|`.
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
    let tiny = 4.0 * f64::EPSILON * a.abs().max(b.abs()).max(hi - lo);
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
    bracketed(f, a, b, fa, x0, noise)
}
