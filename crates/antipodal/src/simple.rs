//! The simplicity test of a closed curve, by enclosures of its monotone arcs.
//!
//! The track (tangent-angle samples, each step certified by the hodograph to turn by less than
//! π) cut at the inflections gives arcs on which the tangent turns one way only; cut further
//! so that each turns by less than π/2, an arc lies in the triangle of its chord and end
//! tangents. Two arcs do not meet when
//!
//! - the boxes of their triangles are disjoint, or
//! - one of the two stretches of the curve that join them has all its tangents in an open
//!   half-plane: such a stretch is a graph over the half-plane's axis, so no point of it is
//!   passed twice.
//!
//! The other pairs are halved until their boxes separate, or until they are proven to cross:
//! each runs from one side of the strip around the other's chord to the other side, and two
//! curves crossing a parallelogram between opposite sides meet. A pair that neither separates
//! nor crosses within the halving bound (a curve touching itself within rounding) leaves the
//! result uncertified.
//!
//! On a curve without symbolic forms the inflections are sampled, so an arc may hide a pair of
//! them: the densified polygon of the track is searched for crossings instead.

use crate::dissect::Zeros;
use crate::error::{Error, Result};
use crate::tracks::Tracks;
use crate::view::View;
use curve::{wrap_pi, V2};
use numeric::certificate::{Doubt, Doubts};
use numeric::subdivide::{depth_first, Decision};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Halvings of a pair of arcs before the test gives up on it (2⁻⁴⁰ of an arc is far below
/// the parameter tolerance).
const MAX_SIMPLICITY_DEPTH: usize = 40;

/// Pairs of arcs halved in one test, over all pairs.
const MAX_SPLITS: usize = 4096;

/// A stretch of the curve on which the tangent turns one way only, by less than π/2.
#[derive(Debug, Clone, Copy)]
struct Arc {
    u0: f64,
    u1: f64,
    p0: V2,
    p1: V2,
    /// Unwrapped tangent angles at the ends.
    psi0: f64,
    psi1: f64,
}

/// Where an arc lies: its box, and the strip around its chord line (unit normal `n` through
/// `p0`, half-width `sag`).
#[derive(Debug, Clone, Copy)]
struct Hull {
    lo: V2,
    hi: V2,
    n: V2,
    sag: f64,
}

impl Arc {
    /// The triangle of the chord and the end tangents (padded by `pad` for rounding); a
    /// nearly straight arc strays from its chord by at most `|chord| tan τ`, τ its turning
    /// (every tangent is within τ of the chord's direction, which it takes somewhere).
    fn hull(&self, pad: f64) -> Hull {
        let chord = self.p1 - self.p0;
        let len = chord.norm();
        let n = if len > 0.0 {
            chord.perp() * (1.0 / len)
        } else {
            V2::new(0.0, 0.0)
        };
        let (t0, t1) = (V2::polar(self.psi0), V2::polar(self.psi1));
        let tau = (self.psi1 - self.psi0).abs();
        let sin = t0.cross(t1);
        let (mut lo, mut hi) = (
            V2::new(self.p0.x.min(self.p1.x), self.p0.y.min(self.p1.y)),
            V2::new(self.p0.x.max(self.p1.x), self.p0.y.max(self.p1.y)),
        );
        let sag = if sin.abs() > APEX_MIN_SIN {
            let apex = self.p0 + t0 * (chord.cross(t1) / sin);
            lo = V2::new(lo.x.min(apex.x), lo.y.min(apex.y));
            hi = V2::new(hi.x.max(apex.x), hi.y.max(apex.y));
            (apex - self.p0).dot(n).abs()
        } else {
            let h = len * tau.tan();
            lo = lo - V2::new(h, h);
            hi = hi + V2::new(h, h);
            h
        };
        Hull {
            lo: lo - V2::new(pad, pad),
            hi: hi + V2::new(pad, pad),
            n,
            sag: sag + pad,
        }
    }
}

impl Hull {
    fn overlaps(&self, o: &Hull) -> bool {
        self.lo.x <= o.hi.x && o.lo.x <= self.hi.x && self.lo.y <= o.hi.y && o.lo.y <= self.hi.y
    }
}

/// Arc `b`'s ends lie on opposite sides of the strip around `a`'s chord, outside it.
fn spans(a: &Arc, ha: &Hull, b: &Arc) -> bool {
    let (d0, d1) = ((b.p0 - a.p0).dot(ha.n), (b.p1 - a.p0).dot(ha.n));
    (d0 > ha.sag && d1 < -ha.sag) || (d0 < -ha.sag && d1 > ha.sag)
}

impl View<'_> {
    /// The curve is simple: its tangent turns once around (±2π), and no two of its arcs
    /// meet (see the module notes; without symbolic forms, no two chords of its sampled
    /// polygon cross). Uncertifies the result where a pair of arcs could not be decided.
    pub(crate) fn check_simple(
        &self,
        tr: &Tracks,
        zeros: &Zeros,
        doubts: &mut Doubts,
    ) -> Result<()> {
        let turn = tr.turn();
        if (turn.abs() - TAU).abs() > 0.5 {
            return Err(Error::Winding { turns: turn / TAU });
        }
        if self.cert.is_none() {
            // Sampled inflections and uncertified track steps do not make the arcs monotone:
            // the enclosures would prove nothing, and only the polygon is searched.
            return self.check_polygon(tr);
        }
        let arcs = self.monotone_arcs(tr, zeros, doubts);
        let pad = HULL_ROUNDING * self.scale;
        let hulls: Vec<Hull> = arcs.iter().map(|a| a.hull(pad)).collect();
        let mut order: Vec<usize> = (0..arcs.len()).collect();
        order.sort_by(|&i, &j| hulls[i].lo.x.total_cmp(&hulls[j].lo.x));
        let mut splits = MAX_SPLITS;
        let mut decided = true;
        for (k, &i) in order.iter().enumerate() {
            for &j in &order[k + 1..] {
                if hulls[j].lo.x > hulls[i].hi.x {
                    break;
                }
                if !hulls[i].overlaps(&hulls[j]) || joined_by_graph(&arcs, turn, i, j) {
                    continue;
                }
                decided &= self.apart(arcs[i], arcs[j], pad, 0, &mut splits)?;
            }
        }
        if !decided {
            doubts.add(Doubt::SimplicityUndecided);
        }
        Ok(())
    }

    /// The track's steps cut at the inflections and the ends of straight stretches, then
    /// halved until each turns by less than π/2.
    fn monotone_arcs(&self, tr: &Tracks, zeros: &Zeros, doubts: &mut Doubts) -> Vec<Arc> {
        let mut cuts: Vec<f64> = zeros.zs.iter().map(|z| z.u).collect();
        for &(lo, hi) in &zeros.flats {
            cuts.extend([self.wrap(lo), self.wrap(hi)]);
        }
        cuts.sort_by(f64::total_cmp);
        let mut arcs = Vec::with_capacity(tr.u.len() + cuts.len());
        let mut next_cut = 0;
        for i in 0..tr.u.len() - 1 {
            let (u0, u1) = (tr.u[i], tr.u[i + 1]);
            let point = |k: usize| tr.p.get(k).copied().unwrap_or_else(|| self.point(tr.u[k]));
            let mut start = (u0, point(i), tr.psi[i]);
            while next_cut < cuts.len() && cuts[next_cut] <= u0 {
                next_cut += 1;
            }
            while next_cut < cuts.len() && cuts[next_cut] < u1 {
                let z = cuts[next_cut];
                next_cut += 1;
                // Within a step the tangent turns by less than π: the wrapped difference
                // unwraps it.
                let j = self.jet_to(z, 1);
                let psi = tr.psi[i] + wrap_pi(j.d1.angle() - tr.psi[i]);
                self.push_halved(&mut arcs, start, (z, j.p, psi), doubts);
                start = (z, j.p, psi);
            }
            self.push_halved(&mut arcs, start, (u1, point(i + 1), tr.psi[i + 1]), doubts);
        }
        arcs
    }

    /// Pushes the arc between two cuts, halved until each part turns by less than π/2
    /// (margin 0.1 for the rounding of the angles).
    fn push_halved(
        &self,
        arcs: &mut Vec<Arc>,
        a: (f64, V2, f64),
        b: (f64, V2, f64),
        doubts: &mut Doubts,
    ) {
        let arc = Arc {
            u0: a.0,
            u1: b.0,
            p0: a.1,
            p1: b.1,
            psi0: a.2,
            psi1: b.2,
        };
        // (No depth bound: an arc is halved only while it is wider than the tolerance.)
        depth_first(arc, usize::MAX, |arc, _| {
            let turning = (arc.psi1 - arc.psi0).abs();
            if turning < FRAC_PI_2 - 0.1 || arc.u1 - arc.u0 <= self.tol {
                // An arc within the tolerance that still turns this much (a near-cusp) may
                // leave its triangle: what is decided with it is not proven.
                if turning >= FRAC_PI_2 - 0.1 {
                    doubts.add(Doubt::NearCusp);
                }
                arcs.push(arc);
                return Decision::<_, ()>::Decided;
            }
            let (l, r) = self.halves(&arc);
            Decision::Halve(l, r)
        });
    }

    /// The two halves of an arc (one jet at its middle).
    fn halves(&self, arc: &Arc) -> (Arc, Arc) {
        let m = 0.5 * (arc.u0 + arc.u1);
        let j = self.jet_to(m, 1);
        let psi = arc.psi0 + wrap_pi(j.d1.angle() - arc.psi0);
        (
            Arc {
                u1: m,
                p1: j.p,
                psi1: psi,
                ..*arc
            },
            Arc {
                u0: m,
                p0: j.p,
                psi0: psi,
                ..*arc
            },
        )
    }

    /// Two arcs whose boxes overlap: `Ok(true)` when halving separates them, an error when
    /// they are proven to cross, `Ok(false)` when neither is reached within the bounds.
    fn apart(&self, a: Arc, b: Arc, pad: f64, depth: usize, splits: &mut usize) -> Result<bool> {
        let (ha, hb) = (a.hull(pad), b.hull(pad));
        if !ha.overlaps(&hb) {
            return Ok(true);
        }
        if spans(&a, &ha, &b) && spans(&b, &hb, &a) {
            return Err(Error::SelfIntersecting {
                s: self.to_curve(0.5 * (a.u0 + a.u1)),
                t: self.to_curve(0.5 * (b.u0 + b.u1)),
            });
        }
        if depth >= MAX_SIMPLICITY_DEPTH || *splits == 0 {
            return Ok(false);
        }
        *splits -= 1;
        let (a0, a1) = self.halves(&a);
        let (b0, b1) = self.halves(&b);
        let mut sure = true;
        for (x, y) in [(a0, b0), (a0, b1), (a1, b0), (a1, b1)] {
            sure &= self.apart(x, y, pad, depth + 1, splits)?;
        }
        Ok(sure)
    }

    /// The sampled test of curves without symbolic forms: the track's polygon, four chords
    /// per step, searched for crossings.
    fn check_polygon(&self, tr: &Tracks) -> Result<()> {
        let mut us = Vec::with_capacity(4 * tr.u.len());
        let mut pts = Vec::with_capacity(4 * tr.u.len());
        for (i, w) in tr.u.windows(2).enumerate() {
            us.push(w[0]);
            pts.push(tr.p.get(i).copied().unwrap_or_else(|| self.point(w[0])));
            for k in 1..4 {
                let u = w[0] + (w[1] - w[0]) * k as f64 / 4.0;
                us.push(u);
                pts.push(self.point(u));
            }
        }
        let n = pts.len();
        let seg = |i: usize| (pts[i], pts[(i + 1) % n]);
        let minx = |i: usize| {
            let (p, q) = seg(i);
            p.x.min(q.x)
        };
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&i, &j| minx(i).total_cmp(&minx(j)));
        for (k, &i) in order.iter().enumerate() {
            let (p, q) = seg(i);
            let maxx = p.x.max(q.x);
            for &j in &order[k + 1..] {
                if minx(j) > maxx {
                    break;
                }
                if j == (i + 1) % n || i == (j + 1) % n || i == j {
                    continue;
                }
                let (r, s) = seg(j);
                if crosses(p, q, r, s) {
                    return Err(Error::SelfIntersecting {
                        s: self.to_curve(us[i]),
                        t: self.to_curve(us[j]),
                    });
                }
            }
        }
        Ok(())
    }
}

/// One of the two stretches of the closed curve from arc `i` to arc `j` (both included) has
/// its tangent angles within an open interval shorter than π (`turn`: the total turning,
/// which continues the unwrapped angles across the seam).
fn joined_by_graph(arcs: &[Arc], turn: f64, i: usize, j: usize) -> bool {
    let (lo, hi) = (i.min(j), i.max(j));
    let spread_below_pi = |ks: &mut dyn Iterator<Item = (usize, f64)>| {
        let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
        for (k, shift) in ks {
            let a = &arcs[k];
            min = min.min(a.psi0.min(a.psi1) + shift);
            max = max.max(a.psi0.max(a.psi1) + shift);
            if max - min >= PI - TURN_MARGIN {
                return false;
            }
        }
        true
    };
    let n = arcs.len();
    spread_below_pi(&mut (lo..=hi).map(|k| (k, 0.0)))
        || spread_below_pi(&mut (hi..n).map(|k| (k, 0.0)).chain((0..=lo).map(|k| (k, turn))))
}

/// Proper crossing of segments pq and rs.
fn crosses(p: V2, q: V2, r: V2, s: V2) -> bool {
    let d1 = (q - p).cross(r - p);
    let d2 = (q - p).cross(s - p);
    let d3 = (s - r).cross(p - r);
    let d4 = (s - r).cross(q - r);
    (d1 > 0.0) != (d2 > 0.0)
        && (d3 > 0.0) != (d4 > 0.0)
        && d1 != 0.0
        && d2 != 0.0
        && d3 != 0.0
        && d4 != 0.0
}

/// The sine of the turn between an arc's end tangents above which their meet bounds the arc
/// (below, the division by it is ill-conditioned: the chord's sag bound is used).
const APEX_MIN_SIN: f64 = 1e-9;

/// Room (relative to the size) around each arc's hull for the rounding of its points.
const HULL_ROUNDING: f64 = 1e-12;

/// How far below π the tangent's turn over a run of arcs must stay (radians) for the run to
/// be monotone in direction: far above the rounding of the angles.
const TURN_MARGIN: f64 = 1e-9;
