//! The tool's commands as library calls on curves already read, shared by the command line,
//! its batch mode and the Python package: each picks the algorithm for the curve's shape (a
//! spline or analytic shape, a profile, a region), turns the library's errors into the tool's
//! (bad input names its file and field), and gives the result the tool prints with `--json`
//! ([`json_document`]).
//!
//! ```
//! use curvekit::commands::{self, PreparedCurve};
//! use curvekit::io::parse_curve;
//! use std::sync::Arc;
//!
//! let text = r#"{"kind":"bspline","degree":3,"periodic":true,
//!                "points":[[0,0],[2,-1],[4,0],[4,2],[2,1.2],[0,2]]}"#;
//! let curve = Arc::new(parse_curve("cubic.json", text).unwrap());
//! let prepared = PreparedCurve::new(curve.clone(), "antipodal").unwrap();
//! let found = prepared.antipodal(&antipodal::Options::default()).unwrap();
//! let doc = commands::json_document(&found, &[&curve], None);
//! assert!(doc.starts_with("{\"certified\":true"));
//! ```

mod documents;
mod errors;
mod found;
mod grasps;
mod params;
mod parts;
mod prepared;
mod regions;
mod settings;
mod two_curves;

pub use documents::{json_document, json_document_of, CurveSummary, DrawingSummary, Stats};
use errors::{antipodal_error, refuse};
pub use errors::{CommandError, FailureKind, UsageError};
pub use found::{AntipodalFound, BisectorFound, Found, InflectionsFound, TangentsFound};
pub use grasps::{grasps, validate_grasp_options};
/// The verdict every result answers (`certified()`, `reason()`), and the doubts it reads.
pub use numeric::certificate::{Doubt, Doubts, Verdict};
pub use prepared::{antipodal, inflections, PreparedCurve};
pub use regions::{
    medial, offset, size_of, validate_distances, validate_offset, validate_vcarve_options, vcarve,
    Distances, MAX_OFFSETS,
};
pub use settings::{settings, CommandFamily};
pub use two_curves::{bisector, tangents};

use crate::io::{Curve, CurveKind};
use curve::Profile;

/// The one-curve and two-curve commands' own options checked on their own (the tool checks
/// them before it reads a file: a usage error comes first; the settings they carry are
/// valid by construction, see [`settings`]).
pub fn validate_options(opts: &antipodal::Options) -> Result<(), CommandError> {
    opts.validate().map_err(|e| antipodal_error(e, &[]))
}

/// A region is no curve: the commands on curves refuse it by name.
fn one_curve(curves: &[&Curve], command: &str) -> Result<(), CommandError> {
    for c in curves {
        match &c.shape {
            CurveKind::Region(_) => {
                return Err(refuse(
                    c,
                    "kind",
                    &format!("{command} takes a curve or a profile, not a region"),
                ))
            }
            CurveKind::Regions(parts) => {
                return Err(refuse(
                    c,
                    "kind",
                    &format!(
                        "{command} takes one curve, and the input holds {} parts: choose one \
                         with --pick N (0 to {})",
                        parts.len(),
                        parts.len() - 1
                    ),
                ))
            }
            _ => {}
        }
    }
    Ok(())
}

/// A curve as a profile: itself, or the profile of one segment in the curve's own parameter
/// (a line, an arc, a spline, an analytic shape's exact form; cut at its corners).
pub fn as_profile(c: &Curve, command: &str) -> Result<Profile, CommandError> {
    match &c.shape {
        CurveKind::Profile(p) => Ok(p.as_ref().clone()),
        CurveKind::Region(_) | CurveKind::Regions(_) => Err(refuse(
            c,
            "kind",
            &format!("{command} takes a curve or a profile, not a region"),
        )),
        _ => match crate::io::curve_profile(c) {
            Some(made) => made.map_err(CommandError::Input),
            None => unreachable!("every curve but a profile or a region has a profile"),
        },
    }
}
