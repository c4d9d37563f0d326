//! `grasps` on arbitrary curves and frictions: an error or a result, never a panic or a hang;
//! results hold finite numbers, best grasps within the domain (or their triangle) and on the
//! curve, and every certified region's best grasp needs no more friction than given; the
//! stretches its proof spares are proper intervals shorter than the period.
#![no_main]

#[path = "common.rs"]
mod common;

use arbitrary::Arbitrary;
use common::{all_finite, ArbCurve};
use curvekit::grasp::{grasps, GraspOptions};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    curve: ArbCurve,
    /// The friction, from a byte: 0.01 to about 2.6 (and 0, refused).
    friction: u8,
    widths: Option<(u8, u8)>,
}

fuzz_target!(|input: Input| {
    let Some(curve) = input.curve.curve() else {
        return;
    };
    let mu = f64::from(input.friction) / 100.0;
    let size = curve
        .polyline(64)
        .iter()
        .fold(0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    let opts = GraspOptions {
        min_width: input.widths.map(|w| f64::from(w.0) / 64.0 * size),
        max_width: input.widths.map(|w| f64::from(w.0) / 64.0 * size + f64::from(w.1) / 32.0 * size),
        ..GraspOptions::friction(mu)
    };
    let plane = curve.plane_curve();
    let Ok(g) = grasps(plane, &opts) else {
        return;
    };
    assert!(all_finite(&serde_json::to_value(&g).unwrap()), "{g:?}");
    let domain = curve.domain();
    let period = domain.1 - domain.0;
    for r in &g.regions {
        let b = &r.best;
        for &[u0, u1] in &b.toward {
            assert!(u0 < u1 && u1 - u0 < period, "spared stretch [{u0}, {u1}] of {b:?}");
        }
        for (u, p) in [(b.s, b.p), (b.t, b.q)] {
            assert!(
                (domain.0 - 1e-9 * period..=domain.1 + 1e-9 * period).contains(&u),
                "best {b:?} outside {domain:?}"
            );
            let c = plane.jet(u).p.arr();
            assert!(
                (c[0] - p[0]).hypot(c[1] - p[1]) <= 1e-6 * size.max(f64::MIN_POSITIVE),
                "best point {p:?} not at {u}"
            );
        }
        if r.certified {
            assert!(b.min_friction <= mu * (1.0 + 1e-6) + 1e-12, "{b:?} at μ = {mu}");
        }
    }
});
