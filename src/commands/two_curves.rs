//! The two-curve commands (`tangents`, `bisector`), on smooth curves or, where one is a
//! profile, on profiles.

use super::errors::{antipodal_error, refuse, zeroset_error};
use super::found::Doubted;
use super::params::{DocMap, InDocument};
use super::prepared::{smooth_map, spline_with_corners};
use super::{as_profile, one_curve, validate_options, BisectorFound, CommandError, TangentsFound};
use crate::io::{Curve, CurveKind};

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
        antipodal::profile_tangents(&a, &b, opts).map(|f| {
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
    let found = if analytic || needs_profiles(&curves)? {
        let profiles = curves
            .iter()
            .map(|c| as_profile(c, "bisector"))
            .collect::<Result<Vec<_>, _>>()?;
        let maps: Vec<DocMap<'_>> = profiles.iter().map(DocMap::Profile).collect();
        match &profiles[..] {
            [a, b] => zeroset::profile_bisector(a, b, opts),
            [one, ..] => zeroset::profile_self_bisector(one, opts),
            [] => unreachable!("one curve at least"),
        }
        .map(|f| BisectorFound::Profile(f.into_document(&maps)))
    } else {
        let rationals = curves
            .iter()
            .map(|c| spline_of(c))
            .collect::<Result<Vec<_>, _>>()?;
        let maps: Vec<DocMap<'_>> = curves.iter().map(|c| smooth_map(c)).collect();
        match &rationals[..] {
            [a, b] => zeroset::bisector(a, b, opts),
            [one, ..] => zeroset::self_bisector(one, opts),
            [] => unreachable!("one curve at least"),
        }
        .map(|f| BisectorFound::Curve(f.into_document(&maps)))
    };
    found.map_err(zeroset_error)
}

/// Bisectors are computed on the exact rational form, which only spline kinds have.
fn spline_of(c: &Curve) -> Result<&bspline::Rational, CommandError> {
    c.rational().ok_or_else(|| {
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
