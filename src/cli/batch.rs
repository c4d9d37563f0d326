//! `curvekit batch`: one command over many inputs on a pool of threads, one JSON line per input
//! in input order; an input that fails becomes its line, never the end of the run.

use super::{Failure, MethodArg, UsageError};
use clap::Args;
use curvekit::commands::{self, json_document, CommandError, CommandFamily};
use curvekit::io::{
    parse_curve, parse_region, read_curve_picked, read_region, Curve, CurveFileError,
};
use indicatif::{ProgressBar, ProgressStyle};
use numeric::tolerance::DEFAULT_CHORD_TOL;
use rayon::prelude::*;
use serde_json::Value;
use std::collections::BTreeMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::mpsc;

/// Most threads `--jobs` accepts: far beyond any machine's cores, a guard against a typo.
const MAX_JOBS: usize = 1024;

/// The commands batch mode runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum BatchCommand {
    /// `antipodal`.
    Antipodal,
    /// `inflections`.
    Inflections,
    /// `tangents` of each input with the curve `--with`.
    Tangents,
    /// `bisector` of each input: its self-bisector, or its bisector with the curve `--with`.
    Bisector,
    /// `medial`.
    Medial,
    /// `offset`.
    Offset,
    /// `vcarve`.
    Vcarve,
}

/// What one run of batch mode does, from the command line.
#[derive(Debug, Clone, Args)]
pub(crate) struct Batch {
    /// The command to run on each input.
    #[arg(value_enum)]
    pub(crate) command: BatchCommand,
    /// Curve, region or drawing files; a `.jsonl` file holds one curve document a line.
    #[arg(required = true, value_name = "INPUTS")]
    pub(crate) inputs: Vec<PathBuf>,
    /// Threads (default: one per core).
    #[arg(long, value_name = "N")]
    pub(crate) jobs: Option<usize>,
    /// Write the JSON lines to FILE instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// Also write each input's figure into DIR (named by its place and file, `0007-bolt.svg`;
    /// its line says where, as `"figure"`).
    #[arg(long, value_name = "DIR")]
    pub(crate) figures: Option<PathBuf>,
    /// Parameter tolerance.
    #[arg(long, value_name = "T", default_value_t = numeric::tolerance::DEFAULT_PARAM_TOL, value_parser = super::parse_tol, allow_hyphen_values = true)]
    pub(crate) tol: f64,
    /// Chord tolerance (bisector, medial, offset, vcarve), relative to the size.
    #[arg(long, value_name = "C", default_value_t = numeric::tolerance::DEFAULT_CHORD_TOL, value_parser = super::parse_tol, allow_hyphen_values = true)]
    pub(crate) chord_tol: f64,
    /// The other curve (tangents: required; bisector: the bisector with it, not the
    /// self-bisector).
    #[arg(long, value_name = "FILE")]
    pub(crate) with: Option<PathBuf>,
    /// Bisector function (bisector).
    #[arg(long, value_enum, default_value_t = MethodArg::F3)]
    pub(crate) method: MethodArg,
    /// Only the trimmed bisector (bisector).
    #[arg(long)]
    pub(crate) trimmed: bool,
    /// Edges also as fitted B-splines (medial).
    #[arg(long)]
    pub(crate) fit: bool,
    /// The exterior axis (medial), outward offsets (offset).
    #[arg(long, alias = "outward")]
    pub(crate) exterior: bool,
    /// One distance (offset).
    #[arg(long, value_name = "D", allow_hyphen_values = true, conflicts_with_all = ["distances", "step"])]
    pub(crate) distance: Option<f64>,
    /// Several distances, comma-separated (offset).
    #[arg(
        long,
        value_name = "D1,D2,…",
        value_delimiter = ',',
        allow_hyphen_values = true,
        conflicts_with = "step"
    )]
    pub(crate) distances: Option<Vec<f64>>,
    /// Every multiple of S while the region lasts (offset).
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub(crate) step: Option<f64>,
    /// The bit's included angle in degrees (vcarve).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub(crate) angle: Option<f64>,
    /// The deepest cut (vcarve).
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    pub(crate) max_depth: Option<f64>,
    /// In a drawing that holds several profiles or regions, the one to take (from 0).
    #[arg(long, value_name = "N")]
    pub(crate) pick: Option<usize>,
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
        error: CurveFileError,
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
            return Err(
                UsageError::out_of_range("jobs", n, format!("between 1 and {MAX_JOBS}")).into(),
            )
        }
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let task = Task::new(batch)?;
    let inputs = expand(&batch.inputs);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .map_err(|source| Failure::Threads { jobs, source })?;
    let mut sink: Box<dyn Write> = match &batch.out {
        Some(path) => Box::new(std::io::BufWriter::new(
            std::fs::File::create(path)
                .map_err(|e| Failure::io(format!("cannot write {}", path.display()), e))?,
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
                        let _ = tx.send((k, task.run_caught(k, input)));
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
        other => other.map_err(|e| Failure::io("batch: cannot write the results".into(), e))?,
    }
    if failures.is_empty() {
        return Ok(());
    }
    Err(Failure::Batch {
        failed: failures.len(),
        inputs: inputs.len(),
        computation_failed: failures.iter().any(|e| e.exit_code() != 2),
        first: Box::new(failures.swap_remove(0)),
    })
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
                error: CurveFileError {
                    file,
                    field: "document".into(),
                    problem: curvekit::io::Problem::Unreadable(e.to_string()),
                },
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

/// The command with its options, checked once before any input is read (with the curve
/// `--with`, read once).
struct Task {
    command: BatchCommand,
    pick: Option<usize>,
    figures: Option<PathBuf>,
    with: Option<Curve>,
    curve_opts: antipodal::Options,
    bisector_opts: zeroset::BisectorOptions,
    medial_opts: medial::MedialOptions,
    offset_opts: offset::OffsetOptions,
    distances: commands::Distances,
    vcarve_opts: offset::VCarveOptions,
}

/// The options of `b` the command does not take, by name (each names the commands it is for).
fn not_taken(b: &Batch) -> Vec<&'static str> {
    use BatchCommand as C;
    let c = b.command;
    let offsets = b.distance.is_some() || b.distances.is_some() || b.step.is_some();
    [
        (
            "--with",
            b.with.is_some() && !matches!(c, C::Tangents | C::Bisector),
        ),
        ("--trimmed", b.trimmed && c != C::Bisector),
        ("--fit", b.fit && c != C::Medial),
        (
            "--exterior",
            b.exterior && !matches!(c, C::Medial | C::Offset),
        ),
        ("--distance, --distances, --step", offsets && c != C::Offset),
        (
            "--angle, --max-depth",
            (b.angle.is_some() || b.max_depth.is_some()) && c != C::Vcarve,
        ),
    ]
    .into_iter()
    .filter(|(_, given)| *given)
    .map(|(name, _)| name)
    .collect()
}

impl Task {
    fn new(b: &Batch) -> Result<Self, Failure> {
        let refused = not_taken(b);
        if !refused.is_empty() {
            return Err(UsageError::NotTaken {
                command: b.command.name(),
                options: refused,
            }
            .into());
        }
        // The settings, once, in the words of the command's family (the curve commands take
        // no chord tolerance: theirs is the default).
        let settings = match b.command {
            BatchCommand::Antipodal | BatchCommand::Inflections | BatchCommand::Tangents => {
                commands::settings(CommandFamily::Curves, b.tol, DEFAULT_CHORD_TOL)?
            }
            BatchCommand::Bisector => {
                commands::settings(CommandFamily::Bisector, b.tol, b.chord_tol)?
            }
            BatchCommand::Medial | BatchCommand::Offset | BatchCommand::Vcarve => {
                commands::settings(CommandFamily::Regions, b.tol, b.chord_tol)?
            }
        };
        let curve_opts = antipodal::Options {
            settings,
            ..antipodal::Options::default()
        };
        let bisector_opts = zeroset::BisectorOptions {
            method: b.method.method(),
            settings,
            trimmed: b.trimmed,
            ..zeroset::BisectorOptions::default()
        };
        let medial_opts = medial::MedialOptions {
            settings,
            fit: b.fit,
            exterior: b.exterior,
        };
        let offset_opts = offset::OffsetOptions { settings };
        let distances = match (&b.distance, &b.distances, b.step) {
            (Some(d), _, _) => commands::Distances::List(vec![*d]),
            (_, Some(list), _) => commands::Distances::List(list.clone()),
            (_, _, Some(s)) => commands::Distances::Step(s),
            _ => commands::Distances::List(Vec::new()),
        };
        let vcarve_opts = offset::VCarveOptions {
            angle: b.angle.unwrap_or(f64::NAN),
            max_depth: b.max_depth,
            offset: offset_opts,
        };
        match b.command {
            BatchCommand::Antipodal | BatchCommand::Inflections | BatchCommand::Tangents => {
                commands::validate_options(&curve_opts)?
            }
            BatchCommand::Bisector | BatchCommand::Medial => {}
            BatchCommand::Offset => commands::validate_offset(&distances, b.exterior)?,
            BatchCommand::Vcarve => {
                if b.angle.is_none() {
                    return Err(UsageError::Missing("batch vcarve: --angle is required").into());
                }
                commands::validate_vcarve_options(&vcarve_opts)?;
            }
        }
        if b.command == BatchCommand::Tangents && b.with.is_none() {
            return Err(UsageError::Missing(
                "batch tangents: --with FILE is required (the curve each input is paired with)",
            )
            .into());
        }
        let with = b
            .with
            .as_deref()
            .map(|path| read_curve_picked(path, None))
            .transpose()?;
        if let Some(dir) = &b.figures {
            std::fs::create_dir_all(dir)
                .map_err(|e| Failure::io(format!("cannot create {}", dir.display()), e))?;
        }
        Ok(Self {
            command: b.command,
            pick: b.pick,
            figures: b.figures.clone(),
            with,
            curve_opts,
            bisector_opts,
            medial_opts,
            offset_opts,
            distances,
            vcarve_opts,
        })
    }

    /// [`Task::run`], with a panic (a defect, never expected) made this input's failure.
    fn run_caught(&self, k: usize, input: &Input) -> Result<String, CommandError> {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.run(k, input)))
            .unwrap_or_else(|_| Err(CommandError::panicked()))
    }

    /// Reads input `k` and runs the command on it: the JSON document of `--json`, with the
    /// input's name first (and its figure's path, where figures are asked for).
    fn run(&self, k: usize, input: &Input) -> Result<String, CommandError> {
        let curve = self.read(input)?;
        let pair = [&curve].into_iter().chain(&self.with).collect::<Vec<_>>();
        let drawn = self.figures.is_some();
        let (doc, figure) = match self.command {
            BatchCommand::Antipodal => {
                let found = commands::antipodal(&curve, &self.curve_opts)?;
                let figure = drawn.then(|| super::commands::antipodal_figure(&curve, &found));
                (json_document(&found, &[&curve], None), figure)
            }
            BatchCommand::Inflections => {
                let found = commands::inflections(&curve, &self.curve_opts)?;
                let figure = drawn.then(|| super::commands::inflections_figure(&curve, &found));
                (json_document(&found, &[&curve], None), figure)
            }
            BatchCommand::Tangents => {
                let other = self.with.as_ref().ok_or_else(|| {
                    CommandError::from(UsageError::Missing(
                        "batch tangents: --with FILE is required",
                    ))
                })?;
                let found = commands::tangents(&curve, other, &self.curve_opts)?;
                let figure = drawn.then(|| super::commands::tangents_figure(&pair, &found));
                (json_document(&found, &pair, None), figure)
            }
            BatchCommand::Bisector => {
                let found = commands::bisector(&curve, self.with.as_ref(), &self.bisector_opts)?;
                let figure = drawn
                    .then(|| super::commands::bisector_figure(&pair, &found))
                    .transpose()?;
                (json_document(&found, &pair, None), figure)
            }
            BatchCommand::Medial => {
                let axis = commands::medial(&curve, &self.medial_opts)?;
                let figure = drawn.then(|| super::medial::axis_figure(&curve, &axis));
                (json_document(&axis, &[&curve], None), figure)
            }
            BatchCommand::Offset => {
                let found = commands::offset(
                    &curve,
                    &self.distances,
                    &self.offset_opts,
                    &self.medial_opts,
                )?;
                let figure = drawn.then(|| super::offset::figure(&curve, &found));
                (json_document(&found, &[&curve], None), figure)
            }
            BatchCommand::Vcarve => {
                let found = commands::vcarve(&curve, &self.vcarve_opts, &self.medial_opts)?;
                let figure = drawn.then(|| super::vcarve::figure(&curve, &found));
                (json_document(&found, &[&curve], None), figure)
            }
        };
        let line = with_input(&input.name(), &doc);
        match (&self.figures, figure) {
            (Some(dir), Some(svg)) => {
                let path = dir.join(figure_name(k, &input.name()));
                std::fs::write(&path, svg)
                    .map_err(|e| CommandError::io(format!("cannot write {}", path.display()), e))?;
                Ok(with_figure(&line, &path))
            }
            _ => Ok(line),
        }
    }

    fn read(&self, input: &Input) -> Result<Curve, CommandError> {
        let region = matches!(
            self.command,
            BatchCommand::Medial | BatchCommand::Offset | BatchCommand::Vcarve
        );
        Ok(match input {
            Input::File(path) if region => read_region(path, self.pick)?,
            Input::File(path) => read_curve_picked(path, self.pick)?,
            Input::Line { name, text } if region => {
                parse_region(name, None, text.as_bytes(), self.pick)?
            }
            Input::Line { name, text } => parse_curve(name, text)?,
            Input::Unreadable { error, .. } => return Err(CommandError::Input(error.clone())),
        })
    }
}

impl BatchCommand {
    /// The command's name on the command line.
    fn name(self) -> &'static str {
        match self {
            BatchCommand::Antipodal => "antipodal",
            BatchCommand::Inflections => "inflections",
            BatchCommand::Tangents => "tangents",
            BatchCommand::Bisector => "bisector",
            BatchCommand::Medial => "medial",
            BatchCommand::Offset => "offset",
            BatchCommand::Vcarve => "vcarve",
        }
    }
}

/// The figure file of input `k` named `name`: its place (so that two inputs of one name do
/// not meet) and the name's last part, in characters every file system takes.
fn figure_name(k: usize, name: &str) -> String {
    let stem = Path::new(name)
        .file_stem()
        .map_or(name.into(), |s| s.to_string_lossy());
    let clean: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{k:04}-{clean}.svg")
}

/// A line with `"figure": path` added last.
fn with_figure(line: &str, path: &Path) -> String {
    let body = line.trim_end().strip_suffix('}').unwrap_or(line);
    format!(
        "{body},\"figure\":{}}}\n",
        Value::from(path.display().to_string())
    )
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
