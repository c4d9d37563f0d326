//! The segments a profile is made of (see [`crate::Profile`]): straight lines and circular
//! arcs, each with an exact rational form (a linear Bézier curve; rational quadratic pieces),
//! and open Bézier and B-spline curves. Every segment is an open [`SplineCurve`], so each
//! algorithm that runs on a spline runs on a segment.

use crate::error::{Error, Result};
use crate::geom::{Jet, V2};
use crate::own_param::OwnParam;
use crate::param::ParamCurve;
use crate::plane::ExactCurve;
use crate::shapes::{circle_form_spline, CircleShape, Shape};
use crate::spline::SplineCurve;
use std::f64::consts::{FRAC_PI_2, TAU};

/// What a segment was given as (its exact form is a [`SplineCurve`] in every case).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SegmentKind {
    /// A straight line from one point to another.
    Line,
    /// A circular arc.
    Arc,
    /// An elliptical arc (an SVG arc, a DXF `ELLIPSE`): a circular arc moved by an affine map.
    EllipticArc,
    /// A Bézier curve.
    Bezier,
    /// An open B-spline or NURBS curve.
    BSpline,
}

impl SegmentKind {
    /// The kind's name in curve files.
    pub fn name(self) -> &'static str {
        match self {
            SegmentKind::Line => "line",
            SegmentKind::Arc => "arc",
            SegmentKind::EllipticArc => "elliptic_arc",
            SegmentKind::Bezier => "bezier",
            SegmentKind::BSpline => "bspline",
        }
    }
}

/// One segment of a profile: an open curve with its kind.
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    kind: SegmentKind,
    curve: SplineCurve,
    /// The centre and radius of a circular arc, as defined (arcs of one circle share them
    /// exactly: a continuum of antipodal pairs between them is proven by their definition).
    circle: Option<([f64; 2], f64)>,
    /// How the exact form's parameter maps to the segment's own (an arc's angle share).
    own: OwnParam,
    /// The smooth closed curve the segment runs once round, as it was defined, where it was
    /// made from one (see [`Segment::whole_curve`]).
    whole: Option<ExactCurve>,
}

/// The widest angle one rational quadratic piece of an arc spans: a quarter turn keeps its
/// middle weight `cos(δ/2)` at least `cos(π/4)` and its middle control point near the arc.
const ARC_PIECE: f64 = FRAC_PI_2;

/// Room for the rounding of `|end − start|` against a full turn (radians).
const FULL_TURN_ROUNDING: f64 = 1e-12;

impl Segment {
    /// The straight line from `from` to `to` (parameter `[0, 1]`, uniform speed).
    ///
    /// ```
    /// use curve::{ParamCurve, Segment};
    /// let l = Segment::line([0.0, 0.0], [2.0, 0.0]).unwrap();
    /// assert_eq!(l.jet(0.5).p.arr(), [1.0, 0.0]);
    /// ```
    pub fn line(from: [f64; 2], to: [f64; 2]) -> Result<Self> {
        finite_point("from", from)?;
        finite_point("to", to)?;
        if from == to {
            return Err(Error::InvalidShape {
                field: "to",
                value: to[0],
                why: "a point other than `from`",
            });
        }
        Ok(Self {
            kind: SegmentKind::Line,
            curve: SplineCurve::clamped(1, &[from, to], None, None)?,
            circle: None,
            own: OwnParam::Same,
            whole: None,
        })
    }

    /// The arc of the circle about `center` with radius `r` from the angle `start` to `end`
    /// (radians; counterclockwise when `end > start`, clockwise when `end < start`, at most a
    /// full turn). Its exact form is `k ≤ 4` rational quadratic pieces of equal angle, with
    /// knots at `i/k` on `[0, 1]`: the form's parameter (at `i/k` the point is at the angle
    /// `start + (i/k)(end − start)`; between knots it runs within a few percent of the angle's
    /// share) is not the arc's own, which is proportional to the angle
    /// ([`Segment::own_param`] converts). The points are the circle's rounded to doubles.
    ///
    /// ```
    /// use curve::{ParamCurve, Segment};
    /// let a = Segment::arc([0.0, 0.0], 2.0, 0.0, std::f64::consts::PI).unwrap();
    /// let top = a.jet(0.5).p;
    /// assert!((top.x - 0.0).abs() < 1e-15 && (top.y - 2.0).abs() < 1e-15);
    /// ```
    pub fn arc(center: [f64; 2], r: f64, start: f64, end: f64) -> Result<Self> {
        finite_point("center", center)?;
        if !(r.is_finite() && r > 0.0) {
            return Err(Error::InvalidShape {
                field: "r",
                value: r,
                why: "finite and > 0",
            });
        }
        for (field, a) in [("start", start), ("end", end)] {
            if !a.is_finite() {
                return Err(Error::InvalidShape {
                    field,
                    value: a,
                    why: "finite",
                });
            }
        }
        let sweep = end - start;
        if sweep == 0.0 {
            return Err(Error::InvalidShape {
                field: "end",
                value: end,
                why: "other than start",
            });
        }
        if sweep.abs() > TAU + FULL_TURN_ROUNDING {
            return Err(Error::InvalidShape {
                field: "end",
                value: end,
                why: "within 2π of start",
            });
        }
        let full = sweep.abs() >= TAU - FULL_TURN_ROUNDING;
        let k = ((sweep.abs() / ARC_PIECE).ceil() as usize).clamp(1, 4);
        let step = sweep / k as f64;
        let at = |a: f64, radius: f64| {
            let (s, c) = a.sin_cos();
            [center[0] + radius * c, center[1] + radius * s]
        };
        let mid_weight = (0.5 * step).cos();
        let mut points = Vec::with_capacity(2 * k + 1);
        let mut weights = Vec::with_capacity(2 * k + 1);
        for j in 0..k {
            let a = start + step * j as f64;
            points.push(at(a, r));
            weights.push(1.0);
            points.push(at(a + 0.5 * step, r / mid_weight));
            weights.push(mid_weight);
        }
        // A full turn ends exactly where it starts (the angle's rounding would leave a gap).
        points.push(if full { points[0] } else { at(end, r) });
        weights.push(1.0);
        let mut knots = vec![0.0; 3];
        for j in 1..k {
            let x = j as f64 / k as f64;
            knots.extend([x, x]);
        }
        knots.extend([1.0; 3]);
        Ok(Self {
            kind: SegmentKind::Arc,
            curve: SplineCurve::clamped(2, &points, Some(&weights), Some(knots))?,
            circle: Some((center, r)),
            own: OwnParam::Arc {
                pieces: k,
                piece_sweep: step,
            },
            whole: None,
        })
    }

    /// An open Bézier or B-spline curve as a segment (`kind` says which it was given as).
    /// A periodic curve has no ends to join: refused.
    pub fn spline(kind: SegmentKind, curve: SplineCurve) -> Result<Self> {
        if curve.periodic_order().is_some() {
            return Err(Error::InvalidShape {
                field: "periodic",
                value: 1.0,
                why: "false: a profile's segments are open curves",
            });
        }
        Ok(Self {
            kind,
            curve,
            circle: None,
            own: OwnParam::Same,
            whole: None,
        })
    }

    /// A segment from its parts (the caller vouches that `curve` is of `kind`, on `circle`
    /// where one is given, and that `own` is how its parameter maps to its own).
    pub(crate) fn from_parts(
        kind: SegmentKind,
        curve: SplineCurve,
        circle: Option<([f64; 2], f64)>,
        own: OwnParam,
    ) -> Self {
        Self {
            kind,
            curve,
            circle,
            own,
            whole: None,
        }
    }

    /// A periodic spline as the segment that runs once round it: the spline clamped over its
    /// domain (the same curve, its seam now the segment's ends), its parameter the spline's.
    /// Where the spline is at least `C¹` across its seam and regular there (its derivative
    /// not zero: repeated control points about the seam may make a corner of a `C¹`
    /// spline), the segment keeps it as its [`whole curve`](Segment::whole_curve): smooth
    /// there by definition.
    ///
    /// ```
    /// use curve::{ParamCurve, Segment, SegmentKind, SplineCurve};
    /// let ring = [[2.0, 0.0], [0.0, 1.0], [-2.0, 0.0], [0.0, -1.0]];
    /// let spline = SplineCurve::periodic(3, &ring, None).unwrap();
    /// let seg = Segment::periodic_spline(SegmentKind::BSpline, &spline).unwrap();
    /// assert!(seg.is_closed() && seg.whole_curve().is_some());
    /// assert!((seg.jet(1.5).p - spline.jet(1.5).p).norm() < 1e-15);
    /// ```
    pub fn periodic_spline(kind: SegmentKind, periodic: &SplineCurve) -> Result<Self> {
        let Some(order) = periodic.periodic_order() else {
            return Err(Error::InvalidShape {
                field: "periodic",
                value: 0.0,
                why: "true: a periodic spline",
            });
        };
        let (a, b) = periodic.domain();
        let clamped = SplineCurve::new(periodic.curve().restrict(a, b)?)?;
        let segment = Segment::spline(kind, clamped)?;
        let regular = periodic.jet_to(a, 1).d1.norm() > 0.0;
        Ok(if order >= 1 && regular {
            segment.of_whole_curve(ExactCurve::Spline(Box::new(periodic.clone())))
        } else {
            segment
        })
    }

    /// An analytic shape as one closed segment, for a profile whose parameter is the shape's
    /// angle φ ∈ `[0, 2π)` ([`crate::Profile::of_curve`] on `(0, 2π)`): a circle or an
    /// ellipse as a full-turn arc (its own parameter the angle's share), the other shapes as
    /// their exact rational form on the rational circle (its own parameter the angle itself),
    /// with the rounding of that form's coefficients as their error. The shape is the
    /// segment's [`whole curve`](Segment::whole_curve).
    ///
    /// ```
    /// use curve::shapes::{Limacon, Shape};
    /// use curve::{ParamCurve, Profile, Segment};
    /// let shape = Shape::Limacon(Limacon::new(4.0, 2.5).unwrap());
    /// let seg = Segment::of_shape(shape).unwrap();
    /// let p = Profile::of_curve(seg, (0.0, std::f64::consts::TAU)).unwrap();
    /// let u = p.internal_param(1.0);
    /// let want = shape.jet(1.0).p;
    /// assert!((p.jet(u).p - want).norm() < 1e-13);
    /// ```
    pub fn of_shape(shape: Shape) -> Result<Self> {
        let segment = match (shape, shape.circle_shape()) {
            (Shape::Circle(c), _) => Segment::arc(c.center(), c.r(), 0.0, TAU),
            (Shape::Ellipse(e), _) => {
                Segment::elliptic_arc(e.center(), e.a(), e.b(), 0.0, 0.0, TAU)
            }
            (shape, circle) => {
                // (A slender lemniscate has a form too; the antipodal search only declines it.)
                let form = match (shape, circle) {
                    (_, Some(form)) => form,
                    (Shape::EllipticLemniscate(l), None) => {
                        CircleShape::Lemniscate { a: l.a(), b: l.b() }
                    }
                    _ => unreachable!("every other shape has a circle form"),
                };
                let (hom, err) = circle_form_spline(form)?;
                let rational = bspline::Rational::from_homogeneous_with_error(hom, err)?;
                Ok(Segment::from_parts(
                    SegmentKind::BSpline,
                    SplineCurve::new(rational)?,
                    None,
                    OwnParam::Angle(form.angle()),
                ))
            }
        }?;
        Ok(segment.of_whole_curve(ExactCurve::Shape(shape)))
    }

    /// The segment as the one that runs once round `whole`, its parameter `whole`'s (the
    /// caller vouches for both).
    pub(crate) fn of_whole_curve(self, whole: ExactCurve) -> Self {
        Self {
            whole: Some(whole),
            ..self
        }
    }

    /// The smooth closed curve the segment runs once round, as it was defined (an analytic
    /// shape, a periodic spline `C¹` or smoother and regular across its seam), where it was
    /// made from one ([`Segment::of_shape`], [`Segment::periodic_spline`]); its parameter maps
    /// linearly onto the segment's own ([`Segment::form_param_of_whole`]). A closed profile
    /// of this one segment is that curve:
    /// its seam is smooth by definition, and the algorithms of smooth closed curves run on it
    /// as defined. A segment moved, reversed or cut is a segment of its own (`None`).
    pub fn whole_curve(&self) -> Option<&ExactCurve> {
        self.whole.as_ref()
    }

    /// The exact form's parameter at the parameter `x` of the segment's whole curve (within
    /// its domain; `None` without one): the segment's own parameter is the whole curve's,
    /// mapped linearly onto the own domain (an arc's share of the turn for a circle or an
    /// ellipse, the angle itself for the other shapes, a spline's own).
    pub fn form_param_of_whole(&self, x: f64) -> Option<f64> {
        let whole = self.whole.as_ref()?;
        let (wa, wb) = whole.curve().domain();
        let (oa, ob) = self.own_domain();
        let own = if (wa, wb) == (oa, ob) {
            x
        } else {
            oa + (x - wa) / (wb - wa) * (ob - oa)
        };
        Some(self.own.form(own, self.curve.domain()))
    }

    /// How the exact form's parameter maps to the segment's own: the identity but for arcs
    /// (own parameter proportional to the angle) and analytic shapes (their angle φ).
    pub fn own_param(&self) -> OwnParam {
        self.own
    }

    /// The segment's own parameter at the exact form's parameter `v`.
    pub fn own_at(&self, v: f64) -> f64 {
        self.own.own(v, self.curve.domain())
    }

    /// The domain of the segment's own parameter.
    pub fn own_domain(&self) -> (f64, f64) {
        self.own.own_domain(self.curve.domain())
    }

    /// The centre and radius of a circular arc as defined (`None` for other kinds): arcs of
    /// one circle carry the same ones exactly.
    pub fn circle(&self) -> Option<([f64; 2], f64)> {
        self.circle
    }

    /// What the segment was given as.
    pub fn kind(&self) -> SegmentKind {
        self.kind
    }

    /// Its exact form.
    pub fn curve(&self) -> &SplineCurve {
        &self.curve
    }

    /// The first point.
    pub fn start(&self) -> V2 {
        self.curve.jet_to(self.curve.domain().0, 0).p
    }

    /// The last point.
    pub fn end(&self) -> V2 {
        self.curve.jet_to(self.curve.domain().1, 0).p
    }

    /// The unit tangent leaving the first point (from the first control point that differs from
    /// it: a repeated end point leaves the first derivative zero there).
    pub fn start_direction(&self) -> Option<V2> {
        self.start_leg().map(V2::unit)
    }

    /// The unit tangent arriving at the last point.
    pub fn end_direction(&self) -> Option<V2> {
        self.end_leg().map(V2::unit)
    }

    /// The control polygon's first leg: from the first point to the first control point that
    /// differs from it (along the tangent leaving the first point; its length says how far
    /// the rounding of the points can turn that tangent).
    pub fn start_leg(&self) -> Option<V2> {
        let pts = self.curve.control_points();
        let first = V2::from_arr(pts[0]);
        pts.iter()
            .map(|&p| V2::from_arr(p) - first)
            .find(|d| d.norm() > 0.0)
    }

    /// The control polygon's last leg, arriving at the last point.
    pub fn end_leg(&self) -> Option<V2> {
        let pts = self.curve.control_points();
        let last = V2::from_arr(pts[pts.len() - 1]);
        pts.iter()
            .rev()
            .map(|&p| last - V2::from_arr(p))
            .find(|d| d.norm() > 0.0)
    }

    /// The jet at `x ∈ [0, 1]`, the segment's share of a profile's parameter (mapped linearly
    /// onto its own domain).
    pub(crate) fn jet_in_unit(&self, x: f64, order: usize) -> Jet {
        let (a, b) = self.curve.domain();
        let w = b - a;
        let j = self.curve.jet_to(a + x * w, order);
        Jet {
            p: j.p,
            d1: j.d1 * w,
            d2: j.d2 * (w * w),
            d3: j.d3 * (w * w * w),
        }
    }
}

/// A segment evaluates as its exact form, in that form's parameter.
impl ParamCurve for Segment {
    fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    fn is_closed(&self) -> bool {
        self.curve.is_closed()
    }

    fn jet_to(&self, u: f64, order: usize) -> Jet {
        self.curve.jet_to(u, order)
    }
}

fn finite_point(field: &'static str, p: [f64; 2]) -> Result<()> {
    match p.iter().find(|x| !x.is_finite()) {
        Some(&x) => Err(Error::InvalidShape {
            field,
            value: x,
            why: "finite",
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use proptest::prelude::*;
    use std::f64::consts::PI;

    proptest! {
        /// Every point of an arc's exact form lies on its circle, its ends at the angles given,
        /// its tangent turns the way the arc runs, and the knots sit at equal shares of the
        /// angle.
        #[test]
        fn arcs_lie_on_their_circles(
            cx in -1e3f64..1e3, cy in -1e3f64..1e3,
            r in 1e-3f64..1e3,
            start in -10.0f64..10.0,
            sweep in prop_oneof![-TAU..-1e-3, 1e-3..TAU, Just(TAU), Just(-TAU)],
        ) {
            let a = Segment::arc([cx, cy], r, start, start + sweep).unwrap();
            let c = V2::new(cx, cy);
            let size = r + cx.abs().max(cy.abs());
            for i in 0..=64 {
                let j = a.curve().jet(i as f64 / 64.0);
                testkit::prop_assert_near!((j.p - c).norm(), r, 1e-13 * size);
                // Counterclockwise: the tangent turns left of the radius.
                prop_assert!((j.p - c).cross(j.d1) * sweep > 0.0);
            }
            let end = c + V2::polar(start + sweep) * r;
            prop_assert!((a.end() - end).norm() <= 1e-12 * size);
            let k = ((sweep.abs() / ARC_PIECE).ceil() as usize).clamp(1, 4);
            for i in 0..=k {
                let p = a.curve().jet(i as f64 / k as f64).p;
                let want = c + V2::polar(start + sweep * i as f64 / k as f64) * r;
                prop_assert!((p - want).norm() <= 1e-12 * size, "{p:?} {want:?}");
            }
        }
    }

    #[test]
    fn a_periodic_spline_is_whole_only_where_smooth_and_regular_at_its_seam() {
        let smooth = [[2.0, 0.0], [0.0, 1.0], [-2.0, 0.0], [0.0, -1.0]];
        let c = SplineCurve::periodic(3, &smooth, None).unwrap();
        let seg = Segment::periodic_spline(SegmentKind::BSpline, &c).unwrap();
        assert!(matches!(seg.whole_curve(), Some(ExactCurve::Spline(s)) if **s == c));
        // The seam (u = 0) is shaped by the first four points, its derivative half the
        // third less the first: those are one point, and the derivative vanishes there, where
        // the tangent turns (a corner).
        let pinched = [[2.0, 1.0], [0.0, 0.0], [2.0, 1.0], [3.0, 3.0], [0.0, 3.0]];
        let c = SplineCurve::periodic(3, &pinched, None).unwrap();
        let seg = Segment::periodic_spline(SegmentKind::BSpline, &c).unwrap();
        assert!(seg.whole_curve().is_none());
        // A polygon, C⁰: no whole curve either.
        let c = SplineCurve::periodic(1, &smooth, None).unwrap();
        let seg = Segment::periodic_spline(SegmentKind::BSpline, &c).unwrap();
        assert!(seg.whole_curve().is_none());
    }

    #[test]
    fn a_full_turn_is_closed_and_half_turns_are_not() {
        let full = Segment::arc([1.0, 2.0], 3.0, 0.3, 0.3 + TAU).unwrap();
        assert_eq!(full.start(), full.end());
        assert!(full.curve().is_closed());
        let half = Segment::arc([1.0, 2.0], 3.0, 0.3, 0.3 - PI).unwrap();
        assert!(!half.curve().is_closed());
    }

    #[test]
    fn bad_lines_and_arcs_name_their_field() {
        let field = |e: Error| match e {
            Error::InvalidShape { field, .. } => field,
            e => panic!("{e}"),
        };
        assert_eq!(
            field(Segment::line([1.0, 1.0], [1.0, 1.0]).unwrap_err()),
            "to"
        );
        assert_eq!(
            field(Segment::line([f64::NAN, 1.0], [1.0, 1.0]).unwrap_err()),
            "from"
        );
        assert_eq!(
            field(Segment::arc([0.0, 0.0], 0.0, 0.0, 1.0).unwrap_err()),
            "r"
        );
        assert_eq!(
            field(Segment::arc([0.0, 0.0], 1.0, 0.0, 0.0).unwrap_err()),
            "end"
        );
        assert_eq!(
            field(Segment::arc([0.0, 0.0], 1.0, 0.0, 7.0).unwrap_err()),
            "end"
        );
        assert_eq!(
            field(Segment::arc([0.0, 0.0], 1.0, f64::INFINITY, 1.0).unwrap_err()),
            "start"
        );
    }

    #[test]
    fn end_directions_skip_repeated_points() {
        let c = SplineCurve::clamped(
            3,
            &[[0.0, 0.0], [0.0, 0.0], [1.0, 1.0], [2.0, 1.0]],
            None,
            None,
        )
        .unwrap();
        let s = Segment::spline(SegmentKind::Bezier, c).unwrap();
        let d = s.start_direction().unwrap();
        assert!((d.x - d.y).abs() < 1e-15 && d.x > 0.0);
        assert_eq!(s.end_direction().unwrap().arr(), [1.0, 0.0]);
    }
}
