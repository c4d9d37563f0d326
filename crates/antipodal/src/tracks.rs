//! The track of a curve (Jia §5.1): sample parameters carrying the unwrapped tangent angle ψ,
//! with increments below π between neighbours, certified for spline curves by the hodograph
//! (the tangent numerator's control points on each interval lie in an open half-plane).
//! Dissection reads the curve's turning from it.

use crate::enclosure::HALF_PLANE_MARGIN;
use crate::error::{Error, Result};
use crate::view::View;
use curve::{wrap_pi, V2};
use smallvec::SmallVec;
use std::f64::consts::PI;

/// Unwrapped tangent angle along the curve.
pub(crate) struct Tracks {
    pub(crate) u: Vec<f64>,
    pub(crate) psi: Vec<f64>,
    /// The curve's points there (for the simplicity test; empty for a curve simple by
    /// construction).
    pub(crate) p: Vec<V2>,
}

impl Tracks {
    /// Total turning over the track (±2π for a simple closed curve).
    pub(crate) fn turn(&self) -> f64 {
        self.psi[self.psi.len() - 1] - self.psi[0]
    }

    /// The same track for the curve run backwards (`u ↦ a + b − u`): no re-evaluation.
    pub(crate) fn reversed(&self, a: f64, b: f64) -> Tracks {
        // The reversed tangent points the other way: its angle is ψ + π, read backwards.
        Tracks {
            u: self.u.iter().rev().map(|u| a + b - u).collect(),
            psi: self.psi.iter().rev().map(|p| p + PI).collect(),
            p: self.p.iter().rev().copied().collect(),
        }
    }
}

/// The most points a track takes (with a depth of 40 halvings) before the curve is refused
/// as singular: a tangent turning too fast to resolve is a cusp to within rounding.
const MAX_SAMPLES: usize = 1 << 14;

/// Points a track has room for at first (the papers' shapes take 7–13 on their circle forms,
/// a random cubic with 20 control points 22).
const TRACK_ROOM: usize = 32;

impl View<'_> {
    /// Tangent angle at `u` given the track (valid for any unwrapped `u`).
    pub(crate) fn psi(&self, tr: &Tracks, u: f64) -> f64 {
        let (base, turns) = if self.closed {
            let k = ((u - self.a) / self.period).floor();
            (u - k * self.period, k)
        } else {
            (u.clamp(self.a, self.b), 0.0)
        };
        let i = tr.u.partition_point(|&x| x <= base).clamp(1, tr.u.len()) - 1;
        let ang = self.jet_to(base, 1).d1.angle();
        // ψᵢ is the sample's tangent angle unwrapped: the wrapped difference needs no jet there.
        tr.psi[i] + wrap_pi(ang - tr.psi[i]) + turns * tr.turn()
    }

    /// ψ at a track point shifted by whole periods (no evaluation).
    pub(crate) fn psi_sample(&self, tr: &Tracks, i: usize, periods: f64) -> f64 {
        tr.psi[i] + periods * tr.turn()
    }

    /// Builds the track over one period (or the open domain).
    pub(crate) fn tracks(&self, knots: &[f64]) -> Result<Tracks> {
        // A certified curve only needs the track for the unwrapped angle and for the arcs of
        // the simplicity test: the hodograph certifies every step, so a few samples besides
        // the breakpoints do. Otherwise the track is Jia's sampling (and the polygon of the
        // sampled simplicity test).
        let coarse = self.cert.is_some();
        let (m, max_step) = if coarse {
            (16, PI / 2.0)
        } else {
            (self.samples.max(4 * knots.len()), PI / 4.0)
        };
        // A coarse track starts from the breakpoints alone: the refinement below halves a
        // step until the hodograph certifies it (one fine piece of the tangent's enclosure
        // does at once) and it turns by less than π/2. (Starting from every fine piece cost
        // the ellipse a tenth of its run in samples it did not need.)
        let mut us: Vec<f64> = Vec::with_capacity(m + 1 + knots.len());
        if coarse {
            us.extend([self.a, self.b]);
        } else {
            us.extend((0..=m).map(|i| self.a + self.period * i as f64 / m as f64));
        }
        us.extend(knots.iter().copied().filter(|&k| k > self.a && k < self.b));
        us.sort_by(f64::total_cmp);
        us.dedup();
        let speed_floor = SPEED_FLOOR * self.scale / self.period.max(f64::MIN_POSITIVE);
        let jet = |x: f64| -> Result<curve::Jet> {
            let j = self.jet_to(x, 1);
            if j.d1.norm() <= speed_floor {
                return Err(Error::Cusp {
                    u: self.to_curve(x),
                });
            }
            Ok(j)
        };
        let (mut x0, mut j0) = (us[0], jet(us[0])?);
        // (Room for a typical track: growing the vectors cost more than filling them.)
        let mut out_u = Vec::with_capacity(TRACK_ROOM);
        out_u.push(x0);
        let mut out_psi = Vec::with_capacity(TRACK_ROOM);
        out_psi.push(j0.d1.angle());
        // Points only for the simplicity test (not run on a curve simple by construction).
        let keep_points = !self.curve_known_simple();
        let mut out_p = Vec::with_capacity(if keep_points { TRACK_ROOM } else { 0 });
        if keep_points {
            out_p.push(j0.p);
        }
        let mut stack: SmallVec<[(f64, usize, curve::Jet); 16]> = SmallVec::new();
        for &w1 in &us[1..] {
            // Depth-first refinement of [x0, w1] until each step turns by less than
            // `max_step` (and, for splines, the hodograph certifies less than π). Every
            // point is evaluated once: the stack holds right ends with their jets.
            stack.push((w1, 0, jet(w1)?));
            while let Some(&(x1, depth, j1)) = stack.last() {
                // (The angle between the two tangents: one arctangent, not two.)
                let step = j0.d1.cross(j1.d1).atan2(j0.d1.dot(j1.d1));
                let axis = (j0.d1.unit() + j1.d1.unit()).unit();
                if step.abs() < max_step && self.hodograph_cone_ok(x0, x1, axis) {
                    stack.pop();
                    let last = out_psi[out_psi.len() - 1];
                    out_u.push(x1);
                    out_psi.push(last + step);
                    if keep_points {
                        out_p.push(j1.p);
                    }
                    (x0, j0) = (x1, j1);
                    continue;
                }
                if depth > 40 || out_u.len() + stack.len() > MAX_SAMPLES {
                    return Err(Error::Cusp {
                        u: self.to_curve(0.5 * (x0 + x1)),
                    });
                }
                let mid = 0.5 * (x0 + x1);
                stack.push((mid, depth + 1, jet(mid)?));
            }
        }
        Ok(Tracks {
            u: out_u,
            psi: out_psi,
            p: out_p,
        })
    }

    /// For splines: the tangent numerator's control points on `[x0, x1]` lie in an open
    /// half-plane, so the tangent turns by less than π there. Always true for analytic curves.
    fn hodograph_cone_ok(&self, x0: f64, x1: f64, axis: V2) -> bool {
        let Some(cert) = &self.cert else {
            return true;
        };
        let (l, h) = (x0.max(self.a), x1.min(self.b));
        if h <= l {
            return true;
        }
        if cert.bound_forms().is_some_and(|f| {
            f.tangent.in_half_plane(l, h) || f.tangent.in_half_plane_of(l, h, axis)
        }) {
            return true;
        }
        let mut ok = true;
        cert.tangent.for_each_restricted_points(l, h, |pts, err| {
            // Each coordinate within its bound of the exact one: the projection on the axis
            // within their weighted sum, beyond which the point must lie on the axis's side
            // (with room for the rounding of the projection).
            let reach = err[0] * axis.x.abs() + err[1] * axis.y.abs();
            ok = pts.chunks_exact(2).all(|c| {
                let v = V2::new(c[0], c[1]);
                v.dot(axis) > reach + HALF_PLANE_MARGIN * v.norm().max(f64::MIN_POSITIVE)
            });
            ok
        });
        ok
    }
}

/// The speed (relative to the size over the period) below which a track's point is a cusp to
/// within rounding: the tangent's direction there is noise.
const SPEED_FLOOR: f64 = 1e-13;
