//! Two-finger grasps with friction: every force-closure pair of contacts on a closed curve,
//! as regions of the square of contact parameters, certified by the sign tests of the
//! B-spline zero sets that bound them.
//!
//! A pair `(s, t)` is force closure for Coulomb friction μ (Nguyen 1988) when the chord
//! `d = C(t) − C(s)` lies inside the friction cone at `s` (half-angle `α = atan μ` round the
//! inward normal) and `−d` inside the one at `t`. Each of the four cone edges gives a
//! bivariate B-spline `⟨μN ∓ T, ±d⟩ ≥ 0` ([`cones`](crate)), and the regions are the cells of
//! the torus of pairs where all hold: their boundaries are traced as zero sets
//! ([`zeroset::nonnegative_set`]), joined into loops, and glued across the curve's seam.
//! Each region gets:
//! - its **independent contact region**: stretches `[s0, s1]` and `[t0, t1]` whose every pair
//!   is force closure, proven by the sign of every function's Bernstein coefficients there;
//! - its **most robust grasp**: the pair of least `min_friction`, an antipodal pair (0) where
//!   the region holds one.
//!
//! With μ → 0 the regions shrink onto Jia's antipodal pairs and families
//! ([`antipodal::antipodal`]).

mod assemble;
mod best;
mod cells;
mod compute;
mod cones;
mod contact;
mod corners;
mod entries;
mod error;
mod model;
mod near;
mod options;
mod polyline;
mod proof;
mod quality;
mod region_set;
mod spared;
mod types;

pub use entries::{grasps, prepare, PreparedGrasps};
pub use error::{Error, Result};
pub use options::GraspOptions;
pub use types::{BestGrasp, ContactRegion, GraspRegion, Grasps};
