//! Pairs of nearby contacts are never force closure, and this is proven without the zero sets.
//!
//! Every function of [`crate::cones`] vanishes where the contacts meet (`d = 0`): on the
//! diagonal, at a joint of two segments, and at the corner `(start, end)` of a closed curve's
//! seam. The coefficient test cannot prove a sign on a patch that touches such a point, so
//! the subdivision would grind down to its size limit there. But a chord between nearby
//! contacts runs along the curve: `d = ∫ C'` over the arc between them, a positive
//! combination of the hodograph's control points on that arc (of each segment it crosses).
//! Where every such direction is beyond one cone edge (the inner product of every control
//! point of the edge normal on the patch with every hodograph direction has one sign), that
//! function is negative on the whole patch (on `d / (t − s)`, for the divided diagonal cells),
//! and the patch holds no grasp.
//!
//! Pairs far apart are excluded by their normals alone: a chord can lie within α of the
//! inward normal at `s` and within α of the reversed inward normal at `t` only where those two
//! directions are within `2α` of each other. Where the normals' directions over the patch
//! (from the hodograph's control points) keep them farther apart, the patch holds no grasp,
//! whatever the chord.

use crate::model::Model;
use numeric::Rect;

/// Arcs longer than this share of their segments are not tried: their directions spread too
/// far to lie beyond one cone edge, except along straight stretches that the coefficient test
/// decides anyway.
const LONGEST_ARC: f64 = 0.5;

/// Each inner product must be this far below zero, relative to the lengths of its factors:
/// the control points carry rounding of this order.
const SIGN_MARGIN: f64 = 1e-12;

/// Two directions must be this much farther apart than `2α` (radians) for the normals' test:
/// the angles are computed from rounded control points.
const ANGLE_MARGIN: f64 = 1e-9;

/// One stretch of the arc between the contacts: a segment and a range of its form's parameter.
type Stretch = (usize, f64, f64);

/// The proof on the cells of one closed profile, for the friction `mu`.
pub(crate) struct NearContacts<'a> {
    model: &'a Model<'a>,
    mu: f64,
}

impl<'a> NearContacts<'a> {
    pub(crate) fn new(model: &'a Model<'a>, mu: f64) -> Self {
        Self { model, mu }
    }

    /// Whether no pair `s < t` of `bx` (`[s0, s1]` on segment `i` × `[t0, t1]` on segment `j`,
    /// in their forms' parameters) is force closure, proven from the directions of the arc
    /// between the contacts.
    pub(crate) fn excluded(&self, i: usize, j: usize, bx: Rect) -> bool {
        // The hodograph's control points over the box's stretches: every tangent at `s` and
        // at `t` is a positive combination of them.
        let forms = &self.model.forms;
        let (mut at_s, mut at_t) = (Vec::new(), Vec::new());
        forms[i].hodograph_points(bx.t.lo, bx.t.hi, &mut at_s);
        forms[j].hodograph_points(bx.r.lo, bx.r.hi, &mut at_t);
        self.normals_apart(&at_s, &at_t) || self.chords_beyond(i, j, bx, [&at_s, &at_t])
    }

    /// Whether the inward normal at `s` and the reversed one at `t` stay more than `2α` apart,
    /// where the tangents are positive combinations of `at_s` and of `at_t`.
    fn normals_apart(&self, at_s: &[[f64; 2]], at_t: &[[f64; 2]]) -> bool {
        // The tangents' directions as arcs (centre, half-width); the normals turn by the same
        // quarter turn at both ends, and reversing one adds a half turn: the gap between the
        // normal at s and the reversed normal at t is π minus the gap between the tangents.
        let (Some(ts), Some(tt)) = (direction_arc(at_s), direction_arc(at_t)) else {
            return false;
        };
        let between = angle_between(ts.0, tt.0);
        let gap = (std::f64::consts::PI - between) - ts.1 - tt.1;
        gap > 2.0 * self.mu.atan() + ANGLE_MARGIN
    }

    /// Whether the chords between nearby contacts are proven beyond a cone edge (`hodographs`:
    /// [`NearContacts::excluded`]'s control points at `s` and at `t`).
    fn chords_beyond(&self, i: usize, j: usize, bx: Rect, hodographs: [&[[f64; 2]]; 2]) -> bool {
        let n = self.model.n();
        let dom = |k: usize| self.model.forms[k].domain();
        let share = |k: usize, lo: f64, hi: f64| {
            let (a, b) = dom(k);
            (hi - lo) / (b - a)
        };
        let short = |arcs: &[Stretch]| {
            arcs.iter()
                .map(|&(k, lo, hi)| share(k, lo, hi))
                .sum::<f64>()
                <= LONGEST_ARC
        };
        let mut tries: Vec<(Vec<Stretch>, f64)> = Vec::new();
        if i == j {
            let (lo, hi) = (bx.t.lo.min(bx.r.lo), bx.t.hi.max(bx.r.hi));
            tries.push((vec![(i, lo, hi)], 1.0));
            if n == 1 {
                // Across the seam: d = C(t) − C(s) = −(∫ from t to the end + ∫ from the start
                // to s).
                let (a, b) = dom(i);
                tries.push((vec![(i, bx.r.lo, b), (i, a, bx.t.hi)], -1.0));
            }
        } else {
            if j == i + 1 {
                tries.push((vec![(i, bx.t.lo, dom(i).1), (j, dom(j).0, bx.r.hi)], 1.0));
            }
            if i == 0 && j == n - 1 {
                tries.push((vec![(j, bx.r.lo, dom(j).1), (i, dom(i).0, bx.t.hi)], -1.0));
            }
        }
        tries
            .iter()
            .any(|(arcs, sign)| short(arcs) && self.beyond_an_edge(i, j, hodographs, arcs, *sign))
    }

    /// Whether one cone function is negative on the box when `d` is `sign` times a positive
    /// combination of the hodograph directions on `arcs`.
    fn beyond_an_edge(
        &self,
        i: usize,
        j: usize,
        [at_s, at_t]: [&[[f64; 2]]; 2],
        arcs: &[Stretch],
        sign: f64,
    ) -> bool {
        let forms = &self.model.forms;
        let mut chord = Vec::new();
        for &(k, lo, hi) in arcs {
            forms[k].hodograph_points(lo, hi, &mut chord);
        }
        if chord.is_empty() || at_s.is_empty() || at_t.is_empty() {
            return false;
        }
        // (Each direction's length once, not once per product.)
        let chord: Vec<([f64; 2], f64)> =
            chord.into_iter().map(|c| (c, c[0].hypot(c[1]))).collect();
        // At s the cone holds d, at t it holds −d.
        let sides = [(i, at_s, sign), (j, at_t, -sign)];
        let beyond = sides.into_iter().any(|(k, edge_pts, dir)| {
            [false, true].into_iter().any(|ahead| {
                edge_pts.iter().all(|&q| {
                    let n = forms[k].edge_normal_at(q, self.mu, ahead);
                    let margin = SIGN_MARGIN * n[0].hypot(n[1]);
                    chord.iter().all(|&(c, length)| {
                        let dot = dir * (n[0] * c[0] + n[1] * c[1]);
                        dot < -margin * length
                    })
                })
            })
        });
        beyond
    }
}

/// The arc of directions of `vectors` (centre angle, half-width), when it is less than a half
/// turn wide and no vector vanishes.
fn direction_arc(vectors: &[[f64; 2]]) -> Option<(f64, f64)> {
    let first = *vectors.first()?;
    let base = first[1].atan2(first[0]);
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for v in vectors {
        if v[0] == 0.0 && v[1] == 0.0 {
            return None;
        }
        let a = (first[0] * v[1] - first[1] * v[0]).atan2(first[0] * v[0] + first[1] * v[1]);
        lo = lo.min(a);
        hi = hi.max(a);
    }
    (hi - lo < std::f64::consts::PI).then_some((base + 0.5 * (lo + hi), 0.5 * (hi - lo)))
}

/// The angle between two directions, in `[0, π]`.
fn angle_between(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}
