//! The file as text: its code/value line pairs, the records of its `ENTITIES` section as
//! written (type, handle, place, and a `SPLINE`'s groups), and the `dxf` crate's reading of
//! that section, checked against them.

use super::Failure;
use crate::io::Problem;
use dxf::entities::{Entity, EntityType};
use std::borrow::Cow;

/// Most entity records the `ENTITIES` section may hold: bounds the reader's work and memory.
pub(super) const MAX_ENTITIES: usize = 100_000;

/// The entity types read (all others are skipped).
pub(super) const READ_TYPES: [&str; 7] = [
    "LINE",
    "ARC",
    "CIRCLE",
    "ELLIPSE",
    "LWPOLYLINE",
    "POLYLINE",
    "SPLINE",
];
/// One entity record of the `ENTITIES` section, as written.
#[derive(Debug)]
pub(super) struct Record<'a> {
    /// Its type (`LINE`).
    pub(super) kind: Cow<'a, str>,
    /// Its handle (code 5), if given.
    pub(super) handle: Option<Cow<'a, str>>,
    /// Its place among the section's records, from 1.
    pub(super) place: usize,
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

/// The `ENTITIES` section: its records, and where it lies in the file's bytes.
#[derive(Debug, Default)]
pub(super) struct Section<'a> {
    pub(super) records: Vec<Record<'a>>,
    /// From its `0 SECTION` to the end of its `0 ENDSEC` (or of the file).
    pub(super) range: Option<(usize, Option<usize>)>,
}

/// Reads the `ENTITIES` section's records, in order (at most [`MAX_ENTITIES`]). The bytes
/// are read as code/value line pairs, as the `dxf` crate reads them (lines end at `\n`, less
/// one `\r` before it; codes trimmed; comments (999) skipped), up to the section's end.
pub(super) fn entity_records(bytes: &[u8]) -> Result<Section<'_>, Problem> {
    let mut section = Section::default();
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
    let mut in_entities = false;
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
                in_entities = value.trim_ascii() == b"ENTITIES";
                if in_entities {
                    section.range = Some((section_start, None));
                }
                continue;
            }
        }
        if code == 0 {
            match value {
                b"SECTION" => {
                    opening = Some(at);
                    in_entities = false;
                }
                b"ENDSEC" if in_entities => {
                    // The end of this value line: the next line's start.
                    let end = lines.clone().next().map(|(_, (next, _))| next);
                    if let Some((start, _)) = section.range {
                        section.range = Some((start, end.or(Some(bytes.len()))));
                    }
                    break;
                }
                b"ENDSEC" => in_entities = false,
                b"EOF" => break,
                kind if in_entities => {
                    if section.records.len() == MAX_ENTITIES {
                        return Err(Problem::OutOfRange {
                            rule: format!("at most {MAX_ENTITIES} entities"),
                            value: (MAX_ENTITIES + 1) as f64,
                        });
                    }
                    let place = section.records.len() + 1;
                    section.records.push(Record {
                        kind: String::from_utf8_lossy(kind),
                        handle: None,
                        place,
                        groups: Vec::new(),
                    });
                }
                _ => {}
            }
            continue;
        }
        if !in_entities {
            continue;
        }
        if let Some(r) = section.records.last_mut() {
            if code == 5 && r.handle.is_none() {
                r.handle = Some(String::from_utf8_lossy(value));
            }
            if r.kind == "SPLINE" {
                r.groups.push((code, String::from_utf8_lossy(value)));
            }
        }
    }
    Ok(section)
}

/// The `dxf` crate's reading of the `ENTITIES` section (the rest of the file is not the
/// reader's concern: its tables and objects are neither read nor checked).
pub(super) fn load_entities(bytes: &[u8], section: &Section<'_>) -> Result<dxf::Drawing, Problem> {
    let Some((start, end)) = section.range else {
        return Ok(dxf::Drawing::new());
    };
    let mut text = bytes
        .get(start..end.unwrap_or(bytes.len()))
        .unwrap_or_default()
        .to_vec();
    if end.is_some() {
        text.extend_from_slice(b"0\nEOF\n");
    }
    dxf::Drawing::load(&mut &text[..]).map_err(|e| {
        Problem::Unsupported(format!(
            "not a readable ASCII DXF file: in its ENTITIES section: {e}"
        ))
    })
}

/// The crate's entities of the types read, each with its record; refused when the two
/// readings disagree (the crate skipped or merged an entity it could not read).
pub(super) fn pair_up<'d, 'r>(
    drawing: &'d dxf::Drawing,
    records: &'r [Record<'r>],
) -> Result<Vec<(&'d Entity, &'r Record<'r>)>, Failure> {
    let ours: Vec<&Record<'_>> = records
        .iter()
        .filter(|r| READ_TYPES.contains(&r.kind.as_ref()))
        .collect();
    let theirs: Vec<&Entity> = drawing
        .entities()
        .filter(|e| type_name(&e.specific).is_some())
        .collect();
    let mut out = Vec::with_capacity(ours.len());
    for (k, record) in ours.iter().enumerate() {
        let Some(entity) = theirs.get(k) else {
            return Err(unreadable(record));
        };
        // (Handles are the records': the crate gives one of its own to an entity written
        // without, or with handle 0.)
        if type_name(&entity.specific) != Some(record.kind.as_ref()) {
            return Err(unreadable(record));
        }
        out.push((*entity, *record));
    }
    if theirs.len() != ours.len() {
        return Err((
            "document".into(),
            Problem::Unsupported(
                "the DXF reader found entities that are not in the ENTITIES section".into(),
            ),
        ));
    }
    Ok(out)
}

fn unreadable(record: &Record<'_>) -> Failure {
    (
        record.name(),
        Problem::Unsupported(
            "the entity could not be read (a malformed or missing group value)".into(),
        ),
    )
}

/// The DXF type of the entity kinds read.
fn type_name(e: &EntityType) -> Option<&'static str> {
    Some(match e {
        EntityType::Line(_) => "LINE",
        EntityType::Arc(_) => "ARC",
        EntityType::Circle(_) => "CIRCLE",
        EntityType::Ellipse(_) => "ELLIPSE",
        EntityType::LwPolyline(_) => "LWPOLYLINE",
        EntityType::Polyline(_) => "POLYLINE",
        EntityType::Spline(_) => "SPLINE",
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
    fn the_tokenizer_reads_the_entities_section_only() {
        let t = text(&[
            (999, "a comment"),
            (0, "SECTION"),
            (2, "HEADER"),
            (0, "LINE"), // (not an entity: the HEADER section)
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
            (0, "ENDSEC"),
            (0, "SECTION"),
            (2, "OBJECTS"),
            (0, "LINE"),
        ])
        .replace('\n', "\r\n");
        let section = entity_records(t.as_bytes()).unwrap();
        let r = &section.records;
        let kinds: Vec<&str> = r.iter().map(|r| r.kind.as_ref()).collect();
        assert_eq!(kinds, ["LINE", "SPLINE", "TEXT"]);
        assert_eq!(r[0].name(), "LINE 2F");
        assert_eq!(r[1].name(), "SPLINE #2");
        let groups: Vec<(i32, &str)> = r[1].groups.iter().map(|(c, v)| (*c, v.as_ref())).collect();
        assert_eq!(groups, [(71, "3"), (10, "1.5")]);
        assert!(r[0].groups.is_empty(), "groups are kept for splines only");
        // The section's bytes, as the crate is given them.
        let (a, b) = section.range.unwrap();
        assert!(t[a..].starts_with("0\r\nSECTION\r\n2\r\nENTITIES\r\n"));
        assert!(t[..b.unwrap()].ends_with("0\r\nTEXT\r\n0\r\nENDSEC\r\n"));
        // A code line that is not a number, and a file ending after a code: refused.
        assert!(entity_records(b"0\nSECTION\nx\nENTITIES\n").is_err());
        assert!(entity_records(b"0\nSECTION\n2").is_err());
        // A blank code line ends the file only where nothing but blank lines follows it.
        assert!(entity_records(b"0\nSECTION\n2\nENTITIES\n\n0\nLINE\n").is_err());
        assert!(entity_records(b"0\nSECTION\n2\nENTITIES\n0\nLINE\n\n \r\n\n").is_ok());
    }
}
