//! Exact B-spline and NURBS algebra for planar curves, with certified root isolation.
//!
//! Everything here stays in the B-spline/Bernstein basis (never the power basis): products,
//! sums, derivatives, knot insertion, subdivision and degree elevation return B-splines equal
//! to the true result up to rounding. Root isolation decides existence from the signs of
//! B-spline coefficients with a rounding-error bound, so "no root here" and "exactly one simple
//! root here" are proofs, not samples.

mod algebra;
mod error;
pub mod knots;
mod refine;
mod spline;

pub use error::{Error, Result};
pub use refine::Bezier;
pub use spline::{clamped_uniform_knots, BSpline};
