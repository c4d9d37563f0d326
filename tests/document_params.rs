//! Every parameter a command reports names the point it reports, in the input's own terms
//! (the contract's "Parameters, sizes and drawings"): checked with an independent evaluator
//! of the documents (`common::evaluate`) on curves and regions of every kind, arcs in
//! profiles, splines with corners and the analytic shapes as region boundaries.
#![allow(clippy::unwrap_used)]

mod common;

use common::evaluate::{dist, domain, eval};
use common::{curvekit, curvekit_json, fixture};
use serde_json::{json, Value};
use std::path::PathBuf;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

fn pt(v: &Value) -> [f64; 2] {
    [num(&v[0]), num(&v[1])]
}

fn arr(v: &Value) -> &Vec<Value> {
    v.as_array().unwrap()
}

/// A temporary file holding `doc`.
fn file_of(doc: &Value, dir: &tempfile::TempDir, name: &str) -> String {
    let path: PathBuf = dir.path().join(name);
    std::fs::write(&path, doc.to_string()).unwrap();
    path.display().to_string()
}

/// The size of a document's curve: max(width, height) of its points sampled densely.
fn size_of(doc: &Value) -> f64 {
    let (a, b) = domain(doc);
    let pts: Vec<[f64; 2]> = (0..=2000)
        .map(|i| eval(doc, a + (b - a) * i as f64 / 2000.0))
        .collect();
    let ext = |k: usize| {
        let (lo, hi) = pts
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[k]), hi.max(p[k]))
            });
        hi - lo
    };
    ext(0).max(ext(1))
}

/// `inflections` and `antipodal` name their points by their parameters.
fn check_one_curve(doc: &Value, path: &str) {
    let size = size_of(doc);
    let near = |u: f64, p: &Value, what: &str| {
        let d = dist(eval(doc, u), pt(p));
        assert!(
            d <= 1e-9 * size,
            "{path}: {what} at {u}: {d:e} from its point"
        );
    };
    let inf = curvekit_json(&["inflections", path]);
    for f in arr(&inf["inflections"]) {
        near(num(&f["u"]), &f["p"], "inflection");
    }
    for c in inf.get("corners").map(arr).into_iter().flatten() {
        near(num(&c["u"]), &c["p"], "corner");
    }
    if doc["kind"] == "profile" && doc.get("closed") == Some(&json!(false)) {
        return;
    }
    let run = curvekit(&["antipodal", path, "--json"]);
    if run.code != 0 {
        // (Open curves are refused by name.)
        assert!(run.stderr.contains("closed"), "{path}: {}", run.stderr);
        return;
    }
    let found: Value = serde_json::from_str(&run.stdout).unwrap();
    for p in arr(&found["pairs"]) {
        near(num(&p["s"]), &p["p"], "pair's s");
        near(num(&p["t"]), &p["q"], "pair's t");
    }
}

#[test]
fn one_curve_commands_report_parameters_of_their_points() {
    let dir = tempfile::tempdir().unwrap();
    let mut docs: Vec<(Value, String)> = [
        "ellipse.json",
        "limacon.json",
        "periodic_cubic.json",
        "periodic_nurbs.json",
        "clamped_closed.json",
        "open_nurbs.json",
        "profile-rounded-slot.json",
        "profile-cam.json",
        "profile-bracket.json",
        "profile-s-curve.json",
        "flat_between_arcs.json",
    ]
    .iter()
    .map(|name| {
        let path = fixture(name);
        let doc: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        (doc, path)
    })
    .collect();
    // Arcs sweeping various angles, each way round, in profiles; a degree-1 periodic spline
    // (a polygon); a cubic with a knot of full multiplicity at a corner; a clamped spline closed
    // by its points with a corner there.
    let quarter = std::f64::consts::FRAC_PI_2;
    let made = [
        json!({"kind":"profile","segments":[
            {"kind":"line","from":[0,0],"to":[4,0]},
            {"kind":"arc","center":[4,1.5],"r":1.5,"start":-quarter,"end":quarter},
            {"kind":"line","from":[4,3],"to":[0,3]},
            {"kind":"arc","center":[0,1.5],"r":1.5,"start":quarter,"end":3.0 * quarter}]}),
        json!({"kind":"profile","segments":[
            {"kind":"arc","center":[0,0],"r":3,"start":0.2,"end":3.0},
            {"kind":"line","from":[-2.969977490829282,0.4233600241796016],"to":[2.940199733523725,0.5960079923851836]}]}),
        json!({"kind":"bspline","degree":1,"periodic":true,
               "points":[[0,0],[3,-1],[5,1],[4,4],[1,3]]}),
        json!({"kind":"bspline","degree":3,
               "points":[[0,0],[1,-1],[2,-1],[3,0],[3.5,1],[3,2],[2,3],[0,2],[0,0]],
               "knots":[0,0,0,0,0.2,0.4,0.4,0.4,0.7,1,1,1,1]}),
        json!({"kind":"bspline","degree":2,
               "points":[[0,0],[2,-1],[4,0],[3,2],[1,2],[0,0]]}),
    ];
    for (k, doc) in made.into_iter().enumerate() {
        let path = file_of(&doc, &dir, &format!("made{k}.json"));
        docs.push((doc, path));
    }
    for (doc, path) in &docs {
        check_one_curve(doc, path);
    }
}

/// The boundary documents of a region file (or of a closed curve taken as a region).
fn boundaries(doc: &Value) -> Vec<Value> {
    if doc["kind"] == "region" {
        std::iter::once(doc["outer"].clone())
            .chain(doc.get("holes").map(arr).into_iter().flatten().cloned())
            .collect()
    } else {
        vec![doc.clone()]
    }
}

#[test]
fn medial_feet_are_in_each_boundarys_own_parameter() {
    let dir = tempfile::tempdir().unwrap();
    let docs = [
        json!({"kind":"ellipse","a":3,"b":1.5,"center":[1,0.5]}),
        json!({"kind":"limacon","a":4,"b":2.5}),
        json!({"kind":"convexities","p":2,"eps":0.2,"m":3}),
        json!({"kind":"elliptic_lemniscate","a":3,"b":2}),
        json!({"kind":"bspline","degree":3,"periodic":true,
               "points":[[0,0],[2,-1],[4,0],[4,2],[2,1.2],[0,2]]}),
        json!({"kind":"bspline","degree":1,"periodic":true,
               "points":[[0,0],[3,-1],[5,1],[4,4],[1,3]]}),
        json!({"kind":"region","outer":{"kind":"bspline","degree":2,"periodic":true,
                   "points":[[0,0],[6,0],[6,4],[0,4]]},
               "holes":[{"kind":"circle","r":0.6,"center":[3,2]}]}),
        serde_json::from_str(&std::fs::read_to_string(fixture("region-pocket.json")).unwrap())
            .unwrap(),
        serde_json::from_str(&std::fs::read_to_string(fixture("clamped_closed.json")).unwrap())
            .unwrap(),
    ];
    for (k, doc) in docs.iter().enumerate() {
        let path = file_of(doc, &dir, &format!("region{k}.json"));
        let axis = curvekit_json(&["medial", &path]);
        let bounds = boundaries(doc);
        let size = bounds.iter().map(size_of).fold(0.0, f64::max);
        let mut checked = 0;
        for e in arr(&axis["edges"]) {
            for (((xy, r), feet), on) in arr(&e["xy"])
                .iter()
                .zip(arr(&e["radius"]))
                .zip(arr(&e["feet"]))
                .zip(arr(&e["boundary"]))
            {
                for s in 0..2 {
                    let b = &bounds[on[s].as_u64().unwrap() as usize];
                    let (lo, hi) = domain(b);
                    let u = num(&feet[s]);
                    assert!(
                        (lo..=hi).contains(&u),
                        "{path}: foot {u} outside [{lo}, {hi}]"
                    );
                    let d = dist(eval(b, u), pt(xy));
                    testkit::assert_near!(
                        d,
                        num(r),
                        1e-7 * size,
                        "{path}: foot {u} is {d} from its vertex, radius {}",
                        num(r)
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 0, "{path}: no feet");
    }
}

/// Asserts that every point of the bisector document `bis` is as far from its foot on
/// `first` as from its foot on `second`, each foot evaluated at the document's parameter
/// (`tr`); the points checked.
fn equidistant_points(bis: &Value, first: &Value, second: &Value) -> usize {
    let mut seen = 0;
    for br in arr(&bis["branches"]) {
        for (tr, xy) in arr(&br["tr"]).iter().zip(arr(&br["xy"])) {
            let (p, q) = (eval(first, num(&tr[0])), eval(second, num(&tr[1])));
            let (dp, dq) = (dist(p, pt(xy)), dist(q, pt(xy)));
            testkit::assert_near!(dp, dq, 1e-6 * (dp + dq), "{tr:?}: {dp} vs {dq}");
            seen += 1;
        }
    }
    seen
}

#[test]
fn bisectors_and_tangents_of_arcs_are_in_the_arcs_angle() {
    let dir = tempfile::tempdir().unwrap();
    let arc = json!({"kind":"arc","center":[0,0],"r":2,"start":0.3,"end":2.8});
    let other = json!({"kind":"line","from":[-3,-1],"to":[3,-1.5]});
    let (a, b) = (
        file_of(&arc, &dir, "arc.json"),
        file_of(&other, &dir, "line.json"),
    );
    let bis = curvekit_json(&["bisector", &a, &b]);
    assert!(equidistant_points(&bis, &arc, &other) > 0);
    // An analytic shape's self-bisector, in its angle.
    let limacon = json!({"kind":"limacon","a":4,"b":2.5});
    let l = file_of(&limacon, &dir, "limacon.json");
    let bis = curvekit_json(&["bisector", &l]);
    assert!(equidistant_points(&bis, &limacon, &limacon) > 0);
    let circle = json!({"kind":"circle","r":1,"center":[0,3]});
    let c = file_of(&circle, &dir, "circle.json");
    let tan = curvekit_json(&["tangents", &a, &c]);
    for l in arr(&tan["lines"]) {
        assert!(dist(eval(&arc, num(&l["s"])), pt(&l["p"])) <= 1e-9);
        assert!(dist(eval(&circle, num(&l["t"])), pt(&l["q"])) <= 1e-9);
    }
}

/// A symmetric teardrop (a clamped cubic closed by its points, its tip a corner where its ends
/// meet) has the pair from its tip to the far end of its axis, and the pair across its waist;
/// written as one spline or as a profile of two Béziers, the same pairs.
#[test]
fn a_teardrops_corner_pair_is_found_either_way_it_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let one = json!({"kind":"bspline","degree":3,
                     "points":[[0,0],[3,2],[6,1.5],[6,-1.5],[3,-2],[0,0]]});
    let two = json!({"kind":"profile","segments":[
        {"kind":"bezier","points":[[0,0],[3,2],[6,1.5],[6,0]]},
        {"kind":"bezier","points":[[6,0],[6,-1.5],[3,-2],[0,0]]}]});
    for (k, doc) in [one, two].iter().enumerate() {
        let path = file_of(doc, &dir, &format!("tear{k}.json"));
        let found = curvekit_json(&["antipodal", &path]);
        assert_eq!(found["certified"], true, "{path}: {found}");
        let pairs = arr(&found["pairs"]);
        assert_eq!(pairs.len(), 2, "{path}: {found}");
        let tip = pairs
            .iter()
            .find(|p| p["corner"][0] == true || p["corner"][1] == true)
            .unwrap_or_else(|| panic!("{path}: no corner pair in {found}"));
        // Along the axis of symmetry: both ends on y = 0.
        assert!(
            pt(&tip["p"])[1].abs() < 1e-12 && pt(&tip["q"])[1].abs() < 1e-12,
            "{tip}"
        );
        check_one_curve(doc, &path);
    }
}

/// A cubic B-spline with a knot of full multiplicity where it turns by 63° lists that corner
/// (at the knot, in its own parameter, with its turn), certified; where the legs either side
/// of such a knot are collinear there is no corner.
#[test]
fn a_corner_at_a_knot_of_full_multiplicity_is_listed() {
    let dir = tempfile::tempdir().unwrap();
    let turn = 63f64.to_radians();
    let (c, s) = (turn.cos(), turn.sin());
    let points = |c: f64, s: f64| {
        json!([
            [0, 0],
            [1, 0.3],
            [2, 0.3],
            [3, 0],
            [3.0 + c, s],
            [3.0 + 2.0 * c, 2.0 * s + 0.3],
            [3.0 + 3.0 * c, 3.0 * s]
        ])
    };
    let knots = json!([0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1]);
    let sharp = json!({"kind":"bspline","degree":3,"points":points(c, s),"knots":knots});
    let path = file_of(&sharp, &dir, "sharp.json");
    let found = curvekit_json(&["inflections", &path]);
    assert_eq!(found["certified"], true, "{found}");
    let corners = arr(&found["corners"]);
    assert_eq!(corners.len(), 1, "{found}");
    assert_eq!(num(&corners[0]["u"]), 0.5);
    // (The legs either side of the knot: (3, 0) − (2, 0.3) and (3 + c, s) − (3, 0).)
    let (din, dout) = ([1.0, -0.3], [c, s]);
    let want = (din[0] * dout[1] - din[1] * dout[0]).atan2(din[0] * dout[0] + din[1] * dout[1]);
    testkit::assert_near!(num(&corners[0]["turn"]), want, 1e-12, "{found}");
    check_one_curve(&sharp, &path);
    let straight = json!({"kind":"bspline","degree":3,"knots":knots,
        "points":[[0, 0], [1, 0.3], [2, 0.3], [3, 0.0], [4, -0.3], [5, 0], [6, 0.5]]});
    let path = file_of(&straight, &dir, "straight.json");
    let found = curvekit_json(&["inflections", &path]);
    assert!(
        found.get("corners").is_none_or(|c| arr(c).is_empty()),
        "{found}"
    );
}
