//! `curvekit batch`: one JSON line per input in input order whatever `--jobs` is, a failing
//! input as its line without ending the run, and each line the single-file command's document.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit, curvekit_json, fixture};
use serde_json::Value;

/// Lines of a batch run's stdout, parsed.
fn lines(stdout: &str) -> Vec<Value> {
    stdout
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// The line without its `input` field: the single-file command's document.
fn without_input(line: &Value) -> Value {
    let mut doc = line.clone();
    doc.as_object_mut().unwrap().remove("input");
    doc
}

#[test]
fn each_line_is_the_single_file_document_in_input_order() {
    let files = [
        "periodic_cubic.json",
        "circle.json",
        "profile-cam.json",
        "antipodal-limacon.json",
        "periodic_nurbs.json",
        "ellipse.json",
    ]
    .map(fixture);
    for command in ["antipodal", "inflections"] {
        let mut args = vec!["batch", command];
        args.extend(files.iter().map(String::as_str));
        for jobs in ["1", "2", "3"] {
            let mut run_args = args.clone();
            run_args.extend(["--jobs", jobs]);
            let run = curvekit(&run_args);
            assert_eq!(run.code, 0, "{}", run.stderr);
            let got = lines(&run.stdout);
            assert_eq!(got.len(), files.len());
            for (line, file) in got.iter().zip(&files) {
                assert_eq!(line["input"], file.as_str(), "{command} --jobs {jobs}");
                let single = curvekit_json(&[command, file]);
                assert_eq!(without_input(line), single, "{command} {file}");
            }
        }
    }
}

#[test]
fn a_failing_input_is_its_line_and_the_run_goes_on() {
    let (good, bad, missing) = (
        fixture("periodic_cubic.json"),
        fixture("bad/weight_zero.json"),
        fixture("no-such-file.json"),
    );
    let run = curvekit(&["batch", "antipodal", &good, &bad, &missing, &good]);
    assert_eq!(run.code, 2, "bad input only: exit 2");
    assert!(
        run.stderr.contains("2 of 4 inputs failed"),
        "{}",
        run.stderr
    );
    let got = lines(&run.stdout);
    assert_eq!(got.len(), 4);
    assert_eq!(got[0]["certified"], true);
    assert_eq!(got[3]["certified"], true);
    for (line, file, field) in [
        (&got[1], &bad, "weights[1]"),
        (&got[2], &missing, "document"),
    ] {
        assert_eq!(line["input"], file.as_str());
        assert_eq!(line["error"]["status"], 2);
        let message = line["error"]["message"].as_str().unwrap();
        // (The single-file command's message, word for word.)
        let single = curvekit(&["antipodal", file]);
        assert_eq!(single.code, 2);
        assert_eq!(format!("curvekit: {message}\n"), single.stderr);
        assert!(message.contains(field), "{message}");
    }
}

#[test]
fn json_lines_inputs_are_named_by_line_and_a_bad_line_is_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("curves.jsonl");
    let circle = r#"{"kind":"circle","center":[1,2],"r":3}"#;
    let cubic = std::fs::read_to_string(fixture("periodic_cubic.json")).unwrap();
    let cubic_line: Value = serde_json::from_str(&cubic).unwrap();
    let text = format!("{circle}\n\n{{\"kind\":\"circle\"}}\n{cubic_line}\n");
    std::fs::write(&path, text).unwrap();
    let name = path.display().to_string();
    let out = dir.path().join("results.jsonl");
    let run = curvekit(&[
        "batch",
        "antipodal",
        &name,
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert!(run.stdout.is_empty(), "--out takes the lines");
    let got = lines(&std::fs::read_to_string(&out).unwrap());
    // (The blank line 2 is no input.)
    let names: Vec<&str> = got.iter().map(|l| l["input"].as_str().unwrap()).collect();
    assert_eq!(
        names,
        [1, 3, 4]
            .map(|k| format!("{name}:{k}"))
            .map(|s| s.leak() as &str)
    );
    assert_eq!(got[0]["curve"]["kind"], "circle");
    assert_eq!(got[1]["error"]["status"], 2);
    assert!(got[1]["error"]["message"]
        .as_str()
        .unwrap()
        .contains(&format!("{name}:3: r: missing")));
    let single = curvekit_json(&["antipodal", &fixture("periodic_cubic.json")]);
    assert_eq!(got[2]["pairs"], single["pairs"]);
}

#[test]
fn bisector_and_medial_run_in_batch_as_alone() {
    let cubic = fixture("periodic_cubic.json");
    let pocket = fixture("drawing-pocket.svg");
    let run = curvekit(&["batch", "bisector", &cubic, "--chord-tol", "1e-2"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let single = curvekit_json(&["bisector", &cubic, "--chord-tol", "1e-2"]);
    assert_eq!(without_input(&lines(&run.stdout)[0]), single);
    let run = curvekit(&["batch", "medial", &pocket, &cubic, "--jobs", "2"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let got = lines(&run.stdout);
    for (line, file) in got.iter().zip([&pocket, &cubic]) {
        assert_eq!(without_input(line), curvekit_json(&["medial", file]));
    }
}

#[test]
fn options_are_checked_before_any_input_is_read() {
    let missing = fixture("no-such-file.json");
    for (args, said) in [
        (vec!["--jobs", "0"], "--jobs"),
        (vec!["--tol", "0.5"], "tol"),
        (vec!["--chord-tol", "2"], "chord"),
    ] {
        let mut all = vec!["batch", "medial", &missing];
        all.extend(args);
        let run = curvekit(&all);
        assert_eq!(run.code, 2, "{all:?}");
        assert!(run.stdout.is_empty(), "{all:?}: no line is written");
        assert!(run.stderr.contains(said), "{all:?}: {}", run.stderr);
    }
    let run = curvekit(&["batch", "tangents", &missing]);
    assert_eq!(
        run.code, 2,
        "tangents takes two curves: not a batch command"
    );
}

/// Every command runs in batch as alone: offsets, V-carving, and the tangents and bisector of
/// each input with the curve `--with`.
#[test]
fn every_command_runs_in_batch_as_alone() {
    let regions = [fixture("region-pocket.json"), fixture("drawing-pocket.svg")];
    let curves = [fixture("circle.json"), fixture("ellipse.json")];
    let with = fixture("limacon.json");
    let cases: Vec<(Vec<&str>, &[String], Vec<&str>)> = vec![
        (vec!["offset"], &regions, vec!["--distances", "0.5,1.5"]),
        (vec!["offset"], &regions, vec!["--step", "1"]),
        (
            vec!["vcarve"],
            &regions,
            vec!["--angle", "60", "--max-depth", "3"],
        ),
        (vec!["tangents"], &curves, vec![]),
        (vec!["bisector"], &curves, vec![]),
    ];
    for (command, inputs, options) in cases {
        let mut args = vec!["batch", command[0]];
        args.extend(inputs.iter().map(String::as_str));
        args.extend(&options);
        let two = matches!(command[0], "tangents" | "bisector");
        if two {
            args.extend(["--with", with.as_str()]);
        }
        let run = curvekit(&args);
        assert_eq!(run.code, 0, "{args:?}: {}", run.stderr);
        assert_eq!(lines(&run.stdout).len(), inputs.len(), "{args:?}");
        for (line, input) in lines(&run.stdout).iter().zip(inputs) {
            let mut single = vec![command[0], input.as_str()];
            if two {
                single.push(with.as_str());
            }
            single.extend(&options);
            assert_eq!(without_input(line), curvekit_json(&single), "{args:?}");
        }
    }
}

/// `--figures DIR`: one figure per input, named by its place and file, and its line says
/// where.
#[test]
fn each_input_gets_its_figure() {
    let dir = tempfile::tempdir().unwrap();
    let figures = dir.path().join("figs");
    let inputs = [fixture("region-pocket.json"), fixture("drawing-pocket.svg")];
    let run = curvekit(&[
        "batch",
        "medial",
        &inputs[0],
        &inputs[1],
        "--figures",
        figures.to_str().unwrap(),
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let got = lines(&run.stdout);
    assert_eq!(got.len(), 2);
    for (k, (line, stem)) in got
        .iter()
        .zip(["region-pocket", "drawing-pocket"])
        .enumerate()
    {
        let path = figures.join(format!("{k:04}-{stem}.svg"));
        assert_eq!(line["figure"], path.display().to_string());
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(
            svg.starts_with("<svg") && svg.contains("<polyline"),
            "{svg:.100}"
        );
    }
}

/// Options a command does not take, and those it needs, are usage errors before any input is
/// read.
#[test]
fn options_must_fit_the_command() {
    let pocket = fixture("region-pocket.json");
    for (args, named) in [
        (vec!["batch", "medial", &pocket, "--angle", "60"], "--angle"),
        (
            vec!["batch", "antipodal", &pocket, "--distance", "1"],
            "--distance",
        ),
        (vec!["batch", "inflections", &pocket, "--fit"], "--fit"),
        (vec!["batch", "vcarve", &pocket, "--exterior"], "--exterior"),
        (vec!["batch", "vcarve", &pocket], "--angle"),
        (
            vec!["batch", "vcarve", &pocket, "--angle", "200"],
            "--angle",
        ),
        (vec!["batch", "tangents", &pocket], "--with"),
        (vec!["batch", "offset", &pocket], "distance"),
    ] {
        let run = curvekit(&args);
        assert_eq!(run.code, 2, "{args:?}: {}", run.stderr);
        assert!(run.stderr.contains(named), "{args:?}: {}", run.stderr);
        assert_eq!(run.stdout, "", "{args:?}");
    }
}
