//! A region's most robust grasp: the pair whose chord lies farthest (in angle) inside both
//! friction cones, that is the least friction that holds it.

use crate::assemble::RawRegion;
use crate::cones::Form;
use crate::quality::slip_angle;
use crate::region_set::holds;

/// Samples across each part's box when no antipodal pair lies in the region.
const SAMPLES_ACROSS: usize = 16;

/// Steps of the compass search from the best sample.
const SEARCH_STEPS: usize = 400;

/// The compass search stops at steps this small, relative to the domain.
const FINEST_STEP: f64 = 1e-12;

/// A slip angle this small is an antipodal pair's (found to rounding).
pub(crate) const ANTIPODAL_ANGLE: f64 = 1e-9;

/// The most robust pair of `region`, and whether it is proven so (an antipodal pair of the
/// region: its slip angle is zero). `seeds`: the antipodal pairs and the middles of the
/// families, in the form's parameter.
pub(crate) fn most_robust(form: &Form, region: &RawRegion, seeds: &[[f64; 2]]) -> ([f64; 2], bool) {
    let domain = form.domain();
    let angle = |p: [f64; 2]| slip_angle(form, p[0], p[1]);
    let mut best: Option<([f64; 2], f64)> = None;
    let consider = |p: [f64; 2], best: &mut Option<([f64; 2], f64)>| {
        let a = angle(p);
        if best.is_none_or(|(_, b)| a < b) {
            *best = Some((p, a));
        }
    };
    for &p in seeds {
        if holds(region, domain, p[0], p[1]) {
            consider(p, &mut best);
        }
    }
    if let Some((p, a)) = best {
        if a <= ANTIPODAL_ANGLE {
            return (p, true);
        }
    }
    for part in &region.parts {
        let (lo, hi) = bounds(part);
        for i in 0..SAMPLES_ACROSS {
            for j in 0..SAMPLES_ACROSS {
                let p = [
                    lo[0] + (i as f64 + 0.5) / SAMPLES_ACROSS as f64 * (hi[0] - lo[0]),
                    lo[1] + (j as f64 + 0.5) / SAMPLES_ACROSS as f64 * (hi[1] - lo[1]),
                ];
                if holds(region, domain, p[0], p[1]) {
                    consider(p, &mut best);
                }
            }
        }
        // A part too thin for the grid: its vertices.
        for &p in part {
            consider(p, &mut best);
        }
    }
    let Some((mut x, mut ax)) = best else {
        let p = region.parts[0][0];
        return (p, false);
    };
    let (lo, hi) = bounds(&region.parts[0]);
    let mut step = (hi[0] - lo[0]).max(hi[1] - lo[1]) / SAMPLES_ACROSS as f64;
    let finest = FINEST_STEP * (domain.1 - domain.0);
    for _ in 0..SEARCH_STEPS {
        if step <= finest {
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
            if ay < ax {
                (x, ax) = (y, ay);
                moved = true;
                break;
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    (x, ax <= ANTIPODAL_ANGLE)
}

/// The box of a polyline.
pub(crate) fn bounds(pts: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    pts.iter().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    )
}
