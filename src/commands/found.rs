//! What the curve commands found, each result on a smooth curve or on a profile, and a
//! drawing's doubt laid on them.

use numeric::certificate::{Doubt, Doubts, Verdict};
use serde::Serialize;

/// What `inflections` found: on a smooth curve, or on a profile (with its corners). The two
/// share one type; the variant says which document the tool writes.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum InflectionsFound {
    /// On a spline or an analytic shape.
    Curve(antipodal::Inflections),
    /// On a profile: also the corners.
    Profile(antipodal::Inflections),
}

/// What `antipodal` found: on a smooth curve, or on a profile (pairs with corners, families
/// with end points). The two share one type; the variant says which document the tool
/// writes.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum AntipodalFound {
    /// On a spline or an analytic shape.
    Curve(antipodal::Antipodal),
    /// On a profile.
    Profile(antipodal::Antipodal),
}

/// What `tangents` found: between two smooth curves, or where one is a profile. The two share
/// one type; the variant says which document the tool writes.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum TangentsFound {
    /// Between two splines or analytic shapes.
    Curve(antipodal::Tangents),
    /// Where one curve or both are profiles.
    Profile(antipodal::Tangents),
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

/// The verdict (and the doubts) of whichever result each variant holds.
macro_rules! two_ways {
    ($found:ident) => {
        impl Doubted for $found {
            fn doubts_mut(&mut self) -> &mut Doubts {
                match self {
                    $found::Curve(f) => &mut f.doubts,
                    $found::Profile(f) => &mut f.doubts,
                }
            }
        }

        impl Verdict for $found {
            fn doubts(&self) -> &Doubts {
                match self {
                    $found::Curve(f) => &f.doubts,
                    $found::Profile(f) => &f.doubts,
                }
            }
        }
    };
}

two_ways!(InflectionsFound);
two_ways!(AntipodalFound);
two_ways!(TangentsFound);
