//! `bisector` on arbitrary splines (one curve: its self-bisector; two: theirs): an error or a
//! result, never a panic or a hang; finite points, curve parameters within the domains.
#![no_main]

#[path = "common.rs"]
mod common;

use arbitrary::Arbitrary;
use common::{all_finite, ArbCurve};
use curvekit::zeroset::{self, BisectorOptions};
use libfuzzer_sys::fuzz_target;

/// The most control points per curve here: a self-bisector's cost grows as about n⁶.
const MAX_BISECTOR_POINTS: usize = 7;

#[derive(Arbitrary, Debug)]
struct Input {
    first: ArbCurve,
    second: Option<ArbCurve>,
    /// The chord tolerance: 0.5 / 2^(code mod 6), from 0.5 down to 1/64.
    chord: u8,
    trimmed: bool,
}

fuzz_target!(|input: Input| {
    let spline = |c: &ArbCurve| {
        let curve = c.curve()?;
        let r = curve.rational()?.clone();
        (r.control_points().len() <= MAX_BISECTOR_POINTS).then_some((curve, r))
    };
    let Some((c1, _)) = spline(&input.first) else {
        return;
    };
    let second = match &input.second {
        Some(c) => match spline(c) {
            Some(s) => Some(s),
            None => return,
        },
        None => None,
    };
    let opts = BisectorOptions {
        settings: curvekit::numeric::tolerance::Settings::new(
            curvekit::numeric::tolerance::DEFAULT_PARAM_TOL,
            0.5 / 2f64.powi((input.chord % 6) as i32),
            None,
        )
        .expect("settings in range"),
        trimmed: input.trimmed,
        ..BisectorOptions::default()
    };
    let result = match &second {
        None => zeroset::self_bisector(c1.plane_curve(), &opts),
        Some((c2, _)) => zeroset::bisector(c1.plane_curve(), c2.plane_curve(), &opts),
    };
    if let Ok(b) = result {
        assert!(all_finite(&serde_json::to_value(&b).unwrap()), "{b:?}");
        let d2 = second.as_ref().map_or(c1.domain(), |(c, _)| c.domain());
        let inside = |tr: [f64; 2]| {
            let (a, z) = c1.domain();
            let (a2, z2) = d2;
            a <= tr[0] && tr[0] <= z && a2 <= tr[1] && tr[1] <= z2
        };
        for p in b.singular.iter().chain(&b.isolated) {
            assert!(inside(p.tr), "{p:?} outside the domains");
        }
    }
});
