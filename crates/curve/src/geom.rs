//! A tiny planar vector type: the algorithms need only a handful of operations.

use std::ops::{Add, Mul, Neg, Sub};

/// A point or vector in the plane.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct V2 {
    /// x coordinate.
    pub x: f64,
    /// y coordinate.
    pub y: f64,
}

impl V2 {
    /// The vector `(x, y)`.
    pub const fn new(x: f64, y: f64) -> Self {
        Self { x, y }
    }
    /// From an array.
    pub fn from_arr(a: [f64; 2]) -> Self {
        Self::new(a[0], a[1])
    }
    /// As an array.
    pub fn arr(self) -> [f64; 2] {
        [self.x, self.y]
    }
    /// Dot product.
    pub fn dot(self, o: V2) -> f64 {
        self.x * o.x + self.y * o.y
    }
    /// The z component of the cross product.
    pub fn cross(self, o: V2) -> f64 {
        self.x * o.y - self.y * o.x
    }
    /// Euclidean length.
    pub fn norm(self) -> f64 {
        // √(x² + y²) is within an ulp or two of hypot and several times faster; hypot only
        // where the squares would overflow or underflow.
        let n2 = self.x * self.x + self.y * self.y;
        if n2.is_finite() && n2 >= f64::MIN_POSITIVE {
            n2.sqrt()
        } else {
            self.x.hypot(self.y)
        }
    }
    /// Rotated by +90°: the left normal direction.
    pub fn perp(self) -> V2 {
        V2::new(-self.y, self.x)
    }
    /// Unit vector in the same direction (the zero vector stays zero).
    pub fn unit(self) -> V2 {
        let n = self.norm();
        if n > 0.0 {
            self * (1.0 / n)
        } else {
            self
        }
    }
    /// Polar angle in `(−π, π]`.
    pub fn angle(self) -> f64 {
        self.y.atan2(self.x)
    }
    /// Unit vector at polar angle `a`.
    pub fn polar(a: f64) -> V2 {
        let (s, c) = a.sin_cos();
        V2::new(c, s)
    }
}

impl Add for V2 {
    type Output = V2;
    fn add(self, o: V2) -> V2 {
        V2::new(self.x + o.x, self.y + o.y)
    }
}
impl Sub for V2 {
    type Output = V2;
    fn sub(self, o: V2) -> V2 {
        V2::new(self.x - o.x, self.y - o.y)
    }
}
impl Neg for V2 {
    type Output = V2;
    fn neg(self) -> V2 {
        V2::new(-self.x, -self.y)
    }
}
impl Mul<f64> for V2 {
    type Output = V2;
    fn mul(self, s: f64) -> V2 {
        V2::new(self.x * s, self.y * s)
    }
}

/// The angle `a` wrapped into `(−π, π]`.
///
/// ```
/// use std::f64::consts::PI;
/// assert_eq!(curve::wrap_pi(-PI), PI);
/// assert!((curve::wrap_pi(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-15);
/// assert!((curve::wrap_pi(7.0 * PI + 0.5) - (-PI + 0.5)).abs() < 1e-14);
/// ```
pub fn wrap_pi(a: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    // Most angles are within a turn of the range: a subtraction, not a floating remainder.
    if (-PI..=PI).contains(&a) && a != -PI {
        return a;
    }
    if a > PI && a <= PI + TAU {
        return a - TAU;
    }
    if a < -PI && a > -PI - TAU {
        return a + TAU;
    }
    let mut r = a.rem_euclid(TAU);
    if r > PI {
        r -= TAU;
    }
    r
}

/// Distance from `x` to the segment `a`–`b` (to `a` where the two coincide).
///
/// ```
/// assert_eq!(curve::distance_to_segment([1.0, 2.0], [0.0, 0.0], [4.0, 0.0]), 2.0);
/// assert_eq!(curve::distance_to_segment([7.0, 4.0], [0.0, 0.0], [4.0, 0.0]), 5.0);
/// ```
pub fn distance_to_segment(x: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (ex, ey) = offset_from_segment(x, a, b);
    ex.hypot(ey)
}

/// The points to insert between `a` and `b` (pushed onto `out` in order) so that the image of
/// the segment under `map` stays within `tol` of the polyline through the images: the
/// segment's middles, halved at most `depth` times, where the image of a middle lies off the
/// chord of its ends' images. A chord whose image's middle lies off by more than a quarter of
/// its length maps across a jump (a seam) and is not followed; nor one `map` has no image of.
///
/// ```
/// // The parabola's image of [0, 1] on the x axis: halved until its middles lie within 0.02.
/// let map = |p: [f64; 2]| Some([p[0], p[0] * p[0]]);
/// let mut mids = Vec::new();
/// curve::follow_image(&map, [0.0, 0.0], [1.0, 0.0], 0.02, 8, &mut mids);
/// assert_eq!(mids, [[0.25, 0.0], [0.5, 0.0], [0.75, 0.0]]);
/// ```
pub fn follow_image(
    map: &dyn Fn([f64; 2]) -> Option<[f64; 2]>,
    a: [f64; 2],
    b: [f64; 2],
    tol: f64,
    depth: usize,
    out: &mut Vec<[f64; 2]>,
) {
    if depth == 0 {
        return;
    }
    let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    let (Some(ma), Some(mb), Some(mm)) = (map(a), map(b), map(mid)) else {
        return;
    };
    let off = distance_to_segment(mm, ma, mb);
    if off > tol && off < 0.25 * (ma[0] - mb[0]).hypot(ma[1] - mb[1]) + tol {
        follow_image(map, a, mid, tol, depth - 1, out);
        out.push(mid);
        follow_image(map, mid, b, tol, depth - 1, out);
    }
}

/// The square of [`distance_to_segment`], without its root (for the least of many).
///
/// ```
/// // Beyond the segment's end, the distance to the end: 3² + 4².
/// assert_eq!(curve::squared_distance_to_segment([7.0, 4.0], [0.0, 0.0], [4.0, 0.0]), 25.0);
/// ```
pub fn squared_distance_to_segment(x: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (ex, ey) = offset_from_segment(x, a, b);
    ex * ex + ey * ey
}

/// `x` less its nearest point on the segment `a`–`b`.
fn offset_from_segment(x: [f64; 2], a: [f64; 2], b: [f64; 2]) -> (f64, f64) {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let s = if len2 > 0.0 {
        (((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (x[0] - a[0] - s * dx, x[1] - a[1] - s * dy)
}

/// Point, first, second and third derivative of a curve at one parameter.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Jet {
    /// The point.
    pub p: V2,
    /// First derivative.
    pub d1: V2,
    /// Second derivative.
    pub d2: V2,
    /// Third derivative.
    pub d3: V2,
}

impl Jet {
    /// Unit tangent.
    pub fn tangent(&self) -> V2 {
        self.d1.unit()
    }
    /// Unit left normal (the inward normal of a counterclockwise curve).
    pub fn normal(&self) -> V2 {
        self.d1.unit().perp()
    }
    /// Signed curvature (positive where the curve turns left).
    pub fn curvature(&self) -> f64 {
        let s = self.d1.norm();
        self.d1.cross(self.d2) / (s * s * s)
    }
    /// Derivative of the signed curvature in the parameter (needs the third derivative):
    /// `κ′ = C′ × C‴ / |C′|³ − 3 (C′ × C″)(C′ · C″) / |C′|⁵`.
    pub fn curvature_rate(&self) -> f64 {
        let s2 = self.d1.dot(self.d1);
        let s3 = s2 * s2.sqrt();
        (self.d1.cross(self.d3) - 3.0 * self.d1.cross(self.d2) * self.d1.dot(self.d2) / s2) / s3
    }
}

/// The scale of points: the diagonal of their box (0 for none), what a model's own tolerances
/// (a profile's joins, a spline's closedness, a curve's sampled searches) are taken of. It
/// is not the contract's size ([`crate::box_size`]), which the options' relative tolerances are.
///
/// ```
/// assert_eq!(curve::points_scale([[0.0, 0.0], [3.0, 1.0], [1.0, 4.0]]), 5.0);
/// ```
pub fn points_scale(points: impl IntoIterator<Item = [f64; 2]>) -> f64 {
    let mut lo = V2::new(f64::INFINITY, f64::INFINITY);
    let mut hi = V2::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in points {
        lo = V2::new(lo.x.min(p[0]), lo.y.min(p[1]));
        hi = V2::new(hi.x.max(p[0]), hi.y.max(p[1]));
    }
    if lo.x > hi.x {
        return 0.0;
    }
    (hi - lo).norm()
}

#[cfg(test)]
mod tests {
    use super::*;
    use numeric::rounding::ulps;
    use std::f64::consts::{PI, TAU};

    proptest::proptest! {
        /// Wrapping by subtraction agrees with the floating remainder, into (−π, π].
        #[test]
        fn wrap_pi_matches_remainder(a in -40.0f64..40.0) {
            let want = {
                let r = a.rem_euclid(TAU);
                if r > PI { r - TAU } else { r }
            };
            let got = wrap_pi(a);
            proptest::prop_assert!(got > -PI && got <= PI, "{a} → {got}");
            testkit::prop_assert_near!(got, want, ulps(4.0) * a.abs().max(1.0));
        }
    }

    proptest::proptest! {
        /// κ′ of the jets of a random cubic `C(u) = Σ aᵢuⁱ` against central differences of κ.
        #[test]
        fn curvature_rate_matches_differences(
            c in proptest::collection::vec(-2.0f64..2.0, 8),
            u in -1.0f64..1.0,
        ) {
            let jet = |u: f64| {
                let poly = |k: usize, d: usize| -> f64 {
                    // d-th derivative of c[k] + c[k+2] u + c[k+4] u² + c[k+6] u³ at u.
                    let a = [c[k], c[k + 2], c[k + 4], c[k + 6]];
                    (d..4)
                        .map(|i| {
                            let f = (i - d + 1..=i).product::<usize>() as f64;
                            a[i] * f * u.powi((i - d) as i32)
                        })
                        .sum()
                };
                let v = |d: usize| V2::new(poly(0, d), poly(1, d));
                Jet { p: v(0), d1: v(1), d2: v(2), d3: v(3) }
            };
            let j = jet(u);
            proptest::prop_assume!(j.d1.norm() > 0.1);
            let h = 1e-5;
            let fd = (jet(u + h).curvature() - jet(u - h).curvature()) / (2.0 * h);
            let got = j.curvature_rate();
            testkit::prop_assert_near!(got, fd, 1e-5 * (1.0 + fd.abs()), "{got} vs {fd}");
        }
    }

    #[test]
    fn wrap_pi_edges() {
        assert_eq!(wrap_pi(PI), PI);
        assert_eq!(wrap_pi(-PI), PI);
        assert_eq!(wrap_pi(0.0), 0.0);
        testkit::assert_near!(wrap_pi(3.0 * PI), PI, 1e-15);
    }
}
