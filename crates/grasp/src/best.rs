//! A region's most robust grasp: the pair whose chord lies farthest (in angle) inside both
//! friction cones, that is the least friction that holds it.

use crate::assemble::RawRegion;
use crate::model::Model;
use crate::polyline::bounds;
use crate::quality::slip_angle;
use crate::region_set::{deepest, depth, held_inside, holds, in_triangle};

/// Samples across each part's box when no antipodal pair lies in the region.
const SAMPLES_ACROSS: usize = 16;

/// Samples along a corner line's stretch.
const SAMPLES_ALONG: usize = 64;

/// Steps of the compass search from the best sample.
const SEARCH_STEPS: usize = 400;

/// The compass search stops at steps this small (in the profile's parameter).
const FINEST_STEP: f64 = 1e-12;

/// A slip angle this small is an antipodal pair's (found to rounding).
pub(crate) const ANTIPODAL_ANGLE: f64 = 1e-9;

/// The most robust pair of `region`, and whether it is proven so (an antipodal pair of the
/// region: its slip angle is zero). `seeds`: the antipodal pairs and the middles of the
/// families, in the profile's parameter; `alpha`: the friction angle.
pub(crate) fn most_robust(
    model: &Model<'_>,
    region: &RawRegion,
    seeds: &[[f64; 2]],
    alpha: f64,
    inside_by: f64,
) -> ([f64; 2], bool) {
    let n = model.n();
    let angle = |p: [f64; 2]| slip_angle(model, p[0], p[1]);
    // The best pair known exactly (antipodal, on a corner line, single) and the best pair
    // inside a part, which a search from it may improve: both are kept, the search run, and
    // the better taken (a corner line's best may lie beside a part's better one).
    let mut exact: Option<([f64; 2], f64)> = None;
    let mut inside: Option<([f64; 2], f64)> = None;
    let consider = |p: [f64; 2], best: &mut Option<([f64; 2], f64)>| {
        let a = angle(p);
        if best.is_none_or(|(_, b)| a < b) {
            *best = Some((p, a));
        }
    };
    for &p in seeds {
        if holds(region, n, p[0], p[1]) {
            consider(p, &mut exact);
        }
    }
    if let Some((p, a)) = exact {
        if a <= ANTIPODAL_ANGLE {
            return (p, true);
        }
    }
    for part in &region.parts {
        let (lo, hi) = bounds(part);
        for i in 0..SAMPLES_ACROSS {
            for j in 0..SAMPLES_ACROSS {
                let across =
                    |k: usize, d: usize| (k as f64 + 0.5) / SAMPLES_ACROSS as f64 * (hi[d] - lo[d]);
                let p = [lo[0] + across(i, 0), lo[1] + across(j, 1)];
                if holds(region, n, p[0], p[1]) {
                    consider(p, &mut inside);
                }
            }
        }
    }
    if inside.is_none() {
        // Parts too thin for the grid (a sliver, as the pinch grasps of a corner just
        // sharper than twice the friction angle): the deepest point found inside them (a
        // sliver's pairs all need about the same friction; its edges are only within the
        // chord tolerance of the exact boundary).
        if let Some(&(p, _)) = deepest(region, 1).first() {
            consider(p, &mut inside);
        }
    }
    if inside.is_none() {
        // Thinner still, a sliver within rounding of its edges: the search starts on them.
        for part in &region.parts {
            for w in part.windows(2) {
                for k in 0..=SAMPLES_ALONG {
                    consider(
                        lerp(w[0], w[1], k as f64 / SAMPLES_ALONG as f64),
                        &mut inside,
                    );
                }
            }
        }
    }
    // Each line's best sample; then, from the best line on, a search along the line between
    // its sample's neighbours (the least friction may fall toward an end, as toward a reflex
    // corner's line) while a line's sample beats the best found (a search gains less than
    // the samples' spacing tells apart).
    let mut line_samples: Vec<(&[[f64; 2]; 2], usize, f64)> = region
        .lines
        .iter()
        .filter_map(|l| {
            (0..=SAMPLES_ALONG)
                .map(|k| {
                    (
                        l,
                        k,
                        angle(lerp(l[0], l[1], k as f64 / SAMPLES_ALONG as f64)),
                    )
                })
                .min_by(|a, b| a.2.total_cmp(&b.2))
        })
        .collect();
    line_samples.sort_by(|a, b| a.2.total_cmp(&b.2));
    for (l, k, sampled) in line_samples {
        if exact.is_some_and(|(_, b)| b < sampled) {
            break;
        }
        let at = |x: f64| lerp(l[0], l[1], x);
        consider(at(along(&|x| angle(at(x)), k)), &mut exact);
    }
    for &p in &region.points {
        consider(p, &mut exact);
    }
    // A part's vertex at a cell's corner is a pair of joints the region reaches, exactly
    // (the cells' edges are the joints' lines): where it is force closure, a candidate the
    // search from inside, kept a chord from the edges, cannot reach.
    let joint = |x: f64| x == x.round();
    for &p in region.parts.iter().flatten() {
        if joint(p[0]) && joint(p[1]) && angle(p) <= alpha {
            consider(p, &mut exact);
        }
    }
    let inside = inside.map(|(x, _)| {
        let (x, ax) = descend(model, region, x, inside_by);
        if ax <= alpha {
            return (x, ax);
        }
        // Not force closure: the region is thinner there than its polylines resolve (a
        // sliver within rounding of its edges, or one a chord passes outside of where it
        // bows). Its pairs lie within the chord tolerance of the polylines, not inside them:
        // the search roams that far round them.
        search(model, region, x, &|y| {
            holds(region, n, y[0], y[1]) || depth(region, y) <= inside_by
        })
    });
    let best = match (exact, inside) {
        (Some(e), Some(i)) => Some(if i.1 < e.1 { i } else { e }),
        (e, i) => e.or(i),
    };
    let Some((x, ax)) = best else {
        return (region.parts.first().map_or([0.0; 2], |p| p[0]), false);
    };
    (in_triangle(n, x[0], x[1]), ax <= ANTIPODAL_ANGLE)
}

/// The share of the way along a line (sampled at [`SAMPLES_ALONG`] steps) where `angle` is
/// least, by a compass search from the sample `k` in steps halved from one sample's down to
/// [`FINEST_STEP`], staying on the line.
fn along(angle: &dyn Fn(f64) -> f64, k: usize) -> f64 {
    let mut x = k as f64 / SAMPLES_ALONG as f64;
    let mut ax = angle(x);
    let mut step = 1.0 / SAMPLES_ALONG as f64;
    for _ in 0..SEARCH_STEPS {
        if step <= FINEST_STEP {
            break;
        }
        let better = [x - step, x + step]
            .into_iter()
            .filter(|y| (0.0..=1.0).contains(y))
            .map(|y| (y, angle(y)))
            .find(|&(_, ay)| ay < ax);
        match better {
            Some((y, ay)) => (x, ax) = (y, ay),
            None => step *= 0.5,
        }
    }
    x
}

/// The point a share `x` of the way from `a` to `b`.
fn lerp(a: [f64; 2], b: [f64; 2], x: f64) -> [f64; 2] {
    [a[0] + x * (b[0] - a[0]), a[1] + x * (b[1] - a[1])]
}

/// A compass search for the pair of least slip angle from `start` (a pair of the region),
/// staying in the region a chord (`inside_by`) inside its polylines: the pair found and its
/// slip angle. (Where the least friction falls toward the region's edge, as on a width
/// limit, the best grasp is the pair a chord inside, whichever side of the exact edge its
/// polyline passes.)
pub(crate) fn descend(
    model: &Model<'_>,
    region: &RawRegion,
    start: [f64; 2],
    inside_by: f64,
) -> ([f64; 2], f64) {
    let n = model.n();
    search(model, region, start, &|y| {
        held_inside(region, n, y, inside_by)
    })
}

/// A compass search for the pair of least slip angle from `start`, by steps from a
/// sixteenth of the region's largest part's box down, moving only to pairs `allowed`: the
/// pair found and its slip angle.
fn search(
    model: &Model<'_>,
    region: &RawRegion,
    start: [f64; 2],
    allowed: &dyn Fn([f64; 2]) -> bool,
) -> ([f64; 2], f64) {
    let angle = |p: [f64; 2]| slip_angle(model, p[0], p[1]);
    let (mut x, mut ax) = (start, angle(start));
    let mut step = region
        .parts
        .iter()
        .map(|part| {
            let (lo, hi) = bounds(part);
            (hi[0] - lo[0]).max(hi[1] - lo[1])
        })
        .fold(0.0, f64::max)
        / SAMPLES_ACROSS as f64;
    for _ in 0..SEARCH_STEPS {
        if step <= FINEST_STEP {
            break;
        }
        let mut moved = false;
        for (ds, dt) in [
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, 1.0),
            (0.0, -1.0),
            (1.0, 1.0),
            (-1.0, -1.0),
            (1.0, -1.0),
            (-1.0, 1.0),
        ] {
            let y = [x[0] + ds * step, x[1] + dt * step];
            let ay = angle(y);
            if ay < ax && allowed(y) {
                (x, ax) = (y, ay);
                moved = true;
                break;
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    (x, ax)
}
