//! SVG drawings read as a renderer draws them (issue 38, the contract's "Parameters, sizes and
//! drawings"): subpaths closed with or without `Z`, tiny closing gaps closed within the
//! precision the numbers are written to, fill rules deciding the holes across elements,
//! `<use>`, elements not drawn, multi-part drawings, what is skipped and the units. Each
//! reading is compared with the same geometry written another way (metamorphic), or with the
//! region as the fill rule defines it.
#![allow(clippy::unwrap_used)]

mod common;
#[path = "../crates/medial/tests/common/graph.rs"]
mod graph;

use common::curvekit_json;
use curvekit::curve::{ParamCurve, Profile, Region, SegmentKind, V2};
use curvekit::geometry::NearestPoint;
use curvekit::io::{parse_region, read_curve_picked, CurveKind, DrawingFormat};
use numeric::certificate::Verdict;
use proptest::prelude::*;
use serde_json::Value;
use std::io::Write;

fn svg(body: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">{body}</svg>"#
    )
}

fn file_of(text: &str) -> tempfile::NamedTempFile {
    let mut f = tempfile::Builder::new().suffix(".svg").tempfile().unwrap();
    f.write_all(text.as_bytes()).unwrap();
    f
}

/// The parts (regions) a drawing's body makes.
fn parts_of(body: &str) -> Vec<Region> {
    let c = parse_region(
        "t.svg",
        Some(DrawingFormat::Svg),
        svg(body).as_bytes(),
        None,
    )
    .unwrap_or_else(|e| panic!("{body}: {e}"));
    match c.shape {
        CurveKind::Region(r) => vec![*r],
        CurveKind::Regions(parts) => parts,
        other => panic!("not regions: {other:?}"),
    }
}

fn profile_of(body: &str) -> Profile {
    let f = file_of(&svg(body));
    match read_curve_picked(f.path(), None).unwrap().shape {
        CurveKind::Profile(p) => *p,
        other => panic!("not a profile: {other:?}"),
    }
}

/// Points along a profile, 16 a segment.
fn samples(p: &Profile) -> Vec<V2> {
    let n = p.segments().len() * 16;
    (0..=n).map(|k| p.jet(k as f64 / 16.0).p).collect()
}

fn same_points(a: &Profile, b: &Profile, tol: f64) {
    assert_eq!(a.segments().len(), b.segments().len());
    for (p, q) in samples(a).into_iter().zip(samples(b)) {
        assert!((p - q).norm() <= tol, "{p:?} vs {q:?}");
    }
}

#[test]
fn a_subpath_back_at_its_start_is_closed_with_or_without_z() {
    let with_z = profile_of(r#"<path d="M0 0 L10 0 L10 10 L0 10 Z"/>"#);
    let back = profile_of(r#"<path d="M0 0 L10 0 L10 10 L0 10 L0 0"/>"#);
    let back_z = profile_of(r#"<path d="M0 0 L10 0 L10 10 L0 10 L0 0 Z"/>"#);
    for p in [&with_z, &back, &back_z] {
        assert!(p.is_closed());
        assert_eq!((p.segments().len(), p.corners().count()), (4, 4));
    }
    same_points(&with_z, &back, 0.0);
    same_points(&with_z, &back_z, 0.0);
    // Drawn with a stroke only, the same subpath is closed too (it comes back); one that does
    // not come back stays open.
    let stroked =
        profile_of(r#"<path fill="none" stroke="black" d="M0 0 L10 0 L10 10 L0 10 L0 0"/>"#);
    assert!(stroked.is_closed());
    let open = profile_of(r#"<path fill="none" stroke="black" d="M0 0 L10 0 L10 10 L0 10"/>"#);
    assert!(!open.is_closed());
    // Filled, an open subpath is filled as closed (by a line, as SVG fills it).
    let filled = profile_of(r#"<path d="M0 0 L10 0 L10 10 L0 10"/>"#);
    assert!(filled.is_closed());
    same_points(&with_z, &filled, 0.0);
}

#[test]
fn closing_gaps_within_the_written_precision_are_closed_and_beyond_it_are_lines() {
    // Relative commands written to two decimals come back 0.01 off: within the rounding of
    // the 6 numbers written, the subpath closes there (its last segment ends at the start);
    // written in full, the same gap is a line of its own.
    let rounded = profile_of(r#"<path d="M0 0 l10 0 l0 10.01 l-10 -10 Z"/>"#);
    assert_eq!(
        rounded.segments().len(),
        3,
        "the 0.01 gap is closed, not drawn"
    );
    assert_eq!(rounded.segments()[2].end(), V2::new(0.0, 0.0));
    let full = profile_of(r#"<path d="M0 0 l10 0 l0 10.0000001 l-10 -10 Z"/>"#);
    assert_eq!(full.segments().len(), 3, "1e-7 within its precision");
    let drawn = profile_of(r#"<path d="M0 0 l10 0 l0 10.5 l-10 -10 Z"/>"#);
    assert_eq!(drawn.segments().len(), 4, "a gap of 0.5 is drawn by Z");
    // An arc that ends off the start moves the line after it instead (arcs stay circular).
    let arc = profile_of(r#"<path d="M10 0 L20 0 L20 10 L10.01 10 A5 5 0 0 1 10.01 0 Z"/>"#);
    assert_eq!(arc.segments().len(), 4);
    assert!(arc.segments().iter().any(|s| s.kind() == SegmentKind::Arc));
}

#[test]
fn degenerate_pieces_are_their_lines_and_handles_on_ends_keep_speed() {
    // A quadratic with its control point on its start is the straight line it draws.
    let q = profile_of(r#"<path d="M0 0 Q0 0 10 0 L10 10 L0 10 Z"/>"#);
    assert_eq!(q.segments()[0].kind(), SegmentKind::Line);
    // A cubic whose first handle is on its start: its point moves off by half a unit in the
    // last place written (0.005 here), so it has speed there, and the curve moves by less.
    let c = profile_of(r#"<path d="M0 0 C0 0 5 8 10 0 L10 -5.00 L0 -5 Z"/>"#);
    let seg = &c.segments()[0];
    assert_eq!(seg.kind(), SegmentKind::Bezier);
    assert!(seg.curve().jet(0.0).d1.norm() > 0.0);
    let p1 = V2::from_arr(seg.curve().control_points()[1]);
    assert!(
        p1.norm() <= 0.005 * (1.0 + 1e-12) && p1.norm() > 0.0,
        "{p1:?}"
    );
}

#[test]
fn an_arc_just_reaching_across_its_chord_meets_its_lines_without_a_corner() {
    // Radius 5 across a chord of exactly 10 (written so that the radius ratio rounds either
    // way): the half circle is tangent to the lines either side, a stadium's end.
    for d in [
        "M0 0 L20 0 A5 5 0 0 1 20 10 L0 10 Z",
        "M0.1 0.3 L20.1 0.3 A5 5 0 0 1 20.1 10.3 L0.1 10.3 Z",
        "M1000.7 0.3 L1020.7 0.3 a5 5 0 0 1 0 10 L1000.7 10.3 Z",
        "M0.1 0.3 L20.1 0.3 A4.99 4.99 0 0 1 20.1 10.3 L0.1 10.3 Z",
    ] {
        let p = profile_of(&format!(r#"<path d="{d}"/>"#));
        let corners = p.corners().count();
        assert_eq!(corners, 2, "{d}: {:?}", p.joints());
    }
}

#[test]
fn fill_rules_decide_the_holes() {
    let outer_ccw = "M0 0 L0 10 L10 10 L10 0 Z";
    let inner_same = "M3 3 L3 7 L7 7 L7 3 Z";
    let inner_other = "M3 3 L7 3 L7 7 L3 7 Z";
    // nonzero (the default): an inner loop run the same way adds to the winding (no hole);
    // run the other way it cancels it (a hole).
    let same = parts_of(&format!(r#"<path d="{outer_ccw} {inner_same}"/>"#));
    assert_eq!((same.len(), same[0].holes().len()), (1, 0));
    let other = parts_of(&format!(r#"<path d="{outer_ccw} {inner_other}"/>"#));
    assert_eq!((other.len(), other[0].holes().len()), (1, 1));
    // evenodd: a hole either way.
    for inner in [inner_same, inner_other] {
        let r = parts_of(&format!(
            r#"<path fill-rule="evenodd" d="{outer_ccw} {inner}"/>"#
        ));
        assert_eq!((r.len(), r[0].holes().len()), (1, 1));
    }
    // In a style, and inherited from a group.
    let styled = parts_of(&format!(
        r#"<g style="fill-rule:evenodd"><path d="{outer_ccw} {inner_same}"/></g>"#
    ));
    assert_eq!(styled[0].holes().len(), 1);
    // Across elements the fills are united: a second element inside the first's fill adds
    // nothing (no hole), and one inside its hole is a part of its own.
    let united = parts_of(&format!(
        r#"<path d="{outer_ccw}"/><path d="{inner_other}"/>"#
    ));
    assert_eq!((united.len(), united[0].holes().len()), (1, 0));
    let island = parts_of(&format!(
        r#"<path fill-rule="evenodd" d="{outer_ccw} {inner_same}"/><path d="M4 4 L6 4 L6 6 L4 6 Z"/>"#
    ));
    assert_eq!(island.len(), 2);
    assert_eq!((island[0].holes().len(), island[1].holes().len()), (1, 0));
}

#[test]
fn elements_not_drawn_and_use_are_read_as_drawn() {
    // An icon's bounding box written with neither fill nor stroke is not drawn: the region is
    // the shape inside it, not a box with a hole.
    let icon = parts_of(r#"<path fill="none" d="M0 0h24v24H0z"/><circle cx="12" cy="12" r="5"/>"#);
    assert_eq!((icon.len(), icon[0].holes().len()), (1, 0));
    // A <use> places its element, moved by x, y and its transform.
    let used = parts_of(
        r##"<defs><circle id="dot" r="1"/></defs><use href="#dot" x="3" y="4"/>
           <use xlink:href="#dot" transform="translate(10 0)"/>"##,
    );
    assert_eq!(used.len(), 2);
    let centre = |r: &Region| {
        let p = r.outer();
        let a = p.jet(0.0).p;
        let b = p.jet(p.internal_param(0.5 * p.document_domain().1)).p;
        (a + b) * 0.5
    };
    let mut centres: Vec<V2> = used.iter().map(centre).collect();
    centres.sort_by(|a, b| a.x.total_cmp(&b.x));
    assert!(
        (centres[0] - V2::new(3.0, 4.0)).norm() < 1e-12,
        "{centres:?}"
    );
    assert!(
        (centres[1] - V2::new(10.0, 0.0)).norm() < 1e-12,
        "{centres:?}"
    );
    // display: none hides a subtree.
    let hidden = parts_of(r#"<g style="display:none"><circle r="3"/></g><circle cx="10" r="1"/>"#);
    assert_eq!(hidden.len(), 1);
}

/// The JSON of `medial` on an SVG body.
fn medial_json(body: &str) -> Value {
    let f = file_of(&svg(body));
    curvekit_json(&["medial", f.path().to_str().unwrap()])
}

#[test]
fn drawings_say_what_they_skipped_and_their_units() {
    let d = medial_json(r#"<text x="1" y="1">A</text><text>B</text><rect width="10" height="6"/>"#);
    assert_eq!(
        d["skipped"],
        serde_json::json!([{"type": "text", "count": 2}])
    );
    assert_eq!(d["certified"], true);
    assert!(d.get("units").is_none());
    // An open stroke in a drawing of regions could be part of an outline: skipped, and the
    // answer is not certified, saying why.
    let d = medial_json(
        r#"<rect width="10" height="6"/><path fill="none" stroke="red" d="M20 0 L30 5"/>"#,
    );
    assert_eq!(d["skipped"][0]["type"], "open chain");
    assert_eq!(d["certified"], false);
    assert!(d["reason"].as_str().unwrap().contains("open"), "{d}");
    // A drawing in millimetres.
    let mm = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50"><rect width="10" height="6"/></svg>"#;
    let f = file_of(mm);
    let d = curvekit_json(&["medial", f.path().to_str().unwrap()]);
    assert_eq!(d["units"], "mm");
}

#[test]
fn several_parts_are_one_input_to_medial_and_offset() {
    let body = r#"<path d="M0 0 H10 V10 H0 Z M20 0 H30 V10 H20 Z"/>"#;
    let d = medial_json(body);
    let parts: Vec<u64> = d["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n["part"].as_u64().unwrap())
        .collect();
    assert!(parts.contains(&0) && parts.contains(&1));
    assert!(d["edges"]
        .as_array()
        .unwrap()
        .iter()
        .all(|e| e["part"].is_u64()));
    // A square's axis is an X: 5 nodes, 4 edges, per part.
    assert_eq!(d["nodes"].as_array().unwrap().len(), 10);
    let f = file_of(&svg(body));
    let o = curvekit_json(&["offset", f.path().to_str().unwrap(), "--distance", "1"]);
    let loops = o["offsets"][0]["loops"].as_array().unwrap();
    assert_eq!(loops.len(), 2);
    assert_eq!(loops[0]["part"], 0);
    assert_eq!(loops[1]["part"], 1);
    // The one-curve commands ask for a part.
    let run = common::curvekit(&["antipodal", f.path().to_str().unwrap()]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("--pick"), "{}", run.stderr);
    // Outlines that cross are refused, naming where.
    let g = file_of(&svg(r#"<circle r="5"/><circle cx="6" r="5"/>"#));
    let run = common::curvekit(&["medial", g.path().to_str().unwrap()]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("cross"), "{}", run.stderr);
}

proptest! {
    /// Metamorphic: a polygon written with `Z`, without it (coming back), with absolute or
    /// relative commands, or with a transform applied or written out, is one profile.
    #[test]
    fn one_polygon_written_many_ways(
        pts in proptest::collection::vec((0.0f64..1.0, 1.0f64..3.0), 3..9),
        relative in any::<bool>(),
        with_z in any::<bool>(),
        shift in (-100.0f64..100.0, -100.0f64..100.0),
    ) {
        // A star-shaped polygon about the origin (no crossing), counterclockwise.
        let n = pts.len();
        let total: f64 = pts.iter().map(|p| p.0 + 0.2).sum();
        let mut acc = 0.0;
        let v: Vec<V2> = pts
            .iter()
            .map(|&(step, r)| {
                let a = std::f64::consts::TAU * acc / total;
                acc += step + 0.2;
                V2::polar(a) * r
            })
            .collect();
        let write = |offset: V2, relative: bool, with_z: bool| {
            let mut d = format!("M{:?} {:?}", v[0].x + offset.x, v[0].y + offset.y);
            let mut at = v[0];
            for k in 1..=n {
                let p = v[k % n];
                if k == n && with_z {
                    break;
                }
                if relative {
                    d.push_str(&format!(" l{:?} {:?}", p.x - at.x, p.y - at.y));
                } else {
                    d.push_str(&format!(" L{:?} {:?}", p.x + offset.x, p.y + offset.y));
                }
                at = p;
            }
            if with_z {
                d.push_str(" Z");
            }
            d
        };
        let plain = profile_of(&format!(r#"<path d="{}"/>"#, write(V2::new(0.0, 0.0), false, true)));
        let other = profile_of(&format!(r#"<path d="{}"/>"#, write(V2::new(0.0, 0.0), relative, with_z)));
        prop_assert!(other.is_closed());
        same_points(&plain, &other, 1e-12);
        let moved = V2::new(shift.0, shift.1);
        let written_out = profile_of(&format!(r#"<path d="{}"/>"#, write(moved, false, with_z)));
        let transformed = profile_of(&format!(
            r#"<g transform="translate({:?} {:?})"><path d="{}"/></g>"#,
            shift.0, shift.1, write(V2::new(0.0, 0.0), relative, with_z)
        ));
        same_points(&written_out, &transformed, 1e-12 * (1.0 + shift.0.abs() + shift.1.abs()));
    }
}

/// Asserts that `p`'s antipodal pairs are certified and that the longest is as long as its
/// diameter (sampled); the pairs, and the longest's length. `case` heads a failure's message.
fn longest_pair_is_the_diameter(p: &Profile, case: &str) -> (curvekit::antipodal::Antipodal, f64) {
    let r = curvekit::antipodal::antipodal(p, &Default::default()).unwrap();
    assert!(r.certified(), "{case}{:?}", r.reason());
    let longest = r.pairs.iter().map(|q| q.distance).fold(0.0, f64::max);
    let diameter = sampled_diameter(p);
    testkit::assert_near!(
        longest,
        diameter,
        1e-9 * diameter,
        "{case}{longest} vs {diameter}"
    );
    (r, longest)
}

/// The diameter of a closed profile by dense sampling and local refinement (golden-section
/// on each coordinate in turn from the best sampled pair): an oracle independent of the
/// antipodal search.
fn sampled_diameter(p: &Profile) -> f64 {
    let (a, b) = p.domain();
    let n = 4000;
    let at = |k: usize| a + (b - a) * k as f64 / n as f64;
    let points: Vec<V2> = (0..n).map(|k| p.jet(at(k)).p).collect();
    let mut best = (0.0, 0, 0);
    for i in 0..n {
        for j in i + 1..n {
            let d = (points[i] - points[j]).norm();
            if d > best.0 {
                best = (d, i, j);
            }
        }
    }
    let step = (b - a) / n as f64;
    let (mut s, mut t) = (at(best.1), at(best.2));
    let dist = |s: f64, t: f64| (p.jet(s.clamp(a, b)).p - p.jet(t.clamp(a, b)).p).norm();
    for _ in 0..20 {
        for which in 0..2 {
            let (mut lo, mut hi) = if which == 0 {
                (s - step, s + step)
            } else {
                (t - step, t + step)
            };
            for _ in 0..60 {
                let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
                let f = |x: f64| if which == 0 { dist(x, t) } else { dist(s, x) };
                if f(m1) < f(m2) {
                    lo = m1;
                } else {
                    hi = m2;
                }
            }
            if which == 0 {
                s = 0.5 * (lo + hi)
            } else {
                t = 0.5 * (lo + hi)
            }
        }
    }
    dist(s, t).max(best.0)
}

/// Heroicons' sparkle (arcs at its tips, written to three decimals, so each tip is a corner
/// of a few 1e-4 rad): its diameter runs from the corner at its top tip to the middle of its
/// bottom tip's arc, a knot of the arc's rational form. Found and certified, from whichever
/// point the path starts; its facing parallel sides, which do not overlap, leave the
/// certificate alone.
#[test]
fn a_diameter_from_a_corner_to_an_arcs_middle_is_found_and_certified() {
    let tips = "a.75.75 0 0 1 .721.544l.813 2.846a3.75 3.75 0 0 0 2.576 2.576l2.846.813a.75.75 0 0 1 0 1.442l-2.846.813a3.75 3.75 0 0 0-2.576 2.576l-.813 2.846a.75.75 0 0 1-1.442 0l-.813-2.846a3.75 3.75 0 0 0-2.576-2.576l-2.846-.813a.75.75 0 0 1 0-1.442l2.846-.813A3.75 3.75 0 0 0 7.466 7.89l.813-2.846A.75.75 0 0 1 9 4.5";
    let top = format!(r#"<path d="M9 4.5{tips}Z"/>"#);
    let side = r#"<path d="M9.721 5.044l.813 2.846a3.75 3.75 0 0 0 2.576 2.576l2.846.813a.75.75 0 0 1 0 1.442l-2.846.813a3.75 3.75 0 0 0-2.576 2.576l-.813 2.846a.75.75 0 0 1-1.442 0l-.813-2.846a3.75 3.75 0 0 0-2.576-2.576l-2.846-.813a.75.75 0 0 1 0-1.442l2.846-.813A3.75 3.75 0 0 0 7.466 7.89l.813-2.846A.75.75 0 0 1 9 4.5a.75.75 0 0 1 .721.544Z"/>"#;
    for body in [top.as_str(), side] {
        let p = profile_of(body);
        let (r, longest) = longest_pair_is_the_diameter(&p, "");
        let top_tip = r
            .pairs
            .iter()
            .find(|q| (q.distance - longest).abs() <= 1e-12 * longest)
            .unwrap();
        let ends = [top_tip.p, top_tip.q];
        assert!(
            ends.iter()
                .any(|e| (V2::from_arr(*e) - V2::new(9.0, 4.5)).norm() < 1e-12),
            "{top_tip:?}"
        );
    }
    // Metamorphic: moved far from the origin, scaled, rotated and mirrored (its orientation
    // reversed), it is still certified with the diameter as its longest pair.
    for transform in [
        "translate(30000 -10000)",
        "scale(1000)",
        "scale(0.001)",
        "rotate(37)",
        "scale(-1 1)",
    ] {
        let moved = profile_of(&format!(r#"<g transform="{transform}">{top}</g>"#));
        longest_pair_is_the_diameter(&moved, &format!("{transform}: "));
    }
}

/// phosphor's `pinterest-logo-fill` (issue 38): its outline starts with a cubic that meets
/// the closing arc (radius 104) nearly tangentially. Their bisector is traced from the joint
/// straight to far off, where its feet meet again; the search for the end of the joint's
/// stretch took that meeting for its end and put a node at the arc's centre with radius 104,
/// 3.6 from the boundary, on an edge of its own. Every node is at its distance from the
/// boundary, and the axis is one piece.
#[test]
fn a_joints_leaf_does_not_end_at_a_far_centre_of_curvature() {
    let body = r#"<path d="M240,128.7c-.38,56.49-46.46,102.73-102.94,103.29a104.16,104.16,0,0,1-25.94-3,4,4,0,0,1-2.91-4.86l8.64-34.55A60.57,60.57,0,0,0,144,196c37,0,66.7-33.45,63.81-73.36A72,72,0,1,0,69.24,155,8,8,0,0,0,80,159.29a8.19,8.19,0,0,0,4-10.49,56,56,0,1,1,107.86-24.93C194,154.4,171.73,180,144,180a44.87,44.87,0,0,1-23.14-6.44l14.9-59.62a8,8,0,0,0-15.52-3.88L93.38,217.51a4,4,0,0,1-5.71,2.59A104,104,0,0,1,32,126.88C32.6,70.52,78.67,24.52,135,24A104,104,0,0,1,240,128.7Z"/>"#;
    let region = parts_of(body).remove(0);
    let axis = curvekit::medial::medial_axis(&region, &Default::default()).unwrap();
    let size = region.size();
    for n in &axis.nodes {
        let d = region.outer().nearest(n.xy, 0.0).distance;
        testkit::assert_near!(
            d,
            n.radius,
            1e-6 * size,
            "node at {:?}: radius {}, distance {d}",
            n.xy,
            n.radius
        );
    }
    assert_eq!(graph::components_and_cycles(&axis).0, 1);
}
