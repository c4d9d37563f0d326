//! How the bisector of a pair is followed: by the feet on one of its sites (a line's, an
//! arc's, or a reflex corner's fan of normals), each with its normal ray.

use super::{Pairwise, Param};
use crate::true_sites::TrueSite;
use curve::V2;

/// The feet along the parametrising site of a pair, by a parameter on `[0, 1]` (beyond, round
/// a whole circle): a line's points, an arc's, or a reflex corner's fan of normals.
#[derive(Clone, Copy)]
pub(super) enum Feet {
    Line {
        start: V2,
        step: V2,
        inward: V2,
    },
    Round {
        centre: V2,
        radius: f64,
        side: f64,
        from: f64,
        turn: f64,
    },
}

impl Feet {
    /// The parameter of the foot of `x` (its inverse of [`Feet::ray`]); round a circle, the
    /// one nearest the span `[0, 1]`.
    pub(super) fn param_of(&self, x: V2) -> f64 {
        match *self {
            Feet::Line { start, step, .. } => step.dot(x - start) / step.dot(step),
            Feet::Round {
                centre, from, turn, ..
            } => {
                let angle = ((x - centre).angle() - from) * turn.signum();
                let angle = angle.rem_euclid(std::f64::consts::TAU);
                let (after, before) = (
                    angle / turn.abs(),
                    (angle - std::f64::consts::TAU) / turn.abs(),
                );
                if after - 1.0 <= -before {
                    after
                } else {
                    before
                }
            }
        }
    }

    /// The foot and the unit normal into the axis's side at parameter `t`.
    pub(super) fn ray(&self, t: f64) -> (V2, V2) {
        match *self {
            Feet::Line {
                start,
                step,
                inward,
            } => (start + step * t, inward),
            Feet::Round {
                centre,
                radius,
                side,
                from,
                turn,
            } => {
                let u = V2::polar(from + turn * t);
                (centre + u * radius, u * side)
            }
        }
    }
}

impl Pairwise<'_, '_, '_> {
    /// How the bisector of `pair` is followed; `Ok(None)` where the sites share no axis (a
    /// smooth joint's two segments, a segment and its own end).
    pub(super) fn param(&self, pair: [TrueSite; 2]) -> Option<Option<Param>> {
        let model = self.model;
        if pair[0] == pair[1]
            || model.smooth_joint_between(pair[0], pair[1]).is_some()
            || model.own_end(pair[0], pair[1]).is_some()
        {
            return Some(None);
        }
        // (A line's feet parametrise every bisector point; then an arc's; a corner's last.)
        let rank = |s: TrueSite| match (s.corner, model.line(s).is_some()) {
            (true, _) => 2,
            (false, true) => 0,
            (false, false) => 1,
        };
        let by = if rank(pair[1]) < rank(pair[0]) { 1 } else { 0 };
        let (along, other) = (pair[by], pair[1 - by]);
        let (feet, whole) = self.feet(along)?;
        Some(Some(Param {
            along,
            other,
            feet,
            whole,
        }))
    }

    /// The feet along site `s`, and whether they run round a whole circle.
    fn feet(&self, s: TrueSite) -> Option<(Feet, bool)> {
        let model = self.model;
        if s.corner {
            let fan = self.fans.get(&s)?;
            return Some((
                Feet::Round {
                    centre: model.start(s),
                    radius: 0.0,
                    side: 1.0,
                    from: fan.from.angle(),
                    turn: fan.turn,
                },
                false,
            ));
        }
        if let Some(l) = model.line(s) {
            return Some((
                Feet::Line {
                    start: l.start,
                    step: l.along * l.length,
                    inward: l.inward,
                },
                false,
            ));
        }
        let arc = model.arc(s)?;
        let from = arc.direction_at(0.0);
        Some((
            Feet::Round {
                centre: arc.centre,
                radius: arc.radius,
                side: arc.side,
                from,
                turn: arc.direction_at(arc.sweep()) - from,
            },
            arc.full(),
        ))
    }
}
