//! The commands on regions (`medial`, `offset`, `vcarve`), each part of a multi-part input
//! on its own, and the checks of their options.

use super::errors::{refuse, vcarve_error};
use super::params::{self, InDocument};
use super::settings::sized;
use super::{parts, CommandError, UsageError};
use crate::io::Curve;

/// The medial axis of a region read (as [`crate::io::read_region`] gives it), its feet in
/// each boundary's own parameter; of every part of a multi-part input, each node and edge
/// saying its part.
pub fn medial(
    region: &Curve,
    opts: &medial::MedialOptions,
) -> Result<medial::MedialAxis, CommandError> {
    let mut axes = axes_of_parts(region, opts)?;
    for (axis, part) in axes.iter_mut().zip(region.parts()) {
        axis.in_document(&params::region_maps(part));
    }
    Ok(parts::joined_axes(axes, region.drawing_outline_doubt()))
}

/// The medial axis of each part, its feet in the boundaries' profile parameters (as the
/// offsets take it), with the tolerances relative to the size of all the parts together.
fn axes_of_parts(
    region: &Curve,
    opts: &medial::MedialOptions,
) -> Result<Vec<medial::MedialAxis>, CommandError> {
    let parts = region.parts();
    if parts.is_empty() {
        return Err(refuse(region, "kind", "medial takes a region"));
    }
    if opts.exterior && parts.len() > 1 {
        return Err(refuse(
            region,
            "document",
            &format!(
                "the exterior axis (--exterior, --outward) of {} parts together is not computed:                  choose one with --pick N (0 to {})",
                parts.len(),
                parts.len() - 1
            ),
        ));
    }
    let opts = medial::MedialOptions {
        settings: sized(&opts.settings, parts::size_of(&parts))?,
        ..*opts
    };
    parts
        .iter()
        .map(|r| medial::medial_axis(r, &opts).map_err(CommandError::Medial))
        .collect()
}

/// The distances `offset` is asked for.
#[derive(Debug, Clone, PartialEq)]
pub enum Distances {
    /// These, in this order.
    List(Vec<f64>),
    /// Every multiple of the step while the region lasts (up to its widest inscribed disk).
    Step(f64),
}

/// Most offsets one call computes (`--step` against the widest disk): beyond, a pocketing
/// operation of that many passes is a typo.
pub const MAX_OFFSETS: usize = 10_000;

/// The distances checked on their own (as [`validate_options`](super::validate_options)):
/// each finite and positive.
pub fn validate_distances(distances: &Distances) -> Result<(), CommandError> {
    let positive = |flag: &str, d: f64| {
        if d.is_finite() && d > 0.0 {
            Ok(())
        } else {
            Err(UsageError::out_of_range(flag, d, "must be a finite number > 0").into())
        }
    };
    match distances {
        Distances::List(list) if list.is_empty() => {
            Err(UsageError::Missing("offset: no distance given").into())
        }
        Distances::List(list) => list.iter().try_for_each(|&d| positive("distance", d)),
        Distances::Step(s) => positive("step", *s),
    }
}

/// The distances checked ([`validate_distances`]) for offsets inward, or `outward`: a step
/// has no last pass outward, where the offsets never vanish.
pub fn validate_offset(distances: &Distances, outward: bool) -> Result<(), CommandError> {
    validate_distances(distances)?;
    if outward && matches!(distances, Distances::Step(_)) {
        return Err(UsageError::Conflict(
            "--step: outward offsets never vanish, so a step has no last pass: give \
             --distance or --distances",
        )
        .into());
    }
    Ok(())
}

/// The offsets of a region read (as [`crate::io::read_region`] gives it), from its medial
/// axis computed with `medial_opts`: inward, or outward with `medial_opts.exterior` (from the
/// exterior axis).
pub fn offset(
    region: &Curve,
    distances: &Distances,
    opts: &offset::OffsetOptions,
    medial_opts: &medial::MedialOptions,
) -> Result<offset::Offsets, CommandError> {
    validate_offset(distances, medial_opts.exterior)?;
    let axes = axes_of_parts(region, medial_opts)?;
    let list = match distances {
        Distances::List(list) => list.clone(),
        Distances::Step(step) => {
            let widest = axes
                .iter()
                .flat_map(|axis| {
                    axis.edges
                        .iter()
                        .flat_map(|e| e.radius.iter().copied())
                        .chain(axis.nodes.iter().map(|n| n.radius))
                })
                .fold(0.0, f64::max);
            let count = (widest / step).floor();
            if count > MAX_OFFSETS as f64 {
                return Err(UsageError::out_of_range(
                    "step",
                    step,
                    format!("gives more than {MAX_OFFSETS} offsets in this region"),
                )
                .into());
            }
            (1..=count as usize).map(|k| k as f64 * step).collect()
        }
    };
    let parts = region.parts();
    let opts = offset::OffsetOptions {
        settings: sized(&opts.settings, parts::size_of(&parts))?,
    };
    let found = parts
        .iter()
        .zip(&axes)
        .map(|(r, axis)| {
            if medial_opts.exterior {
                offset::outward_offsets(r, axis, &list, &opts)
            } else {
                offset::offsets(r, axis, &list, &opts)
            }
            .map_err(|e| match e {
                offset::Error::Cancelled => CommandError::Offset(e),
                _ => UsageError::Offset(e).into(),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(parts::joined_offsets(found, region.drawing_outline_doubt()))
}

/// The V-carving tool paths of a region read (as [`crate::io::read_region`] gives it), from
/// the medial axis of each part computed with `medial_opts`, with the flat passes' offsets
/// relative to the size of all the parts.
pub fn vcarve(
    region: &Curve,
    opts: &offset::VCarveOptions,
    medial_opts: &medial::MedialOptions,
) -> Result<offset::VCarve, CommandError> {
    validate_vcarve_options(opts)?;
    if medial_opts.exterior {
        return Err(UsageError::Conflict(
            "vcarve: the tool path follows the inner medial axis, not the exterior one",
        )
        .into());
    }
    let axes = axes_of_parts(region, medial_opts)?;
    let parts = region.parts();
    let opts = offset::VCarveOptions {
        offset: offset::OffsetOptions {
            settings: sized(&opts.offset.settings, parts::size_of(&parts))?,
        },
        ..*opts
    };
    let found = parts
        .iter()
        .zip(&axes)
        .map(|(r, axis)| offset::vcarve(r, axis, &opts).map_err(vcarve_error))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(parts::joined_carves(found, region.drawing_outline_doubt()))
}

/// The V-carving options checked on their own (as
/// [`validate_options`](super::validate_options)).
pub fn validate_vcarve_options(opts: &offset::VCarveOptions) -> Result<(), CommandError> {
    opts.validate().map_err(vcarve_error)
}

/// The contract's size of a region read: max(width, height) of the bounding box of all its
/// parts (0 for a curve that is no region).
pub fn size_of(region: &Curve) -> f64 {
    parts::size_of(&region.parts())
}
