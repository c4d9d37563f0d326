//! `curvekit inflections` on random open and closed B-splines (degree 2–5, quadratic ones
//! included, whose curvature jumps at every knot) against an independent oracle: the sign of
//! the curvature sampled densely from the curve's derivatives.
#![allow(clippy::unwrap_used)]

mod common;

use common::Tally;
use curvekit::io::parse_curve;
use proptest::prelude::*;
use serde_json::json;

const SAMPLES: usize = 4000;

/// Sign changes of the sampled curvature: the midpoints between samples of opposite signs,
/// skipping samples whose sign rounding could flip; `None` when two changes are too close
/// for the sampling to resolve (the case is then not compared).
fn oracle(curve: &dyn antipodal::PlaneCurve) -> Option<Vec<f64>> {
    let (a, b) = curve.domain();
    let closed = curve.is_closed();
    let mut out = Vec::new();
    let mut last: Option<(f64, bool)> = None;
    // A closed curve is sampled from its seam on, the sample at the seam taken again at the
    // end, so that a change across the seam is seen too.
    for i in 0..=SAMPLES {
        let u = a + (b - a) * i as f64 / SAMPLES as f64;
        let u = if closed && i == SAMPLES { a } else { u };
        let j = curve.jet(u);
        let k = j.d1.cross(j.d2);
        if k.abs() <= 1e-7 * j.d1.norm() * j.d2.norm().max(j.d1.norm()) {
            continue;
        }
        let u = if closed && i == SAMPLES { b } else { u };
        if let Some((v, s)) = last {
            if s != (k > 0.0) {
                out.push(0.5 * (u + v));
            }
        }
        last = Some((u, k > 0.0));
    }
    let step = (b - a) / SAMPLES as f64;
    let resolved = out.windows(2).all(|w| w[1] - w[0] > 8.0 * step);
    resolved.then_some(out)
}

fn spline() -> impl Strategy<Value = (usize, Vec<[f64; 2]>, bool)> {
    (2usize..=5, 6usize..=14, any::<bool>()).prop_flat_map(|(deg, n, periodic)| {
        (
            Just(deg),
            proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), n)
                .prop_map(|v| v.into_iter().map(|(x, y)| [x, y]).collect()),
            Just(periodic),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Every sampled sign change of the curvature is reported, and every reported inflection
    /// is a sampled sign change (within the sampling's resolution).
    fn inflections_match_sampled_curvature((deg, points, periodic) in spline()) {
        let text = json!({"kind": "bspline", "degree": deg, "points": points, "periodic": periodic})
            .to_string();
        let Ok(curve) = parse_curve("prop.json", &text) else {
            return Ok(());
        };
        // Cusps and self-touching control polygons are refused: nothing to compare.
        let Ok(found) = antipodal::inflections(curve.plane_curve(), &antipodal::Options::default().tolerance(numeric::tolerance::ParamTol::new(1e-10).expect("in range"))) else {
            return Ok(());
        };
        let plane = curve.plane_curve();
        let Some(want) = oracle(plane) else {
            return Ok(());
        };
        let (a, b) = plane.domain();
        let near = |x: f64, y: f64| {
            let d = (x - y).abs();
            let d = if periodic { d.min(b - a - d) } else { d };
            d <= 2.0 * (b - a) / SAMPLES as f64
        };
        for &w in &want {
            prop_assert!(
                found.inflections.iter().any(|i| near(i.u, w)),
                "sign change near {w} not reported: {:?} (want {want:?})",
                found.inflections.iter().map(|i| i.u).collect::<Vec<_>>()
            );
        }
        // Two sign changes closer than the sampling resolves may cancel in the samples: a
        // reported inflection the samples miss must have a reported neighbour that close
        // (`near`), and its own sign change is checked on the curve right beside it.
        let kappa = |u: f64| {
            let j = plane.jet(u);
            j.d1.cross(j.d2)
        };
        for i in &found.inflections {
            if want.iter().any(|&w| near(i.u, w)) {
                continue;
            }
            let paired = found
                .inflections
                .iter()
                .any(|o| o.u != i.u && near(o.u, i.u));
            let h = 1e-7 * (b - a);
            let changes = (kappa(i.u - h) < 0.0) != (kappa(i.u + h) < 0.0);
            prop_assert!(
                paired && changes,
                "reported {} is no sign change (want {want:?})", i.u
            );
        }
        COMPARED.add(1);
        INFLECTIONS.add(want.len());
    }
}

static COMPARED: Tally = Tally::new();
static INFLECTIONS: Tally = Tally::new();

/// Runs the property; most cases must be compared, with many inflections among them.
#[test]
fn inflections_match_sampled_curvature_on_many_curves() {
    inflections_match_sampled_curvature();
    let (n, k) = (COMPARED.get(), INFLECTIONS.get());
    assert!(
        n >= 300 && k >= 1000,
        "only {n} cases and {k} inflections compared"
    );
}
