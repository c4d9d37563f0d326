//! A region's most robust grasp: the pair whose chord lies farthest (in angle) inside both
//! friction cones, that is the least friction that holds it.

use crate::assemble::RawRegion;
use crate::model::Model;
use crate::polyline::bounds;
use crate::quality::{contact_angles, slip_angle};
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
    let first_step = region
        .parts
        .iter()
        .map(|part| {
            let (lo, hi) = bounds(part);
            (hi[0] - lo[0]).max(hi[1] - lo[1])
        })
        .fold(0.0, f64::max)
        / SAMPLES_ACROSS as f64;
    compass(
        &|p| contact_angles(model, p[0], p[1]),
        start,
        first_step,
        allowed,
    )
}

/// A compass search for the least of the larger of the two `angles` from `start`, by steps
/// from `first_step` halved down to [`FINEST_STEP`], moving only to points `allowed`, and
/// along the ridge where the two are equal when no step of the compass descends: the point
/// found and its value.
fn compass(
    angles: &dyn Fn([f64; 2]) -> [f64; 2],
    start: [f64; 2],
    first_step: f64,
    allowed: &dyn Fn([f64; 2]) -> bool,
) -> ([f64; 2], f64) {
    let larger = |a: [f64; 2]| a[0].max(a[1]);
    let (mut x, mut at_x) = (start, angles(start));
    let mut step = first_step;
    for _ in 0..SEARCH_STEPS {
        if step <= FINEST_STEP {
            break;
        }
        // The angles a step along each axis either way (`+s, −s, +t, −t`), for the ridge.
        let mut axes = [[0.0; 2]; 4];
        let mut moved = false;
        for (k, (ds, dt)) in [
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, 1.0),
            (0.0, -1.0),
            (1.0, 1.0),
            (-1.0, -1.0),
            (1.0, -1.0),
            (-1.0, 1.0),
        ]
        .into_iter()
        .enumerate()
        {
            let y = [x[0] + ds * step, x[1] + dt * step];
            let at_y = angles(y);
            if let Some(a) = axes.get_mut(k) {
                *a = at_y;
            }
            if larger(at_y) < larger(at_x) && allowed(y) {
                (x, at_x) = (y, at_y);
                moved = true;
                break;
            }
        }
        if moved {
            continue;
        }
        // Stalled: where the two angles are equal (the larger one's kink), the descent may
        // run along their ridge between the compass's directions.
        let on_ridge = along_ridge(angles, x, at_x, axes, step).and_then(|ys| {
            ys.into_iter()
                .map(|y| (y, angles(y)))
                .find(|&(y, at_y)| larger(at_y) < larger(at_x) && allowed(y))
        });
        match on_ridge {
            Some(y) => (x, at_x) = y,
            None => step *= 0.5,
        }
    }
    (x, larger(at_x))
}

/// Differences of the two angles (radians) across a step below this are their rounding (a
/// few units in the last place of angles up to π), not a ridge.
const RIDGE_ROUNDING: f64 = 1e-12;

/// The share of a step across which the ridge's direction is measured (by central
/// differences): small enough to see the ridge's bend at that step (an angle's kink at a
/// corner within it), large enough to keep the angles' rounding out of the difference.
const RIDGE_DIFFERENCE: f64 = 1e-2;

/// Where the ridge on which the two `angles` are equal passes within `step` of `x` (whose
/// angles are `at_x`, and `axes` those a step along each axis either way, `+s, −s, +t, −t`):
/// the points a step along it the way the angles fall, then the other way, each moved back
/// onto it (one Newton step across it). Along the ridge the larger angle may descend where a
/// step across it climbs (the other angle rising faster than the ridge falls), so that no
/// step of the compass improves on `x`: the best grasp beside a reflex corner, on a narrow
/// valley running between the directions.
fn along_ridge<'a>(
    angles: &'a dyn Fn([f64; 2]) -> [f64; 2],
    x: [f64; 2],
    at_x: [f64; 2],
    axes: [[f64; 2]; 4],
    step: f64,
) -> Option<impl Iterator<Item = [f64; 2]> + 'a> {
    let gap = |a: [f64; 2]| a[0] - a[1];
    // Central differences of the angles' gap and of their mean over `h` either way of `x`.
    let across =
        |at: [[f64; 2]; 4], f: &dyn Fn([f64; 2]) -> f64| [f(at[0]) - f(at[1]), f(at[2]) - f(at[3])];
    // Whether the ridge passes within the step, by the compass's own samples; then its
    // direction from samples nearer.
    let coarse = across(axes, &gap);
    if gap(at_x).abs() > 0.5 * coarse[0].hypot(coarse[1]) {
        return None;
    }
    let h = RIDGE_DIFFERENCE * step;
    let near =
        [[h, 0.0], [-h, 0.0], [0.0, h], [0.0, -h]].map(|d| angles([x[0] + d[0], x[1] + d[1]]));
    let differences = across(near, &gap);
    // (Where the angles stay equal, as on a circle's diameters, the differences are rounding
    // and their direction is noise: no ridge.)
    let spread = differences[0].hypot(differences[1]);
    if !(spread > RIDGE_ROUNDING && spread.is_finite()) {
        return None;
    }
    let slope = differences.map(|d| d / (2.0 * h));
    let norm = 0.5 * spread / h;
    // The ridge's direction, the way the mean of the angles (both, on it) falls.
    let mut along = [-slope[1] / norm, slope[0] / norm];
    let mean = across(near, &|a| 0.5 * (a[0] + a[1]));
    if along[0] * mean[0] + along[1] * mean[1] > 0.0 {
        along = [-along[0], -along[1]];
    }
    // (Lazily: the other way only where the first does not descend.)
    let onto = move |sign: f64| {
        let y = [x[0] + sign * step * along[0], x[1] + sign * step * along[1]];
        let e = gap(angles(y)) / (norm * norm);
        [y[0] - e * slope[0], y[1] - e * slope[1]]
    };
    Some([1.0, -1.0].into_iter().map(onto))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Two planes meeting in a narrow valley along the direction `(cos θ, sin θ)` (their
    /// ridge), climbing across it `steep` times faster than it falls along it: the larger
    /// of the two has its least on the ridge's end at the square's edge, where `allowed`
    /// stops. The compass's eight directions miss the valley unless θ is one of theirs.
    fn valley(theta: f64, steep: f64) -> impl Fn([f64; 2]) -> [f64; 2] {
        let (c, s) = (theta.cos(), theta.sin());
        move |p: [f64; 2]| {
            let along = c * p[0] + s * p[1];
            let across = -s * p[0] + c * p[1];
            [-along + steep * across, -along - steep * across]
        }
    }

    proptest! {
        /// The search follows the valley to the disk's rim, on the ridge: the least of the
        /// larger angle within the unit disk (`−1`, at the ridge's end) to within the finest
        /// step's reach, from any start inside.
        #[test]
        fn the_compass_follows_a_narrow_valley_between_its_directions(
            theta in 0.0f64..std::f64::consts::TAU,
            steep in 10.0f64..1e4,
            start in (-0.5f64..0.5, -0.5f64..0.5),
        ) {
            let angles = valley(theta, steep);
            let in_disk = |p: [f64; 2]| p[0].hypot(p[1]) <= 1.0;
            let (x, least) = compass(&angles, [start.0, start.1], 0.25, &in_disk);
            prop_assert!(in_disk(x));
            prop_assert!(least < -1.0 + 1e-6, "{least} at {x:?}, θ = {theta}, steep = {steep}");
        }
    }

    /// Without the ridge's steps the same search stalls in the valley (the test above can
    /// fail): a direction between the compass's, steep sides.
    #[test]
    fn the_compass_alone_stalls_in_a_valley_between_its_directions() {
        let angles = valley(0.3, 1e3);
        let angle = |p: [f64; 2]| {
            let [a, b] = angles(p);
            a.max(b)
        };
        let start = [0.0, 0.0];
        // Every compass step from the start climbs, at every step size.
        let mut step = 0.25;
        while step > FINEST_STEP {
            for d in [[1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, -1.0]] {
                for sign in [1.0, -1.0] {
                    let y = [sign * d[0] * step, sign * d[1] * step];
                    assert!(angle(y) > angle(start), "{y:?}");
                }
            }
            step *= 0.5;
        }
        let in_disk = |p: [f64; 2]| p[0].hypot(p[1]) <= 1.0;
        let (_, least) = compass(&angles, start, 0.25, &in_disk);
        assert!(least < -1.0 + 1e-6, "{least}");
    }
}
