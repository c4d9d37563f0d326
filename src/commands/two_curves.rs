//! The two-curve commands (`tangents`, `bisector`), on smooth curves or, where one is a
//! profile, on profiles.

use super::errors::{antipodal_error, refuse, zeroset_error};
use super::found::Doubted;
use super::params::{DocMap, InDocument};
use super::prepared::{smooth_map, spline_with_corners};
use super::{as_profile, one_curve, validate_options, BisectorFound, CommandError, TangentsFound};
use crate::io::{Curve, CurveKind};
use curve::Profile;

/// The lines tangent to two curves; where one is a profile, the other is taken as a
/// one-segment profile (a line, an arc, an open or clamped spline).
pub fn tangents(
    c1: &Curve,
    c2: &Curve,
    opts: &antipodal::Options,
) -> Result<TangentsFound, CommandError> {
    validate_options(opts)?;
    let both = [c1, c2];
    one_curve(&both, "tangents")?;
    let found = if needs_profiles(&both)? {
        let (a, b) = (as_profile(c1, "tangents")?, as_profile(c2, "tangents")?);
        antipodal::common_tangents(&a, &b, opts).map(|f| {
            TangentsFound::Profile(f.into_document(&[DocMap::Profile(&a), DocMap::Profile(&b)]))
        })
    } else {
        let (a, b) = antipodal::prepare_pair(c1.plane_curve(), c2.plane_curve());
        a.common_tangents(&b, opts)
            .map(|f| TangentsFound::Curve(f.into_document(&[smooth_map(c1), smooth_map(c2)])))
    };
    let doubt = c1
        .drawing_outline_doubt()
        .or_else(|| c2.drawing_outline_doubt());
    found
        .map(|f| f.doubted(doubt))
        .map_err(|e| antipodal_error(e, &both))
}

/// Whether a command on several curves runs on profiles: where one is a profile or a spline
/// with corners (the others are then taken as profiles of one segment).
fn needs_profiles(curves: &[&Curve]) -> Result<bool, CommandError> {
    for c in curves {
        if matches!(c.shape, CurveKind::Profile(_)) || spline_with_corners(c)?.is_some() {
            return Ok(true);
        }
    }
    Ok(false)
}

/// The bisector of two curves, or the self-bisector of one (`c2` `None`); where one is a
/// profile, the other is taken as a one-segment profile.
pub fn bisector(
    c1: &Curve,
    c2: Option<&Curve>,
    opts: &zeroset::BisectorOptions,
) -> Result<BisectorFound, CommandError> {
    let curves: Vec<&Curve> = std::iter::once(c1).chain(c2).collect();
    one_curve(&curves, "bisector")?;
    // (An analytic shape has no spline of its own: it is taken as the profile of its exact
    // form, in its angle.)
    let analytic = curves
        .iter()
        .any(|c| matches!(c.shape, CurveKind::Analytic(_)));
    let found = if curves.iter().all(|c| spline_in_profile_exactly(c)) {
        // Splines go as profiles: one smooth segment is the curve it is (zeroset runs the
        // curve's bisector on it), written as the curve's document; a spline with corners is
        // the profile of its pieces.
        let profiles = profiles_of(&curves)?;
        let maps: Vec<DocMap<'_>> = profiles.iter().map(DocMap::Profile).collect();
        let found = on_profiles(&profiles, opts);
        if profiles.iter().any(has_corners) {
            found.map(|f| BisectorFound::Profile(f.into_document(&maps)))
        } else {
            found.map(|f| BisectorFound::Curve(f.without_sites().into_document(&maps)))
        }
    } else if analytic || needs_profiles(&curves)? {
        let profiles = profiles_of(&curves)?;
        let maps: Vec<DocMap<'_>> = profiles.iter().map(DocMap::Profile).collect();
        on_profiles(&profiles, opts).map(|f| BisectorFound::Profile(f.into_document(&maps)))
    } else {
        // Lines and arcs read as curves (and the splines beside them, or on a domain the
        // profile's parameter would round) keep the zero set of their rational forms in this
        // step: a profile would take their closed forms, which change the results (for the
        // better: a circle's centre found), a later step of its own.
        let splines = curves
            .iter()
            .map(|c| spline_of(c))
            .collect::<Result<Vec<_>, _>>()?;
        let maps: Vec<DocMap<'_>> = curves.iter().map(|c| smooth_map(c)).collect();
        match splines[..] {
            [a, b] => zeroset::bisector(a, b, opts),
            [one, ..] => zeroset::self_bisector(one, opts),
            [] => unreachable!("one curve at least"),
        }
        .map(|f| BisectorFound::Curve(f.into_document(&maps)))
    };
    found.map_err(zeroset_error)
}

/// Whether `c` is a spline whose parameter a profile of it carries exactly: its domain is
/// `[0, 2^k]` (a Bézier's `[0, 1]`, a B-spline's on its default knots, a periodic one of
/// `2^k` points), so the profile's parameter, its share of the domain, and the document's
/// parameter again differ only in the exponent. On other domains that round trip can change
/// the last digit, which the curve's document would show (on `[0.15, 2.7]`, of about 1 % of
/// parameters; on `[0, 49)`, of 1 and of parameters just below powers of two).
fn spline_in_profile_exactly(c: &Curve) -> bool {
    /// The fraction bits of an `f64`: zero on a power of two.
    const FRACTION_BITS: u64 = (1 << 52) - 1;
    let (a, b) = c.domain();
    matches!(c.shape, CurveKind::Spline(_))
        && a == 0.0
        && b.is_normal()
        && b > 0.0
        && b.to_bits() & FRACTION_BITS == 0
}

/// The bisector's inputs as profiles.
fn profiles_of(curves: &[&Curve]) -> Result<Vec<Profile>, CommandError> {
    curves.iter().map(|c| as_profile(c, "bisector")).collect()
}

/// Whether a profile has corners or several segments: a spline so read is the profile of its
/// pieces (as `prepared::spline_with_corners` takes it).
fn has_corners(p: &Profile) -> bool {
    p.segments().len() > 1 || p.corners().next().is_some()
}

/// The bisector of two profiles, or the self-bisector of one.
fn on_profiles(
    profiles: &[Profile],
    opts: &zeroset::BisectorOptions,
) -> zeroset::Result<zeroset::Bisector> {
    match profiles {
        [a, b] => zeroset::bisector(a, b, opts),
        [one, ..] => zeroset::self_bisector(one, opts),
        [] => unreachable!("one curve at least"),
    }
}

/// A curve read as a curve has its bisector computed on its exact rational form, which only
/// spline kinds (lines and arcs among them) have: the curve as that spline.
fn spline_of(c: &Curve) -> Result<&dyn curve::PlaneCurve, CommandError> {
    c.rational().map(|_| c.plane_curve()).ok_or_else(|| {
        refuse(
            c,
            "kind",
            &format!(
                "bisector needs a bezier, bspline, line or arc curve, got {}",
                c.kind()
            ),
        )
    })
}
