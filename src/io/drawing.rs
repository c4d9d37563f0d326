//! Drawing files (SVG and ASCII DXF, see `docs/interfaces.md`, "Profiles, regions and drawing
//! files"): each reader turns the file's geometry into chains of segments, and here each
//! chain becomes a profile; the command gets the one profile the file holds, or the one
//! `--pick N` chooses.

use super::{Curve, CurveFileError, CurveKind, Problem};
use curve::{FillRule, Profile, Segment};
use serde::{Deserialize, Serialize};

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
    /// The group it is filled with (an SVG element; 0 for a DXF drawing): a drawing is the
    /// union of its groups' fills ([`curve::Region::filled`]).
    pub group: usize,
    /// The group's fill rule (even-odd nesting for outlines drawn without fill, and DXF).
    pub rule: FillRule,
}

/// What a drawing's reader found: its chains, what it did not read, and its units.
#[derive(Debug, Clone, Default)]
pub struct DrawingRead {
    /// The chains, in the order of their first entity or element in the file.
    pub chains: Vec<Chain>,
    /// What was not read, by type, in the order first met.
    pub skipped: Vec<Skipped>,
    /// The unit of the coordinates, where the drawing says (`mm`, `in`, …).
    pub units: Option<String>,
}

/// Entities or elements of one type that a reader did not read (the contract's `skipped`
/// gives their type and count: [`Skipped::entry`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Skipped {
    /// The type: a DXF entity type (`TEXT`, `INSERT`), an SVG element (`text`), or what a
    /// reader left out of the outlines (`open chain`).
    #[serde(rename = "type")]
    pub kind: String,
    /// How many.
    pub count: usize,
    /// Whether they could be part of an outline (a curve, a 3D polyline off the plane, a block
    /// that could not be expanded): then no answer on the drawing is certified.
    pub outline: bool,
    /// The first one's name and why it was not read, for the reason an answer gives.
    pub first: String,
}

impl Skipped {
    /// The contract's entry: `{"type", "count"}`.
    pub fn entry(&self) -> serde_json::Value {
        serde_json::json!({"type": self.kind, "count": self.count})
    }
}

impl DrawingRead {
    /// Counts one more of `kind` not read (`outline`: it could be part of an outline; `why`:
    /// its name and why, kept for the first of its type).
    pub fn skip(&mut self, kind: &str, outline: bool, why: impl FnOnce() -> String) {
        match self.skipped.iter_mut().find(|s| s.kind == kind) {
            Some(s) => {
                s.count += 1;
                s.outline |= outline;
            }
            None => self.skipped.push(Skipped {
                kind: kind.to_string(),
                count: 1,
                outline,
                first: why(),
            }),
        }
    }
}

/// A chain's profile, with its name and how it is filled.
pub(super) struct DrawnProfile {
    pub(super) profile: Profile,
    pub(super) name: String,
    pub(super) group: usize,
    pub(super) rule: FillRule,
}

/// The profile of each chain, in order.
pub(super) fn profiles(
    file: &str,
    chains: Vec<Chain>,
) -> Result<Vec<DrawnProfile>, CurveFileError> {
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
            super::profile::at_most_max_segments(c.segments.len(), "segments")
                .map_err(|p| error(file, &c.name, p))?;
            let profile = Profile::new(c.segments, c.closed).map_err(|e| {
                let field = match super::profile::segment_at_fault(&e) {
                    Some(segment) => format!("{} segment {segment}", c.name),
                    None => c.name.clone(),
                };
                error(file, &field, Problem::Geometry(e.to_string()))
            })?;
            Ok(DrawnProfile {
                profile,
                name: c.name,
                group: c.group,
                rule: c.rule,
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
    Ok(Curve::new(file, CurveKind::Profile(Box::new(p))))
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
