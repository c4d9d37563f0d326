//! The independent oracle on random regions: each boundary sampled densely, and the check of
//! an axis (inside and exterior) against it, with the per-thread counts that show a property
//! was not vacuous.

use crate::graph::components_and_cycles;
use crate::helpers::end_foot;
use crate::sampled_voronoi::sampled_medial_points;
use crate::traced::{axis, off_axis, traced_options, CHORD};
use curve::{ParamCurve, Profile, Region};
use medial::{medial_axis, MedialAxis, MedialOptions, NodeKind};
use numeric::certificate::Verdict;
use proptest::prelude::*;
use std::cell::Cell;
use std::f64::consts::PI;
use testkit::boundary_oracle::{off_polylines, winding, Oracle};

/// Every boundary of the region with its oracle.
pub(crate) struct Boundaries<'a> {
    profiles: Vec<&'a Profile>,
    oracles: Vec<Oracle<'a>>,
}

impl<'a> Boundaries<'a> {
    pub(crate) fn new(region: &'a Region) -> Self {
        let profiles: Vec<&Profile> = std::iter::once(region.outer())
            .chain(region.holes())
            .collect();
        let oracles = profiles.iter().map(|p| Oracle::new(p)).collect();
        Self { profiles, oracles }
    }

    /// The distance to the boundary, and the nearest point.
    pub(crate) fn nearest(&self, x: [f64; 2]) -> (f64, [f64; 2]) {
        let mut best = (f64::INFINITY, [0.0; 2]);
        for (p, o) in self.profiles.iter().zip(&self.oracles) {
            let (d, u) = o.nearest(x);
            if d < best.0 {
                best = (d, p.jet(u).p.arr());
            }
        }
        best
    }

    /// How many distinct boundary points (`apart` from each other) are within `spread` of
    /// the least distance from `x`, and that distance (searched in the sample steps within
    /// `near` of it).
    pub(crate) fn contacts(&self, x: [f64; 2], spread: f64, apart: f64, near: f64) -> (usize, f64) {
        let minima: Vec<(f64, [f64; 2])> = self
            .profiles
            .iter()
            .zip(&self.oracles)
            .flat_map(|(p, o)| {
                o.minima_near(x, near)
                    .into_iter()
                    .map(|(d, u)| (d, p.jet(u).p.arr()))
            })
            .collect();
        let least = minima.iter().map(|m| m.0).fold(f64::INFINITY, f64::min);
        let mut points: Vec<[f64; 2]> = Vec::new();
        for (d, q) in minima {
            if d <= least + spread
                && points
                    .iter()
                    .all(|p| (p[0] - q[0]).hypot(p[1] - q[1]) > apart)
            {
                points.push(q);
            }
        }
        (points.len(), least)
    }

    pub(crate) fn inside(&self, x: [f64; 2]) -> bool {
        let w = |o: &Oracle<'_>| winding(&o.pts, x) != 0;
        w(&self.oracles[0]) && !self.oracles[1..].iter().any(w)
    }
}

// Counts per test thread (proptest runs a property's cases on its caller's thread), so that
// each property runs as a test of its own, in parallel, and is checked for being vacuous.
thread_local! {
    pub(crate) static MEDIAL_POINTS: Cell<usize> = const { Cell::new(0) };
    pub(crate) static WITH_HOLES: Cell<usize> = const { Cell::new(0) };
    pub(crate) static CERTIFIED: Cell<usize> = const { Cell::new(0) };
    pub(crate) static NEAR_CUSPS: Cell<usize> = const { Cell::new(0) };
    pub(crate) static CHECKED: Cell<usize> = const { Cell::new(0) };
}

/// Adds `by` to this thread's `counter`, returning its value before.
pub(crate) fn bump(counter: &'static std::thread::LocalKey<Cell<usize>>, by: usize) -> usize {
    counter.with(|c| c.replace(c.get() + by))
}

/// How near a corner's turn comes to a half turn (a cusp) before the axis beside it may be
/// wrong, if it says it is not certified.
pub(crate) const NEAR_CUSP: f64 = 1e-2;

/// Whether a corner of the region turns within `NEAR_CUSP` of a half turn.
pub(crate) fn near_cusp(b: &Boundaries<'_>) -> bool {
    b.profiles
        .iter()
        .any(|p| p.corners().any(|j| j.turn.abs() > PI - NEAR_CUSP))
}

/// Whether the graph is one piece with `holes` independent cycles.
pub(crate) fn shaped_like_the_region(a: &MedialAxis, holes: usize) -> bool {
    components_and_cycles(a) == (1, holes)
}

/// The contract's size: max(width, height) of the region's bounding box (of its points).
pub(crate) fn size_of(region: &Region) -> f64 {
    region.size()
}

/// Every this many random regions, the axis is also fitted (`fit`) and the oracle's points
/// checked against the fitted curves; and another one in as many, the exterior axis is
/// checked.
pub(crate) const FIT_EVERY: usize = 4;

/// The fitted curves of an axis, sampled: 32 points per step of the edge's polyline.
pub(crate) fn fitted_samples(a: &MedialAxis) -> Vec<Vec<[f64; 2]>> {
    a.edges
        .iter()
        .map(|e| {
            let f = e.bspline.as_ref().unwrap();
            let n = 32 * e.xy.len();
            (0..=n).map(|k| f.eval(k as f64 / n as f64).0).collect()
        })
        .collect()
}

/// The exterior axis of a random region: every vertex outside the region (to the slack of
/// the boundary's own points) and in the clip box, at its radius from the boundary, attained
/// at both feet; every leaf at the box is on its edge.
pub(crate) fn check_exterior(region: &Region, b: &Boundaries<'_>) -> Result<(), TestCaseError> {
    let opts = MedialOptions {
        exterior: true,
        ..traced_options()
    };
    let a = medial_axis(region, &opts).unwrap();
    prop_assert!(a.complete);
    let size = size_of(region);
    let [lo_x, lo_y, hi_x, hi_y] = region.bounding_box();
    let clip = [
        lo_x - 0.5 * size,
        lo_y - 0.5 * size,
        hi_x + 0.5 * size,
        hi_y + 0.5 * size,
    ];
    let slack = 1e-9 * size;
    for e in &a.edges {
        for (k, (&x, &r)) in e.xy.iter().zip(&e.radius).enumerate() {
            let (d, _) = b.nearest(x);
            testkit::prop_assert_near!(d, r, slack, "exterior vertex {x:?}: radius {r}, distance {d}, vertex {k} of {}, nodes {:?} {:?}, feet {:?} on {:?}", e.xy.len(), a.nodes[e.from], a.nodes[e.to], e.feet[k], e.boundary[k]);
            // (Beside a near-cusp the needle's crack is narrower than the oracle's polygon
            // resolves.)
            prop_assert!(
                r <= slack || !b.inside(x) || near_cusp(b),
                "exterior vertex {x:?} inside the region"
            );
            prop_assert!(
                x[0] >= clip[0] - slack
                    && x[0] <= clip[2] + slack
                    && x[1] >= clip[1] - slack
                    && x[1] <= clip[3] + slack,
                "exterior vertex {x:?} outside the clip box {clip:?}"
            );
            for s in 0..2 {
                let f = b.profiles[e.boundary[k][s]].jet(e.feet[k][s]).p.arr();
                let to_foot = (x[0] - f[0]).hypot(x[1] - f[1]);
                testkit::prop_assert_near!(to_foot, r, slack, "exterior vertex {x:?}: foot {s} at {to_foot}, radius {r}, vertex {k} of {}, nodes {:?} {:?}, feet {:?}", e.xy.len(), a.nodes[e.from], a.nodes[e.to], e.feet[k]);
            }
        }
    }
    for n in a.nodes.iter().filter(|n| n.kind == NodeKind::Clip) {
        let edge = (0..2)
            .any(|k| (n.xy[k] - clip[k]).abs() <= slack || (n.xy[k] - clip[k + 2]).abs() <= slack);
        prop_assert!(edge, "clip node {:?} not on the box {clip:?}", n.xy);
    }
    Ok(())
}

pub(crate) fn check(region: &Region) -> Result<(), TestCaseError> {
    let a = axis(region);
    prop_assert!(a.complete);
    let case = bump(&CHECKED, 1);
    if case % FIT_EVERY == 1 {
        check_exterior(region, &Boundaries::new(region))?;
    }
    let fitted = case.is_multiple_of(FIT_EVERY).then(|| {
        let opts = MedialOptions {
            fit: true,
            ..traced_options()
        };
        medial_axis(region, &opts).unwrap()
    });
    let fitted_curves = fitted.as_ref().map(fitted_samples);
    if let Some(f) = &fitted {
        // The fitted curves start and end at their edges' nodes, within their bound.
        for e in &f.edges {
            let s = e.bspline.as_ref().unwrap();
            prop_assert!(s.error <= 0.5 * CHORD * size_of(region));
            prop_assert_eq!(s.points[0], e.xy[0]);
            prop_assert_eq!(s.points[s.points.len() - 1], e.xy[e.xy.len() - 1]);
        }
    }
    let b = Boundaries::new(region);
    let size = size_of(region);
    // Every vertex on the axis: its radius the boundary's distance, attained at both feet.
    for e in &a.edges {
        for k in 0..e.xy.len() {
            let (x, r) = (e.xy[k], e.radius[k]);
            let (d, _) = b.nearest(x);
            testkit::prop_assert_near!(d, r, 1e-9 * size, "vertex {x:?}: radius {r}, distance {d}, vertex {k} of {} (size {size}, feet {:?} on {:?})", e.xy.len(), e.feet[k], e.boundary[k]);
            for s in 0..2 {
                let f = b.profiles[e.boundary[k][s]].jet(e.feet[k][s]).p.arr();
                let to_foot = (x[0] - f[0]).hypot(x[1] - f[1]);
                testkit::prop_assert_near!(
                    to_foot,
                    r,
                    1e-9 * size,
                    "vertex {x:?}: foot {s} at {to_foot}, radius {r}"
                );
            }
        }
    }
    // Within 1e-2 rad of a cusp (a corner turning back on itself: a needle or a crack) the
    // graph may come apart or miss the stretch round the needle's tip (a known limit); the
    // axis must then say it is not certified.
    if near_cusp(&b) && !shaped_like_the_region(&a, region.holes().len()) {
        prop_assert!(!a.certified(), "a certified axis came apart beside a cusp");
        bump(&NEAR_CUSPS, 1);
        return Ok(());
    }
    // A certified junction is within 1e-9 of the size of a disk touching the boundary at
    // three points: their distances from the node agree to twice that.
    if a.certified() {
        bump(&CERTIFIED, 1);
        for node in a.nodes.iter().filter(|n| n.kind == NodeKind::Junction) {
            let (touching, least) = b.contacts(
                node.xy,
                2e-9 * size + 1e-12 * size,
                1e-6 * size,
                1e-3 * size,
            );
            prop_assert!(
                touching >= 3 && (least - node.radius).abs() <= 1e-9 * size,
                "certified junction {node:?}: {touching} contacts, distance {least}"
            );
        }
        // A certified end off an arc's centre is at a peak of the curvature: the largest of
        // dense samples about its foot lies next to it.
        for node in a.nodes.iter().filter(|n| n.kind == NodeKind::End) {
            let Some((u, k)) = end_foot(&a, node.id) else {
                continue;
            };
            let p = b.profiles[k];
            let n = p.segments().len() as f64;
            // (An end at an arc's centre, or at a joint with an arc, is exact data.)
            let (i, _) = p.locate(u.rem_euclid(n));
            let before = p.locate((u - 1e-9).rem_euclid(n)).0;
            let after = p.locate((u + 1e-9).rem_euclid(n)).0;
            if [i, before, after]
                .iter()
                .any(|&j| p.segments()[j].circle().is_some())
            {
                continue;
            }
            let kappa = |v: f64| {
                let v = if p.is_closed() {
                    v.rem_euclid(n)
                } else {
                    v.clamp(0.0, n)
                };
                let s = p.locate(v).0;
                p.jet_on(s, v, 2).curvature().abs()
            };
            let (reach, steps) = (1e-3, 4000);
            let top = (0..=steps)
                .map(|j| u - reach + 2.0 * reach * j as f64 / steps as f64)
                .max_by(|x, y| kappa(*x).total_cmp(&kappa(*y)))
                .unwrap();
            testkit::prop_assert_near!(
                top,
                u,
                2.0 * reach / steps as f64 + 1e-9,
                "certified end {node:?} at foot {u}: the curvature peaks at {top}"
            );
        }
    }
    // Connected, with one cycle per hole.
    prop_assert!(
        shaped_like_the_region(&a, region.holes().len()),
        "not one piece with a cycle per hole: {:?}",
        a.nodes
    );
    // Nothing missed: every point of the sampled boundary's Voronoi diagram, refined onto
    // the axis, lies within the chord tolerance of an edge (and of the fitted curves).
    let room = CHORD * size + 1e-6 * size;
    let sampled = sampled_medial_points(&b.profiles, size, |x| b.nearest(x).0, |x| b.inside(x));
    prop_assert!(
        sampled.unrefined + sampled.dominated <= sampled.kept / 10
            && sampled.unresolved <= sampled.kept / 4,
        "{} of {} Voronoi edges did not refine, {} had a foot beyond the widest window, {} \
         were dominated",
        sampled.unrefined,
        sampled.kept,
        sampled.unresolved,
        sampled.dominated
    );
    for z in &sampled.points {
        let off = off_axis(&a, z.xy);
        prop_assert!(
            off <= room,
            "medial point {:?} (radius {}) is {off} off the axis",
            z.xy,
            z.radius
        );
        if let Some(curves) = &fitted_curves {
            let off = off_polylines(z.xy, curves.iter().map(|c| &c[..]));
            prop_assert!(
                off <= room,
                "medial point {:?} is {off} off the fitted axis",
                z.xy
            );
        }
    }
    let found = sampled.points.len();
    bump(&MEDIAL_POINTS, found.min(1));
    Ok(())
}
