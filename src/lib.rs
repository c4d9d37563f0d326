//! curvekit: certified geometry on planar freeform curves.
//!
//! The crates do the geometry ([`bspline`]: exact B-spline algebra and certified roots;
//! [`zeroset`]: zero sets and bisectors; [`antipodal`]: antipodal points and common tangents).
//! This crate adds what the `curvekit` tool needs around them: reading curve files ([`io`]),
//! the analytic shapes of the file format ([`shapes`]), inflections ([`inflections`]) and
//! figures ([`svg`]).
pub use antipodal;
pub use bspline;
pub use zeroset;

pub mod inflections;
pub mod io;
pub mod shapes;
pub mod svg;
