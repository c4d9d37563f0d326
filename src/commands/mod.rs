//! The tool's commands as library calls on curves already read, shared by the command line,
//! its batch mode and the Python package: each picks the algorithm for the curve's shape (a
//! spline or analytic shape, a profile, a region), turns the library's errors into the tool's
//! (bad input names its file and field), and gives the result the tool prints with `--json`
//! ([`json_document`]).
//!
//! ```
//! use curvekit::commands::{self, Prepared};
//! use curvekit::io::parse_curve;
//! use std::sync::Arc;
//!
//! let text = r#"{"kind":"bspline","degree":3,"periodic":true,
//!                "points":[[0,0],[2,-1],[4,0],[4,2],[2,1.2],[0,2]]}"#;
//! let curve = Arc::new(parse_curve("cubic.json", text).unwrap());
//! let prepared = Prepared::new(curve.clone(), "antipodal").unwrap();
//! let found = prepared.antipodal(&antipodal::Options::default()).unwrap();
//! let doc = commands::json_document(&found, &[&curve], None);
//! assert!(doc.starts_with("{\"certified\":true"));
//! ```

mod errors;
mod params;
mod parts;

pub use errors::CommandError;
use errors::{antipodal_error, refuse, zeroset_error};
use params::{DocMap, InDocument};

use crate::io::{Curve, Shape};
use curve::{ParamCurve, PlaneCurve, Profile};
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::sync::Arc;

/// What `inflections` found: on a smooth curve, or on a profile (with its corners).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum InflectionsFound {
    /// On a spline or an analytic shape.
    Curve(antipodal::Inflections),
    /// On a profile: also the corners.
    Profile(antipodal::ProfileInflections),
}

/// What `antipodal` found: on a smooth curve, or on a profile (pairs with corners, families
/// with end points).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum AntipodalFound {
    /// On a spline or an analytic shape.
    Curve(antipodal::Antipodal),
    /// On a profile.
    Profile(antipodal::ProfileAntipodal),
}

/// What `tangents` found: between two smooth curves, or where one is a profile.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum TangentsFound {
    /// Between two splines or analytic shapes.
    Curve(antipodal::Tangents),
    /// Where one curve or both are profiles.
    Profile(antipodal::ProfileTangents),
}

/// What `bisector` found: of splines, or where one curve is a profile.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum BisectorFound {
    /// Of one or two splines (lines and arcs among them).
    Curve(zeroset::Bisector),
    /// Where one curve or both are profiles.
    Profile(zeroset::ProfileBisector),
}

/// The median time of one run, as `--time` reports it (the `stats` of a JSON document).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stats {
    /// Median time of one warm run (on a prepared curve), in microseconds.
    pub median_us: f64,
    /// How many runs the median is taken over.
    pub runs: usize,
    /// Median time of one cold run (preparing the curve read and answering once).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cold_median_us: Option<f64>,
    /// How many cold runs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cold_runs: Option<usize>,
}

/// A curve made ready for the one-curve commands: a spline or an analytic shape is prepared
/// once (its frame, symbolic forms and enclosures; [`antipodal::prepare`]), so that later
/// calls answer warm; a profile needs no preparation, and a spline with corners (a degree-1
/// spline, knots of full multiplicity) is taken as the profile of its pieces. A region is
/// refused: the one-curve commands take curves. It shares the curve, so it can be kept and
/// sent between threads.
pub struct Prepared {
    curve: Arc<Curve>,
    smooth: Option<antipodal::Prepared<'static>>,
    /// The spline taken as a profile, where it has corners.
    cut: Option<Profile>,
}

impl Prepared {
    /// Prepares `curve` for `command` (named in the refusal of a region).
    pub fn new(curve: Arc<Curve>, command: &str) -> Result<Self, CommandError> {
        one_curve(&[&curve], command)?;
        let cut = spline_with_corners(&curve)?;
        let smooth = match (&curve.shape, &cut) {
            (Shape::Profile(_), _) | (_, Some(_)) => None,
            _ => Some(antipodal::prepare_shared(Arc::new(Shared(curve.clone())))),
        };
        Ok(Self { curve, smooth, cut })
    }

    /// The curve prepared.
    pub fn curve(&self) -> &Curve {
        &self.curve
    }

    /// The inflections (and a profile's corners).
    pub fn inflections(&self, opts: &antipodal::Options) -> Result<InflectionsFound, CommandError> {
        inflections_of(&self.curve, self.route(), opts)
    }

    /// The antipodal pairs, inflections and families (and a profile's corners).
    pub fn antipodal(&self, opts: &antipodal::Options) -> Result<AntipodalFound, CommandError> {
        antipodal_of(&self.curve, self.route(), opts)
    }

    fn route(&self) -> Route<'_> {
        match (&self.curve.shape, &self.cut, &self.smooth) {
            (Shape::Profile(p), _, _) => Route::Profile(p),
            (_, Some(p), _) => Route::Profile(p),
            (_, None, Some(s)) => Route::Smooth(s),
            (_, None, None) => unreachable!("a curve that is no profile is prepared"),
        }
    }
}

/// Results that say whether they are certified: a drawing's doubt makes them not.
trait Doubted {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>);

    /// Not certified, for `doubt` (where there is one and the result has no reason of its
    /// own).
    fn doubted(mut self, doubt: Option<String>) -> Self
    where
        Self: Sized,
    {
        if let Some(why) = doubt {
            let (certified, reason) = self.certified_mut();
            *certified = false;
            reason.get_or_insert(why);
        }
        self
    }
}

impl Doubted for InflectionsFound {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>) {
        match self {
            InflectionsFound::Curve(f) => (&mut f.certified, &mut f.reason),
            InflectionsFound::Profile(f) => (&mut f.certified, &mut f.reason),
        }
    }
}

impl Doubted for AntipodalFound {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>) {
        match self {
            AntipodalFound::Curve(f) => (&mut f.certified, &mut f.reason),
            AntipodalFound::Profile(f) => (&mut f.certified, &mut f.reason),
        }
    }
}

impl Doubted for TangentsFound {
    fn certified_mut(&mut self) -> (&mut bool, &mut Option<String>) {
        match self {
            TangentsFound::Curve(f) => (&mut f.certified, &mut f.reason),
            TangentsFound::Profile(f) => (&mut f.certified, &mut f.reason),
        }
    }
}

/// Which algorithms a one-curve command runs: a profile's, or a smooth curve's (prepared).
enum Route<'a> {
    Profile(&'a Profile),
    Smooth(&'a antipodal::Prepared<'a>),
}

/// A spline with corners (a degree-1 spline, a knot of full multiplicity where it turns, a
/// clamped closed spline with a corner where its ends meet) as the profile of its pieces, in
/// its own parameter; `None` for a smooth spline and for every other kind.
fn spline_with_corners(c: &Curve) -> Result<Option<Profile>, CommandError> {
    if !matches!(c.shape, Shape::Spline(_)) {
        return Ok(None);
    }
    match crate::io::curve_profile(c) {
        Some(Ok(p)) if p.segments().len() > 1 || p.corners().next().is_some() => Ok(Some(p)),
        Some(Ok(_)) | None => Ok(None),
        Some(Err(e)) => Err(CommandError::Input(e)),
    }
}

/// How `curve`'s exact form's parameters map to its document's on the smooth path.
fn smooth_map(curve: &Curve) -> DocMap<'_> {
    match &curve.shape {
        Shape::Segment(s) => DocMap::Segment(s),
        _ => DocMap::Own,
    }
}

/// `inflections` of `curve` on `route`, in the curve's own parameter.
fn inflections_of(
    curve: &Curve,
    route: Route<'_>,
    opts: &antipodal::Options,
) -> Result<InflectionsFound, CommandError> {
    let found = match route {
        Route::Profile(p) => antipodal::profile_inflections(p, opts).map(|mut f| {
            f.in_document(&[DocMap::Profile(p)]);
            InflectionsFound::Profile(f)
        }),
        Route::Smooth(prepared) => prepared.inflections(opts).map(|mut f| {
            f.in_document(&[smooth_map(curve)]);
            InflectionsFound::Curve(f)
        }),
    };
    found
        .map(|f| f.doubted(curve.drawing_doubt()))
        .map_err(|e| antipodal_error(e, &[curve]))
}

/// `antipodal` of `curve` on `route`, in the curve's own parameter.
fn antipodal_of(
    curve: &Curve,
    route: Route<'_>,
    opts: &antipodal::Options,
) -> Result<AntipodalFound, CommandError> {
    let found = match route {
        Route::Profile(p) => antipodal::profile_antipodal(p, opts).map(|mut f| {
            f.in_document(&[DocMap::Profile(p)]);
            AntipodalFound::Profile(f)
        }),
        Route::Smooth(prepared) => prepared.antipodal(opts).map(|mut f| {
            f.in_document(&[smooth_map(curve)]);
            AntipodalFound::Curve(f)
        }),
    };
    found
        .map(|f| f.doubted(curve.drawing_doubt()))
        .map_err(|e| antipodal_error(e, &[curve]))
}

/// A curve read, shared with its prepared form: the plane curve of its shape.
struct Shared(Arc<Curve>);

impl ParamCurve for Shared {
    fn domain(&self) -> (f64, f64) {
        self.0.plane_curve().domain()
    }
    fn is_closed(&self) -> bool {
        self.0.plane_curve().is_closed()
    }
    fn jet_to(&self, u: f64, order: usize) -> curve::Jet {
        self.0.plane_curve().jet_to(u, order)
    }
    fn jet(&self, u: f64) -> curve::Jet {
        self.0.plane_curve().jet(u)
    }
}

impl PlaneCurve for Shared {
    fn exact(&self) -> Option<curve::Exact<'_>> {
        self.0.plane_curve().exact()
    }
}

/// `inflections` of a curve read: [`Prepared::inflections`] on a freshly prepared curve.
pub fn inflections(
    curve: &Curve,
    opts: &antipodal::Options,
) -> Result<InflectionsFound, CommandError> {
    validate_options(opts)?;
    one_curve(&[curve], "inflections")?;
    match (&curve.shape, spline_with_corners(curve)?) {
        (Shape::Profile(p), _) => inflections_of(curve, Route::Profile(p), opts),
        (_, Some(p)) => inflections_of(curve, Route::Profile(&p), opts),
        _ => inflections_of(
            curve,
            Route::Smooth(&antipodal::prepare(curve.plane_curve())),
            opts,
        ),
    }
}

/// `antipodal` of a curve read: [`Prepared::antipodal`] on a freshly prepared curve.
pub fn antipodal(curve: &Curve, opts: &antipodal::Options) -> Result<AntipodalFound, CommandError> {
    validate_options(opts)?;
    one_curve(&[curve], "antipodal")?;
    match (&curve.shape, spline_with_corners(curve)?) {
        (Shape::Profile(p), _) => antipodal_of(curve, Route::Profile(p), opts),
        (_, Some(p)) => antipodal_of(curve, Route::Profile(&p), opts),
        _ => antipodal_of(
            curve,
            Route::Smooth(&antipodal::prepare(curve.plane_curve())),
            opts,
        ),
    }
}

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
        antipodal::profile_tangents(&a, &b, opts).map(|mut f| {
            f.in_document(&[DocMap::Profile(&a), DocMap::Profile(&b)]);
            TangentsFound::Profile(f)
        })
    } else {
        let (a, b) = antipodal::prepare_pair(c1.plane_curve(), c2.plane_curve());
        a.common_tangents(&b, opts).map(|mut f| {
            f.in_document(&[smooth_map(c1), smooth_map(c2)]);
            TangentsFound::Curve(f)
        })
    };
    let doubt = c1.drawing_doubt().or_else(|| c2.drawing_doubt());
    found
        .map(|f| f.doubted(doubt))
        .map_err(|e| antipodal_error(e, &both))
}

/// Whether a command on several curves runs on profiles: where one is a profile or a spline
/// with corners (the others are then taken as profiles of one segment).
fn needs_profiles(curves: &[&Curve]) -> Result<bool, CommandError> {
    for c in curves {
        if matches!(c.shape, Shape::Profile(_)) || spline_with_corners(c)?.is_some() {
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
    validate_bisector_options(opts)?;
    let curves: Vec<&Curve> = std::iter::once(c1).chain(c2).collect();
    one_curve(&curves, "bisector")?;
    // (An analytic shape has no spline of its own: it is taken as the profile of its exact
    // form, in its angle.)
    let analytic = curves.iter().any(|c| matches!(c.shape, Shape::Analytic(_)));
    let found = if analytic || needs_profiles(&curves)? {
        let profiles = curves
            .iter()
            .map(|c| as_profile(c, "bisector"))
            .collect::<Result<Vec<_>, _>>()?;
        let maps: Vec<DocMap<'_>> = profiles.iter().map(DocMap::Profile).collect();
        match &profiles[..] {
            [a, b] => zeroset::profile_bisector(a, b, opts),
            [one, ..] => zeroset::profile_self_bisector(one, opts),
            [] => unreachable!("one curve at least"),
        }
        .map(|mut f| {
            f.in_document(&maps);
            BisectorFound::Profile(f)
        })
    } else {
        let rationals = curves
            .iter()
            .map(|c| spline_of(c))
            .collect::<Result<Vec<_>, _>>()?;
        let maps: Vec<DocMap<'_>> = curves.iter().map(|c| smooth_map(c)).collect();
        match &rationals[..] {
            [a, b] => zeroset::bisector(a, b, opts),
            [one, ..] => zeroset::self_bisector(one, opts),
            [] => unreachable!("one curve at least"),
        }
        .map(|mut f| {
            f.in_document(&maps);
            BisectorFound::Curve(f)
        })
    };
    found.map_err(zeroset_error)
}

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
    Ok(parts::joined_axes(axes, region.drawing_doubt()))
}

/// The medial axis of each part, its feet in the boundaries' profile parameters (as the
/// offsets take it), with the tolerances relative to the size of all the parts together.
fn axes_of_parts(
    region: &Curve,
    opts: &medial::MedialOptions,
) -> Result<Vec<medial::MedialAxis>, CommandError> {
    validate_medial_options(opts)?;
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
        size: Some(parts::size_of(&parts)),
        ..*opts
    };
    parts
        .iter()
        .map(|r| {
            medial::medial_axis(r, &opts).map_err(|e| CommandError::Other(format!("medial: {e}")))
        })
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

/// The distances checked on their own (as [`validate_options`]): each finite and positive.
pub fn validate_distances(distances: &Distances) -> Result<(), CommandError> {
    let positive = |flag: &str, d: f64| {
        if d.is_finite() && d > 0.0 {
            Ok(())
        } else {
            Err(CommandError::Usage(format!(
                "--{flag}: {d} is out of range: must be a finite number > 0"
            )))
        }
    };
    match distances {
        Distances::List(list) if list.is_empty() => {
            Err(CommandError::Usage("offset: no distance given".into()))
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
        return Err(CommandError::Usage(
            "--step: outward offsets never vanish, so a step has no last pass: give \
             --distance or --distances"
                .into(),
        ));
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
    validate_medial_options(medial_opts)?;
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
                return Err(CommandError::Usage(format!(
                    "--step: {step} is out of range: gives more than {MAX_OFFSETS} offsets in \
                     this region"
                )));
            }
            (1..=count as usize).map(|k| k as f64 * step).collect()
        }
    };
    let parts = region.parts();
    let opts = offset::OffsetOptions {
        size: Some(parts::size_of(&parts)),
        ..*opts
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
                offset::Error::Cancelled => CommandError::Other(format!("offset: {e}")),
                _ => CommandError::Usage(format!("offset: {e}")),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(parts::joined_offsets(found, region.drawing_doubt()))
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
        return Err(CommandError::Usage(
            "vcarve: the tool path follows the inner medial axis, not the exterior one".into(),
        ));
    }
    let axes = axes_of_parts(region, medial_opts)?;
    let parts = region.parts();
    let opts = offset::VCarveOptions {
        offset: offset::OffsetOptions {
            size: Some(parts::size_of(&parts)),
            ..opts.offset
        },
        ..*opts
    };
    let found = parts
        .iter()
        .zip(&axes)
        .map(|(r, axis)| {
            offset::vcarve(r, axis, &opts).map_err(|e| match e {
                offset::Error::Cancelled => CommandError::Other(format!("vcarve: {e}")),
                _ => CommandError::Usage(format!("vcarve: {}", usage_of(&e))),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(parts::joined_carves(found, region.drawing_doubt()))
}

/// The V-carving options checked on their own (as [`validate_options`]).
pub fn validate_vcarve_options(opts: &offset::VCarveOptions) -> Result<(), CommandError> {
    opts.validate()
        .map_err(|e| CommandError::Usage(format!("vcarve: {}", usage_of(&e))))
}

/// An offset error as the command line names its options (`--max-depth`, not `max_depth`).
fn usage_of(e: &offset::Error) -> String {
    match e {
        offset::Error::BadOption { field, value, why } => {
            format!(
                "--{}: {value} is out of range: {why}",
                field.replace('_', "-")
            )
        }
        other => other.to_string(),
    }
}

/// The contract's size of a region read: max(width, height) of the bounding box of all its
/// parts (0 for a curve that is no region).
pub fn size_of(region: &Curve) -> f64 {
    parts::size_of(&region.parts())
}

/// One JSON document, as the tool prints it with `--json`: the result's own fields (as the
/// contract names them), then the extensions `curve` (or `curves`, for two) and, when timed,
/// `stats`; one line, ending in a newline.
pub fn json_document(result: &impl Serialize, curves: &[&Curve], stats: Option<&Stats>) -> String {
    let summaries: Vec<CurveSummary> = curves.iter().map(|c| CurveSummary::of(c)).collect();
    json_document_of(result, &summaries, stats)
}

/// [`json_document`] with the curves given by their summaries (a result kept apart from its
/// curves, as a Python result is).
pub fn json_document_of(
    result: &impl Serialize,
    curves: &[CurveSummary],
    stats: Option<&Stats>,
) -> String {
    let mut doc = serde_json::to_value(result).unwrap_or(Value::Null);
    if let Some(map) = doc.as_object_mut() {
        // (The contract's "Nothing is dropped silently": for a drawing, what was not read and
        // its units, beside the result's own fields.)
        let drawings: Vec<&DrawingSummary> =
            curves.iter().filter_map(|c| c.drawing.as_ref()).collect();
        if !drawings.is_empty() {
            let skipped: Vec<Value> = drawings
                .iter()
                .flat_map(|d| &d.skipped)
                .map(crate::io::Skipped::entry)
                .collect();
            map.insert("skipped".into(), Value::Array(skipped));
            if let Some(units) = drawings.iter().find_map(|d| d.units.as_ref()) {
                map.insert("units".into(), json!(units));
            }
        }
        match curves {
            [one] => {
                map.insert("curve".into(), json!(one));
            }
            many => {
                map.insert("curves".into(), json!(many));
            }
        }
        if let Some(s) = stats {
            map.insert("stats".into(), json!(s));
        }
    }
    format!("{doc}\n")
}

/// The `curve` object of JSON reports (an extension: which curve the numbers belong to).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CurveSummary {
    /// The file as named (or the name given to a curve made in memory).
    pub file: String,
    /// Its `kind`.
    pub kind: String,
    /// Closed or open.
    pub closed: bool,
    /// The parameter domain.
    pub domain: [f64; 2],
    /// For a drawing, what was not read and its units (written beside the result's fields,
    /// not in the curve's).
    #[serde(skip)]
    pub drawing: Option<DrawingSummary>,
}

/// What a drawing said besides its geometry, as a result carries it.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct DrawingSummary {
    /// What was not read, by type.
    pub skipped: Vec<crate::io::Skipped>,
    /// The unit of the coordinates, where the drawing says.
    pub units: Option<String>,
}

impl CurveSummary {
    /// The summary of `curve`.
    pub fn of(curve: &Curve) -> Self {
        let (a, b) = curve.domain();
        Self {
            file: curve.file.clone(),
            kind: curve.kind().into(),
            closed: curve.is_closed(),
            domain: [a, b],
            drawing: curve.drawing.as_ref().map(|d| DrawingSummary {
                skipped: d.skipped.clone(),
                units: d.units.clone(),
            }),
        }
    }
}

/// The one-curve and two-curve commands' options checked on their own (the tool checks
/// them before it reads a file: a usage error comes first).
pub fn validate_options(opts: &antipodal::Options) -> Result<(), CommandError> {
    opts.validate().map_err(|e| antipodal_error(e, &[]))
}

/// The bisector's options checked on their own (as [`validate_options`]).
pub fn validate_bisector_options(opts: &zeroset::BisectorOptions) -> Result<(), CommandError> {
    opts.validate().map_err(zeroset_error)
}

/// The medial axis's options checked on their own (as [`validate_options`]).
pub fn validate_medial_options(opts: &medial::MedialOptions) -> Result<(), CommandError> {
    opts.validate()
        .map_err(|e| CommandError::Usage(format!("medial: {e}")))
}

/// A region is no curve: the commands on curves refuse it by name.
fn one_curve(curves: &[&Curve], command: &str) -> Result<(), CommandError> {
    for c in curves {
        match &c.shape {
            Shape::Region(_) => {
                return Err(refuse(
                    c,
                    "kind",
                    &format!("{command} takes a curve or a profile, not a region"),
                ))
            }
            Shape::Regions(parts) => {
                return Err(refuse(
                    c,
                    "kind",
                    &format!(
                        "{command} takes one curve, and the input holds {} parts: choose one \
                         with --pick N (0 to {})",
                        parts.len(),
                        parts.len() - 1
                    ),
                ))
            }
            _ => {}
        }
    }
    Ok(())
}

/// A curve as a profile: itself, or the profile of one segment in the curve's own parameter
/// (a line, an arc, a spline, an analytic shape's exact form; cut at its corners).
pub fn as_profile(c: &Curve, command: &str) -> Result<Profile, CommandError> {
    match &c.shape {
        Shape::Profile(p) => Ok(p.as_ref().clone()),
        Shape::Region(_) | Shape::Regions(_) => Err(refuse(
            c,
            "kind",
            &format!("{command} takes a curve or a profile, not a region"),
        )),
        _ => match crate::io::curve_profile(c) {
            Some(made) => made.map_err(CommandError::Input),
            None => unreachable!("every curve but a profile or a region has a profile"),
        },
    }
}

/// Bisectors are computed on the exact rational form, which only spline kinds have.
fn spline_of(c: &Curve) -> Result<&bspline::Rational, CommandError> {
    c.rational().ok_or_else(|| {
        refuse(
            c,
            "kind",
            &format!(
                "bisector needs a bezier, bspline, line or arc curve, got {}",
                c.kind()
            ),
        )
    })
}
