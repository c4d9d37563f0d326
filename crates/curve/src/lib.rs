//! The plane-curve model of curvekit: what the algorithms run on.
//!
//! - [`ParamCurve`]: evaluation (domain, closedness, jets to an order), all a curve needs to be
//!   searched by Jia's sampled method; [`PlaneCurve`] adds the curve's [`Exact`] description,
//!   from which certified decisions are made.
//! - [`SplineCurve`]: B-spline and NURBS curves; [`shapes`]: the analytic shapes of the curve
//!   files, each defined once, with their exact rational forms on the rational circle
//!   ([`circle`]) and their view in its parameter ([`OnCircle`]).
//! - [`Profile`]: chains of [`Segment`]s (lines, arcs, Bézier and open B-spline curves) joined
//!   at corners or smoothly, as part outlines are drawn; [`Region`]: an outer profile and
//!   holes (a pocket with islands).
//! - [`Boundary`]: what a command takes, a smooth curve or a profile (a smooth closed curve
//!   is a closed profile of one segment).
//! - [`Frame`]: exact changes of coordinates into a frame of about unit size near the curve.
//! - [`exact`]: exact predicates on the data (collinear points, parallel stretches).
//! - [`V2`], [`Jet`]: the small geometric types the algorithms share.
//! - What a profile keeps to be searched fast, as data: the boxes of its segments and of
//!   their Bézier pieces ([`piece_bounds`]) and the hierarchy over them ([`box_tree`]). The
//!   searches themselves (clearance, nearest point, flattening) are the `geometry` crate's.
//!
//! The constructors keep the model's promise: a [`Profile`] does not cross itself and a
//! [`Region`]'s boundaries do not cross each other (a certified crossing test, the one
//! predicate the model runs, since every certificate built on a profile rests on it).
//!
//! ```
//! use curve::{shapes::Ellipse, ParamCurve, PlaneCurve};
//! let e = Ellipse::new(3.0, 2.0, [1.0, 0.0]).unwrap();
//! assert_eq!(e.jet(0.0).p.arr(), [4.0, 0.0]);
//! assert!(e.exact().is_some());
//! ```

mod affine;
mod bezier_piece;
mod boundary;
pub mod box_tree;
pub mod circle;
mod corner_knots;
mod crossing;
mod error;
pub mod exact;
mod extent;
mod fill;
mod frame;
mod geom;
mod on_circle;
mod own_param;
mod param;
pub mod piece_bounds;
mod plane;
mod profile;
mod region;
mod segment;
pub mod shapes;
mod spans;
mod spline;
pub mod watch;

pub use affine::Affine;
pub use boundary::Boundary;
pub use corner_knots::{smooth_turn, DocumentSpan, CORNER_TURN};
pub use error::{Error, Result};
pub use extent::{box_size, curves_box, union as box_union, Box2};
pub use fill::{FillRule, FilledOutline};
pub use frame::Frame;
pub use geom::{
    distance_to_segment, follow_image, points_scale, squared_distance_to_segment, wrap_pi, Jet, V2,
};
pub use on_circle::OnCircle;
pub use own_param::OwnParam;
pub use param::ParamCurve;
pub use plane::{Exact, ExactCurve, PlaneCurve};
pub use profile::{Joint, JointKind, Profile, JOIN_GAP};
pub use region::Region;
pub use segment::{Segment, SegmentKind};
pub use spans::SpanOf;
pub use spline::{rational_derivs, SplineCurve, StraightSpan};
