//! The regions against an independent dense check: on a grid of pairs `(s, t)`, the force
//! closure condition evaluated from the curve's points and tangents alone (no B-spline
//! algebra) agrees with membership in the reported regions wherever the grid point is farther
//! from every reported boundary than the chord tolerance allows.

use curve::{ParamCurve, SplineCurve};
use grasp::{grasps, GraspOptions, Grasps};
use proptest::prelude::*;
use testkit::boundary_oracle::{off_polylines, winding};
use testkit::stars::star_curve;

/// Grid points per side of the square of pairs.
const GRID: usize = 90;

/// The larger angle between a contact's inward normal and the chord to the other contact,
/// from the curve's jets (counterclockwise curves: the inward normal is the left normal).
fn slip_angle(c: &dyn ParamCurve, orientation: f64, s: f64, t: f64) -> f64 {
    let (js, jt) = (c.jet(s), c.jet(t));
    let d = [jt.p.x - js.p.x, jt.p.y - js.p.y];
    let angle = |tan: [f64; 2], d: [f64; 2]| {
        let n = [-orientation * tan[1], orientation * tan[0]];
        (tan[0] * d[0] + tan[1] * d[1])
            .abs()
            .atan2(n[0] * d[0] + n[1] * d[1])
    };
    angle([js.d1.x, js.d1.y], d).max(angle([jt.d1.x, jt.d1.y], [-d[0], -d[1]]))
}

/// The signed area of a sampled closed curve: its orientation.
fn orientation(c: &dyn ParamCurve) -> f64 {
    let (a, b) = c.domain();
    let n = 400;
    let p: Vec<_> = (0..n)
        .map(|i| c.jet(a + (b - a) * i as f64 / n as f64).p)
        .collect();
    let area: f64 = (0..n)
        .map(|i| {
            let (u, v) = (p[i], p[(i + 1) % n]);
            u.x * v.y - v.x * u.y
        })
        .sum();
    area.signum()
}

/// Whether the grasps' regions hold the pair `(s, t)` of the triangle `s < t`.
fn held(g: &Grasps, p: [f64; 2]) -> bool {
    g.regions.iter().any(|r| {
        let parts: Vec<&Vec<[f64; 2]>> = if r.parts.is_empty() {
            vec![&r.boundary]
        } else {
            r.parts.iter().collect()
        };
        parts.iter().any(|part| winding(part, p) != 0)
            && !r.holes.iter().any(|h| winding(h, p) != 0)
    })
}

/// Every boundary polyline of the result.
fn lines(g: &Grasps) -> Vec<&[[f64; 2]]> {
    g.regions
        .iter()
        .flat_map(|r| {
            std::iter::once(r.boundary.as_slice())
                .chain(r.parts.iter().map(Vec::as_slice))
                .chain(r.holes.iter().map(Vec::as_slice))
        })
        .collect()
}

/// Checks the grid; returns the number of grid points decided.
fn check(c: &SplineCurve, mu: f64) -> Result<usize, TestCaseError> {
    let opts = GraspOptions::friction(mu);
    let g = grasps(c, &opts).map_err(|e| TestCaseError::fail(format!("{e}")))?;
    prop_assert!(g.complete);
    let (a, b) = c.domain();
    let o = orientation(c);
    let alpha = mu.atan();
    // The chord tolerance is relative to the square's diagonal; a margin of a few of them.
    let margin = 4.0 * opts.settings.chord_tol.get() * std::f64::consts::SQRT_2 * (b - a);
    let boundaries = lines(&g);
    let mut decided = 0;
    for i in 0..GRID {
        for j in i + 1..GRID {
            let s = a + (b - a) * (i as f64 + 0.31) / GRID as f64;
            let t = a + (b - a) * (j as f64 + 0.37) / GRID as f64;
            if s >= t {
                continue;
            }
            let p = [s, t];
            if off_polylines(p, boundaries.iter().copied()) <= margin {
                continue;
            }
            decided += 1;
            let fc = slip_angle(c, o, s, t) <= alpha;
            prop_assert_eq!(
                fc,
                held(&g, p),
                "pair ({}, {}) slip angle {} against α = {}; {} regions",
                s,
                t,
                slip_angle(c, o, s, t),
                alpha,
                g.regions.len()
            );
        }
    }
    Ok(decided)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(testkit::cases(24)))]

    /// Random periodic cubic B-splines on star polygons, μ from 0.05 to 1.
    #[test]
    fn regions_match_the_dense_check_on_cubic_splines(
        seed in prop::collection::vec(0.0..1.0f64, 12..=20),
        mu in 0.05..1.0f64,
    ) {
        let c = star_curve(3, &seed, None);
        check(&c, mu)?;
    }

    /// Random rational (NURBS) quadratics.
    #[test]
    fn regions_match_the_dense_check_on_rational_splines(
        seed in prop::collection::vec(0.0..1.0f64, 12..=16),
        weights in prop::collection::vec(0.3..3.0f64, 8),
        mu in 0.05..1.0f64,
    ) {
        let c = star_curve(2, &seed, Some(&weights));
        check(&c, mu)?;
    }
}
