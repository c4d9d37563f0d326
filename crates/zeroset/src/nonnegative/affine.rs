//! The set where affine functions are all non-negative, in closed form: the domain clipped by
//! one half-plane per function, a convex polygon whose edges on the zero lines are the
//! boundary pieces.
//!
//! Functions of degree at most one in each variable on one span, whose twist vanishes to
//! rounding, are affine (the cone conditions of two straight segments are). Subdivision
//! settles their zero lines one patch at a time, and slowly where two of them are nearly
//! parallel yet apart (no patch along them is settled until the other takes one sign); the
//! clip needs no patch at all. The sign of an affine function along a segment is that of its
//! ends, so every cut is found from the values at two vertices, within the same band of zero
//! as the subdivision's.

use super::ZERO_BAND;
use crate::boundary::{BoundaryPiece, PieceEnd};
use bspline::tensor::TensorBSpline;
use curve::distance_to_segment;
use numeric::rounding::UNIT_ROUNDOFF;
use numeric::Rect;

use super::NonNegativeSet;

/// The twist `c₀₀ − c₀₁ − c₁₀ + c₁₁` of an affine function's corner values is rounding: this
/// many units of it relative to the largest value.
const TWIST_SLACK: f64 = 64.0 * UNIT_ROUNDOFF;

/// A set thinner than this many times the widest band of zero (in the domain's units) has no
/// inside: a line or a point, not a region (two zero lines coinciding with opposite sides).
const THIN_BANDS: f64 = 8.0;

/// Halvings of a piece whose image under the caller's map bends (a straight piece maps to a
/// straight one under the linear maps of lines).
const MAP_DEPTH: usize = 12;

/// An affine function `value + slope_t (t − t0) + slope_r (r − r0)` on the domain, and its band
/// of zero.
struct Affine {
    corners: [f64; 4],
    band: f64,
    slope: [f64; 2],
}

impl Affine {
    /// `f` as an affine function on `dom`, if it is one (and not zero throughout).
    fn of(f: &TensorBSpline, dom: Rect) -> Option<Self> {
        let (pt, pr) = (f.deg_t(), f.deg_r());
        if pt > 1 || pr > 1 || f.n_t() != pt + 1 || f.n_r() != pr + 1 {
            return None;
        }
        // Values at the corners (t0, r0), (t0, r1), (t1, r0), (t1, r1).
        let at = |i: usize, j: usize| f.coef(i.min(pt), j.min(pr));
        let corners = [at(0, 0), at(0, 1), at(1, 0), at(1, 1)];
        let largest = corners.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let twist = corners[0] - corners[1] - corners[2] + corners[3];
        if largest == 0.0 || twist.abs() > TWIST_SLACK * largest {
            return None;
        }
        let [wt, wr] = dom.widths();
        let slope = [
            0.5 * (corners[2] - corners[0] + corners[3] - corners[1]) / wt,
            0.5 * (corners[1] - corners[0] + corners[3] - corners[2]) / wr,
        ];
        Some(Self {
            corners,
            band: ZERO_BAND * f.max_abs_coef(),
            slope,
        })
    }

    /// The value at `p`, interpolated from the corners (exact for an affine function, to
    /// rounding).
    fn at(&self, dom: Rect, p: [f64; 2]) -> f64 {
        let [wt, wr] = dom.widths();
        let u = (p[0] - dom.t.lo) / wt;
        let v = (p[1] - dom.r.lo) / wr;
        let [c00, c01, c10, c11] = self.corners;
        (1.0 - u) * ((1.0 - v) * c00 + v * c01) + u * ((1.0 - v) * c10 + v * c11)
    }

    /// How far from its zero line the band reaches, in the domain's units.
    fn band_width(&self) -> f64 {
        let g = self.slope[0].hypot(self.slope[1]);
        if g > 0.0 {
            self.band / g
        } else {
            f64::INFINITY
        }
    }
}

/// What an edge of the clipped polygon lies on.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Edge {
    /// The domain's border.
    Border,
    /// The zero line of this function.
    Zero(usize),
}

/// The set where every function of `fs` is non-negative on `dom`, when all are affine and
/// every point where all vanish (`meets`) is a corner of the domain; `None` otherwise (the
/// subdivision's case). A set without inside is said unresolved (at its middle), unless it is
/// only a meeting point or lies along the border.
pub(super) fn affine_set(
    fs: &[TensorBSpline],
    dom: Rect,
    meets: &[[f64; 2]],
    map: &dyn Fn(f64, f64) -> Option<[f64; 2]>,
    chord_abs: f64,
) -> Option<NonNegativeSet> {
    let corners = [
        [dom.t.lo, dom.r.lo],
        [dom.t.hi, dom.r.lo],
        [dom.t.hi, dom.r.hi],
        [dom.t.lo, dom.r.hi],
    ];
    if !meets.iter().all(|m| corners.contains(m)) {
        return None;
    }
    let affine: Vec<Affine> = fs
        .iter()
        .map(|f| Affine::of(f, dom))
        .collect::<Option<_>>()?;
    // The polygon, counterclockwise: each vertex with the edge that leaves it.
    let mut polygon: Vec<([f64; 2], Edge)> = corners.iter().map(|&c| (c, Edge::Border)).collect();
    for (k, f) in affine.iter().enumerate() {
        polygon = clip(&polygon, |p| f.at(dom, p), f.band, k);
        if polygon.is_empty() {
            break;
        }
    }
    let mut out = NonNegativeSet {
        complete: true,
        ..NonNegativeSet::default()
    };
    // (An edge of no length, where a cut falls on a vertex, is dropped: the edge that leaves
    // the point is the next one's.)
    let mut kept: Vec<([f64; 2], Edge)> = Vec::with_capacity(polygon.len());
    for (p, edge) in polygon {
        match kept.last_mut() {
            Some(last) if last.0 == p => last.1 = edge,
            _ => kept.push((p, edge)),
        }
    }
    while kept.len() > 1 && kept[0].0 == kept[kept.len() - 1].0 {
        kept.pop();
    }
    let polygon = kept;
    if polygon.is_empty() {
        return Some(out);
    }
    let thin = THIN_BANDS
        * affine
            .iter()
            .map(Affine::band_width)
            .fold(0.0f64, f64::max)
            .max(UNIT_ROUNDOFF * dom.t.width().hypot(dom.r.width()));
    if thickness(&polygon) <= thin {
        // A set without inside: the meeting point alone is no boundary's, nor a stretch of
        // the border (where the contact is at the end of its segment: the joint's, not the
        // cell's); anything else is a line (or a point) of the set, said as the subdivision
        // says it.
        let near_meet = meets.iter().any(|m| {
            polygon
                .iter()
                .all(|(p, _)| (p[0] - m[0]).hypot(p[1] - m[1]) <= thin)
        });
        let on_side = |d: usize, x: f64| polygon.iter().all(|(p, _)| (p[d] - x).abs() <= thin);
        let on_border = on_side(0, dom.t.lo)
            || on_side(0, dom.t.hi)
            || on_side(1, dom.r.lo)
            || on_side(1, dom.r.hi);
        if !near_meet && !on_border {
            let k = polygon.len() as f64;
            let mid = polygon
                .iter()
                .fold([0.0; 2], |m, (p, _)| [m[0] + p[0] / k, m[1] + p[1] / k]);
            out.unresolved.push(mid);
        }
        return Some(out);
    }
    let n = polygon.len();
    for i in 0..n {
        let Edge::Zero(k) = polygon[i].1 else {
            continue;
        };
        let (a, b) = (polygon[i].0, polygon[(i + 1) % n].0);
        // (At a meeting corner every zero line passes: the piece ends on the border there,
        // as a blown-up corner's do, not at a crossing.)
        let end = |e: Edge, at: [f64; 2]| match e {
            Edge::Zero(j) if !meets.contains(&at) => PieceEnd::Crossing(j),
            _ => PieceEnd::Border,
        };
        let mut pts = vec![a];
        follow(map, a, b, chord_abs, MAP_DEPTH, &mut pts);
        pts.push(b);
        out.pieces.push(BoundaryPiece {
            function: k,
            pts,
            ends: Some([
                end(polygon[(i + n - 1) % n].1, a),
                end(polygon[(i + 1) % n].1, b),
            ]),
        });
    }
    Some(out)
}

/// The convex polygon clipped to the half-plane `value ≥ −band` (Sutherland–Hodgman): the
/// stretch of the zero line it gains is the edge `Zero(k)`.
fn clip(
    polygon: &[([f64; 2], Edge)],
    value: impl Fn([f64; 2]) -> f64,
    band: f64,
    k: usize,
) -> Vec<([f64; 2], Edge)> {
    let values: Vec<f64> = polygon.iter().map(|&(p, _)| value(p)).collect();
    let n = polygon.len();
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..n {
        let ((a, edge), b) = (polygon[i], polygon[(i + 1) % n].0);
        let (va, vb) = (values[i], values[(i + 1) % n]);
        let (a_in, b_in) = (va >= -band, vb >= -band);
        // (Where the edge crosses the zero line: from the values at its ends, the sign of an
        // affine function along a segment being theirs.)
        let cut = || {
            let l = (va / (va - vb)).clamp(0.0, 1.0);
            [a[0] + l * (b[0] - a[0]), a[1] + l * (b[1] - a[1])]
        };
        match (a_in, b_in) {
            (true, true) => out.push((a, edge)),
            (true, false) => {
                out.push((a, edge));
                out.push((cut(), Edge::Zero(k)));
            }
            (false, true) => out.push((cut(), edge)),
            (false, false) => {}
        }
    }
    out
}

/// The polygon's least width across: twice its area over its longest edge (a polygon thinner
/// than rounding has no inside).
fn thickness(polygon: &[([f64; 2], Edge)]) -> f64 {
    let n = polygon.len();
    let (mut area2, mut longest) = (0.0f64, 0.0f64);
    for i in 0..n {
        let (a, b) = (polygon[i].0, polygon[(i + 1) % n].0);
        area2 += a[0] * b[1] - a[1] * b[0];
        longest = longest.max((b[0] - a[0]).hypot(b[1] - a[1]));
    }
    if longest > 0.0 {
        area2.abs() / longest
    } else {
        0.0
    }
}

/// The inner vertices that keep the image of the segment from `a` to `b` under `map` within
/// `tol` of the image's chords (its middles, where the image's middle is off the mapped
/// chord).
fn follow(
    map: &dyn Fn(f64, f64) -> Option<[f64; 2]>,
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
    let (Some(ma), Some(mb), Some(mm)) = (map(a[0], a[1]), map(b[0], b[1]), map(mid[0], mid[1]))
    else {
        return;
    };
    if distance_to_segment(mm, ma, mb) > tol {
        follow(map, a, mid, tol, depth - 1, out);
        out.push(mid);
        follow(map, mid, b, tol, depth - 1, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nonnegative::{nonnegative_set, NonNegativeOptions};
    use bspline::BSpline;
    use proptest::prelude::*;

    /// `a + b t + c r` on `[t0, t1] × [r0, r1]`, its factors raised `raise` degrees (so the
    /// same function comes in a form the closed form does not take).
    fn affine(
        [a, b, c]: [f64; 3],
        (t0, t1): (f64, f64),
        (r0, r1): (f64, f64),
        raise: usize,
    ) -> TensorBSpline {
        let line = |lo: f64, hi: f64, x0: f64, x1: f64| {
            BSpline::bezier(1, vec![x0, x1])
                .unwrap()
                .reparam(lo, hi)
                .unwrap()
                .elevate(raise)
        };
        let one_t = line(t0, t1, 1.0, 1.0);
        let one_r = line(r0, r1, 1.0, 1.0);
        TensorBSpline::sum_of_outer(&[
            (line(t0, t1, a + b * t0, a + b * t1), one_r.clone()),
            (one_t, line(r0, r1, c * r0, c * r1)),
        ])
        .unwrap()
    }

    /// Whether every function is at least `-slack` at `p`.
    fn inside(fs: &[TensorBSpline], p: [f64; 2], slack: f64) -> bool {
        fs.iter().all(|f| f.eval(p[0], p[1]) >= -slack)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(testkit::cases(200)))]

        /// The closed form's pieces lie on their zero lines with the set on their left, and
        /// are the subdivision's pieces of the same functions given at a higher degree.
        #[test]
        fn the_clip_gives_the_subdivision_s_pieces(
            lines in prop::collection::vec((0.0..std::f64::consts::TAU, 0.0..1.0f64, 0.0..1.0f64), 2..=4),
            t0 in -2.0..2.0f64, wt in 0.1..3.0f64,
            r0 in -2.0..2.0f64, wr in 0.1..3.0f64,
        ) {
            let (dt, dr) = ((t0, t0 + wt), (r0, r0 + wr));
            // Each zero line through a point of the domain, at any angle.
            let coefs: Vec<(f64, f64, f64)> = lines
                .iter()
                .map(|&(angle, x, y)| {
                    let (q, (c, s)) = ([t0 + x * wt, r0 + y * wr], angle.sin_cos());
                    (-(s * q[0] + c * q[1]), s, c)
                })
                .collect();
            let fs: Vec<TensorBSpline> =
                coefs.iter().map(|&(a, b, c)| affine([a, b, c], dt, dr, 0)).collect();
            let raised: Vec<TensorBSpline> =
                coefs.iter().map(|&(a, b, c)| affine([a, b, c], dt, dr, 1)).collect();
            let opts = NonNegativeOptions::default();
            let closed = nonnegative_set(&fs, &opts, &|_| false).unwrap();
            let traced = nonnegative_set(&raised, &opts, &|_| false).unwrap();
            prop_assume!(traced.complete && traced.unresolved.is_empty());
            prop_assert!(closed.complete && closed.unresolved.is_empty());
            let diag = wt.hypot(wr);
            for p in &closed.pieces {
                prop_assert_eq!(p.pts.len(), 2);
                let (a, b) = (p.pts[0], p.pts[1]);
                let f = &fs[p.function];
                for q in [a, b] {
                    prop_assert!(f.eval(q[0], q[1]).abs() <= 1e-12 * f.max_abs_coef());
                }
                // Beside its middle: the set on the left, function k negative on the right.
                let len = (b[0] - a[0]).hypot(b[1] - a[1]);
                let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                let left = [-(b[1] - a[1]) / len, (b[0] - a[0]) / len];
                let h = 1e-7 * diag;
                prop_assert!(inside(&fs, [mid[0] + h * left[0], mid[1] + h * left[1]], 1e-12));
                prop_assert!(f.eval(mid[0] - h * left[0], mid[1] - h * left[1]) < 0.0);
            }
            // The same pieces as the subdivision's: functions, ends and end points.
            prop_assert_eq!(closed.pieces.len(), traced.pieces.len());
            for p in &closed.pieces {
                let near = |x: [f64; 2], y: [f64; 2]| (x[0] - y[0]).hypot(x[1] - y[1]) <= 1e-6 * diag;
                let same = traced.pieces.iter().any(|q| {
                    q.function == p.function
                        && q.ends == p.ends
                        && near(q.pts[0], p.pts[0])
                        && near(q.pts[q.pts.len() - 1], p.pts[1])
                });
                prop_assert!(same, "{:?} not among {:?}", p, traced.pieces);
            }
        }
    }

    /// Two zero lines on one line with opposite sides: the set is that line, without inside,
    /// said unresolved; with the same side, the stretch is the first function's.
    #[test]
    fn coinciding_zero_lines() {
        let (dt, dr) = ((0.0, 1.0), (0.0, 1.0));
        let up = affine([-0.5, 0.0, 1.0], dt, dr, 0);
        let down = affine([0.5, 0.0, -1.0], dt, dr, 0);
        let opts = NonNegativeOptions::default();
        let line = nonnegative_set(&[up.clone(), down], &opts, &|_| false).unwrap();
        assert!(line.pieces.is_empty());
        assert_eq!(line.unresolved.len(), 1);
        let twice = affine([-1.0, 0.0, 2.0], dt, dr, 0);
        let same = nonnegative_set(&[up, twice], &opts, &|_| false).unwrap();
        assert!(same.unresolved.is_empty());
        assert_eq!(same.pieces.len(), 1);
        assert_eq!(same.pieces[0].function, 0);
        assert_eq!(same.pieces[0].ends, Some([PieceEnd::Border; 2]));
    }

    /// Zero lines through a corner where every function vanishes (two contacts meeting): a
    /// wedge is traced from the corner; an empty one leaves nothing, not even the corner.
    #[test]
    fn wedges_at_a_meeting_corner() {
        let (dt, dr) = ((0.0, 1.0), (0.0, 1.0));
        let opts = NonNegativeOptions {
            meets: vec![[0.0, 0.0]],
            ..NonNegativeOptions::default()
        };
        // r ≥ t/2 and r ≤ 2t: a wedge from the corner.
        let wedge = [
            affine([0.0, -0.5, 1.0], dt, dr, 0),
            affine([0.0, 2.0, -1.0], dt, dr, 0),
        ];
        let s = nonnegative_set(&wedge, &opts, &|_| false).unwrap();
        assert!(s.unresolved.is_empty());
        assert_eq!(s.pieces.len(), 2);
        assert!(s.pieces.iter().all(|p| p.pts.contains(&[0.0, 0.0])));
        // r ≥ 2t and r ≤ t/2: only the corner.
        let empty = [
            affine([0.0, -2.0, 1.0], dt, dr, 0),
            affine([0.0, 0.5, -1.0], dt, dr, 0),
        ];
        let s = nonnegative_set(&empty, &opts, &|_| false).unwrap();
        assert!(s.pieces.is_empty() && s.unresolved.is_empty() && s.points.is_empty());
    }
}
