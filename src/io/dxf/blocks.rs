//! Block references: the BLOCKS section's definitions, and the entities of the ENTITIES
//! section read in order with each `INSERT` expanded in its place by its transform, every
//! entity it places named by its path (`INSERT 2A > CIRCLE 3F`); what is not read is counted
//! in the drawing's `skipped`, by type.

use super::entities::{number, plane, point, shape_of, EntityError, Item, Outcome, Plane, MIRROR};
use super::text::{pair_up, Listed, Record, Section, READ_TYPES};
use super::Failure;
use crate::io::drawing::DrawingRead;
use crate::io::Problem;
use curve::Affine;
use dxf::entities::{Entity, EntityType, Insert};
use std::collections::hash_map::Entry;
use std::collections::HashMap;

/// Deepest nesting of block references expanded (a reference of the ENTITIES section is at
/// depth 1): drawings nest blocks a few levels; a reference deeper is skipped, named.
pub(super) const MAX_NESTING: usize = 16;

/// Most entities, array cells and points (polyline vertices, spline control points) block
/// references may place in all: each costs work and memory, and references multiply (ten
/// references to a block of ten references to …); repeated holes and symbols place thousands.
pub(super) const MAX_PLACED: usize = 500_000;

/// Records that belong to the entity before them (a polyline's vertices, the end of its
/// vertices or of a reference's attributes): not entities of their own.
const PARTS: [&str; 2] = ["VERTEX", "SEQEND"];

/// Entity types not read that are no part of an outline (text, annotation, fills, markers,
/// images, construction lines, surfaces), and what each is. Every other type not read could be
/// part of an outline.
const NOT_OUTLINES: [(&str, &str); 30] = [
    ("TEXT", "text"),
    ("MTEXT", "text"),
    ("ATTRIB", "text (a block reference's attribute)"),
    ("ATTDEF", "text (an attribute definition)"),
    ("DIMENSION", "a dimension"),
    ("ARC_DIMENSION", "a dimension"),
    ("LARGE_RADIAL_DIMENSION", "a dimension"),
    ("LEADER", "an annotation"),
    ("MLEADER", "an annotation"),
    ("MULTILEADER", "an annotation"),
    ("TOLERANCE", "an annotation"),
    ("ACAD_TABLE", "a table"),
    ("HATCH", "a fill (of outlines drawn by other entities)"),
    ("POINT", "a point"),
    ("SHAPE", "a symbol"),
    ("IMAGE", "an image"),
    ("WIPEOUT", "a mask"),
    ("OLEFRAME", "an embedded object"),
    ("OLE2FRAME", "an embedded object"),
    ("VIEWPORT", "a view"),
    ("XLINE", "an infinite construction line"),
    ("RAY", "an infinite construction line"),
    ("3DFACE", "a surface"),
    ("MESH", "a surface"),
    ("LIGHT", "a light"),
    ("SUN", "a light"),
    ("UNDERLAY", "an underlay"),
    ("PDFUNDERLAY", "an underlay"),
    ("DWFUNDERLAY", "an underlay"),
    ("DGNUNDERLAY", "an underlay"),
];

/// A block definition.
struct Def<'a> {
    /// Its name as written.
    name: String,
    base: [f64; 2],
    /// The path of the drawing it refers to, for an external reference (XREF).
    xref: Option<String>,
    /// Its entities, or why they cannot be read (refused when the block is inserted).
    entities: Result<Vec<Listed<'a>>, Failure>,
    /// Whether another block has the same name.
    ambiguous: bool,
}

/// The BLOCKS section's definitions, by name (upper case: names are case-insensitive).
#[derive(Default)]
pub(super) struct Blocks<'a> {
    by_name: HashMap<String, Def<'a>>,
    /// Why the section could not be read at all (refused when a block is inserted).
    unreadable: Option<Problem>,
}

impl<'a> Blocks<'a> {
    /// The definitions of the `dxf` crate's reading of the BLOCKS section, each paired with
    /// its records as written.
    pub(super) fn new(
        drawing: Result<Option<&'a dxf::Drawing>, Problem>,
        section: &'a Section<'a>,
    ) -> Blocks<'a> {
        let drawing = match drawing {
            Ok(Some(d)) => d,
            Ok(None) => return Blocks::default(),
            Err(p) => {
                return Blocks {
                    unreadable: Some(p),
                    ..Blocks::default()
                }
            }
        };
        let ours = block_records(&section.records);
        let theirs: Vec<&dxf::Block> = drawing.blocks().collect();
        if theirs.len() != ours.len() {
            return Blocks {
                unreadable: Some(Problem::Unsupported(format!(
                    "the BLOCKS section holds {} blocks, and the DXF reader read {}",
                    ours.len(),
                    theirs.len()
                ))),
                ..Blocks::default()
            };
        }
        let mut by_name: HashMap<String, Def<'a>> = HashMap::with_capacity(ours.len());
        for (block, records) in theirs.into_iter().zip(ours) {
            let label = format!("block {}", block.name);
            let entities = pair_up(block.entities.iter(), records, &label).map_err(|(field, p)| {
                match field.as_str() {
                    "document" => (label.clone(), p),
                    _ => (field, p),
                }
            });
            let def = Def {
                name: block.name.clone(),
                base: [block.base_point.x, block.base_point.y],
                // (Flags 4: an external reference; 8: one overlaid.)
                xref: (block.flags & (4 | 8) != 0).then(|| block.xref_path_name.clone()),
                entities,
                ambiguous: false,
            };
            match by_name.entry(block.name.to_uppercase()) {
                Entry::Occupied(mut o) => o.get_mut().ambiguous = true,
                Entry::Vacant(v) => {
                    v.insert(def);
                }
            }
        }
        Blocks {
            by_name,
            unreadable: None,
        }
    }
}

/// Each block's entity records (between its `BLOCK` and `ENDBLK`), in order.
fn block_records<'r, 'a>(records: &'r [Record<'a>]) -> Vec<&'r [Record<'a>]> {
    let mut out = Vec::new();
    let mut rest = records;
    while let Some(start) = rest.iter().position(|r| r.kind == "BLOCK") {
        let body = rest.get(start + 1..).unwrap_or_default();
        let end = body
            .iter()
            .position(|r| r.kind == "ENDBLK" || r.kind == "BLOCK")
            .unwrap_or(body.len());
        out.push(body.get(..end).unwrap_or_default());
        rest = body.get(end..).unwrap_or_default();
    }
    out
}

/// The items of the ENTITIES section's entities `listed`, block references expanded, and what
/// was not read counted in `read`.
pub(super) fn expand(
    blocks: &Blocks<'_>,
    listed: &[Listed<'_>],
    read: &mut DrawingRead,
) -> Result<Vec<Item>, Failure> {
    let mut reader = Reader {
        blocks,
        read,
        items: Vec::new(),
        placed: 0,
    };
    let top = Place {
        map: Affine::IDENTITY,
        path: String::new(),
        blocks: Vec::new(),
    };
    reader.list(listed, &top)?;
    Ok(reader.items)
}

/// Where entities are being read: the block references on the way to them.
struct Place {
    /// From their block's coordinates to the world's.
    map: Affine,
    /// The references' path, `INSERT 2A > ` (empty in the ENTITIES section).
    path: String,
    /// The blocks expanded on the way, outermost first: (upper-case name, name).
    blocks: Vec<(String, String)>,
}

struct Reader<'b, 'a> {
    blocks: &'b Blocks<'a>,
    read: &'b mut DrawingRead,
    items: Vec<Item>,
    /// What block references have placed so far (see [`MAX_PLACED`]).
    placed: usize,
}

impl Reader<'_, '_> {
    /// Reads entities in order, at `place`.
    fn list(&mut self, listed: &[Listed<'_>], place: &Place) -> Result<(), Failure> {
        let top = place.blocks.is_empty();
        for l in listed {
            let r = l.record;
            if PARTS.contains(&r.kind.as_ref()) {
                continue;
            }
            let name = format!("{}{}", place.path, r.name());
            if !top {
                self.charge(1, &name)?;
            }
            // (An entity of a block is where its reference puts it, whatever its own code 67.)
            if top && r.paper_space {
                self.read.skip("paper space", false, || {
                    format!("{name} is in paper space (code 67): on the sheet, not in the model")
                });
                continue;
            }
            match (r.kind.as_ref(), l.entity) {
                ("INSERT", Some(e)) => self.insert(e, &name, place)?,
                (kind, Some(e)) if READ_TYPES.contains(&kind) => self.entity(e, r, name, place)?,
                (kind, _) => self.not_read(kind, &name),
            }
        }
        Ok(())
    }

    /// Counts `n` more placed by block references; refused past [`MAX_PLACED`], naming the
    /// entity being placed.
    fn charge(&mut self, n: usize, name: &str) -> Result<(), Failure> {
        self.placed = self.placed.saturating_add(n);
        if self.placed > MAX_PLACED {
            return Err((
                name.to_string(),
                Problem::OutOfRange {
                    rule: format!(
                        "at most {MAX_PLACED} entities, array cells and points placed by block \
                         references in all"
                    ),
                    value: self.placed as f64,
                },
            ));
        }
        Ok(())
    }

    /// A curve entity: its shape where `place` puts it, or why it is not read.
    fn entity(
        &mut self,
        e: &Entity,
        r: &Record<'_>,
        name: String,
        place: &Place,
    ) -> Result<(), Failure> {
        let at = |(what, p): EntityError| named(&name, what, p);
        match shape_of(e, r).map_err(at)? {
            Outcome::EntityShape(shape) => {
                let shape = shape.moved(&place.map).map_err(at)?;
                if !place.blocks.is_empty() {
                    self.charge(shape.points(), &name)?;
                }
                let order = self.items.len();
                self.items.push(Item { order, name, shape });
            }
            Outcome::Nothing => {}
            Outcome::Skip { outline, why } => {
                self.read.skip(&r.kind, outline, || format!("{name} {why}"));
            }
        }
        Ok(())
    }

    /// An entity of a type not read: counted, as part of an outline unless known not to be.
    fn not_read(&mut self, kind: &str, name: &str) {
        match NOT_OUTLINES.iter().find(|(k, _)| *k == kind) {
            Some((_, what)) => self
                .read
                .skip(kind, false, || format!("{name} is {what}: not read")),
            None => self.read.skip(kind, true, || {
                format!("{name}: {kind} entities are not read, and it could be part of an outline")
            }),
        }
    }

    /// A block reference: its block's entities read where each of its cells puts them, or
    /// the reference skipped, saying why.
    fn insert(&mut self, e: &Entity, name: &str, place: &Place) -> Result<(), Failure> {
        let EntityType::Insert(ins) = &e.specific else {
            return Ok(());
        };
        let skip = |read: &mut DrawingRead, why: String| -> Result<(), Failure> {
            read.skip("INSERT", true, || format!("{name} {why}"));
            Ok(())
        };
        let n = &ins.extrusion_direction;
        let mirrored = match plane([n.x, n.y, n.z]).map_err(|(w, p)| named(name, w, p))? {
            Plane::Level { mirrored } => mirrored,
            Plane::Off(why) => return skip(self.read, why),
        };
        if let Some(p) = &self.blocks.unreadable {
            return Err((name.to_string(), p.clone()));
        }
        let key = ins.name.to_uppercase();
        let Some(def) = self.blocks.by_name.get(&key) else {
            let why = format!(
                "refers to block `{}`, which the drawing does not define",
                ins.name
            );
            return skip(self.read, why);
        };
        if def.ambiguous {
            let why = format!(
                "refers to block `{}`, which the drawing defines twice",
                def.name
            );
            return skip(self.read, why);
        }
        if let Some(path) = &def.xref {
            let why = format!(
                "refers to block `{}`, an external reference (XREF) to {path:?}: another \
                 drawing, not read",
                def.name
            );
            return skip(self.read, why);
        }
        if let Some(k) = place.blocks.iter().position(|(b, _)| *b == key) {
            let cycle: Vec<&str> = place
                .blocks
                .get(k..)
                .unwrap_or_default()
                .iter()
                .map(|(_, n)| n.as_str())
                .chain([def.name.as_str()])
                .collect();
            let why = format!(
                "inserts block `{}` inside itself ({}): not expanded",
                def.name,
                cycle.join(" > ")
            );
            return skip(self.read, why);
        }
        if place.blocks.len() >= MAX_NESTING {
            let why = format!(
                "is a block reference nested {} deep, beyond the {MAX_NESTING} levels read: \
                 not expanded",
                place.blocks.len() + 1
            );
            return skip(self.read, why);
        }
        let entities = def
            .entities
            .as_ref()
            .map_err(|(field, p)| (format!("{name} > {field}"), p.clone()))?;
        let cells = match Cells::of(ins, def.base).map_err(|(w, p)| named(name, w, p))? {
            Ok(cells) => cells,
            Err(why) => return skip(self.read, why),
        };
        let array = cells.columns * cells.rows > 1;
        for row in 0..cells.rows {
            for column in 0..cells.columns {
                let here = match array {
                    true => format!("{name} (row {row}, column {column})"),
                    false => name.to_string(),
                };
                self.charge(1, &here)?;
                let mut inner = Place {
                    map: place.map.after(&cells.map(column, row, mirrored)),
                    path: format!("{here} > "),
                    blocks: place.blocks.clone(),
                };
                inner.blocks.push((key.clone(), def.name.clone()));
                self.list(entities, &inner)?;
            }
        }
        Ok(())
    }
}

/// The field `what` of the entity `name` (the entity itself when empty).
fn named(name: &str, what: String, p: Problem) -> Failure {
    match what.is_empty() {
        true => (name.to_string(), p),
        false => (format!("{name} {what}"), p),
    }
}

/// The cells of a block reference (one, or a MINSERT's array) and their transform.
struct Cells {
    /// The block's base point, the insertion point (in the reference's object coordinates).
    base: [f64; 2],
    at: [f64; 2],
    scale: [f64; 2],
    /// The rotation's sine and cosine.
    turn: (f64, f64),
    spacing: [f64; 2],
    columns: i64,
    rows: i64,
}

impl Cells {
    /// The cells of `ins` (block base point `base`), or why it places nothing (a scale of 0,
    /// an array of no cells). Cells at one place (spacing 0) are placed once, as CAD programs
    /// show them: a copy on a copy.
    fn of(ins: &Insert, base: [f64; 2]) -> Result<Result<Cells, String>, EntityError> {
        let base = point("block base point", base[0], base[1])?;
        let at = point("insertion point", ins.location.x, ins.location.y)?;
        let scale = [
            number("x scale", ins.x_scale_factor)?,
            number("y scale", ins.y_scale_factor)?,
        ];
        let degrees = number("rotation", ins.rotation)?;
        let spacing = [
            number("column spacing", ins.column_spacing)?,
            number("row spacing", ins.row_spacing)?,
        ];
        let (columns, rows) = (i64::from(ins.column_count), i64::from(ins.row_count));
        if scale.contains(&0.0) {
            return Ok(Err(format!(
                "has scales {} and {}: its block collapses onto a line or a point",
                scale[0], scale[1]
            )));
        }
        if columns < 1 || rows < 1 {
            return Ok(Err(format!(
                "is an array of {columns} columns and {rows} rows: no cell to place"
            )));
        }
        Ok(Ok(Cells {
            base,
            at,
            scale,
            turn: sin_cos_degrees(degrees),
            spacing,
            columns: if spacing[0] == 0.0 { 1 } else { columns },
            rows: if spacing[1] == 0.0 { 1 } else { rows },
        }))
    }

    /// The map of the cell (`column`, `row`): block coordinates less the base point, scaled,
    /// rotated, moved to the insertion point and the cell's offset (rotated, not scaled), in
    /// the reference's object coordinates (mirrored in x for extrusion (0, 0, −1)).
    fn map(&self, column: i64, row: i64, mirrored: bool) -> Affine {
        let (s, c) = self.turn;
        let [sx, sy] = self.scale;
        // Columns of the linear part: the images of (1, 0) and (0, 1).
        let l = [c * sx, s * sx, -s * sy, c * sy];
        let (ox, oy) = (
            column as f64 * self.spacing[0],
            row as f64 * self.spacing[1],
        );
        let [bx, by] = self.base;
        let t = [
            self.at[0] + (c * ox - s * oy) - (l[0] * bx + l[2] * by),
            self.at[1] + (s * ox + c * oy) - (l[1] * bx + l[3] * by),
        ];
        let m = Affine([l[0], l[1], l[2], l[3], t[0], t[1]]);
        if mirrored {
            MIRROR.after(&m)
        } else {
            m
        }
    }
}

/// The sine and cosine of an angle in degrees, exact at quarter turns (where the radians'
/// rounding leaves 1e-16 in place of 0).
fn sin_cos_degrees(degrees: f64) -> (f64, f64) {
    let d = degrees.rem_euclid(360.0);
    if d == 0.0 {
        (0.0, 1.0)
    } else if d == 90.0 {
        (1.0, 0.0)
    } else if d == 180.0 {
        (0.0, -1.0)
    } else if d == 270.0 {
        (-1.0, 0.0)
    } else {
        d.to_radians().sin_cos()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_turns_are_exact() {
        assert_eq!(sin_cos_degrees(90.0), (1.0, 0.0));
        assert_eq!(sin_cos_degrees(-90.0), (-1.0, 0.0));
        assert_eq!(sin_cos_degrees(720.0), (0.0, 1.0));
        let (s, c) = sin_cos_degrees(30.0);
        assert!((s - 0.5).abs() < 1e-15 && (c - 0.75f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn a_cell_is_scaled_and_rotated_about_the_base_point_then_moved() {
        let cells = Cells {
            base: [1.0, 0.0],
            at: [10.0, 0.0],
            scale: [2.0, 3.0],
            turn: sin_cos_degrees(90.0),
            spacing: [5.0, 7.0],
            columns: 2,
            rows: 2,
        };
        // The base point goes to the insertion point; (2, 1) is 2 right and 3 up of it before
        // the quarter turn: 3 left and 2 up after.
        let m = cells.map(0, 0, false);
        assert_eq!(m.apply([1.0, 0.0]), [10.0, 0.0]);
        assert_eq!(m.apply([2.0, 1.0]), [7.0, 2.0]);
        // The cell (1, 1)'s offset (5, 7) turns with it, unscaled: (−7, 5).
        assert_eq!(cells.map(1, 1, false).apply([1.0, 0.0]), [3.0, 5.0]);
        // Mirrored object coordinates: x negated after all.
        assert_eq!(cells.map(0, 0, true).apply([2.0, 1.0]), [-7.0, 2.0]);
    }

    #[test]
    fn blocks_records_are_split_at_their_ends() {
        let rec = |kind: &'static str| Record {
            kind: kind.into(),
            handle: None,
            place: 0,
            paper_space: false,
            groups: Vec::new(),
        };
        let records: Vec<Record<'_>> = ["BLOCK", "LINE", "ARC", "ENDBLK", "BLOCK", "ENDBLK"]
            .into_iter()
            .map(rec)
            .collect();
        let blocks = block_records(&records);
        let kinds: Vec<Vec<&str>> = blocks
            .iter()
            .map(|b| b.iter().map(|r| r.kind.as_ref()).collect())
            .collect();
        assert_eq!(kinds, [vec!["LINE", "ARC"], vec![]]);
    }
}
