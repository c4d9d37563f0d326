//! The search for every pair's stretches with empty disks: each pair's feet sampled, the
//! ends of their runs placed by bisection, and each pair whose edge meets a node found
//! followed from it.

use super::{Bound, Found, Pairwise, Param, END_HALVINGS};
use crate::lines_and_arcs::SAME_SEED_NODE;
use crate::true_sites::TrueSite;
use curve::V2;
use std::collections::HashSet;

/// Feet sampled along the parametrising site of each pair (at equal steps of its
/// parameter) to find where the pair's bisector has empty disks.
const SAMPLES: usize = 32;

/// The first step (a share of the parametrising site's span) from a node along a pair's
/// feet when a stretch is followed from it; the steps then double. A stretch shorter than
/// this is not found, and the coverage of the feet refuses the axis.
const FOLLOW_STEP: f64 = 1e-9;

/// Most doublings of the step while a stretch is followed: 2³⁰ of the first step, the span.
const FOLLOW_DOUBLINGS: usize = 30;

/// Most stretches (a bound on the search from nodes): the axis of n sites has O(n) edges;
/// beyond this many the region is no small one.
const MAX_STRETCHES: usize = 1 << 12;

impl Pairwise<'_, '_, '_> {
    /// Every stretch of every pair's bisector with empty disks. Each pair's feet are
    /// sampled; then every node found names the pairs whose edges meet there (each two of
    /// its sites), and a pair with no stretch ending there is followed from it: a stretch
    /// shorter than the samples' spacing is found from its nodes. `None` where an end cannot
    /// be solved, a pair's axis is a cycle, or the work is cancelled.
    pub(super) fn stretches(&self, stage: &curve::watch::Stage) -> Option<Vec<Found>> {
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
}
