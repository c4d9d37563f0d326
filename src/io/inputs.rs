//! Reading a command's input: a curve file or a drawing (SVG, DXF), from a path or from
//! standard input, as a curve or as the region it bounds.

use super::drawing::{self, DrawingRead};
use super::{
    dxf, parse_curve, profile, regions, svg, Curve, CurveFileError, CurveKind, DrawingInfo,
    FieldError, Problem,
};
use std::path::Path;

/// The region a command on regions takes from a file: a `region` file as it is; any other
/// closed curve with an exact form (a closed profile, a closed `bezier` or `bspline`, a
/// circle, a full-turn arc) as the region it encloses; from a drawing, its closed profiles
/// nested inside each other (even-odd), `pick` choosing among several regions. The curve
/// returned is the region's (`CurveKind::Region`); anything else is bad input naming the file.
pub fn read_region(path: &Path, pick: Option<usize>) -> Result<Curve, CurveFileError> {
    read_region_as(path, None, pick)
}

/// [`read_region`] with the format of an input whose extension does not name one (standard
/// input, the path `-`, among them; `None`: a curve file).
pub fn read_region_as(
    path: &Path,
    format: Option<InputFormat>,
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    let (file, drawing, bytes) = input_bytes(path, format)?;
    parse_region(&file, drawing, &bytes, pick)
}

/// [`read_region`] on a file's bytes: a drawing of `format`, or a curve file (`None`);
/// `file` names it in errors.
pub fn parse_region(
    file: &str,
    format: Option<DrawingFormat>,
    bytes: &[u8],
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    if let Some(format) = format {
        let read = drawing_read(file, format, bytes)?;
        return regions::pick_region(file, read, pick);
    }
    let c = parse_curve(file, utf8_text(file, bytes)?)?;
    let fail = |(field, problem): FieldError| CurveFileError {
        file: c.file.clone(),
        field,
        problem,
    };
    let shape = match c.shape {
        CurveKind::Region(r) => CurveKind::Region(r),
        CurveKind::Regions(parts) => regions::picked_part(file, parts, pick)?,
        shape => {
            let outer = profile::boundary_of("curve", shape).map_err(fail)?;
            let region = curve::Region::new(outer, Vec::new())
                .map_err(|e| fail(("curve".into(), Problem::Geometry(e.to_string()))))?;
            CurveKind::Region(Box::new(region))
        }
    };
    Ok(Curve::new(c.file, shape))
}

/// Reads and validates a curve file, or a drawing (see [`read_curve_picked`]).
pub fn read_curve(path: &Path) -> Result<Curve, CurveFileError> {
    read_curve_picked(path, None)
}

/// Reads and validates a curve file (JSON), or a drawing by its extension: `.svg` (every
/// path's subpaths) or `.dxf` (ASCII DXF entities chained end to end). A drawing's profiles
/// are numbered from 0 in file order; `pick` chooses one where it holds several (a curve
/// file, holding one curve, ignores it).
pub fn read_curve_picked(path: &Path, pick: Option<usize>) -> Result<Curve, CurveFileError> {
    read_curve_as(path, None, pick)
}

/// [`read_curve_picked`] with the format of an input whose extension does not name one
/// (standard input, the path `-`, among them; `None`: a curve file).
pub fn read_curve_as(
    path: &Path,
    format: Option<InputFormat>,
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    let (file, drawing, bytes) = input_bytes(path, format)?;
    match drawing {
        Some(format) => parse_drawing(&file, format, &bytes, pick),
        // (A curve file holds one curve: `pick` is for drawings.)
        None => parse_curve(&file, utf8_text(&file, &bytes)?),
    }
}

/// What a command's input is given as (`--format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InputFormat {
    /// A curve, profile or region file (JSON).
    Json,
    /// An SVG drawing.
    Svg,
    /// An ASCII DXF drawing.
    Dxf,
}

/// The path that names standard input.
pub const STDIN_PATH: &str = "-";

/// The name standard input goes by in messages and reports.
pub const STDIN_NAME: &str = "<stdin>";

/// Most bytes read from standard input: as much as the readers' own limits let through, and a
/// bound on memory where the stream does not end.
const MAX_STDIN_BYTES: u64 = 1 << 30;

/// The text of a file's `bytes` (a curve file, an SVG drawing), refused when it is not UTF-8;
/// `file` names it in the error.
fn utf8_text<'a>(file: &str, bytes: &'a [u8]) -> Result<&'a str, CurveFileError> {
    std::str::from_utf8(bytes)
        .map_err(|e| drawing::error(file, "document", Problem::Syntax(format!("not UTF-8: {e}"))))
}

fn unreadable(file: &str, e: std::io::Error) -> CurveFileError {
    drawing::error(file, "document", Problem::Unreadable(e.to_string()))
}

/// An input's name (for messages), drawing format (`None` for a curve file) and bytes: from
/// standard input for `-` (a curve file unless `format` says otherwise), else from the file,
/// by its extension (`.svg`, `.dxf`, `.json`), or else as `format` says (a curve file unless
/// it does).
fn input_bytes(
    path: &Path,
    format: Option<InputFormat>,
) -> Result<(String, Option<DrawingFormat>, Vec<u8>), CurveFileError> {
    let drawing = |f: InputFormat| match f {
        InputFormat::Json => None,
        InputFormat::Svg => Some(DrawingFormat::Svg),
        InputFormat::Dxf => Some(DrawingFormat::Dxf),
    };
    if path == Path::new(STDIN_PATH) {
        use std::io::Read;
        let mut bytes = Vec::new();
        std::io::stdin()
            .lock()
            .take(MAX_STDIN_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| unreadable(STDIN_NAME, e))?;
        if bytes.len() as u64 > MAX_STDIN_BYTES {
            return Err(drawing::error(
                STDIN_NAME,
                "document",
                Problem::Unreadable(format!("more than {MAX_STDIN_BYTES} bytes")),
            ));
        }
        let format = format.unwrap_or(InputFormat::Json);
        return Ok((STDIN_NAME.to_string(), drawing(format), bytes));
    }
    let file = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    // (An extension that names a format is that format; `format` names the others'.)
    let format = match ext.as_deref() {
        Some("svg") => InputFormat::Svg,
        Some("dxf") => InputFormat::Dxf,
        Some("json") => InputFormat::Json,
        _ => format.unwrap_or(InputFormat::Json),
    };
    let bytes = std::fs::read(path).map_err(|e| unreadable(&file, e))?;
    Ok((file, drawing(format), bytes))
}

/// The formats of drawing files.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DrawingFormat {
    /// SVG (UTF-8 XML).
    Svg,
    /// ASCII DXF.
    Dxf,
}

/// The profile a command takes from a drawing's bytes (see [`read_curve_picked`]); `file`
/// names it in errors.
///
/// ```
/// use curvekit::io::{parse_drawing, DrawingFormat, CurveKind};
/// let svg = br#"<svg xmlns="http://www.w3.org/2000/svg"><rect width="4" height="2"/></svg>"#;
/// let c = parse_drawing("r.svg", DrawingFormat::Svg, svg, None).unwrap();
/// assert!(matches!(c.shape, CurveKind::Profile(ref p) if p.segments().len() == 4));
/// ```
pub fn parse_drawing(
    file: &str,
    format: DrawingFormat,
    bytes: &[u8],
    pick: Option<usize>,
) -> Result<Curve, CurveFileError> {
    let read = drawing_read(file, format, bytes)?;
    let info = DrawingInfo {
        skipped: read.skipped,
        units: read.units,
    };
    let profiles = drawing::profiles(file, read.chains)?
        .into_iter()
        .map(|d| d.profile)
        .collect();
    let mut curve = drawing::pick_profile(file, profiles, pick)?;
    curve.drawing = Some(info);
    Ok(curve)
}

/// What a drawing's bytes hold.
fn drawing_read(
    file: &str,
    format: DrawingFormat,
    bytes: &[u8],
) -> Result<DrawingRead, CurveFileError> {
    match format {
        DrawingFormat::Svg => svg::read(file, utf8_text(file, bytes)?),
        DrawingFormat::Dxf => dxf::read(file, bytes),
    }
}
