//! `tangents` on arbitrary pairs of curves: an error or a result, never a panic or a hang;
//! lines with finite ends on the two curves, at parameters within their domains.
#![no_main]

#[path = "common.rs"]
mod common;

use antipodal::Options;
use arbitrary::Arbitrary;
use common::{accepted_and_finite, tolerance, within, ArbCurve};
use curvekit::antipodal;
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    first: ArbCurve,
    second: ArbCurve,
    tol: u8,
    raw_tol: f64,
}

fuzz_target!(|input: Input| {
    let (Some(c1), Some(c2)) = (input.first.curve(), input.second.curve()) else {
        return;
    };
    // (A tolerance out of range, now and then drawn, is refused where it is made.)
    let Ok(tol) = curvekit::numeric::tolerance::ParamTol::new(tolerance(input.tol, input.raw_tol))
    else {
        return;
    };
    let opts = Options::default().tolerance(tol);
    let (p1, p2) = (c1.plane_curve(), c2.plane_curve());
    if let Ok(r) = antipodal::common_tangents(p1, p2, &opts) {
        accepted_and_finite(&opts, &r);
        for l in &r.lines {
            assert!(
                within(l.s, c1.domain()) && within(l.t, c2.domain()),
                "{l:?}"
            );
        }
    }
});
