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
use curve::follow_image;
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
        follow_image(&|p| map(p[0], p[1]), a, b, chord_abs, MAP_DEPTH, &mut pts);
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
