//! The bisector of two straight segments in closed form: the foot `L1(t)` and the bisector
//! point on its normal, `X = L1(t) + s n1`, whose distance `|s|` from the first line is its
//! distance `|σ|` from the second, `X = L2(r) + σ n2` with `σ = ε s`. For each sign `ε` that is
//! two linear equations in `(s, r)`, `[ε n2 − n1 | L2′] (s, r − r0) = L1(t) − L2(r0)`: both
//! affine in `t` (the two angle bisectors; one, the midline, for parallel lines). Where the
//! foot `r` leaves the second segment, or the point leaves the reach, the branch ends.
//! This is the zero set the general bisector traces for two lines, without the subdivision.

use super::point_site::Reach;
use crate::bisector::{Bisector, Branch};
use bspline::Rational;

/// The bisector of the straight curves `c1` and `c2` (degree 1, parameters affine), as
/// branches in their own parameters; `None` for curves that are not straight segments of
/// positive length, or lines without a bisector point (one line's points, or two parallel
/// ones with no second sign).
pub(crate) fn line_bisector(c1: &Rational, c2: &Rational, reach: &Reach) -> Option<Bisector> {
    let l1 = Straight::of(c1)?;
    let l2 = Straight::of(c2)?;
    let corner = common_end(&l1, &l2);
    // (Within rounding of the domain: the window's ends are solved for.)
    let near = |v: f64, end: f64, l: &Straight| (v - end).abs() <= END_ROUNDING * (l.hi - l.lo);
    let mut branches = Vec::new();
    for sign in [1.0, -1.0] {
        // The matrix [ε n2 − n1 | L2′] and its determinant (zero only when ε n2 = n1).
        let d = [
            sign * l2.normal[0] - l1.normal[0],
            sign * l2.normal[1] - l1.normal[1],
        ];
        let v = l2.velocity;
        let det = d[0] * v[1] - d[1] * v[0];
        if det == 0.0 || !det.is_finite() {
            continue;
        }
        // (s, r) at t: the solve of M (s, r − r0) = L1(t) − L2(r0).
        let solve = |t: f64| {
            let p = l1.at(t);
            let rhs = [p[0] - l2.start[0], p[1] - l2.start[1]];
            let s = (rhs[0] * v[1] - rhs[1] * v[0]) / det;
            let r = l2.lo + (d[0] * rhs[1] - d[1] * rhs[0]) / det;
            (s, r, p)
        };
        let point = |t: f64| {
            let (s, r, p) = solve(t);
            ([p[0] + s * l1.normal[0], p[1] + s * l1.normal[1]], r)
        };
        // Where the foot r (affine in t) stays on the second segment and the point (affine
        // too) within reach: an interval of t, the ends found in closed form.
        let Some((from, to)) = l1.window(|t| point(t).1, [l2.lo, l2.hi]) else {
            continue;
        };
        let Some((from, to)) = within_reach(&|t| point(t).0, reach, from, to) else {
            continue;
        };
        // Vertices as dense as a traced zero set's (the axis tests each vertex, and
        // brackets its junctions between them): STEPS per domain of either line, whichever
        // foot moves faster (a short line's foot sweeps its domain while the long one's
        // moves a little).
        let share = ((to - from) / (l1.hi - l1.lo))
            .max((point(to).1 - point(from).1).abs() / (l2.hi - l2.lo));
        let steps = (share * STEPS as f64).ceil().max(1.0) as usize;
        let (tr, xy) = (0..=steps)
            .map(|k| {
                let t = if k == steps {
                    to
                } else {
                    from + (to - from) * k as f64 / steps as f64
                };
                let (x, r) = point(t);
                let r = r.clamp(l2.lo, l2.hi);
                // (An end at the lines' common end is that point: near a nearly flat corner
                // the solve amplifies the feet's rounding by the inverse of the turn.)
                match corner {
                    Some((tc, rc, c))
                        if (k == 0 || k == steps) && near(t, tc, &l1) && near(r, rc, &l2) =>
                    {
                        ([tc, rc], c)
                    }
                    _ => ([t, r], x),
                }
            })
            .unzip();
        branches.push(Branch::of_curves(tr, xy));
    }
    Some(Bisector {
        branches,
        singular: Vec::new(),
        isolated: Vec::new(),
        complete: true,
    })
}

/// A window's end within this share of a line's domain of the line's end is at it.
const END_ROUNDING: f64 = 1e-9;

/// The end the two lines share, if they do (a corner of a profile): each line's parameter
/// there, and the point.
fn common_end(l1: &Straight, l2: &Straight) -> Option<(f64, f64, [f64; 2])> {
    let ends = |l: &Straight| [(l.lo, l.start), (l.hi, l.end)];
    ends(l1).into_iter().find_map(|(t, p)| {
        ends(l2)
            .into_iter()
            .find(|(_, q)| p == *q)
            .map(|(r, _)| (t, r, p))
    })
}

/// Vertices of a branch per domain length of the line whose foot moves faster.
pub(super) const STEPS: usize = 64;

/// The part of `[from, to]` where the affine point `x(t)` is within reach (a disk: one
/// interval, by the quadratic `|x(t) − centre|² = far²`).
fn within_reach(
    x: &dyn Fn(f64) -> [f64; 2],
    reach: &Reach,
    from: f64,
    to: f64,
) -> Option<(f64, f64)> {
    let (p, q) = (x(from), x(to));
    let d = [q[0] - p[0], q[1] - p[1]];
    let m = [p[0] - reach.center[0], p[1] - reach.center[1]];
    // |m + λ d|² ≤ far² for λ in [0, 1].
    let a = d[0] * d[0] + d[1] * d[1];
    let b = m[0] * d[0] + m[1] * d[1];
    let c = m[0] * m[0] + m[1] * m[1] - reach.far * reach.far;
    if a == 0.0 {
        return (c <= 0.0).then_some((from, to));
    }
    let disc = b * b - a * c;
    if disc < 0.0 {
        return None;
    }
    let root = disc.sqrt();
    let (l0, l1) = (((-b - root) / a).max(0.0), ((-b + root) / a).min(1.0));
    (l0 <= l1).then_some((from + l0 * (to - from), from + l1 * (to - from)))
}

/// A straight segment `L(t) = start + (t − lo) velocity` on `[lo, hi]`, with its unit normal
/// (the direction turned a quarter left).
struct Straight {
    lo: f64,
    hi: f64,
    start: [f64; 2],
    /// The end point as given (`start + (hi − lo) velocity` only to rounding).
    end: [f64; 2],
    velocity: [f64; 2],
    normal: [f64; 2],
}

impl Straight {
    fn of(c: &Rational) -> Option<Self> {
        let pts = c.control_points();
        if c.degree() != 1 || c.is_rational() || pts.len() != 2 {
            return None;
        }
        let (lo, hi) = c.domain();
        let (a, b) = ([pts[0][0], pts[0][1]], [pts[1][0], pts[1][1]]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let len = d[0].hypot(d[1]);
        if !(len > 0.0 && hi > lo) {
            return None;
        }
        Some(Self {
            lo,
            hi,
            start: a,
            end: b,
            velocity: [d[0] / (hi - lo), d[1] / (hi - lo)],
            normal: [-d[1] / len, d[0] / len],
        })
    }

    /// The part of the domain where the affine `f` lies in `[lo, hi]`.
    fn window(&self, f: impl Fn(f64) -> f64, [lo, hi]: [f64; 2]) -> Option<(f64, f64)> {
        let (f0, f1) = (f(self.lo), f(self.hi));
        let slope = (f1 - f0) / (self.hi - self.lo);
        if slope == 0.0 || !slope.is_finite() {
            return (f0 >= lo && f0 <= hi).then_some((self.lo, self.hi));
        }
        let at = |v: f64| self.lo + (v - f0) / slope;
        let (a, b) = if slope > 0.0 {
            (at(lo), at(hi))
        } else {
            (at(hi), at(lo))
        };
        let (a, b) = (a.max(self.lo), b.min(self.hi));
        (a <= b).then_some((a, b))
    }

    fn at(&self, t: f64) -> [f64; 2] {
        let k = t - self.lo;
        [
            self.start[0] + k * self.velocity[0],
            self.start[1] + k * self.velocity[1],
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile_bisector::closed_form_checks::{agrees_with_traced, check_vertices};
    use bspline::BSpline;
    use proptest::prelude::*;

    fn line(a: [f64; 2], b: [f64; 2], lo: f64, hi: f64) -> Rational {
        let c = BSpline::new(1, vec![lo, lo, hi, hi], 2, vec![a[0], a[1], b[0], b[1]]);
        Rational::polynomial(&c.expect("line"))
    }

    proptest! {
        /// Every vertex is a bisector point (on both feet's normals, equidistant from them),
        /// and the closed form and the traced zero set of the general bisector lie within
        /// the chord tolerance of each other, on random pairs of segments (parallel ones
        /// included) with parameters on any interval.
        #[test]
        fn the_closed_form_is_the_traced_zero_set(
            ends in proptest::collection::vec((-2.0f64..2.0, -2.0f64..2.0), 4),
            parallel in any::<bool>(),
            domains in proptest::collection::vec((-3.0f64..3.0, 0.1f64..4.0), 2),
        ) {
            let p = |k: usize| [ends[k].0, ends[k].1];
            let (a, b, c) = (p(0), p(1), p(2));
            let d = if parallel {
                // Parallel to the first, half as long the other way.
                [c[0] - 0.5 * (b[0] - a[0]), c[1] - 0.5 * (b[1] - a[1])]
            } else {
                p(3)
            };
            let len = |u: [f64; 2], v: [f64; 2]| (v[0] - u[0]).hypot(v[1] - u[1]);
            prop_assume!(len(a, b) > 0.2 && len(c, d) > 0.2);
            // Not on one line, and apart from each other.
            let cross = |u: [f64; 2], v: [f64; 2], w: [f64; 2]| {
                ((v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])) / len(u, v)
            };
            prop_assume!(cross(a, b, c).abs() > 0.05 || cross(a, b, d).abs() > 0.05);
            let (l1, l2) = (
                line(a, b, domains[0].0, domains[0].0 + domains[0].1),
                line(c, d, domains[1].0, domains[1].0 + domains[1].1),
            );
            let chord = 1e-4;
            let reach = Reach { center: [0.0, 0.0], far: 20.0, chord, tol: 1e-12 };
            let closed = line_bisector(&l1, &l2, &reach).expect("two segments");
            check_vertices(&l1, &l2, &closed, |_| 1e-9)?;
            agrees_with_traced(&l1, &l2, &closed, chord, reach.far, 8.0)?;
        }
    }
}
