//! All antipodal point pairs of a closed plane curve, its inflections, and all common tangent
//! lines of two curves, by Yan-Bin Jia's method:
//!
//! - Jia, *Computation on Parametric Curves with an Application in Grasping* (IJRR 2004):
//!   dissection at inflections (§5), common tangents (§2, Appendix B), the Antipodal-Points
//!   procedure of Table 1 with Bisect (§4.1) and March (§4.2), the primitives of Appendix A.
//! - Jia, *Curvature-Based Computation of Antipodal Grasps* (ICRA 2002).
//!
//! Two points are antipodal when their inward normals are opposite, collinear and point at each
//! other (a two-finger force-closure grasp). The curve is cut into monotone pieces (curvature of
//! one sign, total curvature below π); every pair of pieces is reduced to sections with opposite
//! normals whose normals face each other, and each section is searched by bisection and marching
//! with provable convergence. No multi-start Newton and no sampling of the `(s, t)` square.
//!
//! For B-spline and NURBS curves ([`SplineCurve`]) every existence decision — inflections,
//! tangent-turning bounds, and the roots of each primitive — rests on sign tests of B-spline
//! coefficients (certified root isolation from `bspline`), and the curve is proven simple by
//! enclosures of its monotone arcs (or proven to cross itself). Analytic shapes use Jia's sampled
//! inflection search and sign tests at segment ends; their results say `certified: false`. The
//! ellipse, the limaçon and the curves with convexities run on their exact rational forms
//! through the rational unit circle instead (certified, parameters still reported in φ), and
//! so does the elliptic lemniscate, the inverse of an ellipse, up to `a/b = 5` (more slender
//! ones stay sampled).
//!
//! The modules, in the order of the paper's steps (each says where it goes beyond the paper):
//! `prepare` (the frame and the symbolic forms, once per curve) and `driver` (one run);
//! `tracks`, `dissect` and `simple` (§5: the tangent's turning, monotone pieces, and the
//! proof that the curve is simple);
//! `prims` (Appendix A: the primitives); `tangent` (§2.5: common tangents); `pairs` (a pair
//! of pieces and its sections); `bisect` (§4.1); `search` (Table 1) and `march` (§4.2);
//! `finish`, `monotone`, `radius_rates` and `families` (beyond the paper: proofs that spare
//! marches, that θ is monotone or of one sign on a stretch, and continua of pairs); `profiles`,
//! `profile_pairs`, `corner_pairs` and `profile_tangents` (beyond the papers: profiles of
//! segments joined at corners, segment by segment, and the corners' cones); `whole_curve` (a
//! closed profile of one smooth segment is a smooth closed curve, and runs as one). Curves and
//! profiles share the result types: what only a profile has (corners, segments, a family's end
//! points) is `None` on a smooth curve, and its document does not write it. Below them the proof layer: `view` (a curve as the steps see it), `arcs` (what an
//! arc is proven to be), `bounds` and `cells` (per-piece curvature and rate cells), `enclosure`,
//! `taylor` (with `numeric::Interval` for ranges); `ledger` keeps the doubts met on each view
//! of a run (`numeric::certificate::Doubt` names every reason a result is not certified).

mod arcs;
mod bisect;
mod bounds;
mod cells;
mod corner_pairs;
mod dissect;
mod driver;
mod enclosure;
mod entries;
mod error;
mod families;
mod finish;
mod forms;
mod ledger;
mod march;
mod monotone;
mod pairs;
mod prepare;
mod prims;
mod profile_pairs;
mod profile_tangents;
mod profiles;
mod radius_rates;
mod search;
mod simple;
mod tangent;
mod taylor;
mod tracks;
mod types;
mod view;
mod whole_curve;

pub use curve::{
    shapes, Boundary, Frame, Jet, ParamCurve, PlaneCurve, Profile, Segment, SplineCurve, V2,
};
pub use entries::{antipodal, common_tangents, inflections};
pub use error::{Error, Result};
pub use forms::SymbolicForms;
pub use numeric::certificate::{Doubt, Doubts, Verdict};
pub use prepare::{prepare, prepare_pair, prepare_shared, Prepared};
pub use profile_tangents::MAX_SEGMENT_PAIRS;
pub use types::{
    Antipodal, AntipodalPair, Corner, CornerKind, Family, Inflection, InflectionKind, Inflections,
    Options, PairType, TangentLine, Tangents,
};
