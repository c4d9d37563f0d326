//! Certificates as values: why a result is not certified, carried with it.
//!
//! Every step that decides something a proof may fail to settle returns its answer with the
//! doubts it met ([`Certified`]), and the caller joins them into its own ([`Doubts::absorb`]).
//! Nothing is marked afterwards, and no step keeps its provenance in interior mutability. A
//! result is certified when it carries no doubt; its `reason` (the contract's JSON field) is
//! the first doubt met, stated as [`Doubt`]'s `Display` writes it.
//!
//! [`Doubt`] lists every reason of the workspace once. It lives here, at the bottom, because a
//! result of any crate may carry the doubts of the crates it builds on (an offset carries the
//! medial axis's), and only a type every crate sees can hold them all.
//!
//! ```
//! use numeric::certificate::{Certified, Doubt, Doubts};
//!
//! fn halve(x: f64) -> Certified<f64> {
//!     let mut out = Certified::proven(x / 2.0);
//!     if x.abs() < 1e-300 {
//!         out.doubt(Doubt::RootsUnresolved);
//!     }
//!     out
//! }
//! let mut doubts = Doubts::default();
//! let a = doubts.absorb(halve(3.0));
//! let b = doubts.absorb(halve(0.0));
//! assert_eq!((a, b), (1.5, 0.0));
//! assert!(!doubts.is_empty());
//! assert_eq!(
//!     doubts.reason().as_deref(),
//!     Some("a sign test's roots could not be isolated within rounding")
//! );
//! ```

use std::fmt;

mod document;
pub use document::Verdict;

/// One reason a result is not certified: a decision that rounding, a bound, a search limit or
/// the lack of an exact form left unproven. Its `Display` is the reason as results state it.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum Doubt {
    // Antipodal points, inflections and common tangents (Jia).
    /// The curve has no exact form to prove signs on: found by Jia's sampled method.
    NoExactForm,
    /// Certification was turned off by the caller.
    CertificationOff,
    /// An analytic shape's exact rational form (of this degree) loses the precision its sign
    /// tests need: found by the sampled method instead.
    ExactFormPrecision {
        /// The degree of the exact form.
        degree: usize,
    },
    /// Two arcs of the curve come within rounding of each other: simplicity is not proven.
    SimplicityUndecided,
    /// A stretch shorter than the parameter tolerance turns the tangent by nearly a right
    /// angle (close to a cusp).
    NearCusp,
    /// An odd number of curvature sign changes on a closed curve: one was missed or doubled
    /// within rounding.
    OddInflections,
    /// The curvature's sign changes could not all be isolated within rounding.
    CurvatureUnresolved,
    /// Where the curvature jumps, whether the tangent turns there (a corner) is within
    /// rounding of the threshold.
    CornerUndecided,
    /// A sign test's roots could not be isolated within rounding.
    RootsUnresolved,
    /// A stretch whose curvature vanishes within rounding, not proven straight, taken as
    /// straight.
    FlatWithinRounding,
    /// A straight stretch with corners inside (a polyline) searched as one segment.
    CornerInStraight,
    /// A continuum of pairs within rounding (nearly a circle, nearly parallel stretches), not
    /// proven to be one.
    Continuum,
    /// Roots within rounding of each other (a double root or a cluster).
    RootCluster,
    /// A root within rounding of the end of its interval.
    RootAtEnd,
    /// The normal turns by a finite angle within one unit of the parameter.
    NormalJump,
    /// A point found as a pair was none beyond rounding (dropped).
    NotAPair,
    /// Neither sign of θ could be proven at a section's cut.
    SectionUndecided,
    /// A stretch beside a found pair skipped by Table 1's ε, not proven free of pairs.
    EpsilonCut,
    /// A stretch of nearly constant width, whose pairs are found by sampling its width.
    ConstantWidth,
    /// The two curves touch or overlap within rounding where their common tangents are
    /// sought.
    CurvesTouch,
    /// The region test and the tangent iteration disagree on a pair of segments.
    TangentTestsDisagree,
    /// A profile's curvature vanishes within rounding at the end of a segment, at a corner or
    /// the profile's end: whether it changes sign just inside is not decided.
    CurvatureAtSegmentEnd {
        /// The profile parameter of the end.
        u: f64,
        /// The segment.
        segment: usize,
    },
    /// A profile's curvature vanishes within rounding at a smooth joint.
    CurvatureAtJoint {
        /// The profile parameter of the joint.
        u: f64,
    },
    /// A point of tangency from a corner is not separated from another within rounding.
    TangencyFromCorner {
        /// The profile parameter of the corner.
        u: f64,
        /// The segment the tangency is on.
        segment: usize,
    },
    /// A point of tangency from a smooth joint whose tangents turn by rounding is not
    /// separated from another within rounding.
    TangencyFromJoint {
        /// The profile parameter of the joint.
        u: f64,
        /// The segment the tangency is on.
        segment: usize,
    },
    /// A foot point of a profile's corner (a pair with the corner at one end) is not
    /// separated from another within rounding.
    FootFromCorner {
        /// The profile parameter of the corner.
        u: f64,
        /// The segment the foot point is on.
        segment: usize,
    },
    /// A foot point of a smooth joint whose tangents turn by rounding (a pair with the joint
    /// at one end) is not separated from another within rounding.
    FootFromJoint {
        /// The profile parameter of the joint.
        u: f64,
        /// The segment the foot point is on.
        segment: usize,
    },
    /// The foot points of a profile's corner on a segment could not be found.
    CornerFeetNotFound {
        /// The segment.
        segment: usize,
        /// Why, as the search's error states it.
        why: String,
    },

    // The medial axis.
    /// A disk's emptiness was decided by the nearest point found, within rounding of the
    /// boundary.
    DiskByNearest,
    /// A junction's exact point was not proven near it.
    Junction,
    /// An end's curvature extremum was not proven.
    AxisEnd,
    /// A corner leaf is not at a corner convex for the region.
    CornerLeaf,
    /// The graph is not one piece with a cycle per hole (the axis inside a region is).
    AxisGraph {
        /// The first convex corner no leaf reaches, if any.
        unreached: Option<UnreachedCorner>,
    },
    /// The feet of the edges do not cover the boundaries once round: a piece of the axis may
    /// be missing.
    Coverage {
        /// The first convex corner no leaf reaches, if any.
        unreached: Option<UnreachedCorner>,
    },
    /// A search limit was hit.
    SearchLimit,
    /// The work was cancelled before every node was proven.
    Cancelled,

    // Offsets, from the medial axis.
    /// The medial axis the offsets are taken from is not certified (its doubts follow this
    /// one in the offsets' [`Doubts`]; a V-carving states the axis's own doubts first, and
    /// this one among its flat passes').
    AxisUncertified,
    /// A seam's feet did not converge.
    SeamUnconverged,
    /// A loop's pieces did not meet by more than the chord tolerance (a seam the axis does
    /// not show), and it was left out.
    LoopLeftOut,
    /// A loop's pieces did not meet (a seam the axis does not show), and the gap, within the
    /// chord tolerance, was bridged by a line.
    LoopBridged,
    /// A spline's offset is this far from the exact offset where measured, past the chord
    /// tolerance.
    OffsetError {
        /// The widest distance measured.
        error: f64,
    },
    /// A loop is not a simple closed profile.
    LoopNotAProfile {
        /// Why, as the profile's check states it.
        why: String,
    },
    /// The axis's radius may cross a distance between two of its vertices (a neck or a bump
    /// whose extremum was not found on the axis).
    NeckUnresolved,
    /// Two loops' fitted pieces cross across a passage narrower than they follow.
    LoopsCross,

    // Grasps.
    /// A point of a grasp region's boundary was not resolved: a zero set's singular point, or
    /// an end of a piece of the boundary that no other piece continues.
    GraspBoundaryUnresolved,
    /// A grasp region is a single point (force closure only where two conditions touch),
    /// found within rounding.
    GraspPointRegion,
    /// A grasp region's most robust grasp was found by a local search, not proven (the set
    /// traced again just below its friction could not be shown to miss the region).
    GraspBestUnproven,
    /// An antipodal pair (force closure at any friction) lies in no grasp region: regions
    /// narrower than the subdivision resolves were lost.
    GraspPairLost,

    // The tool's inputs.
    /// The drawing the input was read from holds what could be part of an outline and was
    /// not read.
    UnreadOutline {
        /// What was not read, each named as the reader names it (its type and where).
        names: Vec<String>,
    },
    /// A doubt of one part of a multi-part input (numbered from 0).
    InPart {
        /// The part.
        part: usize,
        /// The part's doubt.
        doubt: Box<Doubt>,
    },

    // Read back.
    /// A doubt read back from a result's document (its JSON, a pickled Python result): the
    /// reason as the document states it, its kind not recorded there.
    Stated {
        /// The reason, as stated.
        reason: String,
    },
}

/// A convex corner of a boundary that no leaf of the medial axis reaches: where a piece of
/// the axis may be missing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnreachedCorner {
    /// The corner's point.
    pub at: [f64; 2],
    /// The boundary it is on (0 the outer one, then the holes).
    pub boundary: usize,
    /// The angle the boundary turns by there (radians).
    pub turn: f64,
    /// How many more such corners there are.
    pub more: usize,
}

impl Doubt {
    /// The fixed part of the reason: the whole of it, but for the variants that name a place
    /// or a figure.
    fn fixed(&self) -> &'static str {
        match self {
            Doubt::NoExactForm => "no exact form to prove signs on: found by Jia's sampled method",
            Doubt::CertificationOff => "certification was turned off (Options::certify)",
            Doubt::SimplicityUndecided => {
                "two arcs of the curve come within rounding of each other: not proven simple"
            }
            Doubt::NearCusp => {
                "the tangent turns by nearly a right angle within the parameter tolerance \
                 (close to a cusp)"
            }
            Doubt::OddInflections => {
                "an odd number of curvature sign changes on a closed curve: one was missed or \
                 doubled within rounding"
            }
            Doubt::CurvatureUnresolved => {
                "the curvature's sign changes could not all be isolated within rounding"
            }
            Doubt::CornerUndecided => {
                "whether the curve has a corner where its curvature jumps is within rounding"
            }
            Doubt::RootsUnresolved => "a sign test's roots could not be isolated within rounding",
            Doubt::FlatWithinRounding => {
                "a stretch whose curvature vanishes within rounding is taken as straight \
                 without proof"
            }
            Doubt::CornerInStraight => {
                "a straight stretch with corners inside (a polyline) is searched as one segment"
            }
            Doubt::Continuum => {
                "pairs found as a continuous family within rounding, not proven to be one"
            }
            Doubt::RootCluster => {
                "roots within rounding of each other (a double root or a cluster)"
            }
            Doubt::RootAtEnd => "a root within rounding of the end of its interval",
            Doubt::NormalJump => {
                "the normal turns by a finite angle within one unit of the parameter, beyond \
                 what double precision resolves"
            }
            Doubt::NotAPair => "a point found as a pair is none beyond rounding (dropped)",
            Doubt::SectionUndecided => "the sign of theta at a section's cut is within rounding",
            Doubt::EpsilonCut => {
                "a stretch beside a found pair was skipped by Jia's epsilon without a proof \
                 that it holds no other pair"
            }
            Doubt::ConstantWidth => {
                "a stretch of nearly constant width: its pairs are found by sampling its width"
            }
            Doubt::CurvesTouch => "the curves touch or overlap within rounding",
            Doubt::TangentTestsDisagree => {
                "the region test and the tangent iteration disagree on a pair of segments"
            }
            Doubt::DiskByNearest => {
                "a disk's emptiness was decided by the nearest point found, within rounding of \
                 the boundary"
            }
            Doubt::Junction => {
                "a junction's tri-tangent disk was not proven within 1e-9 of the size of it"
            }
            Doubt::AxisGraph { .. } => {
                "the graph is not one connected piece with one cycle per hole"
            }
            Doubt::Coverage { .. } => {
                "the feet of the edges do not cover the boundaries once round: a piece of the \
                 axis may be missing"
            }
            Doubt::CornerLeaf => {
                "a corner leaf is not at a corner of the boundary convex for the region"
            }
            Doubt::AxisEnd => {
                "an end was not proven at an arc's centre, or at a centre of curvature within \
                 the tolerance of a proven peak of the curvature"
            }
            Doubt::SearchLimit => "a search limit was hit",
            Doubt::GraspBoundaryUnresolved => {
                "a point of a grasp region's boundary was not resolved (a singular point of a \
                 zero set, or an end no other piece of the boundary continues)"
            }
            Doubt::GraspPointRegion => {
                "a grasp region is a single point, where two conditions of force closure touch \
                 within rounding"
            }
            Doubt::GraspBestUnproven => {
                "a grasp region's most robust grasp was found by a local search"
            }
            Doubt::GraspPairLost => {
                "an antipodal pair lies in no grasp region (regions narrower than the \
                 subdivision resolves were lost)"
            }
            Doubt::Cancelled => "the work was cancelled before the axis was proven",
            Doubt::AxisUncertified => "the medial axis is not certified",
            Doubt::SeamUnconverged => "a seam's feet did not converge",
            Doubt::LoopLeftOut => {
                "a loop's pieces did not meet by more than the chord tolerance (a seam the axis \
                 does not show), and it was left out"
            }
            Doubt::LoopBridged => {
                "a loop's pieces did not meet (a seam the axis does not show), and the gap, \
                 within the chord tolerance, was bridged by a line"
            }
            Doubt::NeckUnresolved => {
                "the axis's radius may cross a distance between two of its vertices (a neck or \
                 a bump whose extremum was not found on the axis)"
            }
            Doubt::LoopsCross => {
                "two loops' fitted pieces cross across a passage narrower than they follow"
            }
            Doubt::ExactFormPrecision { .. }
            | Doubt::CurvatureAtSegmentEnd { .. }
            | Doubt::CurvatureAtJoint { .. }
            | Doubt::TangencyFromCorner { .. }
            | Doubt::FootFromCorner { .. }
            | Doubt::FootFromJoint { .. }
            | Doubt::TangencyFromJoint { .. }
            | Doubt::CornerFeetNotFound { .. }
            | Doubt::OffsetError { .. }
            | Doubt::LoopNotAProfile { .. }
            | Doubt::UnreadOutline { .. }
            | Doubt::InPart { .. }
            | Doubt::Stated { .. } => "",
        }
    }
}

impl fmt::Display for Doubt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Doubt::ExactFormPrecision { degree } => write!(
                f,
                "the shape's exact rational form (degree {degree}) loses the precision its \
                 sign tests need: found by Jia's sampled method"
            ),
            Doubt::CurvatureAtSegmentEnd { u, segment } => write!(
                f,
                "the curvature vanishes within rounding at the end u = {u} of segment \
                 {segment}, by a corner or the profile's end: whether it changes sign just \
                 inside is not decided"
            ),
            Doubt::CurvatureAtJoint { u } => write!(
                f,
                "the curvature vanishes within rounding at the smooth joint at u = {u}"
            ),
            Doubt::TangencyFromCorner { u, segment } => write!(
                f,
                "a point of tangency from the corner at u = {u} on segment {segment} is not \
                 separated from another within rounding"
            ),
            Doubt::FootFromCorner { u, segment } => write!(
                f,
                "a foot point of the corner at u = {u} on segment {segment} is not separated \
                 from another within rounding"
            ),
            Doubt::TangencyFromJoint { u, segment } => write!(
                f,
                "a point of tangency from the smooth joint at u = {u} on segment {segment} is \
                 not separated from another within rounding"
            ),
            Doubt::FootFromJoint { u, segment } => write!(
                f,
                "a foot point of the smooth joint at u = {u} on segment {segment} is not \
                 separated from another within rounding"
            ),
            Doubt::CornerFeetNotFound { segment, why } => write!(
                f,
                "the foot points of a corner on segment {segment} were not found: {why}"
            ),
            Doubt::OffsetError { error } => write!(
                f,
                "a spline's offset is {error:e} from the exact offset where measured, past the \
                 chord tolerance"
            ),
            Doubt::LoopNotAProfile { why } => {
                write!(f, "a loop is not a simple closed profile: {why}")
            }
            Doubt::UnreadOutline { names } => write!(
                f,
                "the drawing holds what could be part of an outline and was not read: {}",
                names.join("; ")
            ),
            Doubt::InPart { part, doubt } => write!(f, "part {part}: {doubt}"),
            Doubt::Stated { reason } => f.write_str(reason),
            Doubt::AxisGraph {
                unreached: Some(corner),
            }
            | Doubt::Coverage {
                unreached: Some(corner),
            } => {
                let more = match corner.more {
                    0 => String::new(),
                    1 => " (and 1 more such corner)".to_string(),
                    m => format!(" (and {m} more such corners)"),
                };
                write!(
                    f,
                    "{}: no leaf reaches the convex corner at ({}, {}) of boundary {}, which \
                     turns by {:.1e} rad{more}",
                    self.fixed(),
                    corner.at[0],
                    corner.at[1],
                    corner.boundary,
                    corner.turn,
                )
            }
            _ => f.write_str(self.fixed()),
        }
    }
}

/// The doubts a result carries, in the order they were met (a doubt met twice is kept once).
/// Empty: the result is certified.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Doubts(Vec<Doubt>);

impl Doubts {
    /// No doubt: certified.
    pub fn none() -> Doubts {
        Doubts(Vec::new())
    }

    /// True when there is no doubt.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Adds `doubt` (after those met before; kept once).
    pub fn add(&mut self, doubt: Doubt) {
        if !self.0.contains(&doubt) {
            self.0.push(doubt);
        }
    }

    /// Adds every doubt of `other`, after these.
    pub fn join(&mut self, other: Doubts) {
        for doubt in other.0 {
            self.add(doubt);
        }
    }

    /// Takes the value of `step`, keeping its doubts with these: the `?` of certificates.
    pub fn absorb<T>(&mut self, step: Certified<T>) -> T {
        self.join(step.doubts);
        step.value
    }

    /// The first doubt met: the one a result's `reason` states.
    pub fn first(&self) -> Option<&Doubt> {
        self.0.first()
    }

    /// Every doubt, in the order met.
    pub fn iter(&self) -> impl Iterator<Item = &Doubt> {
        self.0.iter()
    }

    /// The reason a result is not certified (its first doubt, stated), if it is not.
    pub fn reason(&self) -> Option<String> {
        self.first().map(ToString::to_string)
    }
}

impl From<Doubt> for Doubts {
    fn from(doubt: Doubt) -> Doubts {
        Doubts(vec![doubt])
    }
}

impl FromIterator<Doubt> for Doubts {
    fn from_iter<I: IntoIterator<Item = Doubt>>(iter: I) -> Doubts {
        let mut out = Doubts::none();
        for doubt in iter {
            out.add(doubt);
        }
        out
    }
}

/// A value with the doubts met in finding it. Steps return it; callers take the value with
/// [`Doubts::absorb`] (or [`Certified::and_then`]) and so carry the doubts on.
#[derive(Debug, Clone, PartialEq)]
#[must_use = "a certified value's doubts must be carried on"]
pub struct Certified<T> {
    /// The value.
    pub value: T,
    /// The doubts met finding it (none: it is certified).
    pub doubts: Doubts,
}

impl<T> Certified<T> {
    /// `value`, proven.
    pub fn proven(value: T) -> Certified<T> {
        Certified {
            value,
            doubts: Doubts::none(),
        }
    }

    /// `value`, with `doubts`.
    pub fn with(value: T, doubts: impl Into<Doubts>) -> Certified<T> {
        Certified {
            value,
            doubts: doubts.into(),
        }
    }

    /// True when no doubt was met.
    pub fn is_certified(&self) -> bool {
        self.doubts.is_empty()
    }

    /// Adds a doubt.
    pub fn doubt(&mut self, doubt: Doubt) {
        self.doubts.add(doubt);
    }

    /// The reason the value is not certified, if it is not.
    pub fn reason(&self) -> Option<String> {
        self.doubts.reason()
    }

    /// The value changed by `f`, with the same doubts.
    pub fn map<U>(self, f: impl FnOnce(T) -> U) -> Certified<U> {
        Certified {
            value: f(self.value),
            doubts: self.doubts,
        }
    }

    /// The next step on the value, carrying this step's doubts before its own.
    pub fn and_then<U>(self, f: impl FnOnce(T) -> Certified<U>) -> Certified<U> {
        let mut doubts = self.doubts;
        let next = f(self.value);
        doubts.join(next.doubts);
        Certified {
            value: next.value,
            doubts,
        }
    }

    /// The value and its doubts.
    pub fn into_parts(self) -> (T, Doubts) {
        (self.value, self.doubts)
    }
}

#[cfg(test)]
mod tests;
