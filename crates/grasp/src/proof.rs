//! A region's least friction, proven: the set traced again at a friction just below its best
//! grasp's holds no pair of the region. The sets grow with the friction, so every pair of the
//! region then needs at least that much, and the best grasp is the most robust to within that
//! gap.

use crate::assemble::{regions, RawRegion};
use crate::cells::{cells_where, trace};
use crate::corners::corner_lines;
use crate::error::Result;
use crate::model::Model;
use crate::near::NearContacts;
use crate::options::GraspOptions;
use crate::polyline::bounds;
use crate::quality::{force_closure, min_friction};
use crate::region_set::{deepest, depth, holds};
use numeric::certificate::{Doubt, Doubts};
use std::collections::BTreeSet;

/// The share of its friction below a best grasp's at which the set is traced again: the best
/// grasp is proven the most robust of its region to this share.
pub(crate) const BEST_GAP: f64 = 1e-4;

/// Samples along a corner line of the lower set, each tested against the region.
const LINE_SAMPLES: usize = 16;

/// What the set at a lower friction says of a region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Below {
    /// No pair of the region is force closure at the lower friction.
    None,
    /// This pair of the region is (a point deep inside a region of the lower set, on a
    /// corner line of it, or a single pair of it).
    Beaten([f64; 2]),
    /// Not proven either way (the lower set left unresolved, or a part of it too thin to
    /// tell).
    Unknown,
}

/// Whether any pair of `region` (a region of the set at `opts.friction`, whose best grasp
/// needs the friction `least`) is force closure at a friction [`BEST_GAP`] below: the set
/// there is traced on the cells the region's box meets, and its regions, corner lines and
/// points are tested against `region`.
pub(crate) fn none_below(
    model: &Model<'_>,
    opts: &GraspOptions,
    widths: [Option<f64>; 2],
    region: &RawRegion,
    least: f64,
    chord: f64,
) -> Result<Below> {
    let friction = least * (1.0 - BEST_GAP);
    let lower = GraspOptions { friction, ..*opts };
    let wanted = cells_met(model.n(), region, chord);
    let near = NearContacts::new(model, friction);
    let mut traced = Vec::with_capacity(wanted.len());
    for cell in cells_where(model, &lower, widths, |i, j| wanted.contains(&(i, j)))? {
        let t = trace(model, &cell, &lower, &near)?;
        if !t.complete || t.unresolved {
            return Ok(Below::Unknown);
        }
        traced.push(((cell.i, cell.j), t));
    }
    let mut doubts = Doubts::none();
    let lines = corner_lines(model, friction, widths, &mut doubts)?;
    if !doubts.is_empty() {
        return Ok(Below::Unknown);
    }
    let alpha = friction.atan();
    let holds_lower = |p: [f64; 2]| force_closure(model, alpha, widths, p);
    let found = regions(model, &traced, &lines, chord, &holds_lower);
    let n = model.n();
    let (lo, hi) = region_box(region, chord);
    let near_region = |(a, b): ([f64; 2], [f64; 2])| {
        a[0] <= hi[0] && b[0] >= lo[0] && a[1] <= hi[1] && b[1] >= lo[1]
    };
    for q in &found {
        if q.doubts
            .iter()
            .any(|d| *d == Doubt::GraspBoundaryUnresolved)
        {
            return Ok(Below::Unknown);
        }
        for part in &q.parts {
            if !near_region(bounds(part)) {
                continue;
            }
            // The part's vertices lie on the lower set's boundary (to rounding): one clearly
            // outside the region puts the whole part outside (the part lies in one region
            // of the higher set); one inside it is a pair of the region needing less
            // friction than the best grasp, where it does.
            // (A pair within a chord of the region's edge is not taken: best grasps keep a
            // chord inside, as on a width limit, where the least friction lies on the edge.)
            let inside = |p: [f64; 2]| holds(region, n, p[0], p[1]) && depth(region, p) >= chord;
            let mut outside = false;
            for &v in part {
                if holds(region, n, v[0], v[1]) {
                    if inside(v) && min_friction(model, v[0], v[1]) < least {
                        // (The middle of the part, where the part is wide enough to have
                        // one inside the region, is nearer the least friction.)
                        let single = RawRegion {
                            parts: vec![part.clone()],
                            holes: q.holes.clone(),
                            ..RawRegion::default()
                        };
                        let middle = deepest(&single, 1)
                            .first()
                            .map(|&(p, _)| p)
                            .filter(|&p| inside(p) && min_friction(model, p[0], p[1]) < least);
                        return Ok(Below::Beaten(middle.unwrap_or(v)));
                    }
                } else if depth(region, v) > 2.0 * chord {
                    outside = true;
                    break;
                }
            }
            if !outside {
                return Ok(Below::Unknown);
            }
        }
        // A finger at a corner, or a single pair, that holds at the lower friction.
        let on_line = q.lines.iter().find_map(|l| {
            (0..=LINE_SAMPLES).find_map(|k| {
                let x = k as f64 / LINE_SAMPLES as f64;
                let p = [
                    l[0][0] + x * (l[1][0] - l[0][0]),
                    l[0][1] + x * (l[1][1] - l[0][1]),
                ];
                holds(region, n, p[0], p[1]).then_some(p)
            })
        });
        let at_point = || {
            q.points
                .iter()
                .copied()
                .find(|p| holds(region, n, p[0], p[1]))
        };
        if let Some(p) = on_line.or_else(at_point) {
            // (Its friction at most the lower one's but for rounding.)
            return Ok(if min_friction(model, p[0], p[1]) < least {
                Below::Beaten(p)
            } else {
                Below::Unknown
            });
        }
    }
    Ok(Below::None)
}

/// The box of a region's parts, corner lines and points, grown by `grow`.
fn region_box(region: &RawRegion, grow: f64) -> ([f64; 2], [f64; 2]) {
    let pts = region
        .parts
        .iter()
        .flatten()
        .chain(region.lines.iter().flatten())
        .chain(&region.points);
    let (lo, hi) = pts.fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    );
    ([lo[0] - grow, lo[1] - grow], [hi[0] + grow, hi[1] + grow])
}

/// The cells `(i, j)`, `i ≤ j`, that the region's box meets.
fn cells_met(n: usize, region: &RawRegion, grow: f64) -> BTreeSet<(usize, usize)> {
    let (lo, hi) = region_box(region, grow);
    let index = |x: f64| (x.floor().max(0.0) as usize).min(n - 1);
    let mut out = BTreeSet::new();
    for i in index(lo[0])..=index(hi[0]) {
        for j in index(lo[1])..=index(hi[1]) {
            out.insert((i.min(j), i.max(j)));
        }
    }
    out
}
