//! Exact B-spline and NURBS algebra for planar curves, with certified root isolation.
//!
//! Everything here stays in the B-spline/Bernstein basis (never the power basis): products,
//! sums, derivatives, knot insertion, subdivision and degree elevation return B-splines equal
//! to the true result up to rounding. Root isolation decides existence from the signs of
//! B-spline coefficients with a rounding-error bound, so "no root here" and "exactly one simple
//! root here" are proofs, not samples.
//!
//! - [`BSpline`]: polynomial B-splines of any dimension (scalar functions, planar curves,
//!   homogeneous curves, rows of tensor-product coefficients).
//! - [`Rational`]: NURBS curves in homogeneous form.
//! - [`symbolic`]: curvature numerators and the sign functions of Jia's primitives.
//! - [`Piecewise`]: the piecewise Bézier form every certified decision reads, with a bound on
//!   the error of its coefficients; its algebra and evaluation.
//! - [`rounding`]: the bounds of the B-spline operations, on `numeric`'s one rounding model.
//! - [`roots`]: certified root counting and isolation.
//! - [`tensor`]: bivariate tensor-product functions `F(t, r)`.

mod algebra;
mod bilinear;
mod error;
pub mod fit;
pub mod knots;
mod piecewise;
mod rational;
mod refine;
pub mod roots;
pub mod rounding;
mod spline;
pub mod symbolic;
pub mod tensor;

pub use error::{Error, Result};
pub use knots::clamped_uniform_knots;
pub use piecewise::{Piecewise, ValueSlope, JUMP};
pub use rational::Rational;
pub use refine::Bezier;
pub use spline::BSpline;
