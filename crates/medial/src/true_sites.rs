//! The sites of a boundary of lines and circular arcs, in closed form: each line, each arc
//! (its circle) and each corner (a point), with its signed distance on the axis's side and
//! the normal rays its disks grow along. The closed-form paths solve and trace the axis on
//! them ([`crate::lines_and_arcs`]); the closed-form junction proof ([`crate::junction_proof`])
//! takes its lines from here too.
//!
//! Every bisector of two such sites is a conic, and a point of it is found in closed form from
//! the foot on either site: along that site's normal ray at the foot, the other site's
//! distance equals the ray's length where an equation linear in that length holds (the
//! squares of a circle's distances differ by a linear term).

use curve::{OwnParam, Profile, V2};
use std::f64::consts::TAU;

/// A true site: segment `segment` of boundary `boundary`, or the corner where it starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct TrueSite {
    pub(crate) boundary: usize,
    pub(crate) segment: usize,
    pub(crate) corner: bool,
}

/// One line of a boundary: its start, unit direction, length and unit normal into the axis's
/// side.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LineSite {
    pub(crate) start: V2,
    pub(crate) along: V2,
    pub(crate) length: f64,
    pub(crate) inward: V2,
}

impl LineSite {
    /// The line from `start` to `end` of a boundary whose axis's side is on its left where
    /// `inside_left` is positive.
    pub(crate) fn new(start: V2, end: V2, inside_left: f64) -> Self {
        let length = (end - start).norm();
        let along = (end - start) * (1.0 / length);
        Self {
            start,
            along,
            length,
            inward: V2::new(-along.y, along.x) * inside_left,
        }
    }
}

/// One circular arc of a boundary: its circle, the side of it the axis lies on, and where on
/// the circle it runs.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ArcSite {
    pub(crate) centre: V2,
    pub(crate) radius: f64,
    /// +1 where the axis lies outside the circle (the arc bulges into the region), −1 where
    /// inside (the centre on the axis's side).
    pub(crate) side: f64,
    /// The angle of the arc's start, the direction it turns in (+1 counter-clockwise) and the
    /// angle it sweeps (positive).
    start_angle: f64,
    turn: f64,
    sweep: f64,
    /// The unit directions from the centre to the arc's start and end.
    ends: [V2; 2],
    own: OwnParam,
    domain: (f64, f64),
}

/// Room on the angle that tells a whole circle from an arc (as the arc's own reading of a
/// full turn).
const FULL_TURN: f64 = 1e-12;

impl ArcSite {
    /// Segment `i` of `profile` as an arc, its axis on the left where `inside_left` is
    /// positive; `None` where it is no circular arc whose parameter is its angle's share.
    pub(crate) fn new(profile: &Profile, i: usize, inside_left: f64) -> Option<Self> {
        let segment = &profile.segments()[i];
        let (centre, radius) = segment.circle()?;
        let OwnParam::Arc {
            pieces,
            piece_sweep,
        } = segment.own_param()
        else {
            return None;
        };
        let centre = V2::from_arr(centre);
        let start = segment.start();
        let turn = (start - centre).cross(segment.start_direction()?).signum();
        let middle = profile.jet_on(i, i as f64 + 0.5, 1);
        let side = if middle.d1.cross(centre - middle.p) * inside_left > 0.0 {
            -1.0
        } else {
            1.0
        };
        let start_angle = (start - centre).angle();
        let sweep = (pieces as f64 * piece_sweep).abs().min(TAU);
        Some(Self {
            centre,
            radius,
            side,
            start_angle,
            turn,
            sweep,
            ends: [
                V2::polar(start_angle),
                V2::polar(start_angle + turn * sweep),
            ],
            own: segment.own_param(),
            domain: curve::ParamCurve::domain(segment),
        })
    }

    /// Whether the arc is a whole circle (its ends one joint).
    pub(crate) fn full(&self) -> bool {
        self.sweep >= TAU - FULL_TURN
    }

    /// The angle of the foot of `x` from the arc's start, in the arc's direction: in
    /// `[0, sweep]` on the arc, outside it by the nearer end's side (in `[0, 2π)` on a whole
    /// circle).
    pub(crate) fn angle_from_start(&self, x: V2) -> f64 {
        let d = ((x - self.centre).angle() - self.start_angle) * self.turn;
        let d = d.rem_euclid(TAU);
        if d > self.sweep && d - self.sweep > TAU - d {
            d - TAU
        } else {
            d
        }
    }

    /// Whether the ray from the centre in direction `d` meets the arc (the centre itself,
    /// `d` nil, is as near every point of it): the sign tests of [`ArcSite::angle_from_start`]
    /// in `[0, sweep]` without the angle.
    pub(crate) fn spans(&self, d: V2) -> bool {
        if self.full() {
            return true;
        }
        // (Cross products taken in the arc's direction of turn.)
        let [s, e] = self.ends;
        let (from_start, to_end) = (self.turn * s.cross(d), self.turn * d.cross(e));
        if self.sweep <= std::f64::consts::PI {
            from_start >= 0.0 && to_end >= 0.0
        } else {
            // (Off the arc is within the gap from its end to its start, under half a turn.)
            !(from_start < 0.0 && to_end < 0.0)
        }
    }

    /// The angle the arc sweeps (positive).
    pub(crate) fn sweep(&self) -> f64 {
        self.sweep
    }

    /// The point of the circle at `angle` from the arc's start, in its direction.
    pub(crate) fn point_at(&self, angle: f64) -> V2 {
        self.centre + V2::polar(self.direction_at(angle)) * self.radius
    }

    /// The direction (an angle from the x axis) from the centre to the point at `angle`
    /// from the arc's start: the foot parameter of [`SiteShape::ray`] there.
    pub(crate) fn direction_at(&self, angle: f64) -> f64 {
        self.start_angle + self.turn * angle
    }

    /// The share `x ∈ [0, 1]` of the arc's segment in its profile's parameter (the profile
    /// parameter is the segment's index plus it) at `angle` from its start.
    pub(crate) fn share_at(&self, angle: f64) -> f64 {
        let (a, b) = self.domain;
        let w = (angle / self.sweep).clamp(0.0, 1.0);
        ((self.own.form(w, self.domain) - a) / (b - a)).clamp(0.0, 1.0)
    }
}

/// The geometry of a true site: a line, or a circle of radius `radius` about `centre` (a
/// corner is one of radius nil) with the axis on side `side` of it (see [`ArcSite::side`]).
#[derive(Debug, Clone, Copy)]
pub(crate) enum SiteShape {
    Line(LineSite),
    Round { centre: V2, radius: f64, side: f64 },
}

impl SiteShape {
    /// A corner at `at`, as a site.
    pub(crate) fn point(at: V2) -> Self {
        SiteShape::Round {
            centre: at,
            radius: 0.0,
            side: 1.0,
        }
    }

    /// The distance from `x` (signed: positive on the axis's side), and its gradient (not a
    /// number at a round site's centre).
    pub(crate) fn distance(&self, x: V2) -> (f64, V2) {
        match *self {
            SiteShape::Line(l) => (l.inward.dot(x - l.start), l.inward),
            SiteShape::Round {
                centre,
                radius,
                side,
            } => {
                let d = x - centre;
                let n = d.norm();
                (side * (n - radius), d * (side / n))
            }
        }
    }

    /// The foot and the unit normal into the axis's side at foot parameter `t`: a line's
    /// length along it from its start, a round site's angle.
    pub(crate) fn ray(&self, t: f64) -> (V2, V2) {
        match *self {
            SiteShape::Line(l) => (l.start + l.along * t, l.inward),
            SiteShape::Round {
                centre,
                radius,
                side,
            } => {
                let u = V2::polar(t);
                (centre + u * radius, u * side)
            }
        }
    }

    /// The foot parameter of `x` (see [`SiteShape::ray`]).
    pub(crate) fn param_of(&self, x: V2) -> f64 {
        match *self {
            SiteShape::Line(l) => l.along.dot(x - l.start),
            SiteShape::Round { centre, .. } => (x - centre).angle(),
        }
    }

    /// How far along the ray from `foot` in direction `normal` (unit) this site's distance
    /// equals the length: `None` where no such length is on the ray, or its point lies
    /// beyond a circle's centre (where the distance is the other branch's).
    pub(crate) fn radius_on_ray(&self, foot: V2, normal: V2) -> Option<f64> {
        let rho = match *self {
            // inward · (foot + ρ normal − start) = ρ
            SiteShape::Line(l) => l.inward.dot(foot - l.start) / (1.0 - l.inward.dot(normal)),
            // |foot + ρ normal − centre|² = (radius + side ρ)²: the squares of ρ cancel.
            SiteShape::Round {
                centre,
                radius,
                side,
            } => {
                let d = foot - centre;
                (radius * radius - d.dot(d)) / (2.0 * (normal.dot(d) - radius * side))
            }
        };
        let beyond = match *self {
            SiteShape::Line(_) => false,
            SiteShape::Round { radius, side, .. } => radius + side * rho < 0.0,
        };
        (rho.is_finite() && rho >= 0.0 && !beyond).then_some(rho)
    }

    /// How far a point of the axis at `x` is from where its foot parameter is ill-defined (a
    /// round site's centre); a line's feet are defined everywhere.
    pub(crate) fn param_room(&self, x: V2) -> f64 {
        match *self {
            SiteShape::Line(_) => f64::INFINITY,
            SiteShape::Round { centre, .. } => (x - centre).norm(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// Along any normal ray of one site, the point [`SiteShape::radius_on_ray`] gives is as
        /// far from the other site (by its distance) as from the ray's foot, for every pair
        /// of lines, circles either side and points.
        #[test]
        fn a_ray_meets_the_bisector_at_the_radius_given(
            kinds in proptest::array::uniform2(0usize..4),
            c in proptest::array::uniform4(-3.0f64..3.0),
            r in proptest::array::uniform2(0.1f64..2.0),
            t in 0.0f64..6.3,
        ) {
            let shape = |k: usize, c: [f64; 2], r: f64| match k {
                0 => SiteShape::Line(LineSite::new(V2::from_arr(c), V2::from_arr(c) + V2::polar(r * 3.0), 1.0)),
                1 => SiteShape::point(V2::from_arr(c)),
                2 => SiteShape::Round { centre: V2::from_arr(c), radius: r, side: 1.0 },
                _ => SiteShape::Round { centre: V2::from_arr(c), radius: r, side: -1.0 },
            };
            let a = shape(kinds[0], [c[0], c[1]], r[0]);
            let b = shape(kinds[1], [c[2], c[3]], r[1]);
            let (foot, normal) = a.ray(t);
            if let Some(rho) = b.radius_on_ray(foot, normal) {
                let x = foot + normal * rho;
                let scale = 1.0 + rho + x.norm();
                testkit::prop_assert_near!(b.distance(x).0, rho, 1e-9 * scale);
                // (On a circle's near side of its centre, the foot's own distance is ρ too.)
                if a.param_room(x) > 1e-6 && !matches!(a, SiteShape::Round { side, radius, .. } if side < 0.0 && rho > radius) {
                    testkit::prop_assert_near!(a.distance(x).0, rho, 1e-9 * scale);
                    let back = a.ray(a.param_of(x)).0;
                    if !matches!(a, SiteShape::Line(_)) && a.param_room(x) > 1e-3 {
                        proptest::prop_assert!((back - foot).norm() <= 1e-8 * scale);
                    }
                }
            }
        }
    }

    /// The arc about `centre` of radius `radius` from angle `start` to `end`, closed by a
    /// line back to its start unless it is a whole circle, and its site (axis on the left).
    fn arc_profile(centre: [f64; 2], radius: f64, start: f64, end: f64) -> (Profile, ArcSite) {
        let arc = curve::Segment::arc(centre, radius, start, end).unwrap();
        let segments = if f64::abs(end - start) < TAU {
            let line = curve::Segment::line(arc.end().arr(), arc.start().arr()).unwrap();
            vec![arc, line]
        } else {
            vec![arc]
        };
        let profile = Profile::new(segments, None).unwrap();
        let site = ArcSite::new(&profile, 0, 1.0).unwrap();
        (profile, site)
    }

    proptest::proptest! {
        /// An arc spans a direction exactly where the angle from its start lies in
        /// `[0, sweep]` (away from its ends by more than rounding), for arcs of either turn,
        /// shorter and longer than half a turn.
        #[test]
        fn an_arc_spans_the_directions_its_angles_cover(
            start in -7.0f64..7.0,
            sweep in 0.05f64..6.2,
            ccw in proptest::bool::ANY,
            direction in 0.0f64..6.3,
            length in 0.01f64..3.0,
        ) {
            let end = if ccw { start + sweep } else { start - sweep };
            let a = arc_profile([1.0, -2.0], 1.5, start, end).1;
            let d = V2::polar(direction) * length;
            let angle = a.angle_from_start(a.centre + d);
            if angle > 1e-9 && angle < a.sweep() - 1e-9 {
                proptest::prop_assert!(a.spans(d), "{angle} in [0, {}]", a.sweep());
            } else if angle < -1e-9 || angle > a.sweep() + 1e-9 {
                proptest::prop_assert!(!a.spans(d), "{angle} off [0, {}]", a.sweep());
            }
        }
    }

    /// An arc spans every direction from its centre itself; a whole circle spans every
    /// direction; an arc of exactly half a turn spans the half-plane on its side.
    #[test]
    fn an_arc_spans_its_centre_and_half_planes() {
        let arc_of = |start: f64, end: f64| arc_profile([0.0, 0.0], 1.0, start, end).1;
        let whole = arc_of(0.3, 0.3 + TAU);
        let half = arc_of(0.0, std::f64::consts::PI);
        for a in [&whole, &half, &arc_of(1.0, 2.0), &arc_of(2.0, -3.0)] {
            assert!(a.spans(V2::new(0.0, 0.0)));
        }
        for k in 0..16 {
            let d = V2::polar(TAU * k as f64 / 16.0 + 0.01);
            assert!(whole.spans(d));
            assert_eq!(half.spans(d), d.y >= 0.0, "{d:?}");
        }
        // (At its very ends rounding decides, and the closed-form tests measure the ends
        // apart.)
        assert!(half.spans(V2::new(1.0, 1e-9)) && half.spans(V2::new(-1.0, 1e-9)));
        assert!(!half.spans(V2::new(1.0, -1e-9)) && !half.spans(V2::new(-1.0, -1e-9)));
    }

    /// An arc's angles and shares: its ends at 0 and its sweep, shares 0 and 1; its middle at
    /// half the sweep; a point past its end reads past the sweep, one before its start below 0.
    #[test]
    fn an_arcs_angles_and_shares_follow_it() {
        for (start, end) in [(0.3, 2.0), (2.0, 0.3), (-1.0, 4.5), (1.0, 1.0 - TAU)] {
            let (profile, a) = arc_profile([1.0, -2.0], 1.5, start, end);
            let sweep = f64::abs(end - start);
            testkit::assert_near!(a.sweep(), sweep, 1e-12);
            let at = |angle: f64| a.point_at(angle);
            assert!((at(0.0) - profile.segments()[0].start()).norm() < 1e-12);
            assert!((at(sweep) - profile.segments()[0].end()).norm() < 1e-12);
            for share in [0.1, 0.5, 0.9] {
                let x = at(share * sweep);
                testkit::assert_near!(a.angle_from_start(x), share * sweep, 1e-12);
                // The share is the profile parameter's: the profile's point there is x.
                let u = a.share_at(share * sweep);
                assert!((profile.jet_on(0, u, 0).p - x).norm() < 1e-12, "{share}");
            }
            if sweep < TAU - 0.2 {
                assert!(a.angle_from_start(at(sweep + 0.05)) > sweep);
                assert!(a.angle_from_start(at(-0.05)) < 0.0);
            }
        }
    }
}
