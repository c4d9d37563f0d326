//! The axis of a region of few lines and circular arcs, with no diagram: the bisector of
//! every pair of its true sites (segments, and reflex corners as points), trimmed to where
//! its disks hold no point of the boundary nearer than their two feet.
//!
//! Below [`crate::SEED_SEGMENTS`] segments a Voronoi diagram of the chords costs more than
//! the whole axis (about 20 µs a chord, and one round hole takes dozens of chords), and the
//! quadtree's pairs trace B-spline bisectors. Here every distance is in closed form. Along
//! the normal ray at a foot on one site of a pair, the bisector's point comes from the other
//! site ([`crate::true_sites::Shape::radius_on_ray`]); its disk is empty where every other
//! site is as far as the feet. A segment's distance counts only where its foot falls on it:
//! the boundary's distance is the least of those and the joints'. The kept stretches of a
//! pair are found on samples of its feet and their ends by bisection; each end is solved as
//! a node on the pair's equation and the one that ends the stretch there
//! ([`LinesAndArcs::solve_node`]). A node names the pairs whose edges meet there, and a pair
//! with no stretch ending at it is followed from it, so that a stretch shorter than the
//! samples' spacing is found too. Each stretch is traced between its ends as the seed's
//! edges are. The cost is O(n³) in the sites, meant for a few dozen.
//!
//! Nothing here proves the axis. A stretch missed (shorter than the first step a pair is
//! followed by from a node) leaves its feet's gap, and the coverage of the feet
//! ([`crate::coverage`]) refuses the axis, which is then built on the quadtree's pairs.

use crate::lines_and_arcs::{Equation, LinesAndArcs, Solved, Traced, SAME_SEED_NODE};
use crate::sites::Sites;
use crate::stretches::Stretch;
use crate::true_sites::TrueSite;
use curve::V2;
use numeric::rounding::ulps;
use std::cell::Cell;
use std::collections::{HashMap, HashSet};

/// Feet sampled along the parametrising site of each pair (at equal steps of its
/// parameter) to find where the pair's bisector has empty disks.
const SAMPLES: usize = 32;

/// Halvings of a sample step that place a stretch's end: 2⁻²⁸ of it, ~1e-10 of the
/// segment, a thousandth of [`ABOUT`] (the sites found touching there are those of the
/// node) and far within the [`REACH`] Newton's method polishes the node from, which it
/// does to rounding in two or three steps.
const END_HALVINGS: usize = 28;

/// Sites whose distance at a stretch's end exceeds the disk's radius by less than this share
/// of the size touch the node there: its equations hold there to the bisection's precision.
const ABOUT: f64 = 1e-7;

/// The rounding of a distance compared with a disk's radius, relative to the coordinates'
/// magnitude: a few dozen ulps.
const PAIRWISE_ROUNDING: f64 = ulps(64.0);

/// How far (a share of the size) Newton's method may move a node from the end the bisection
/// found.
const REACH: f64 = 1e-6;

/// The first step (a share of the parametrising site's span) from a node along a pair's
/// feet when a stretch is followed from it; the steps then double. A stretch shorter than
/// this is not found, and the coverage of the feet refuses the axis.
const FOLLOW_STEP: f64 = 1e-9;

/// Most doublings of the step while a stretch is followed: 2³⁰ of the first step, the span.
const FOLLOW_DOUBLINGS: usize = 30;

/// Most stretches (a bound on the search from nodes): the axis of n sites has O(n) edges;
/// beyond this many the region is no small one.
const MAX_STRETCHES: usize = 1 << 12;

/// The feet along the parametrising site of a pair, by a parameter on `[0, 1]` (beyond, round
/// a whole circle): a line's points, an arc's, or a reflex corner's fan of normals.
#[derive(Clone, Copy)]
enum Feet {
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
    fn param_of(&self, x: V2) -> f64 {
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
    fn ray(&self, t: f64) -> (V2, V2) {
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

/// The region's true sites with the closed forms.
struct Pairwise<'m, 's, 'a> {
    model: &'m LinesAndArcs<'s, 'a>,
    /// The true sites: every segment, every reflex corner.
    sites: Vec<TrueSite>,
    /// Every joint (a corner site, convex or reflex) and its point: with the segments'
    /// distances where their feet fall on them, the distances to these are the distance to
    /// the boundary from anywhere.
    joints: Vec<(TrueSite, V2)>,
    /// The fan of normals at each reflex corner (see [`Fan`]).
    fans: HashMap<TrueSite, Fan>,
    /// The site (an index into `sites`, then `joints`) that last refused a point's disk.
    last_refusal: Cell<usize>,
}

/// The directions in which a reflex corner is the nearest point: from the normal into the
/// axis's side of the segment that ends there, `from`, turning by `turn` (under half a turn)
/// to that of the segment that starts there, `to`.
#[derive(Clone, Copy)]
struct Fan {
    from: V2,
    to: V2,
    turn: f64,
}

impl Fan {
    /// Whether direction `d` lies in the fan.
    fn holds(&self, d: V2) -> bool {
        let sign = self.turn.signum();
        sign * self.from.cross(d) >= 0.0 && sign * d.cross(self.to) >= 0.0
    }
}

/// The candidates and stretches of the axis of `sites`' region (inside), every boundary made
/// of lines and circular arcs, from every pair of true sites: one candidate per stretch
/// (two where its feet pass the joint of a whole circle). `None` where some boundary has
/// other curves, an end cannot be solved or a stretch traced, a pair's axis is a cycle
/// without nodes, or the work is cancelled.
pub(crate) fn pairwise(sites: &Sites<'_>, chord_tol: f64) -> Option<Traced> {
    if sites.clip.is_some() {
        return None;
    }
    let model = LinesAndArcs::new(sites, chord_tol)?;
    let mut all = Vec::new();
    let mut joints = Vec::new();
    let mut fans = HashMap::new();
    for (boundary, b) in sites.boundaries.iter().enumerate() {
        let n = b.segments().len();
        for segment in 0..n {
            let site = TrueSite {
                boundary,
                segment,
                corner: false,
            };
            let corner = TrueSite {
                corner: true,
                ..site
            };
            all.push(site);
            joints.push((corner, model.start(corner)));
            // (A corner on the axis's side is a reflex one; its point is a site.)
            if sites.inside_of(boundary, segment, segment as f64, true, [0.0; 2]) {
                all.push(corner);
                // (A segment's distance has the unit normal into the axis's side as its
                // gradient on it.)
                let at = model.start(corner);
                let normal = |s: TrueSite| model.shape(s).distance(at).1;
                let before = TrueSite {
                    segment: (segment + n - 1) % n,
                    ..site
                };
                let (from, to) = (normal(before), normal(site));
                let turn = from.cross(to).atan2(from.dot(to));
                fans.insert(corner, Fan { from, to, turn });
            }
        }
    }
    let pairwise = Pairwise {
        model: &model,
        sites: all,
        joints,
        fans,
        last_refusal: Cell::new(0),
    };
    let stage = curve::watch::stage("medial axis: every pair of sites");
    let found = pairwise.stretches(&stage)?;
    let mut candidates = Vec::new();
    let mut stretches = Vec::new();
    let mut proven = HashSet::new();
    for Found { pair, ends, .. } in found {
        if !stage.go_on(1) {
            return None;
        }
        for e in ends.iter().filter(|e| e.proven) {
            proven.insert(e.xy.arr().map(f64::to_bits));
        }
        for (candidate, vertices) in model.trace_edge(pair, ends)? {
            stretches.push(Stretch {
                candidate: candidates.len(),
                vertices,
            });
            candidates.push(candidate);
        }
    }
    Some(Traced {
        candidates,
        stretches,
        proven,
    })
}

/// A stretch of the bisector of `pair` with empty disks: its span of the parametrising
/// site's feet, and its ends solved, with the true sites about each.
struct Found {
    pair: [TrueSite; 2],
    span: [f64; 2],
    ends: [Solved; 2],
    about: [Vec<TrueSite>; 2],
}

/// One end of a span of kept feet: the last parameter kept, and the first not kept beyond it
/// (none where the span runs to the end of the feet).
#[derive(Clone, Copy)]
struct Bound {
    kept: f64,
    beyond: Option<f64>,
}

/// How the bisector of a pair is followed: by the feet on `along` (its ray at each), the
/// other site being `other`; `whole` where the feet run round a whole circle.
#[derive(Clone, Copy)]
struct Param {
    along: TrueSite,
    other: TrueSite,
    feet: Feet,
    whole: bool,
}

impl Pairwise<'_, '_, '_> {
    /// Every stretch of every pair's bisector with empty disks. Each pair's feet are
    /// sampled; then every node found names the pairs whose edges meet there (each two of
    /// its sites), and a pair with no stretch ending there is followed from it: a stretch
    /// shorter than the samples' spacing is found from its nodes. `None` where an end cannot
    /// be solved, a pair's axis is a cycle, or the work is cancelled.
    fn stretches(&self, stage: &curve::watch::Stage) -> Option<Vec<Found>> {
        let mut found: Vec<Found> = Vec::new();
        let n = self.sites.len();
        for i in 0..n {
            if !stage.go_on(0) {
                return None; // (the caller answers "cancelled")
            }
            for j in i + 1..n {
                let (a, b) = (self.sites[i], self.sites[j]);
                let pair = [a.min(b), a.max(b)];
                let Some(param) = self.param(pair)? else {
                    continue;
                };
                for span in self.sampled_runs(pair, param)? {
                    found.push(self.solve_ends(pair, param, span)?);
                }
            }
        }
        let mut next = 0;
        // (Each stretch found adds two ends to look round; a pair is followed from a node
        // once.)
        let mut followed: HashSet<([TrueSite; 2], [u64; 2])> = HashSet::new();
        while next < found.len() * 2 {
            let (k, end) = (next / 2, next % 2);
            next += 1;
            if !stage.go_on(0) {
                return None;
            }
            let node = found[k].ends[end];
            if node.radius == 0.0 {
                continue; // (a convex corner: its one edge is the stretch itself)
            }
            let about = found[k].about[end].clone();
            for (i, &a) in about.iter().enumerate() {
                for &b in &about[i + 1..] {
                    let pair = [a.min(b), a.max(b)];
                    let merge = SAME_SEED_NODE * self.model.sites.size;
                    let ends_here = |f: &Found| {
                        f.pair == pair && f.ends.iter().any(|e| (e.xy - node.xy).norm() <= merge)
                    };
                    if found.iter().any(ends_here)
                        || !followed.insert((pair, node.xy.arr().map(f64::to_bits)))
                    {
                        continue;
                    }
                    let Some(param) = self.param(pair)? else {
                        continue;
                    };
                    for span in self.runs_from(pair, param, node.xy)? {
                        let new = self.solve_ends(pair, param, span)?;
                        // (Found already: its span overlaps one of the pair's, or, round a
                        // whole circle where spans are taken from anywhere, its ends are
                        // another's.)
                        let at_an_end =
                            |x: V2, g: &Found| g.ends.iter().any(|e| (e.xy - x).norm() <= merge);
                        let again = |g: &Found| {
                            g.pair == pair
                                && if param.whole {
                                    new.ends.iter().all(|e| at_an_end(e.xy, g))
                                } else {
                                    g.span[0] < new.span[1] && new.span[0] < g.span[1]
                                }
                        };
                        if !found.iter().any(again) {
                            found.push(new);
                        }
                    }
                }
            }
            if found.len() > MAX_STRETCHES {
                return None;
            }
        }
        Some(found)
    }

    /// How the bisector of `pair` is followed; `Ok(None)` where the sites share no axis (a
    /// smooth joint's two segments, a segment and its own end).
    fn param(&self, pair: [TrueSite; 2]) -> Option<Option<Param>> {
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

    /// The spans of the feet where the bisector's disks are empty, found on samples and
    /// their ends by bisection; `None` round a whole circle with every sample kept (an axis
    /// with no node).
    fn sampled_runs(&self, pair: [TrueSite; 2], param: Param) -> Option<Vec<[Bound; 2]>> {
        let kept = |t: f64| self.point(pair, param, t).is_some();
        let samples: Vec<bool> = (0..=SAMPLES)
            .map(|k| kept(k as f64 / SAMPLES as f64))
            .collect();
        // (Round a whole circle the samples start from one not kept: a run of kept ones
        // then never wraps past the last.)
        let offset = if param.whole {
            samples[..SAMPLES].iter().position(|&k| !k)?
        } else {
            0
        };
        let at = |k: usize| {
            let k = k + offset;
            let kept = if param.whole {
                samples[k % SAMPLES]
            } else {
                samples[k]
            };
            (k as f64 / SAMPLES as f64, kept)
        };
        let mut out = Vec::new();
        let mut k = 0;
        while k <= SAMPLES {
            if !at(k).1 {
                k += 1;
                continue;
            }
            let first = k;
            while k < SAMPLES && at(k + 1).1 {
                k += 1;
            }
            let end = |inside: usize, outside: Option<usize>| match outside {
                Some(o) => self.edge_of_kept(pair, param, at(inside).0, at(o).0),
                None => Bound {
                    kept: at(inside).0,
                    beyond: None,
                },
            };
            let before = (first > 0).then(|| first - 1);
            let after = (k < SAMPLES).then_some(k + 1);
            out.push([end(first, before), end(k, after)]);
            k += 1;
        }
        Some(out)
    }

    /// The spans of kept feet that start at the node at `x` (on either side of its foot),
    /// each followed by steps that double until one is not kept, and its far end then
    /// placed by bisection.
    fn runs_from(&self, pair: [TrueSite; 2], param: Param, x: V2) -> Option<Vec<[Bound; 2]>> {
        let kept = |t: f64| self.point(pair, param, t).is_some();
        let t0 = param.feet.param_of(x);
        let (lo, hi) = if param.whole {
            (t0 - 1.0, t0 + 1.0)
        } else {
            // (A node whose foot is off the feet's span is no end of this pair's stretches.)
            if !(-FOLLOW_STEP..=1.0 + FOLLOW_STEP).contains(&t0) {
                return Some(Vec::new());
            }
            (0.0, 1.0)
        };
        let mut out = Vec::new();
        for dir in [-1.0, 1.0] {
            let mut step = FOLLOW_STEP;
            let mut inside = (t0 + dir * step).clamp(lo, hi);
            if inside == t0 || !kept(inside) {
                continue;
            }
            let near = if kept(t0) {
                // (The node's own foot: the end is behind it, by rounding, unless the pair's
                // stretch runs on through: then the node is none of its ends.)
                let behind = t0 - dir * FOLLOW_STEP;
                if kept(behind) {
                    continue;
                }
                self.edge_of_kept(pair, param, t0, behind)
            } else {
                self.edge_of_kept(pair, param, inside, t0)
            };
            let mut far = None;
            for _ in 0..FOLLOW_DOUBLINGS {
                step *= 2.0;
                let t = (t0 + dir * step).clamp(lo, hi);
                if !kept(t) {
                    far = Some(self.edge_of_kept(pair, param, inside, t));
                    break;
                }
                inside = t;
                if t == lo || t == hi {
                    // (Round a whole circle and back: an axis with no node.)
                    if param.whole {
                        return None;
                    }
                    far = Some(Bound {
                        kept: t,
                        beyond: None,
                    });
                    break;
                }
            }
            let far = far?;
            out.push(if dir < 0.0 { [far, near] } else { [near, far] });
        }
        Some(out)
    }

    /// The kept parameter nearest `outside` between `inside` (kept) and `outside` (not), by
    /// bisection, and the one not kept beyond it.
    fn edge_of_kept(&self, pair: [TrueSite; 2], param: Param, inside: f64, outside: f64) -> Bound {
        let (mut t_in, mut t_out) = (inside, outside);
        for _ in 0..END_HALVINGS {
            let t = 0.5 * (t_in + t_out);
            if self.point(pair, param, t).is_some() {
                t_in = t;
            } else {
                t_out = t;
            }
        }
        Bound {
            kept: t_in,
            beyond: Some(t_out),
        }
    }

    /// The stretch of `pair` over `span`, its ends solved.
    fn solve_ends(&self, pair: [TrueSite; 2], param: Param, span: [Bound; 2]) -> Option<Found> {
        let (p, about_p) = self.node(pair, param, span[0])?;
        let (q, about_q) = self.node(pair, param, span[1])?;
        Some(Found {
            pair,
            span: span.map(|b| b.kept),
            ends: [p, q],
            about: [about_p, about_q],
        })
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

    /// The point of the bisector of `pair` whose foot on the parametrising site is at
    /// parameter `t`, and its radius, where its disk is empty: its foot on `other` falls on that
    /// site, and every other site is at least as far.
    fn point(&self, pair: [TrueSite; 2], param: Param, t: f64) -> Option<(V2, f64)> {
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
    fn falls_on(&self, s: TrueSite, x: V2) -> bool {
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
    fn touches(&self, s: TrueSite, x: V2, radius: f64) -> bool {
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

    /// The node at the end `bound` of a stretch of the bisector of `pair`, and the true
    /// sites about it: solved on the pair's equation and the one that ends the stretch there
    /// ([`Pairwise::ending`]); at a convex corner where the pair's segments meet, the corner.
    fn node(
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
