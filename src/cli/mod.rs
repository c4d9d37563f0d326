//! Command-line arguments, dispatch, and the exit status of each kind of failure.

mod batch;
mod commands;
mod demo;
mod demo_grasps;
mod demo_medial;
mod demo_profiles;
mod grasps;
mod medial;
mod offset;
pub(crate) mod progress;
mod report;
mod timing;
mod vcarve;

use clap::{Args, Parser, Subcommand};
use curvekit::commands::{settings, CommandFamily};
use numeric::tolerance::{Settings, DEFAULT_CHORD_TOL};
use std::path::{Path, PathBuf};

/// Certified geometry on planar freeform curves.
#[derive(Debug, Parser)]
#[command(name = "curvekit", version, about)]
pub(crate) struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run the built-in examples, write their figures, print a summary table.
    Demo {
        /// Directory for the SVG figures.
        #[arg(long, value_name = "DIR", default_value = "demo-out")]
        out: PathBuf,
        #[command(flatten)]
        options: DemoArgs,
    },
    /// Antipodal point pairs of a closed curve.
    Antipodal {
        /// Curve file (JSON).
        curve: PathBuf,
        #[command(flatten)]
        common: Common,
    },
    /// Inflections of a curve.
    Inflections {
        /// Curve file (JSON).
        curve: PathBuf,
        #[command(flatten)]
        common: Common,
    },
    /// Two-finger force-closure grasps of a closed curve with friction: the regions of pairs
    /// of contacts, each with its contact stretches and its most robust grasp.
    Grasps {
        /// Curve file (JSON), or a drawing.
        curve: PathBuf,
        /// The Coulomb friction coefficient μ between finger and curve (> 0): the friction
        /// cone's half-angle is atan μ.
        #[arg(long, value_name = "MU", allow_hyphen_values = true)]
        friction: f64,
        /// The gripper's least opening: pairs of contacts closer than W are left out.
        #[arg(long, value_name = "W", allow_hyphen_values = true)]
        min_width: Option<f64>,
        /// The gripper's greatest opening: pairs of contacts farther apart than W are left out.
        #[arg(long, value_name = "W", allow_hyphen_values = true)]
        max_width: Option<f64>,
        /// Chord tolerance of the regions' boundaries, relative to the parameter domain.
        #[arg(long, value_name = "C", default_value_t = numeric::tolerance::DEFAULT_CHORD_TOL, value_parser = parse_tol, allow_hyphen_values = true)]
        chord_tol: f64,
        #[command(flatten)]
        common: Common,
    },
    /// Lines tangent to two curves.
    Tangents {
        /// First curve file (JSON).
        curve1: PathBuf,
        /// Second curve file (JSON).
        curve2: PathBuf,
        #[command(flatten)]
        common: Common,
    },
    /// Bisector of two curves, or the self-bisector of one.
    Bisector {
        /// First curve file (JSON).
        curve1: PathBuf,
        /// Second curve file (JSON); omitted: the self-bisector of the first.
        curve2: Option<PathBuf>,
        #[command(flatten)]
        options: BisectorArgs,
        #[command(flatten)]
        common: Common,
    },
    /// The medial axis (skeleton) of a region, or of the area inside a closed curve.
    Medial {
        /// Region file (JSON), or a closed curve or profile.
        region: PathBuf,
        /// Chord tolerance of the edges, relative to the region's size.
        #[arg(long, value_name = "C", default_value_t = numeric::tolerance::DEFAULT_CHORD_TOL, value_parser = parse_tol, allow_hyphen_values = true)]
        chord_tol: f64,
        /// Each edge also as a B-spline of the axis and the radius, within the chord tolerance.
        #[arg(long)]
        fit: bool,
        /// The exterior axis instead: outside the outer boundary and inside the holes, clipped
        /// to the region's box grown by half its size.
        #[arg(long)]
        exterior: bool,
        #[command(flatten)]
        out: OutFiles,
        #[command(flatten)]
        common: Common,
    },
    /// The inward offsets of a region: the boundary of its points at distance at least D from
    /// its boundary (pocketing tool paths), from its medial axis.
    Offset {
        /// Region file (JSON), or a closed curve or profile, or a drawing.
        region: PathBuf,
        /// One distance.
        #[arg(long, value_name = "D", allow_hyphen_values = true, conflicts_with_all = ["distances", "step"], required_unless_present_any = ["distances", "step"])]
        distance: Option<f64>,
        /// Several distances, comma-separated, sharing one medial axis.
        #[arg(
            long,
            value_name = "D1,D2,…",
            value_delimiter = ',',
            allow_hyphen_values = true,
            conflicts_with = "step"
        )]
        distances: Option<Vec<f64>>,
        /// Every multiple of S while the region lasts.
        #[arg(long, value_name = "S", allow_hyphen_values = true)]
        step: Option<f64>,
        /// Outward offsets (from the exterior medial axis).
        #[arg(long)]
        outward: bool,
        /// Chord tolerance of the medial axis and of the offsets of splines, relative to the
        /// region's size.
        #[arg(long, value_name = "C", default_value_t = numeric::tolerance::DEFAULT_CHORD_TOL, value_parser = parse_tol, allow_hyphen_values = true)]
        chord_tol: f64,
        #[command(flatten)]
        out: OutFiles,
        #[command(flatten)]
        common: Common,
    },
    /// V-carving tool paths: the medial axis at the depth a V-bit of the given angle cuts its
    /// disks from, clipped at the largest depth with a flat pass there.
    Vcarve {
        /// Region file (JSON), or a closed curve or profile, or a drawing.
        region: PathBuf,
        /// The bit's included angle, in degrees (between 0 and 180).
        #[arg(long, value_name = "A", allow_hyphen_values = true)]
        angle: f64,
        /// The deepest cut, in the drawing's units.
        #[arg(long, value_name = "H", allow_hyphen_values = true)]
        max_depth: Option<f64>,
        /// Chord tolerance of the medial axis and of the flat pass, relative to the region's
        /// size.
        #[arg(long, value_name = "C", default_value_t = numeric::tolerance::DEFAULT_CHORD_TOL, value_parser = parse_tol, allow_hyphen_values = true)]
        chord_tol: f64,
        /// Also write the tool paths as a DXF (3D polylines, the flat pass at its depth).
        #[arg(long, value_name = "FILE")]
        dxf: Option<PathBuf>,
        #[command(flatten)]
        common: Common,
    },
    /// Print a completion script for a shell (bash, zsh, fish, elvish, powershell), to be
    /// sourced by it or saved where it looks.
    Completions {
        /// The shell.
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// One command over many inputs, on several threads: one JSON line per input, in input
    /// order; an input that fails becomes an error line and the run goes on.
    Batch(batch::Batch),
}

/// Options of the bisector command.
#[derive(Debug, Clone, Args)]
pub(crate) struct BisectorArgs {
    /// Bisector function of Elber and Kim (§3): f1 (Eq. 3), f2 (normal form) or f3 (Eq. 13).
    #[arg(long, value_enum, default_value_t = MethodArg::F3)]
    pub(crate) method: MethodArg,
    /// Keep only points whose foot points are the nearest points of the curves (the trimmed
    /// bisector of a medial axis or a Voronoi diagram).
    #[arg(long)]
    pub(crate) trimmed: bool,
    /// Chord tolerance of the bisector polylines, relative to the curves' bounding-box diagonal.
    #[arg(long, value_name = "C", default_value_t = numeric::tolerance::DEFAULT_CHORD_TOL, value_parser = parse_tol, allow_hyphen_values = true)]
    pub(crate) chord_tol: f64,
}

/// The bisector function, as named on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum MethodArg {
    /// Eq. 3: equal distances along the normals.
    F1,
    /// §3.2: the normal form.
    F2,
    /// Eq. 13 times the cross product of the tangents: lowest degree (default).
    F3,
}

impl MethodArg {
    /// The library's bisector function.
    pub(crate) fn method(self) -> zeroset::Method {
        match self {
            MethodArg::F1 => zeroset::Method::F1,
            MethodArg::F2 => zeroset::Method::F2,
            MethodArg::F3 => zeroset::Method::F3,
        }
    }
}

impl BisectorArgs {
    /// The library's options for these arguments and the common tolerance (out of range: a
    /// usage error).
    pub(crate) fn options(&self, tol: f64) -> Result<zeroset::BisectorOptions, Failure> {
        Ok(zeroset::BisectorOptions {
            method: self.method.method(),
            settings: settings(CommandFamily::Bisector, tol, self.chord_tol)?,
            trimmed: self.trimmed,
            ..zeroset::BisectorOptions::default()
        })
    }
}

/// The options of `demo`: its inputs are built in, its figures go to `--out`.
#[derive(Debug, Clone, Args)]
pub(crate) struct DemoArgs {
    /// Print one JSON document instead of the summary table.
    #[arg(long)]
    json: bool,
    /// Parameter tolerance.
    #[arg(long, value_name = "T", default_value_t = numeric::tolerance::DEFAULT_PARAM_TOL, value_parser = parse_tol, allow_hyphen_values = true)]
    tol: f64,
    /// Repeat the examples' inflections for at least 0.5 s and report the median time.
    #[arg(long)]
    time: bool,
}

impl DemoArgs {
    /// The options every command takes, as far as `demo` has them.
    fn common(&self) -> Common {
        Common {
            json: self.json,
            svg: None,
            tol: self.tol,
            time: self.time,
            pick: None,
            format: None,
        }
    }
}

/// The result files of `medial` and `offset`, for CAD and CAM programs.
#[derive(Debug, Clone, Args)]
pub(crate) struct OutFiles {
    /// Also write the result as a DXF (R2010): curves as computed, never flattened.
    #[arg(long, value_name = "FILE")]
    pub(crate) dxf: Option<PathBuf>,
    /// Also write the result as plain SVG paths in the input's coordinates (which curvekit
    /// reads back; `--svg` is the figure).
    #[arg(long, value_name = "FILE")]
    pub(crate) svg_paths: Option<PathBuf>,
}

impl OutFiles {
    /// Writes `found` as the files asked for: its DXF (`dxf`) and its SVG paths (`svg`), in
    /// the drawing's `units`.
    pub(crate) fn write<R>(
        &self,
        found: &R,
        units: Option<&str>,
        dxf: fn(&R, Option<&str>) -> Result<Vec<u8>, curvekit::export::ExportError>,
        svg: fn(&R, Option<&str>) -> Result<String, curvekit::export::ExportError>,
    ) -> Result<(), Failure> {
        write_export(self.dxf.as_deref(), || dxf(found, units))?;
        write_export(self.svg_paths.as_deref(), || svg(found, units))
    }
}

/// Options every command takes.
#[derive(Debug, Clone, Args)]
pub(crate) struct Common {
    /// Print one JSON document instead of the text report.
    #[arg(long)]
    pub(crate) json: bool,
    /// Also write an SVG figure to FILE.
    #[arg(long, value_name = "FILE")]
    pub(crate) svg: Option<PathBuf>,
    /// Parameter tolerance.
    #[arg(long, value_name = "T", default_value_t = numeric::tolerance::DEFAULT_PARAM_TOL, value_parser = parse_tol, allow_hyphen_values = true)]
    pub(crate) tol: f64,
    /// Repeat the computation for at least 0.5 s and report the median time of one run.
    #[arg(long)]
    pub(crate) time: bool,
    /// In a drawing (.svg, .dxf) that holds several profiles, the one to take (from 0).
    #[arg(long, value_name = "N")]
    pub(crate) pick: Option<usize>,
    /// The input's format: for `-` (standard input; json unless given), or a file whose
    /// extension does not say.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub(crate) format: Option<FormatArg>,
}

/// An input's format, as named on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum FormatArg {
    /// A curve, profile or region file.
    Json,
    /// An SVG drawing.
    Svg,
    /// An ASCII DXF drawing.
    Dxf,
}

impl Common {
    fn input_format(&self) -> Option<curvekit::io::InputFormat> {
        self.format.map(|f| match f {
            FormatArg::Json => curvekit::io::InputFormat::Json,
            FormatArg::Svg => curvekit::io::InputFormat::Svg,
            FormatArg::Dxf => curvekit::io::InputFormat::Dxf,
        })
    }

    /// The region at `path` (`-`: standard input), in `--format` or by its extension.
    pub(crate) fn read_region(&self, path: &Path) -> Result<curvekit::io::Curve, Failure> {
        Ok(curvekit::io::read_region_as(
            path,
            self.input_format(),
            self.pick,
        )?)
    }

    /// The curve at `path` (`-`: standard input), in `--format` or by its extension.
    pub(crate) fn read_curve(&self, path: &Path) -> Result<curvekit::io::Curve, Failure> {
        Ok(curvekit::io::read_curve_as(
            path,
            self.input_format(),
            self.pick,
        )?)
    }

    /// The curve algorithms' options for these command-line options, checked (before any
    /// file is read: a usage error comes first).
    pub(crate) fn options(&self) -> Result<antipodal::Options, Failure> {
        let settings = settings(CommandFamily::Curves, self.tol, DEFAULT_CHORD_TOL)?;
        let opts = antipodal::Options {
            settings,
            ..antipodal::Options::default()
        };
        curvekit::commands::validate_options(&opts)?;
        Ok(opts)
    }

    /// The settings of a command on regions: `--tol` and its `--chord-tol`.
    pub(crate) fn region_settings(&self, chord_tol: f64) -> Result<Settings, Failure> {
        settings(CommandFamily::Regions, self.tol, chord_tol)
    }

    /// The medial axis's options of a command on regions (its settings from `--tol` and its
    /// `--chord-tol`), the axis fitted with `fit`, the exterior one with `exterior`.
    pub(crate) fn axis_options(
        &self,
        chord_tol: f64,
        (fit, exterior): (bool, bool),
    ) -> Result<curvekit::medial::MedialOptions, Failure> {
        Ok(curvekit::medial::MedialOptions {
            settings: self.region_settings(chord_tol)?,
            fit,
            exterior,
        })
    }

    /// What `compute` finds, and with `--time` the time it takes (computed again).
    pub(crate) fn computed<T>(
        &self,
        mut compute: impl FnMut() -> Result<T, curvekit::commands::CommandError>,
    ) -> Result<(T, Option<timing::Stats>), Failure> {
        let found = compute()?;
        let stats = self.time.then(|| timing::measure(compute));
        Ok((found, stats))
    }

    /// Writes the figure `figure` draws to the `--svg` file, where one is asked for.
    pub(crate) fn draw(
        &self,
        figure: impl FnOnce() -> Result<String, Failure>,
    ) -> Result<(), Failure> {
        match &self.svg {
            Some(svg) => write_file(svg, figure()?),
            None => Ok(()),
        }
    }

    /// Prints the report of `found` on `curves`: its JSON document with `--json`, else the
    /// text `text` writes.
    pub(crate) fn report(
        &self,
        found: &impl serde::Serialize,
        curves: &[&curvekit::io::Curve],
        stats: Option<&timing::Stats>,
        text: impl FnOnce() -> String,
    ) -> Result<(), Failure> {
        print_out(&if self.json {
            curvekit::commands::json_document(found, curves, stats)
        } else {
            text()
        })
    }
}

fn parse_tol(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
        Ok(_) => Err("must be a finite number > 0".into()),
        Err(_) => Err("not a number".into()),
    }
}

/// Why a command failed, and so its exit status.
pub(crate) use curvekit::commands::CommandError as Failure;
pub(crate) use curvekit::commands::UsageError;

/// Runs one command.
pub(crate) fn run(cli: Cli) -> Result<(), Failure> {
    match cli.command {
        Command::Demo { out, options } => demo::run(&out, &options.common()),
        Command::Completions { shell } => {
            use clap::CommandFactory;
            let mut script = Vec::new();
            clap_complete::generate(shell, &mut Cli::command(), "curvekit", &mut script);
            print_out(&String::from_utf8_lossy(&script))
        }
        Command::Inflections { curve, common } => commands::run_inflections(&curve, &common),
        Command::Antipodal { curve, common } => commands::run_antipodal(&curve, &common),
        Command::Tangents {
            curve1,
            curve2,
            common,
        } => commands::run_tangents(&curve1, &curve2, &common),
        Command::Grasps {
            curve,
            friction,
            min_width,
            max_width,
            chord_tol,
            common,
        } => grasps::run(
            &curve,
            &grasps::GraspArgs {
                friction,
                min_width,
                max_width,
                chord_tol,
            },
            &common,
        ),
        Command::Bisector {
            curve1,
            curve2,
            options,
            common,
        } => commands::run_bisector(&curve1, curve2.as_deref(), &options, &common),
        Command::Medial {
            region,
            chord_tol,
            fit,
            exterior,
            out,
            common,
        } => medial::run(&region, chord_tol, (fit, exterior), &out, &common),
        Command::Offset {
            region,
            distance,
            distances,
            step,
            outward,
            chord_tol,
            out,
            common,
        } => {
            let asked = match (distance, distances, step) {
                (Some(d), _, _) => curvekit::commands::Distances::List(vec![d]),
                (_, Some(list), _) => curvekit::commands::Distances::List(list),
                (_, _, Some(s)) => curvekit::commands::Distances::Step(s),
                _ => curvekit::commands::Distances::List(Vec::new()),
            };
            offset::run(&region, &asked, (chord_tol, outward), &out, &common)
        }
        Command::Vcarve {
            region,
            angle,
            max_depth,
            chord_tol,
            dxf,
            common,
        } => vcarve::run(
            &region,
            (angle, max_depth),
            chord_tol,
            dxf.as_deref(),
            &common,
        ),
        Command::Batch(b) => batch::run(&b),
    }
}

/// Standard input (`-`) can be read once: at most one of `paths` may name it.
pub(crate) fn one_standard_input(paths: &[&Path]) -> Result<(), Failure> {
    let stdin = Path::new(curvekit::io::STDIN_PATH);
    if paths.iter().filter(|p| **p == stdin).count() > 1 {
        return Err(UsageError::Conflict("only one input can be standard input (-)").into());
    }
    Ok(())
}

/// Writes a file, mapping failure to exit 1 with the path named.
pub(crate) fn write_file(path: &Path, contents: impl AsRef<[u8]>) -> Result<(), Failure> {
    std::fs::write(path, contents)
        .map_err(|e| Failure::io(format!("cannot write {}", path.display()), e))
}

/// A result that could not be written (exit 1).
pub(crate) fn export_failure(e: curvekit::export::ExportError) -> Failure {
    Failure::Export(e)
}

/// Writes the file `export` makes of a result to `path`, where one is asked for (`--dxf`,
/// `--svg-paths`).
pub(crate) fn write_export<C: AsRef<[u8]>>(
    path: Option<&Path>,
    export: impl FnOnce() -> Result<C, curvekit::export::ExportError>,
) -> Result<(), Failure> {
    match path {
        Some(path) => write_file(path, export().map_err(export_failure)?),
        None => Ok(()),
    }
}

/// Prints to stdout; a closed pipe ends the output quietly (exit 0), as `head` expects.
pub(crate) fn print_out(text: &str) -> Result<(), Failure> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        // (The reader stopped reading, as `head` does: nothing more is wanted, no failure.)
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other.map_err(|e| Failure::io("cannot write to stdout".into(), e)),
    }
}
