//! Knot vectors: validation, span search and B-spline basis functions.

use crate::error::{check_finite, Error, Result};
use smallvec::SmallVec;

/// Scratch buffers sized for the degrees that occur in practice; larger degrees spill to the heap.
pub(crate) type Scratch = SmallVec<[f64; 32]>;

/// The error of a spline of `degree` given `got` control points, fewer than the `degree + 1`
/// it needs.
pub(crate) fn too_few_points(degree: usize, got: usize) -> Error {
    Error::TooFewPoints {
        degree,
        needed: degree + 1,
        got,
    }
}

/// Validates a knot vector for a spline of `degree` with `n` control points.
///
/// Rules: `n + degree + 1` finite, non-decreasing values; interior multiplicity at most `degree`
/// (so the spline is continuous), end multiplicity at most `degree + 1`; non-empty domain.
pub fn validate_knots(degree: usize, n: usize, knots: &[f64]) -> Result<()> {
    if n < degree + 1 {
        return Err(too_few_points(degree, n));
    }
    if knots.len() != n + degree + 1 {
        return Err(Error::CountMismatch {
            what: "knots (control points + degree + 1)",
            expected: n + degree + 1,
            got: knots.len(),
        });
    }
    check_finite("knots", knots)?;
    for i in 1..knots.len() {
        if knots[i] < knots[i - 1] {
            return Err(Error::DecreasingKnots {
                index: i,
                value: knots[i],
                previous: knots[i - 1],
            });
        }
    }
    let (start, end) = (knots[degree], knots[n]);
    if start >= end {
        return Err(Error::EmptyDomain { start, end });
    }
    let mut i = 0;
    while i < knots.len() {
        let mut j = i;
        while j + 1 < knots.len() && knots[j + 1] == knots[i] {
            j += 1;
        }
        let multiplicity = j - i + 1;
        let at_end = i == 0 || j == knots.len() - 1;
        let max = if at_end { degree + 1 } else { degree };
        if multiplicity > max {
            return Err(Error::KnotMultiplicity {
                value: knots[i],
                multiplicity,
                max,
            });
        }
        i = j + 1;
    }
    Ok(())
}

/// Index `i` of the knot span `[knots[i], knots[i+1])` that contains `u`, with
/// `degree <= i < n`; `u` at or beyond the domain end gives the last non-empty span.
pub fn find_span(degree: usize, n: usize, knots: &[f64], u: f64) -> usize {
    if u >= knots[n] {
        let mut i = n - 1;
        while i > degree && knots[i] >= knots[n] {
            i -= 1;
        }
        return i;
    }
    if u <= knots[degree] {
        let mut i = degree;
        while i + 1 < n && knots[i + 1] <= knots[degree] {
            i += 1;
        }
        return i;
    }
    // Binary search for the last i with knots[i] <= u.
    let (mut lo, mut hi) = (degree, n);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if u < knots[mid] {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo
}

/// Number of times `u` occurs in `knots` (exact comparison).
pub fn multiplicity(knots: &[f64], u: f64) -> usize {
    let start = knots.partition_point(|&k| k < u);
    knots[start..].iter().take_while(|&&k| k == u).count()
}

/// The basis functions of degree `degree` on `knots` that do not vanish at `u`: the index
/// `i` of the first and the values `N_{i, p}(u), …, N_{i+p, p}(u)` (they sum to 1).
///
/// ```
/// let knots = [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
/// let (first, values) = bspline::knots::basis_at(2, &knots, 0.5);
/// assert_eq!(first, 0);
/// assert!((values.iter().sum::<f64>() - 1.0).abs() < 1e-15);
/// ```
pub fn basis_at(degree: usize, knots: &[f64], u: f64) -> (usize, Vec<f64>) {
    let n = knots.len() - degree - 1;
    let span = find_span(degree, n, knots, u);
    let mut ders = Scratch::new();
    basis_derivs(span, u, degree, 0, knots, &mut ders);
    (span - degree, ders[..=degree].to_vec())
}

/// Non-zero basis functions and their derivatives up to order `nd` at `u` in span `span`
/// (The NURBS Book, A2.3). `ders[k * (p+1) + j]` is the k-th derivative of `N_{span-p+j, p}`.
pub(crate) fn basis_derivs(
    span: usize,
    u: f64,
    p: usize,
    nd: usize,
    knots: &[f64],
    ders: &mut Scratch,
) {
    let w = p + 1;
    ders.clear();
    ders.resize((nd + 1) * w, 0.0);
    // One work buffer for the triangle `ndu`, `left`, `right` and the two rows `a`: on the
    // stack up to degree 7 (evaluation is a hot path; no allocation, no large moves).
    let need = w * w + 4 * w;
    let mut stack = [0.0f64; 96];
    let mut heap = Vec::new();
    let work: &mut [f64] = if need <= stack.len() {
        &mut stack[..need]
    } else {
        heap.resize(need, 0.0);
        &mut heap
    };
    let (ndu, rest) = work.split_at_mut(w * w);
    let (left, rest) = rest.split_at_mut(w);
    let (right, a) = rest.split_at_mut(w);
    ndu[0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            // Lower triangle holds knot differences, upper triangle the basis functions.
            ndu[j * w + r] = right[r + 1] + left[j - r];
            let temp = ndu[r * w + j - 1] / ndu[j * w + r];
            ndu[r * w + j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j * w + j] = saved;
    }
    for j in 0..=p {
        ders[j] = ndu[j * w + p];
    }
    if nd == 0 {
        return;
    }
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0] = 1.0;
        for k in 1..=nd.min(p) {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = p - k;
            if r >= k {
                a[s2 * w] = a[s1 * w] / ndu[(pk + 1) * w + (r - k)];
                d = a[s2 * w] * ndu[(r - k) * w + pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if (r as isize - 1) <= pk as isize {
                k - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2 * w + j] = (a[s1 * w + j] - a[s1 * w + j - 1]) / ndu[(pk + 1) * w + idx];
                d += a[s2 * w + j] * ndu[idx * w + pk];
            }
            if r <= pk {
                a[s2 * w + k] = -a[s1 * w + k - 1] / ndu[(pk + 1) * w + r];
                d += a[s2 * w + k] * ndu[r * w + pk];
            }
            ders[k * w + r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut factor = p as f64;
    for k in 1..=nd.min(p) {
        for j in 0..=p {
            ders[k * w + j] *= factor;
        }
        factor *= (p - k) as f64;
    }
}

/// A validated knot vector for splines of a given degree: finite, non-decreasing, interior
/// multiplicity at most `degree`, end multiplicity at most `degree + 1`, non-empty domain.
///
/// ```
/// use bspline::knots::KnotVector;
/// let k = KnotVector::new(2, vec![0., 0., 0., 1., 1., 2., 3., 3., 3.]).unwrap();
/// assert_eq!(k.domain(), (0.0, 3.0));
/// assert_eq!(k.n_ctrl(), 6);
/// assert_eq!(k.multiplicity(1.0), 2);
/// assert!(k.is_clamped());
/// assert_eq!(k.span(1.5), 4); // knots[4] = 1 ≤ 1.5 < knots[5] = 2
/// assert!(KnotVector::new(2, vec![0., 0., 0., 1., 1., 1., 0.5, 3., 3.]).is_err());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct KnotVector {
    degree: usize,
    knots: Vec<f64>,
}

impl KnotVector {
    /// Validates `knots` for splines of `degree` (with `knots.len() − degree − 1` control points).
    pub fn new(degree: usize, knots: Vec<f64>) -> Result<Self> {
        let n = knots.len().saturating_sub(degree + 1);
        validate_knots(degree, n, &knots)?;
        Ok(Self { degree, knots })
    }
    /// The clamped knot vector on `[a, b]` with uniform interior knots for `n` control points.
    pub fn clamped_uniform(degree: usize, n: usize, a: f64, b: f64) -> Result<Self> {
        if n < degree + 1 {
            return Err(too_few_points(degree, n));
        }
        Self::new(degree, clamped_uniform_knots(degree, n, a, b))
    }
    /// The unclamped uniform knot vector `−p, …, n + p` of a closed periodic spline with `n`
    /// distinct control points (domain `[0, n]`).
    pub fn periodic_uniform(degree: usize, n: usize) -> Result<Self> {
        if degree == 0 || n < degree + 1 {
            return Err(too_few_points(degree, n));
        }
        Self::new(
            degree,
            (0..n + 2 * degree + 1)
                .map(|i| i as f64 - degree as f64)
                .collect(),
        )
    }
    /// Wraps the knots of a spline (valid by construction).
    pub(crate) fn from_valid(degree: usize, knots: Vec<f64>) -> Self {
        Self { degree, knots }
    }
    /// The degree the vector was validated for.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// Number of control points it supports.
    pub fn n_ctrl(&self) -> usize {
        self.knots.len() - self.degree - 1
    }
    /// The knot values.
    pub fn as_slice(&self) -> &[f64] {
        &self.knots
    }
    /// The parameter domain `[knots[p], knots[n]]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.n_ctrl()])
    }
    /// The span index `i` with `knots[i] ≤ u < knots[i+1]` (the last span at the domain end).
    pub fn span(&self, u: f64) -> usize {
        find_span(self.degree, self.n_ctrl(), &self.knots, u)
    }
    /// How often `u` occurs.
    pub fn multiplicity(&self, u: f64) -> usize {
        multiplicity(&self.knots, u)
    }
    /// True when both ends have multiplicity `degree + 1`.
    pub fn is_clamped(&self) -> bool {
        let (k, p) = (&self.knots, self.degree);
        k[0] == k[p] && k[k.len() - 1] == k[k.len() - 1 - p]
    }
    /// Consumes the vector, returning the values.
    pub fn into_vec(self) -> Vec<f64> {
        self.knots
    }
}

/// The clamped knot vector of `n` control points and degree `p` on `[a, b]` with uniform
/// interior knots.
///
/// ```
/// // Five control points of a cubic: one interior knot, in the middle.
/// let k = bspline::clamped_uniform_knots(3, 5, 0.0, 2.0);
/// assert_eq!(k, vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0, 2.0]);
/// ```
pub fn clamped_uniform_knots(p: usize, n: usize, a: f64, b: f64) -> Vec<f64> {
    let interior = n - p - 1;
    let mut k = vec![a; p + 1];
    for i in 1..=interior {
        k.push(a + (b - a) * i as f64 / (interior + 1) as f64);
    }
    k.extend(std::iter::repeat_n(b, p + 1));
    k
}
