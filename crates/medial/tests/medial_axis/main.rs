//! The medial axis against closed forms on degenerate regions and against an independent
//! oracle on random ones.
//!
//! The oracle shares no code with the crates: distances by dense sampling of each boundary
//! refined by golden-section search. Every vertex must be at the boundary's distance, that
//! distance attained at both its feet; every point of the Voronoi diagram of a dense sampling
//! of the boundary whose samples are far apart along it, refined onto the axis, must lie
//! within the chord tolerance of an edge; the graph must be connected with one cycle per
//! hole.

#![allow(clippy::unwrap_used, missing_docs)]

mod closed_forms;
mod corners;
#[path = "../common/graph.rs"]
mod graph;
mod helpers;
mod metamorphic;
mod oracle;
mod random_regions;
#[path = "../common/sampled_voronoi.rs"]
mod sampled_voronoi;
mod smooth_joints;
#[path = "../common/traced.rs"]
mod traced;
