//! Random star-shaped control polygons: the property tests' simple closed curves.
//!
//! Vertex `i` of `n` lies at angle `2π (i + jitter·(a − ½)) / n` and radius
//! `size·(inner + (1 − inner)·r)` about `center`, for two draws `a`, `r` in `[0, 1)`. With the
//! default jitter 0.8 the angles stay in order, so the polygon is star-shaped about its centre
//! and its periodic B-splines are simple closed curves for moderate degrees; a jitter above 1
//! lets them fold over themselves.

use curve::SplineCurve;
use std::f64::consts::TAU;

/// The shape of a random star (see the module's documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Star {
    /// The share of the vertices' angular spacing their angles are jittered by (default 0.8).
    pub jitter: f64,
    /// The smallest radius, as a share of `size` (default 0.35).
    pub inner: f64,
    /// The largest radius (default 1).
    pub size: f64,
    /// The centre (default the origin).
    pub center: [f64; 2],
}

impl Default for Star {
    fn default() -> Self {
        Star {
            jitter: 0.8,
            inner: 0.35,
            size: 1.0,
            center: [0.0, 0.0],
        }
    }
}

impl Star {
    /// Vertex `i` of `n`, from its angle draw `a` and radius draw `r` in `[0, 1)`.
    pub fn vertex(&self, i: usize, n: usize, a: f64, r: f64) -> [f64; 2] {
        let angle = TAU * (i as f64 + self.jitter * (a - 0.5)) / n as f64;
        let radius = self.size * (self.inner + (1.0 - self.inner) * r);
        [
            self.center[0] + radius * angle.cos(),
            self.center[1] + radius * angle.sin(),
        ]
    }

    /// The polygon of one vertex per `(angle, radius)` draw.
    pub fn points(&self, draws: &[(f64, f64)]) -> Vec<[f64; 2]> {
        let n = draws.len();
        let vertex = |(i, &(a, r)): (usize, &(f64, f64))| self.vertex(i, n, a, r);
        draws.iter().enumerate().map(vertex).collect()
    }

    /// The polygon of `2n` numbers: vertex `i` from `seed[2i]` (angle) and `seed[2i + 1]`
    /// (radius).
    pub fn points_from_seed(&self, seed: &[f64]) -> Vec<[f64; 2]> {
        let n = seed.len() / 2;
        let vertex = |i| self.vertex(i, n, seed[2 * i], seed[2 * i + 1]);
        (0..n).map(vertex).collect()
    }

    /// A polygon of `n` vertices drawn from `draw` (per vertex its angle, then its radius).
    pub fn drawn(&self, n: usize, draw: &mut dyn FnMut() -> f64) -> Vec<[f64; 2]> {
        (0..n)
            .map(|i| {
                let a = draw();
                self.vertex(i, n, a, draw())
            })
            .collect()
    }
}

/// The default [`Star`]'s polygon of `2n` numbers in `[0, 1)` ([`Star::points_from_seed`]).
pub fn star(seed: &[f64]) -> Vec<[f64; 2]> {
    Star::default().points_from_seed(seed)
}

/// The periodic B-spline of degree `degree` on [`star`]'s polygon, rational with the first
/// `n` of `weights` when given.
///
/// # Panics
/// When the spline cannot be built (a degree of at least the number of vertices).
pub fn star_curve(degree: usize, seed: &[f64], weights: Option<&[f64]>) -> SplineCurve {
    star_curve_with(&Star::default(), degree, seed, weights)
}

/// [`star_curve`] on the polygon of `star`.
///
/// # Panics
/// When the spline cannot be built (a degree of at least the number of vertices).
pub fn star_curve_with(
    star: &Star,
    degree: usize,
    seed: &[f64],
    weights: Option<&[f64]>,
) -> SplineCurve {
    let points = star.points_from_seed(seed);
    let weights = weights.map(|w| &w[..points.len()]);
    SplineCurve::periodic(degree, &points, weights).expect("a periodic star spline")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_angles_stay_in_order_and_the_radii_in_their_band() {
        let mut draw = crate::rng(3);
        let star = Star {
            size: 2.0,
            center: [1.0, -1.0],
            ..Star::default()
        };
        let n = 40;
        let points = star.drawn(n, &mut draw);
        for (i, p) in points.iter().enumerate() {
            let (x, y) = (p[0] - 1.0, p[1] + 1.0);
            let r = x.hypot(y);
            assert!((0.7 - 1e-12..2.0).contains(&r), "{r}");
            // (Within 0.4 of a spacing of its place: the vertices keep their order.)
            let nominal = TAU * i as f64 / n as f64;
            let off = (y.atan2(x) - nominal + TAU / 2.0).rem_euclid(TAU) - TAU / 2.0;
            assert!(
                off.abs() <= 0.4 * TAU / n as f64 + 1e-12,
                "vertex {i}: {off}"
            );
        }
    }
}
