//! What the curve commands found, each result on a smooth curve or on a profile, and a
//! drawing's doubt laid on them.

use serde::Serialize;

/// What `inflections` found: on a smooth curve, or on a profile (with its corners).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum InflectionsFound {
    /// On a spline or an analytic shape.
    Curve(antipodal::Inflections),
    /// On a profile: also the corners.
    Profile(antipodal::ProfileInflections),
}

/// What `antipodal` found: on a smooth curve, or on a profile (pairs with corners, families
/// with end points).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum AntipodalFound {
    /// On a spline or an analytic shape.
    Curve(antipodal::Antipodal),
    /// On a profile.
    Profile(antipodal::ProfileAntipodal),
}

/// What `tangents` found: between two smooth curves, or where one is a profile.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum TangentsFound {
    /// Between two splines or analytic shapes.
    Curve(antipodal::Tangents),
    /// Where one curve or both are profiles.
    Profile(antipodal::ProfileTangents),
}

/// What `bisector` found: of splines, or where one curve is a profile.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum BisectorFound {
    /// Of one or two splines (lines and arcs among them).
    Curve(zeroset::Bisector),
    /// Where one curve or both are profiles.
    Profile(zeroset::ProfileBisector),
}

/// Results that say whether they are certified: a drawing's doubt makes them not.
pub(super) trait Doubted {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>);

    /// Not certified, for `doubt` (where there is one and the result has no reason of its
    /// own).
    fn doubted(mut self, doubt: Option<String>) -> Self
    where
        Self: Sized,
    {
        if let Some(why) = doubt {
            let (certified, reason) = self.certified_mut();
            *certified = false;
            reason.get_or_insert(why);
        }
        self
    }
}

impl Doubted for InflectionsFound {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>) {
        match self {
            InflectionsFound::Curve(f) => (&mut f.certified, &mut f.reason),
            InflectionsFound::Profile(f) => (&mut f.certified, &mut f.reason),
        }
    }
}

impl Doubted for AntipodalFound {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>) {
        match self {
            AntipodalFound::Curve(f) => (&mut f.certified, &mut f.reason),
            AntipodalFound::Profile(f) => (&mut f.certified, &mut f.reason),
        }
    }
}

impl Doubted for TangentsFound {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>) {
        match self {
            TangentsFound::Curve(f) => (&mut f.certified, &mut f.reason),
            TangentsFound::Profile(f) => (&mut f.certified, &mut f.reason),
        }
    }
}
