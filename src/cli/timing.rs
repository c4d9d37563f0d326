//! `--time`: repeat a computation in-process and report the median time of one run.

pub(crate) use curvekit::commands::Stats;
use std::time::{Duration, Instant};

/// How long the repetitions run at least.
const BUDGET: Duration = Duration::from_millis(500);

/// [`measure`] of a warm run and of a cold one, each for the whole budget.
pub(crate) fn measure_both<T, U>(warm: impl FnMut() -> T, cold: impl FnMut() -> U) -> Stats {
    let w = measure(warm);
    let c = measure(cold);
    Stats {
        cold_median_us: Some(c.median_us),
        cold_runs: Some(c.runs),
        ..w
    }
}

/// Runs `f` repeatedly for at least [`BUDGET`] (and at least three times).
pub(crate) fn measure<T>(mut f: impl FnMut() -> T) -> Stats {
    let start = Instant::now();
    let mut times = Vec::new();
    while times.len() < 3 || start.elapsed() < BUDGET {
        let t0 = Instant::now();
        std::hint::black_box(f());
        times.push(t0.elapsed().as_secs_f64() * 1e6);
    }
    times.sort_by(f64::total_cmp);
    let n = times.len();
    let median = if n % 2 == 1 {
        times[n / 2]
    } else {
        0.5 * (times[n / 2 - 1] + times[n / 2])
    };
    Stats {
        median_us: median,
        runs: n,
        cold_median_us: None,
        cold_runs: None,
    }
}
