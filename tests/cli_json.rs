//! The JSON document of every command has the shape the contract gives; `--time`, `--svg` and
//! `demo` do what they say.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit, curvekit_json, fixture};
use serde_json::Value;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn assert_point(v: &Value) {
    let a = v.as_array().unwrap();
    assert_eq!(a.len(), 2, "{v}");
    a.iter().for_each(|x| assert!(num(x).is_finite()));
}

#[test]
fn inflections_json() {
    let d = curvekit_json(&["inflections", &fixture("periodic_cubic.json")]);
    assert_eq!(d["certified"], Value::Bool(true));
    let list = d["inflections"].as_array().unwrap();
    assert_eq!(list.len(), 2);
    for i in list {
        assert!((0.0..6.0).contains(&num(&i["u"])));
        assert_point(&i["p"]);
        assert_eq!(i["certified"], Value::Bool(true));
    }
    assert_eq!(d["curve"]["kind"], "bspline");
    assert!(d.get("stats").is_none());
}

#[test]
fn inflections_known_values() {
    // An S-shaped cubic Bézier, symmetric about its middle: the inflection is at u = 1/2.
    let d = curvekit_json(&["inflections", &fixture("bezier_s.json")]);
    let i = &d["inflections"][0];
    testkit::assert_near!(num(&i["u"]), 0.5, 1e-12);
    assert!((num(&i["p"][0]) - 1.5).abs() < 1e-12 && num(&i["p"][1]).abs() < 1e-12);
    // Limaçon r = a + b cos φ: inflections where a² + 3ab cos φ + 2b² = 0.
    let d = curvekit_json(&["inflections", &fixture("limacon.json")]);
    let (a, b) = (4.0f64, 2.5f64);
    let phi = (-(a * a + 2.0 * b * b) / (3.0 * a * b)).acos();
    let us: Vec<f64> = d["inflections"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| num(&i["u"]))
        .collect();
    assert_eq!(us.len(), 2);
    testkit::assert_near!(us[0], phi, 1e-8, "{us:?} vs {phi}");
    testkit::assert_near!(us[1], std::f64::consts::TAU - phi, 1e-8, "{us:?}");
}

/// The `inflections` command (certified pipeline) and the inflection list of `antipodal` agree
/// on closed spline curves.
#[test]
fn inflections_agree_with_antipodal() {
    for f in [
        "periodic_cubic.json",
        "periodic_nurbs.json",
        "clamped_closed.json",
    ] {
        let a = curvekit_json(&["inflections", &fixture(f)]);
        let b = curvekit_json(&["antipodal", &fixture(f)]);
        let us = |d: &Value| -> Vec<f64> {
            d["inflections"]
                .as_array()
                .unwrap()
                .iter()
                .map(|i| num(&i["u"]))
                .collect()
        };
        let (ua, ub) = (us(&a), us(&b));
        assert_eq!(ua.len(), ub.len(), "{f}");
        for (x, y) in ua.iter().zip(&ub) {
            testkit::assert_near!(x, y, 1e-9, "{f}: {ua:?} vs {ub:?}");
        }
    }
}

#[test]
fn antipodal_json() {
    let d = curvekit_json(&["antipodal", &fixture("ellipse.json")]);
    let pairs = d["pairs"].as_array().unwrap();
    assert_eq!(pairs.len(), 2);
    let mut last = f64::NEG_INFINITY;
    for p in pairs {
        let (s, t) = (num(&p["s"]), num(&p["t"]));
        assert!(s >= last, "sorted by s");
        last = s;
        assert!(s != t);
        assert_point(&p["p"]);
        assert_point(&p["q"]);
        let (pp, qq) = (&p["p"], &p["q"]);
        let dist = (num(&qq[0]) - num(&pp[0])).hypot(num(&qq[1]) - num(&pp[1]));
        testkit::assert_near!(dist, num(&p["distance"]), 1e-9);
        assert!(["A", "B", "C", "D", "E"].contains(&p["type"].as_str().unwrap()));
    }
    assert!(d["inflections"].as_array().unwrap().is_empty());
    assert!(d["families"].is_array());
}

#[test]
fn tangents_json() {
    let d = curvekit_json(&[
        "tangents",
        &fixture("ellipse.json"),
        &fixture("circle.json"),
    ]);
    let lines = d["lines"].as_array().unwrap();
    assert!(!lines.is_empty());
    for l in lines {
        assert!(num(&l["s"]).is_finite() && num(&l["t"]).is_finite());
        assert_point(&l["p"]);
        assert_point(&l["q"]);
    }
    assert_eq!(d["curves"].as_array().unwrap().len(), 2);
}

#[test]
fn bisector_json() {
    let d = curvekit_json(&[
        "bisector",
        &fixture("bisector-fig2-quadratic.json"),
        &fixture("bisector-fig2-line.json"),
    ]);
    let branches = d["branches"].as_array().unwrap();
    assert!(!branches.is_empty());
    for b in branches {
        let (tr, xy) = (b["tr"].as_array().unwrap(), b["xy"].as_array().unwrap());
        assert_eq!(tr.len(), xy.len());
        tr.iter().chain(xy).for_each(assert_point);
    }
}

/// Every bisector point of `branches` as `[x, y]`.
fn bisector_points(d: &Value) -> Vec<[f64; 2]> {
    d["branches"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|b| b["xy"].as_array().unwrap().clone())
        .map(|p| [num(&p[0]), num(&p[1])])
        .collect()
}

/// Distance from `p` to the nearest segment of the branches' polylines.
fn distance_to_branches(d: &Value, p: [f64; 2]) -> f64 {
    let mut best = f64::INFINITY;
    for b in d["branches"].as_array().unwrap() {
        let xy: Vec<[f64; 2]> = b["xy"]
            .as_array()
            .unwrap()
            .iter()
            .map(|q| [num(&q[0]), num(&q[1])])
            .collect();
        for w in xy.windows(2) {
            best = best.min(curve::distance_to_segment(p, w[0], w[1]));
        }
    }
    best
}

/// `--method` and `--trimmed` reach the library: the three functions of §3 trace the same
/// bisector, and the trimmed bisector is a part of it.
#[test]
fn bisector_methods_and_trimming_agree() {
    let (c1, c2) = (
        fixture("bisector-fig3-quadratic1.json"),
        fixture("bisector-fig3-quadratic2.json"),
    );
    let f3 = curvekit_json(&["bisector", &c1, &c2, "--method", "f3"]);
    // Chord tolerance 1e-3 of a diagonal of about 5, on both polylines.
    let near = 2.0 * 1e-3 * 5.0;
    for method in ["f1", "f2"] {
        let other = curvekit_json(&["bisector", &c1, &c2, "--method", method]);
        let pts = bisector_points(&other);
        assert!(!pts.is_empty(), "{method}");
        for p in pts.iter().filter(|p| p[0].hypot(p[1]) < 10.0) {
            let d = distance_to_branches(&f3, *p);
            assert!(d <= near, "{method}: {p:?} is {d} from the F3 bisector");
        }
    }
    let trimmed = curvekit_json(&["bisector", &c1, &c2, "--trimmed"]);
    let pts = bisector_points(&trimmed);
    assert!(!pts.is_empty() && pts.len() < bisector_points(&f3).len());
    for p in pts {
        assert!(distance_to_branches(&f3, p) <= near, "trimmed point {p:?}");
    }
    let bad = curvekit(&["bisector", &c1, &c2, "--method", "f4"]);
    assert_eq!(bad.code, 2);
}

/// A curve written as a one-segment profile has exactly the curve's bisector (branches,
/// parameters and points), with the sites of each branch added.
#[test]
fn one_segment_profiles_have_their_curves_bisector() {
    let dir = tempfile::tempdir().unwrap();
    let (c1, c2) = (
        fixture("bisector-fig3-quadratic1.json"),
        fixture("bisector-fig3-quadratic2.json"),
    );
    let wrap = |name: &str, curve: &str| {
        let text = std::fs::read_to_string(curve).unwrap();
        let path = dir.path().join(name);
        std::fs::write(
            &path,
            format!("{{\"kind\":\"profile\",\"segments\":[{text}]}}"),
        )
        .unwrap();
        path.to_string_lossy().into_owned()
    };
    let (p1, p2) = (wrap("p1.json", &c1), wrap("p2.json", &c2));
    for (curves, profiles) in [
        (
            vec![c1.as_str(), c2.as_str()],
            vec![p1.as_str(), p2.as_str()],
        ),
        (vec![c1.as_str()], vec![p1.as_str()]),
    ] {
        let plain = curvekit_json(&[&["bisector"], &curves[..]].concat());
        let profile = curvekit_json(&[&["bisector"], &profiles[..]].concat());
        let (a, b) = (
            plain["branches"].as_array().unwrap(),
            profile["branches"].as_array().unwrap(),
        );
        assert!(!a.is_empty() && a.len() == b.len(), "{curves:?}");
        for (x, y) in a.iter().zip(b) {
            assert_eq!(x["xy"], y["xy"]);
            assert_eq!(x["tr"], y["tr"]);
            assert_eq!(y["segment"], serde_json::json!([0, 0]));
            assert_eq!(y["corner"], serde_json::json!([false, false]));
        }
        assert_eq!(plain["isolated"], profile["isolated"]);
        assert_eq!(plain["singular"], profile["singular"]);
    }
}

/// The self-bisector of a drawing's outline, trimmed: its reflex corners take part as point
/// sites, and every vertex is at the same distance from its two foot points.
#[test]
fn a_drawings_trimmed_self_bisector_has_corner_branches() {
    let d = curvekit_json(&["bisector", &fixture("profile-bracket.json"), "--trimmed"]);
    let branches = d["branches"].as_array().unwrap();
    assert!(branches
        .iter()
        .any(|b| b["corner"].as_array().unwrap().iter().any(|c| c == true)));
    assert_eq!(d["complete"], true);
}

#[test]
fn time_reports_stats() {
    let d = curvekit_json(&["inflections", &fixture("bezier_s.json"), "--time"]);
    let stats = &d["stats"];
    assert!(num(&stats["median_us"]) > 0.0);
    assert!(stats["runs"].as_u64().unwrap() >= 3);
    let r = curvekit(&["inflections", &fixture("bezier_s.json"), "--time"]);
    assert_eq!(r.code, 0);
    assert!(r
        .stdout
        .lines()
        .any(|l| l.starts_with("time:") && l.contains("median")));
}

#[test]
fn svg_is_written() {
    let dir = tempfile::tempdir().unwrap();
    for (args, name) in [
        (vec!["inflections", "periodic_nurbs.json"], "i.svg"),
        (vec!["antipodal", "limacon.json"], "a.svg"),
        (vec!["tangents", "ellipse.json", "circle.json"], "t.svg"),
        (
            vec![
                "bisector",
                "bisector-fig2-quadratic.json",
                "bisector-fig2-line.json",
            ],
            "b.svg",
        ),
    ] {
        let path = dir.path().join(name);
        let mut full: Vec<String> = vec![args[0].to_string()];
        full.extend(args[1..].iter().map(|f| fixture(f)));
        full.extend(["--svg".to_string(), path.display().to_string()]);
        let refs: Vec<&str> = full.iter().map(String::as_str).collect();
        let r = curvekit(&refs);
        assert_eq!(r.code, 0, "{args:?}: {}", r.stderr);
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        assert!(svg.contains("viewBox"));
    }
}

#[test]
fn demo_writes_figures() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    let r = curvekit(&["demo", "--out", out.to_str().unwrap(), "--json"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let d: Value = serde_json::from_str(&r.stdout).unwrap();
    let shapes = d["shapes"].as_array().unwrap();
    assert!(shapes.len() >= 8);
    for s in shapes {
        // Inflections are available for every example.
        assert!(s["inflections"].is_array(), "{s}");
        let svg = std::fs::read_to_string(s["svg"].as_str().unwrap()).unwrap();
        assert!(svg.starts_with("<svg"));
    }
    let names: Vec<&str> = shapes.iter().map(|s| s["name"].as_str().unwrap()).collect();
    for paper in [
        "limacon",
        "elliptic_lemniscate",
        "convexities_m3",
        "convexities_m4",
    ] {
        assert!(names.contains(&paper));
    }
    for b in d["bisectors"].as_array().unwrap() {
        assert!(std::path::Path::new(b["svg"].as_str().unwrap()).exists());
    }
    // The medial axes of the pockets: each drawn, the pockets with their island's cycle.
    let medial = d["medial"].as_array().unwrap();
    assert!(medial.len() >= 4);
    for m in medial {
        assert!(
            std::path::Path::new(m["svg"].as_str().unwrap()).exists(),
            "{m}"
        );
        assert!(m["medial"]["nodes"].as_u64().unwrap() > 0, "{m}");
    }
    for pocket in ["medial-region-pocket", "medial-drawing-pocket"] {
        let m = medial.iter().find(|m| m["name"] == pocket).unwrap();
        let (n, e) = (
            m["medial"]["nodes"].as_u64().unwrap(),
            m["medial"]["edges"].as_u64().unwrap(),
        );
        assert_eq!(e + 1 - n, 1, "{m}");
    }
}

/// `medial` prints the contract's document, and refuses what encloses no region by name.
#[test]
fn medial_json() {
    let d = curvekit_json(&["medial", &fixture("region-pocket.json")]);
    let nodes = d["nodes"].as_array().unwrap();
    let edges = d["edges"].as_array().unwrap();
    // One cycle round the island: a connected graph with as many edges as nodes.
    assert_eq!(nodes.len(), edges.len());
    for e in edges {
        let n = e["xy"].as_array().unwrap().len();
        for key in ["radius", "feet", "boundary"] {
            assert_eq!(e[key].as_array().unwrap().len(), n, "{key}");
        }
    }
    assert!(nodes.iter().all(|n| n["radius"].as_f64().unwrap() > 0.0));
    assert_eq!(d["complete"], true);
    assert!(edges.iter().all(|e| e.get("bspline").is_none()));
    // With --fit, every edge also as a B-spline: clamped knots, as many axis as radius
    // control points, ends at the edge's ends, within half the chord tolerance (1e-3 of the
    // size, 10) of the polyline.
    let fitted = curvekit_json(&["medial", &fixture("region-pocket.json"), "--fit"]);
    for e in fitted["edges"].as_array().unwrap() {
        let b = &e["bspline"];
        let degree = b["degree"].as_u64().unwrap() as usize;
        let knots = b["knots"].as_array().unwrap();
        let points = b["points"].as_array().unwrap();
        assert_eq!(knots.len(), points.len() + degree + 1);
        assert_eq!(b["radius_points"].as_array().unwrap().len(), points.len());
        assert_eq!(points[0], e["xy"][0]);
        assert_eq!(
            points[points.len() - 1],
            e["xy"][e["xy"].as_array().unwrap().len() - 1]
        );
        assert!(b["error"].as_f64().unwrap() <= 0.5 * 1e-3 * 10.0);
    }
    // --exterior: the pocket's outline is convex, so all there is outside is the island's
    // own axis, its centre (6.5, 3) at radius 1.2.
    let outside = curvekit_json(&["medial", &fixture("region-pocket.json"), "--exterior"]);
    assert_eq!(outside["edges"].as_array().unwrap().len(), 0);
    let nodes = outside["nodes"].as_array().unwrap();
    assert_eq!(nodes.len(), 1);
    assert_eq!(nodes[0]["kind"], "end");
    testkit::assert_near!(nodes[0]["radius"].as_f64().unwrap(), 1.2, 1e-12);
    // A drawing's outlines nested inside each other make a region: the glyph's bowl is a
    // hole, so the axis has one cycle.
    let glyph = curvekit_json(&["medial", &fixture("drawing-glyph-d.svg")]);
    let (n, e) = (
        glyph["nodes"].as_array().unwrap().len(),
        glyph["edges"].as_array().unwrap().len(),
    );
    assert_eq!(e + 1 - n, 1);
    // An open profile bounds no region; a closed analytic curve does (the contract's
    // "Parameters, sizes and drawings").
    let run = curvekit(&["medial", &fixture("profile-s-curve.json")]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("closed"), "{}", run.stderr);
    let limacon = curvekit_json(&["medial", &fixture("limacon.json")]);
    assert!(!limacon["edges"].as_array().unwrap().is_empty());
}
