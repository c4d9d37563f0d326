//! A profile cut into its polynomial or rational pieces: the spline segments at their knots,
//! lines and arcs whole. Work that grows with the pairs of pieces (bisectors, the medial
//! axis) can then skip the pairs that cannot matter, which one long B-spline segment hides.

use crate::error::Result;
use crate::param::ParamCurve;
use crate::profile::Profile;
use crate::segment::{Segment, SegmentKind};
use crate::spline::SplineCurve;

/// Where a segment of a cut profile lies on the profile it was cut from: on segment
/// `segment`, from profile parameter `from` to `to` (the cut profile's parameter runs
/// affinely between them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpanOf {
    /// The segment of the profile cut.
    pub segment: usize,
    /// The profile parameter where the span starts.
    pub from: f64,
    /// The profile parameter where it ends.
    pub to: f64,
}

impl SpanOf {
    /// The profile parameter of the cut profile's parameter `w` on this span (span `index`).
    pub fn param(&self, index: usize, w: f64) -> f64 {
        self.from + (w - index as f64) * (self.to - self.from)
    }
}

impl Segment {
    /// The segment's own parameters where its pieces begin and end, in order: a spline
    /// segment's distinct knots over its domain, a line's or an arc's ends (kept whole).
    pub fn piece_breaks(&self) -> Vec<f64> {
        let knots = self.curve().curve().homogeneous().breakpoints();
        match self.kind() {
            SegmentKind::Bezier | SegmentKind::BSpline if knots.len() > 2 => knots,
            _ => {
                let (a, b) = self.curve().domain();
                vec![a, b]
            }
        }
    }
}

impl Profile {
    /// The profile with every spline segment of several spans cut at its knots into those
    /// spans (the same curve, each span a Bézier segment), and where each span lies on this
    /// profile; `None` when no segment has more than one span.
    ///
    /// ```
    /// use curve::{Profile, Segment, SegmentKind, SplineCurve};
    /// // A closed uniform cubic B-spline of 6 control points, clamped: 3 spans.
    /// let pts = [[0., 0.], [2., -1.], [4., 0.], [4., 2.], [2., 1.2], [0., 0.]];
    /// let c = SplineCurve::clamped(3, &pts, None, None).unwrap();
    /// let p = Profile::new(vec![Segment::spline(SegmentKind::BSpline, c).unwrap()], None).unwrap();
    /// let (cut, spans) = p.split_at_knots().unwrap().unwrap();
    /// assert_eq!(cut.segments().len(), 3);
    /// assert_eq!(spans[1].segment, 0);
    /// assert!((spans[1].param(1, 1.5) - 0.5).abs() < 1e-15);
    /// ```
    pub fn split_at_knots(&self) -> Result<Option<(Profile, Vec<SpanOf>)>> {
        let splits = |s: &Segment| s.piece_breaks().len() > 2;
        if !self.segments().iter().any(splits) {
            return Ok(None);
        }
        let mut segments = Vec::new();
        let mut spans = Vec::new();
        for (i, s) in self.segments().iter().enumerate() {
            if !splits(s) {
                segments.push(s.clone());
                spans.push(SpanOf {
                    segment: i,
                    from: i as f64,
                    to: (i + 1) as f64,
                });
                continue;
            }
            for w in s.piece_breaks().windows(2) {
                let piece = SplineCurve::new(s.curve().curve().restrict(w[0], w[1])?)?;
                segments.push(Segment::spline(SegmentKind::Bezier, piece)?);
                spans.push(SpanOf {
                    segment: i,
                    from: self.profile_param(i, w[0]),
                    to: self.profile_param(i, w[1]),
                });
            }
        }
        let cut = Profile::new(segments, Some(self.is_closed()))?;
        Ok(Some((cut, spans)))
    }
}
