//! Curve files (see `docs/interfaces.md`, "Curve files"): JSON text → a validated [`Curve`].
//!
//! The reader walks the JSON value itself instead of deriving `Deserialize`, so that every error
//! can name the exact field (`points[3][1]`, `knots[5]`), which serde's messages cannot. Unknown
//! fields are rejected like `#[serde(deny_unknown_fields)]` would, but with the field named.

use bspline::Rational;
use curve::shapes::{Circle, Convexities, Ellipse, EllipticLemniscate, Limacon, Shape as Analytic};
use curve::{ParamCurve, PlaneCurve};
use serde_json::{Map, Value};
use std::path::Path;
use thiserror::Error;

mod document;
mod drawing;
mod duplicates;
mod dxf;
mod profile;
mod regions;
mod spline;
mod svg;

pub use document::{
    line_geometry, profile_document, region_document, regions_geometry, segment_document,
    shape_document,
};
pub use drawing::{Chain, DrawingRead, Skipped, MAX_CHAINS};
pub use profile::{MAX_HOLES, MAX_PARTS, MAX_SEGMENTS};

/// Largest accepted magnitude of any number: keeps products of several coordinates (curvature
/// numerators are cubic in the homogeneous points) far from overflow.
pub const MAX_ABS: f64 = 1e100;
/// Largest accepted degree: root isolation cost grows quickly with the degree.
pub const MAX_DEGREE: usize = 64;
/// Largest accepted number of lobes `m` of a `convexities` curve: the work grows as `m²` (the
/// curve has about `1.9 m²` antipodal pairs; `m = 100`, 19,000 of them, takes half a second).
pub const MAX_LOBES: u32 = 100;

/// A curve file that cannot be used: which file, which field, what is wrong.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{file}: {field}: {problem}")]
pub struct CurveFileError {
    /// The file as named on the command line.
    pub file: String,
    /// The offending field (`points[2][0]`, `knots`), or `document` for the file as a whole.
    pub field: String,
    /// What is wrong with it.
    pub problem: Problem,
}

/// What is wrong with a field of a curve file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Problem {
    /// The file could not be read.
    #[error("cannot read the file: {0}")]
    Unreadable(String),
    /// The text is not JSON (or a number is out of the f64 range).
    #[error("invalid JSON: {0}")]
    Json(String),
    /// A drawing file's syntax is broken (XML, path data, a transform, DXF group codes).
    #[error("{0}")]
    Syntax(String),
    /// A required field is absent.
    #[error("missing required field")]
    Missing,
    /// A field given twice (JSON parsers differ on which one counts: none is taken).
    #[error("given more than once")]
    Duplicate,
    /// A field that the kind does not have (a typo, most likely).
    #[error("unknown field for kind `{kind}` (allowed: {allowed})")]
    UnknownField {
        /// The curve kind.
        kind: String,
        /// The fields it allows.
        allowed: String,
    },
    /// `kind` names no known curve kind.
    #[error("unknown kind `{0}` (expected one of: {KINDS})")]
    UnknownKind(String),
    /// A value of the wrong JSON type.
    #[error("expected {expected}, got {got}")]
    WrongType {
        /// What the field must be.
        expected: &'static str,
        /// The JSON type found.
        got: &'static str,
    },
    /// A number beyond [`MAX_ABS`].
    #[error("{0:e} is too large (|value| must be at most 1e100)")]
    TooLarge(f64),
    /// A number that violates its range.
    #[error("must be {rule}, got {value}")]
    OutOfRange {
        /// The rule, e.g. "> 0".
        rule: String,
        /// The value given.
        value: f64,
    },
    /// An array of the wrong length.
    #[error("expected {expected}, got {got}")]
    WrongCount {
        /// The length required.
        expected: String,
        /// The length given.
        got: usize,
    },
    /// `knots` together with `periodic: true`.
    #[error("must be absent when `periodic` is true (a periodic curve has uniform knots)")]
    KnotsWithPeriodic,
    /// The curve's geometry does not suit the command (open where a closed curve is needed,
    /// a cusp, a corner at the seam, a self-intersection).
    #[error("{0}")]
    Geometry(String),
    /// The command does not take this kind of curve.
    #[error("{0}")]
    Unsupported(String),
    /// All control points coincide.
    #[error("all points coincide: the curve is a single point")]
    Degenerate,
    /// The spline cannot be represented: the rule is in the message.
    #[error("{0}")]
    Spline(#[from] bspline::Error),
    /// Derivatives overflow f64 (knots far too close for the coordinates).
    #[error("knot spacing too small for the coordinates: derivatives overflow f64")]
    Overflow,
}

const KINDS: &str = "bezier, bspline, circle, ellipse, limacon, elliptic_lemniscate, convexities, \
     line, arc, profile, region, regions";

/// Which spline kind a file used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SplineKind {
    /// `bezier`.
    Bezier,
    /// `bspline`.
    BSpline,
}

/// A validated B-spline, NURBS or Bézier curve.
#[derive(Debug, Clone, PartialEq)]
pub struct SplineCurve {
    /// The curve as the algorithms take it.
    pub plane: curve::SplineCurve,
    /// Its rational form (polynomial curves have unit weights).
    pub curve: Rational,
    /// `bezier` or `bspline`.
    pub kind: SplineKind,
    /// Given with `periodic: true` (a closed, uniform, `C^(p−1)` curve on `[0, n)`).
    pub periodic: bool,
    /// Closed: periodic, or clamped with equal first and last points.
    pub closed: bool,
    /// Whether `weights` were given.
    pub weighted: bool,
    /// Number of control points in the file.
    pub n_points: usize,
}

/// What a curve file describes.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// `bezier` or `bspline`.
    Spline(Box<SplineCurve>),
    /// One of the analytic kinds (all closed).
    Analytic(Analytic),
    /// `line` or `arc`: one segment of the kinds profiles are made of.
    Segment(Box<curve::Segment>),
    /// `profile`: a chain of segments.
    Profile(Box<curve::Profile>),
    /// `region`: an outer closed boundary and holes.
    Region(Box<curve::Region>),
    /// `regions`, or a drawing of several parts: disjoint regions, each with its holes (two or
    /// more; one part is a [`Shape::Region`]).
    Regions(Vec<curve::Region>),
}

/// A validated curve with the name of the file it came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// File name (for messages and reports).
    pub file: String,
    /// The curve.
    pub shape: Shape,
    /// What a drawing said besides its geometry (`None` for a curve file).
    pub drawing: Option<DrawingInfo>,
}

/// What a drawing says besides the geometry read from it (the contract's "Nothing is dropped
/// silently").
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DrawingInfo {
    /// What was not read, by type.
    pub skipped: Vec<Skipped>,
    /// The unit of its coordinates, where it says.
    pub units: Option<String>,
}

impl DrawingInfo {
    /// Why no answer on the drawing can be certified: something not read could be part of an
    /// outline (named, with why).
    pub fn doubt(&self) -> Option<String> {
        let names: Vec<&str> = self
            .skipped
            .iter()
            .filter(|s| s.outline)
            .map(|s| s.first.as_str())
            .collect();
        (!names.is_empty()).then(|| {
            format!(
                "the drawing holds what could be part of an outline and was not read: {}",
                names.join("; ")
            )
        })
    }
}

impl Curve {
    /// A curve read from a curve file (no drawing information).
    pub fn new(file: impl Into<String>, shape: Shape) -> Self {
        Self {
            file: file.into(),
            shape,
            drawing: None,
        }
    }

    /// Why no answer on this input can be certified: its drawing held something that could
    /// be part of an outline and was not read.
    pub fn drawing_doubt(&self) -> Option<String> {
        self.drawing.as_ref().and_then(DrawingInfo::doubt)
    }

    /// The unit of the coordinates, where the drawing says (`"mm"`, as [`DrawingInfo::units`]).
    pub fn units(&self) -> Option<&str> {
        self.drawing.as_ref().and_then(|d| d.units.as_deref())
    }

    /// The regions of a region input: its one region, or the parts of a multi-part input;
    /// empty for a curve.
    pub fn parts(&self) -> Vec<&curve::Region> {
        match &self.shape {
            Shape::Region(r) => vec![r.as_ref()],
            Shape::Regions(parts) => parts.iter().collect(),
            _ => Vec::new(),
        }
    }
}

impl Curve {
    /// The `kind` of the file.
    pub fn kind(&self) -> &'static str {
        match &self.shape {
            Shape::Spline(s) if s.kind == SplineKind::Bezier => "bezier",
            Shape::Spline(_) => "bspline",
            Shape::Analytic(a) => a.kind(),
            Shape::Segment(s) => s.kind().name(),
            Shape::Profile(_) => "profile",
            Shape::Region(_) => "region",
            Shape::Regions(_) => "regions",
        }
    }

    /// True for closed curves.
    pub fn is_closed(&self) -> bool {
        match &self.shape {
            Shape::Spline(s) => s.closed,
            Shape::Analytic(_) => true,
            Shape::Segment(s) => s.is_closed(),
            Shape::Profile(p) => p.is_closed(),
            Shape::Region(_) | Shape::Regions(_) => true,
        }
    }

    /// The parameter domain.
    pub fn domain(&self) -> (f64, f64) {
        match &self.shape {
            Shape::Spline(s) => s.curve.domain(),
            Shape::Analytic(_) => (0.0, std::f64::consts::TAU),
            Shape::Segment(s) => s.own_domain(),
            Shape::Profile(p) => p.document_domain(),
            Shape::Region(r) => r.outer().document_domain(),
            Shape::Regions(parts) => parts[0].outer().document_domain(),
        }
    }

    /// The curve as the algorithms take it.
    pub fn plane_curve(&self) -> &dyn PlaneCurve {
        match &self.shape {
            Shape::Spline(s) => &s.plane,
            Shape::Analytic(a) => a,
            Shape::Segment(s) => s.curve(),
            Shape::Profile(p) => p.as_ref(),
            // (Commands that need one curve refuse a region; figures draw its outer boundary
            // here and its holes beside it.)
            Shape::Region(r) => r.outer(),
            Shape::Regions(parts) => parts[0].outer(),
        }
    }

    /// The point at the document's parameter `u` (an arc's angle share, a profile's segments at
    /// their own parameters): where the parameters a command reports lie.
    pub fn point_at(&self, u: f64) -> [f64; 2] {
        match &self.shape {
            Shape::Segment(s) => s.jet(s.own_param().form(u, s.domain())).p.arr(),
            Shape::Profile(p) => p.jet(p.internal_param(u)).p.arr(),
            Shape::Region(r) => r.outer().jet(r.outer().internal_param(u)).p.arr(),
            Shape::Regions(parts) => {
                let outer = parts[0].outer();
                outer.jet(outer.internal_param(u)).p.arr()
            }
            Shape::Spline(_) | Shape::Analytic(_) => self.plane_curve().jet(u).p.arr(),
        }
    }

    /// The rational B-spline form, for spline kinds.
    pub fn rational(&self) -> Option<&Rational> {
        match &self.shape {
            Shape::Spline(s) => Some(&s.curve),
            Shape::Segment(s) => Some(s.curve().curve()),
            Shape::Analytic(_) | Shape::Profile(_) | Shape::Region(_) | Shape::Regions(_) => None,
        }
    }

    /// `n + 1` points at uniform parameters over the whole domain (both ends included).
    pub fn polyline(&self, n: usize) -> Vec<[f64; 2]> {
        let c = self.plane_curve();
        let (a, b) = self.domain();
        let n = n.max(1);
        (0..=n)
            .map(|i| c.jet(a + (b - a) * i as f64 / n as f64).p.arr())
            .collect()
    }
}

/// A curve that is not a profile or a region (a spline, an analytic shape, a line or an arc)
/// as the profile of one segment in the curve's own parameter, cut at its corners; `None`
/// for a profile or a region.
pub fn curve_profile(curve: &Curve) -> Option<Result<curve::Profile, CurveFileError>> {
    profile::curve_profile(&curve.shape).map(|made| {
        made.map_err(|(field, problem)| CurveFileError {
            file: curve.file.clone(),
            field,
            problem,
        })
    })
}

/// The region a command on regions takes from a file: a `region` file as it is; any other
/// closed curve with an exact form (a closed profile, a closed `bezier` or `bspline`, a
/// circle, a full-turn arc) as the region it encloses; from a drawing, its closed profiles
/// nested inside each other (even-odd), `pick` choosing among several regions. The curve
/// returned is the region's (`Shape::Region`); anything else is bad input naming the file.
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
    let text = std::str::from_utf8(bytes).map_err(|e| {
        drawing::error(file, "document", Problem::Syntax(format!("not UTF-8: {e}")))
    })?;
    let c = parse_curve(file, text)?;
    let fail = |(field, problem): FieldError| CurveFileError {
        file: c.file.clone(),
        field,
        problem,
    };
    let shape = match c.shape {
        Shape::Region(r) => Shape::Region(r),
        Shape::Regions(parts) => regions::picked_part(file, parts, pick)?,
        shape => {
            let outer = profile::boundary_of("curve", shape).map_err(fail)?;
            let region = curve::Region::new(outer, Vec::new())
                .map_err(|e| fail(("curve".into(), Problem::Geometry(e.to_string()))))?;
            Shape::Region(Box::new(region))
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
        None => {
            let text = std::str::from_utf8(&bytes).map_err(|e| {
                drawing::error(
                    &file,
                    "document",
                    Problem::Syntax(format!("not UTF-8: {e}")),
                )
            })?;
            parse_curve(&file, text)
        }
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
/// use curvekit::io::{parse_drawing, DrawingFormat, Shape};
/// let svg = br#"<svg xmlns="http://www.w3.org/2000/svg"><rect width="4" height="2"/></svg>"#;
/// let c = parse_drawing("r.svg", DrawingFormat::Svg, svg, None).unwrap();
/// assert!(matches!(c.shape, Shape::Profile(ref p) if p.segments().len() == 4));
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
        DrawingFormat::Svg => {
            let text = std::str::from_utf8(bytes).map_err(|e| {
                drawing::error(file, "document", Problem::Syntax(format!("not UTF-8: {e}")))
            })?;
            svg::read(file, text)
        }
        DrawingFormat::Dxf => dxf::read(file, bytes),
    }
}

/// Validates the text of a curve file; `file` names it in errors.
///
/// ```
/// use curvekit::io::{parse_curve, Shape};
/// let c = parse_curve("s.json", r#"{"kind":"bezier","points":[[0,0],[1,2],[2,-2],[3,0]]}"#).unwrap();
/// assert!(matches!(c.shape, Shape::Spline(_)) && !c.is_closed());
///
/// let e = parse_curve("c.json", r#"{"kind":"circle","r":1,"radius":2}"#).unwrap_err();
/// assert_eq!(e.field, "radius");
/// assert!(e.to_string().starts_with("c.json: radius: unknown field"));
/// ```
pub fn parse_curve(file: &str, text: &str) -> Result<Curve, CurveFileError> {
    let err = |field: &str, problem: Problem| CurveFileError {
        file: file.to_string(),
        field: field.to_string(),
        problem,
    };
    if text.trim().is_empty() {
        return Err(err("document", Problem::Json("the file is empty".into())));
    }
    let value: Value =
        serde_json::from_str(text).map_err(|e| err("document", Problem::Json(e.to_string())))?;
    let Value::Object(map) = value else {
        return Err(err(
            "document",
            Problem::WrongType {
                expected: "a JSON object",
                got: type_name(&value),
            },
        ));
    };
    if let Some(key) = duplicates::duplicate_key(text) {
        return Err(err(&key, Problem::Duplicate));
    }
    let shape = parse_shape(&map).map_err(|(field, problem)| err(&field, problem))?;
    Ok(Curve::new(file, shape))
}

/// An error before the file name is attached: (field, problem).
type FieldError = (String, Problem);

pub(super) fn parse_shape(map: &Map<String, Value>) -> Result<Shape, FieldError> {
    let kind = match map.get("kind") {
        None => return Err(("kind".into(), Problem::Missing)),
        Some(Value::String(s)) => s.as_str(),
        Some(v) => return Err(wrong_type("kind", "a string", v)),
    };
    let allowed: &[&str] = match kind {
        "bezier" => &["points", "weights"],
        "bspline" => &["degree", "points", "weights", "knots", "periodic"],
        "circle" => &["r", "center"],
        "ellipse" => &["a", "b", "center"],
        "limacon" | "elliptic_lemniscate" => &["a", "b"],
        "convexities" => &["p", "eps", "m"],
        "line" => &["from", "to"],
        "arc" => &["center", "r", "start", "end"],
        // (`part`: which part of a multi-part input an offset loop belongs to.)
        "profile" => &["segments", "closed", "part"],
        "region" => &["outer", "holes"],
        "regions" => &["parts"],
        other => return Err(("kind".into(), Problem::UnknownKind(other.to_string()))),
    };
    // Reject unknown fields first: a typo'd optional field must not pass silently.
    reject_unknown(map, kind, allowed)?;
    let f = Fields(map);
    let analytic = match kind {
        "bezier" | "bspline" => {
            return spline::parse_spline(kind, &f).map(|s| Shape::Spline(Box::new(s)))
        }
        "line" | "arc" => {
            return profile::parse_segment_kind(kind, &f).map(|s| Shape::Segment(Box::new(s)))
        }
        "profile" => return profile::parse_profile(&f).map(|p| Shape::Profile(Box::new(p))),
        "region" => return profile::parse_region(&f).map(|r| Shape::Region(Box::new(r))),
        "regions" => return profile::parse_regions(&f),
        "circle" => {
            let center = f.opt_point("center")?.unwrap_or([0.0, 0.0]);
            Analytic::Circle(shape("r", Circle::new(f.positive("r")?, center))?)
        }
        "ellipse" => {
            let center = f.opt_point("center")?.unwrap_or([0.0, 0.0]);
            let (a, b) = (f.positive("a")?, f.positive("b")?);
            Analytic::Ellipse(shape("a", Ellipse::new(a, b, center))?)
        }
        "limacon" => {
            let a = f.number("a")?;
            let b = f.number("b")?;
            if b < 0.0 {
                return Err(out_of_range("b", ">= 0", b));
            }
            if a <= b {
                return Err(out_of_range(
                    "a",
                    "> b (a simple limaçon needs a > b >= 0)",
                    a,
                ));
            }
            Analytic::Limacon(shape("a", Limacon::new(a, b))?)
        }
        "elliptic_lemniscate" => {
            let (a, b) = (f.positive("a")?, f.positive("b")?);
            Analytic::EllipticLemniscate(shape("a", EllipticLemniscate::new(a, b))?)
        }
        _ => {
            let p = f.positive("p")?;
            let eps = f.number("eps")?;
            if !(eps > 0.0 && eps < 1.0) {
                return Err(out_of_range("eps", "in (0, 1)", eps));
            }
            let m = f.integer("m", 2, u64::from(MAX_LOBES))?;
            let m = u32::try_from(m).unwrap_or(MAX_LOBES);
            Analytic::Convexities(shape("p", Convexities::new(p, eps, m))?)
        }
    };
    Ok(Shape::Analytic(analytic))
}

/// The first field of `map` besides `kind` that `kind` does not have, as an error naming it.
pub(super) fn reject_unknown(
    map: &Map<String, Value>,
    kind: &str,
    allowed: &[&str],
) -> Result<(), FieldError> {
    match map
        .keys()
        .find(|k| k.as_str() != "kind" && !allowed.contains(&k.as_str()))
    {
        Some(key) => Err((
            key.clone(),
            Problem::UnknownField {
                kind: kind.to_string(),
                allowed: allowed.join(", "),
            },
        )),
        None => Ok(()),
    }
}

/// A shape the reader validated already: a refusal by the curve model (not expected) names its
/// field, or `default` where it names none.
pub(super) fn shape<T>(default: &str, made: curve::Result<T>) -> Result<T, FieldError> {
    made.map_err(|e| match e {
        curve::Error::InvalidShape { field, value, why } => (
            field.to_string(),
            Problem::OutOfRange {
                rule: why.to_string(),
                value,
            },
        ),
        curve::Error::Spline(e) => (default.to_string(), Problem::Spline(e)),
        e => (default.to_string(), Problem::Geometry(e.to_string())),
    })
}

/// Typed access to the fields of one curve object, naming the field in every error.
pub(crate) struct Fields<'a>(pub(crate) &'a Map<String, Value>);

impl Fields<'_> {
    pub(crate) fn get(&self, key: &str) -> Option<&Value> {
        self.0.get(key)
    }

    pub(crate) fn require(&self, key: &str) -> Result<&Value, FieldError> {
        self.0
            .get(key)
            .ok_or_else(|| (key.to_string(), Problem::Missing))
    }

    pub(crate) fn number(&self, key: &str) -> Result<f64, FieldError> {
        number_at(key, self.require(key)?)
    }

    pub(crate) fn positive(&self, key: &str) -> Result<f64, FieldError> {
        let x = self.number(key)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(out_of_range(key, "> 0", x))
        }
    }

    /// An integer in `[min, max]` (a JSON number without a fractional part, `3.0` included).
    pub(crate) fn integer(&self, key: &str, min: u64, max: u64) -> Result<u64, FieldError> {
        let x = self.number(key)?;
        if x.fract() != 0.0 {
            return Err(out_of_range(key, "an integer", x));
        }
        if x < min as f64 {
            return Err(out_of_range(key, &format!("an integer >= {min}"), x));
        }
        if x > max as f64 {
            return Err(out_of_range(key, &format!("an integer <= {max}"), x));
        }
        Ok(x as u64)
    }

    pub(crate) fn opt_point(&self, key: &str) -> Result<Option<[f64; 2]>, FieldError> {
        self.get(key).map(|v| point_at(key, v)).transpose()
    }

    pub(crate) fn opt_bool(&self, key: &str) -> Result<Option<bool>, FieldError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::Bool(b)) => Ok(Some(*b)),
            Some(v) => Err(wrong_type(key, "true or false", v)),
        }
    }

    /// An array of numbers.
    pub(crate) fn opt_numbers(&self, key: &str) -> Result<Option<Vec<f64>>, FieldError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let items = array_at(key, v, "an array of numbers")?;
        items
            .iter()
            .enumerate()
            .map(|(i, x)| number_at(&format!("{key}[{i}]"), x))
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// An array of `[x, y]` points.
    pub(crate) fn points(&self, key: &str) -> Result<Vec<[f64; 2]>, FieldError> {
        let items = array_at(key, self.require(key)?, "an array of [x, y] points")?;
        items
            .iter()
            .enumerate()
            .map(|(i, p)| point_at(&format!("{key}[{i}]"), p))
            .collect()
    }
}

fn array_at<'v>(
    key: &str,
    v: &'v Value,
    expected: &'static str,
) -> Result<&'v Vec<Value>, FieldError> {
    match v {
        Value::Array(items) => Ok(items),
        _ => Err(wrong_type(key, expected, v)),
    }
}

fn point_at(key: &str, v: &Value) -> Result<[f64; 2], FieldError> {
    let items = array_at(key, v, "an [x, y] point")?;
    if items.len() != 2 {
        return Err((
            key.to_string(),
            Problem::WrongCount {
                expected: "2 coordinates [x, y]".into(),
                got: items.len(),
            },
        ));
    }
    Ok([
        number_at(&format!("{key}[0]"), &items[0])?,
        number_at(&format!("{key}[1]"), &items[1])?,
    ])
}

fn number_at(key: &str, v: &Value) -> Result<f64, FieldError> {
    let x = match v {
        Value::Number(n) => n.as_f64(),
        _ => return Err(wrong_type(key, "a number", v)),
    };
    match x {
        Some(x) if x.is_finite() && x.abs() <= MAX_ABS => Ok(x),
        Some(x) => Err((key.to_string(), Problem::TooLarge(x))),
        None => Err(wrong_type(key, "a number", v)),
    }
}

pub(crate) fn out_of_range(key: &str, rule: &str, value: f64) -> FieldError {
    (
        key.to_string(),
        Problem::OutOfRange {
            rule: rule.to_string(),
            value,
        },
    )
}

fn wrong_type(key: &str, expected: &'static str, v: &Value) -> FieldError {
    (
        key.to_string(),
        Problem::WrongType {
            expected,
            got: type_name(v),
        },
    )
}

fn type_name(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}
