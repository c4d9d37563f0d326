//! Options and the plain result types (serde) of the public entry points.

use crate::error::{Error, Result};
use numeric::certificate::{Certified, Doubts};
use numeric::tolerance::{ParamTol, Settings};
use serde::{Deserialize, Serialize};

/// Options of the algorithms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// The tolerances, valid by construction: the parameter tolerance
    /// (`settings.tol`, relative to the domain length) is the one the algorithms read.
    pub settings: Settings,
    /// Use certified root isolation for spline curves (default `true`).
    pub certify: bool,
    /// Limit on the sections searched (a guard against floods on degenerate input).
    pub max_sections: usize,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            settings: Settings::default(),
            certify: true,
            max_sections: 100_000,
        }
    }
}

impl Options {
    /// Sets the parameter tolerance.
    ///
    /// ```
    /// use antipodal::Options;
    /// use numeric::tolerance::ParamTol;
    /// let opts = Options::default().tolerance(ParamTol::new(1e-9).unwrap());
    /// assert_eq!(opts.settings.tol.get(), 1e-9);
    /// ```
    pub fn tolerance(mut self, tol: ParamTol) -> Self {
        self.settings.tol = tol;
        self
    }
    /// Turns certification on or off.
    pub fn certify(mut self, on: bool) -> Self {
        self.certify = on;
        self
    }
    /// Checks the options of the algorithms' own (every entry point checks them too): at least
    /// one section. (The tolerance is valid by construction.)
    ///
    /// ```
    /// use antipodal::Options;
    /// assert!(Options::default().validate().is_ok());
    /// assert!(Options { max_sections: 0, ..Options::default() }.validate().is_err());
    /// ```
    pub fn validate(&self) -> Result<()> {
        if self.max_sections == 0 {
            return Err(Error::InvalidOption {
                field: "max_sections",
                value: 0.0,
                expected: "must be at least 1",
            });
        }
        Ok(())
    }
}

/// The type of a simple antipodal pair (Jia 2004, §3.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum PairType {
    /// Both convex, `1/κ(s) + 1/κ(t) < |r|`.
    A,
    /// Both convex, `1/κ(s) + 1/κ(t) > |r|`.
    B,
    /// Convex and concave, the concave osculating circle inside the convex one.
    C,
    /// Convex and concave, not contained.
    D,
    /// Both concave.
    E,
}

/// One pair of antipodal points: of a smooth curve, or of a profile (which also says whether
/// each point is a corner, and on which segment it lies).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AntipodalPair {
    /// Parameter of the first point (`s ≤ t`; `s < t` on a smooth curve).
    pub s: f64,
    /// Parameter of the second point.
    pub t: f64,
    /// The first point.
    pub p: [f64; 2],
    /// The second point.
    pub q: [f64; 2],
    /// `|q − p|`.
    pub distance: f64,
    /// Type A–E where both ends are smooth points of curved stretches (always on a smooth
    /// curve); `None` (`null`) on a profile with a corner or a straight end (the types need
    /// the curvature at both ends).
    #[serde(rename = "type")]
    pub kind: Option<PairType>,
    /// On a profile: whether the point at `s`, and the one at `t`, is a corner (`None` on a
    /// smooth curve, whose document does not write it).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub corner: Option<[bool; 2]>,
    /// On a profile: the segments of the two points (at a joint: the segment starting there,
    /// for a corner).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub segment: Option<[usize; 2]>,
}

impl AntipodalPair {
    /// The pair as one of a profile of this one segment, in the same parameter: no corner,
    /// both points on segment 0.
    pub fn on_one_segment(self) -> AntipodalPair {
        AntipodalPair {
            corner: Some([false; 2]),
            segment: Some([0; 2]),
            ..self
        }
    }

    /// Whether a point of the pair is a profile's corner.
    pub fn has_corner(&self) -> bool {
        self.corner.is_some_and(|c| c.contains(&true))
    }

    /// The pair with `s ≤ t` (its two contacts swapped if need be).
    pub(crate) fn ordered(self) -> AntipodalPair {
        if self.s <= self.t {
            self
        } else {
            AntipodalPair {
                s: self.t,
                t: self.s,
                p: self.q,
                q: self.p,
                corner: self.corner.map(|[a, b]| [b, a]),
                segment: self.segment.map(|[a, b]| [b, a]),
                ..self
            }
        }
    }
}

/// A point of simple inflection.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Inflection {
    /// Parameter.
    pub u: f64,
    /// Point.
    pub p: [f64; 2],
    /// Existence (and uniqueness in `bracket`) follow from coefficient signs.
    pub certified: bool,
    /// A simple sign change of the curvature, or a cluster (the curvature within rounding of
    /// zero across `bracket`: a flat stretch between a left and a right turn, a root of odd
    /// multiplicity, or roots closer than the tolerance).
    pub kind: InflectionKind,
    /// An interval of parameters proven to hold it (on a closed curve it may cross the seam:
    /// it is then given in the unwrapped parameter, beyond the domain's end); absent where it
    /// was found by sampling.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub bracket: Option<[f64; 2]>,
    /// On a profile, the segment it lies on (at a smooth joint: the segment starting there).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub segment: Option<usize>,
}

/// How an inflection was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum InflectionKind {
    /// A simple sign change of the curvature.
    Simple,
    /// A cluster of roots across which the curvature changes sign.
    Cluster,
}

/// A continuum of antipodal pairs: every `s` in `s` pairs with one `t` in `t`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Family {
    /// Parameter range on one side (on a smooth curve it may run across the seam: then
    /// `s[1] < s[0]`).
    pub s: [f64; 2],
    /// The matching range on the other side (`s[k]` pairs with `t[k]`).
    pub t: [f64; 2],
    /// On a profile: the points at `s[0]` and `s[1]` (a drawing's parameters depend on how
    /// its reader chained it; `None` on a smooth curve, whose document does not write them).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub p: Option<[[f64; 2]; 2]>,
    /// On a profile: the points at `t[0]` and `t[1]`.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub q: Option<[[f64; 2]; 2]>,
}

/// The antipodal pairs, inflections and families of a smooth curve or of a profile
/// ([`antipodal()`](crate::antipodal())).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Antipodal {
    /// Isolated antipodal pairs, sorted by `s`.
    pub pairs: Vec<AntipodalPair>,
    /// Inflections (on a profile: at smooth points and smooth joints), sorted by `u`.
    pub inflections: Vec<Inflection>,
    /// On a profile: its corners, sorted by `u` (not inflections; `None` on a smooth curve,
    /// whose document does not list them).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub corners: Option<Vec<Corner>>,
    /// Continua of antipodal pairs (circles, concentric arcs, facing parallel lines).
    pub families: Vec<Family>,
    /// The doubts met (none: every decision followed from certified sign tests). Read with
    /// [`Verdict`](numeric::certificate::Verdict): `certified()`, and `reason()` (the first
    /// doubt, stated); the document writes them as its `certified` and, when it is false,
    /// `reason` fields.
    #[serde(flatten)]
    pub doubts: Doubts,
    /// False when a work limit was hit (the result may then be incomplete).
    pub complete: bool,
}

/// The inflections of a smooth curve or of a profile ([`crate::inflections`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Inflections {
    /// Inflections (on a profile: at smooth points and smooth joints), sorted by `u`.
    pub inflections: Vec<Inflection>,
    /// On a profile: its corners, sorted by `u` (not inflections; `None` on a smooth curve,
    /// whose document does not list them).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub corners: Option<Vec<Corner>>,
    /// The doubts met (none: every decision followed from certified sign tests). Read with
    /// [`Verdict`](numeric::certificate::Verdict): `certified()`, and `reason()` (the first
    /// doubt, stated); the document writes them as its `certified` and, when it is false,
    /// `reason` fields.
    #[serde(flatten)]
    pub doubts: Doubts,
}

impl Antipodal {
    /// The corners: a profile's, none on a smooth curve.
    pub fn corner_list(&self) -> &[Corner] {
        self.corners.as_deref().unwrap_or_default()
    }
}

impl Inflections {
    /// The corners: a profile's, none on a smooth curve.
    pub fn corner_list(&self) -> &[Corner] {
        self.corners.as_deref().unwrap_or_default()
    }
}

/// A corner of a profile (see [`curve::Joint`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Corner {
    /// The profile parameter there.
    pub u: f64,
    /// The point.
    pub p: [f64; 2],
    /// The signed angle from the incoming to the outgoing tangent (radians, positive turning
    /// left).
    pub turn: f64,
    /// `convex` (turning the way the profile runs round its region) or `reflex`.
    pub kind: CornerKind,
}

/// Whether a corner is convex or reflex.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CornerKind {
    /// Turning the way the profile runs round its region (an open profile: left).
    Convex,
    /// Turning against it.
    Reflex,
}

/// A line tangent to the first curve (or profile) at `s` and to the second at `t`: where a
/// profile's corner is the point of contact, the line passes through it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TangentLine {
    /// Parameter on the first curve.
    pub s: f64,
    /// Parameter on the second curve.
    pub t: f64,
    /// Point of tangency (or the corner) on the first curve.
    pub p: [f64; 2],
    /// Point of tangency (or the corner) on the second curve.
    pub q: [f64; 2],
    /// On profiles: whether the line passes through a corner of the first, and of the second
    /// (`None` between smooth curves, whose document does not write it).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub corner: Option<[bool; 2]>,
    /// On profiles: the segments of the two points (a corner's: the segment starting there).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub segment: Option<[usize; 2]>,
}

/// The common tangent lines of two smooth curves or profiles
/// ([`common_tangents()`](crate::common_tangents())).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Tangents {
    /// The lines, sorted by `s`.
    pub lines: Vec<TangentLine>,
    /// The doubts met (none: every decision followed from certified sign tests). Read with
    /// [`Verdict`](numeric::certificate::Verdict): `certified()`, and `reason()` (the first
    /// doubt, stated); the document writes them as its `certified` and, when it is false,
    /// `reason` fields.
    #[serde(flatten)]
    pub doubts: Doubts,
}

/// Results that say whether they are certified, and why not: stated from the doubts met, at
/// the one place each result is finished.
pub(crate) trait Provenance: Sized {
    /// The result of a run with the doubts it met: certified when there is none, its reason
    /// the first.
    fn finished(run: Certified<Self>) -> Self;
}

macro_rules! provenance {
    ($($t:ty),+) => {
        $(impl Provenance for $t {
            fn finished(run: Certified<Self>) -> Self {
                let (mut result, doubts) = run.into_parts();
                result.doubts = doubts;
                result
            }
        })+
        numeric::impl_verdict!($($t),+);
    };
}
provenance!(Antipodal, Inflections, Tangents);
