//! `curvekit batch`: one command over many inputs on a pool of threads, one JSON line per input
//! in input order; an input that fails becomes its line, never the end of the run.

use super::{Failure, MethodArg};
use curvekit::commands::{self, json_document, CommandError};
use curvekit::io::{parse_curve, parse_region, read_curve_picked, read_region, Curve};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde_json::Value;
use std::collections::BTreeMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::mpsc;

/// Most threads `--jobs` accepts: far beyond any machine's cores, a guard against a typo.
const MAX_JOBS: usize = 1024;

/// The commands batch mode runs (those that take one curve or region).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum BatchCommand {
    /// `antipodal`.
    Antipodal,
    /// `inflections`.
    Inflections,
    /// `bisector` of one curve: its self-bisector.
    Bisector,
    /// `medial`.
    Medial,
}

/// What one run of batch mode does, from the command line.
pub(crate) struct Batch {
    pub(crate) command: BatchCommand,
    pub(crate) inputs: Vec<PathBuf>,
    pub(crate) jobs: Option<usize>,
    pub(crate) out: Option<PathBuf>,
    pub(crate) pick: Option<usize>,
    pub(crate) tol: f64,
    pub(crate) chord_tol: f64,
    pub(crate) method: MethodArg,
    pub(crate) trimmed: bool,
    pub(crate) fit: bool,
    pub(crate) exterior: bool,
}

/// One input: a file, or one line of a JSON-lines file (named `FILE:LINE`).
enum Input {
    File(PathBuf),
    Line {
        name: String,
        text: String,
    },
    /// A JSON-lines file that could not be read: its one line is the error.
    Unreadable {
        name: String,
        error: CommandError,
    },
}

impl Input {
    fn name(&self) -> String {
        match self {
            Input::File(p) => p.display().to_string(),
            Input::Line { name, .. } | Input::Unreadable { name, .. } => name.clone(),
        }
    }
}

/// Runs the batch; the error, if any, comes after every line is written: the worst of the
/// inputs' failures (1 when a computation failed, else 2 for bad input).
pub(crate) fn run(batch: &Batch) -> Result<(), Failure> {
    let jobs = match batch.jobs {
        Some(n) if !(1..=MAX_JOBS).contains(&n) => {
            return Err(Failure::Usage(format!(
                "--jobs: {n} is out of range: between 1 and {MAX_JOBS}"
            )))
        }
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let task = Task::new(batch)?;
    let inputs = expand(&batch.inputs);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .map_err(|e| Failure::Other(format!("batch: cannot start {jobs} threads: {e}")))?;
    let mut sink: Box<dyn Write> = match &batch.out {
        Some(path) => Box::new(std::io::BufWriter::new(
            std::fs::File::create(path)
                .map_err(|e| Failure::Other(format!("cannot write {}: {e}", path.display())))?,
        )),
        None => Box::new(std::io::BufWriter::new(std::io::stdout().lock())),
    };
    let bar = ProgressBar::new(inputs.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} inputs, {per_sec}, eta {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let (tx, rx) = mpsc::channel::<(usize, Result<String, CommandError>)>();
    let mut failures = Vec::new();
    // (Set when the results can no longer be written: the inputs not begun are left.)
    let stopped = std::sync::atomic::AtomicBool::new(false);
    let written: Result<(), std::io::Error> = std::thread::scope(|scope| {
        scope.spawn(|| {
            pool.install(|| {
                inputs
                    .par_iter()
                    .enumerate()
                    .for_each_with(tx, |tx, (k, input)| {
                        if stopped.load(std::sync::atomic::Ordering::Relaxed) {
                            return;
                        }
                        // (The receiver only goes when writing failed: nothing is left to do.)
                        let _ = tx.send((k, task.run_caught(input)));
                    })
            })
        });
        // In input order: a line waits here until every line before it is written.
        let mut waiting = BTreeMap::new();
        let mut next = 0;
        for (k, outcome) in rx {
            waiting.insert(k, outcome);
            while let Some(outcome) = waiting.remove(&next) {
                let line = match outcome {
                    Ok(doc) => doc,
                    Err(e) => {
                        let line = error_line(&inputs[next].name(), &e);
                        failures.push(e);
                        line
                    }
                };
                if let Err(e) = sink.write_all(line.as_bytes()) {
                    stopped.store(true, std::sync::atomic::Ordering::Relaxed);
                    return Err(e);
                }
                bar.inc(1);
                next += 1;
            }
        }
        sink.flush()
    });
    bar.finish_and_clear();
    match written {
        // (The reader stopped reading, as `head` does: a quiet end.)
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => return Ok(()),
        other => {
            other.map_err(|e| Failure::Other(format!("batch: cannot write the results: {e}")))?
        }
    }
    match failures.first() {
        None => Ok(()),
        Some(first) => {
            let message = format!(
                "batch: {} of {} inputs failed (the first: {})",
                failures.len(),
                inputs.len(),
                first.message()
            );
            Err(if failures.iter().any(|e| e.exit_code() != 2) {
                Failure::Other(message)
            } else {
                Failure::Usage(message)
            })
        }
    }
}

/// The inputs: each file, or each non-blank line of a `.jsonl` file.
fn expand(paths: &[PathBuf]) -> Vec<Input> {
    let mut inputs = Vec::new();
    for path in paths {
        if !is_json_lines(path) {
            inputs.push(Input::File(path.clone()));
            continue;
        }
        let file = path.display().to_string();
        match std::fs::read_to_string(path) {
            Ok(text) => inputs.extend(
                text.lines()
                    .enumerate()
                    .filter(|(_, line)| !line.trim().is_empty())
                    .map(|(k, line)| Input::Line {
                        name: format!("{file}:{}", k + 1),
                        text: line.to_string(),
                    }),
            ),
            Err(e) => inputs.push(Input::Unreadable {
                name: file.clone(),
                error: CommandError::Input(curvekit::io::CurveFileError {
                    file,
                    field: "document".into(),
                    problem: curvekit::io::Problem::Unreadable(e.to_string()),
                }),
            }),
        }
    }
    inputs
}

/// An input's failure as its line: `{"input", "error": {"status", "message"}}`.
fn error_line(name: &str, e: &CommandError) -> String {
    format!(
        "{{\"input\":{},\"error\":{{\"status\":{},\"message\":{}}}}}\n",
        Value::from(name),
        e.exit_code(),
        Value::from(e.message())
    )
}

/// The command with its options, checked once before any input is read.
struct Task {
    command: BatchCommand,
    pick: Option<usize>,
    curve_opts: antipodal::Options,
    bisector_opts: zeroset::BisectorOptions,
    medial_opts: medial::MedialOptions,
}

impl Task {
    fn new(b: &Batch) -> Result<Self, Failure> {
        let curve_opts = antipodal::Options::default().tolerance(b.tol);
        let bisector_opts = super::BisectorArgs {
            method: b.method,
            trimmed: b.trimmed,
            chord_tol: b.chord_tol,
        }
        .options(b.tol);
        let medial_opts = medial::MedialOptions {
            tol: b.tol,
            chord_tol: b.chord_tol,
            fit: b.fit,
            exterior: b.exterior,
            size: None,
        };
        match b.command {
            BatchCommand::Antipodal | BatchCommand::Inflections => {
                commands::validate_options(&curve_opts)?
            }
            BatchCommand::Bisector => commands::validate_bisector_options(&bisector_opts)?,
            BatchCommand::Medial => commands::validate_medial_options(&medial_opts)?,
        }
        Ok(Self {
            command: b.command,
            pick: b.pick,
            curve_opts,
            bisector_opts,
            medial_opts,
        })
    }

    /// [`Task::run`], with a panic (a defect, never expected) made this input's failure.
    fn run_caught(&self, input: &Input) -> Result<String, CommandError> {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.run(input)))
            .unwrap_or_else(|_| Err(CommandError::Other("internal error".into())))
    }

    /// Reads the input and runs the command on it: the JSON document of `--json`, with the
    /// input's name first.
    fn run(&self, input: &Input) -> Result<String, CommandError> {
        let curve = self.read(input)?;
        let doc = match self.command {
            BatchCommand::Antipodal => json_document(
                &commands::antipodal(&curve, &self.curve_opts)?,
                &[&curve],
                None,
            ),
            BatchCommand::Inflections => json_document(
                &commands::inflections(&curve, &self.curve_opts)?,
                &[&curve],
                None,
            ),
            BatchCommand::Bisector => json_document(
                &commands::bisector(&curve, None, &self.bisector_opts)?,
                &[&curve],
                None,
            ),
            BatchCommand::Medial => json_document(
                &commands::medial(&curve, &self.medial_opts)?,
                &[&curve],
                None,
            ),
        };
        Ok(with_input(&input.name(), &doc))
    }

    fn read(&self, input: &Input) -> Result<Curve, CommandError> {
        let region = self.command == BatchCommand::Medial;
        Ok(match input {
            Input::File(path) if region => read_region(path, self.pick)?,
            Input::File(path) => read_curve_picked(path, self.pick)?,
            Input::Line { name, text } if region => {
                parse_region(name, None, text.as_bytes(), self.pick)?
            }
            Input::Line { name, text } => parse_curve(name, text)?,
            Input::Unreadable { error, .. } => return Err(error.clone()),
        })
    }
}

/// A document's line with `"input"` as its first field.
fn with_input(name: &str, doc: &str) -> String {
    let body = doc.trim_end().strip_prefix('{').unwrap_or("}");
    let separator = if body.starts_with('}') { "" } else { "," };
    format!("{{\"input\":{}{separator}{body}\n", Value::from(name))
}

/// Whether `path` names a JSON-lines input (one curve document a line).
fn is_json_lines(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("jsonl"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_input_is_the_first_field_of_its_line() {
        assert_eq!(
            with_input("a \"b\".json", "{\"x\":1}\n"),
            "{\"input\":\"a \\\"b\\\".json\",\"x\":1}\n"
        );
        assert_eq!(with_input("c", "{}\n"), "{\"input\":\"c\"}\n");
    }
}
