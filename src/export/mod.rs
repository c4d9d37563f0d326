//! Results written in the formats users take back into their CAD and CAM programs (the
//! contract's "Output files and V-carving"): DXF ([`dxf_file`]) for offsets, medial axes and
//! V-carving tool paths, and plain SVG paths ([`svg_paths`]) for offsets and medial axes, in
//! the input's own coordinates, which curvekit reads back.
//!
//! Curves are written exactly as computed: lines as lines, arcs as arcs, splines as splines
//! (as Bézier pieces in SVG, which is the same curve), never flattened.

pub mod dxf_file;
pub mod svg_paths;

use thiserror::Error;

/// Why a result could not be written.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ExportError {
    /// A piece the format cannot hold exactly (named, with why).
    #[error("{0}")]
    NotRepresentable(String),
    /// The DXF library failed to write the drawing.
    #[error("the DXF could not be written: {0}")]
    Dxf(String),
}

/// An arc that sweeps less than this (radians) is nothing, and is not written: a corner's arc
/// where the offset meets it head on. DXF would draw equal angles as a whole circle, and
/// curvekit's readers take sweeps within 1e-9 rad of nothing as one.
pub const NO_SWEEP: f64 = 1e-9;

/// Whether `s` is an arc that sweeps nothing ([`NO_SWEEP`]): a piece neither writer writes.
pub(crate) fn sweeps_nothing(s: &offset::OffsetSegment) -> bool {
    matches!(s, offset::OffsetSegment::Arc { start, end, .. } if (end - start).abs() <= NO_SWEEP)
}

/// A distance as a layer or group name takes it (`offset_0.25`): Rust's shortest form that
/// reads back as the same number, never an exponent.
pub(crate) fn distance_name(d: f64) -> String {
    format!("offset_{d}")
}
