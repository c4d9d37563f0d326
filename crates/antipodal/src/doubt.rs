//! Why a result is not certified: every decision that could not be proven names its reason,
//! and a result reports the first one met (the rest of the run goes on uncertified).

/// A decision that rounding, a bound or the lack of an exact form left unproven.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Doubt {
    /// The curve has no exact form to prove signs on (or certification was not asked for).
    NoExactForm,
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
    /// A continuum of pairs within rounding (nearly a circle, nearly parallel stretches),
    /// not proven to be one.
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
}

impl Doubt {
    /// The reason, as reported.
    pub(crate) fn reason(self) -> &'static str {
        match self {
            Doubt::NoExactForm => "no exact form to prove signs on: found by Jia's sampled method",
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
        }
    }
}
