//! The numerics every curvekit crate shares (issue 41, `docs/architecture.md`), at the bottom
//! of the workspace: it knows nothing of curves.
//!
//! - [`rounding`]: the one rounding model. Every bound on a computed value's error is written
//!   with [`rounding::gamma`], [`rounding::ulps`] or [`rounding::Bounded`], never with a bare
//!   `f64::EPSILON`.
//! - [`solve`]: the bracketed 1-D solvers: [`solve::bracketed`] (Newton or Halley,
//!   safeguarded by bisection, with its explicit [`solve::Accuracy`]), and for functions
//!   without a derivative the steppers [`solve::Itp`] and [`solve::Illinois`]; without a
//!   bracket, [`solve::newton_within`] (Newton clamped into an interval) and [`solve::secant`]
//!   (secant steps, the answer held to a stated bound).
//! - [`newton2`]: the one two-dimensional Newton's method, [`newton2::newton2`], on
//!   `nalgebra`'s fixed-size matrices, with its damped step, residual test and iteration bound,
//!   and its finish [`newton2::polish`], which keeps the best iterate met by the caller's
//!   residual and stops when it rises.
//! - [`minimize`]: the one bracketed minimisation, [`minimize::minimize`] (parabolic steps
//!   safeguarded by golden sections), and its Newton polish, [`minimize::polish`].
//! - [`subdivide`]: the one halve-until-decided driver, [`subdivide::depth_first`] (depth
//!   first, first half first, so kept parts come in order; the depth bounded).
//! - [`tolerance`]: the parameter and chord tolerances and the size as validated types, with
//!   their defaults and accepted ranges written once, and the [`tolerance::Settings`] that
//!   carries them from the edge to every algorithm.
//! - [`certificate`]: certificates as values, [`certificate::Doubt`] (every reason a result
//!   may not be certified, listed once) and [`certificate::Certified`].
//! - [`Interval`]: closed intervals and the interval arithmetic the proofs combine ranges
//!   with; [`Rect`]: closed rectangles `t × r` of a parameter plane (the bivariate searches'
//!   cells, domains and hulls).
//!
//! ```
//! use numeric::solve::{bracketed, Accuracy};
//! use numeric::rounding::ulps;
//! // The root of x² − 2 on [1, 2], to a few units of rounding.
//! let x = bracketed(|x| (x * x - 2.0, 2.0 * x, 2.0), (1.0, 2.0), (-1.0, 2.0), Accuracy::param(1e-15));
//! assert!((x - 2f64.sqrt()).abs() <= ulps(4.0));
//! ```

pub mod certificate;
mod interval;
pub mod minimize;
pub mod newton2;
mod rect;
pub mod rounding;
pub mod solve;
pub mod subdivide;
pub mod tolerance;

pub use interval::Interval;
pub use rect::Rect;
