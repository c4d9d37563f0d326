//! `curvekit demo`: the built-in examples (embedded, so it runs from any directory): the shapes
//! of Jia's papers and a few B-spline/NURBS curves (inflections, antipodal pairs), then the
//! bisector figures of Elber & Kim, then part outlines with corners (`demo_profiles`), the
//! medial axes (`demo_medial`) and the grasps of two smooth shapes (`demo_grasps`).

use super::report::{antipodal_figure, bisector_figure, draw_curve, time_line};
use super::{
    demo_grasps, demo_medial, demo_profiles, print_out, timing, write_file, Common, Failure,
};
use antipodal::Inflections;
use curvekit::commands::CurveSummary;
use curvekit::io::{parse_curve, Curve, DrawingFormat};
use curvekit::svg::{Figure, Mark, DOT};
use numeric::certificate::Verdict;
use numeric::tolerance::Settings;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::Path;
use std::sync::mpsc;
use std::time::Duration;
use zeroset::{Bisector, BisectorOptions};

/// The text of the file of `fixtures/` whose name is the literals given, joined; embedded.
macro_rules! fixture_text {
    ($($name_part:literal),+) => {
        include_str!(concat!("../../fixtures/", $($name_part),+))
    };
}

/// An embedded curve file of this section: (its name, the text of `fixtures/<name>.json`).
macro_rules! fixture {
    ($name:literal) => {
        ($name, fixture_text!($name, ".json"))
    };
}

/// An [`EmbeddedInput`] of the profile and medial sections: `$name`, from the curve file
/// `$file` of `fixtures/`, or from the drawing `$file` in the format `$format`.
macro_rules! embedded_input {
    ($name:literal, $file:literal) => {
        ($name, None, $crate::cli::demo::fixture_text!($file))
    };
    ($name:literal, $format:ident, $file:literal) => {
        (
            $name,
            Some(curvekit::io::DrawingFormat::$format),
            $crate::cli::demo::fixture_text!($file),
        )
    };
}
pub(super) use {embedded_input, fixture_text};

/// An embedded input of the profile and medial sections: name, format (`None`: a curve
/// file), file text.
pub(super) type EmbeddedInput = (&'static str, Option<DrawingFormat>, &'static str);

/// The failure of the computation `what` of the example `name`, as one line.
pub(super) fn failure<T>(name: &str, what: &str, result: &Result<T, String>) -> Option<String> {
    result
        .as_ref()
        .err()
        .map(|e| format!("{name}: {what}: {e}"))
}

/// Name and file text of each shape example.
const DEMO_SHAPES: &[Embedded] = &[
    fixture!("limacon"),
    fixture!("elliptic_lemniscate"),
    fixture!("convexities_m3"),
    fixture!("convexities_m4"),
    fixture!("ellipse"),
    fixture!("periodic_cubic"),
    fixture!("periodic_nurbs"),
    fixture!("clamped_closed"),
    fixture!("open_nurbs"),
];

/// An embedded curve file: (name, JSON text).
type Embedded = (&'static str, &'static str);

/// The bisector figures of Elber & Kim (the curves are shaped after them): (figure name, first
/// curve, second curve or none for a self-bisector).
const BISECTORS: &[(&str, Embedded, Option<Embedded>)] = &[
    (
        "bisector_fig2",
        fixture!("bisector-fig2-quadratic"),
        Some(fixture!("bisector-fig2-line")),
    ),
    (
        "bisector_fig3",
        fixture!("bisector-fig3-quadratic1"),
        Some(fixture!("bisector-fig3-quadratic2")),
    ),
    (
        "bisector_fig4",
        fixture!("bisector-fig4-quadratic-bspline"),
        None,
    ),
    (
        "bisector_fig5",
        fixture!("bisector-fig5-cubic-bspline"),
        None,
    ),
    (
        "bisector_fig6",
        fixture!("bisector-fig6-cubic-bspline"),
        Some(fixture!("bisector-fig6-line")),
    ),
    (
        "bisector_fig7",
        fixture!("bisector-fig7-quadratic1"),
        Some(fixture!("bisector-fig7-quadratic2")),
    ),
];

/// Longest wait for one bisector: the demo must finish even if a case is slow.
const BISECTOR_BUDGET: Duration = Duration::from_secs(5);

/// A computed cell: `None` where it does not apply (antipodal pairs of an open curve).
type Cell<T> = Option<Result<T, String>>;

struct ShapeRow {
    name: &'static str,
    curve: Curve,
    inflections: Cell<Inflections>,
    pairs: Cell<usize>,
    /// Self-bisector of spline curves (analytic shapes have no exact form to run it on).
    self_bisector: Cell<Bisector>,
    svg: String,
}

struct BisectorRow {
    name: &'static str,
    curves: Vec<Curve>,
    result: Result<Bisector, String>,
    svg: String,
}

pub(super) fn run(out: &Path, common: &Common) -> Result<(), Failure> {
    let opts = common.options()?;
    std::fs::create_dir_all(out)
        .map_err(|e| Failure::io(format!("cannot create {}", out.display()), e))?;
    let shapes = DEMO_SHAPES
        .iter()
        .map(|(name, text)| shape_row(name, text, out, common))
        .collect::<Result<Vec<_>, _>>()?;
    let bisectors = BISECTORS
        .iter()
        .map(|(name, c1, c2)| bisector_row(name, *c1, *c2, out, common))
        .collect::<Result<Vec<_>, _>>()?;
    let profiles = demo_profiles::rows(out, common)?;
    let medial = demo_medial::rows(out, common)?;
    let grasps = demo_grasps::rows(out, common)?;
    let stats = common.time.then(|| {
        timing::measure(|| {
            shapes
                .iter()
                .filter_map(|r| antipodal::inflections(r.curve.plane_curve(), &opts).ok())
                .count()
        })
    });
    let text = if common.json {
        demo_json(
            &shapes,
            &bisectors,
            &profiles,
            &medial,
            &grasps,
            stats.as_ref(),
        )
    } else {
        table(
            &shapes,
            &bisectors,
            &profiles,
            &medial,
            &grasps,
            out,
            stats.as_ref(),
        )
    };
    print_out(&text)?;
    // The demo shows the state of every example; one that fails is reported, not fatal.
    for e in errors(&shapes, &bisectors)
        .into_iter()
        .chain(demo_profiles::errors(&profiles))
        .chain(demo_medial::errors(&medial))
        .chain(demo_grasps::errors(&grasps))
    {
        eprintln!("curvekit: warning: demo example {e}");
    }
    Ok(())
}

/// One line per failed computation.
fn errors(shapes: &[ShapeRow], bisectors: &[BisectorRow]) -> Vec<String> {
    let mut out = Vec::new();
    for r in shapes {
        out.extend(
            r.inflections
                .as_ref()
                .and_then(|c| failure(r.name, "inflections", c)),
        );
        out.extend(
            r.pairs
                .as_ref()
                .and_then(|c| failure(r.name, "antipodal", c)),
        );
        out.extend(
            r.self_bisector
                .as_ref()
                .and_then(|c| failure(r.name, "self-bisector", c)),
        );
    }
    out.extend(
        bisectors
            .iter()
            .filter_map(|r| failure(r.name, "bisector", &r.result)),
    );
    out
}

fn shape_row(
    name: &'static str,
    text: &str,
    out: &Path,
    common: &Common,
) -> Result<ShapeRow, Failure> {
    let curve = parse_curve(&format!("demo:{name}"), text)?;
    let opts = common.options()?;
    let prepared = antipodal::prepare(curve.plane_curve());
    let inflections = Some(prepared.inflections(&opts).map_err(|e| e.to_string()));
    let antipodal = curve
        .is_closed()
        .then(|| prepared.antipodal(&opts).map_err(|e| e.to_string()));
    let self_bisector = curve
        .rational()
        .is_some()
        .then(|| bisector_within_budget(std::slice::from_ref(&curve), opts.settings));
    let title = format!(
        "demo {name} — antipodal: {} pairs, {} inflections",
        cell(&antipodal, |a| a.pairs.len().to_string()),
        cell(&inflections, |i| i.inflections.len().to_string()),
    );
    let svg = out.join(format!("{name}.svg"));
    let figure = match &antipodal {
        Some(Ok(a)) => antipodal_figure(&curve, a, title),
        // An open curve, or a failure (reported in the table): the curve and its inflections.
        _ => {
            let mut fig = Figure::new();
            draw_curve(&mut fig, &curve);
            if let Some(Ok(found)) = &inflections {
                found.inflections.iter().for_each(|i| fig.dot(i.p));
                fig.legend(Mark::Dot(DOT.into()), "inflection");
                fig.status(found.certified(), found.reason().as_deref());
            }
            fig.title(title);
            fig.render()
        }
    };
    write_file(&svg, &figure)?;
    if let Some(Ok(b)) = &self_bisector {
        let title = format!("demo {name} — self-bisector: {}", branches_of(b));
        write_file(
            &out.join(format!("{name}_self_bisector.svg")),
            bisector_figure(&[&curve], b, title),
        )?;
    }
    Ok(ShapeRow {
        name,
        curve,
        inflections,
        pairs: antipodal.map(|r| r.map(|a| a.pairs.len())),
        self_bisector,
        svg: svg.display().to_string(),
    })
}

fn bisector_row(
    name: &'static str,
    c1: Embedded,
    c2: Option<Embedded>,
    out: &Path,
    common: &Common,
) -> Result<BisectorRow, Failure> {
    let mut curves = vec![parse_curve(&format!("demo:{}", c1.0), c1.1)?];
    if let Some((n, text)) = c2 {
        curves.push(parse_curve(&format!("demo:{n}"), text)?);
    }
    let result = bisector_within_budget(&curves, common.options()?.settings);
    let svg = out.join(format!("{name}.svg"));
    let refs: Vec<&Curve> = curves.iter().collect();
    let figure = match &result {
        Ok(b) => bisector_figure(
            &refs,
            b,
            format!("demo {name} — bisector: {}", branches_of(b)),
        ),
        Err(e) => {
            let mut fig = Figure::new();
            curves.iter().for_each(|c| draw_curve(&mut fig, c));
            fig.title(format!("demo {name} — bisector: not computed: {e}"));
            fig.render()
        }
    };
    write_file(&svg, &figure)?;
    Ok(BisectorRow {
        name,
        curves,
        result,
        svg: svg.display().to_string(),
    })
}

/// The bisector of one or two curves (self-bisector for one), computed in a thread so that a
/// slow case is reported as such instead of stalling the demo.
fn bisector_within_budget(curves: &[Curve], settings: Settings) -> Result<Bisector, String> {
    let splines: Vec<curve::SplineCurve> = curves
        .iter()
        .filter_map(|c| c.rational().cloned())
        .filter_map(|r| curve::SplineCurve::new(r).ok())
        .collect();
    let opts = BisectorOptions {
        settings,
        ..BisectorOptions::default()
    };
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let r = match splines.as_slice() {
            [one] => zeroset::self_bisector(one, &opts),
            [a, b] => zeroset::bisector(a, b, &opts),
            _ => Err(zeroset::Error::NotPlanar { which: 1, dim: 0 }),
        };
        let _ = tx.send(r.map_err(|e| e.to_string()));
    });
    rx.recv_timeout(BISECTOR_BUDGET)
        .unwrap_or_else(|e| match e {
            mpsc::RecvTimeoutError::Timeout => {
                Err(format!("timeout (> {} s)", BISECTOR_BUDGET.as_secs_f64()))
            }
            mpsc::RecvTimeoutError::Disconnected => Err("the computation panicked".into()),
        })
}

/// `n branches` of a bisector (`1 branch`), marked when a search limit was hit.
fn branches_of(b: &Bisector) -> String {
    let n = super::commands::branch_count(b.branches.len());
    if b.complete {
        n
    } else {
        format!("{n} (incomplete)")
    }
}

/// A branch count for the summary table, marked when a search limit was hit.
fn branch_count(b: &Bisector) -> String {
    if b.complete {
        b.branches.len().to_string()
    } else {
        format!("{} (incomplete)", b.branches.len())
    }
}

fn cell<T>(c: &Cell<T>, show: impl Fn(&T) -> String) -> String {
    match c {
        None => "-".into(),
        Some(Ok(v)) => show(v),
        Some(Err(_)) => "failed".into(),
    }
}

fn table(
    shapes: &[ShapeRow],
    bisectors: &[BisectorRow],
    profiles: &[demo_profiles::ProfileRow],
    medial: &[demo_medial::MedialRow],
    grasps: &[demo_grasps::GraspRow],
    out: &Path,
    stats: Option<&timing::Stats>,
) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<20} {:<20} {:>11} {:>10} {:>15} {:>22}",
        "curve", "kind", "inflections", "certified", "antipodal pairs", "self-bisector branches"
    );
    for r in shapes {
        let _ = writeln!(
            s,
            "{:<20} {:<20} {:>11} {:>10} {:>15} {:>22}",
            r.name,
            r.curve.kind(),
            cell(&r.inflections, |i| i.inflections.len().to_string()),
            cell(&r.inflections, |i| if i.certified() { "yes" } else { "no" }
                .into()),
            cell(&r.pairs, usize::to_string),
            cell(&r.self_bisector, branch_count),
        );
    }
    let _ = writeln!(
        s,
        "\n{:<14} {:<52} {:>17}",
        "figure", "curves", "bisector branches"
    );
    for r in bisectors {
        let names: Vec<&str> = r
            .curves
            .iter()
            .map(|c| c.file.trim_start_matches("demo:"))
            .collect();
        let branches = r
            .result
            .as_ref()
            .map_or_else(|_| "failed".to_string(), branch_count);
        let _ = writeln!(
            s,
            "{:<14} {:<52} {:>17}",
            r.name,
            names.join(" + "),
            branches
        );
    }
    s.push_str(&demo_profiles::table(profiles));
    s.push_str(&demo_medial::table(medial));
    s.push_str(&demo_grasps::table(grasps));
    for e in errors(shapes, bisectors)
        .into_iter()
        .chain(demo_profiles::errors(profiles))
        .chain(demo_medial::errors(medial))
        .chain(demo_grasps::errors(grasps))
    {
        let _ = writeln!(s, "failed: {e}");
    }
    let _ = writeln!(s, "figures written to {}", out.display());
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

fn demo_json(
    shapes: &[ShapeRow],
    bisectors: &[BisectorRow],
    profiles: &[demo_profiles::ProfileRow],
    medial: &[demo_medial::MedialRow],
    grasps: &[demo_grasps::GraspRow],
    stats: Option<&timing::Stats>,
) -> String {
    let err = |e: &String| json!({ "error": e });
    let shapes: Vec<Value> = shapes
        .iter()
        .map(|r| {
            json!({
                "name": r.name,
                "curve": CurveSummary::of(&r.curve),
                "inflections": r.inflections.as_ref().map(|x| x.as_ref().map_or_else(err, |i| json!(i.inflections))),
                "certified": r.inflections.as_ref().and_then(|x| x.as_ref().ok()).map(|i| i.certified()),
                "pairs": r.pairs.as_ref().map(|x| x.as_ref().map_or_else(err, |n| json!(n))),
                "self_bisector_branches": r.self_bisector.as_ref().map(|x| x.as_ref().map_or_else(err, |b| json!(b.branches.len()))),
                "svg": r.svg,
            })
        })
        .collect();
    let bisectors: Vec<Value> = bisectors
        .iter()
        .map(|r| {
            json!({
                "name": r.name,
                "curves": r.curves.iter().map(CurveSummary::of).collect::<Vec<_>>(),
                "branches": r.result.as_ref().map_or_else(err, |b| json!(b.branches.len())),
                "svg": r.svg,
            })
        })
        .collect();
    let profiles = demo_profiles::json(profiles);
    let medial = demo_medial::json(medial);
    let grasps = demo_grasps::json(grasps);
    let mut doc = json!({
        "shapes": shapes,
        "bisectors": bisectors,
        "profiles": profiles,
        "medial": medial,
        "grasps": grasps,
    });
    if let (Some(s), Some(map)) = (stats, doc.as_object_mut()) {
        map.insert("stats".into(), json!(s));
    }
    format!("{doc}\n")
}
