//! The tests' shared ground (issue 41, `docs/architecture.md`): one copy of what every
//! crate's tests and benchmarks need, a dev-dependency only.
//!
//! - [`assert_near!`] and [`prop_assert_near!`]: two values within a named tolerance, the
//!   values and the gap printed when they are not ([`gap`] measures it, on any [`Near`] value).
//! - [`cases`]: how many cases a property test runs, scaled for stress runs.
//! - [`rng`] and [`Lcg`]: one seeded generator of uniform draws.
//! - [`stars`]: the random star-shaped control polygons the property tests draw curves from.
//! - [`profiles`]: random profiles (filleted polygons, chains of Béziers), reassembled from
//!   another segment or backwards.
//! - [`boundary_oracle`]: distances to a profile by dense sampling and golden-section search,
//!   sharing no code with the crates; the exact winding number of a polygon.
//! - [`evaluation_only`]: a curve known by evaluation only (no exact form).
//! - [`grasp_oracle`]: force closure from a profile's points and tangents alone.
//! - [`far_joints`]: profiles with smooth joints (stadiums, filleted rectangles, D-shapes,
//!   ovals of arcs) for the tests far from the origin.
//! - [`outlines`]: the benchmarks' parts (the pocket, the CAD outline, gears, star polygons),
//!   which the tests also run on, so a fault found on a benchmark shape is tested on it.
//!
//! ```
//! use testkit::{assert_near, stars::star};
//! let points = star(&[0.5, 1.0, 0.5, 1.0, 0.5, 1.0]);
//! assert_eq!(points.len(), 3);
//! assert_near!(points[0], [1.0, 0.0], 1e-15);
//! ```

pub mod boundary_oracle;
pub mod evaluation_only;
pub mod far_joints;
pub mod grasp_oracle;
#[doc(hidden)]
pub mod near;
pub mod outlines;
pub mod profiles;
mod random;
pub mod stars;

pub use near::{gap, within, Near};
pub use random::{rng, Lcg};

/// The settings of a test: the default parameter tolerance, the chord tolerance `chord_tol`,
/// and the size `size` the tolerances are relative to (`None`: each algorithm's input's).
pub fn settings(chord_tol: f64, size: Option<f64>) -> numeric::tolerance::Settings {
    numeric::tolerance::Settings::new(numeric::tolerance::DEFAULT_PARAM_TOL, chord_tol, size)
        .expect("settings in range")
}

/// Re-exported for [`prop_assert_near!`], so that a crate using it needs no import of its own.
#[doc(hidden)]
pub use proptest as __proptest;

/// Proptest cases: `n`, scaled by the environment variable `CURVEKIT_CASES_SCALE` (a number,
/// default 1). CI runs the default; stress runs (as behind the figures of a closing note) many
/// times more.
pub fn cases(n: u32) -> u32 {
    let scale: f64 = std::env::var("CURVEKIT_CASES_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);
    ((n as f64 * scale).round() as u32).max(1)
}
