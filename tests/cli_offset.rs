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

/// The plate (issue 38): a 100 × 100 plate with corners rounded by 10 and a hole of
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
