//! Offsets against closed forms (rectangles, disks, annuli) and against an independent
//! distance (the boundary sampled densely): every offset point lies at the distance, the loops
//! close, run the right way round, and their number follows the region's shape.
#![allow(clippy::unwrap_used)]

mod closed_forms;
#[path = "../common/mod.rs"]
mod common;
mod helpers;
mod metamorphic;
mod necks;
mod oracle;
mod outward;
mod random_regions;
mod refusals;
