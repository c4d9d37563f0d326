//! A region as a set of pairs: which pairs it holds, on the whole torus of parameters.

use crate::assemble::{inside, RawRegion};

/// The pair `(s, t)` (any reals, read modulo the period, in either order) as the point of the
/// triangle `s < t` of the domain `[a, b]`.
pub(crate) fn in_triangle((a, b): (f64, f64), s: f64, t: f64) -> [f64; 2] {
    let w = b - a;
    let wrap = |u: f64| {
        let x = a + (u - a).rem_euclid(w);
        if x >= b {
            a
        } else {
            x
        }
    };
    let (s, t) = (wrap(s), wrap(t));
    if s <= t {
        [s, t]
    } else {
        [t, s]
    }
}

/// Whether the region holds the pair `(s, t)` (by its polylines: exact up to the chord
/// tolerance of their boundaries).
pub(crate) fn holds(region: &RawRegion, domain: (f64, f64), s: f64, t: f64) -> bool {
    let p = in_triangle(domain, s, t);
    region.parts.iter().any(|part| inside(part, p)) && !region.holes.iter().any(|h| inside(h, p))
}
