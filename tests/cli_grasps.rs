//! `curvekit grasps`: its JSON document has the contract's fields, and what it says is checked
//! against the ellipse's closed form (Nguyen's force-closure condition evaluated directly, on
//! a grid of pairs and over each contact region); its text and figure are written; bad
//! options and curves it does not take are refused by name.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit, curvekit_json, fixture};
use serde_json::Value;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The friction coefficient of the tests, as the papers' examples take it.
const MU: f64 = 0.3;

/// `fixtures/ellipse.json`: semi-axes and centre.
const ELLIPSE: (f64, f64, [f64; 2]) = (3.0, 1.5, [1.0, 0.5]);

/// Pairs whose force-closure margin (in cosine) is within this of 0 are not judged on the
/// grid: the regions' polylines are within the chord tolerance of their true boundaries, and
/// this keeps the grid's pairs several chord tolerances inside or outside.
const GRID_MARGIN: f64 = 0.01;

/// How far a contact region's pairs may fall outside the cones (in cosine): rounding of the
/// closed form, far below any error the contact regions could make.
const ROUNDING: f64 = 1e-12;

/// How close the best grasp of a region holding an antipodal pair is to it (parameters,
/// and `min_friction` from 0): the pairs of an ellipse's axes are found to rounding.
const AT_PAIR: f64 = 1e-9;

/// Grid points per side of the parameter square.
const GRID: usize = 160;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn pair(v: &Value) -> [f64; 2] {
    let a = v.as_array().unwrap();
    assert_eq!(a.len(), 2, "{v}");
    [num(&a[0]), num(&a[1])]
}

fn keys(v: &Value) -> Vec<&str> {
    let mut k: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    k.sort_unstable();
    k
}

/// The ellipse's point at `u`.
fn point(u: f64) -> [f64; 2] {
    let (a, b, c) = ELLIPSE;
    [c[0] + a * u.cos(), c[1] + b * u.sin()]
}

/// The ellipse's inward unit normal at `u` (it runs counterclockwise).
fn inward(u: f64) -> [f64; 2] {
    let (a, b, _) = ELLIPSE;
    let n = [-b * u.cos(), -a * u.sin()];
    let l = n[0].hypot(n[1]);
    [n[0] / l, n[1] / l]
}

/// The cosines of the chord's angles with the inward normals at `s` and at `t`.
fn cosines(s: f64, t: f64) -> [f64; 2] {
    let (p, q) = (point(s), point(t));
    let d = [q[0] - p[0], q[1] - p[1]];
    let l = d[0].hypot(d[1]);
    let (ns, nt) = (inward(s), inward(t));
    [
        (ns[0] * d[0] + ns[1] * d[1]) / l,
        -(nt[0] * d[0] + nt[1] * d[1]) / l,
    ]
}

/// How far `(s, t)` is inside both friction cones, in cosine (negative: outside one).
fn margin(s: f64, t: f64, mu: f64) -> f64 {
    let [cs, ct] = cosines(s, t);
    cs.min(ct) - mu.atan().cos()
}

/// The least friction for which `(s, t)` is force closure (the tangent of the larger angle).
fn least_friction(s: f64, t: f64) -> f64 {
    let [cs, ct] = cosines(s, t);
    cs.min(ct).clamp(-1.0, 1.0).acos().tan()
}

/// Whether `(x, y)` lies inside the closed polyline `poly` (even-odd).
fn inside(poly: &[[f64; 2]], [x, y]: [f64; 2]) -> bool {
    let mut c = false;
    for (k, &[x1, y1]) in poly.iter().enumerate() {
        let [x2, y2] = poly[(k + poly.len() - 1) % poly.len()];
        if (y1 > y) != (y2 > y) && x < x1 + (y - y1) * (x2 - x1) / (y2 - y1) {
            c = !c;
        }
    }
    c
}

fn polylines(v: &Value) -> Vec<Vec<[f64; 2]>> {
    v.as_array()
        .map(|ls| {
            ls.iter()
                .map(|l| l.as_array().unwrap().iter().map(pair).collect())
                .collect()
        })
        .unwrap_or_default()
}

/// Whether the pair lies in the region: in one of its parts (or its boundary), in no hole.
fn in_region(region: &Value, st: [f64; 2]) -> bool {
    let mut loops = polylines(&region["parts"]);
    if loops.is_empty() {
        loops.push(polylines(&Value::Array(vec![region["boundary"].clone()])).remove(0));
    }
    loops.iter().any(|l| inside(l, st))
        && !polylines(&region["holes"]).iter().any(|h| inside(h, st))
}

/// `u` within `[lo, hi]`, read modulo the period (an interval may run across the seam).
fn within(u: f64, [lo, hi]: [f64; 2]) -> bool {
    [-TAU, 0.0, TAU]
        .iter()
        .any(|k| (lo..=hi).contains(&(u + k)))
}

fn ellipse_grasps(extra: &[&str]) -> Value {
    let f = fixture("ellipse.json");
    let mu = MU.to_string();
    let mut args = vec!["grasps", f.as_str(), "--friction", mu.as_str()];
    args.extend_from_slice(extra);
    curvekit_json(&args)
}

/// The document as the contract names it: `certified`/`complete` at the top, per region its
/// `boundary`, `contact`, `best` and `certified` (with `parts` where it runs across the seam).
#[test]
fn the_ellipse_document_has_the_contract_fields() {
    let d = ellipse_grasps(&[]);
    assert_eq!(
        keys(&d),
        ["certified", "complete", "curve", "friction", "regions"]
    );
    assert_eq!(d["certified"], true);
    assert_eq!(d["complete"], true);
    assert_eq!(num(&d["friction"]), MU);
    let regions = d["regions"].as_array().unwrap();
    assert_eq!(regions.len(), 2);
    for r in regions {
        for k in keys(r) {
            assert!(
                ["best", "boundary", "certified", "contact", "holes", "parts"].contains(&k),
                "{k}"
            );
        }
        assert_eq!(r["certified"], true);
        assert_eq!(keys(&r["best"]), ["min_friction", "p", "q", "s", "t"]);
        assert_eq!(keys(&r["contact"]), ["p", "q", "s", "t"]);
        let boundary = polylines(&Value::Array(vec![r["boundary"].clone()])).remove(0);
        assert!(boundary.len() >= 4);
        for st in &boundary {
            assert!(
                st[0] < st[1] && (0.0..=TAU).contains(&st[0]) && st[1] <= TAU,
                "{st:?}"
            );
        }
    }
}

/// Each region holds one axis pair of the ellipse as its best grasp, of least friction 0; its
/// contact stretches hold it, every pair of them is force closure, and their end points are
/// the curve's.
#[test]
fn the_ellipse_regions_hold_its_axes() {
    let d = ellipse_grasps(&[]);
    let mut axes: Vec<[f64; 2]> = Vec::new();
    for r in d["regions"].as_array().unwrap() {
        let best = &r["best"];
        let (s, t) = (num(&best["s"]), num(&best["t"]));
        assert!(num(&best["min_friction"]).abs() < AT_PAIR, "{best}");
        assert!(least_friction(s, t) < AT_PAIR, "{best}");
        for (u, p) in [(s, &best["p"]), (t, &best["q"])] {
            let (got, want) = (pair(p), point(u));
            assert!(
                (got[0] - want[0]).hypot(got[1] - want[1]) < AT_PAIR,
                "{best}"
            );
        }
        assert!(in_region(r, [s, t]), "{r}");
        axes.push([s, t]);

        let c = &r["contact"];
        let (cs, ct) = (pair(&c["s"]), pair(&c["t"]));
        assert!(cs[0] < cs[1] && ct[0] < ct[1], "{c}");
        assert!(within(s, cs) && within(t, ct), "{best} outside {c}");
        for (ends, points) in [(cs, &c["p"]), (ct, &c["q"])] {
            for (u, p) in ends.iter().zip(points.as_array().unwrap()) {
                let (got, want) = (pair(p), point(*u));
                assert!((got[0] - want[0]).hypot(got[1] - want[1]) < AT_PAIR, "{c}");
            }
        }
        let steps = 24;
        for i in 0..=steps {
            for j in 0..=steps {
                let s = cs[0] + (cs[1] - cs[0]) * i as f64 / steps as f64;
                let t = ct[0] + (ct[1] - ct[0]) * j as f64 / steps as f64;
                assert!(margin(s, t, MU) > -ROUNDING, "({s}, {t}) of {c}");
            }
        }
    }
    // The two axes, each once: (π/2, 3π/2) and (0, π).
    axes.sort_by(|a, b| b[0].total_cmp(&a[0]));
    let want = [[FRAC_PI_2, 3.0 * FRAC_PI_2], [0.0, PI]];
    for (got, want) in axes.iter().zip(want) {
        let off = |x: f64, y: f64| ((x - y + PI).rem_euclid(TAU) - PI).abs();
        assert!(
            off(got[0], want[0]) < AT_PAIR && off(got[1], want[1]) < AT_PAIR,
            "{axes:?}"
        );
    }
}

/// On a grid of pairs `s < t` (those clearly inside or outside), a pair lies in a region
/// exactly when Nguyen's condition holds for it, and in one region at most.
#[test]
fn the_ellipse_regions_are_the_force_closure_pairs() {
    let d = ellipse_grasps(&[]);
    let regions = d["regions"].as_array().unwrap();
    let (mut judged, mut inside_count) = (0, 0);
    for i in 0..GRID {
        for j in i + 1..GRID {
            let st = [
                (i as f64 + 0.5) * TAU / GRID as f64,
                (j as f64 + 0.5) * TAU / GRID as f64,
            ];
            let holding = regions.iter().filter(|r| in_region(r, st)).count();
            assert!(holding <= 1, "{st:?} in {holding} regions");
            let m = margin(st[0], st[1], MU);
            if m.abs() < GRID_MARGIN {
                continue;
            }
            judged += 1;
            inside_count += holding;
            assert_eq!(m > 0.0, holding == 1, "{st:?}: margin {m}");
        }
    }
    // (Not vacuous: most pairs judged, some of them inside.)
    assert!(
        judged > GRID * GRID / 3 && inside_count > 20,
        "{judged}, {inside_count}"
    );
}

/// A gripper that opens at most 4 keeps the minor axis's region only (width 3), one that
/// opens at least 4 the major axis's (width 6); the document says the limits.
#[test]
fn width_limits_keep_the_axis_that_fits() {
    let narrow = ellipse_grasps(&["--max-width", "4"]);
    assert_eq!(num(&narrow["max_width"]), 4.0);
    assert!(narrow.get("min_width").is_none());
    let wide = ellipse_grasps(&["--min-width", "4"]);
    assert_eq!(num(&wide["min_width"]), 4.0);
    for (d, axis) in [(&narrow, [FRAC_PI_2, 3.0 * FRAC_PI_2]), (&wide, [0.0, PI])] {
        let regions = d["regions"].as_array().unwrap();
        assert_eq!(regions.len(), 1, "{d}");
        let best = &regions[0]["best"];
        assert!((num(&best["s"]) - axis[0]).abs() < AT_PAIR, "{best}");
        assert!((num(&best["t"]) - axis[1]).abs() < AT_PAIR, "{best}");
    }
}

/// The text report names each region's best grasp and contact, the figure is SVG that parses
/// with a region's colour in both panels.
#[test]
fn text_and_figure_are_written() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("grasps.svg");
    let f = fixture("ellipse.json");
    let run = curvekit(&[
        "grasps",
        &f,
        "--friction",
        "0.3",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    for needle in [
        "regions:     2",
        "best s = ",
        "contact s ∈ [",
        "certified:   true",
    ] {
        assert!(run.stdout.contains(needle), "{needle}: {}", run.stdout);
    }
    assert_eq!(run.stdout.matches("min friction").count(), 2);
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect();
    assert!(
        texts
            .iter()
            .any(|t| t.contains("grasps at μ = 0.3: 2 regions")),
        "{texts:?}"
    );
    assert!(
        texts.iter().any(|t| t.starts_with("s ∈")) && texts.iter().any(|t| t.starts_with("t ∈"))
    );
    // Each region filled in the square, in the colour of its stretches on the curve.
    let filled: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polygon") && n.attribute("fill") != Some("none"))
        .filter_map(|n| n.attribute("fill"))
        .collect();
    assert!(filled.len() >= 2, "{filled:?}");
    for colour in filled {
        assert!(
            doc.descendants()
                .any(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some(colour)),
            "{colour}"
        );
    }
}

/// Options out of range are usage errors (exit 2) naming the option.
#[test]
fn bad_options_name_the_option() {
    let f = fixture("ellipse.json");
    let cases: &[(&[&str], &str)] = &[
        (&["--friction", "0"], "--friction"),
        (&["--friction", "-0.3"], "--friction"),
        (&["--friction", "nan"], "--friction"),
        (&["--friction", "inf"], "--friction"),
        (&["--friction", "x"], "--friction"),
        (&[], "--friction"),
        (&["--friction", "0.3", "--min-width", "0"], "--min-width"),
        (&["--friction", "0.3", "--max-width", "-1"], "--max-width"),
        (
            &["--friction", "0.3", "--min-width", "2", "--max-width", "2"],
            "--min-width",
        ),
        (&["--friction", "0.3", "--chord-tol", "0.9"], "--chord-tol"),
        (&["--friction", "0.3", "--tol", "0.1"], "--tol"),
    ];
    for (extra, option) in cases {
        let mut args = vec!["grasps", f.as_str()];
        args.extend_from_slice(extra);
        let run = curvekit(&args);
        assert_eq!(run.code, 2, "{args:?}: {}", run.stderr);
        assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
        assert!(run.stderr.contains(option), "{args:?}: {}", run.stderr);
        assert!(run.stdout.is_empty());
    }
}

/// Curves the command does not take are bad input naming the file and the cause: an open
/// curve, a region, a drawing of several profiles. A polygon and a profile with corners are
/// taken (their corners' cones take part).
#[test]
fn curves_it_does_not_take_are_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let square = dir.path().join("square.json");
    std::fs::write(
        &square,
        r#"{"kind":"bspline","degree":1,"points":[[0,0],[2,0],[2,1],[0,1],[0,0]]}"#,
    )
    .unwrap();
    let square = square.to_str().unwrap().to_string();
    for file in [square.clone(), fixture("profile-bracket.json")] {
        let run = curvekit(&["grasps", &file, "--friction", "0.3", "--json"]);
        assert_eq!(run.code, 0, "{file}: {}", run.stderr);
        let d: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
        assert!(!d["regions"].as_array().unwrap().is_empty(), "{file}");
    }
    let cases = [
        (fixture("open_nurbs.json"), "open"),
        (fixture("region-pocket.json"), "not a region"),
        (fixture("drawing-pocket.svg"), "--pick"),
    ];
    for (file, cause) in &cases {
        let run = curvekit(&["grasps", file, "--friction", "0.3"]);
        assert_eq!(run.code, 2, "{file}: {}", run.stderr);
        assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
        assert!(run.stderr.contains(file.as_str()), "{}", run.stderr);
        assert!(run.stderr.contains(cause), "{file}: {}", run.stderr);
        assert!(!run.stderr.contains("panicked"), "{}", run.stderr);
    }
}

/// Under width limits each region's best grasp lies in the region and fits the gripper, and a
/// region of some extent has a contact region (with `--min-width 3.05` the minor axis, width
/// 3, no longer fits). The most robust pair may lie on the width limit (the friction it needs
/// falls toward the excluded axis): on the region's boundary, to the rounding of the width.
#[test]
fn under_width_limits_the_best_grasp_lies_in_its_region() {
    /// How far below the width limit, relative, a best grasp on it may lie: rounding.
    const ON_LIMIT: f64 = 1e-9;
    let d = ellipse_grasps(&["--min-width", "3.05"]);
    let regions = d["regions"].as_array().unwrap();
    assert!(!regions.is_empty());
    for r in regions {
        let best = &r["best"];
        let (p, q) = (pair(&best["p"]), pair(&best["q"]));
        let width = (q[0] - p[0]).hypot(q[1] - p[1]);
        assert!(width >= 3.05 * (1.0 - ON_LIMIT), "{best}");
        let st = [num(&best["s"]), num(&best["t"])];
        let on_limit = width <= 3.05 * (1.0 + ON_LIMIT);
        assert!(in_region(r, st) || on_limit, "{best}");
        assert!(!r["contact"].is_null(), "{r}");
        let c = &r["contact"];
        // The contact region's corners are force closure and fit the gripper.
        for (ps, qs) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            let (a, b) = (pair(&c["p"][ps]), pair(&c["q"][qs]));
            assert!(
                (b[0] - a[0]).hypot(b[1] - a[1]) >= 3.05 * (1.0 - ON_LIMIT),
                "{c}"
            );
        }
    }
}

/// The grasps of one drawing of the corpus at μ = 0.3 (its first outline).
fn drawing_grasps(name: &str) -> Value {
    let f = fixture(&format!("corpus/{name}"));
    curvekit_json(&["grasps", f.as_str(), "--friction", "0.3", "--pick", "0"])
}

/// Font Awesome's octagon: eight straight sides, two of them 0.05° off parallel, its corners
/// short curves meeting the sides with reflex kinks of 0.02°. Its cells of two sides are
/// clipped in closed form: the regions round its four pairs of opposite sides, their
/// outlines a few straight pieces (the subdivision once traced 184,627 vertices for one of
/// them, in 4 s). A finger at a reflex kink takes no part, so the pairs of a corner with it
/// cut the corner's line: four of the regions come apart there, eight in all (they were
/// glued through those pairs, and the count depended on where the outline started). The
/// two beside the kinks without an antipodal pair keep their best grasps unproven.
#[test]
fn a_drawn_octagon_s_regions_have_straight_edges_and_part_at_its_kinks() {
    let d = drawing_grasps("icons/fontawesome-solid/octagon.svg");
    if d["certified"] != true {
        assert_eq!(
            d["reason"],
            "a grasp region's most robust grasp was found by a local search"
        );
    }
    let regions = d["regions"].as_array().unwrap();
    assert_eq!(regions.len(), 8);
    let mut straight = 0;
    let mut antipodal = 0;
    for r in regions {
        assert_eq!(r["certified"], true);
        antipodal += usize::from(num(&r["best"]["min_friction"]) < 1e-12);
        // (A part in a cell of two straight sides, a few straight pieces; the parts reaching
        // the corners' short curved stretches a few dozen vertices each.)
        let boundary: Vec<[f64; 2]> = r["boundary"].as_array().unwrap().iter().map(pair).collect();
        straight += usize::from((4..=8).contains(&boundary.len()));
        for part in polylines(&r["parts"]) {
            assert!(part.len() <= 100, "{} vertices", part.len());
        }
    }
    assert_eq!(straight, 4);
    assert_eq!(antipodal, 6);
}

/// Glyphs whose best grasps lie at a pair of joints their regions reach (the search from
/// inside keeps a chord from the cells' edges): taken there, force closure, proven the most
/// robust, and the results certified.
#[test]
fn glyphs_best_grasps_at_pairs_of_joints_are_proven() {
    for name in [
        "glyphs/cantarell/0070-p.svg",
        "glyphs/dejavu-sans/0032-two.svg",
        "glyphs/roboto/0064-d.svg",
    ] {
        let d = drawing_grasps(name);
        assert_eq!(d["certified"], true, "{name}: {}", d["reason"]);
        for r in d["regions"].as_array().unwrap() {
            assert!(num(&r["best"]["min_friction"]) <= 0.3, "{name}");
        }
    }
}
