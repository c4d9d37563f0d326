//! Regions from drawings (see `docs/interfaces.md`, "Profiles, regions and drawing files"):
//! the closed profiles of a drawing nested inside each other by even-odd nesting
//! ([`curve::Region::nested`]); a command that takes a region gets the one the file holds,
//! or the one `--pick N` chooses.

use super::drawing::{error, pick_one};
use super::{Curve, CurveFileError, Problem, Shape};
use curve::{Profile, Region};

/// The region a command takes from a drawing's profiles (open ones are left out).
pub(super) fn pick_region(
    file: &str,
    profiles: Vec<Profile>,
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    let regions = Region::nested(profiles)
        .map_err(|e| error(file, "document", Problem::Geometry(e.to_string())))?;
    let none = "the file holds no closed outline to make a region of";
    let region = pick_one(file, regions, pick, "regions", none)?;
    Ok(Curve {
        file: file.to_string(),
        shape: Shape::Region(Box::new(region)),
    })
}
