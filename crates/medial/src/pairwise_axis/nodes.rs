//! The nodes at the ends of a pair's stretches: each solved on the pair's equation and the
//! one that ends the stretch there (a foot leaving its segment, or a third site entering).

use super::{Bound, Pairwise, Param, ABOUT, REACH};
use crate::lines_and_arcs::{Equation, Solved};
use crate::true_sites::TrueSite;
use curve::V2;

impl Pairwise<'_, '_, '_> {
    /// The node at the end `bound` of a stretch of the bisector of `pair`, and the true
    /// sites about it: solved on the pair's equation and the one that ends the stretch there
    /// ([`Pairwise::ending`]); at a convex corner where the pair's segments meet, the corner.
    pub(super) fn node(
        &self,
        pair: [TrueSite; 2],
        param: Param,
        bound: Bound,
    ) -> Option<(Solved, Vec<TrueSite>)> {
        let model = self.model;
        let size = model.sites.size;
        let (x, radius) = self.point(pair, param, bound.kept)?;
        if radius <= ABOUT * size {
            let later = model.joint_between(pair[0], pair[1])?;
            let corner = Solved {
                xy: model.start(later),
                radius: 0.0,
                proven: false,
            };
            return Some((corner, pair.to_vec()));
        }
        let mut about = pair.to_vec();
        about.extend(
            self.sites
                .iter()
                .filter(|&&s| !pair.contains(&s) && self.touches(s, x, radius)),
        );
        let equations = [
            model.equation_between(pair[0], pair[1]),
            self.ending(pair, param, bound, x)?,
        ];
        let solved = model.solve_node(x, &equations, &about, REACH * size)?;
        Some((solved, about))
    }

    /// What ends a stretch of the bisector of `pair` at `bound` (`x` its point there): the
    /// foot on the parametrising site at its end, where the span runs there; else what
    /// fails just beyond: the foot on the other site passing its end, or the site that
    /// enters the disk deepest (`None` if that is a convex corner, which no disk inside
    /// reaches alone, or the bisector has no point there).
    fn ending(&self, pair: [TrueSite; 2], param: Param, bound: Bound, x: V2) -> Option<Equation> {
        let model = self.model;
        let Some(beyond) = bound.beyond else {
            return self.foot_leaves(param.along, bound.kept < 0.5, x);
        };
        let (foot, normal) = param.feet.ray(beyond);
        let radius = model.shape(param.other).radius_on_ray(foot, normal)?;
        let y = foot + normal * radius;
        if !self.falls_on(param.other, y) {
            return self.foot_leaves(param.other, false, x);
        }
        let mut deepest: Option<(f64, TrueSite)> = None;
        let mut deeper = |depth: f64, s: TrueSite| {
            if depth > 0.0 && deepest.is_none_or(|(d, _)| depth > d) {
                deepest = Some((depth, s));
            }
        };
        for &s in self.sites.iter().filter(|s| !s.corner && !pair.contains(s)) {
            if self.falls_on(s, y) {
                deeper(radius - model.shape(s).distance(y).0.abs(), s);
            }
        }
        for &(s, at) in self.joints.iter().filter(|(s, _)| !pair.contains(s)) {
            deeper(radius - (y - at).norm(), s);
        }
        let (_, s) = deepest?;
        if s.corner && !self.fans.contains_key(&s) {
            return None;
        }
        Some(model.equation_between(param.along, s))
    }

    /// The foot of `x` on site `s` at one end of it: for a segment the end nearer `x`'s foot
    /// (or its start, with `at_start`, where the feet of a span run out there); for a reflex
    /// corner the edge of its fan nearer `x`'s direction (or its first), where the foot on
    /// the segment there is the corner.
    fn foot_leaves(&self, s: TrueSite, at_start: bool, x: V2) -> Option<Equation> {
        let model = self.model;
        let at_end = |segment: TrueSite, end: V2| Equation::FootAtEnd {
            segment,
            tangent: model.tangent_at(segment, end),
            end,
        };
        if s.corner {
            let fan = self.fans.get(&s)?;
            let corner = model.start(s);
            let d = x - corner;
            let n = model.sites.boundaries[s.boundary].segments().len();
            let before = at_start || fan.from.dot(d) > fan.to.dot(d);
            let segment = TrueSite {
                segment: if before {
                    (s.segment + n - 1) % n
                } else {
                    s.segment
                },
                corner: false,
                ..s
            };
            return Some(at_end(segment, corner));
        }
        let n = model.sites.boundaries[s.boundary].segments().len();
        let start = model.start(s);
        let end = model.start(TrueSite {
            segment: (s.segment + 1) % n,
            corner: true,
            ..s
        });
        let first = at_start || (x - start).norm() < (x - end).norm();
        Some(at_end(s, if first { start } else { end }))
    }
}
