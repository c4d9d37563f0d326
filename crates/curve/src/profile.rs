//! Profiles: chains of segments ([`Segment`]) joined end to end, as part outlines are drawn —
//! lines, arcs and splines meeting at corners or tangentially. A profile is a curve with
//! parameter `[0, n)` for `n` segments (`u ∈ [i, i+1]` is segment `i` at its own parameter
//! mapped linearly); its joints are classified as smooth (G1), convex or reflex corners.

use crate::box_tree::BoxTree;
use crate::corner_knots::{smooth_turn, DocumentSpan, CORNER_TURN};
use crate::crossing::first_crossing;
use crate::error::{Error, Result};
use crate::geom::{points_scale, Jet, V2};
use crate::param::ParamCurve;
use crate::segment::Segment;
use numeric::rounding::ulps;

/// Where two segments meet, or the seam of a closed profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joint {
    /// The profile parameter there (the index of the segment that starts there).
    pub u: f64,
    /// The signed angle from the incoming to the outgoing tangent (radians, positive turning
    /// left); within [`CORNER_TURN`] of zero the joint is smooth (beyond the rounding of the
    /// tangents: [`crate::smooth_turn`]).
    pub turn: f64,
    /// Smooth, or a corner and which kind.
    pub kind: JointKind,
    /// The largest turn this joint may have and be smooth: the contract's [`CORNER_TURN`],
    /// beyond the rounding of its tangents ([`crate::smooth_turn`]). A smooth joint turns by
    /// at most this; whoever trusts it to be smooth trusts it to this turn.
    pub smooth_turn: f64,
}

/// The kind of a joint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointKind {
    /// The tangent direction is continuous (G1).
    Smooth,
    /// A corner that turns the way the profile runs round its region (for an open profile:
    /// turning left); its inward normals form a cone.
    Convex,
    /// A corner turning against the profile's way round (for an open profile: right).
    Reflex,
}

/// How far apart (relative to the profile's scale) the end of a segment and the start of the
/// next may be: the interface contract's tolerance for drawings whose end points were rounded.
pub const JOIN_GAP: f64 = 1e-9;

/// A joint's gap (relative to the largest coordinate) that is rounding of the coordinates,
/// whatever the scale: end points computed far from the origin (an arc's, from its centre and
/// angles) round by a few units there.
const JOIN_ROUNDING: f64 = ulps(16.0);

/// Samples per segment of the polygon whose signed area gives a closed profile's orientation.
const AREA_SAMPLES: usize = 32;

/// The area (relative to the scale squared) below which a closed profile encloses nothing.
const FLAT_AREA: f64 = 1e-12;

/// A chain of segments, closed or open, with its joints.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    segments: Vec<Segment>,
    /// Per segment, where it lies in the document's parameter.
    spans: Vec<DocumentSpan>,
    closed: bool,
    joints: Vec<Joint>,
    /// +1 counterclockwise, −1 clockwise (a closed profile), 0 open.
    orientation: f64,
    /// The diagonal of the box of the control points.
    scale: f64,
    /// The largest turn a joint of this profile may have and be judged smooth.
    smooth_turn: f64,
    /// How far apart two computations of one point of it may lie.
    point_rounding: f64,
    /// Per segment, the box of its control points (`[lo x, lo y, hi x, hi y]`): it holds
    /// the segment, and bounds the distance from a point to it from below.
    boxes: Vec<[f64; 4]>,
    /// Per segment and Bézier piece, the box of the piece's Euclidean control points grown by
    /// what their rounding may hide: the disk tests pass over the pieces it keeps far.
    piece_boxes: Vec<Vec<[f64; 4]>>,
    /// The hierarchy over `boxes`.
    tree: BoxTree,
}

impl Profile {
    /// The profile of `segments`, each starting where the previous one ends (within
    /// [`JOIN_GAP`] of the scale, or a few units of rounding of the coordinates far from the
    /// origin); closed when `closed` says so, or, when it is `None`, when
    /// the last segment ends where the first starts. A spline segment with a corner inside it
    /// (a knot of full multiplicity where the tangent turns) is cut there into segments
    /// joined at that corner; [`Profile::document_param`] gives parameters in the segments as
    /// given. Errors name segments as given.
    ///
    /// ```
    /// use curve::{JointKind, ParamCurve, Profile, Segment};
    /// // A unit square, counterclockwise: four convex corners.
    /// let c = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    /// let sides = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap()).collect();
    /// let sq = Profile::new(sides, None).unwrap();
    /// assert!(sq.is_closed() && sq.domain() == (0.0, 4.0));
    /// assert!(sq.joints().iter().all(|j| j.kind == JointKind::Convex));
    /// ```
    pub fn new(segments: Vec<Segment>, closed: Option<bool>) -> Result<Self> {
        let (segments, spans) = crate::corner_knots::cut_at_corner_knots(segments)?;
        let given: Vec<usize> = spans.iter().map(|s| s.segment).collect();
        Self::of_pieces(segments, spans, closed).map_err(|e| {
            crate::corner_knots::named_as_given(e, |i| given.get(i).copied().unwrap_or(i))
        })
    }

    /// A curve (one segment: a closed spline or analytic shape, an open spline) as a profile
    /// whose parameter is the curve's own: each piece between corners covers its stretch of
    /// the segment's own domain, mapped linearly onto `domain` (the segment's own domain for
    /// a spline; `[0, 2π]` for a circle or an ellipse made as a full-turn arc).
    ///
    /// ```
    /// use curve::{ParamCurve, Profile, Segment};
    /// let circle = Segment::arc([0.0, 0.0], 2.0, 0.0, std::f64::consts::TAU).unwrap();
    /// let p = Profile::of_curve(circle, (0.0, std::f64::consts::TAU)).unwrap();
    /// assert!(p.is_closed());
    /// // A quarter of the way round is the angle π/2, at the top.
    /// let u = p.internal_param(std::f64::consts::FRAC_PI_2);
    /// assert!((p.jet(u).p.y - 2.0).abs() < 1e-15);
    /// ```
    pub fn of_curve(segment: Segment, domain: (f64, f64)) -> Result<Self> {
        let (segments, shares) = crate::corner_knots::cut_at_corner_knots(vec![segment])?;
        // (Each piece's span is its share of the segment: a segment is cut only where its own
        // parameter is the spline's, linear.)
        let on_domain = |x: f64| domain.0 + (domain.1 - domain.0) * x;
        let spans = shares
            .iter()
            .map(|s| DocumentSpan {
                segment: 0,
                lo: on_domain(s.lo),
                hi: on_domain(s.hi),
            })
            .collect();
        Self::of_pieces(segments, spans, None)
            .map_err(|e| crate::corner_knots::named_as_given(e, |_| 0))
    }

    /// The profile of segments without corners inside them, with their document spans.
    fn of_pieces(
        segments: Vec<Segment>,
        spans: Vec<DocumentSpan>,
        closed: Option<bool>,
    ) -> Result<Self> {
        if segments.is_empty() {
            return Err(Error::EmptyProfile);
        }
        let scale = scale_of(&segments);
        // (Far from the origin a joint's two ends may round apart by more than that: a few
        // units of rounding of the coordinates are no gap.)
        let point_rounding = JOIN_ROUNDING * magnitude_of(&segments);
        let room = (JOIN_GAP * scale).max(point_rounding);
        // (NaN fails too.)
        let joined = |gap: f64| gap <= room;
        for (i, w) in segments.windows(2).enumerate() {
            let gap = (w[1].start() - w[0].end()).norm();
            if !joined(gap) {
                return Err(Error::Gap {
                    segment: i + 1,
                    gap,
                    at: w[0].end().arr(),
                });
            }
        }
        let n = segments.len();
        let seam_gap = (segments[0].start() - segments[n - 1].end()).norm();
        let closed = match closed {
            Some(true) if !joined(seam_gap) => {
                return Err(Error::Gap {
                    segment: 0,
                    gap: seam_gap,
                    at: segments[n - 1].end().arr(),
                })
            }
            Some(c) => c,
            None => joined(seam_gap),
        };
        // (Before the crossings: a joint that turns back is named as that, not as the
        // crossing it makes.)
        let first = if closed { 0 } else { 1 };
        let mut turns = Vec::with_capacity(n);
        for i in first..n {
            let before = &segments[(i + n - 1) % n];
            let (Some(din), Some(dout)) = (before.end_leg(), segments[i].start_leg()) else {
                return Err(Error::ZeroLength { segment: i });
            };
            let turn = din.cross(dout).atan2(din.dot(dout));
            if turn.abs() >= std::f64::consts::PI - CORNER_TURN {
                return Err(Error::Cusp {
                    segment: i,
                    at: segments[i].start().arr(),
                });
            }
            turns.push((i, turn, smooth_turn(segments[i].start(), din, dout)));
        }
        // (Before the area: a bow tie encloses none, and its crossing is the cause.)
        if let Some(c) = first_crossing(&segments, closed, scale)? {
            return Err(Error::SelfCrossing {
                first: c.first,
                second: c.second,
                at: c.at,
            });
        }
        let orientation = if closed {
            let area = signed_area(&segments);
            if area.abs().partial_cmp(&(FLAT_AREA * scale * scale))
                != Some(std::cmp::Ordering::Greater)
            {
                return Err(Error::FlatProfile { area });
            }
            area.signum()
        } else {
            0.0
        };
        let left = if closed { orientation > 0.0 } else { true };
        // The seam of a smooth closed curve taken whole is smooth by its definition, however
        // its exact form's end tangents round (an ellipse far from the origin).
        let whole = closed && n == 1 && segments[0].whole_curve().is_some();
        let joints: Vec<Joint> = turns
            .into_iter()
            .map(|(i, turn, smooth)| Joint {
                u: i as f64,
                turn,
                // (The whole curve's seam turns by what it turns, and is smooth.)
                smooth_turn: if whole {
                    smooth.max(turn.abs())
                } else {
                    smooth
                },
                kind: if turn.abs() <= smooth || whole {
                    JointKind::Smooth
                } else if (turn > 0.0) == left {
                    JointKind::Convex
                } else {
                    JointKind::Reflex
                },
            })
            .collect();
        let smooth_turn = joints
            .iter()
            .fold(CORNER_TURN, |most, j| most.max(j.smooth_turn));
        let boxes: Vec<[f64; 4]> = segments.iter().map(control_box).collect();
        let tree = BoxTree::new(&boxes);
        let piece_boxes = segments
            .iter()
            .map(crate::piece_bounds::piece_boxes)
            .collect();
        Ok(Self {
            segments,
            spans,
            closed,
            joints,
            orientation,
            scale,
            smooth_turn,
            point_rounding,
            boxes,
            piece_boxes,
            tree,
        })
    }

    /// The box of segment `i`'s control points, `[lo x, lo y, hi x, hi y]`: it holds the
    /// segment (its weights are positive).
    pub fn segment_box(&self, i: usize) -> [f64; 4] {
        self.boxes[i]
    }

    /// The box of Bézier piece `k` of segment `i`, grown by what the rounding of its
    /// Euclidean control points may hide (see [`crate::piece_bounds`]): the piece lies in it.
    pub fn piece_box(&self, i: usize, k: usize) -> [f64; 4] {
        self.piece_boxes[i][k]
    }

    /// The hierarchy over the segments' boxes.
    pub fn box_tree(&self) -> &BoxTree {
        &self.tree
    }

    /// The diagonal of the box of the segments' control points: the scale of the profile's
    /// own tolerances ([`crate::points_scale`]). (The contract's size, which the options'
    /// relative tolerances are taken of, is the larger side of its box: [`crate::box_size`].)
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// How far apart two computations of one of its points may lie, whatever its scale: a few
    /// units of rounding of its largest coordinate (a joint's two ends, a pair found from the
    /// segments on both sides of a joint). Far below the scale near the origin; far from it,
    /// not: a part 0.03 wide drawn at 1e8 has its points rounded by 1.5e-8.
    pub fn point_rounding(&self) -> f64 {
        self.point_rounding
    }

    /// How close two of its points are to count as one, at `share` of its scale: never closer
    /// than the rounding of its points ([`Profile::point_rounding`]).
    pub fn same_point_room(&self, share: f64) -> f64 {
        (share * self.scale).max(self.point_rounding)
    }

    /// The largest turn a joint of this profile may have and be judged smooth (the most of its
    /// joints' [`Joint::smooth_turn`]): the contract's
    /// [`CORNER_TURN`], or more where the rounding of its tangents is more (a drawing far from
    /// the origin with short segments; see [`crate::smooth_turn`]). Whoever trusts a joint to be
    /// smooth trusts it to this turn.
    pub fn smooth_turn(&self) -> f64 {
        self.smooth_turn
    }

    /// The first point.
    pub fn start(&self) -> V2 {
        self.segments[0].start()
    }

    /// The segments in order.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// The joints in order of their parameter (the seam, at `u = 0`, first on a closed
    /// profile; an open profile's ends are not joints).
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The corners (joints that are not smooth).
    pub fn corners(&self) -> impl Iterator<Item = &Joint> {
        self.joints.iter().filter(|j| j.kind != JointKind::Smooth)
    }

    /// `+1` for a closed profile running counterclockwise round its region, `−1` clockwise,
    /// `0` for an open one.
    pub fn orientation(&self) -> f64 {
        self.orientation
    }

    /// The segment holding the profile parameter `u` and the share `x ∈ [0, 1]` of it (a joint
    /// belongs to the segment starting there; the domain's end to the last segment).
    pub fn locate(&self, u: f64) -> (usize, f64) {
        let n = self.segments.len();
        let u = u.clamp(0.0, n as f64);
        let i = (u.floor() as usize).min(n - 1);
        (i, u - i as f64)
    }

    /// The jet of segment `i` at the profile parameter `u` (clamped to the segment's
    /// `[i, i + 1]`): at a joint, the segment asked for, not the one starting there.
    pub fn jet_on(&self, i: usize, u: f64, order: usize) -> Jet {
        let x = (u - i as f64).clamp(0.0, 1.0);
        self.segments[i].jet_in_unit(x, order)
    }

    /// Where each segment lies in the document's parameter.
    pub fn document_spans(&self) -> &[DocumentSpan] {
        &self.spans
    }

    /// The same profile with its document parameter moved onto `spans` (one per segment, in
    /// order, increasing): for a profile made again from moved or rebuilt segments.
    pub fn with_document_spans(mut self, spans: Vec<DocumentSpan>) -> Self {
        if spans.len() == self.segments.len() {
            self.spans = spans;
        }
        self
    }

    /// The domain of the document's parameter.
    pub fn document_domain(&self) -> (f64, f64) {
        let n = self.spans.len();
        (self.spans[0].lo, self.spans[n - 1].hi)
    }

    /// The document's parameter at the profile parameter `u` (as its file gives it: an arc's
    /// angle share, a curve's own parameter; see [`DocumentSpan`]).
    pub fn document_param(&self, u: f64) -> f64 {
        let (i, x) = self.locate(u);
        self.document_param_on(i, x)
    }

    /// The document's parameter at the share `x ∈ [0, 1]` of segment `i`'s exact form.
    pub fn document_param_on(&self, i: usize, x: f64) -> f64 {
        let s = &self.segments[i];
        let (a, b) = s.curve().domain();
        let (own_lo, own_hi) = s.own_domain();
        let own = s.own_at(a + x * (b - a));
        let span = self.spans[i];
        span.lo + (span.hi - span.lo) * ((own - own_lo) / (own_hi - own_lo))
    }

    /// The document's segment index of segment `i` (a segment cut at a corner inside it is
    /// one segment of its document).
    pub fn document_segment(&self, i: usize) -> usize {
        self.spans[i].segment
    }

    /// The profile parameter of the document's parameter `d` (the inverse of
    /// [`Profile::document_param`]; clamped to the document's domain).
    pub fn internal_param(&self, d: f64) -> f64 {
        let n = self.spans.len();
        let i = self.spans.partition_point(|s| s.hi <= d).min(n - 1);
        let span = self.spans[i];
        let s = &self.segments[i];
        let (own_lo, own_hi) = s.own_domain();
        let share = ((d - span.lo) / (span.hi - span.lo)).clamp(0.0, 1.0);
        let dom = s.curve().domain();
        let v = s.own_param().form(own_lo + share * (own_hi - own_lo), dom);
        i as f64 + ((v - dom.0) / (dom.1 - dom.0)).clamp(0.0, 1.0)
    }

    /// The profile parameter of segment `i`'s own parameter `v`.
    pub fn profile_param(&self, i: usize, v: f64) -> f64 {
        let (a, b) = self.segments[i].curve().domain();
        i as f64 + (v - a) / (b - a)
    }
}

/// A profile is known to the algorithms of smooth curves by evaluation only: its segments'
/// exact forms are taken segment by segment by the algorithms that know of profiles.
impl crate::plane::PlaneCurve for Profile {}

impl ParamCurve for Profile {
    fn domain(&self) -> (f64, f64) {
        (0.0, self.segments.len() as f64)
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn jet_to(&self, u: f64, order: usize) -> Jet {
        let (i, x) = self.locate(u);
        self.segments[i].jet_in_unit(x, order)
    }
}

/// The box of a segment's control points, `[lo x, lo y, hi x, hi y]`.
fn control_box(s: &Segment) -> [f64; 4] {
    s.curve().control_points().iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        },
    )
}

/// The scale of the segments' control points.
fn scale_of(segments: &[Segment]) -> f64 {
    points_scale(segments.iter().flat_map(|s| s.curve().control_points()))
}

/// The largest coordinate of the segments' control points.
fn magnitude_of(segments: &[Segment]) -> f64 {
    segments
        .iter()
        .flat_map(|s| s.curve().control_points())
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()))
}

/// The signed area of the polygon through samples of the segments (positive
/// counterclockwise), about the first point (for the precision of shapes far from the origin).
fn signed_area(segments: &[Segment]) -> f64 {
    let origin = segments[0].start();
    let mut last = V2::new(0.0, 0.0);
    let mut twice = 0.0;
    for s in segments {
        for k in 1..=AREA_SAMPLES {
            let p = s.jet_in_unit(k as f64 / AREA_SAMPLES as f64, 0).p - origin;
            twice += last.cross(p);
            last = p;
        }
    }
    0.5 * twice
}

#[cfg(test)]
mod tests;
