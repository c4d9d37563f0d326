//! The offset's loops read back as the tool's reader would read them: whether loops with
//! fitted pieces are simple closed profiles, apart from each other.

use crate::{OffsetLoop, OffsetSegment};
use curve::Region;

/// Whether a loop has a fitted piece (the offset of a spline).
fn has_fitted(l: &OffsetLoop) -> bool {
    l.segments
        .iter()
        .any(|s| matches!(s, OffsetSegment::BSpline { .. }))
}

/// What the tool's reader makes of loops with fitted pieces.
#[derive(Debug, PartialEq)]
pub(crate) enum ReadBack {
    /// Simple closed profiles, no two crossing.
    Simple,
    /// A loop crosses itself, or two loops cross.
    Crossing,
    /// A loop is refused for another reason.
    Refused(curve::Error),
}

/// Reads back the loops with fitted pieces as the tool's reader would (each a profile, and
/// all of them, where there are several, as the boundaries of regions).
pub(crate) fn read_back(loops: &[OffsetLoop]) -> ReadBack {
    if !loops.iter().any(has_fitted) {
        return ReadBack::Simple;
    }
    let mut profiles = Vec::with_capacity(loops.len());
    for l in loops {
        match l.profile() {
            Ok(p) => profiles.push(p),
            Err(curve::Error::SelfCrossing { .. }) => return ReadBack::Crossing,
            Err(bad) => return ReadBack::Refused(bad),
        }
    }
    if profiles.len() < 2 {
        return ReadBack::Simple;
    }
    match Region::nested(profiles) {
        Ok(_) => ReadBack::Simple,
        Err(curve::Error::BoundariesCross { .. }) => ReadBack::Crossing,
        Err(bad) => ReadBack::Refused(bad),
    }
}
