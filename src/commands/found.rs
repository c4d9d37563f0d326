//! What the curve commands found, each result on a smooth curve or on a profile, and a
//! drawing's doubt laid on them.

use numeric::certificate::{Doubt, Doubts, Verdict};
use serde::Serialize;

/// What a curve command found, and which document the tool writes of it: a smooth curve's,
/// or a profile's (its pairs and lines with their corners and segments, its corners listed).
/// A curve and a profile share one result type; what only a profile has is absent on a
/// curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Found<T> {
    /// On a spline or an analytic shape: the curve's document.
    Curve(T),
    /// On a profile: the profile's document.
    Profile(T),
}

impl<T> Found<T> {
    /// The result, whichever document it is written as.
    pub fn result(&self) -> &T {
        match self {
            Found::Curve(f) | Found::Profile(f) => f,
        }
    }

    /// The result, taken.
    pub fn into_result(self) -> T {
        match self {
            Found::Curve(f) | Found::Profile(f) => f,
        }
    }

    fn result_mut(&mut self) -> &mut T {
        match self {
            Found::Curve(f) | Found::Profile(f) => f,
        }
    }
}

/// What `inflections` found: on a smooth curve, or on a profile (with its corners).
pub type InflectionsFound = Found<antipodal::Inflections>;

/// What `antipodal` found: on a smooth curve, or on a profile (pairs with corners, families
/// with end points).
pub type AntipodalFound = Found<antipodal::Antipodal>;

/// What `tangents` found: between two smooth curves, or where one is a profile.
pub type TangentsFound = Found<antipodal::Tangents>;

/// What `bisector` found: of splines, or where one curve is a profile.
pub type BisectorFound = Found<zeroset::Bisector>;

/// Results that say whether they are certified: a drawing's doubt makes them not.
pub(super) trait Doubted {
    fn doubts_mut(&mut self) -> &mut Doubts;

    /// Not certified, for `doubt` (where there is one; stated after the result's own doubts,
    /// so a result with a reason of its own keeps it).
    fn doubted(mut self, doubt: Option<Doubt>) -> Self
    where
        Self: Sized,
    {
        if let Some(why) = doubt {
            self.doubts_mut().add(why);
        }
        self
    }
}

macro_rules! doubted {
    ($($result:ty),*) => {
        $(impl Doubted for $result {
            fn doubts_mut(&mut self) -> &mut Doubts {
                &mut self.doubts
            }
        })*
    };
}

doubted!(
    antipodal::Inflections,
    antipodal::Antipodal,
    antipodal::Tangents
);

impl<T: Doubted> Doubted for Found<T> {
    fn doubts_mut(&mut self) -> &mut Doubts {
        self.result_mut().doubts_mut()
    }
}

impl<T: Verdict> Verdict for Found<T> {
    fn doubts(&self) -> &Doubts {
        self.result().doubts()
    }
}
