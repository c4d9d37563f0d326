//! Pairs of nearby contacts are never force closure, and this is proven without the zero sets.
//!
//! Every function of [`crate::cones`] vanishes where the contacts meet (`d = 0`): on the
//! diagonal, at the corner `(start, end)` of a closed curve's seam, and at a knot corner
//! where a diagonal cell touches the next. The coefficient test cannot prove a sign on a
//! patch that touches such a point, so the subdivision would grind down to its size limit
//! there. But a chord between nearby contacts runs along the curve: `d = ∫ C'` over the arc
//! between them, a positive combination of the hodograph's control points on that arc. Where
//! every such direction is beyond one cone edge (the inner product of every control point of
//! the edge normal on the patch with every hodograph direction has one sign), that function is
//! negative on the whole patch (on `d / (t − s)`, for the divided diagonal cells), and the
//! patch holds no grasp.

use crate::cones::Form;
use numeric::Rect;

/// Arcs longer than this share of the domain are not tried: their directions spread too far
/// to lie beyond one cone edge, except along straight stretches that the coefficient test
/// decides anyway.
const LONGEST_ARC: f64 = 0.25;

/// Each inner product must be this far below zero, relative to the lengths of its factors:
/// the control points carry rounding of this order.
const SIGN_MARGIN: f64 = 1e-12;

/// The proof on one closed curve, for the friction `mu`.
pub(crate) struct NearContacts<'a> {
    form: &'a Form,
    mu: f64,
    /// Whether the curve is closed (then the seam corner `(start, end)` is a meeting too).
    closed: bool,
}

impl<'a> NearContacts<'a> {
    pub(crate) fn new(form: &'a Form, mu: f64, closed: bool) -> Self {
        Self { form, mu, closed }
    }

    /// Whether no pair `s < t` of `bx` (`[s0, s1] × [t0, t1]`) is force closure, proven from
    /// the directions of the arc between the contacts.
    pub(crate) fn excluded(&self, bx: Rect) -> bool {
        let (a, b) = self.form.domain();
        let longest = LONGEST_ARC * (b - a);
        let (lo, hi) = (bx.t.lo.min(bx.r.lo), bx.t.hi.max(bx.r.hi));
        if hi - lo <= longest && self.beyond_an_edge(bx, &[(lo, hi)], 1.0) {
            return true;
        }
        // Across the seam: d = C(t) − C(s) = −(∫ from t to the end + ∫ from the start to s).
        self.closed
            && (b - bx.r.lo) + (bx.t.hi - a) <= longest
            && self.beyond_an_edge(bx, &[(bx.r.lo, b), (a, bx.t.hi)], -1.0)
    }

    /// Whether one cone function is negative on `bx` when `d` is `sign` times a positive
    /// combination of the hodograph directions on `arcs`.
    fn beyond_an_edge(&self, bx: Rect, arcs: &[(f64, f64)], sign: f64) -> bool {
        let mut chord = Vec::new();
        for &(lo, hi) in arcs {
            self.form.hodograph_points(lo, hi, &mut chord);
        }
        let (mut at_s, mut at_t) = (Vec::new(), Vec::new());
        self.form.hodograph_points(bx.t.lo, bx.t.hi, &mut at_s);
        self.form.hodograph_points(bx.r.lo, bx.r.hi, &mut at_t);
        if chord.is_empty() || at_s.is_empty() || at_t.is_empty() {
            return false;
        }
        // At s the cone holds d, at t it holds −d.
        let sides: [(&[[f64; 2]], f64); 2] = [(&at_s, sign), (&at_t, -sign)];
        let beyond = sides.into_iter().any(|(edge_pts, dir)| {
            [false, true].into_iter().any(|ahead| {
                edge_pts.iter().all(|&q| {
                    let n = self.form.edge_normal_at(q, self.mu, ahead);
                    chord.iter().all(|c| {
                        let dot = dir * (n[0] * c[0] + n[1] * c[1]);
                        dot < -SIGN_MARGIN * n[0].hypot(n[1]) * c[0].hypot(c[1])
                    })
                })
            })
        });
        beyond
    }
}
