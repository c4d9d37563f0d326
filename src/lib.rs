//! curvekit: certified geometry on planar freeform curves.
//!
//! The crates do the geometry ([`bspline`]: exact B-spline algebra and certified roots;
//! [`curve`]: the curve model and the analytic shapes; [`geometry`]: clearance, the nearest
//! point and flattening on it; [`zeroset`]: zero sets and bisectors;
//! [`antipodal`]: inflections, antipodal points and common tangents; [`grasp`]: two-finger
//! force-closure grasps with friction; [`medial`]: the medial axis of regions; [`offset`]:
//! offsets of regions from it). This crate adds what the `curvekit` tool needs around them:
//! reading curve files ([`io`]), the commands as calls on the curves read ([`commands`]: the
//! command line, its batch mode and the Python package share them), results written for
//! other programs ([`export`]: DXF and SVG paths) and figures ([`svg`]).
pub use antipodal;
pub use bspline;
pub use curve;
pub use geometry;
pub use grasp;
pub use medial;
pub use numeric;
pub use offset;
pub use zeroset;

pub mod commands;
pub mod export;
pub mod io;
pub mod svg;
