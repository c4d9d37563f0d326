//! `inflections` and `antipodal` on arbitrary curves: an error or a result, never a panic or a
//! hang; results hold finite numbers, parameters within the domain, points on the curve, and a
//! certified result on a closed curve is possible (an even number of inflections, at least one
//! antipodal pair).
#![no_main]

#[path = "common.rs"]
mod common;

use antipodal::{Options, Verdict};
use arbitrary::Arbitrary;
use common::{accepted_and_finite, all_finite, tolerance, within, ArbCurve};
use curvekit::antipodal;
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    curve: ArbCurve,
    tol: u8,
    raw_tol: f64,
    certify: bool,
}

fuzz_target!(|input: Input| {
    let Some(curve) = input.curve.curve() else {
        return;
    };
    // (A tolerance out of range, now and then drawn, is refused where it is made.)
    let Ok(tol) = curvekit::numeric::tolerance::ParamTol::new(tolerance(input.tol, input.raw_tol))
    else {
        return;
    };
    let opts = Options::default().tolerance(tol).certify(input.certify);
    let plane = curve.plane_curve();
    let domain = curve.domain();
    let size = curve
        .polyline(64)
        .iter()
        .fold(0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    let on_curve = |u: f64, p: [f64; 2]| {
        let c = plane.jet(u).p.arr();
        // (Far looser than any tolerance: this catches a point of another parameter.)
        (c[0] - p[0]).hypot(c[1] - p[1]) <= 1e-6 * size.max(f64::MIN_POSITIVE)
    };
    let prepared = antipodal::prepare(plane);
    if let Ok(r) = prepared.inflections(&opts) {
        accepted_and_finite(&opts, &r);
        for i in &r.inflections {
            assert!(
                within(i.u, domain),
                "inflection at {} outside {domain:?}",
                i.u
            );
            assert!(
                on_curve(i.u, i.p),
                "inflection point {:?} not at {}",
                i.p,
                i.u
            );
            if let Some(b) = i.bracket {
                // (On a closed curve a bracket across the seam is in the unwrapped parameter,
                // beyond the domain's end.)
                let period = domain.1 - domain.0;
                let inside = |u: f64| b[0] <= u && u <= b[1];
                let held = inside(i.u) || (curve.is_closed() && inside(i.u + period));
                assert!(held, "{} outside its bracket {b:?}", i.u);
            }
        }
        if r.certified() && curve.is_closed() {
            assert!(
                r.inflections.len() % 2 == 0,
                "odd inflections, certified: {r:?}"
            );
        }
    }
    if let Ok(r) = prepared.antipodal(&opts) {
        assert!(all_finite(&serde_json::to_value(&r).unwrap()), "{r:?}");
        for p in &r.pairs {
            assert!(
                within(p.s, domain) && within(p.t, domain),
                "{p:?} outside {domain:?}"
            );
            assert!(
                on_curve(p.s, p.p) && on_curve(p.t, p.q),
                "pair off the curve: {p:?}"
            );
        }
        if r.certified() && r.complete {
            assert!(
                !r.pairs.is_empty() || !r.families.is_empty(),
                "no antipodal pair, certified"
            );
            assert!(
                r.inflections.len() % 2 == 0,
                "odd inflections, certified: {r:?}"
            );
        }
    }
});
