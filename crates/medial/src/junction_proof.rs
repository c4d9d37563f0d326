//! A junction of three sites whose distances have closed forms (lines, points and circles), proven by
//! Krawczyk's test: a box about the point found holds exactly one point equidistant from the
//! three.
//!
//! With `F(x) = (dA − dB, dA − dC)`, `x̃` the point found, `Y` an approximate inverse of the
//! Jacobian `J(x̃)` and `X` the box of half-width `h` about `x̃`, Krawczyk's operator
//! `K(X) = x̃ − Y F(x̃) + (I − Y J(X)) (X − x̃)` lies inside `X` when
//! `‖Y F(x̃)‖ + ‖I − Y J(X)‖ h < h` (maximum norms), and then `X` holds one zero of `F`.
//! Over `X` a line's gradient is constant and a point's (a unit vector) turns by at most
//! `√2 h / (r − √2 h)` at distance `r`: `J(X)` is `J(x̃)` within those bounds per row. Every
//! quantity is bounded with its rounding.
//!
//! The winding test of [`crate::certificate`] bounds distances by disks and the map by a
//! Lipschitz constant, which cannot part the two components of a junction whose equations
//! are nearly parallel (a reflex corner 1e-6 of the size off a far side's line): the
//! derivatives this test uses can.

use crate::coverage::FOOT_AT_REFLEX_CORNER;
use crate::sites::Sites;
use crate::true_sites::{ArcSite, LineSite, SiteShape};
use curve::{JointKind, SegmentKind, V2};
use numeric::rounding::ulps;

/// Units of rounding of the distance itself a distance in closed form carries (a generous
/// bound: the difference of the point and the site rounds by half a unit of itself, the
/// line's unit normal turns by a few, the dot product or the norm adds a few). Relative to
/// the distance, not to the coordinates: far from the origin as near it.
const DISTANCE_ULPS: f64 = 16.0;

/// Units of rounding allowed on each entry of the products of 2 × 2 matrices computed here
/// (relative to the products of the magnitudes).
const PRODUCT_ULPS: f64 = 8.0;

/// A site with a distance in closed form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum ClosedSite {
    /// A line through `start` with unit normal `inward`: the signed distance.
    Line { start: V2, inward: V2 },
    /// A point.
    Point(V2),
    /// A circle about `centre` of radius `radius`, with the axis on side `side` of it (+1
    /// outside, −1 inside): the signed distance `side · (|x − centre| − radius)`.
    Circle { centre: V2, radius: f64, side: f64 },
}

impl ClosedSite {
    /// The distance from `x`, a bound on its rounding, its gradient, and how far the
    /// gradient turns over the box of half-width `h` about `x` (`None` where the box may
    /// hold the point).
    fn at(&self, x: V2, h: f64) -> Option<(f64, f64, V2, f64)> {
        match *self {
            ClosedSite::Line { start, inward } => {
                let error = ulps(DISTANCE_ULPS) * (x - start).norm();
                Some((inward.dot(x - start), error, inward, 0.0))
            }
            ClosedSite::Point(p) => {
                let d = x - p;
                let r = d.norm();
                let error = ulps(DISTANCE_ULPS) * r;
                let reach = std::f64::consts::SQRT_2 * h;
                (r > 2.0 * reach).then(|| (r, error, d * (1.0 / r), reach / (r - reach)))
            }
            ClosedSite::Circle {
                centre,
                radius,
                side,
            } => {
                // (As a point's, the gradient turning about the centre; the radius's rounding
                // adds to the distance's.)
                let r = (x - centre).norm();
                let error = ulps(DISTANCE_ULPS) * (r + radius);
                let reach = std::f64::consts::SQRT_2 * h;
                let (distance, gradient) = SiteShape::Round {
                    centre,
                    radius,
                    side,
                }
                .distance(x);
                (r > 2.0 * reach).then_some((distance, error, gradient, reach / (r - reach)))
            }
        }
    }
}

/// Whether the box of half-width `h` about `x` holds exactly one point equidistant from the
/// three sites (by Krawczyk's test; `false` where the test cannot tell).
pub(crate) fn proven_within(sites: [ClosedSite; 3], x: V2, h: f64) -> bool {
    let Some([a, b, c]) = sites
        .iter()
        .map(|s| s.at(x, h))
        .collect::<Option<Vec<_>>>()
        .and_then(|v| <[_; 3]>::try_from(v).ok())
    else {
        return false;
    };
    // F(x̃) with its bounds, J(x̃), and how far J's rows may turn over the box (their
    // rounding too: a unit vector's components are within a few units).
    let f = [a.0 - b.0, a.0 - c.0];
    let f_error = [a.1 + b.1 + rounding_of(f[0]), a.1 + c.1 + rounding_of(f[1])];
    let j = [a.2 - b.2, a.2 - c.2];
    let gradient_rounding = ulps(8.0);
    let j_spread = [a.3 + b.3 + gradient_rounding, a.3 + c.3 + gradient_rounding];
    let det = j[0].cross(j[1]);
    if det == 0.0 || !det.is_finite() {
        return false;
    }
    // Y = J⁻¹ (rows), as computed: the test holds for any Y.
    let y = [
        V2::new(j[1].y, -j[0].y) * (1.0 / det),
        V2::new(-j[1].x, j[0].x) * (1.0 / det),
    ];
    // ‖Y F(x̃)‖ with F's bounds.
    let newton = (0..2)
        .map(|i| {
            y[i].x.abs() * (f[0].abs() + f_error[0]) + y[i].y.abs() * (f[1].abs() + f_error[1])
        })
        .fold(0.0, f64::max);
    // ‖I − Y J(X)‖ ≤ ‖I − Y J(x̃)‖ + ‖|Y| spread‖, with the products' rounding.
    let contraction = (0..2)
        .map(|i| {
            let row = [
                y[i].x * j[0].x + y[i].y * j[1].x,
                y[i].x * j[0].y + y[i].y * j[1].y,
            ];
            let magnitude = y[i].x.abs() * (j[0].x.abs() + j[0].y.abs())
                + y[i].y.abs() * (j[1].x.abs() + j[1].y.abs());
            let identity = [f64::from(u8::from(i == 0)), f64::from(u8::from(i == 1))];
            let residual = (identity[0] - row[0]).abs() + (identity[1] - row[1]).abs();
            // (A row of J turning by s moves each entry by at most s.)
            let spread = 2.0 * (y[i].x.abs() * j_spread[0] + y[i].y.abs() * j_spread[1]);
            residual + spread + ulps(PRODUCT_ULPS) * (magnitude + 1.0)
        })
        .fold(0.0, f64::max);
    let slack = 1.0 - ulps(PRODUCT_ULPS);
    newton.is_finite() && newton + contraction * h < h * slack
}

/// The site, with its distance in closed form, that boundary `b` is about its foot at
/// profile parameter `u` for every point within `reach` of `x`: the line of a straight
/// segment whose inside the points all project to, the circle of an arc whose inside they all
/// project to from its centre, or a reflex corner whose fan they all lie in. There the
/// distance to that stretch of the boundary is the site's. `None` elsewhere (a curve of
/// another kind, a foot near a segment's end, a point near a fan's edge).
pub(crate) fn closed_site_at(
    sites: &Sites<'_>,
    b: usize,
    u: f64,
    x: V2,
    reach: f64,
) -> Option<ClosedSite> {
    let profile = sites.boundaries[b];
    let segments = profile.segments();
    let n = segments.len();
    let side = sites.inside_left(b);
    let joint = u.round();
    if (u - joint).abs() <= FOOT_AT_REFLEX_CORNER * n as f64 {
        let at = joint as usize % n;
        // (A joint's parameter is the index of the segment that starts there.)
        let joints = profile.joints();
        let turn = joints
            .binary_search_by(|j| j.u.total_cmp(&(at as f64)))
            .ok()
            .map(|k| joints[k])
            .filter(|j| j.kind != JointKind::Smooth)?
            .turn;
        if turn * side >= 0.0 {
            return None; // (a convex corner: no fan)
        }
        let corner = segments[at].start();
        let (into, out) = (
            segments[(at + n - 1) % n].end_direction()?,
            segments[at].start_direction()?,
        );
        // (Past the end of the segment before, short of the start of the one after; and where
        // either is an arc, which may bend back towards the box, the corner its nearest point
        // from all of the box. Other curves: no.)
        let d = x - corner;
        let clear = |k: usize, ends_here: bool| match segments[k].kind() {
            SegmentKind::Line => true,
            SegmentKind::Arc => ArcSite::new(profile, k, side)
                .is_some_and(|a| corner_nearest(&a, ends_here, x, reach)),
            _ => false,
        };
        return (d.dot(into) > 2.0 * reach
            && d.dot(out) < -2.0 * reach
            && clear((at + n - 1) % n, true)
            && clear(at, false))
        .then_some(ClosedSite::Point(corner));
    }
    let i = (u.floor().max(0.0) as usize).min(n - 1);
    let segment = &segments[i];
    if segment.kind() == SegmentKind::Arc {
        // (Every point of the box on the axis's side of the circle and projecting onto the
        // arc from its centre, a box's width in from either end: its distance to the arc is
        // its distance to the circle.)
        let arc = ArcSite::new(profile, i, side)?;
        let r = (x - arc.centre).norm();
        let margin = (2.0 * reach / r).asin();
        let angle = arc.angle_from_start(x);
        return (r > 4.0 * reach
            && arc.side * (r - arc.radius) > 2.0 * reach
            && margin.is_finite()
            && angle > margin
            && angle < arc.sweep() - margin)
            .then_some(ClosedSite::Circle {
                centre: arc.centre,
                radius: arc.radius,
                side: arc.side,
            });
    }
    if segment.kind() != SegmentKind::Line {
        return None;
    }
    let line = LineSite::new(segment.start(), segment.end(), side);
    let (start, inward) = (line.start, line.inward);
    let t = line.along.dot(x - start);
    (t > 2.0 * reach && t < line.length - 2.0 * reach && inward.dot(x - start) > 2.0 * reach)
        .then_some(ClosedSite::Line { start, inward })
}

/// Whether the end of `arc` where it ends (`ends_here`) or starts is its nearest point from
/// every point within `reach` of `x`: all of them project from the centre beyond that end
/// (the distance to a circle's points grows with their angle from the point's own, so the
/// arc's nearest is then an end), nearer that end than the other.
fn corner_nearest(arc: &ArcSite, ends_here: bool, x: V2, reach: f64) -> bool {
    let r = (x - arc.centre).norm();
    let margin = (2.0 * reach / r).asin();
    let angle = arc.angle_from_start(x);
    let (this, other, beyond) = if ends_here {
        (arc.sweep(), 0.0, angle > arc.sweep() + margin)
    } else {
        (0.0, arc.sweep(), angle < -margin)
    };
    let apart = |a: f64| (x - arc.point_at(a)).norm();
    r > 4.0 * reach
        && margin.is_finite()
        && !arc.full()
        && beyond
        && apart(other) > apart(this) + 4.0 * reach
}

/// A few units of rounding of `v`.
fn rounding_of(v: f64) -> f64 {
    ulps(4.0) * v.abs()
}

#[cfg(test)]
mod tests {
    use super::*;
    use testkit::rng;

    /// The point equidistant from three sites, by bisection-free closed forms: the incircle
    /// of a triangle (three lines), checked against the test with a box that holds it and
    /// one beside it that does not.
    #[test]
    fn proves_the_incentre_and_refuses_a_box_beside_it() {
        let mut rnd = rng(7);
        for _ in 0..500 {
            let p: Vec<V2> = (0..3)
                .map(|_| V2::new(rnd() * 2.0 - 1.0, rnd() * 2.0 - 1.0))
                .collect();
            let area = (p[1] - p[0]).cross(p[2] - p[0]);
            if area.abs() < 1e-3 {
                continue;
            }
            let side = |i: usize| {
                let (s, e) = (p[i], p[(i + 1) % 3]);
                let along = (e - s).unit();
                ClosedSite::Line {
                    start: s,
                    inward: along.perp() * area.signum(),
                }
            };
            let lengths: Vec<f64> = (0..3)
                .map(|i| (p[(i + 1) % 3] - p[(i + 2) % 3]).norm())
                .collect();
            let total: f64 = lengths.iter().sum();
            let incentre =
                (p[0] * lengths[0] + p[1] * lengths[1] + p[2] * lengths[2]) * (1.0 / total);
            let sites = [side(0), side(1), side(2)];
            assert!(proven_within(sites, incentre, 1e-9));
            assert!(!proven_within(sites, incentre + V2::new(3e-9, 0.0), 1e-9));
        }
    }

    /// Two points and a line: the centre of the circle through the points tangent to the
    /// line, found by Newton's method on the closed forms; the box about it is proven, one
    /// moved by three half-widths is not.
    #[test]
    fn proves_a_point_point_line_junction() {
        let mut rnd = rng(8);
        let mut proven = 0;
        for _ in 0..500 {
            let (p, q) = (V2::new(rnd(), 1.0 + rnd()), V2::new(-rnd(), 1.0 + rnd()));
            let line = ClosedSite::Line {
                start: V2::new(0.0, 0.0),
                inward: V2::new(0.0, 1.0),
            };
            // On the bisector of p and q: x = m + t n; the distance to the line (y) equals
            // |x − p|: solve for t by Newton's method.
            let (m, n) = ((p + q) * 0.5, (q - p).perp().unit());
            let g = |t: f64| {
                let x = m + n * t;
                (x - p).norm() - x.y
            };
            let mut t = 0.0;
            for _ in 0..60 {
                let d = (g(t + 1e-7) - g(t - 1e-7)) / 2e-7;
                t -= g(t) / d;
            }
            let x = m + n * t;
            if g(t).abs() > 1e-13 || x.y <= 0.0 {
                continue;
            }
            let sites = [line, ClosedSite::Point(p), ClosedSite::Point(q)];
            assert!(proven_within(sites, x, 1e-9), "{x:?}");
            assert!(!proven_within(sites, x + n * 3e-9, 1e-9));
            proven += 1;
        }
        assert!(proven > 400, "{proven}");
    }

    /// Two lines at a right angle and a circle, the axis outside it or inside it: the point
    /// of their diagonal as far from the circle, in closed form, is proven; a box moved by
    /// three half-widths along the diagonal is not.
    #[test]
    fn proves_a_line_line_circle_junction() {
        let lines = [
            ClosedSite::Line {
                start: V2::new(0.0, 0.0),
                inward: V2::new(0.0, 1.0),
            },
            ClosedSite::Line {
                start: V2::new(0.0, 0.0),
                inward: V2::new(1.0, 0.0),
            },
        ];
        let root2 = std::f64::consts::SQRT_2;
        // Outside the circle about (3, 3) of radius 1: √2 (3 − t) − 1 = t. Inside the one
        // about (1, 1) of radius 5: 5 − √2 (t − 1) = t.
        for (centre, radius, side, t) in [
            (3.0, 1.0, 1.0, (3.0 * root2 - 1.0) / (1.0 + root2)),
            (1.0, 5.0, -1.0, (5.0 + root2) / (1.0 + root2)),
        ] {
            let circle = ClosedSite::Circle {
                centre: V2::new(centre, centre),
                radius,
                side,
            };
            let sites = [lines[0], lines[1], circle];
            let x = V2::new(t, t);
            assert!(proven_within(sites, x, 1e-9), "{circle:?}");
            assert!(!proven_within(sites, x + V2::new(3e-9, 3e-9), 1e-9));
        }
    }

    /// A junction of a point 1e-6 off one of two parallel lines, its disk touching both
    /// lines: the point's gradient nearly the line's.
    #[test]
    fn proves_a_junction_beside_a_point_near_a_line() {
        let sites = [
            ClosedSite::Line {
                start: V2::new(0.0, 0.0),
                inward: V2::new(0.0, 1.0),
            },
            ClosedSite::Point(V2::new(0.0, 1e-6)),
            ClosedSite::Line {
                start: V2::new(0.0, 2.0),
                inward: V2::new(0.0, -1.0),
            },
        ];
        // Equidistant: y = 1 (the lines), |x − (0, 1e-6)| = 1.
        let x = V2::new((1.0f64 - (1.0 - 1e-6) * (1.0 - 1e-6)).sqrt(), 1.0);
        assert!(proven_within(sites, x, 1e-9));
    }

    /// The distance from `x` to the segment from `a` to `b` (brute force).
    fn to_segment(x: V2, a: V2, b: V2) -> f64 {
        let d = b - a;
        let t = ((x - a).dot(d) / d.dot(d)).clamp(0.0, 1.0);
        (x - (a + d * t)).norm()
    }

    /// The distance from `x` to arc `arc` of the circle about `c` of radius `r` (brute force:
    /// the circle's nearest point where the arc's dense polyline passes through it, else the
    /// nearer end).
    fn to_arc(x: V2, arc: &curve::Segment, c: V2, r: f64) -> f64 {
        use curve::ParamCurve;
        let on_circle = c + (x - c) * (r / (x - c).norm());
        let (a, b) = arc.domain();
        let polyline: Vec<V2> = (0..=4000)
            .map(|k| arc.jet(a + (b - a) * k as f64 / 4000.0).p)
            .collect();
        let on_arc = polyline
            .windows(2)
            .any(|w| to_segment(on_circle, w[0], w[1]) < 1e-6 * r);
        let ends = (x - arc.start()).norm().min((x - arc.end()).norm());
        if on_arc {
            (x - on_circle).norm().min(ends)
        } else {
            ends
        }
    }

    /// Wherever a closed site is given for a foot, its distance is the distance to the
    /// boundary's segments about the foot (the segment, or both sides of a reflex corner)
    /// at every point sampled within the reach: on random stars with reflex corners (half
    /// of them with fillets and bulging sides), feet along the sides and at the corners,
    /// points off them at random distances and angles.
    #[test]
    fn a_closed_site_is_the_distance_to_its_stretch_of_boundary() {
        let mut rnd = rng(4101);
        let (mut lines, mut points, mut circles, mut beside_arcs) = (0, 0, 0, 0);
        for case in 0..400 {
            let n = 5 + (6.0 * rnd()) as usize;
            let radii: Vec<f64> = (0..n).map(|_| 0.6 + rnd()).collect();
            let wobble: Vec<f64> = (0..n).map(|_| 0.3 * (rnd() - 0.5)).collect();
            // (Half of them with arcs: fillets, and sides bulging either way.)
            let region = if case % 2 == 0 {
                crate::test_shapes::polygon_star(&radii, &wobble, &[])
            } else {
                let fillet: Vec<f64> = wobble.iter().map(|w| 0.3 * w.abs()).collect();
                crate::test_shapes::rounded_star(&radii, &fillet, &wobble, &[])
            };
            let Some(region) = region else {
                continue;
            };
            let sites = Sites::new(&region, false);
            let segments = region.outer().segments();
            let m = segments.len();
            let k = (m as f64 * rnd()) as usize % m;
            // (At the corner, or along the side.)
            let u = if rnd() < 0.5 {
                k as f64
            } else {
                k as f64 + rnd()
            };
            let foot = V2::from_arr(sites.foot(0, u));
            // (From a corner, about the middle of its fan if it has one: away from both
            // sides.)
            let middle = segments[(k + m - 1) % m].end_direction().unwrap()
                - segments[k].start_direction().unwrap();
            let angle = if u.fract() == 0.0 && middle.norm() > 1e-3 {
                middle.y.atan2(middle.x) + 0.2 * (rnd() - 0.5)
            } else {
                std::f64::consts::TAU * rnd()
            };
            let x = foot + V2::new(angle.cos(), angle.sin()) * (0.3 * rnd());
            let reach = 1e-3 * rnd();
            let Some(site) = closed_site_at(&sites, 0, u, x, reach) else {
                continue;
            };
            let near = |y: V2| {
                (0..m)
                    .filter(|&j| j == k || (u.fract() == 0.0 && j == (k + m - 1) % m))
                    .map(|j| match segments[j].circle() {
                        Some((c, r)) => to_arc(y, &segments[j], V2::from_arr(c), r),
                        None => to_segment(y, segments[j].start(), segments[j].end()),
                    })
                    .fold(f64::INFINITY, f64::min)
            };
            match site {
                ClosedSite::Line { .. } => lines += 1,
                ClosedSite::Point(_) => {
                    points += 1;
                    let before = &segments[(k + m - 1) % m];
                    beside_arcs +=
                        usize::from(before.circle().is_some() || segments[k].circle().is_some());
                }
                ClosedSite::Circle { .. } => circles += 1,
            }
            for _ in 0..20 {
                let y = x + V2::new(rnd() - 0.5, rnd() - 0.5) * (2.0 * reach);
                let (closed, ..) = site.at(y, 0.0).expect("away from the site");
                testkit::assert_near!(
                    closed,
                    near(y),
                    1e-12,
                    "{site:?} at {y:?}: {closed} vs {}",
                    near(y)
                );
            }
        }
        assert!(
            lines > 20 && points > 5 && circles > 10 && beside_arcs > 3,
            "{lines} lines, {points} points ({beside_arcs} beside arcs), {circles} circles"
        );
    }
}
