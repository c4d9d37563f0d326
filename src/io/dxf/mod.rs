//! ASCII DXF drawings (see `docs/interfaces.md`, "Profiles, regions and drawing files" and
//! "Parameters, sizes and drawings"): the model-space curves of the ENTITIES section (`LINE`,
//! `ARC`, `CIRCLE`, `ELLIPSE`, `LWPOLYLINE`, `POLYLINE` with bulges, `SPLINE`), with block
//! references (`INSERT`) expanded, chained end to end into profiles; everything else counted
//! as skipped, by type, and the unit of `$INSUNITS` reported. Nothing is dropped silently: an
//! entity is read, or counted in [`DrawingRead::skipped`] with its name and why (those that
//! could be part of an outline make every answer on the drawing uncertified), or the file is
//! refused, naming it.
//!
//! **How it is read** ([`text`]). A small tokenizer of the file's code/value line pairs finds
//! the HEADER, BLOCKS and ENTITIES sections and gives each record's type, handle (code `5`),
//! paper-space flag (code `67`) and, for splines, its groups as written. The BLOCKS and
//! ENTITIES sections are parsed with the `dxf` crate, whose reading is checked against the
//! records: it silently drops an entity interrupted by a malformed value or a blank line,
//! which is refused here instead. `SPLINE`s are read from their groups ([`spline`]): the crate
//! drops every control point of a spline written without `30` (z) groups, as 2D writers do.
//! The BLOCKS section is parsed only for a drawing with block references; the rest of the
//! file (tables, objects; the header but `$INSUNITS`) is not read.
//!
//! **Curves** ([`entities`]).
//! - `LINE`: a line (zero-length lines, within the tolerance below, are nothing).
//! - `ARC`: angles in degrees, counterclockwise from start to end (an end below the start
//!   goes once more round; equal angles, or a sweep within
//!   [`ANGLE_ROUNDING`](entities::ANGLE_ROUNDING) of nothing or of a full turn, make a full
//!   circle). `CIRCLE`: a closed profile of one full-turn arc.
//! - `ELLIPSE`: centre, major axis end point (relative to the centre), ratio of the minor axis
//!   to the major, and start and end eccentric angles in radians, counterclockwise about the
//!   extrusion direction; a full turn is a closed profile by itself.
//! - `LWPOLYLINE` and 2D `POLYLINE` (its `VERTEX` entities; spline-frame control vertices are
//!   left out, the fitted vertices kept): a line between consecutive vertices, or an arc where
//!   the first has a bulge `b = tan(θ/4)` (θ the included angle, counterclockwise when
//!   positive); repeated vertices are skipped; the closed flag (bit 1 of code 70) adds the
//!   piece from the last vertex back to the first. A 3D `POLYLINE` (bit 8) is read in plan
//!   view when its vertices are at one height.
//! - `SPLINE`: degree (71), knots (40, interior multiplicities kept), control points (10/20),
//!   weights (41: used whenever given, one per control point; the rational flag, bit 4 of
//!   code 70, without weights is refused). Fit points (11/21) are not control points: a spline
//!   given by fit points only is refused. A spline whose knots are not clamped (periodic
//!   splines are written so, with their first control points repeated at the end) is
//!   restricted to its domain by knot insertion, which is exact; one flagged closed or
//!   periodic (bits 1, 2) must then end where it starts. Interior knots of multiplicity equal
//!   to the degree where the curve turns are corners (the profile is cut there), a degree-1
//!   spline is a polygon, and a clamped spline closed by its points has a corner at its seam
//!   unless it is smooth there.
//!
//! **The drawing's plane.** Entities are read in plan view, each in a plane parallel to the
//! drawing's (its height, z, does not matter). `ARC`, `CIRCLE`, `LWPOLYLINE` and 2D
//! `POLYLINE` are given in their object coordinate system: with the extrusion direction
//! (210/220/230) (0, 0, −1), common in mirrored CAD output, its x axis is the world's −x, so
//! they are mirrored in x. `LINE`, `ELLIPSE`, `SPLINE` and 3D `POLYLINE`s are given in world
//! coordinates (an ellipse with extrusion (0, 0, −1) runs clockwise as seen from above). An
//! entity with any other extrusion direction, a `LINE`, 3D `POLYLINE` or `SPLINE` whose points'
//! heights differ (by more than the join tolerance of its size), or an `ELLIPSE` whose major
//! axis leaves the plane, is out of the drawing's plane: skipped as part of an outline, named
//! with its heights (`POLYLINE 2C is a 3D polyline off the drawing's plane (z from 0 to 10)`),
//! not projected.
//!
//! **Block references** ([`blocks`]). An `INSERT` places its block's entities (the BLOCKS
//! section's `BLOCK` of that name, names compared without case; anonymous `*` blocks alike)
//! where they are in the file: block coordinates less the block's base point (10/20), scaled
//! (41/42; negative scales mirror; 43 moves no point of the plane), rotated (50, degrees;
//! quarter turns exact), moved to the insertion point (10/20), all in the reference's object
//! coordinates (extrusion (0, 0, −1) mirrors in x; any other skips the reference). A MINSERT
//! array (70 columns, 71 rows, 44/45 their spacing) places one copy per cell, offset by the
//! spacing turned by the rotation, not scaled; cells at one place (spacing 0) are placed once.
//! References inside blocks are expanded in turn, their transforms composed; each segment is
//! moved exactly ([`curve::Affine`]: arcs stay arcs under similarities and become elliptic
//! arcs under non-uniform scales). Each entity placed is named by its path, `INSERT 2A >
//! CIRCLE 3F` (`INSERT 2A (row 1, column 0) > …` in an array, from 0). Blocks never
//! inserted are not drawn. A reference is skipped, as part of an outline and named with why,
//! when its block is not defined, is defined twice, is an external reference (XREF, flags
//! 4, 8), is being expanded already (a cycle), or lies deeper than
//! [`MAX_NESTING`](blocks::MAX_NESTING) levels, or when it places nothing (a scale of 0, an
//! array of no cells). The work is bounded: past [`MAX_PLACED`](blocks::MAX_PLACED) entities,
//! array cells and points placed by references the drawing is refused, naming the entity.
//!
//! **Skipped.** Every entity not read is counted by its type ([`DrawingRead::skip`]), inside
//! blocks once per copy placed: text (`TEXT`, `MTEXT`, `ATTRIB` and `ATTDEF`), annotation
//! (`DIMENSION`, `LEADER`, …), fills (`HATCH`), points, images, construction lines, meshes and
//! other surfaces, none of them part of an outline; and any other type (`SOLID`, `MLINE`,
//! `REGION`, proxies, …), which could be. Entities in paper space (code 67) are counted as
//! `paper space`: the sheet, not the model. Every layer is read. A drawing of which nothing is
//! read but something is skipped is refused, naming what was skipped.
//!
//! **Units** ([`header`]). `$INSUNITS` 1 to 20 (`in`, `ft`, `mi`, `mm`, `cm`, `m`, `km`, `uin`,
//! `mil`, `yd`, `angstrom`, `nm`, `um`, `dm`, `dam`, `hm`, `Gm`, `au`, `ly`, `pc`) and 21 to
//! 24 (the US survey foot, inch, yard and mile, `us_ft` …) are [`DrawingRead::units`]; 0
//! (unitless) or no `$INSUNITS` is none; any other value is refused.
//!
//! **Chaining** ([`pieces`], [`chain`]). Closed entities (circles, full ellipses, closed
//! splines, closed polylines) are profiles by themselves; every other piece (a line, an arc, a
//! partial ellipse, an open spline, an open polyline with its vertices in their order) is
//! joined to others at its ends. Two ends join when they are within the drawing's tolerance,
//! [`JOIN_GAP`](curve::JOIN_GAP) (1e-9) of its size (the diagonal of the box of all entities'
//! end and control points, polyline vertices and bulge middles, where references put them),
//! or a few units of rounding of its largest coordinate. A grid of cells of half the
//! tolerance finds each end's partners in constant time. Three or more ends at one point are
//! a branch: refused, naming the entities. A chain starts at the first unused piece in file
//! order and grows at its end, then at its start, taking each piece forwards or reversed; it
//! is closed when it comes back to its own start. Two open ends of the drawing nearer than
//! [`NEAR_MISS`](pieces::NEAR_MISS) of its size (and
//! [`NEAR_MISS_OWN`](chain::NEAR_MISS_OWN) of their chains' sizes) are a gap in an outline
//! that was meant to close: refused, naming the entity and where the gap is. Profiles are
//! ordered by the position of their first entity in the file (references expanded in place)
//! and named after it: its type and handle (`LINE 2F`), or its place in the ENTITIES section
//! (or its block) when it has no handle (`LINE #3`, from 1).

mod blocks;
mod chain;
mod entities;
mod header;
mod pieces;
mod spline;
mod text;

use super::drawing::{error, DrawingRead};
use super::{CurveFileError, Problem};
use blocks::Blocks;
use chain::chain_pieces;
use pieces::Tolerance;
use text::{load_section, pair_up, scan};

/// The chains of segments of an ASCII DXF drawing, in the order of their first entities in the
/// file (see the module documentation), what was not read, and the drawing's units; refused
/// when it holds no geometry that is read but some that is not, naming it. One group, filled
/// even-odd: outlines nested inside each other alternate between part and hole.
pub(super) fn read(file: &str, bytes: &[u8]) -> Result<DrawingRead, CurveFileError> {
    let fail = |(field, problem): Failure| error(file, &field, problem);
    let document = |problem: Problem| error(file, "document", problem);
    if bytes.starts_with(b"AutoCAD Binary DXF") || bytes.starts_with(b"AutoCAD DXB") {
        return Err(document(Problem::Unsupported(
            "a binary DXF (or DXB) file: only ASCII DXF is read".into(),
        )));
    }
    let text = scan(bytes).map_err(document)?;
    let mut read = DrawingRead {
        units: header::units(text.insunits.as_deref()).map_err(fail)?,
        ..DrawingRead::default()
    };
    let drawing = load_section(bytes, &text.entities, "ENTITIES").map_err(document)?;
    let entities = drawing.as_ref().map(|d| d.entities());
    let listed = pair_up(
        entities.into_iter().flatten(),
        &text.entities.records,
        "ENTITIES section",
    )
    .map_err(fail)?;
    // (The BLOCKS section is read where a reference needs it: a section the crate cannot
    // read refuses only a drawing that inserts its blocks.)
    let inserts = text
        .entities
        .records
        .iter()
        .any(|r| r.kind == "INSERT" && !r.paper_space);
    let block_drawing = match inserts {
        true => load_section(bytes, &text.blocks, "BLOCKS"),
        false => Ok(None),
    };
    let blocks = Blocks::new(
        block_drawing
            .as_ref()
            .map(Option::as_ref)
            .map_err(Clone::clone),
        &text.blocks,
    );
    let items = blocks::expand(&blocks, &listed, &mut read).map_err(fail)?;
    let tol = Tolerance::of(&items);
    let pieces = items
        .into_iter()
        .map(|item| item.piece(tol.join))
        .collect::<Result<Vec<_>, _>>()
        .map_err(fail)?;
    read.chains = chain_pieces(pieces, &tol).map_err(fail)?;
    if read.chains.is_empty() && !read.skipped.is_empty() {
        let what: Vec<&str> = read.skipped.iter().map(|s| s.first.as_str()).collect();
        return Err(document(Problem::Geometry(format!(
            "the file holds no usable geometry: what it holds was not read ({})",
            what.join("; ")
        ))));
    }
    Ok(read)
}

/// An error before the file name is attached: (field, problem).
type Failure = (String, Problem);
