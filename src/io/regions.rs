//! Regions from drawings (see `docs/interfaces.md`, "Profiles, regions and drawing files"):
//! the closed profiles of a drawing nested inside each other by even-odd nesting
//! ([`curve::Region::nested`]); a command that takes a region gets the one the file holds,
//! or the one `--pick N` chooses.

use super::drawing::error;
use super::{Curve, CurveFileError, Problem, Shape};
use curve::{Profile, Region};

/// The region a command takes from a drawing's profiles (open ones are left out).
pub(super) fn pick_region(
    file: &str,
    profiles: Vec<Profile>,
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    let mut regions = Region::nested(profiles)
        .map_err(|e| error(file, "document", Problem::Geometry(e.to_string())))?;
    let n = regions.len();
    let chosen = match (pick, n) {
        (_, 0) => {
            return Err(error(
                file,
                "document",
                Problem::Geometry("the file holds no closed outline to make a region of".into()),
            ))
        }
        (None, 1) => 0,
        (None, _) => {
            return Err(error(
                file,
                "document",
                Problem::Unsupported(format!(
                    "the file holds {n} regions: choose one with --pick N (0 to {})",
                    n - 1
                )),
            ))
        }
        (Some(k), _) if k < n => k,
        (Some(k), _) => {
            return Err(error(
                file,
                "--pick",
                Problem::OutOfRange {
                    rule: format!("below {n}, the number of regions in the file"),
                    value: k as f64,
                },
            ))
        }
    };
    Ok(Curve {
        file: file.to_string(),
        shape: Shape::Region(Box::new(regions.swap_remove(chosen))),
    })
}
