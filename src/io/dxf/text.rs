//! The file as text: its code/value line pairs, read as the `dxf` crate reads them; the
//! records of its BLOCKS and ENTITIES sections as written (type, handle, place, paper space,
//! and a `SPLINE`'s groups), and the HEADER's `$INSUNITS`; and the crate's reading of those two
//! sections, checked against the records.

use super::Failure;
use crate::io::Problem;
use dxf::entities::{Entity, EntityType};
use std::borrow::Cow;

/// Most entity records each of the BLOCKS and ENTITIES sections may hold: bounds the reader's
/// work and memory.
pub(super) const MAX_ENTITIES: usize = 100_000;

/// The curve types read (all other types are skipped, and `INSERT` expanded).
pub(super) const READ_TYPES: [&str; 7] = [
    "LINE",
    "ARC",
    "CIRCLE",
    "ELLIPSE",
    "LWPOLYLINE",
    "POLYLINE",
    "SPLINE",
];

/// Whether the crate's entities of this type are paired with their records: the curves read,
/// and block references.
fn paired(kind: &str) -> bool {
    READ_TYPES.contains(&kind) || kind == "INSERT"
}

/// One record (an entity, or a block's `BLOCK` and `ENDBLK`) of the BLOCKS or ENTITIES section,
/// as written.
#[derive(Debug)]
pub(super) struct Record<'a> {
    /// Its type (`LINE`).
    pub(super) kind: Cow<'a, str>,
    /// Its handle (code 5), if given.
    pub(super) handle: Option<Cow<'a, str>>,
    /// Its place among the section's entities, or its block's, from 1.
    pub(super) place: usize,
    /// In paper space (code 67 other than 0): on the drawing's sheet, not in its model.
    pub(super) paper_space: bool,
    /// Its groups after the type, kept for `SPLINE` only (the crate loses some of them).
    pub(super) groups: Vec<(i32, Cow<'a, str>)>,
}

impl Record<'_> {
    /// `LINE 2F`, or `LINE #3` without a handle.
    pub(super) fn name(&self) -> String {
        match &self.handle {
            Some(h) => format!("{} {}", self.kind, h.trim()),
            None => format!("{} #{}", self.kind, self.place),
        }
    }
}

/// A section: its records, and where it lies in the file's bytes.
#[derive(Debug, Default)]
pub(super) struct Section<'a> {
    pub(super) records: Vec<Record<'a>>,
    /// From its `0 SECTION` to the end of its `0 ENDSEC` (or of the file).
    pub(super) range: Option<(usize, Option<usize>)>,
}

/// What the reader takes from the file's text.
#[derive(Debug, Default)]
pub(super) struct Text<'a> {
    pub(super) blocks: Section<'a>,
    pub(super) entities: Section<'a>,
    /// The value of `$INSUNITS` (its code 70) in the HEADER section, as written.
    pub(super) insunits: Option<Cow<'a, str>>,
}

/// The sections the reader takes records or variables from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum In {
    Header,
    Blocks,
    Entities,
    Other,
}

/// Reads the file's BLOCKS and ENTITIES records, in order (at most [`MAX_ENTITIES`] each),
/// and `$INSUNITS`. The bytes are read as code/value line pairs, as the `dxf` crate reads them
/// (lines end at `\n`, less one `\r` before it; codes trimmed; comments (999) skipped), up to
/// the ENTITIES section's end (the OBJECTS section after it is not the reader's concern).
pub(super) fn scan(bytes: &[u8]) -> Result<Text<'_>, Problem> {
    let mut text = Text::default();
    let mut offset = 0;
    if bytes.starts_with(b"\xEF\xBB\xBF") {
        offset = 3;
    }
    let mut lines = bytes
        .get(offset..)
        .unwrap_or_default()
        .split(|&b| b == b'\n')
        .scan(offset, |at, line| {
            let start = *at;
            *at += line.len() + 1;
            Some((start, line.strip_suffix(b"\r").unwrap_or(line)))
        })
        .enumerate();
    // Where the last `0 SECTION` started, and whether its name is to come next.
    let mut opening: Option<usize> = None;
    let mut current = In::Other;
    // In the HEADER: whether the variable being read is `$INSUNITS`.
    let mut insunits = false;
    // The place of the next entity of the block being read.
    let mut in_block = 0;
    let malformed = |line: usize, what: &str| {
        Problem::Unsupported(format!(
            "not a readable ASCII DXF file: line {line}: {what}"
        ))
    };
    // Each turn takes two lines: the loop ends with the bytes.
    while let Some((i, (at, code_line))) = lines.next() {
        let code_line = String::from_utf8_lossy(code_line);
        let code_line = code_line.trim();
        if code_line.is_empty() {
            // The crate stops at a blank code line as at the end of the file, and would
            // silently leave out whatever follows: only blank lines may.
            if bytes
                .get(at..)
                .unwrap_or_default()
                .iter()
                .all(u8::is_ascii_whitespace)
            {
                break;
            }
            return Err(malformed(
                i + 1,
                "an empty line where a group code should be",
            ));
        }
        let Ok(code) = code_line.parse::<i32>() else {
            return Err(malformed(
                i + 1,
                &format!("`{code_line}` is not a group code"),
            ));
        };
        let Some((_, (_, value))) = lines.next() else {
            return Err(malformed(i + 1, "the file ends after a group code"));
        };
        if code == 999 {
            continue;
        }
        if let Some(section_start) = opening.take() {
            if code == 2 {
                current = match value.trim_ascii() {
                    b"HEADER" => In::Header,
                    b"BLOCKS" => In::Blocks,
                    b"ENTITIES" => In::Entities,
                    _ => In::Other,
                };
                let section = match current {
                    In::Blocks => &mut text.blocks,
                    In::Entities => &mut text.entities,
                    _ => continue,
                };
                section.range = Some((section_start, None));
                continue;
            }
        }
        if code == 0 {
            let section = match current {
                In::Blocks => Some(&mut text.blocks),
                In::Entities => Some(&mut text.entities),
                _ => None,
            };
            match (value, section) {
                (b"SECTION", _) => {
                    opening = Some(at);
                    current = In::Other;
                }
                (b"ENDSEC", section) => {
                    // The end of this value line: the next line's start.
                    let end = lines.clone().next().map(|(_, (next, _))| next);
                    if let Some(s) = section {
                        if let Some((start, _)) = s.range {
                            s.range = Some((start, end.or(Some(bytes.len()))));
                        }
                    }
                    if current == In::Entities {
                        break;
                    }
                    current = In::Other;
                }
                (b"EOF", _) => break,
                (kind, Some(section)) => {
                    if section.records.len() == MAX_ENTITIES {
                        return Err(Problem::OutOfRange {
                            rule: format!("at most {MAX_ENTITIES} entities in a section"),
                            value: (MAX_ENTITIES + 1) as f64,
                        });
                    }
                    let place = if current == In::Blocks {
                        in_block = if kind == b"BLOCK" { 0 } else { in_block + 1 };
                        in_block
                    } else {
                        section.records.len() + 1
                    };
                    section.records.push(Record {
                        kind: String::from_utf8_lossy(kind),
                        handle: None,
                        place,
                        paper_space: false,
                        groups: Vec::new(),
                    });
                }
                _ => {}
            }
            continue;
        }
        let section = match current {
            In::Header => {
                if code == 9 {
                    insunits = value.trim_ascii() == b"$INSUNITS";
                } else if code == 70 && insunits && text.insunits.is_none() {
                    text.insunits = Some(String::from_utf8_lossy(value));
                }
                continue;
            }
            In::Blocks => &mut text.blocks,
            In::Entities => &mut text.entities,
            In::Other => continue,
        };
        if let Some(r) = section.records.last_mut() {
            match code {
                5 if r.handle.is_none() => r.handle = Some(String::from_utf8_lossy(value)),
                // (As the crate reads it: an integer, not 0.)
                67 => r.paper_space = value.trim_ascii() != b"0",
                _ => {}
            }
            if r.kind == "SPLINE" {
                r.groups.push((code, String::from_utf8_lossy(value)));
            }
        }
    }
    Ok(text)
}

/// The `dxf` crate's reading of one section (`label`: its name, for messages), or `None`
/// where the file has none. (The rest of the file is not the reader's concern: its tables
/// and objects are neither read nor checked.)
pub(super) fn load_section(
    bytes: &[u8],
    section: &Section<'_>,
    label: &str,
) -> Result<Option<dxf::Drawing>, Problem> {
    let Some((start, end)) = section.range else {
        return Ok(None);
    };
    let mut text = bytes
        .get(start..end.unwrap_or(bytes.len()))
        .unwrap_or_default()
        .to_vec();
    if end.is_some() {
        text.extend_from_slice(b"0\nEOF\n");
    }
    dxf::Drawing::load(&mut &text[..]).map(Some).map_err(|e| {
        Problem::Unsupported(format!(
            "not a readable ASCII DXF file: in its {label} section: {e}"
        ))
    })
}

/// A record, with the crate's entity for it where its type is paired (a curve read, or a
/// block reference).
#[derive(Debug, Clone, Copy)]
pub(super) struct Listed<'a> {
    pub(super) record: &'a Record<'a>,
    pub(super) entity: Option<&'a Entity>,
}

/// Each record with the crate's entity for it, in order; refused when the two readings
/// disagree (the crate skipped or merged an entity it could not read). `theirs`: the crate's
/// entities of the same records (`label`: where they are, for messages).
pub(super) fn pair_up<'a>(
    theirs: impl Iterator<Item = &'a Entity>,
    records: &'a [Record<'a>],
    label: &str,
) -> Result<Vec<Listed<'a>>, Failure> {
    let mut theirs = theirs.filter(|e| type_name(&e.specific).is_some());
    let mut out = Vec::with_capacity(records.len());
    for record in records {
        if !paired(&record.kind) {
            out.push(Listed {
                record,
                entity: None,
            });
            continue;
        }
        let Some(entity) = theirs.next() else {
            return Err(unreadable(record));
        };
        // (Handles are the records': the crate gives one of its own to an entity written
        // without, or with handle 0.)
        if type_name(&entity.specific) != Some(record.kind.as_ref()) {
            return Err(unreadable(record));
        }
        out.push(Listed {
            record,
            entity: Some(entity),
        });
    }
    if theirs.next().is_some() {
        return Err((
            "document".into(),
            Problem::Unsupported(format!(
                "the DXF reader found entities that are not in the {label}"
            )),
        ));
    }
    Ok(out)
}

pub(super) fn unreadable(record: &Record<'_>) -> Failure {
    (
        record.name(),
        Problem::Unsupported(
            "the entity could not be read (a malformed or missing group value)".into(),
        ),
    )
}

/// The DXF type of the entity kinds paired.
fn type_name(e: &EntityType) -> Option<&'static str> {
    Some(match e {
        EntityType::Line(_) => "LINE",
        EntityType::Arc(_) => "ARC",
        EntityType::Circle(_) => "CIRCLE",
        EntityType::Ellipse(_) => "ELLIPSE",
        EntityType::LwPolyline(_) => "LWPOLYLINE",
        EntityType::Polyline(_) => "POLYLINE",
        EntityType::Spline(_) => "SPLINE",
        EntityType::Insert(_) => "INSERT",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(groups: &[(i32, &str)]) -> String {
        groups.iter().map(|(c, v)| format!("{c}\n{v}\n")).collect()
    }

    #[test]
    fn the_tokenizer_reads_the_header_variable_blocks_and_entities() {
        let t = text(&[
            (999, "a comment"),
            (0, "SECTION"),
            (2, "HEADER"),
            (9, "$MEASUREMENT"),
            (70, "1"),
            (9, "$INSUNITS"),
            (70, "4"),
            (0, "LINE"), // (not an entity: the HEADER section)
            (0, "ENDSEC"),
            (0, "SECTION"),
            (2, "BLOCKS"),
            (0, "BLOCK"),
            (2, "PIN"),
            (0, "CIRCLE"),
            (5, "3F"),
            (0, "TEXT"),
            (0, "ENDBLK"),
            (0, "ENDSEC"),
            (0, "SECTION"),
            (2, "ENTITIES"),
            (0, "LINE"),
            (5, "2F"),
            (0, "SPLINE"),
            (71, "3"),
            (999, "skipped"),
            (10, "1.5"),
            (0, "TEXT"),
            (67, "1"),
            (0, "ENDSEC"),
            (0, "SECTION"),
            (2, "OBJECTS"),
            (0, "LINE"),
        ])
        .replace('\n', "\r\n");
        let read = scan(t.as_bytes()).unwrap();
        assert_eq!(read.insunits.as_deref(), Some("4"));
        let r = &read.entities.records;
        let kinds: Vec<&str> = r.iter().map(|r| r.kind.as_ref()).collect();
        assert_eq!(kinds, ["LINE", "SPLINE", "TEXT"]);
        assert_eq!(r[0].name(), "LINE 2F");
        assert_eq!(r[1].name(), "SPLINE #2");
        assert!(r[2].paper_space && !r[1].paper_space);
        let groups: Vec<(i32, &str)> = r[1].groups.iter().map(|(c, v)| (*c, v.as_ref())).collect();
        assert_eq!(groups, [(71, "3"), (10, "1.5")]);
        assert!(r[0].groups.is_empty(), "groups are kept for splines only");
        // A block's entities are numbered within it.
        let b = &read.blocks.records;
        let names: Vec<String> = b.iter().map(Record::name).collect();
        assert_eq!(names, ["BLOCK #0", "CIRCLE 3F", "TEXT #2", "ENDBLK #3"]);
        // The sections' bytes, as the crate is given them.
        let (a, b) = read.entities.range.unwrap();
        assert!(t[a..].starts_with("0\r\nSECTION\r\n2\r\nENTITIES\r\n"));
        assert!(t[..b.unwrap()].ends_with("0\r\nTEXT\r\n67\r\n1\r\n0\r\nENDSEC\r\n"));
        let (a, b) = read.blocks.range.unwrap();
        assert!(t[a..b.unwrap()].starts_with("0\r\nSECTION\r\n2\r\nBLOCKS\r\n"));
        assert!(t[..b.unwrap()].ends_with("0\r\nENDBLK\r\n0\r\nENDSEC\r\n"));
        // A code line that is not a number, and a file ending after a code: refused.
        assert!(scan(b"0\nSECTION\nx\nENTITIES\n").is_err());
        assert!(scan(b"0\nSECTION\n2").is_err());
        // A blank code line ends the file only where nothing but blank lines follows it.
        assert!(scan(b"0\nSECTION\n2\nENTITIES\n\n0\nLINE\n").is_err());
        assert!(scan(b"0\nSECTION\n2\nENTITIES\n0\nLINE\n\n \r\n\n").is_ok());
    }
}
