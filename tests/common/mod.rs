//! Helpers shared by the end-to-end tests: run the binary, find fixtures, round numbers.
#![allow(dead_code, clippy::unwrap_used)]

use serde_json::Value;
use std::path::PathBuf;
use std::process::Command;

/// A count of what a property test checked, over all its cases (which run on several
/// threads), so that the test can assert it was not vacuous.
pub(crate) struct Tally(std::sync::atomic::AtomicUsize);

impl Tally {
    pub(crate) const fn new() -> Self {
        Self(std::sync::atomic::AtomicUsize::new(0))
    }

    /// Counts `n` more.
    pub(crate) fn add(&self, n: usize) {
        self.0.fetch_add(n, std::sync::atomic::Ordering::Relaxed);
    }

    /// The count so far.
    pub(crate) fn get(&self) -> usize {
        self.0.load(std::sync::atomic::Ordering::Relaxed)
    }
}

/// Exit status (or -1 when killed), stdout and stderr of one run of `curvekit`.
pub(crate) struct Run {
    pub(crate) code: i32,
    pub(crate) stdout: String,
    pub(crate) stderr: String,
}

pub(crate) fn curvekit(args: &[&str]) -> Run {
    let out = Command::new(env!("CARGO_BIN_EXE_curvekit"))
        .args(args)
        .output()
        .unwrap();
    Run {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Runs with `--json` appended and parses stdout (asserting success).
pub(crate) fn curvekit_json(args: &[&str]) -> Value {
    let mut all = args.to_vec();
    all.push("--json");
    let r = curvekit(&all);
    assert_eq!(r.code, 0, "{args:?}: {}", r.stderr);
    serde_json::from_str(&r.stdout).unwrap()
}

pub(crate) fn fixture(name: &str) -> String {
    fixtures_dir().join(name).display().to_string()
}

pub(crate) fn fixtures_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fixtures")
}

/// The `.json` files directly in `dir`, sorted.
pub(crate) fn json_files(dir: &std::path::Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

/// Numbers rounded to 9 significant digits, and values below 1e-9 in magnitude set to zero, so
/// snapshots survive floating-point noise.
pub(crate) fn rounded(v: &Value) -> Value {
    match v {
        Value::Number(n) => match n.as_f64() {
            Some(x) if n.is_f64() => {
                let r: f64 = if x.abs() < 1e-9 {
                    0.0
                } else {
                    format!("{x:.8e}").parse().unwrap()
                };
                serde_json::json!(r + 0.0)
            }
            _ => v.clone(),
        },
        Value::Array(items) => Value::Array(items.iter().map(rounded).collect()),
        Value::Object(map) => {
            Value::Object(map.iter().map(|(k, x)| (k.clone(), rounded(x))).collect())
        }
        _ => v.clone(),
    }
}
pub(crate) mod evaluate;
