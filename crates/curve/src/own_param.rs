//! Parameters as documents give them. A segment's exact form is a rational B-spline whose
//! parameter is not always the one its curve file or drawing speaks of: an arc's is that of its
//! rational quadratic pieces, not its angle; an analytic shape's is the rational circle's, not
//! its angle φ. [`OwnParam`] converts both ways, in closed form, so that every parameter a
//! command reports is in its input's own terms (the contract's "Parameters, sizes and
//! drawings") while the algorithms work on the exact forms.

use crate::circle::{circle_param, Angle};
use std::f64::consts::TAU;

/// How a segment's exact form's parameter `v` maps to its own parameter (the one its document
/// gives it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OwnParam {
    /// They are the same (lines, Bézier and B-spline curves).
    Same,
    /// A circular or elliptic arc made of `pieces` rational quadratic pieces of equal angle on
    /// `[0, 1]`, each sweeping `piece_sweep` radians (signed): its own parameter runs
    /// proportionally to the angle on `[0, 1]`.
    Arc {
        /// The number of pieces (knots at `i / pieces`).
        pieces: usize,
        /// The angle each piece sweeps.
        piece_sweep: f64,
    },
    /// An analytic shape on the rational circle (form parameter `[0, 4]`): its own parameter
    /// is the shape's angle φ on `[0, 2π]`.
    Angle(Angle),
}

impl OwnParam {
    /// The own parameter of the form's parameter `v` (on the form's domain `(a, b)`).
    pub fn own(self, v: f64, (a, b): (f64, f64)) -> f64 {
        match self {
            OwnParam::Same => v,
            OwnParam::Arc {
                pieces,
                piece_sweep,
            } => {
                let x = ((v - a) / (b - a)).clamp(0.0, 1.0);
                let k = pieces as f64;
                let j = (x * k).floor().min(k - 1.0);
                (j + arc_angle_share(x * k - j, piece_sweep)) / k
            }
            OwnParam::Angle(angle) => {
                // The domain's end is the full turn, not its wrap to 0.
                if v >= b {
                    TAU
                } else {
                    angle.phi(v)
                }
            }
        }
    }

    /// The form's parameter of the own parameter `w` (the inverse of [`OwnParam::own`]).
    pub fn form(self, w: f64, (a, b): (f64, f64)) -> f64 {
        match self {
            OwnParam::Same => w,
            OwnParam::Arc {
                pieces,
                piece_sweep,
            } => {
                let k = pieces as f64;
                let y = w.clamp(0.0, 1.0) * k;
                let j = y.floor().min(k - 1.0);
                let x = (j + arc_form_share(y - j, piece_sweep)) / k;
                a + x * (b - a)
            }
            OwnParam::Angle(angle) => {
                if w >= TAU {
                    return b;
                }
                let psi = match angle {
                    Angle::Circle => w,
                    // tan φ = (a/b) tan ψ (see `Angle`): ψ from φ, in the same quarter.
                    Angle::Squeezed { a, b } => {
                        let (s, c) = w.sin_cos();
                        (b * s).atan2(a * c).rem_euclid(TAU)
                    }
                };
                circle_param(psi)
            }
        }
    }

    /// The own parameter's domain, for the form's domain `(a, b)`.
    pub fn own_domain(self, (a, b): (f64, f64)) -> (f64, f64) {
        match self {
            OwnParam::Same => (a, b),
            OwnParam::Arc { .. } => (0.0, 1.0),
            OwnParam::Angle(_) => (0.0, TAU),
        }
    }
}

/// On one rational quadratic arc piece of sweep `sweep` (end weights 1, middle weight
/// `cos(sweep/2)`), the share of the sweep reached at the piece's parameter `s ∈ [0, 1]`. Such a
/// piece is a Möbius reparametrisation of the half-angle: with θ the angle from the piece's
/// start, `tan((θ − δ/2) / 2) = (2s − 1) tan(δ/4)` (δ = |sweep|).
fn arc_angle_share(s: f64, sweep: f64) -> f64 {
    let half = 0.5 * sweep.abs();
    if half == 0.0 {
        return s;
    }
    0.5 + ((2.0 * s - 1.0) * (0.5 * half).tan()).atan() / half
}

/// The inverse of [`arc_angle_share`]: the piece's parameter where the share `f` of its sweep
/// is reached.
fn arc_form_share(f: f64, sweep: f64) -> f64 {
    let half = 0.5 * sweep.abs();
    if half == 0.0 {
        return f;
    }
    (0.5 + 0.5 * ((f - 0.5) * half).tan() / (0.5 * half).tan()).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::circle::angle;
    use crate::param::ParamCurve;
    use crate::segment::Segment;
    use crate::V2;
    use proptest::prelude::*;

    proptest! {
        /// An arc's own parameter is its angle's share: the point at the form's parameter
        /// `v` lies at the angle `start + own(v) · sweep` from the centre (measured by atan2,
        /// an independent computation), and `form` inverts `own`.
        #[test]
        fn an_arcs_own_parameter_is_its_angle(
            r in 1e-3f64..1e3, start in -7.0f64..7.0,
            sweep in prop_oneof![-TAU..-1e-3, 1e-3..TAU, Just(TAU), Just(-TAU)],
            v in 0.0f64..=1.0,
        ) {
            let arc = Segment::arc([3.0, -1.0], r, start, start + sweep).unwrap();
            let map = arc.own_param();
            let dom = arc.curve().domain();
            let w = map.own(v, dom);
            prop_assert!((0.0..=1.0).contains(&w));
            let p = arc.jet(v).p - V2::new(3.0, -1.0);
            let at = p.y.atan2(p.x);
            let want = start + w * sweep;
            let diff = (at - want).rem_euclid(TAU);
            prop_assert!(diff.min(TAU - diff) <= 1e-13 * (1.0 + start.abs()), "{at} vs {want}");
            testkit::prop_assert_near!(map.form(w, dom), v, 1e-13, "{} vs {v}", map.form(w, dom));
        }
    }

    #[test]
    fn the_circle_angle_and_its_inverse() {
        for angle_kind in [Angle::Circle, Angle::Squeezed { a: 3.0, b: 1.25 }] {
            let map = OwnParam::Angle(angle_kind);
            for i in 0..=400 {
                let u = 4.0 * i as f64 / 400.0;
                let phi = map.own(u, (0.0, 4.0));
                if let Angle::Circle = angle_kind {
                    let want = if u >= 4.0 { TAU } else { angle(u)[0] };
                    testkit::assert_near!(phi, want, 1e-15, "{u}");
                }
                let back = map.form(phi, (0.0, 4.0));
                testkit::assert_near!(back, u, 1e-12, "{u}: {back}");
            }
        }
    }
}
