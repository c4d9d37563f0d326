//! Edges of the closed-form paths: an edge traced between two solved nodes, straight or
//! conic, each vertex's feet and disk tested, and cut where its feet pass a whole circle's
//! joint.

use super::{LinesAndArcs, Solved, SAME_SEED_NODE};
use crate::candidates::{Candidate, Vertex};
use crate::corners::entered_across_corner;
use crate::true_sites::{SiteShape, TrueSite};
use curve::{wrap_pi, V2};
use numeric::subdivide::{depth_first, Decision};
use std::f64::consts::PI;

/// Most distance (a share of the size) between the vertices of an edge: the disks between
/// its ends are tested at that step (as the bisectors of two corners are on the other paths).
const EDGE_STEP: f64 = 1e-2;

/// Most vertices of one edge, and halvings of its foot parameter while it is traced: a
/// parabola's to the finest chord tolerance (1e-9 of the size) takes ~2e4 on a region's
/// width; beyond this the input is refused to the other paths.
const MAX_EDGE_VERTICES: usize = 1 << 16;
const MAX_EDGE_HALVINGS: usize = 16;

/// The least distance (a share of the size) from a round site's centre at which its feet
/// parametrise a conic edge: at the centre every point of the circle is a foot.
const FOOT_ROOM: f64 = 1e-6;

/// The foot parameter on `along` strictly between `t0` and `t1` (a share of their span
/// inside) where the radius of the bisector with `other` is least or greatest, if any: where
/// the feet on both sites are on one normal (a line's foot below the other's centre; a
/// circle's foot towards the other's centre or straight across to the line). Two lines'
/// radius is affine along their bisector.
fn radius_extremum(along: SiteShape, other: SiteShape, t0: f64, t1: f64) -> Option<f64> {
    let inside = |t: f64| {
        let margin = 1e-9 * (t1 - t0).abs();
        (t - t0.min(t1) > margin && t0.max(t1) - t > margin).then_some(t)
    };
    match (along, other) {
        (SiteShape::Line(_), SiteShape::Line(_)) => None,
        (SiteShape::Line(l), SiteShape::Round { centre, .. }) => {
            inside(l.along.dot(centre - l.start))
        }
        (SiteShape::Round { centre, side, .. }, other) => {
            let towards = match other {
                SiteShape::Line(l) => l.inward * -side,
                SiteShape::Round { centre: c, .. } => c - centre,
            };
            let angle = towards.angle();
            // (Either way along the line through the centres; the turn nearest the span.)
            [angle, angle + PI].into_iter().find_map(|a| {
                let a = t0 + wrap_pi(a - t0);
                inside(a)
            })
        }
    }
}

impl LinesAndArcs<'_, '_> {
    /// The candidates and vertices of the edge of sites `[a, b]` between its solved ends:
    /// one, or two where its feet pass the joint of a whole circle; none where its ends are
    /// one node (the edge of nearly cocircular sites that snapping made); `None` where the
    /// true coordinates refuse it (a corner site off the axis's side, a foot off its
    /// segment, an entered disk).
    pub(crate) fn trace_edge(
        &self,
        [a, b]: [TrueSite; 2],
        [p, q]: [Solved; 2],
    ) -> Option<Vec<(Candidate, Vec<Vertex>)>> {
        if (q.xy - p.xy).norm() <= SAME_SEED_NODE * self.sites.size {
            return Some(Vec::new());
        }
        // (A point site on the axis's side is a reflex corner.)
        for s in [a, b].into_iter().filter(|s| s.corner) {
            let u = s.segment as f64;
            if !self
                .sites
                .inside_of(s.boundary, s.segment, u, true, p.xy.arr())
            {
                return None;
            }
        }
        let sites = [a, b];
        let ends = [p, q];
        let straight = a.corner == b.corner && self.arc(a).is_none() && self.arc(b).is_none();
        let points = if straight {
            self.straight(p.xy, q.xy)?
        } else {
            self.conic(sites, p.xy, q.xy)?
        };
        let affine = straight && !a.corner && ends.iter().all(|e| self.on_bisector(sites, e));
        let last = points.len() - 1;
        let vertices = points
            .iter()
            .enumerate()
            .map(|(k, &x)| {
                // (Between two lines the radius is affine along the edge: the ends' radii
                // interpolated, where they are the lines' distances, so that the disks
                // between are the sweep of the end disks.)
                let radius = match k {
                    0 => p.radius,
                    k if k == last => q.radius,
                    _ if affine => p.radius + (q.radius - p.radius) * (k as f64 / last as f64),
                    _ => self.shape(sites[0]).distance(x).0,
                };
                let tr = [self.foot(sites[0], x)?, self.foot(sites[1], x)?];
                (radius >= 0.0).then_some(Vertex {
                    tr,
                    xy: x.arr(),
                    radius,
                })
            })
            .collect::<Option<Vec<Vertex>>>()?;
        let candidate = |vertices: &[Vertex]| Candidate {
            boundary: sites.map(|s| s.boundary),
            segment: sites.map(|s| s.segment),
            corner: sites.map(|s| s.corner),
            tr: vertices.iter().map(|v| v.tr).collect(),
            xy: vertices.iter().map(|v| v.xy).collect(),
        };
        // (The ends' disks were tested when they were solved; those between, all at once
        // where the edge is two lines' and the sweep of its disks is proven empty.)
        let swept = last > 1 && affine && self.sweep_is_empty(sites, ends);
        let whole = candidate(&vertices);
        for (k, v) in vertices.iter().enumerate() {
            let tested = k == 0 || k == last || swept;
            if !(tested || self.empty(v)) || entered_across_corner(self.sites, &whole, v).is_some()
            {
                return None;
            }
        }
        Some(
            self.cut_at_joints(sites, vertices)?
                .into_iter()
                .map(|v| (candidate(&v), v))
                .collect(),
        )
    }

    /// The vertices of an edge cut where the feet on a whole circle pass its joint (where
    /// their parameter runs on from 1 to 0, or back): at the point of the edge whose foot is
    /// the joint, in closed form.
    fn cut_at_joints(
        &self,
        sites: [TrueSite; 2],
        vertices: Vec<Vertex>,
    ) -> Option<Vec<Vec<Vertex>>> {
        let mut pieces = vec![vertices];
        for (k, &s) in sites.iter().enumerate() {
            let Some(arc) = self.arc(s).filter(|a| a.full()) else {
                continue;
            };
            let other = self.shape(sites[1 - k]);
            let mut out = Vec::new();
            for piece in pieces {
                let angle = |v: &Vertex| arc.angle_from_start(V2::from_arr(v.xy));
                let Some(cut) = piece
                    .windows(2)
                    .position(|w| (angle(&w[0]) - angle(&w[1])).abs() > PI)
                else {
                    out.push(piece);
                    continue;
                };
                let joint = arc.point_at(0.0);
                let normal = (joint - arc.centre) * (arc.side / arc.radius);
                let radius = other.radius_on_ray(joint, normal)?;
                let x = joint + normal * radius;
                let base = s.segment as f64;
                // (The feet run up to the joint's end of the arc, then on from its start.)
                let rising = angle(&piece[cut]) > PI;
                let at = |share: f64| {
                    let mut tr = piece[cut].tr;
                    tr[k] = base + share;
                    tr[1 - k] = self.foot(sites[1 - k], x)?;
                    Some(Vertex {
                        tr,
                        xy: x.arr(),
                        radius,
                    })
                };
                let (before, after) = if rising { (1.0, 0.0) } else { (0.0, 1.0) };
                let (end, start) = (at(before)?, at(after)?);
                if !self.empty(&end) {
                    return None;
                }
                // (A vertex at the cut itself, the radius's extremum where the joint faces
                // the other site, is the cut's: kept once in each piece.)
                let at_cut = |v: &Vertex| {
                    (V2::from_arr(v.xy) - x).norm() <= SAME_SEED_NODE * self.sites.size
                };
                let mut first = piece[..=cut].to_vec();
                if first.len() > 1 && first.last().is_some_and(at_cut) {
                    first.pop();
                }
                first.push(end);
                let rest = &piece[cut + 1..];
                let rest = match rest {
                    [v, more @ ..] if !more.is_empty() && at_cut(v) => more,
                    _ => rest,
                };
                let mut second = vec![start];
                second.extend_from_slice(rest);
                out.push(first);
                out.push(second);
            }
            pieces = out;
        }
        Some(pieces)
    }

    /// The vertices of the straight bisector (of two lines or two points) from `p` to `q`,
    /// [`EDGE_STEP`] apart.
    fn straight(&self, p: V2, q: V2) -> Option<Vec<V2>> {
        let steps = ((q - p).norm() / (EDGE_STEP * self.sites.size))
            .ceil()
            .max(1.0);
        (steps <= MAX_EDGE_VERTICES as f64).then(|| {
            let n = steps as usize;
            // (The ends exactly: they are the nodes.)
            (0..=n)
                .map(|k| match k {
                    0 => p,
                    k if k == n => q,
                    k => p + (q - p) * (k as f64 / n as f64),
                })
                .collect()
        })
    }

    /// The vertices of the conic bisector of `sites` from `p` to `q`, within the chord
    /// tolerance and [`EDGE_STEP`] apart. Its points come from the feet on one site (a line if
    /// there is one, else the round site whose centre is farther from the ends): along the
    /// normal ray at each foot, the other site is as far as the foot where
    /// [`SiteShape::radius_on_ray`] says. The foot parameter's span is halved until each chord
    /// is within the tolerance of the point halfway along it.
    fn conic(&self, sites: [TrueSite; 2], p: V2, q: V2) -> Option<Vec<V2>> {
        let shapes = sites.map(|s| self.shape(s));
        let room = |k: usize| shapes[k].param_room(p).min(shapes[k].param_room(q));
        let by = if room(1) > room(0) { 1 } else { 0 };
        // (Not a number too refuses.)
        if room(by).partial_cmp(&(FOOT_ROOM * self.sites.size)) != Some(std::cmp::Ordering::Greater)
        {
            return None;
        }
        let (along, other) = (shapes[by], shapes[1 - by]);
        let t0 = along.param_of(p);
        let t1 = match along {
            SiteShape::Line(_) => along.param_of(q),
            // (A foot turns by less than half a turn along one edge.)
            SiteShape::Round { .. } => t0 + wrap_pi(along.param_of(q) - t0),
        };
        let at = |t: f64| {
            let (foot, normal) = along.ray(t);
            other.radius_on_ray(foot, normal).map(|r| foot + normal * r)
        };
        let step = EDGE_STEP * self.sites.size;
        let mut out = vec![p];
        // (The spans to halve, in order; the point where the radius is least or greatest
        // between the ends, a vertex, parts them: the offsets find where a pass touches itself
        // there.)
        let (start, end) = ((t0, p), (t1, q));
        let cut = match radius_extremum(along, other, t0, t1) {
            Some(t) => Some((t, at(t)?)),
            None => None,
        };
        let spans = match cut {
            Some(cut) => [Some((start, cut)), Some((cut, end))],
            None => [Some((start, end)), None],
        };
        for span in spans.into_iter().flatten() {
            let refused = depth_first(span, MAX_EDGE_HALVINGS, |(lo, hi), visit| {
                let ((t_lo, x_lo), (t_hi, x_hi)) = (lo, hi);
                let t_mid = 0.5 * (t_lo + t_hi);
                let Some(x_mid) = at(t_mid) else {
                    return Decision::Stop(());
                };
                let sag = curve::distance_to_segment(x_mid.arr(), x_lo.arr(), x_hi.arr());
                if (x_hi - x_lo).norm() > step || sag > self.chord_tol {
                    if !visit.can_halve {
                        // (Finer than the tracer goes: the other paths decide.)
                        return Decision::Stop(());
                    }
                    let mid = (t_mid, x_mid);
                    return Decision::Halve((lo, mid), (mid, hi));
                }
                out.push(x_hi);
                if out.len() > MAX_EDGE_VERTICES {
                    return Decision::Stop(());
                }
                Decision::Decided
            });
            if refused.is_some() {
                return None;
            }
        }
        Some(out)
    }
}
