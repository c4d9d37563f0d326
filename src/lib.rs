//! curvekit: certified geometry on planar freeform curves.
pub use antipodal;
pub use bspline;
pub use zeroset;
