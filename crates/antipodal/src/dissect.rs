//! Dissection (Jia §5.1–5.2): inflections, then monotone pieces of total curvature below π.
//!
//! A "track" of sample parameters carries the unwrapped tangent angle ψ with increments below
//! π between neighbours. For spline curves each increment is certified by the hodograph: the
//! tangent numerator's control points on the interval lie in an open half-plane, so the tangent
//! turns by less than π there. Analytic curves are sampled (Jia's method, not certified).

use crate::error::Result;
use crate::prims::solve_in;
use crate::tracks::Tracks;
use crate::view::View;
use bspline::roots::SignChangeKind;
use curve::V2;
use numeric::certificate::{Doubt, Doubts};
use numeric::rounding::ulps;
use smallvec::SmallVec;
use std::f64::consts::PI;

/// A monotone piece of the curve: κ of one sign inside, |total curvature| < π.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Piece {
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    /// κ > 0 inside (the tangent turns left; convex on a counterclockwise closed curve).
    pub(crate) convex: bool,
    /// Tangent angle at `lo` (unwrapped).
    pub(crate) psi_lo: f64,
    /// Signed total curvature Φ(lo, hi).
    pub(crate) rot: f64,
    /// A straight stretch (κ ≡ 0): its normal is constant.
    pub(crate) flat: bool,
    /// How fast the tangent turns at the ends, `dψ/du` (for [`Piece::param_guess`]).
    pub(crate) rates: (f64, f64),
    /// Its place in the view's list of pieces.
    pub(crate) id: usize,
}

impl Piece {
    /// Where the tangent angle is about `ang` (unwrapped, inside the piece's range): the
    /// cubic Hermite interpolant of `u(ψ)` from the ends' parameters and turning rates, its
    /// slopes limited to keep it monotone (Fritsch–Carlson; at an inflection that ends the
    /// piece the rate vanishes). A start for Newton, not an answer.
    pub(crate) fn param_guess(&self, ang: f64) -> f64 {
        if self.rot == 0.0 {
            return 0.5 * (self.lo + self.hi);
        }
        let x = ((ang - self.psi_lo) / self.rot).clamp(0.0, 1.0);
        let du = self.hi - self.lo;
        // Slopes of u(x) at the ends: du/dψ · dψ/dx, within [0, 3 du] (u rises with x).
        let slope = |rate: f64| {
            let m = self.rot / rate;
            if m.is_finite() && m > 0.0 {
                m.min(3.0 * du)
            } else {
                3.0 * du
            }
        };
        let (m0, m1) = (slope(self.rates.0), slope(self.rates.1));
        let (x2, x3) = (x * x, x * x * x);
        let u = (2.0 * x3 - 3.0 * x2 + 1.0) * self.lo
            + (x3 - 2.0 * x2 + x) * m0
            + (-2.0 * x3 + 3.0 * x2) * self.hi
            + (x3 - x2) * m1;
        u.clamp(self.lo, self.hi)
    }
}

/// Where the curvature changes sign.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Zero {
    /// The parameter.
    pub(crate) u: f64,
    /// An interval proven to hold it (certified isolation), in the view's parameter.
    pub(crate) bracket: Option<(f64, f64)>,
    /// Existence (and uniqueness in the bracket) follow from coefficient signs.
    pub(crate) certified: bool,
    /// A cluster of roots (the curvature within rounding of zero across the bracket).
    pub(crate) cluster: bool,
    /// A jump of the curvature where the tangent jumps too (a corner): the curve is cut
    /// there, but it does not inflect.
    pub(crate) corner: bool,
}

impl Zero {
    fn sampled(u: f64) -> Self {
        Zero {
            u,
            bracket: None,
            certified: false,
            cluster: false,
            corner: false,
        }
    }
}

/// The largest sine of the angle between the one-sided tangents at a jump of the curvature
/// that still counts as a continuous tangent (an inflection rather than a corner), where the
/// forms do not prove the curve `C¹` there: far above the rounding of the tangents, far below
/// any drawn corner.
const TANGENT_CONTINUITY: f64 = 1e-9;

/// Inflections and straight stretches.
pub(crate) struct Zeros {
    /// Sign changes of the curvature in `[a, a + period)`, sorted: simple inflections, and
    /// corners.
    pub(crate) zs: Vec<Zero>,
    /// Straight stretches between a left and a right turn: an inflection each, reported as a
    /// cluster (not cut at: the stretches are pieces of their own).
    pub(crate) flat_changes: Vec<Zero>,
    /// Intervals where the curvature vanishes identically (unwrapped, `lo < hi`).
    pub(crate) flats: Vec<(f64, f64)>,
}

impl View<'_> {
    /// Simple inflections in `[a, a + period)`, sorted (Jia §5.1): from the symbolic forms,
    /// or sampled along the track `tr` (built here when not given).
    pub(crate) fn inflections(&self, tr: Option<&Tracks>, doubts: &mut Doubts) -> Result<Zeros> {
        let mut flats = Vec::new();
        let mut flat_changes = Vec::new();
        let mut out = match &self.cert {
            Some(cert) => {
                // The sign changes of the curvature numerator: simple roots, narrow clusters
                // across which the sign changes (a double root bends back: second-order,
                // neglected as in §5.1), jumps at discontinuities and at the seam of a clamped
                // closed curve. Clusters wider than 1e-6 of the period are straight stretches.
                let found = cert.curvature_sign_changes(&cert.opts, self.closed)?;
                if !found.certified() {
                    doubts.add(Doubt::CurvatureUnresolved);
                }
                // A stretch whose curvature vanishes within rounding is taken as straight:
                // proven where the data make it exactly straight, a judgement elsewhere.
                if found.flats.iter().any(|f| {
                    let (lo, hi) = f.bracket;
                    self.straight_chain(lo, hi).is_none()
                }) {
                    doubts.add(Doubt::FlatWithinRounding);
                }
                flats.extend(found.flats.iter().map(|f| f.bracket));
                // (A straight stretch between opposite bends: the inflection is the stretch,
                // certain where it is proven straight.)
                flat_changes.extend(found.flats.iter().filter(|f| f.sign_change).map(|f| Zero {
                    u: f.u,
                    bracket: Some(f.bracket),
                    certified: self.straight_chain(f.bracket.0, f.bracket.1).is_some(),
                    cluster: true,
                    corner: false,
                }));
                found
                    .changes
                    .iter()
                    .map(|c| {
                        let (corner, certain) = match c.kind {
                            SignChangeKind::Jump => self.corner_at(c.u),
                            _ => (false, true),
                        };
                        if !certain {
                            doubts.add(Doubt::CornerUndecided);
                        }
                        Zero {
                            u: c.u,
                            bracket: Some(c.bracket),
                            certified: c.certified && certain,
                            cluster: c.kind == SignChangeKind::Cluster,
                            corner,
                        }
                    })
                    .collect()
            }
            None => {
                let owned;
                let tr = match tr {
                    Some(tr) => tr,
                    None => {
                        owned = self.tracks(&[])?;
                        &owned
                    }
                };
                let kappa = |u: f64| {
                    let j = self.jet(u);
                    (j.d1.cross(j.d2), j.d1.cross(j.d3), f64::NAN)
                };
                let mut zs = Vec::new();
                for w in tr.u.windows(2) {
                    let (k0, k1) = (kappa(w[0]).0, kappa(w[1]).0);
                    if k0 == 0.0 && w[0] == tr.u[0] && !self.closed {
                        continue;
                    }
                    if (k0 < 0.0) != (k1 < 0.0) && k1 != 0.0 {
                        let u = solve_in(kappa, (w[0], w[1]), (k0, k1), self.tol, f64::NAN);
                        zs.push(Zero::sampled(u));
                    }
                }
                zs
            }
        };
        for z in &mut out {
            if self.closed {
                let w = self.wrap(z.u);
                let shift = w - z.u;
                z.u = w;
                z.bracket = z.bracket.map(|(lo, hi)| (lo + shift, hi + shift));
            }
        }
        out.sort_by(|x, y| x.u.total_cmp(&y.u));
        // One root found twice (at a break of the forms, or at both ends of the period): its
        // brackets meet. Two certified roots in disjoint brackets stay two however close
        // (merging two 1.1e-9 apart across a seam at a tolerance of 1e-10 left a closed curve
        // with three inflections, certified). Without brackets, closeness decides.
        let tol = self.tol;
        let same = move |x: &Zero, y: &Zero, shift: f64| match (x.bracket, y.bracket) {
            (Some((a, b)), Some((c, d))) => a <= d + shift && c + shift <= b,
            _ => (x.u - y.u - shift).abs() <= 4.0 * tol,
        };
        out.dedup_by(|x, y| same(x, y, 0.0));
        if self.closed && out.len() > 1 {
            let last = out.len() - 1;
            if same(&out[0], &out[last], -self.period) {
                out.pop();
            }
        }
        Ok(Zeros {
            zs: out,
            flat_changes,
            flats,
        })
    }

    /// Whether the curvature's jump at `u` (a break of the forms, or the seam) is a corner,
    /// and whether that is certain: where the homogeneous form is `C¹` the tangent is
    /// continuous (no corner, certain); elsewhere the one-sided tangents are compared (not
    /// certain).
    fn corner_at(&self, u: f64) -> (bool, bool) {
        let Some(cert) = &self.cert else {
            return (false, false);
        };
        let hom = &cert.hom;
        let breaks = hom.breaks();
        let k = breaks.partition_point(|&x| x < u);
        let seam = k == 0 || k == breaks.len() - 1;
        let smooth = if seam {
            hom.continuity(0)
        } else if breaks[k] == u {
            hom.continuity(k)
        } else {
            i32::MAX
        };
        if smooth >= 1 {
            return (false, true);
        }
        // The one-sided tangents are the tangent numerator's end coefficients on either side
        // (Bézier pieces interpolate their ends), each within its pieces' error bound.
        // (Tangents sampled a little to either side turn by more than the threshold on a
        // tightly curved stretch: a smooth seam was taken for a corner.)
        let tangent = &cert.tangent;
        let n = tangent.pieces();
        let (i_before, i_after) = match (seam, k) {
            (true, _) => (n - 1, 0),
            (false, k) => (k - 1, k),
        };
        let end = |i: usize, last: bool| {
            let c = tangent.piece(i);
            let at = if last { c.len() - 2 } else { 0 };
            let e = tangent.errors(i);
            (V2::new(c[at], c[at + 1]), e[0].max(e[1]))
        };
        let ((before, eb), (after, ea)) = (end(i_before, true), end(i_after, false));
        let (nb, na) = (before.norm(), after.norm());
        // |a × b| and a · b move by at most |a| e_b + |b| e_a + e_a e_b (per coordinate
        // errors, √2 each way), plus their own rounding.
        let slack = 2.0 * (na * eb + nb * ea + ea * eb) + ulps(4.0) * na * nb;
        let cross = before.cross(after).abs();
        let threshold = TANGENT_CONTINUITY * nb * na;
        let continuous = before.dot(after) > slack && cross + slack <= threshold;
        let corner = before.dot(after) < -slack || cross - slack > threshold;
        (corner, continuous || corner)
    }

    /// The monotone pieces with |Φ| < π (Jia §5.1 step 2).
    pub(crate) fn pieces(&self, tr: &Tracks, zeros: &Zeros, doubts: &mut Doubts) -> Vec<Piece> {
        let zs: Vec<f64> = zeros.zs.iter().map(|z| z.u).collect();
        let zs = &zs;
        let mut arcs: Vec<(f64, f64)> = Vec::with_capacity(zs.len() + 1);
        let mut flat_pieces = Vec::new();
        if self.closed && !zeros.flats.is_empty() {
            // Cut at inflections and at both ends of every straight stretch.
            let mut cuts: Vec<f64> = zs.clone();
            for &(l, h) in &zeros.flats {
                cuts.push(self.wrap(l));
                cuts.push(self.wrap(h));
                let lo = self.wrap(l);
                flat_pieces.push((lo, lo + (h - l)));
            }
            cuts.sort_by(f64::total_cmp);
            cuts.dedup_by(|x, y| (*x - *y).abs() <= 4.0 * self.tol);
            for (i, &z) in cuts.iter().enumerate() {
                let next = if i + 1 < cuts.len() {
                    cuts[i + 1]
                } else {
                    cuts[0] + self.period
                };
                let mid = self.wrap(0.5 * (z + next));
                let is_flat = flat_pieces.iter().any(|&(l, h)| {
                    let m = if mid < l { mid + self.period } else { mid };
                    m > l && m < h
                });
                if !is_flat {
                    arcs.push((z, next));
                }
            }
        } else if self.closed {
            if zs.is_empty() {
                // A convex curve: start at a generic tangent direction, so that symmetric
                // shapes do not put their antipodal points on piece ends.
                let target = self.psi(tr, self.a) + 0.3819660112501051;
                let w0 = self.param_at_angle(tr, self.a, self.a + self.period, target, doubts);
                arcs.push((w0, w0 + self.period));
            } else {
                for (i, &z) in zs.iter().enumerate() {
                    let next = if i + 1 < zs.len() {
                        zs[i + 1]
                    } else {
                        zs[0] + self.period
                    };
                    arcs.push((z, next));
                }
            }
        } else {
            // Cut at inflections and at both ends of every straight stretch, as above.
            let mut cuts = vec![self.a];
            cuts.extend(zs.iter().copied().filter(|&z| z > self.a && z < self.b));
            for &(l, h) in &zeros.flats {
                let (l, h) = (l.max(self.a), h.min(self.b));
                if h > l {
                    cuts.extend([l, h]);
                    flat_pieces.push((l, h));
                }
            }
            cuts.push(self.b);
            cuts.sort_by(f64::total_cmp);
            cuts.dedup_by(|x, y| (*x - *y).abs() <= 4.0 * self.tol);
            for w in cuts.windows(2) {
                let mid = 0.5 * (w[0] + w[1]);
                if !flat_pieces.iter().any(|&(l, h)| mid > l && mid < h) {
                    arcs.push((w[0], w[1]));
                }
            }
        }
        let mut out = Vec::with_capacity(2 * arcs.len() + flat_pieces.len());
        // (Consecutive arcs share an end: its angle is taken once.)
        let mut last_end: Option<(f64, f64)> = None;
        for (lo, hi) in arcs {
            let p0 = match last_end {
                Some((u, psi)) if u == lo => psi,
                _ => self.psi(tr, lo),
            };
            let p1 = self.psi(tr, hi);
            last_end = Some((hi, p1));
            let rot = p1 - p0;
            let k = ((rot.abs() / (0.8 * PI)).ceil() as usize).clamp(1, 64);
            let mut cuts: SmallVec<[f64; 4]> = smallvec::smallvec![lo];
            for j in 1..k {
                let target = p0 + rot * j as f64 / k as f64;
                let prev = cuts[cuts.len() - 1];
                cuts.push(self.param_at_angle(tr, prev, hi, target, doubts));
            }
            cuts.push(hi);
            let rate = |u: f64| {
                let j = self.jet_to(u, 2);
                j.d1.cross(j.d2) / j.d1.dot(j.d1)
            };
            // The angles at the cuts (the arc's ends are known already).
            let mut q0 = p0;
            for (i, w) in cuts.windows(2).enumerate() {
                let q1 = if i + 2 == cuts.len() {
                    p1
                } else {
                    self.psi(tr, w[1])
                };
                let convex = if (q1 - q0).abs() > TURN_ROUNDING {
                    q1 > q0
                } else {
                    self.jet_to(0.5 * (w[0] + w[1]), 2).curvature() > 0.0
                };
                out.push(Piece {
                    lo: w[0],
                    hi: w[1],
                    convex,
                    psi_lo: q0,
                    rot: q1 - q0,
                    flat: false,
                    rates: (rate(w[0]), rate(w[1])),
                    id: out.len(),
                });
                q0 = q1;
            }
        }
        for (lo, hi) in flat_pieces {
            out.push(Piece {
                lo,
                hi,
                convex: false,
                psi_lo: self.psi(tr, 0.5 * (lo + hi)),
                rot: 0.0,
                flat: true,
                rates: (0.0, 0.0),
                id: out.len(),
            });
        }
        out
    }

    /// The parameter in `[lo, hi]` (a monotone stretch) where the tangent angle is `target`.
    fn param_at_angle(
        &self,
        tr: &Tracks,
        lo: f64,
        hi: f64,
        target: f64,
        doubts: &mut Doubts,
    ) -> f64 {
        let k0 = if self.closed {
            ((lo - self.a) / self.period).floor()
        } else {
            0.0
        };
        let periods = if self.closed { 2 } else { 1 };
        // The track's samples strictly inside (lo, hi), over the periods it may span, between
        // the two ends: consecutive points bracket the target angle (no allocation).
        let inside = (0..periods).flat_map(|k| {
            let periods = k0 + k as f64;
            let off = periods * self.period;
            tr.u.iter().enumerate().filter_map(move |(i, &u)| {
                let x = u + off;
                (x > lo && x < hi).then(|| (x, self.psi_sample(tr, i, periods)))
            })
        });
        let points = std::iter::once((lo, self.psi(tr, lo)))
            .chain(inside)
            .chain(std::iter::once((hi, self.psi(tr, hi))));
        let mut prev: Option<(f64, f64)> = None;
        for (x1, p1) in points {
            if let Some((x0, p0)) = prev {
                let (a0, a1) = (p0 - target, p1 - target);
                if a0 == 0.0 {
                    return x0;
                }
                if (a0 < 0.0) != (a1 < 0.0) {
                    let n = V2::polar(target).perp();
                    return self
                        .point_with_normal(x0, x1, n, doubts)
                        .unwrap_or(0.5 * (x0 + x1));
                }
            }
            prev = Some((x1, p1));
        }
        0.5 * (lo + hi)
    }
}

/// A piece's turn (in radians) below which its sign is rounding of the tangent angles at its
/// ends: the curvature in its middle decides whether it is convex instead.
const TURN_ROUNDING: f64 = 1e-12;

#[cfg(test)]
mod tests {
    use super::*;

    fn piece(rates: (f64, f64), rot: f64) -> Piece {
        Piece {
            lo: 2.0,
            hi: 3.0,
            convex: rot > 0.0,
            psi_lo: 1.0,
            rot,
            flat: false,
            rates,
            id: 0,
        }
    }

    /// The guess reproduces a uniformly turning piece, its ends, and stays monotone inside
    /// the piece when a rate vanishes (an inflection at an end) or is huge.
    #[test]
    fn param_guess_is_exact_on_uniform_turning_and_monotone() {
        let uniform = piece((0.5, 0.5), 0.5);
        for i in 0..=10 {
            let x = i as f64 / 10.0;
            testkit::assert_near!(uniform.param_guess(1.0 + 0.5 * x), 2.0 + x, 1e-12);
        }
        for rates in [(0.0, 0.5), (0.5, 0.0), (1e9, 0.1), (-0.5, -0.5)] {
            for rot in [0.5f64, -0.5] {
                let p = piece((rates.0 * rot.signum(), rates.1 * rot.signum()), rot);
                assert_eq!(p.param_guess(1.0), 2.0);
                assert_eq!(p.param_guess(1.0 + rot), 3.0);
                let mut last = 2.0;
                for i in 1..=100 {
                    let u = p.param_guess(1.0 + rot * i as f64 / 100.0);
                    assert!(u >= last && u <= 3.0, "{rates:?} {rot}: {u} after {last}");
                    last = u;
                }
            }
        }
    }
}
