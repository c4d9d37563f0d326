//! The tool in a pipeline and at a shell: standard input as `-` with `--format`, a reader that
//! stops reading, completion scripts, suggestions for a typo, and help that lists only what a
//! command takes.
#![allow(clippy::unwrap_used)]

mod common;

use common::{curvekit, curvekit_json, fixture};
use std::io::{Read, Write};
use std::process::{Command, Stdio};

/// Runs the tool with `input` on its standard input; (exit status, stdout, stderr).
fn with_stdin(args: &[&str], input: &[u8]) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_curvekit"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // (A command that refuses its options exits before reading: its pipe is then closed.)
    let _ = child.stdin.take().unwrap().write_all(input);
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `-` reads standard input: a curve file by default, a drawing with `--format`; the answer
/// is the one the file gives, named `<stdin>`.
#[test]
fn standard_input_is_read_as_the_file_would_be() {
    for (name, format) in [
        ("region-pocket.json", None),
        ("drawing-pocket.svg", Some("svg")),
        ("drawing-plate.dxf", Some("dxf")),
    ] {
        let path = fixture(name);
        let bytes = std::fs::read(&path).unwrap();
        let mut args = vec!["medial", "-", "--json"];
        if let Some(f) = format {
            args.extend(["--format", f]);
        }
        let (code, stdout, stderr) = with_stdin(&args, &bytes);
        assert_eq!(code, 0, "{name}: {stderr}");
        let piped: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        let read = curvekit_json(&["medial", &path]);
        assert_eq!(piped["edges"], read["edges"], "{name}");
        assert_eq!(piped["curve"]["file"], "<stdin>", "{name}");
    }
    // A drawing without its format is read as a curve file, and refused naming stdin.
    let svg = std::fs::read(fixture("drawing-pocket.svg")).unwrap();
    let (code, _, stderr) = with_stdin(&["medial", "-"], &svg);
    assert_eq!(code, 2);
    assert!(stderr.contains("<stdin>"), "{stderr}");
    // `--format` also names the format of a file whose extension does not say.
    let dir = tempfile::tempdir().unwrap();
    let odd = dir.path().join("pocket.drawing");
    std::fs::write(&odd, &svg).unwrap();
    let doc = curvekit_json(&[
        "offset",
        odd.to_str().unwrap(),
        "--distance",
        "1",
        "--format",
        "svg",
    ]);
    assert_eq!(doc["certified"], true);
}

/// Standard input is read once: two inputs cannot both be it.
#[test]
fn two_standard_inputs_are_a_usage_error() {
    let (code, _, stderr) = with_stdin(&["tangents", "-", "-"], b"{}");
    assert_eq!(code, 2);
    assert!(stderr.contains("standard input"), "{stderr}");
}

/// A reader that stops early (`head`) ends the output quietly: exit 0, nothing on stderr.
#[test]
fn a_closed_pipe_is_a_quiet_end() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_curvekit"))
        .args([
            "offset",
            &fixture("region-pocket.json"),
            "--step",
            "0.0005",
            "--json",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 16];
    stdout.read_exact(&mut first).unwrap();
    drop(stdout);
    let mut stderr = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut stderr)
        .unwrap();
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(0), "{stderr}");
    assert_eq!(stderr, "");
}

#[test]
fn completion_scripts_know_every_command() {
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let run = curvekit(&["completions", shell]);
        assert_eq!(run.code, 0, "{shell}: {}", run.stderr);
        for command in ["medial", "offset", "vcarve", "batch"] {
            assert!(run.stdout.contains(command), "{shell} lacks {command}");
        }
    }
    assert_eq!(curvekit(&["completions", "tcsh"]).code, 2);
}

#[test]
fn a_typo_gets_a_suggestion() {
    let run = curvekit(&["medal", "x.json"]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("'medial'"), "{}", run.stderr);
    let run = curvekit(&["offset", &fixture("region-pocket.json"), "--distanse", "1"]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("--distance"), "{}", run.stderr);
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
}

/// `demo` lists only the options it takes: no figure file, no pick, no input format.
#[test]
fn demo_help_lists_what_demo_takes() {
    let run = curvekit(&["demo", "--help"]);
    assert_eq!(run.code, 0);
    for absent in ["--svg", "--pick", "--format"] {
        assert!(!run.stdout.contains(absent), "demo --help lists {absent}");
    }
    for present in ["--out", "--json", "--tol", "--time"] {
        assert!(run.stdout.contains(present), "demo --help lacks {present}");
    }
}
