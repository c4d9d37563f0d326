//! Zero sets of bivariate B-spline functions, square 2×2 systems, and the bisectors of planar
//! rational curves (Elber & Kim, *Bisector curves of planar rational curves*, CAD 1998).
//!
//! - [`zero_set`]: all curves, crossings and isolated points of `F(t, r) = 0` by subdivision
//!   with convex-hull purging and a proof of simplicity per patch (§4 of the paper).
//! - [`nonnegative_set`]: the boundary of the set where several functions are all
//!   non-negative (pieces of their zero sets, cut where they cross).
//! - [`solve_system`]: the isolated common zeros of two bivariate functions.
//! - [`bisector`], [`self_bisector`]: the bisector as branches of matched foot points `(t, r)`
//!   and bisector points `P(t, r)` (Eq. 16), from the functions `F1`, `F2`, `F3` of §3
//!   ([`bisector_function`]); of curves or of profiles (chains of segments with corners),
//!   corners acting as point sites inside their cones.
//! - [`profile_bisector_of_pairs`], [`profile_self_bisector_of_pairs`]: a profile's, kept to
//!   the pairs of segments a caller has shown can matter (the medial axis).

mod assemble;
mod bisector;
mod blowup;
mod boundary;
mod deviation;
mod entries;
mod error;
mod extract;
mod nonnegative;
mod patch;
mod profile_bisector;
mod solve1;
mod symbolic;
mod system;
mod zeroset;

pub use bisector::{
    bisector_point, Bisector, BisectorOptions, BisectorPoint, Branch, Side, RESIDUAL,
};
pub use boundary::{BoundaryPiece, PieceEnd};
pub use entries::{bisector, self_bisector};
pub use error::{Error, Result};
pub use nonnegative::{
    nonnegative_set, nonnegative_set_mapped, NonNegativeOptions, NonNegativeSet,
};
pub use profile_bisector::{profile_bisector_of_pairs, profile_self_bisector_of_pairs};
pub use symbolic::{bisector_function, Method};
pub use system::{solve_system, Solution, SystemOptions};
pub use zeroset::{zero_set, Polyline, ZeroSet, ZeroSetOptions};
