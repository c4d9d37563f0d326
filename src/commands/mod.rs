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

pub use errors::CommandError;
use errors::{antipodal_error, refuse, zeroset_error};

use crate::io::{Curve, Shape};
use curve::{ParamCurve, PlaneCurve, Profile, Segment, SegmentKind};
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
/// calls answer warm; a profile needs no preparation. A region is refused: the one-curve
/// commands take curves. It shares the curve, so it can be kept and sent between threads.
pub struct Prepared {
    curve: Arc<Curve>,
    smooth: Option<antipodal::Prepared<'static>>,
}

impl Prepared {
    /// Prepares `curve` for `command` (named in the refusal of a region).
    pub fn new(curve: Arc<Curve>, command: &str) -> Result<Self, CommandError> {
        one_curve(&[&curve], command)?;
        let smooth = match &curve.shape {
            Shape::Profile(_) => None,
            _ => Some(antipodal::prepare_shared(Arc::new(Shared(curve.clone())))),
        };
        Ok(Self { curve, smooth })
    }

    /// The curve prepared.
    pub fn curve(&self) -> &Curve {
        &self.curve
    }

    /// The inflections (and a profile's corners).
    pub fn inflections(&self, opts: &antipodal::Options) -> Result<InflectionsFound, CommandError> {
        inflections_of(&self.curve, self.smooth.as_ref(), opts)
    }

    /// The antipodal pairs, inflections and families (and a profile's corners).
    pub fn antipodal(&self, opts: &antipodal::Options) -> Result<AntipodalFound, CommandError> {
        antipodal_of(&self.curve, self.smooth.as_ref(), opts)
    }
}

/// A curve that is no profile, prepared on a borrow (for one answer: no copy of the curve).
fn prepare_borrowed(curve: &Curve) -> Option<antipodal::Prepared<'_>> {
    match &curve.shape {
        Shape::Profile(_) => None,
        _ => Some(antipodal::prepare(curve.plane_curve())),
    }
}

/// `inflections` of `curve`, prepared as `smooth` unless it is a profile.
fn inflections_of(
    curve: &Curve,
    smooth: Option<&antipodal::Prepared<'_>>,
    opts: &antipodal::Options,
) -> Result<InflectionsFound, CommandError> {
    let found = match (smooth, &curve.shape) {
        (_, Shape::Profile(p)) => {
            antipodal::profile_inflections(p, opts).map(InflectionsFound::Profile)
        }
        (Some(prepared), _) => prepared.inflections(opts).map(InflectionsFound::Curve),
        (None, _) => unreachable!("a curve that is no profile is prepared"),
    };
    found.map_err(|e| antipodal_error(e, &[curve]))
}

/// `antipodal` of `curve`, prepared as `smooth` unless it is a profile.
fn antipodal_of(
    curve: &Curve,
    smooth: Option<&antipodal::Prepared<'_>>,
    opts: &antipodal::Options,
) -> Result<AntipodalFound, CommandError> {
    let found = match (smooth, &curve.shape) {
        (_, Shape::Profile(p)) => {
            antipodal::profile_antipodal(p, opts).map(AntipodalFound::Profile)
        }
        (Some(prepared), _) => prepared.antipodal(opts).map(AntipodalFound::Curve),
        (None, _) => unreachable!("a curve that is no profile is prepared"),
    };
    found.map_err(|e| antipodal_error(e, &[curve]))
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
    inflections_of(curve, prepare_borrowed(curve).as_ref(), opts)
}

/// `antipodal` of a curve read: [`Prepared::antipodal`] on a freshly prepared curve.
pub fn antipodal(curve: &Curve, opts: &antipodal::Options) -> Result<AntipodalFound, CommandError> {
    validate_options(opts)?;
    one_curve(&[curve], "antipodal")?;
    antipodal_of(curve, prepare_borrowed(curve).as_ref(), opts)
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
    let found = if both.iter().any(|c| matches!(c.shape, Shape::Profile(_))) {
        let (a, b) = (as_profile(c1, "tangents")?, as_profile(c2, "tangents")?);
        antipodal::profile_tangents(&a, &b, opts).map(TangentsFound::Profile)
    } else {
        let (a, b) = antipodal::prepare_pair(c1.plane_curve(), c2.plane_curve());
        a.common_tangents(&b, opts).map(TangentsFound::Curve)
    };
    found.map_err(|e| antipodal_error(e, &both))
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
    let found = if curves.iter().any(|c| matches!(c.shape, Shape::Profile(_))) {
        let profiles = curves
            .iter()
            .map(|c| as_profile(c, "bisector"))
            .collect::<Result<Vec<_>, _>>()?;
        match &profiles[..] {
            [a, b] => zeroset::profile_bisector(a, b, opts),
            [one, ..] => zeroset::profile_self_bisector(one, opts),
            [] => unreachable!("one curve at least"),
        }
        .map(BisectorFound::Profile)
    } else {
        let rationals = curves
            .iter()
            .map(|c| spline_of(c))
            .collect::<Result<Vec<_>, _>>()?;
        match &rationals[..] {
            [a, b] => zeroset::bisector(a, b, opts),
            [one, ..] => zeroset::self_bisector(one, opts),
            [] => unreachable!("one curve at least"),
        }
        .map(BisectorFound::Curve)
    };
    found.map_err(zeroset_error)
}

/// The medial axis of a region read (as [`crate::io::read_region`] gives it).
pub fn medial(
    region: &Curve,
    opts: &medial::MedialOptions,
) -> Result<medial::MedialAxis, CommandError> {
    validate_medial_options(opts)?;
    let Shape::Region(r) = &region.shape else {
        return Err(refuse(region, "kind", "medial takes a region"));
    };
    medial::medial_axis(r, opts).map_err(|e| CommandError::Other(format!("medial: {e}")))
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

/// The offsets of a region read (as [`crate::io::read_region`] gives it), from its medial
/// axis computed with `medial_opts`: inward, or outward with `medial_opts.exterior` (from the
/// exterior axis).
pub fn offset(
    region: &Curve,
    distances: &Distances,
    opts: &offset::OffsetOptions,
    medial_opts: &medial::MedialOptions,
) -> Result<offset::Offsets, CommandError> {
    validate_distances(distances)?;
    validate_medial_options(medial_opts)?;
    let axis = medial(region, medial_opts)?;
    let Shape::Region(r) = &region.shape else {
        return Err(refuse(region, "kind", "offset takes a region"));
    };
    let list = match distances {
        Distances::List(list) => list.clone(),
        Distances::Step(step) => {
            let widest = axis
                .edges
                .iter()
                .flat_map(|e| e.radius.iter().copied())
                .chain(axis.nodes.iter().map(|n| n.radius))
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
    let found = if medial_opts.exterior {
        offset::outward_offsets(r, &axis, &list, opts)
    } else {
        offset::offsets(r, &axis, &list, opts)
    };
    found.map_err(|e| CommandError::Usage(format!("offset: {e}")))
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
    let bisector_opts = zeroset::BisectorOptions {
        tol: opts.tol,
        chord_tol: opts.chord_tol,
        ..Default::default()
    };
    bisector_opts
        .validate()
        .map_err(|e| CommandError::Usage(format!("medial: {e}")))
}

/// A region is no curve: the commands on curves refuse it by name.
fn one_curve(curves: &[&Curve], command: &str) -> Result<(), CommandError> {
    match curves.iter().find(|c| matches!(c.shape, Shape::Region(_))) {
        Some(c) => Err(refuse(
            c,
            "kind",
            &format!("{command} takes a curve or a profile, not a region"),
        )),
        None => Ok(()),
    }
}

/// A curve as a profile: itself, or one segment (a line, an arc, a spline that is not
/// periodic); an analytic shape or a periodic spline is refused by name (with `command`).
pub fn as_profile(c: &Curve, command: &str) -> Result<Profile, CommandError> {
    let refuse_as = |why: &str| {
        refuse(
            c,
            "kind",
            &format!(
                "{command} with a profile: {why}; give it as a profile or an open or clamped \
                 spline"
            ),
        )
    };
    let segment = match &c.shape {
        Shape::Profile(p) => return Ok(p.as_ref().clone()),
        Shape::Segment(s) => s.as_ref().clone(),
        Shape::Spline(s) if !s.periodic => Segment::spline(SegmentKind::BSpline, s.plane.clone())
            .map_err(|e| refuse_as(&e.to_string()))?,
        Shape::Spline(_) => {
            return Err(refuse_as(
                "a periodic spline has no ends to make a segment of",
            ))
        }
        Shape::Analytic(a) => {
            return Err(refuse_as(&format!(
                "an analytic {} is not a segment",
                a.kind()
            )))
        }
        Shape::Region(_) => return Err(refuse_as("a region is not a curve")),
    };
    Profile::new(vec![segment], None).map_err(|e| refuse_as(&e.to_string()))
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
