//! The two-curve commands (`tangents`, `bisector`), on smooth curves or, where one is a
//! profile, on profiles.

use super::errors::{antipodal_error, zeroset_error};
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
    let found = if analytic || needs_profiles(&curves)? {
        let profiles = profiles_of(&curves)?;
        let maps: Vec<DocMap<'_>> = profiles.iter().map(DocMap::Profile).collect();
        on_profiles(&profiles, opts).map(|f| BisectorFound::Profile(f.into_document(&maps)))
    } else if curves
        .iter()
        .all(|c| matches!(c.shape, CurveKind::Segment(_)))
    {
        // Lines and arcs go as profiles of their one segment, so that their closed forms
        // apply (two arcs of one circle: its centre). Written as the curves' document: no
        // sites, each parameter the segment's own (a profile of one segment spans its own
        // domain).
        let profiles = profiles_of(&curves)?;
        let maps: Vec<DocMap<'_>> = profiles.iter().map(DocMap::Profile).collect();
        on_profiles(&profiles, opts)
            .map(|f| BisectorFound::Curve(f.without_sites().into_document(&maps)))
    } else {
        // Smooth splines, and lines or arcs beside them, are the curves they are: the curve
        // engine on their rational forms, in their own parameters. (No closed form takes a
        // spline; as a profile, a spline would lose its own parameter's last digits on a
        // domain other than [0, 2^k] and a periodic one its whole curve, for the same points.)
        match curves[..] {
            [a, b] => zeroset::bisector(a.plane_curve(), b.plane_curve(), opts),
            [one, ..] => zeroset::self_bisector(one.plane_curve(), opts),
            [] => unreachable!("one curve at least"),
        }
        .map(|f| BisectorFound::Curve(f.into_document(&maps_of(&curves))))
    };
    found.map_err(zeroset_error)
}

/// How the curves' exact forms' parameters map to their documents' (a line's or an arc's
/// own).
fn maps_of<'a>(curves: &[&'a Curve]) -> Vec<DocMap<'a>> {
    curves.iter().map(|c| smooth_map(c)).collect()
}

/// The bisector's inputs as profiles.
fn profiles_of(curves: &[&Curve]) -> Result<Vec<Profile>, CommandError> {
    curves.iter().map(|c| as_profile(c, "bisector")).collect()
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
