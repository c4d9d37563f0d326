//! Regions from drawings (see `docs/interfaces.md`, "Profiles, regions and drawing files" and
//! "Parameters, sizes and drawings"): the closed profiles of a drawing filled as its renderer
//! fills them ([`curve::Region::filled`]: each group by its rule, the union of the groups),
//! giving one part or several. A command on regions takes them all (a multi-part input), or
//! the part `--pick N` chooses. Open chains bound nothing: they are listed as skipped, and no
//! answer on the drawing is then certified.

use super::drawing::{error, pick_one, profiles, DrawingRead};
use super::{Curve, CurveFileError, CurveKind, DrawingInfo, Problem};
use curve::{FilledOutline, ParamCurve, Region};

/// The region (or regions) a command takes from a drawing: every part, or the `pick`-th.
pub(super) fn pick_region(
    file: &str,
    read: DrawingRead,
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    let mut info = DrawingInfo {
        skipped: read.skipped.clone(),
        units: read.units.clone(),
    };
    let mut drawing = read;
    let drawn = profiles(file, std::mem::take(&mut drawing.chains))?;
    let mut names = Vec::new();
    let mut outlines = Vec::new();
    for d in drawn {
        if d.profile.is_closed() {
            names.push(d.name);
            outlines.push(FilledOutline {
                profile: d.profile,
                group: d.group,
                rule: d.rule,
            });
        } else {
            let n = d.profile.segments().len();
            let gap = (d.profile.segments()[n - 1].end() - d.profile.start()).norm();
            let name = d.name;
            drawing.skip("open chain", true, || {
                format!("{name} is open (its ends are {gap:e} apart)")
            });
        }
    }
    info.skipped = drawing.skipped;
    let parts = Region::filled(outlines).map_err(|e| {
        let message = match e {
            curve::Error::OutlinesCross { first, second, at } => format!(
                "the outlines {} and {} cross or touch at ({}, {}): the drawing's regions are not \
                 those of its outlines",
                names[first], names[second], at[0], at[1]
            ),
            e => e.to_string(),
        };
        error(file, "document", Problem::Geometry(message))
    })?;
    if parts.is_empty() {
        let why = match info.skipped.iter().find(|s| s.kind == "open chain") {
            Some(open) => format!(
                "the file holds no closed outline to make a region of ({})",
                open.first
            ),
            None => "the file holds no closed outline to make a region of".to_string(),
        };
        return Err(error(file, "document", Problem::Geometry(why)));
    }
    let shape = picked_part(file, parts, pick)?;
    Ok(Curve {
        file: file.to_string(),
        shape,
        drawing: Some(info),
    })
}

/// All the parts (one: a region), or the `pick`-th.
pub(super) fn picked_part(
    file: &str,
    mut parts: Vec<Region>,
    pick: Option<usize>,
) -> Result<CurveKind, CurveFileError> {
    if pick.is_none() {
        return Ok(match parts.len() {
            1 => CurveKind::Region(Box::new(parts.swap_remove(0))),
            _ => CurveKind::Regions(parts),
        });
    }
    let none = "the file holds no closed outline to make a region of";
    let part = pick_one(file, parts, pick, "parts", none)?;
    Ok(CurveKind::Region(Box::new(part)))
}
