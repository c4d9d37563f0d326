//! `curvekit offset`: the contract's document, whose loops are closed profiles the tool reads
//! back, and options checked before the region is read.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit, curvekit_json, fixture};

#[test]
fn each_loop_is_a_closed_profile_the_tool_reads_back() {
    let doc = curvekit_json(&["offset", &fixture("region-pocket.json"), "--step", "0.5"]);
    assert_eq!(doc["certified"], true);
    assert_eq!(doc["complete"], true);
    let offsets = doc["offsets"].as_array().unwrap();
    let distances: Vec<f64> = offsets
        .iter()
        .map(|o| o["distance"].as_f64().unwrap())
        .collect();
    assert_eq!(distances, [0.5, 1.0, 1.5, 2.0, 2.5]);
    let dir = tempfile::tempdir().unwrap();
    for (k, o) in offsets.iter().enumerate() {
        for (j, l) in o["loops"].as_array().unwrap().iter().enumerate() {
            assert_eq!(l["kind"], "profile");
            let path = dir.path().join(format!("loop-{k}-{j}.json"));
            std::fs::write(&path, l.to_string()).unwrap();
            let back = curvekit_json(&["inflections", path.to_str().unwrap()]);
            assert_eq!(back["curve"]["closed"], true, "{l}");
        }
    }
    // (Round the island and round the pocket at first; nothing beyond the widest disk.)
    assert_eq!(offsets[0]["loops"].as_array().unwrap().len(), 2);
    let past = curvekit_json(&["offset", &fixture("region-pocket.json"), "--distance", "9"]);
    assert!(past["offsets"][0]["loops"].as_array().unwrap().is_empty());
}

/// A drawing's splines offset to fitted cubics (with their knots) that the tool reads back,
/// within the chord tolerance where measured. At 40, half the glyph's stroke, its bowl leaves
/// slivers narrower than the tolerance, across which fitted pieces crossed until they were
/// fitted again, finer.
#[test]
fn spline_offsets_are_cubics_the_tool_reads_back() {
    let doc = curvekit_json(&["offset", &fixture("drawing-glyph-d.svg"), "--step", "40"]);
    let dir = tempfile::tempdir().unwrap();
    let mut cubics = 0;
    for (k, o) in doc["offsets"].as_array().unwrap().iter().enumerate() {
        let error = o["error"].as_f64().unwrap();
        assert!(
            (0.0..1.0).contains(&error),
            "d = {}: error {error}",
            o["distance"]
        );
        for (j, l) in o["loops"].as_array().unwrap().iter().enumerate() {
            for s in l["segments"].as_array().unwrap() {
                if s["kind"] == "bspline" && s["degree"] == 3 {
                    let (n, knots) = (
                        s["points"].as_array().unwrap().len(),
                        s["knots"].as_array().unwrap().len(),
                    );
                    assert_eq!(knots, n + 4, "{s}");
                    cubics += 1;
                }
            }
            let path = dir.path().join(format!("loop-{k}-{j}.json"));
            std::fs::write(&path, l.to_string()).unwrap();
            let back = curvekit_json(&["inflections", path.to_str().unwrap()]);
            assert_eq!(back["curve"]["closed"], true, "{l}");
        }
    }
    assert!(cubics > 0, "no fitted cubic in {doc}");
}

#[test]
fn distances_are_checked_before_the_region_is_read() {
    let missing = fixture("no-such-file.json");
    for args in [
        vec!["--distance", "0"],
        vec!["--distance", "-1"],
        vec!["--distances", "1,nan"],
        vec!["--step", "0"],
    ] {
        let mut all = vec!["offset", &missing];
        all.extend(args.iter().copied());
        let run = curvekit(&all);
        assert_eq!(run.code, 2, "{all:?}: {}", run.stderr);
        assert!(
            !run.stderr.contains("no-such-file"),
            "{all:?}: {}",
            run.stderr
        );
    }
    let run = curvekit(&["offset", &fixture("region-pocket.json")]);
    assert_eq!(run.code, 2, "a distance is required");
}

#[test]
fn outward_offsets_grow_the_region() {
    let doc = curvekit_json(&[
        "offset",
        &fixture("region-pocket.json"),
        "--distances",
        "0.5,2",
        "--outward",
    ]);
    let loops = |k: usize| doc["offsets"][k]["loops"].as_array().unwrap().len();
    // (Round the pocket and inside the island's hole; at 2 the hole is filled.)
    assert_eq!((loops(0), loops(1)), (2, 1));
    let far = curvekit(&[
        "offset",
        &fixture("region-pocket.json"),
        "--distance",
        "9",
        "--outward",
    ]);
    assert_eq!(
        far.code, 2,
        "beyond the exterior axis's margin: {}",
        far.stderr
    );
}

/// The issue's plate (issue 38): a 100 × 100 plate with corners rounded by 10 and a hole of
/// radius 35, exactly 15 wide at four points, with an island in the hole. At 7.5 the plate's
/// offset is its four corners touching at those points (closed there): four loops, each
/// read back as a closed profile. Two of its four touching points were joined by seams solved
/// either side of them (in either order), and an arc ran the long way round the hole, certified.
#[test]
fn a_plate_touching_its_hole_at_the_distance_is_four_corners() {
    let plate = fixture("corpus/dxf/island_in_hole.dxf");
    let doc = curvekit_json(&["offset", &plate, "--distances", "7.5"]);
    assert_eq!(doc["certified"], true, "{doc}");
    assert_eq!(doc["complete"], true, "{doc}");
    let loops = doc["offsets"][0]["loops"].as_array().unwrap();
    let plate_loops: Vec<&serde_json::Value> = loops.iter().filter(|l| l["part"] == 0).collect();
    assert_eq!(plate_loops.len(), 4, "{doc}");
    let dir = tempfile::tempdir().unwrap();
    for (j, l) in plate_loops.iter().enumerate() {
        let path = dir.path().join(format!("loop-{j}.json"));
        std::fs::write(&path, l.to_string()).unwrap();
        let back = curvekit_json(&["inflections", path.to_str().unwrap()]);
        assert_eq!(back["curve"]["closed"], true, "{l}");
        // (Each corner's arcs of the hole's offset sweep a quarter turn at most.)
        for s in l["segments"].as_array().unwrap() {
            if s["kind"] == "arc" {
                let sweep = (s["end"].as_f64().unwrap() - s["start"].as_f64().unwrap()).abs();
                assert!(sweep <= std::f64::consts::FRAC_PI_2 + 1e-9, "{s}");
            }
        }
    }
}

/// The sample of real drawings whose offsets had loops that were not closed (issue 38: the
/// corpus found 47), with the distances the corpus asked: every loop now closes, to the
/// rounding of its coordinates. (Each is after an uncertified medial axis: a convex corner of
/// a few hundredths of a degree without its edge, or parts of the graph apart, so that a seam
/// is missing and the pieces either side of it do not meet. A gap within the chord tolerance
/// is bridged by a line, a wider one's loop left out; the result says so, uncertified.)
#[test]
fn loops_of_real_drawings_are_closed() {
    let cases = [
        (
            "icons/fontawesome-solid/droplet.svg",
            "10.56,33.0418,33.6425,66.0835,105.734,145.384",
        ),
        (
            "icons/fontawesome-solid/indian-rupee-sign.svg",
            "8.95926,12.1412,24.2823,34.8783",
        ),
        (
            "icons/fontawesome-solid/octagon.svg",
            "10.236,61.916,123.832,198.131,272.431",
        ),
        (
            "icons/octicons/agent-24.svg",
            "0.219499,0.438998,0.48,0.702396,0.965795",
        ),
        (
            "icons/octicons/broadcast-24.svg",
            "0.48,0.49951,0.999021,1.59843,2.19785",
        ),
        (
            "icons/octicons/flag-24.svg",
            "0.239377,0.3612,0.478754,0.761654,0.766006,1.05326",
        ),
        (
            "icons/octicons/question-24.svg",
            "0.249973,0.44,0.499945,0.799912,1.09988",
        ),
        (
            "icons/phosphor-fill/pinterest-logo-fill.svg",
            "4.16016,7.45504,14.9101,16.8077",
        ),
        (
            "icons/heroicons-solid/document-arrow-up.svg",
            "0.42,1.13644,2.27289,2.56216",
        ),
        (
            "icons/heroicons-solid/light-bulb.svg",
            "0.450007,1.40498,2.80995,4.49592,6.1819",
        ),
        (
            "icons/heroicons-solid/rectangle-stack.svg",
            "0.39,1.5,3,4.8,6.6",
        ),
        (
            "icons/heroicons-solid/server-stack.svg",
            "0.42,0.75,1.22727,1.5,2.4,3.3",
        ),
        (
            "icons/ionicons-filled/caret-back.svg",
            "6.55339,22.0738,44.1476,70.6362,97.1248",
        ),
        (
            "icons/ionicons-filled/eye.svg",
            "9.60003,17.0038,33.0802,34.0077,54.4123",
        ),
        (
            "icons/ionicons-filled/rose.svg",
            "9.59993,38.6147,77.2294,123.567,169.905",
        ),
        (
            "glyphs/noto-sans/0038-eight.svg",
            "12.1046,14.68,24.2093,38.7348,42.2562",
        ),
        (
            "dxf/far_from_origin.dxf",
            "1.2,2.44876,4.89753,7.79152,7.83604,10.7746",
        ),
    ];
    let ends = |s: &serde_json::Value| -> ([f64; 2], [f64; 2]) {
        let xy = |v: &serde_json::Value| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()];
        match s["kind"].as_str().unwrap() {
            "line" => (xy(&s["from"]), xy(&s["to"])),
            "arc" => {
                let (c, r) = (xy(&s["center"]), s["r"].as_f64().unwrap());
                let at = |a: f64| [c[0] + r * a.cos(), c[1] + r * a.sin()];
                (
                    at(s["start"].as_f64().unwrap()),
                    at(s["end"].as_f64().unwrap()),
                )
            }
            _ => {
                let p = s["points"].as_array().unwrap();
                (xy(&p[0]), xy(&p[p.len() - 1]))
            }
        }
    };
    let mut open = Vec::new();
    for (file, distances) in cases {
        let doc = curvekit_json(&[
            "offset",
            &fixture(&format!("corpus/{file}")),
            "--distances",
            distances,
        ]);
        for o in doc["offsets"].as_array().unwrap() {
            for (j, l) in o["loops"].as_array().unwrap().iter().enumerate() {
                let segments = l["segments"].as_array().unwrap();
                for (k, s) in segments.iter().enumerate() {
                    let (_, end) = ends(s);
                    let (start, _) = ends(&segments[(k + 1) % segments.len()]);
                    let scale = end.iter().chain(&start).fold(1.0f64, |m, x| m.max(x.abs()));
                    let gap = (end[0] - start[0]).hypot(end[1] - start[1]);
                    if gap > 1e-9 * scale {
                        open.push(format!(
                            "{file} d = {}: loop {j}, piece {k}: {gap}",
                            o["distance"]
                        ));
                    }
                }
            }
        }
    }
    assert!(open.is_empty(), "{open:#?}");
}

/// The glyph '8' (Noto Sans) at 38.7348: the axis between the corners of its two counters,
/// where they face each other across its waist, dips to 38.70, and the offset crosses it at
/// two seams, where the circles of the distance about the two corners cross. Both were solved
/// at one crossing (a fan's foot was judged within its step by the corner's parameter alone),
/// the loops joined wrongly and left gaps (uncertified, incomplete). Each seam is now within
/// its step by its direction from the corner: six loops, as the corpus's oracle counts
/// (buffer), certified.
#[test]
fn the_seams_either_side_of_a_neck_between_two_corners_are_apart() {
    let eight = fixture("corpus/glyphs/noto-sans/0038-eight.svg");
    let doc = curvekit_json(&["offset", &eight, "--distances", "38.7348"]);
    assert_eq!(doc["certified"], true, "{}", doc["reason"]);
    assert_eq!(doc["complete"], true);
    assert_eq!(doc["offsets"][0]["loops"].as_array().unwrap().len(), 6);
}
