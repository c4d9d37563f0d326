//! De Casteljau's cut of Bernstein coefficients in place (one coordinate, or whole points) and
//! the rounding one more cut adds to a piece's error bounds: the one step that the stretches,
//! the rotation and the restrictions of a function are made of.

use super::Piecewise;
use crate::rounding;

impl Piecewise {
    /// Adds to the per-coordinate errors `e` of a stretch of piece `i` (whose coefficients lie
    /// within the piece's magnitudes and `e`) the rounding of one more de Casteljau cut.
    pub(super) fn cut_errors(&self, i: usize, e: &mut [f64]) {
        for (c, ec) in e.iter_mut().enumerate() {
            *ec += rounding::casteljau(self.degree, self.coordinate_magnitude(i, c) + *ec);
        }
    }
}

/// [`split_left`] on points of dimension `d` stored point-major, all coordinates at once.
pub(crate) fn split_left_points(g: &mut [f64], d: usize, r: f64) {
    if d == 1 {
        return split_left(g, r);
    }
    let p = g.len() / d - 1;
    for level in 1..=p {
        for j in (level..=p).rev() {
            let (head, tail) = g.split_at_mut(j * d);
            let prev = &head[(j - 1) * d..];
            for (x, &y) in tail[..d].iter_mut().zip(prev) {
                *x = y + r * (*x - y);
            }
        }
    }
}

/// [`split_right`] on points of dimension `d` stored point-major, all coordinates at once.
pub(crate) fn split_right_points(g: &mut [f64], d: usize, r: f64) {
    if d == 1 {
        return split_right(g, r);
    }
    let p = g.len() / d - 1;
    for level in 1..=p {
        for j in 0..=p - level {
            let (head, tail) = g.split_at_mut((j + 1) * d);
            let cur = &mut head[j * d..];
            for (x, &y) in cur.iter_mut().zip(&tail[..d]) {
                *x += r * (y - *x);
            }
        }
    }
}

/// Replaces the Bernstein coefficients on `[0, 1]` by those of the part on `[0, r]`.
pub(crate) fn split_left(g: &mut [f64], r: f64) {
    let p = g.len() - 1;
    // After level k, g[k] is the k-th left coefficient; the tail is updated in place.
    for level in 1..=p {
        for j in (level..=p).rev() {
            g[j] = g[j - 1] + r * (g[j] - g[j - 1]);
        }
    }
}

/// Replaces the Bernstein coefficients on `[0, 1]` by those of the part on `[r, 1]`.
pub(crate) fn split_right(g: &mut [f64], r: f64) {
    let p = g.len() - 1;
    for level in 1..=p {
        for j in 0..=p - level {
            g[j] += r * (g[j + 1] - g[j]);
        }
    }
}
