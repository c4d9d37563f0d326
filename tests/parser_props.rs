//! The curve-file reader returns `Err` (never panics) on junk, on mutations of valid files and
//! on random JSON objects made of the format's own field names; whatever it accepts, the
//! inflection computation handles without panicking.
#![allow(clippy::unwrap_used)]

use curvekit::io::parse_curve;
use proptest::prelude::*;
use serde_json::{json, Map, Value};

const VALID: &[&str] = &[
    include_str!("../fixtures/periodic_nurbs.json"),
    include_str!("../fixtures/clamped_closed.json"),
    include_str!("../fixtures/open_nurbs.json"),
    include_str!("../fixtures/convexities_m3.json"),
    include_str!("../fixtures/ellipse.json"),
];

const KEYS: &[&str] = &[
    "kind", "points", "weights", "knots", "degree", "periodic", "r", "a", "b", "center", "p",
    "eps", "m", "radius",
];
const KINDS: &[&str] = &[
    "bezier",
    "bspline",
    "circle",
    "ellipse",
    "limacon",
    "elliptic_lemniscate",
    "convexities",
    "spiral",
];

/// Parses, and if accepted, computes the inflections (the result may be an error, not a panic).
fn exercise(text: &str) {
    if let Ok(curve) = parse_curve("prop.json", text) {
        let _ = antipodal::inflections(
            curve.plane_curve(),
            &antipodal::Options::default()
                .tolerance(numeric::tolerance::ParamTol::new(1e-10).expect("in range")),
        );
    }
}

fn number() -> impl Strategy<Value = Value> {
    prop_oneof![
        (-4i64..6).prop_map(|i| json!(i)),
        (-10.0f64..10.0).prop_map(|x| json!(x)),
        Just(json!(1e100)),
        Just(json!(-1e-300)),
        Just(json!(0.0)),
    ]
}

fn leaf() -> impl Strategy<Value = Value> {
    prop_oneof![
        4 => number(),
        1 => Just(Value::Null),
        1 => any::<bool>().prop_map(Value::Bool),
        1 => prop::sample::select(KINDS).prop_map(|k| json!(k)),
    ]
}

/// Values shaped like the format's fields: numbers, points, lists of numbers and of points.
fn field_value() -> impl Strategy<Value = Value> {
    let point = prop::collection::vec(number(), 1..4).prop_map(Value::Array);
    prop_oneof![
        3 => leaf(),
        2 => prop::collection::vec(number(), 0..10).prop_map(Value::Array),
        3 => prop::collection::vec(point, 0..9).prop_map(Value::Array),
    ]
}

fn object() -> impl Strategy<Value = String> {
    (
        prop::sample::select(KINDS),
        prop::collection::vec((prop::sample::select(KEYS), field_value()), 0..6),
    )
        .prop_map(|(kind, fields)| {
            let mut map = Map::new();
            map.insert("kind".into(), json!(kind));
            for (k, v) in fields {
                map.insert(k.to_string(), v);
            }
            Value::Object(map).to_string()
        })
}

/// A valid file with one random edit: delete, insert or replace a span of characters.
fn mutated() -> impl Strategy<Value = String> {
    (
        prop::sample::select(VALID),
        any::<prop::sample::Index>(),
        0usize..6,
        "[\\[\\]{}\",:0-9.eE+-]{0,4}",
    )
        .prop_map(|(text, at, len, insert)| {
            let chars: Vec<char> = text.chars().collect();
            let i = at.index(chars.len() + 1);
            let j = (i + len).min(chars.len());
            let mut out: String = chars[..i].iter().collect();
            out.push_str(&insert);
            out.extend(&chars[j..]);
            out
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn junk_never_panics(text in "\\PC{0,64}") {
        exercise(&text);
    }

    #[test]
    fn json_like_junk_never_panics(text in "[\\[\\]{}\",:0-9a-z.eE+ -]{0,64}") {
        exercise(&text);
    }

    #[test]
    fn mutated_files_never_panic(text in mutated()) {
        exercise(&text);
    }

    #[test]
    fn random_objects_never_panic(text in object()) {
        exercise(&text);
    }
}

#[test]
fn valid_fixtures_parse() {
    for text in VALID {
        assert!(parse_curve("valid.json", text).is_ok(), "{text}");
    }
}

/// Spline objects that are mostly valid: small integer coordinates (so repeated points, cusps,
/// collinear runs and zero-length pieces are common), optional weights, knots and periodicity.
fn plausible_spline() -> impl Strategy<Value = String> {
    (1usize..5, 2usize..10)
        .prop_flat_map(|(degree, n)| {
            (
                Just(degree),
                prop::collection::vec((-3i32..4, -3i32..4), n),
                prop::option::of(prop::collection::vec(1u32..6, n)),
                any::<bool>(),
                prop::option::of(prop::collection::vec(0u32..5, n + degree + 1)),
            )
        })
        .prop_map(|(degree, pts, weights, periodic, knots)| {
            let mut map = Map::new();
            map.insert("kind".into(), json!("bspline"));
            map.insert("degree".into(), json!(degree));
            let points: Vec<[i32; 2]> = pts.iter().map(|&(x, y)| [x, y]).collect();
            map.insert("points".into(), json!(points));
            if let Some(w) = weights {
                let w: Vec<f64> = w.iter().map(|&x| f64::from(x) * 0.5).collect();
                map.insert("weights".into(), json!(w));
            }
            if periodic {
                map.insert("periodic".into(), json!(true));
            } else if let Some(mut k) = knots {
                k.sort_unstable();
                map.insert("knots".into(), json!(k));
            }
            Value::Object(map).to_string()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn plausible_splines_never_panic(text in plausible_spline()) {
        exercise(&text);
    }
}

/// The first control point of a parsed curve.
fn first_point(text: &str) -> [f64; 2] {
    let curve = parse_curve("exact.json", text).unwrap();
    match curve.plane_curve().exact() {
        Some(curve::Exact::Spline(s)) => s.control_points()[0],
        _ => panic!("not a spline"),
    }
}

proptest! {
    /// Numbers are read exactly: the double nearest the decimal in the file, as Rust's own
    /// correctly rounded parser gives it, in every notation and with more digits than a
    /// double holds (a reader one ulp off computes on another curve than the file's, and
    /// certifies that one).
    #[test]
    fn numbers_are_read_exactly(
        bits in any::<u64>(),
        digits in 17usize..30,
    ) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite() && x.abs() < 1e99 && x.abs() > 1e-300);
        for text in [format!("{x}"), format!("{x:e}"), format!("{x:.digits$e}")] {
            let want: f64 = text.parse().unwrap();
            let file = format!(
                r#"{{"kind":"bspline","degree":1,"points":[[{text},0],[1,1],[0,2]]}}"#
            );
            prop_assert_eq!(first_point(&file)[0].to_bits(), want.to_bits(), "{}", text);
        }
    }
}
