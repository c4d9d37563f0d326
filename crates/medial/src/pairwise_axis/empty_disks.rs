//! The disk test of a bisector point in closed form: every other site at least as far as
//! its feet, a segment's distance counted only where its foot falls on it.

use super::{Pairwise, Param, ABOUT};
use crate::true_sites::TrueSite;
use curve::V2;
use numeric::rounding::ulps;

/// The rounding of a distance compared with a disk's radius, relative to the coordinates'
/// magnitude: a few dozen ulps.
const PAIRWISE_ROUNDING: f64 = ulps(64.0);

impl Pairwise<'_, '_, '_> {
    /// The point of the bisector of `pair` whose foot on the parametrising site is at
    /// parameter `t`, and its radius, where its disk is empty: its foot on `other` falls on that
    /// site, and every other site is at least as far.
    pub(super) fn point(&self, pair: [TrueSite; 2], param: Param, t: f64) -> Option<(V2, f64)> {
        let model = self.model;
        let Param { along, other, .. } = param;
        let (foot, normal) = param.feet.ray(t);
        let radius = model.shape(other).radius_on_ray(foot, normal)?;
        // (Past an arc's centre its feet are on the far side; no disk inside is wider than
        // the region, and the rounding of a farther point's distances is no measure.)
        if radius > model.sites.diagonal
            || model
                .arc(along)
                .is_some_and(|a| a.side < 0.0 && radius > a.radius)
        {
            return None;
        }
        let x = foot + normal * radius;
        if !self.falls_on(other, x) {
            return None;
        }
        // (Each site as far as the feet, to rounding: where a foot is at a segment's end,
        // the joint there is as far. A looser slack would keep the bisector a little past
        // where a third site enters, the farther the shallower it enters, and the end's node
        // would lie off it.)
        let reach = radius - PAIRWISE_ROUNDING * (x.x.abs().max(x.y.abs()) + radius);
        let clear = |k: usize| match self.sites.get(k) {
            Some(&s) => s.corner || pair.contains(&s) || self.clears(s, x, reach),
            None => {
                let (s, at) = self.joints[k - self.sites.len()];
                pair.contains(&s) || (x - at).norm() >= reach
            }
        };
        // (Nearby feet are mostly refused by the site that refused the last: it is tried
        // first.)
        let last = self.last_refusal.get();
        if !clear(last) {
            return None;
        }
        match (0..self.sites.len() + self.joints.len()).find(|&k| k != last && !clear(k)) {
            Some(k) => {
                self.last_refusal.set(k);
                None
            }
            None => Some((x, radius)),
        }
    }

    /// Whether the foot of `x` on site `s` falls on its segment (for a reflex corner,
    /// whether `x` lies in its fan).
    pub(super) fn falls_on(&self, s: TrueSite, x: V2) -> bool {
        let model = self.model;
        if s.corner {
            return self
                .fans
                .get(&s)
                .is_some_and(|f| f.holds(x - model.start(s)));
        }
        model.falls_on(s, x)
    }

    /// Whether site `s` touches the disk about `x` of radius `radius` (to [`ABOUT`]): its
    /// line or circle is as far, and the foot there falls on it or within that of one of its
    /// ends (where the stretch ends as the foot leaves a segment, rounding may put it just
    /// off). An arc whose centre `x` is touches along all of it.
    pub(super) fn touches(&self, s: TrueSite, x: V2, radius: f64) -> bool {
        let model = self.model;
        let near = ABOUT * model.sites.size;
        let (d, gradient) = model.shape(s).distance(x);
        if (d.abs() - radius).abs() > near {
            return false;
        }
        if s.corner || self.falls_on(s, x) {
            return true;
        }
        let foot = x - gradient * d;
        let (start, end) = match (model.line(s), model.arc(s)) {
            (Some(l), _) => (l.start, l.start + l.along * l.length),
            (None, Some(a)) => (a.point_at(0.0), a.point_at(a.sweep())),
            _ => return false,
        };
        (foot - start).norm().min((foot - end).norm()) <= near
    }

    /// Whether segment `s` holds no point nearer `x` than `radius`, but maybe its ends: its
    /// line or circle is as far, or its foot falls off it (its nearest point is then an
    /// end).
    fn clears(&self, s: TrueSite, x: V2, radius: f64) -> bool {
        self.model.shape(s).distance(x).0.abs() >= radius || !self.falls_on(s, x)
    }
}
