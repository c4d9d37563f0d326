//! An oracle of distances to a profile that shares no code with the crates: dense samples
//! refined by golden-section search on the profile's own evaluation; and plain polygon
//! helpers.

use curve::{ParamCurve, Profile};

/// Samples per segment (per knot span of a spline segment) of the oracle's distance.
const PER_SEGMENT: usize = 300;

/// Dense samples of a profile with their parameters.
pub struct Oracle<'a> {
    p: &'a Profile,
    u: Vec<f64>,
    /// The samples.
    pub pts: Vec<[f64; 2]>,
    /// For each sample, twice the longer chord to a neighbour: more than the profile runs
    /// between the two, so a point of it there is no nearer than the sample less this.
    reach: Vec<f64>,
}

impl<'a> Oracle<'a> {
    /// The oracle of `p`: its dense samples, with their reach.
    pub fn new(p: &'a Profile) -> Self {
        let n = p.segments().len();
        // (A closed spline read as one segment has many spans: as densely sampled as so
        // many segments, so that two minima close together have samples between them.)
        let u: Vec<f64> = p
            .segments()
            .iter()
            .enumerate()
            .flat_map(|(i, s)| {
                let spans = s.curve().curve().homogeneous().breakpoints().len().max(2) - 1;
                let m = PER_SEGMENT * spans;
                (0..m).map(move |k| i as f64 + k as f64 / m as f64)
            })
            .chain([n as f64])
            .collect();
        let pts: Vec<[f64; 2]> = u.iter().map(|&u| p.jet(u).p.arr()).collect();
        let last = pts.len() - 1;
        let chord = |a: usize, b: usize| (pts[a][0] - pts[b][0]).hypot(pts[a][1] - pts[b][1]);
        let reach = (0..=last)
            .map(|k| {
                let (before, after) = neighbours(k, last);
                2.0 * chord(before, k).max(chord(k, after))
            })
            .collect();
        Self { p, u, pts, reach }
    }

    /// The distance from `x` to the profile and the parameter of the nearest point: the
    /// least of the local minima of the distance along it (as found by the search of
    /// `minimum_about`), nearest samples first, skipping those whose samples are too far
    /// to beat the best found.
    pub fn nearest(&self, x: [f64; 2]) -> (f64, f64) {
        let squared = self.squared_distances(x);
        let mut candidates = self.sampled_minima(&squared);
        candidates.sort_by(|&a, &b| squared[a].total_cmp(&squared[b]));
        let mut best = (f64::INFINITY, 0.0);
        for k in candidates {
            if squared[k].sqrt() - self.reach[k] >= best.0 {
                continue;
            }
            let m = self.minimum_about(x, k, squared[k]);
            if m.0 < best.0 {
                best = m;
            }
        }
        best
    }

    /// The squared distance from `x` to every sample (squared: the comparisons are the
    /// same, without a square root each).
    fn squared_distances(&self, x: [f64; 2]) -> Vec<f64> {
        self.pts
            .iter()
            .map(|q| (q[0] - x[0]).powi(2) + (q[1] - x[1]).powi(2))
            .collect()
    }

    /// The samples at local minima of the distance (the last sample is the first one
    /// again: a closed profile's seam has both sides).
    fn sampled_minima(&self, squared: &[f64]) -> Vec<usize> {
        let last = self.u.len() - 1;
        (0..=last)
            .filter(|&k| {
                let (before, after) = neighbours(k, last);
                squared[k] <= squared[before] && squared[k] <= squared[after]
            })
            .collect()
    }

    /// The least distance from `x` about the sample `k`, a local minimum of the sampled
    /// distance (`squared` there): golden-section search on the stretches to either side.
    fn minimum_about(&self, x: [f64; 2], k: usize, squared: f64) -> (f64, f64) {
        let last = self.u.len() - 1;
        let (before, after) = neighbours(k, last);
        let f = |u: f64| {
            let q = self.p.jet(u).p.arr();
            (q[0] - x[0]).powi(2) + (q[1] - x[1]).powi(2)
        };
        let mut best = (squared, self.u[k]);
        for (a, b) in [(before, before + 1), (after - 1, after)] {
            let u = golden(&f, self.u[a], self.u[b], GOLDEN_STEPS);
            let value = f(u);
            if value < best.0 {
                best = (value, u);
            }
        }
        (best.0.sqrt(), best.1)
    }

    /// Every local minimum of the distance from `x` within `within` of the least sampled
    /// distance, with near-duplicates: each sample step whose ends are that near is sampled
    /// 64 times more finely and searched about its fine local minima (two minima within one
    /// step of each other, either side of a corner, say, are both found).
    #[allow(dead_code)] // (each test crate uses what it needs)
    pub fn minima_near(&self, x: [f64; 2], within: f64) -> Vec<(f64, f64)> {
        const FINE: usize = 64;
        let d = |q: [f64; 2]| ((q[0] - x[0]).powi(2) + (q[1] - x[1]).powi(2)).sqrt();
        let f = |u: f64| d(self.p.jet(u).p.arr());
        let ds: Vec<f64> = self.pts.iter().map(|q| d(*q)).collect();
        let least = ds.iter().copied().fold(f64::INFINITY, f64::min);
        let mut out = Vec::new();
        for k in 0..self.u.len() - 1 {
            if ds[k].min(ds[k + 1]) > least + within {
                continue;
            }
            let (a, b) = (self.u[k], self.u[k + 1]);
            let at = |j: usize| a + (b - a) * j as f64 / FINE as f64;
            let fine: Vec<f64> = (0..=FINE).map(|j| f(at(j))).collect();
            for j in 0..=FINE {
                let left = j == 0 || fine[j] <= fine[j - 1];
                let right = j == FINE || fine[j] <= fine[j + 1];
                if left && right {
                    let u = golden(
                        &f,
                        at(j.saturating_sub(1)),
                        at((j + 1).min(FINE)),
                        GOLDEN_STEPS,
                    );
                    out.push((f(u), u));
                }
            }
        }
        out
    }
}

/// The samples before and after sample `k` of `0..=last`, the last sample being the first
/// one again.
fn neighbours(k: usize, last: usize) -> (usize, usize) {
    (
        if k == 0 { last - 1 } else { k - 1 },
        if k == last { 1 } else { k + 1 },
    )
}

/// The oracle's golden-section steps: the bracket shrinks by 0.618⁶⁰ ≈ 3e-13.
const GOLDEN_STEPS: usize = 60;

/// Where `f` is least on `[a, b]`, by `steps` steps of golden-section search (where it has
/// one minimum there).
pub fn golden(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, steps: usize) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..steps {
        let (c, e) = (b - g * (b - a), a + g * (b - a));
        if f(c) < f(e) {
            b = e;
        } else {
            a = c;
        }
    }
    0.5 * (a + b)
}

/// The distance from `p` to the segment `a b`.
pub fn off_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let v = [p[0] - a[0], p[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let s = if len2 > 0.0 {
        ((v[0] * d[0] + v[1] * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    // (A square root, not `hypot`: these coordinates cannot overflow when squared, and the
    // oracle's searches call this millions of times.)
    ((v[0] - s * d[0]).powi(2) + (v[1] - s * d[1]).powi(2)).sqrt()
}

/// The distance from `p` to the nearest of the `polylines` (infinite where there are none).
pub fn off_polylines<'a>(p: [f64; 2], polylines: impl IntoIterator<Item = &'a [[f64; 2]]>) -> f64 {
    polylines
        .into_iter()
        .flat_map(|line| line.windows(2).map(|w| off_segment(p, w[0], w[1])))
        .fold(f64::INFINITY, f64::min)
}

/// The winding number of a closed polygon about `x`.
pub fn winding(poly: &[[f64; 2]], x: [f64; 2]) -> i32 {
    let mut w = 0;
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        let side = (b[0] - a[0]) * (x[1] - a[1]) - (x[0] - a[0]) * (b[1] - a[1]);
        if a[1] <= x[1] && b[1] > x[1] && side > 0.0 {
            w += 1;
        } else if a[1] > x[1] && b[1] <= x[1] && side < 0.0 {
            w -= 1;
        }
    }
    w
}
