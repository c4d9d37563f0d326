//! The single-curve and two-curve commands: read, compute (`curvekit::commands`), optionally
//! time and draw, report.

use super::report::{self, draw_curve};
use super::timing::Stats;
use super::{timing, BisectorArgs, Common, Failure};
use curvekit::commands::{
    self, AntipodalFound, BisectorFound, CommandError, InflectionsFound, PreparedCurve,
    TangentsFound,
};
use curvekit::io::{Curve, CurveKind};
use curvekit::svg::{Figure, Mark, DOT};
use numeric::certificate::Verdict;
use serde::Serialize;
use std::path::Path;
use std::sync::Arc;

pub(super) fn run_inflections(path: &Path, common: &Common) -> Result<(), Failure> {
    run_one_curve(
        path,
        common,
        OneCurve {
            name: "inflections",
            warm: PreparedCurve::inflections,
            cold: commands::inflections,
            figure: inflections_figure,
            text: |curve, found, stats| match found {
                InflectionsFound::Curve(f) => report::inflections_text(curve, f, stats),
                InflectionsFound::Profile(f) => report::profile_inflections_text(curve, f, stats),
            },
        },
    )
}

pub(super) fn run_antipodal(path: &Path, common: &Common) -> Result<(), Failure> {
    run_one_curve(
        path,
        common,
        OneCurve {
            name: "antipodal",
            warm: PreparedCurve::antipodal,
            cold: commands::antipodal,
            figure: antipodal_figure,
            text: |curve, found, stats| match found {
                AntipodalFound::Curve(f) => report::antipodal_text(curve, f, stats),
                AntipodalFound::Profile(f) => report::profile_antipodal_text(curve, f, stats),
            },
        },
    )
}

/// A one-curve command as the tool runs it: computed on the curve prepared (warm) and from
/// the curve read (cold, timed beside it), drawn and reported.
struct OneCurve<F> {
    name: &'static str,
    warm: fn(&PreparedCurve, &antipodal::Options) -> Result<F, CommandError>,
    cold: fn(&Curve, &antipodal::Options) -> Result<F, CommandError>,
    figure: fn(&Curve, &F) -> String,
    text: fn(&Curve, &F, Option<&Stats>) -> String,
}

fn run_one_curve<F: Serialize>(
    path: &Path,
    common: &Common,
    command: OneCurve<F>,
) -> Result<(), Failure> {
    let opts = common.options()?;
    let curve = Arc::new(common.read_curve(path)?);
    let prepared = PreparedCurve::new(curve.clone(), command.name)?;
    let found = (command.warm)(&prepared, &opts)?;
    let stats = common.time.then(|| {
        timing::measure_both(
            || (command.warm)(&prepared, &opts),
            || (command.cold)(&curve, &opts),
        )
    });
    common.draw(|| Ok((command.figure)(&curve, &found)))?;
    common.report(&found, &[&curve], stats.as_ref(), || {
        (command.text)(&curve, &found, stats.as_ref())
    })
}

pub(super) fn run_tangents(path1: &Path, path2: &Path, common: &Common) -> Result<(), Failure> {
    let opts = common.options()?;
    super::one_standard_input(&[path1, path2])?;
    let (c1, c2) = (common.read_curve(path1)?, common.read_curve(path2)?);
    let both = [&c1, &c2];
    let run = || commands::tangents(&c1, &c2, &opts);
    let found = run()?;
    let stats = common.time.then(|| match &found {
        // (Two smooth curves: warm on the pair prepared, cold preparing it as well.)
        TangentsFound::Curve(_) => {
            let (a, b) = antipodal::prepare_pair(c1.plane_curve(), c2.plane_curve());
            timing::measure_both(|| a.common_tangents(&b, &opts), run)
        }
        TangentsFound::Profile(_) => timing::measure_both(run, run),
    });
    common.draw(|| Ok(tangents_figure(&both, &found)))?;
    common.report(&found, &both, stats.as_ref(), || match &found {
        TangentsFound::Curve(f) => report::tangents_text(&both, f, stats.as_ref()),
        TangentsFound::Profile(f) => report::profile_tangents_text(&both, f, stats.as_ref()),
    })
}

pub(super) fn run_bisector(
    path1: &Path,
    path2: Option<&Path>,
    args: &BisectorArgs,
    common: &Common,
) -> Result<(), Failure> {
    // (A usage error comes before any file is read.)
    let opts = args.options(common.tol)?;
    super::one_standard_input(
        &[Some(path1), path2]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>(),
    )?;
    let c1 = common.read_curve(path1)?;
    let c2 = path2.map(|p| common.read_curve(p)).transpose()?;
    let curves: Vec<&Curve> = std::iter::once(&c1).chain(c2.as_ref()).collect();
    let (found, stats) = common.computed(|| commands::bisector(&c1, c2.as_ref(), &opts))?;
    common.draw(|| bisector_figure(&curves, &found))?;
    common.report(&found, &curves, stats.as_ref(), || match &found {
        BisectorFound::Curve(f) => report::bisector_text(&curves, f, stats.as_ref()),
        BisectorFound::Profile(f) => report::profile_bisector_text(&curves, f, stats.as_ref()),
    })
}

/// The figure of a curve's inflections (and a profile's corners).
pub(super) fn inflections_figure(curve: &Curve, found: &InflectionsFound) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, curve);
    let (inflections, corners) = (&found.result().inflections, found.result().corner_list());
    inflections.iter().for_each(|i| fig.dot(i.p));
    corners.iter().for_each(|c| fig.corner(c.p));
    let mut title = format!("{} — inflections: {}", curve.file, inflections.len());
    if let CurveKind::Profile(_) = curve.shape {
        title.push_str(&format!(", {} corners", corners.len()));
    }
    if !inflections.is_empty() {
        fig.legend(Mark::Dot(DOT.into()), "inflection");
    }
    if !corners.is_empty() {
        fig.legend(Mark::Square, "corner");
    }
    fig.title(title);
    fig.status(found.certified(), found.reason().as_deref());
    fig.render()
}

/// The figure of a curve's antipodal pairs.
pub(super) fn antipodal_figure(curve: &Curve, found: &AntipodalFound) -> String {
    // (A curve's title counts its inflections, a profile's its corners.)
    let title = |pairs: usize, marks: usize, what: &str| {
        format!("{} — antipodal: {pairs} pairs, {marks} {what}", curve.file)
    };
    let (f, title) = match found {
        AntipodalFound::Curve(f) => (f, title(f.pairs.len(), f.inflections.len(), "inflections")),
        AntipodalFound::Profile(f) => (f, title(f.pairs.len(), f.corner_list().len(), "corners")),
    };
    report::antipodal_figure(curve, f, title)
}

/// The figure of the lines tangent to two curves, numbered.
pub(super) fn tangents_figure(both: &[&Curve], found: &TangentsFound) -> String {
    let mut fig = Figure::new();
    for c in both {
        draw_curve(&mut fig, c);
    }
    for c in both {
        if let CurveKind::Profile(p) = &c.shape {
            p.corners()
                .for_each(|j| fig.corner(curvekit::curve::ParamCurve::jet(&**p, j.u).p.arr()));
        }
    }
    let lines: Vec<([f64; 2], [f64; 2])> =
        found.result().lines.iter().map(|l| (l.p, l.q)).collect();
    for (k, (p, q)) in lines.iter().enumerate() {
        fig.segment(*p, *q, Some((k + 1).to_string()));
    }
    let names: Vec<&str> = both.iter().map(|c| c.file.as_str()).collect();
    fig.title(format!(
        "{} — tangents: {} common tangent lines",
        names.join(" and "),
        lines.len()
    ));
    if !lines.is_empty() {
        fig.legend(
            Mark::Dashed,
            "common tangent, numbered, between its contacts",
        );
    }
    fig.status(found.certified(), found.reason().as_deref());
    fig.render()
}

/// The figure of a bisector (or self-bisector) and its curves.
pub(super) fn bisector_figure(curves: &[&Curve], found: &BisectorFound) -> Result<String, Failure> {
    Ok(match found {
        BisectorFound::Curve(f) => {
            let title = bisector_title(curves, f.branches.len(), f.complete);
            report::bisector_figure(curves, f, title)
        }
        BisectorFound::Profile(f) => {
            let title = bisector_title(curves, f.branches.len(), f.complete);
            let profiles = curves
                .iter()
                .map(|c| commands::as_profile(c, "bisector"))
                .collect::<Result<Vec<_>, _>>()?;
            report::profile_bisector_figure(curves, &profiles, f, title)
        }
    })
}

/// A bisector figure's title: the files, the branches, and whether the search was complete
/// (a bisector has no certificate to state).
fn bisector_title(curves: &[&Curve], branches: usize, complete: bool) -> String {
    let names: Vec<&str> = curves.iter().map(|c| c.file.as_str()).collect();
    let what = if curves.len() == 1 {
        "self-bisector"
    } else {
        "bisector"
    };
    format!(
        "{} — {what}: {}{}",
        names.join(" and "),
        branch_count(branches),
        if complete {
            ""
        } else {
            " (incomplete: a search limit was hit)"
        }
    )
}

/// `n branches`, or `1 branch`.
pub(super) fn branch_count(n: usize) -> String {
    if n == 1 {
        "1 branch".into()
    } else {
        format!("{n} branches")
    }
}
