//! ASCII DXF drawings (see `docs/interfaces.md`, "Profiles, regions and drawing files"): the
//! model-space entities `LINE`, `ARC`, `CIRCLE`, `ELLIPSE`, `LWPOLYLINE`, `POLYLINE` (with
//! bulges) and `SPLINE` of the `ENTITIES` section, chained end to end into profiles.
//!
//! **What is read.** The `ENTITIES` section is parsed with the `dxf` crate, except `SPLINE`
//! entities, whose group codes are read here from the text: the crate drops every control
//! point of a spline written without `30` (z) groups, as 2D writers do, and keeps the rest
//! only up to the shortest of the `10`/`20`/`30` lists. A small tokenizer of the file's
//! code/value line pairs finds the section, gives the splines' groups and each entity's
//! handle (code `5`) as written, and checks that the crate read every entity: it silently
//! drops an entity interrupted by a malformed value or a blank line, which is refused here
//! instead. The rest of the file (header, tables, blocks, objects) is not read.
//!
//! - `LINE`: a line (zero-length lines, within the tolerance below, are skipped).
//! - `ARC`: angles in degrees, counterclockwise from start to end (an end below the start
//!   goes once more round; equal angles, or a sweep within [`ANGLE_ROUNDING`](entities::ANGLE_ROUNDING) of nothing or of
//!   a full turn, make a full circle). `CIRCLE`: a closed profile of one full-turn arc.
//! - `ELLIPSE`: centre, major axis end point (relative to the centre), ratio of the minor axis
//!   to the major, and start and end eccentric angles in radians, counterclockwise about the
//!   extrusion direction; a full turn is a closed profile by itself.
//! - `LWPOLYLINE` and 2D `POLYLINE` (its `VERTEX` entities; spline-frame control vertices are
//!   left out, the fitted vertices kept): a line between consecutive vertices, or an arc where
//!   the first has a bulge `b = tan(θ/4)` (θ the included angle, counterclockwise when
//!   positive); repeated vertices are skipped; the closed flag (bit 1 of code 70) adds the
//!   piece from the last vertex back to the first. A 3D `POLYLINE` is read in plan view;
//!   polygon and polyface meshes are surfaces, skipped.
//! - `SPLINE`: degree (71), knots (40, interior multiplicities kept), control points (10/20),
//!   weights (41: used whenever given, one per control point; the rational flag, bit 4 of
//!   code 70, without weights is refused). Fit points (11/21) are not control points: a spline
//!   given by fit points only is refused. A spline whose knots are not clamped (periodic
//!   splines are written so, with their first control points repeated at the end) is
//!   restricted to its domain by knot insertion, which is exact; one flagged closed or
//!   periodic (bits 1, 2) must then end where it starts.
//!
//! Entities in paper space (code 67) are left out; every layer is read. Block references
//! (`INSERT`) are skipped, not expanded, and so are all other entity types (`TEXT`,
//! `DIMENSION`, `HATCH`, `POINT`, …). Coordinates are read in plan view: z is ignored.
//!
//! **Extrusion direction** (210/220/230). `ARC`, `CIRCLE`, `LWPOLYLINE` and 2D `POLYLINE` are
//! given in their object coordinate system: with the extrusion direction (0, 0, −1), common in
//! mirrored CAD output, its x axis is the world's −x, so they are mirrored in x. `LINE`,
//! `ELLIPSE` and `SPLINE` are given in world coordinates (an ellipse with extrusion (0, 0, −1)
//! runs clockwise as seen from above). Any other extrusion direction puts the entity out of
//! the drawing's plane: refused, naming the entity.
//!
//! **Chaining.** Closed entities (circles, full ellipses, closed splines, closed polylines) are
//! profiles by themselves; every other piece (a line, an arc, a partial ellipse, an open
//! spline, an open polyline with its vertices in their order) is joined to others at its ends.
//! Two ends join when they are within the drawing's tolerance, [`JOIN_GAP`](curve::JOIN_GAP) (1e-9) of its size
//! (the diagonal of the box of all entities' end and control points, polyline vertices and
//! bulge middles), or a few units of rounding of its largest coordinate. A grid of cells of
//! half the tolerance finds each end's partners in constant time. Three or more ends at one
//! point are a branch: refused, naming the entities. A chain starts at the first unused piece
//! in file order and grows at its end, then at its start, taking each piece forwards or
//! reversed; it is closed when it comes back to its own start. Two open ends of the drawing
//! nearer than [`NEAR_MISS`](pieces::NEAR_MISS) of its size (and [`NEAR_MISS_OWN`](chain::NEAR_MISS_OWN) of their chains' sizes) are a
//! gap in an outline that was meant to close: refused, naming the entity and where the gap
//! is. Profiles are ordered by the position of
//! their first entity in the file and named after it: its type and handle (`LINE 2F`), or its
//! place in the `ENTITIES` section when it has no handle (`LINE #3`, from 1).

mod chain;
mod entities;
mod pieces;
mod spline;
mod text;

use super::drawing::{error, DrawingRead};
use super::{CurveFileError, Problem};
use chain::chain_pieces;
use entities::{shape_of, Item};
use pieces::Tolerance;
use text::{entity_records, load_entities, pair_up};

/// The chains of segments of an ASCII DXF drawing, in the order of their first entities in the
/// file (see the module documentation); empty when it holds no geometry that is read. One
/// group, filled even-odd: outlines nested inside each other alternate between part and hole.
pub(super) fn read(file: &str, bytes: &[u8]) -> Result<DrawingRead, CurveFileError> {
    let fail = |field: &str, problem: Problem| error(file, field, problem);
    if bytes.starts_with(b"AutoCAD Binary DXF") || bytes.starts_with(b"AutoCAD DXB") {
        return Err(fail(
            "document",
            Problem::Unsupported("a binary DXF (or DXB) file: only ASCII DXF is read".into()),
        ));
    }
    let section = entity_records(bytes).map_err(|p| fail("document", p))?;
    let drawing = load_entities(bytes, &section).map_err(|p| fail("document", p))?;
    let entities = pair_up(&drawing, &section.records).map_err(|(field, p)| fail(&field, p))?;

    let mut shapes = Vec::with_capacity(entities.len());
    for (order, (entity, record)) in entities.iter().enumerate() {
        if entity.common.is_in_paper_space {
            continue;
        }
        let name = record.name();
        let shape = shape_of(entity, record).map_err(|(what, p)| {
            let field = if what.is_empty() {
                name.clone()
            } else {
                format!("{name} {what}")
            };
            fail(&field, p)
        })?;
        if let Some(shape) = shape {
            shapes.push(Item { order, name, shape });
        }
    }
    let tol = Tolerance::of(&shapes);
    let pieces = shapes
        .into_iter()
        .map(|item| item.piece(tol.join))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|(field, p)| fail(&field, p))?;
    let chains = chain_pieces(pieces, &tol).map_err(|(field, p)| fail(&field, p))?;
    Ok(DrawingRead {
        chains,
        ..DrawingRead::default()
    })
}

/// An error before the file name is attached: (field, problem).
type Failure = (String, Problem);
