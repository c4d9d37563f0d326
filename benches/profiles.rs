//! Antipodal pairs of profiles (issue 18): a profile of 8 to 20 segments should answer in the
//! same order of time per pair as a smooth B-spline of the same complexity. Profiles: the
//! rounded slot (8 segments: lines and arcs), the bracket (7: lines, a fillet arc, a Bézier),
//! a 12-segment chain of cubic Béziers with corners, and the gear drawing (48 segments); against
//! periodic cubic B-splines of 8 and 12 spans. Each is reported with its number of pairs so
//! that the time per pair can be compared.
#![allow(missing_docs, clippy::unwrap_used)]

use antipodal::{antipodal, Options, Profile, SplineCurve};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use curvekit::io::{read_curve_picked, CurveKind};
use std::path::Path;
use std::time::Duration;

use testkit::outlines::bezier_chain;
use testkit::rng;
use testkit::stars::Star;

fn fixture(name: &str) -> Profile {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fixtures")
        .join(name);
    let pick = (!name.ends_with(".json")).then_some(0);
    match read_curve_picked(&path, pick).unwrap().shape {
        CurveKind::Profile(p) => *p,
        _ => unreachable!(),
    }
}

/// A random star-shaped periodic cubic B-spline with `n` control points.
fn star(n: usize, seed: u64) -> SplineCurve {
    let points = Star::default().drawn(n, &mut rng(seed));
    SplineCurve::periodic(3, &points, None).unwrap()
}

fn profiles(c: &mut Criterion) {
    let opts = Options::default();
    let cases = [
        (
            "profile_rounded_slot_8",
            fixture("profile-rounded-slot.json"),
        ),
        ("profile_bracket_7", fixture("profile-bracket.json")),
        ("profile_bezier_chain_12", bezier_chain(12)),
        ("profile_gear_48", fixture("drawing-gear.svg")),
    ];
    for (name, p) in &cases {
        let r = antipodal(p, &opts).unwrap();
        assert!(r.complete, "{name}");
        eprintln!(
            "{name}: {} pairs, {} families",
            r.pairs.len(),
            r.families.len()
        );
        c.bench_function(name, |b| b.iter(|| antipodal(black_box(p), &opts).unwrap()));
    }
    for (name, s) in [
        ("bspline_star_8", star(8, 3)),
        ("bspline_star_12", star(12, 5)),
    ] {
        let r = antipodal(&s, &opts).unwrap();
        eprintln!("{name}: {} pairs", r.pairs.len());
        c.bench_function(&format!("{name}_cold"), |b| {
            b.iter(|| antipodal(black_box(&s), &opts).unwrap())
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = profiles
}
criterion_main!(benches);
