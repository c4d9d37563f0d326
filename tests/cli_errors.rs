//! Exit status 2 with one line on stderr naming the file, the field and the problem, for every
//! bad fixture and every kind of usage error.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit, fixture, fixtures_dir, json_files};

/// Every file in `fixtures/bad/` with the field its message must name.
const BAD: &[(&str, &str)] = &[
    ("arc_sweep_too_large.json", "end"),
    ("bezier_one_point.json", "points"),
    ("center_arity.json", "center"),
    ("coincident_points.json", "points"),
    ("degree_not_integer.json", "degree"),
    ("degree_too_high.json", "degree"),
    ("degree_zero.json", "degree"),
    ("duplicate_field.json", "r"),
    ("ellipse_negative.json", "a"),
    ("empty.json", "document"),
    ("eps_out_of_range.json", "eps"),
    ("invalid_json.json", "document"),
    ("kind_not_string.json", "kind"),
    ("knots_count.json", "knots"),
    ("knots_decreasing.json", "knots[4]"),
    ("knots_multiplicity.json", "knots"),
    ("knots_overflow.json", "knots"),
    ("knots_with_periodic.json", "knots"),
    ("lemniscate_b_zero.json", "b"),
    ("limacon_a_le_b.json", "a"),
    ("limacon_b_negative.json", "b"),
    ("line_zero_length.json", "to"),
    ("m_not_integer.json", "m"),
    ("m_too_small.json", "m"),
    ("missing_field.json", "r"),
    ("missing_kind.json", "kind"),
    ("not_object.json", "document"),
    ("number_out_of_range.json", "document"),
    ("number_too_large.json", "r"),
    ("p_negative.json", "p"),
    ("periodic_not_bool.json", "periodic"),
    ("point_arity.json", "points[1]"),
    ("point_not_number.json", "points[1][1]"),
    ("profile_crossing.json", "segments[3]"),
    ("profile_gap.json", "segments[1]"),
    ("profile_nested_duplicate.json", "segments[0].to"),
    ("profile_segment_field.json", "segments[1].radius"),
    ("profile_segment_kind.json", "segments[0].kind"),
    ("profile_turns_back.json", "segments[1]"),
    ("radius_zero.json", "r"),
    ("region_boundaries_cross.json", "holes[0]"),
    ("region_hole_outside.json", "holes[0]"),
    ("region_open_boundary.json", "outer"),
    ("too_few_points.json", "points"),
    ("unknown_field.json", "radius"),
    ("unknown_kind.json", "kind"),
    ("weight_zero.json", "weights[1]"),
    ("weights_count.json", "weights"),
    ("wrong_type.json", "r"),
];

/// Asserts exit 2 and a single stderr line containing every `needle`.
fn assert_usage_error(args: &[&str], needles: &[&str]) {
    let r = curvekit(args);
    assert_eq!(r.code, 2, "{args:?}: stderr {:?}", r.stderr);
    assert_eq!(r.stderr.lines().count(), 1, "{args:?}: {:?}", r.stderr);
    assert!(r.stdout.is_empty(), "{args:?}: {:?}", r.stdout);
    for n in needles {
        assert!(r.stderr.contains(n), "{args:?}: {:?} lacks {n:?}", r.stderr);
    }
}

#[test]
fn every_bad_fixture_is_listed() {
    let on_disk: Vec<String> = json_files(&fixtures_dir().join("bad"))
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    let listed: Vec<String> = BAD.iter().map(|(f, _)| f.to_string()).collect();
    assert_eq!(on_disk, listed);
}

#[test]
fn bad_fixtures_exit_2_naming_file_and_field() {
    for (file, field) in BAD {
        let path = fixture(&format!("bad/{file}"));
        assert_usage_error(&["inflections", &path], &[&path, &format!(": {field}: ")]);
    }
}

#[test]
fn every_command_rejects_bad_input() {
    let bad = fixture("bad/unknown_field.json");
    let good = fixture("periodic_cubic.json");
    for args in [
        vec!["antipodal", bad.as_str()],
        vec!["inflections", bad.as_str(), "--json"],
        vec!["tangents", good.as_str(), bad.as_str()],
        vec!["bisector", bad.as_str()],
        vec!["bisector", good.as_str(), bad.as_str()],
    ] {
        assert_usage_error(&args, &[&bad, ": radius: "]);
    }
}

#[test]
fn unreadable_file() {
    assert_usage_error(
        &["inflections", "no/such/file.json"],
        &["no/such/file.json"],
    );
}

#[test]
fn usage_errors_are_one_line_exit_2() {
    let good = fixture("ellipse.json");
    assert_usage_error(&[], &["no command"]);
    assert_usage_error(&["frobnicate"], &["frobnicate"]);
    assert_usage_error(&["inflections"], &["<CURVE>"]);
    assert_usage_error(&["inflections", &good, "--bogus"], &["--bogus"]);
    assert_usage_error(&["tangents", &good], &["<CURVE2>"]);
    assert_usage_error(&["demo", "--svg", "x.svg"], &["--svg"]);
    for tol in ["-1", "0", "abc", "inf", "NaN"] {
        assert_usage_error(&["inflections", &good, "--tol", tol], &["--tol"]);
    }
    // Accepted by the parser but not by the algorithms (outside what they can deliver):
    // still a usage error, saying the range.
    for tol in ["0.5", "1e-3", "1e-16", "1e-300"] {
        for command in ["antipodal", "inflections"] {
            assert_usage_error(
                &[command, &good, "--tol", tol],
                &["--tol", "must be at least 1e-15"],
            );
        }
        let both = [good.as_str(), good.as_str()];
        assert_usage_error(
            &["tangents", both[0], both[1], "--tol", tol],
            &["--tol", "1e-15"],
        );
        assert_usage_error(&["demo", "--tol", tol], &["--tol", "1e-15"]);
    }
    let spline = fixture("periodic_cubic.json");
    for chord in ["1e-12", "0.75", "5"] {
        // (Spelled as on the command line.)
        assert_usage_error(
            &["bisector", &spline, "--chord-tol", chord],
            &["--chord-tol: ", "1e-9"],
        );
    }
    // Options are checked before any file is read.
    let missing = "no/such/file.json";
    assert_usage_error(&["antipodal", missing, "--tol", "0.5"], &["--tol"]);
    assert_usage_error(
        &["bisector", missing, "--chord-tol", "1e-12"],
        &["--chord-tol"],
    );
}

#[test]
fn unsuitable_curves_are_input_errors() {
    // An open curve has no antipodal pairs to speak of.
    let open = fixture("bezier_s.json");
    assert_usage_error(&["antipodal", &open], &[&open, ": points: ", "not closed"]);
    // A stationary point (three equal control points): no tangent, no curvature there. Both
    // the certified regularity proof (inflections) and the dissection (antipodal) refuse it.
    let cusp = fixture("singular/cusp_closed.json");
    for command in ["inflections", "antipodal"] {
        assert_usage_error(
            &[command, &cusp],
            &[&cusp, ": points: ", "singular", "u = 0"],
        );
    }
    // A limaçon within rounding of its cusp (b a few units of rounding below a) is refused as
    // singular there (it exited 1 as "oscillating too often", which it does not).
    let dir = tempfile::tempdir().unwrap();
    let near_cusp = dir.path().join("near_cusp.json");
    std::fs::write(
        &near_cusp,
        r#"{"kind":"limacon","a":1,"b":0.99999999999999}"#,
    )
    .unwrap();
    let near_cusp = near_cusp.display().to_string();
    assert_usage_error(
        &["antipodal", &near_cusp],
        &[&near_cusp, ": kind: ", "singular", "u = 3.14159"],
    );
}

#[test]
fn help_and_version_succeed() {
    for args in [
        vec!["--help"],
        vec!["--version"],
        vec!["inflections", "--help"],
    ] {
        let r = curvekit(&args);
        assert_eq!(r.code, 0, "{args:?}");
        assert!(!r.stdout.is_empty());
    }
}

/// A region is read (its outer boundary and holes validated) and refused by the commands on
/// curves, by name.
#[test]
fn regions_are_read_and_refused_by_curve_commands() {
    let path = fixture("region-pocket.json");
    for cmd in ["inflections", "antipodal"] {
        assert_usage_error(&[cmd, &path], &[&path, ": kind: ", "not a region"]);
    }
    let r = curvekit::io::read_curve(std::path::Path::new(&path)).unwrap();
    match r.shape {
        curvekit::io::CurveKind::Region(region) => {
            assert_eq!(region.holes().len(), 1);
            assert_eq!(region.outer().segments().len(), 8);
        }
        other => panic!("{other:?}"),
    }
}
