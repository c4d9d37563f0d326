//! How many cases a property test runs. Included by path by the test crates that need it.
#![allow(unreachable_pub)]

/// Proptest cases: `n`, scaled by the environment variable `CURVEKIT_CASES_SCALE` (a number,
/// default 1): CI runs the default, stress runs (as behind the figures of a closing note) many
/// times more.
pub fn cases(n: u32) -> u32 {
    let scale: f64 = std::env::var("CURVEKIT_CASES_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);
    ((n as f64 * scale).round() as u32).max(1)
}
