//! A validated curve read from a file: its shape (a spline, an analytic shape, a segment, a
//! profile, a region or several), what its drawing said besides, and the views of it the
//! commands take.

use super::{profile, CurveFileError, Skipped};
use bspline::Rational;
use curve::shapes::Shape as Analytic;
use curve::{ParamCurve, PlaneCurve};
use numeric::certificate::Doubt;

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
pub struct SplineDocument {
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
pub enum CurveKind {
    /// `bezier` or `bspline`.
    Spline(Box<SplineDocument>),
    /// One of the analytic kinds (all closed).
    Analytic(Analytic),
    /// `line` or `arc`: one segment of the kinds profiles are made of.
    Segment(Box<curve::Segment>),
    /// `profile`: a chain of segments.
    Profile(Box<curve::Profile>),
    /// `region`: an outer closed boundary and holes.
    Region(Box<curve::Region>),
    /// `regions`, or a drawing of several parts: disjoint regions, each with its holes (two or
    /// more; one part is a [`CurveKind::Region`]).
    Regions(Vec<curve::Region>),
}

/// A validated curve with the name of the file it came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// File name (for messages and reports).
    pub file: String,
    /// The curve.
    pub shape: CurveKind,
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
    /// outline (named, with why), as stated.
    pub fn doubt(&self) -> Option<String> {
        self.outline_doubt().map(|d| d.to_string())
    }

    /// [`DrawingInfo::doubt`] as the doubt the answers carry.
    pub fn outline_doubt(&self) -> Option<Doubt> {
        let names: Vec<String> = self
            .skipped
            .iter()
            .filter(|s| s.outline)
            .map(|s| s.first.clone())
            .collect();
        (!names.is_empty()).then_some(Doubt::UnreadOutline { names })
    }
}

impl Curve {
    /// A curve read from a curve file (no drawing information).
    pub fn new(file: impl Into<String>, shape: CurveKind) -> Self {
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

    /// [`Curve::drawing_doubt`] as the doubt the answers carry.
    pub fn drawing_outline_doubt(&self) -> Option<Doubt> {
        self.drawing.as_ref().and_then(DrawingInfo::outline_doubt)
    }

    /// The unit of the coordinates, where the drawing says (`"mm"`, as [`DrawingInfo::units`]).
    pub fn units(&self) -> Option<&str> {
        self.drawing.as_ref().and_then(|d| d.units.as_deref())
    }

    /// The regions of a region input: its one region, or the parts of a multi-part input;
    /// empty for a curve.
    pub fn parts(&self) -> Vec<&curve::Region> {
        match &self.shape {
            CurveKind::Region(r) => vec![r.as_ref()],
            CurveKind::Regions(parts) => parts.iter().collect(),
            _ => Vec::new(),
        }
    }
}

impl Curve {
    /// The `kind` of the file.
    pub fn kind(&self) -> &'static str {
        match &self.shape {
            CurveKind::Spline(s) if s.kind == SplineKind::Bezier => "bezier",
            CurveKind::Spline(_) => "bspline",
            CurveKind::Analytic(a) => a.kind(),
            CurveKind::Segment(s) => s.kind().name(),
            CurveKind::Profile(_) => "profile",
            CurveKind::Region(_) => "region",
            CurveKind::Regions(_) => "regions",
        }
    }

    /// True for closed curves.
    pub fn is_closed(&self) -> bool {
        match &self.shape {
            CurveKind::Spline(s) => s.closed,
            CurveKind::Analytic(_) => true,
            CurveKind::Segment(s) => s.is_closed(),
            CurveKind::Profile(p) => p.is_closed(),
            CurveKind::Region(_) | CurveKind::Regions(_) => true,
        }
    }

    /// The parameter domain.
    pub fn domain(&self) -> (f64, f64) {
        match &self.shape {
            CurveKind::Spline(s) => s.curve.domain(),
            CurveKind::Analytic(_) => (0.0, std::f64::consts::TAU),
            CurveKind::Segment(s) => s.own_domain(),
            CurveKind::Profile(p) => p.document_domain(),
            CurveKind::Region(r) => r.outer().document_domain(),
            CurveKind::Regions(parts) => parts[0].outer().document_domain(),
        }
    }

    /// The curve as the algorithms take it.
    pub fn plane_curve(&self) -> &dyn PlaneCurve {
        match &self.shape {
            CurveKind::Spline(s) => &s.plane,
            CurveKind::Analytic(a) => a,
            CurveKind::Segment(s) => s.curve(),
            CurveKind::Profile(p) => p.as_ref(),
            // (Commands that need one curve refuse a region; figures draw its outer boundary
            // here and its holes beside it.)
            CurveKind::Region(r) => r.outer(),
            CurveKind::Regions(parts) => parts[0].outer(),
        }
    }

    /// The point at the document's parameter `u` (an arc's angle share, a profile's segments at
    /// their own parameters): where the parameters a command reports lie.
    pub fn point_at(&self, u: f64) -> [f64; 2] {
        match &self.shape {
            CurveKind::Segment(s) => s.jet(s.own_param().form(u, s.domain())).p.arr(),
            CurveKind::Profile(p) => p.jet(p.internal_param(u)).p.arr(),
            CurveKind::Region(r) => r.outer().jet(r.outer().internal_param(u)).p.arr(),
            CurveKind::Regions(parts) => {
                let outer = parts[0].outer();
                outer.jet(outer.internal_param(u)).p.arr()
            }
            CurveKind::Spline(_) | CurveKind::Analytic(_) => self.plane_curve().jet(u).p.arr(),
        }
    }

    /// The rational B-spline form, for spline kinds.
    pub fn rational(&self) -> Option<&Rational> {
        match &self.shape {
            CurveKind::Spline(s) => Some(&s.curve),
            CurveKind::Segment(s) => Some(s.curve().curve()),
            CurveKind::Analytic(_)
            | CurveKind::Profile(_)
            | CurveKind::Region(_)
            | CurveKind::Regions(_) => None,
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
