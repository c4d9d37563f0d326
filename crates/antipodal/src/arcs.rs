//! What the symbolic forms prove about an arc of a view's curve: its curvature, greatest
//! speed and bounding box, and the rate of its radius of curvature, read from the curve's
//! [`crate::bounds::BoundForms`] over the fine pieces the arc spans.

use crate::bounds::MARGIN;
use crate::view::View;
use curve::V2;
use numeric::Interval;

/// What the control points of an arc's symbolic forms prove about it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ArcBounds {
    /// The signed curvature (positive where the view's curve turns left; it may include zero
    /// where the arc reaches an inflection).
    pub(crate) kappa: Interval,
    /// The greatest speed `|C′|` (in the view's parameter).
    pub(crate) speed: f64,
    /// Bounding box of the arc.
    pub(crate) lo: V2,
    pub(crate) hi: V2,
}

impl ArcBounds {
    /// Diagonal of the bounding box.
    pub(crate) fn diameter(&self) -> f64 {
        (self.hi - self.lo).norm()
    }

    /// The least and greatest distance between a point of this arc and one of `o`.
    pub(crate) fn distance(&self, o: &ArcBounds) -> Interval {
        let gap = |a0: f64, a1: f64, b0: f64, b1: f64| (b0 - a1).max(a0 - b1).max(0.0);
        let span = |a0: f64, a1: f64, b0: f64, b1: f64| (b1 - a0).max(a1 - b0);
        let near = V2::new(
            gap(self.lo.x, self.hi.x, o.lo.x, o.hi.x),
            gap(self.lo.y, self.hi.y, o.lo.y, o.hi.y),
        );
        let far = V2::new(
            span(self.lo.x, self.hi.x, o.lo.x, o.hi.x),
            span(self.lo.y, self.hi.y, o.lo.y, o.hi.y),
        );
        Interval::new(near.norm(), far.norm())
    }
}

impl View<'_> {
    /// Certified bounds over the (unwrapped) parameter interval `[lo, hi]` of a monotone piece
    /// (curvature of one sign, turning below π); `None` for a curve without symbolic forms, or
    /// where the enclosures prove nothing (a weight or the speed not bounded away from zero).
    ///
    /// With the tangent numerator `D = wX′ − w′X` and the curvature numerator
    /// `K = w³ (x′y″ − x″y′)` (for a polynomial curve `w ≡ 1`): `C′ = D / w²` and
    /// `κ = K w³ / |D|³`, each factor enclosed over the interval. The arc lies in the triangle
    /// of its chord and end tangents.
    pub(crate) fn arc_bounds(&self, lo: f64, hi: f64) -> Option<ArcBounds> {
        self.arc_bounds_padded(lo, hi, 0.0, (f64::NEG_INFINITY, f64::INFINITY))
    }

    /// [`View::arc_bounds`] over `[lo − pad, hi + pad]` clipped to `limits` (the arc of
    /// points solved to within `pad`): its box is that of `[lo, hi]`, whose end jets are
    /// usually at hand, grown by how far the ends move at the greatest speed.
    pub(crate) fn arc_bounds_padded(
        &self,
        lo: f64,
        hi: f64,
        pad: f64,
        limits: (f64, f64),
    ) -> Option<ArcBounds> {
        let cert = self.cert.as_ref()?;
        let forms = cert.bound_forms()?;
        let (a, b) = (lo.min(hi), lo.max(hi));
        let (lo, hi) = ((a - pad).max(limits.0), (b + pad).min(limits.1));
        let mut kappa = Interval::new(f64::INFINITY, f64::NEG_INFINITY);
        let mut speed = 0.0f64;
        for (x0, x1, _) in self.domain_pieces(lo, hi) {
            speed = speed.max(forms.join_arc_kappa(x0, x1, &mut kappa)?);
        }
        // (The range may reach zero: at an inflection that ends the piece.)
        if !(kappa.lo.is_finite() && kappa.hi.is_finite()) {
            return None;
        }
        let speed = speed * (1.0 + MARGIN);
        let (lo_box, hi_box) = self.arc_box(a, b)?;
        let grow = (a - lo).max(hi - b).max(0.0) * speed * (1.0 + MARGIN);
        let grow = V2::new(grow, grow);
        Some(ArcBounds {
            kappa,
            speed,
            lo: lo_box - grow,
            hi: hi_box + grow,
        })
    }

    /// The range of `dρ/dψ` (see `BoundForms::rho_rates`) over the unwrapped parameter
    /// interval `[lo, hi]` of a monotone piece (`convex`: of positive curvature), from the
    /// cells it touches; `None` for a curve without symbolic forms, or where nothing is
    /// proven.
    pub(crate) fn arc_rho_rate(
        &self,
        lo: f64,
        hi: f64,
        convex: bool,
        fine: bool,
    ) -> Option<Interval> {
        let forms = self.cert.as_ref()?.bound_forms()?;
        let (lo, hi) = (lo.min(hi), lo.max(hi));
        let mut acc = Interval::new(f64::INFINITY, f64::NEG_INFINITY);
        // The fine piece before the current one along the arc (the break between them is
        // inside it).
        let mut before: Option<usize> = None;
        for (x0, x1, _) in self.domain_pieces(lo, hi) {
            acc = forms.join_rho_rate(x0, x1, &mut before, acc, convex, fine)?;
        }
        (acc.lo <= acc.hi).then_some(acc)
    }

    /// Bounding box of a monotone arc `[a, b]` (curvature of one sign, turning below π): the
    /// triangle of its chord and the meet of its end tangents, or, where the end tangents are
    /// too close to parallel for that meet, the chord widened by the turn. `None` when the end
    /// tangents are opposite.
    pub(crate) fn arc_box(&self, a: f64, b: f64) -> Option<(V2, V2)> {
        let (ja, jb) = (self.jet_to(a, 1), self.jet_to(b, 1));
        let (ta, tb) = (ja.d1.unit(), jb.d1.unit());
        let (sin, cos) = (ta.cross(tb), ta.dot(tb));
        let chord = jb.p - ja.p;
        let pts = if cos > 0.0 && sin.abs() <= NEARLY_STRAIGHT {
            // Nearly straight: the arc strays from its chord by at most |chord| · turn.
            let pad = chord.norm() * (sin.abs() + CHORD_ROUNDING);
            let pad = V2::new(pad, pad);
            [ja.p - pad, ja.p + pad, jb.p - pad, jb.p + pad]
        } else if sin.abs() > NEARLY_STRAIGHT {
            let apex = ja.p + ta * (chord.cross(tb) / sin);
            [ja.p, jb.p, apex, apex]
        } else {
            return None;
        };
        let lo = V2::new(
            pts.iter().map(|p| p.x).fold(f64::MAX, f64::min),
            pts.iter().map(|p| p.y).fold(f64::MAX, f64::min),
        );
        let hi = V2::new(
            pts.iter().map(|p| p.x).fold(f64::MIN, f64::max),
            pts.iter().map(|p| p.y).fold(f64::MIN, f64::max),
        );
        Some((lo, hi))
    }
}

/// The sine of the turn between an arc's end tangents below which the meet of the tangents
/// is too ill-conditioned (a division by the sine) to bound the arc: it is bounded by its
/// chord widened by the turn instead.
const NEARLY_STRAIGHT: f64 = 1e-6;

/// Relative room for the rounding of the chord's end points in that widening.
const CHORD_ROUNDING: f64 = 1e-12;

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use crate::prepare::tests::{as_given, star_curve as curve};
    use crate::view::View;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

        /// The curvature of random closed B-splines and NURBS, sampled densely over any
        /// interval, lies within the certified range; over a monotone stretch, so do its points
        /// within the box.
        #[test]
        fn arc_bounds_hold_sampled_curvature_and_points(
            deg in 3usize..=5,
            seed in proptest::collection::vec(0.0f64..1.0, 16..=40),
            w in proptest::collection::vec(0.5f64..2.0, 20),
            rational in any::<bool>(),
            a in 0.0f64..1.0,
            len in prop_oneof![1e-5f64..1e-3, 1e-3f64..0.05, 0.05f64..0.5],
        ) {
            let c = curve(deg, &seed, rational.then_some(&w[..]));
            let prep = as_given(&c);
            let v = View::new(prep.source(true), false, 1e-12).value;
            let lo = v.a + a * v.period;
            let hi = lo + len * v.period;
            let Some(b) = v.arc_bounds(lo, hi) else {
                return Ok(());
            };
            let mut turn = 0.0f64;
            let mut last = v.jet(lo).d1;
            let mut sign = 0.0f64;
            let mut monotone = true;
            for i in 0..=300 {
                let u = lo + (hi - lo) * i as f64 / 300.0;
                let j = v.jet(u);
                let k = j.curvature();
                prop_assert!(b.kappa.holds(k, 1e-9), "κ = {k} outside {:?} at {u}", b.kappa);
                let sp = j.d1.norm();
                prop_assert!(sp <= b.speed * (1.0 + 1e-9), "speed {sp} above {} at {u}", b.speed);
                monotone &= sign * k >= 0.0;
                if sign == 0.0 {
                    sign = k.signum();
                }
                turn += last.cross(j.d1).atan2(last.dot(j.d1)).abs();
                last = j.d1;
            }
            if monotone && turn < 3.0 {
                let pad = 1e-9 * (b.hi - b.lo).norm().max(1e-12);
                for i in 0..=300 {
                    let p = v.point(lo + (hi - lo) * i as f64 / 300.0);
                    prop_assert!(
                        p.x >= b.lo.x - pad && p.x <= b.hi.x + pad
                            && p.y >= b.lo.y - pad && p.y <= b.hi.y + pad,
                        "{p:?} outside {:?}–{:?}", b.lo, b.hi
                    );
                }
            }
        }
    }
}
