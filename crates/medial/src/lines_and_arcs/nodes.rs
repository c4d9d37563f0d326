//! Nodes of the closed-form paths: a node solved from its equations by Newton's method near
//! a vertex of the topology, its disk tested empty, and a junction's place proven.

use super::{Equation, LinesAndArcs, Solved};
use crate::certificate::JUNCTION_ROOM;
use crate::junction_proof::{proven_within, ClosedSite};
use crate::true_sites::{SiteShape, TrueSite};
use curve::V2;
use numeric::newton2::{newton2, Iterate, Matrix2, Newton2, Outcome, StepVerdict, Vector2};
use numeric::rounding::ulps;

/// Newton steps that place a node: from a start ~2e-9 of the size off, the equations
/// (linear for lines, a norm for points and circles) converge in two or three.
const NODE_NEWTON_STEPS: usize = 16;

/// The equations of a node not used to solve it (a fourth site of nearly cocircular ones)
/// must hold to this share of the size: within the reach in which ends are one node.
const OTHER_EQUATIONS: f64 = 1e-6;

/// The least sine of the angle between the gradients of two equations a node is solved
/// on: below, they are one equation to rounding (two lines of one line, after snapping), and
/// Newton's method would slide along their common zero.
const MIN_SINE: f64 = 1e-9;

/// The three sites of two equations of equal distance that share one, the shared first.
pub(crate) fn three_sites(p: [TrueSite; 2], q: [TrueSite; 2]) -> Option<[TrueSite; 3]> {
    let shared = p.into_iter().find(|s| q.contains(s))?;
    let other = |e: [TrueSite; 2]| if e[0] == shared { e[1] } else { e[0] };
    let (b, c) = (other(p), other(q));
    (b != c).then_some([shared, b, c])
}

impl LinesAndArcs<'_, '_> {
    /// The node where `equations` hold near `start` (within `reach` of it), its disk tested
    /// empty, and whether its place is proven (a junction of three sites); `about` are the
    /// true sites the node touches. The centre of an arc about the axis is the node where it
    /// is within reach and the equations hold there: the arc's distance has no gradient there
    /// for Newton's method, but the place is exact. `None` where Newton's method fails or
    /// leaves the reach, the equations disagree, or the disk is entered.
    pub(crate) fn solve_node(
        &self,
        start: V2,
        equations: &[Equation],
        about: &[TrueSite],
        reach: f64,
    ) -> Option<Solved> {
        let size = self.sites.size;
        let agree = |x: V2| {
            equations
                .iter()
                .all(|&e| self.equation(e, x).0.abs() <= OTHER_EQUATIONS * size)
        };
        let centre = about.iter().find_map(|&s| {
            let arc = self.arc(s).filter(|a| a.side < 0.0)?;
            ((arc.centre - start).norm() <= reach && agree(arc.centre))
                .then_some((arc.centre, arc.radius))
        });
        if let Some((xy, radius)) = centre {
            return self.disk_is_empty(xy, radius).then_some(Solved {
                xy,
                radius,
                proven: false,
            });
        }
        let (e0, e1) = self.best_pair(equations, start)?;
        // Newton's method on the two equations (their values and gradients the rows), to
        // a step at the coordinates' rounding; a singular Jacobian places no node, the
        // iteration bound leaves the last iterate to the tests below.
        let linearize = |x: &V2| {
            let ((f0, g0), (f1, g1)) = (self.equation(e0, *x), self.equation(e1, *x));
            (Vector2::new(f0, f1), Matrix2::new(g0.x, g0.y, g1.x, g1.y))
        };
        let advance = |x: &V2, step: Vector2<f64>| *x - V2::new(step[0], step[1]);
        let judge = |it: &Iterate<V2>| {
            if it.step.norm() <= ulps(4.0) * (it.to.norm() + size) {
                StepVerdict::Converged
            } else {
                StepVerdict::Continue
            }
        };
        let x = match newton2(
            start,
            Newton2::steps(NODE_NEWTON_STEPS),
            linearize,
            advance,
            judge,
        ) {
            Outcome::Converged(x) | Outcome::Exhausted(x) | Outcome::Abandoned(x) => x,
            Outcome::Singular(_) => return None,
        };
        let moved = (x - start).norm();
        if moved.is_nan() || moved > reach {
            return None;
        }
        let site = match e0 {
            Equation::Equal(a, _) => a,
            Equation::FootAtEnd { segment, .. } => segment,
        };
        let radius = self.shape(site).distance(x).0;
        if !(agree(x) && radius > 0.0 && self.disk_is_empty(x, radius)) {
            return None;
        }
        // (Proven on the best conditioned two equations of equal distance: those Newton's
        // method used may hold a foot at a segment's end, which is no junction's.)
        let equal: Vec<Equation> = equations
            .iter()
            .copied()
            .filter(|e| matches!(e, Equation::Equal(..)))
            .collect();
        let proven = match self.best_pair(&equal, x) {
            Some((Equation::Equal(a, b), Equation::Equal(c, d))) => {
                self.prove_junction(x, three_sites([a, b], [c, d]))
            }
            _ => false,
        };
        Some(Solved {
            xy: x,
            radius,
            proven,
        })
    }

    /// What holds where the disks of true sites `a` and `b` meet at a node (the equation
    /// of an edge between them): their distances equal; or, across a smooth joint or
    /// between a segment and its own end, the foot at the joint, where the edge is the
    /// normal there.
    pub(crate) fn equation_between(&self, a: TrueSite, b: TrueSite) -> Equation {
        if let Some(end) = self.smooth_joint_between(a, b) {
            // (Their distances are one function: the edge is the normal at the joint.)
            Equation::FootAtEnd {
                segment: a,
                tangent: self.tangent_at(a, end),
                end,
            }
        } else if let Some((segment, end)) = self.own_end(a, b) {
            Equation::FootAtEnd {
                segment,
                tangent: self.tangent_at(segment, end),
                end,
            }
        } else {
            Equation::Equal(a.min(b), a.max(b))
        }
    }

    /// Whether a point within [`JUNCTION_ROOM`] of `x` is equidistant from the three sites
    /// ([`proven_within`]).
    pub(crate) fn prove_junction(&self, x: V2, sites: Option<[TrueSite; 3]>) -> bool {
        let Some(sites) = sites else {
            return false;
        };
        let closed = sites.map(|s| match self.shape(s) {
            SiteShape::Line(l) => Some(ClosedSite::Line {
                start: l.start,
                inward: l.inward,
            }),
            SiteShape::Round {
                centre,
                radius,
                side,
            } => Some(if radius == 0.0 {
                ClosedSite::Point(centre)
            } else {
                ClosedSite::Circle {
                    centre,
                    radius,
                    side,
                }
            }),
        });
        let [Some(a), Some(b), Some(c)] = closed else {
            return false;
        };
        // (The box's half-width: its corners within the room of its centre.)
        JUNCTION_ROOM.iter().any(|&room| {
            proven_within(
                [a, b, c],
                x,
                room * self.sites.size / std::f64::consts::SQRT_2,
            )
        })
    }

    /// The two equations whose gradients at `x` are nearest perpendicular (the best
    /// conditioned system), if any two are independent.
    pub(crate) fn best_pair(&self, equations: &[Equation], x: V2) -> Option<(Equation, Equation)> {
        let unit = |e: Equation| {
            let g = self.equation(e, x).1;
            g * (1.0 / g.norm())
        };
        let mut best: Option<(f64, Equation, Equation)> = None;
        for (i, &a) in equations.iter().enumerate() {
            for &b in &equations[i + 1..] {
                let det = unit(a).cross(unit(b)).abs();
                if det > MIN_SINE && best.is_none_or(|(d, _, _)| det > d) {
                    best = Some((det, a, b));
                }
            }
        }
        best.map(|(_, a, b)| (a, b))
    }
}
