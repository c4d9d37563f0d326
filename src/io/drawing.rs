//! Drawing files (SVG and ASCII DXF, see `docs/interfaces.md`, "Profiles, regions and drawing
//! files"): each reader turns the file's geometry into chains of segments, and here each
//! chain becomes a profile; the command gets the one profile the file holds, or the one
//! `--pick N` chooses.

use super::{Curve, CurveFileError, Problem, Shape, MAX_SEGMENTS};
use curve::{Profile, Segment};

/// Chains one file may hold (each is checked, and a command's work grows with them).
pub const MAX_CHAINS: usize = 10_000;

/// Segments joined end to end, as a reader found them.
#[derive(Debug, Clone)]
pub struct Chain {
    /// Where it came from, for messages: `path[2] subpath 1`, `LWPOLYLINE 2F`.
    pub name: String,
    /// The segments in order.
    pub segments: Vec<Segment>,
    /// Closed as drawn (an SVG `Z`, a DXF closed flag), or `None` to decide by the ends.
    pub closed: Option<bool>,
}

/// The profile of each chain, in order.
pub(super) fn profiles(file: &str, chains: Vec<Chain>) -> Result<Vec<Profile>, CurveFileError> {
    if chains.len() > MAX_CHAINS {
        return Err(error(
            file,
            "document",
            Problem::OutOfRange {
                rule: format!("at most {MAX_CHAINS} profiles"),
                value: chains.len() as f64,
            },
        ));
    }
    chains
        .into_iter()
        .map(|c| {
            if c.segments.len() > MAX_SEGMENTS {
                return Err(error(
                    file,
                    &c.name,
                    Problem::OutOfRange {
                        rule: format!("at most {MAX_SEGMENTS} segments"),
                        value: c.segments.len() as f64,
                    },
                ));
            }
            Profile::new(c.segments, c.closed).map_err(|e| {
                let field = match e {
                    curve::Error::Gap { segment, .. }
                    | curve::Error::ZeroLength { segment }
                    | curve::Error::Cusp { segment, .. }
                    | curve::Error::SelfCrossing {
                        second: segment, ..
                    } => format!("{} segment {segment}", c.name),
                    _ => c.name.clone(),
                };
                error(file, &field, Problem::Geometry(e.to_string()))
            })
        })
        .collect()
}

/// The curve a command takes from a drawing: its one profile, or the `pick`-th (from 0).
pub(super) fn pick_profile(
    file: &str,
    profiles: Vec<Profile>,
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    let p = pick_one(
        file,
        profiles,
        pick,
        "profiles",
        "the file holds no usable geometry",
    )?;
    Ok(Curve {
        file: file.to_string(),
        shape: Shape::Profile(Box::new(p)),
    })
}

/// The one item of a drawing (`what`: what they are, plural), or the `pick`-th (from 0);
/// `none` says why there is none.
pub(super) fn pick_one<T>(
    file: &str,
    mut items: Vec<T>,
    pick: Option<usize>,
    what: &str,
    none: &str,
) -> Result<T, CurveFileError> {
    let n = items.len();
    let chosen = match (pick, n) {
        (_, 0) => return Err(error(file, "document", Problem::Geometry(none.into()))),
        (None, 1) => 0,
        (None, _) => {
            return Err(error(
                file,
                "document",
                Problem::Unsupported(format!(
                    "the file holds {n} {what}: choose one with --pick N (0 to {})",
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
                    rule: format!("below {n}, the number of {what} in the file"),
                    value: k as f64,
                },
            ))
        }
    };
    Ok(items.swap_remove(chosen))
}

pub(super) fn error(file: &str, field: &str, problem: Problem) -> CurveFileError {
    CurveFileError {
        file: file.to_string(),
        field: field.to_string(),
        problem,
    }
}
