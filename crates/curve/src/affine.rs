//! Affine maps of the plane and what drawing readers do with segments: move them by a
//! transform (SVG's `transform`, DXF's extrusion direction), run them backwards (chaining
//! entities drawn either way), and elliptical arcs, the affine images of circular ones (a
//! rational quadratic form is carried exactly by an affine map: control points move, weights
//! stay).

use crate::error::{Error, Result};
use crate::geom::V2;
use crate::own_param::OwnParam;
use crate::param::ParamCurve;
use crate::profile::Profile;
use crate::region::Region;
use crate::segment::{Segment, SegmentKind};
use crate::spline::SplineCurve;

/// The affine map `p ↦ (a·x + c·y + e, b·x + d·y + f)` (SVG's `matrix(a b c d e f)`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine(pub [f64; 6]);

/// How far from a similarity (relative to the map's scale) an affine map may be and still
/// carry circles to circles: the rounding of a rotation's sine and cosine, and more.
const SIMILARITY: f64 = 1e-12;

impl Affine {
    /// The identity.
    pub const IDENTITY: Affine = Affine([1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);

    /// The image of `p`.
    pub fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        let [a, b, c, d, e, f] = self.0;
        [a * p[0] + c * p[1] + e, b * p[0] + d * p[1] + f]
    }

    /// `self` after `inner`: the map `p ↦ self(inner(p))`.
    pub fn after(&self, inner: &Affine) -> Affine {
        let [a, b, c, d, e, f] = self.0;
        let [a2, b2, c2, d2, e2, f2] = inner.0;
        Affine([
            a * a2 + c * b2,
            b * a2 + d * b2,
            a * c2 + c * d2,
            b * c2 + d * d2,
            a * e2 + c * f2 + e,
            b * e2 + d * f2 + f,
        ])
    }

    /// The determinant of the linear part (negative: the map mirrors).
    pub fn determinant(&self) -> f64 {
        let [a, b, c, d, _, _] = self.0;
        a * d - b * c
    }

    /// Whether the linear part is a rotation times a scale (possibly mirrored): circles stay
    /// circles.
    pub fn is_similarity(&self) -> bool {
        let [a, b, c, d, _, _] = self.0;
        let scale = a.abs().max(b.abs()).max(c.abs()).max(d.abs());
        let (col0, col1) = (a * a + b * b, c * c + d * d);
        (col0 - col1).abs() <= SIMILARITY * scale * scale
            && (a * c + b * d).abs() <= SIMILARITY * scale * scale
    }

    /// Whether every coefficient is finite and the map is invertible.
    pub fn is_valid(&self) -> bool {
        self.0.iter().all(|x| x.is_finite()) && self.determinant() != 0.0
    }
}

impl Profile {
    /// The profile moved by `map`, segment by segment ([`Segment::transformed`]), open or
    /// closed as it was. Its corners and joints are those of the moved segments, checked
    /// anew.
    ///
    /// ```
    /// use curve::{Affine, ParamCurve, Profile, Segment};
    /// let side = Profile::new(vec![Segment::line([0.0, 0.0], [1.0, 0.0]).unwrap()], None).unwrap();
    /// let moved = side.transformed(&Affine([0.0, 1.0, -1.0, 0.0, 5.0, 0.0])).unwrap();
    /// assert_eq!(moved.jet_to(1.0, 0).p.arr(), [5.0, 1.0]);
    /// ```
    pub fn transformed(&self, map: &Affine) -> Result<Profile> {
        let segments = self
            .segments()
            .iter()
            .map(|s| s.transformed(map))
            .collect::<Result<Vec<_>>>()?;
        Ok(Profile::new(segments, Some(self.is_closed()))?
            .with_document_spans(self.document_spans().to_vec()))
    }
}

impl Region {
    /// The region moved by `map`: its outer boundary and every hole
    /// ([`Profile::transformed`]), validated anew.
    pub fn transformed(&self, map: &Affine) -> Result<Region> {
        let holes = self
            .holes()
            .iter()
            .map(|h| h.transformed(map))
            .collect::<Result<Vec<_>>>()?;
        Region::new(self.outer().transformed(map)?, holes)
    }
}

impl Segment {
    /// The segment moved by `map` (its control points moved, its weights kept: exact for
    /// every kind). A circular arc stays one under a similarity; under any other map it
    /// becomes an elliptical arc.
    ///
    /// ```
    /// use curve::{Affine, ParamCurve, Segment, SegmentKind};
    /// let arc = Segment::arc([0.0, 0.0], 1.0, 0.0, 1.0).unwrap();
    /// let squashed = arc.transformed(&Affine([2.0, 0.0, 0.0, 1.0, 0.0, 0.0])).unwrap();
    /// assert_eq!(squashed.kind(), SegmentKind::EllipticArc);
    /// let p = squashed.jet(0.5).p;
    /// assert!(((p.x / 2.0).powi(2) + p.y.powi(2) - 1.0).abs() < 1e-15);
    /// ```
    pub fn transformed(&self, map: &Affine) -> Result<Segment> {
        if !map.is_valid() {
            return Err(Error::InvalidShape {
                field: "transform",
                value: map.determinant(),
                why: "an invertible map with finite coefficients",
            });
        }
        let c = self.curve();
        let points: Vec<[f64; 2]> = c.control_points().iter().map(|&p| map.apply(p)).collect();
        let (kind, circle) = match (self.kind(), self.circle()) {
            (SegmentKind::Arc, Some((center, r))) if map.is_similarity() => (
                SegmentKind::Arc,
                Some((map.apply(center), r * map.determinant().abs().sqrt())),
            ),
            (SegmentKind::Arc, _) => (SegmentKind::EllipticArc, None),
            (k, _) => (k, None),
        };
        rebuilt(kind, c, points, false, circle, self.own_param())
    }

    /// The segment with its first point moved to `start` and its last to `end` (where given):
    /// how a drawing reader closes a gap within the drawing's tolerance. Only the end control
    /// points move, weights and knots stay; an arc whose ends move is no longer circular (a
    /// rational quadratic spline, its parameter its own).
    pub fn with_ends(&self, start: Option<V2>, end: Option<V2>) -> Result<Segment> {
        let c = self.curve();
        let mut points = c.control_points();
        let n = points.len();
        let old = (points[0], points[n - 1]);
        if let Some(p) = start {
            points[0] = p.arr();
        }
        if let Some(p) = end {
            points[n - 1] = p.arr();
        }
        if (points[0], points[n - 1]) == old {
            return Ok(self.clone());
        }
        if self.kind() == SegmentKind::Line {
            return Segment::line(points[0], points[n - 1]);
        }
        let (kind, own) = match self.kind() {
            SegmentKind::Arc | SegmentKind::EllipticArc => (SegmentKind::BSpline, OwnParam::Same),
            kind => (kind, self.own_param()),
        };
        rebuilt(kind, c, points, false, None, own)
    }

    /// The same segment run backwards (its parameter `v ↦ a + b − v`).
    pub fn reversed(&self) -> Result<Segment> {
        let c = self.curve();
        let mut points = c.control_points();
        points.reverse();
        // (An arc's pieces are symmetric: its map to the angle share is the same backwards.
        // An analytic shape's angle is not: run backwards it is a spline of its own.)
        let own = match self.own_param() {
            OwnParam::Angle(_) => OwnParam::Same,
            own => own,
        };
        rebuilt(self.kind(), c, points, true, self.circle(), own)
    }

    /// The arc of the ellipse with centre `center`, semi-axes `rx`, `ry` (the first along the
    /// direction at angle `rotation`), from the eccentric angle `start` to `end`
    /// (counterclockwise when `end > start`, at most a full turn): the affine image of a
    /// circular arc, exact as rational quadratic pieces. Parameter `[0, 1]`.
    ///
    /// ```
    /// use curve::{ParamCurve, Segment};
    /// use std::f64::consts::PI;
    /// let e = Segment::elliptic_arc([1.0, 2.0], 3.0, 1.0, 0.0, 0.0, PI).unwrap();
    /// let top = e.jet(0.5).p;
    /// assert!((top.x - 1.0).abs() < 1e-15 && (top.y - 3.0).abs() < 1e-15);
    /// ```
    pub fn elliptic_arc(
        center: [f64; 2],
        rx: f64,
        ry: f64,
        rotation: f64,
        start: f64,
        end: f64,
    ) -> Result<Segment> {
        for (field, r) in [("rx", rx), ("ry", ry)] {
            if !(r.is_finite() && r > 0.0) {
                return Err(Error::InvalidShape {
                    field,
                    value: r,
                    why: "finite and > 0",
                });
            }
        }
        if !rotation.is_finite() {
            return Err(Error::InvalidShape {
                field: "rotation",
                value: rotation,
                why: "finite",
            });
        }
        let unit = Segment::arc([0.0, 0.0], 1.0, start, end)?;
        let (s, c) = rotation.sin_cos();
        let map = Affine([rx * c, rx * s, -ry * s, ry * c, center[0], center[1]]);
        let moved = unit.transformed(&map)?;
        let (kind, circle) = if rx == ry {
            (SegmentKind::Arc, Some((center, rx)))
        } else {
            (SegmentKind::EllipticArc, None)
        };
        let curve = moved.curve().clone();
        Ok(Segment::from_parts(kind, curve, circle, unit.own_param()))
    }
}

/// A segment of `kind` (on `circle`, if given) with the knots, degree and weights of `like`
/// and the given control points; the knots (and weights) reversed when `backwards`.
fn rebuilt(
    kind: SegmentKind,
    like: &SplineCurve,
    points: Vec<[f64; 2]>,
    backwards: bool,
    circle: Option<([f64; 2], f64)>,
    own: OwnParam,
) -> Result<Segment> {
    let rational = like.curve();
    let (a, b) = like.domain();
    let mut knots = rational.homogeneous().knots().to_vec();
    let mut weights = rational.weights();
    if backwards {
        knots = knots
            .iter()
            .rev()
            .map(|&k| match k {
                k if k == a => b,
                k if k == b => a,
                k => a + b - k,
            })
            .collect();
        weights.reverse();
    }
    let weights = rational.is_rational().then_some(&weights[..]);
    let curve = SplineCurve::clamped(rational.degree(), &points, weights, Some(knots))?;
    Ok(Segment::from_parts(kind, curve, circle, own))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::f64::consts::TAU;

    proptest! {
        /// An elliptical arc's points satisfy the ellipse's equation in its own axes, it runs
        /// from the start angle's point to the end angle's, and reversed it runs back.
        #[test]
        fn elliptic_arcs_lie_on_their_ellipses(
            cx in -100.0f64..100.0, cy in -100.0f64..100.0,
            rx in 0.01f64..50.0, ry in 0.01f64..50.0,
            rot in -4.0f64..4.0, start in -7.0f64..7.0,
            sweep in prop_oneof![-TAU..-0.01, 0.01..TAU],
        ) {
            let e = Segment::elliptic_arc([cx, cy], rx, ry, rot, start, start + sweep).unwrap();
            let (s, c) = rot.sin_cos();
            let size = rx.max(ry) + cx.abs().max(cy.abs());
            for k in 0..=16 {
                let p = e.jet(k as f64 / 16.0).p - V2::new(cx, cy);
                let (u, v) = (p.x * c + p.y * s, -p.x * s + p.y * c);
                let f = (u / rx).powi(2) + (v / ry).powi(2) - 1.0;
                prop_assert!(f.abs() * rx.min(ry) <= 1e-12 * size, "{f}");
            }
            let at = |t: f64| {
                let (st, ct) = t.sin_cos();
                V2::new(cx + rx * ct * c - ry * st * s, cy + rx * ct * s + ry * st * c)
            };
            prop_assert!((e.start() - at(start)).norm() <= 1e-12 * size);
            prop_assert!((e.end() - at(start + sweep)).norm() <= 1e-12 * size);
            let back = e.reversed().unwrap();
            for k in 0..=8 {
                let x = k as f64 / 8.0;
                prop_assert!((back.jet(x).p - e.jet(1.0 - x).p).norm() <= 1e-12 * size);
            }
        }

        /// Moving a segment moves its points: evaluation commutes with the map.
        #[test]
        fn transforms_commute_with_evaluation(
            m in proptest::array::uniform6(-3.0f64..3.0),
            r in 0.1f64..5.0, start in -7.0f64..7.0, sweep in 0.1f64..6.0,
        ) {
            let map = Affine(m);
            prop_assume!(map.determinant().abs() > 1e-3);
            let arc = Segment::arc([1.0, -2.0], r, start, start + sweep).unwrap();
            let moved = arc.transformed(&map).unwrap();
            for k in 0..=8 {
                let x = k as f64 / 8.0;
                let want = V2::from_arr(map.apply(arc.jet(x).p.arr()));
                prop_assert!((moved.jet(x).p - want).norm() <= 1e-12 * (1.0 + r) * 20.0);
            }
        }
    }

    #[test]
    fn similarities_keep_arcs_circular() {
        let arc = Segment::arc([0.0, 0.0], 1.0, 0.0, 2.0).unwrap();
        let (s, c) = 0.7f64.sin_cos();
        let turn = Affine([2.0 * c, 2.0 * s, -2.0 * s, 2.0 * c, 5.0, 1.0]);
        assert_eq!(arc.transformed(&turn).unwrap().kind(), SegmentKind::Arc);
        let mirror = Affine([1.0, 0.0, 0.0, -1.0, 0.0, 0.0]);
        assert_eq!(arc.transformed(&mirror).unwrap().kind(), SegmentKind::Arc);
        let shear = Affine([1.0, 0.0, 0.5, 1.0, 0.0, 0.0]);
        assert_eq!(
            arc.transformed(&shear).unwrap().kind(),
            SegmentKind::EllipticArc
        );
        assert!(arc.transformed(&Affine([0.0; 6])).is_err());
    }
}
