//! Move 6 (issue 41), the last step: lines and arcs read as curves take the profile
//! bisector's closed forms, written as the curves' document (no `segment`, no `corner`) in
//! each segment's own parameter. Two arcs of one circle have its centre; two lines their
//! angle bisectors; an arc and a line tangent to its circle the centre too.
#![allow(clippy::unwrap_used)]

use curvekit::commands::BisectorFound;
use curvekit::io::{parse_curve, Curve};
use serde_json::Value;
use zeroset::BisectorOptions;

fn curve(name: &str, json: &str) -> Curve {
    parse_curve(name, json).unwrap()
}

/// The arc of centre `center` and radius `r` from angle `start` to `end`, read from its file.
fn arc(center: [f64; 2], r: f64, start: f64, end: f64) -> Curve {
    let json = format!(
        r#"{{"kind":"arc","center":[{},{}],"r":{r},"start":{start},"end":{end}}}"#,
        center[0], center[1]
    );
    curve("arc", &json)
}

/// The tool's bisector of `a` and `b` as its JSON document, checked to be the curve's.
fn document(a: &Curve, b: &Curve) -> Value {
    let found = curvekit::commands::bisector(a, Some(b), &BisectorOptions::default()).unwrap();
    assert!(matches!(found, BisectorFound::Curve(_)), "{}", a.file);
    let doc = serde_json::to_value(&found).unwrap();
    let text = doc.to_string();
    assert!(
        !text.contains("\"segment\"") && !text.contains("\"corner\""),
        "{text}"
    );
    assert_eq!(doc["complete"], true, "{text}");
    doc
}

fn pair(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

/// The isolated points of a document: (tr, xy).
fn isolated(doc: &Value) -> Vec<([f64; 2], [f64; 2])> {
    let list = doc["isolated"].as_array().unwrap();
    list.iter()
        .map(|p| (pair(&p["tr"]), pair(&p["xy"])))
        .collect()
}

/// A point of an arc of centre (0, 0) and radius 2 at its own parameter `u` (its angle's
/// share).
fn on_arc(start: f64, end: f64, u: f64) -> [f64; 2] {
    let a = start + u * (end - start);
    [2.0 * a.cos(), 2.0 * a.sin()]
}

#[test]
fn two_arcs_of_one_circle_have_its_centre() {
    let a = arc([0.0, 0.0], 2.0, 0.3, 1.2);
    let b = arc([0.0, 0.0], 2.0, 2.0, 2.8);
    let doc = document(&a, &b);
    assert!(doc["branches"].as_array().unwrap().is_empty(), "{doc}");
    let [(tr, xy)] = isolated(&doc)[..] else {
        panic!("{doc}")
    };
    assert_eq!(xy, [0.0, 0.0]);
    // The feet are the arcs' points in their own parameters, at the radius from the centre.
    assert!(tr.iter().all(|u| (0.0..=1.0).contains(u)), "{tr:?}");
    for p in [on_arc(0.3, 1.2, tr[0]), on_arc(2.0, 2.8, tr[1])] {
        assert!((p[0].hypot(p[1]) - 2.0).abs() < 1e-12);
    }
}

#[test]
fn two_lines_have_their_angle_bisectors() {
    // y = 0 from x = 1 to 5 and x = 0 from y = 1 to 5: the diagonal y = x, feet at t = r.
    let a = curve("a", r#"{"kind":"line","from":[1,0],"to":[5,0]}"#);
    let b = curve("b", r#"{"kind":"line","from":[0,1],"to":[0,5]}"#);
    let doc = document(&a, &b);
    let branches = doc["branches"].as_array().unwrap();
    assert!(!branches.is_empty(), "{doc}");
    for br in branches {
        for (tr, xy) in br["tr"]
            .as_array()
            .unwrap()
            .iter()
            .zip(br["xy"].as_array().unwrap())
        {
            let (tr, xy) = (pair(tr), pair(xy));
            assert!((xy[0] - xy[1]).abs() < 1e-12, "{xy:?}");
            assert!((tr[0] - tr[1]).abs() < 1e-12, "{tr:?}");
            // The foot on y = 0 is (1 + 4t, 0), right below the point.
            assert!((1.0 + 4.0 * tr[0] - xy[0]).abs() < 1e-12, "{tr:?} {xy:?}");
        }
    }
}

#[test]
fn an_arc_and_a_line_tangent_to_its_circle_have_its_centre() {
    // y = −2 touches the circle of radius 2 at (0, −2), on the segment; the arc is far above.
    let a = arc([0.0, 0.0], 2.0, 0.3, 1.2);
    let line = curve("l", r#"{"kind":"line","from":[-3,-2],"to":[3,-2]}"#);
    let doc = document(&a, &line);
    let [(tr, xy)] = isolated(&doc)[..] else {
        panic!("{doc}")
    };
    assert_eq!(xy, [0.0, 0.0]);
    assert!((tr[1] - 0.5).abs() < 1e-12, "the contact (0, −2): {tr:?}");
    // Off the segment, the contact leaves no centre.
    let off = curve("o", r#"{"kind":"line","from":[1,-2],"to":[3,-2]}"#);
    assert!(isolated(&document(&a, &off)).is_empty());
}

#[test]
fn arcs_of_circles_tangent_to_each_other_have_their_centres() {
    // Radius 1 about (0, 0) and 2 about (0, 3) touch at (0, 1), on both arcs: each centre is
    // at its radius from its whole arc and from the contact.
    let small = arc([0.0, 0.0], 1.0, 0.5, 2.5);
    let large = arc([0.0, 3.0], 2.0, -2.5, -0.5);
    let centres: Vec<[f64; 2]> = isolated(&document(&small, &large))
        .into_iter()
        .map(|(_, xy)| xy)
        .collect();
    assert!(
        centres.contains(&[0.0, 0.0]) && centres.contains(&[0.0, 3.0]),
        "{centres:?}"
    );
}
