//! Curve files (see `docs/interfaces.md`, "Curve files"): JSON text → a validated [`Curve`].
//!
//! The reader walks the JSON value itself instead of deriving `Deserialize`, so that every error
//! can name the exact field (`points[3][1]`, `knots[5]`), which serde's messages cannot. Unknown
//! fields are rejected like `#[serde(deny_unknown_fields)]` would, but with the field named.

mod curve_file;
mod curves;
mod document;
mod drawing;
mod duplicates;
mod dxf;
mod errors;
mod fields;
mod inputs;
mod profile;
mod regions;
mod spline;
mod svg;

pub use curve_file::parse_curve;
pub use curves::{curve_profile, Curve, CurveKind, DrawingInfo, SplineDocument, SplineKind};
pub use document::{
    line_geometry, profile_document, region_document, regions_geometry, segment_document,
    shape_document,
};
pub use drawing::{Chain, DrawingRead, Skipped, MAX_CHAINS};
pub use errors::{CurveFileError, Problem};
pub use inputs::{
    parse_drawing, parse_region, read_curve, read_curve_as, read_curve_picked, read_region,
    read_region_as, DrawingFormat, InputFormat, STDIN_NAME, STDIN_PATH,
};
pub use profile::{MAX_HOLES, MAX_PARTS, MAX_SEGMENTS};

// (The readers' shared pieces, for the submodules that read each kind and format.)
use curve_file::{parse_shape, reject_unknown, shape};
use fields::{out_of_range, wrong_type, FieldError, Fields};

/// Largest accepted magnitude of any number: keeps products of several coordinates (curvature
/// numerators are cubic in the homogeneous points) far from overflow.
pub const MAX_ABS: f64 = 1e100;
/// Largest accepted degree: root isolation cost grows quickly with the degree.
pub const MAX_DEGREE: usize = 64;
/// Largest accepted number of lobes `m` of a `convexities` curve: the work grows as `m²` (the
/// curve has about `1.9 m²` antipodal pairs; `m = 100`, 19,000 of them, takes half a second).
pub const MAX_LOBES: u32 = 100;
