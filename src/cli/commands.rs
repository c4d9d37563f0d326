//! The single-curve and two-curve commands: read, compute, optionally time and draw, report.

use super::report::{self, draw_curve};
use super::{print_out, timing, write_file, BisectorArgs, Common, Failure};
use curvekit::io::{read_curve_picked, Curve, CurveFileError, Problem, Shape};
use curvekit::svg::Figure;
use std::path::Path;

pub(super) fn run_inflections(path: &Path, common: &Common) -> Result<(), Failure> {
    common.validate()?;
    let curve = read_curve_picked(path, common.pick)?;
    one_curve(&[&curve], "inflections")?;
    if let Shape::Profile(profile) = &curve.shape {
        return run_profile_inflections(&curve, profile, common);
    }
    let plane = curve.plane_curve();
    let opts = common.options();
    let prepared = antipodal::prepare(plane);
    let found = prepared
        .inflections(&opts)
        .map_err(|e| antipodal_failure(e, &[&curve]))?;
    let stats = common.time.then(|| {
        timing::measure_both(
            || prepared.inflections(&opts),
            || antipodal::prepare(plane).inflections(&opts),
        )
    });
    if let Some(svg) = &common.svg {
        let mut fig = Figure::new();
        draw_curve(&mut fig, &curve);
        found.inflections.iter().for_each(|i| fig.dot(i.p));
        fig.title(format!(
            "{}: {} inflections",
            curve.file,
            found.inflections.len()
        ));
        write_file(svg, &fig.render())?;
    }
    print_out(&if common.json {
        report::json_doc(&found, &[&curve], stats.as_ref())
    } else {
        report::inflections_text(&curve, &found, stats.as_ref())
    })
}

/// `inflections` on a profile: inflections at smooth points and joints, and the corners.
fn run_profile_inflections(
    curve: &Curve,
    profile: &curvekit::curve::Profile,
    common: &Common,
) -> Result<(), Failure> {
    let opts = common.options();
    let found = antipodal::profile_inflections(profile, &opts)
        .map_err(|e| antipodal_failure(e, &[curve]))?;
    let stats = common.time.then(|| {
        let run = || antipodal::profile_inflections(profile, &opts);
        timing::measure_both(run, run)
    });
    if let Some(svg) = &common.svg {
        let mut fig = Figure::new();
        draw_curve(&mut fig, curve);
        found.inflections.iter().for_each(|i| fig.dot(i.p));
        for c in &found.corners {
            fig.corner(c.p);
        }
        fig.title(format!(
            "{}: {} inflections, {} corners",
            curve.file,
            found.inflections.len(),
            found.corners.len()
        ));
        write_file(svg, &fig.render())?;
    }
    print_out(&if common.json {
        report::json_doc(&found, &[curve], stats.as_ref())
    } else {
        report::profile_inflections_text(curve, &found, stats.as_ref())
    })
}

/// A region is no curve: the commands on curves refuse it by name (the medial axis, to come,
/// takes regions).
fn one_curve(curves: &[&Curve], command: &str) -> Result<(), Failure> {
    match curves.iter().find(|c| matches!(c.shape, Shape::Region(_))) {
        Some(c) => Err(Failure::Input(CurveFileError {
            file: c.file.clone(),
            field: "kind".into(),
            problem: Problem::Unsupported(format!(
                "{command} takes a curve or a profile, not a region"
            )),
        })),
        None => Ok(()),
    }
}

pub(super) fn run_antipodal(path: &Path, common: &Common) -> Result<(), Failure> {
    common.validate()?;
    let curve = read_curve_picked(path, common.pick)?;
    one_curve(&[&curve], "antipodal")?;
    if let Shape::Profile(profile) = &curve.shape {
        return run_profile_antipodal(&curve, profile, common);
    }
    let plane = curve.plane_curve();
    let opts = common.options();
    let prepared = antipodal::prepare(plane);
    let found = prepared
        .antipodal(&opts)
        .map_err(|e| antipodal_failure(e, &[&curve]))?;
    let stats = common.time.then(|| {
        timing::measure_both(
            || prepared.antipodal(&opts),
            || antipodal::prepare(plane).antipodal(&opts),
        )
    });
    if let Some(svg) = &common.svg {
        let title = format!(
            "{}: {} antipodal pairs, {} inflections",
            curve.file,
            found.pairs.len(),
            found.inflections.len()
        );
        write_file(svg, &report::antipodal_figure(&curve, &found, title))?;
    }
    print_out(&if common.json {
        report::json_doc(&found, &[&curve], stats.as_ref())
    } else {
        report::antipodal_text(&curve, &found, stats.as_ref())
    })
}

/// `antipodal` on a profile: pairs with corners, families with end points, inflections and
/// corners.
fn run_profile_antipodal(
    curve: &Curve,
    profile: &curvekit::curve::Profile,
    common: &Common,
) -> Result<(), Failure> {
    let opts = common.options();
    let found =
        antipodal::profile_antipodal(profile, &opts).map_err(|e| antipodal_failure(e, &[curve]))?;
    let stats = common.time.then(|| {
        let run = || antipodal::profile_antipodal(profile, &opts);
        timing::measure_both(run, run)
    });
    if let Some(svg) = &common.svg {
        let title = format!(
            "{}: {} antipodal pairs, {} corners",
            curve.file,
            found.pairs.len(),
            found.corners.len()
        );
        write_file(svg, &report::profile_antipodal_figure(curve, &found, title))?;
    }
    print_out(&if common.json {
        report::json_doc(&found, &[curve], stats.as_ref())
    } else {
        report::profile_antipodal_text(curve, &found, stats.as_ref())
    })
}

pub(super) fn run_tangents(path1: &Path, path2: &Path, common: &Common) -> Result<(), Failure> {
    common.validate()?;
    let (c1, c2) = (
        read_curve_picked(path1, common.pick)?,
        read_curve_picked(path2, common.pick)?,
    );
    let both = [&c1, &c2];
    one_curve(&both, "tangents")?;
    if both.iter().any(|c| matches!(c.shape, Shape::Profile(_))) {
        return run_profile_tangents(&c1, &c2, common);
    }
    let (p1, p2) = (c1.plane_curve(), c2.plane_curve());
    let opts = common.options();
    let (a, b) = antipodal::prepare_pair(p1, p2);
    let found = a
        .common_tangents(&b, &opts)
        .map_err(|e| antipodal_failure(e, &both))?;
    let stats = common.time.then(|| {
        timing::measure_both(
            || a.common_tangents(&b, &opts),
            || antipodal::common_tangents(p1, p2, &opts),
        )
    });
    if let Some(svg) = &common.svg {
        let mut fig = Figure::new();
        draw_curve(&mut fig, &c1);
        draw_curve(&mut fig, &c2);
        for (k, line) in found.lines.iter().enumerate() {
            fig.segment(line.p, line.q, Some((k + 1).to_string()));
        }
        fig.title(format!("{} common tangent lines", found.lines.len()));
        write_file(svg, &fig.render())?;
    }
    print_out(&if common.json {
        report::json_doc(&found, &both, stats.as_ref())
    } else {
        report::tangents_text(&both, &found, stats.as_ref())
    })
}

/// `tangents` where one curve or both are profiles: the other is taken as a one-segment
/// profile (a line, an arc, an open or clamped spline).
fn run_profile_tangents(c1: &Curve, c2: &Curve, common: &Common) -> Result<(), Failure> {
    let both = [c1, c2];
    let (a, b) = (as_profile(c1, "tangents")?, as_profile(c2, "tangents")?);
    let opts = common.options();
    let run = || antipodal::profile_tangents(&a, &b, &opts);
    let found = run().map_err(|e| antipodal_failure(e, &both))?;
    let stats = common.time.then(|| timing::measure_both(run, run));
    if let Some(svg) = &common.svg {
        let mut fig = Figure::new();
        draw_curve(&mut fig, c1);
        draw_curve(&mut fig, c2);
        for p in [&a, &b] {
            p.corners()
                .for_each(|j| fig.corner(curvekit::curve::ParamCurve::jet(p, j.u).p.arr()));
        }
        for (k, line) in found.lines.iter().enumerate() {
            fig.segment(line.p, line.q, Some((k + 1).to_string()));
        }
        fig.title(format!("{} common tangent lines", found.lines.len()));
        write_file(svg, &fig.render())?;
    }
    print_out(&if common.json {
        report::json_doc(&found, &both, stats.as_ref())
    } else {
        report::profile_tangents_text(&both, &found, stats.as_ref())
    })
}

/// A curve as a profile: itself, or one segment (a line, an arc, a spline that is not
/// periodic); an analytic shape or a periodic spline is refused by name.
fn as_profile(c: &Curve, command: &str) -> Result<curvekit::curve::Profile, Failure> {
    use curvekit::curve::{Profile, Segment, SegmentKind};
    let refuse = |why: &str| {
        Failure::Input(CurveFileError {
            file: c.file.clone(),
            field: "kind".into(),
            problem: Problem::Unsupported(format!(
                "{command} with a profile: {why}; give it as a profile or an open or clamped \
                 spline"
            )),
        })
    };
    let segment = match &c.shape {
        Shape::Profile(p) => return Ok(p.as_ref().clone()),
        Shape::Segment(s) => s.as_ref().clone(),
        Shape::Spline(s) if !s.periodic => Segment::spline(SegmentKind::BSpline, s.plane.clone())
            .map_err(|e| refuse(&e.to_string()))?,
        Shape::Spline(_) => {
            return Err(refuse("a periodic spline has no ends to make a segment of"))
        }
        Shape::Analytic(a) => {
            return Err(refuse(&format!(
                "an analytic {} is not a segment",
                a.kind()
            )))
        }
        Shape::Region(_) => return Err(refuse("a region is not a curve")),
    };
    Profile::new(vec![segment], None).map_err(|e| refuse(&e.to_string()))
}

pub(super) fn run_bisector(
    path1: &Path,
    path2: Option<&Path>,
    args: &BisectorArgs,
    common: &Common,
) -> Result<(), Failure> {
    let opts = args.options(common.tol);
    opts.validate().map_err(zeroset_failure)?;
    let c1 = read_curve_picked(path1, common.pick)?;
    let c2 = path2
        .map(|p| read_curve_picked(p, common.pick))
        .transpose()?;
    let curves: Vec<&Curve> = std::iter::once(&c1).chain(c2.as_ref()).collect();
    one_curve(&curves, "bisector")?;
    if curves.iter().any(|c| matches!(c.shape, Shape::Profile(_))) {
        return run_profile_bisector(&curves, &opts, common);
    }
    let r1 = spline_of(&c1)?;
    let r2 = c2.as_ref().map(spline_of).transpose()?;
    let compute = || match r2 {
        None => zeroset::self_bisector(r1, &opts),
        Some(r2) => zeroset::bisector(r1, r2, &opts),
    };
    let found = compute().map_err(zeroset_failure)?;
    let stats = common.time.then(|| timing::measure(compute));
    if let Some(svg) = &common.svg {
        let title = format!("{} bisector branches", found.branches.len());
        write_file(svg, &report::bisector_figure(&curves, &found, title))?;
    }
    print_out(&if common.json {
        report::json_doc(&found, &curves, stats.as_ref())
    } else {
        report::bisector_text(&curves, &found, stats.as_ref())
    })
}

/// `bisector` where one curve or both are profiles: the other is taken as a one-segment
/// profile (a line, an arc, an open or clamped spline).
fn run_profile_bisector(
    curves: &[&Curve],
    opts: &zeroset::BisectorOptions,
    common: &Common,
) -> Result<(), Failure> {
    let profiles = curves
        .iter()
        .map(|c| as_profile(c, "bisector"))
        .collect::<Result<Vec<_>, _>>()?;
    let compute = || match &profiles[..] {
        [one] => zeroset::profile_self_bisector(one, opts),
        [a, b, ..] => zeroset::profile_bisector(a, b, opts),
        [] => unreachable!("one curve at least"),
    };
    let found = compute().map_err(zeroset_failure)?;
    let stats = common.time.then(|| timing::measure(compute));
    if let Some(svg) = &common.svg {
        let title = format!("{} bisector branches", found.branches.len());
        write_file(
            svg,
            &report::profile_bisector_figure(curves, &profiles, &found, title),
        )?;
    }
    print_out(&if common.json {
        report::json_doc(&found, curves, stats.as_ref())
    } else {
        report::profile_bisector_text(curves, &found, stats.as_ref())
    })
}

fn zeroset_failure(e: zeroset::Error) -> Failure {
    match e {
        zeroset::Error::BadOption { field, value, why } => {
            // (The library's field names, as the command line spells them.)
            let flag = field.replace('_', "-");
            Failure::Usage(format!(
                "--{flag}: {} is out of range: {why}",
                number(value)
            ))
        }
        e => Failure::Other(format!("bisector: {e}")),
    }
}

/// Bisectors are computed on the exact rational form, which only spline kinds have.
fn spline_of(c: &Curve) -> Result<&bspline::Rational, Failure> {
    c.rational().ok_or_else(|| {
        Failure::Input(CurveFileError {
            file: c.file.clone(),
            field: "kind".into(),
            problem: Problem::Unsupported(format!(
                "bisector needs a bezier, bspline, line or arc curve, got {}",
                c.kind()
            )),
        })
    })
}

/// Options errors are usage errors, geometric refusals are input errors naming the curve that
/// caused them, the rest is internal.
pub(super) fn antipodal_failure(e: antipodal::Error, curves: &[&Curve]) -> Failure {
    use antipodal::Error as E;
    match e {
        E::InvalidOption {
            field,
            value,
            expected,
        } => Failure::Usage(format!("--{field}: {value} is out of range: {expected}")),
        E::NotClosed { .. }
        | E::Cusp { .. }
        | E::Corner { .. }
        | E::SelfIntersecting { .. }
        | E::Winding { .. }
        | E::InSegment { .. }
        | E::Curve(_) => match blame(curves) {
            Some(culprit) => Failure::Input(CurveFileError {
                file: culprit.file.clone(),
                field: match culprit.shape {
                    Shape::Spline(_) => "points",
                    Shape::Analytic(_) | Shape::Segment(_) => "kind",
                    Shape::Profile(_) => "segments",
                    Shape::Region(_) => "outer",
                }
                .into(),
                problem: Problem::Geometry(e.to_string()),
            }),
            None => Failure::Other(e.to_string()),
        },
        E::Spline(e) => Failure::Other(format!("spline arithmetic failed: {e}")),
        E::TooComplex { .. } => Failure::Other(e.to_string()),
        // (A refusal of the two profiles together: the first names them.)
        E::TooManySegmentPairs { .. } => match curves.first() {
            Some(c) => Failure::Input(CurveFileError {
                file: c.file.clone(),
                field: "segments".into(),
                problem: Problem::Unsupported(e.to_string()),
            }),
            None => Failure::Other(e.to_string()),
        },
    }
}

/// The curve a geometric refusal is about: with two curves, the first one that is refused on
/// its own (paired with a unit circle, which is never refused), else the second.
fn blame<'c>(curves: &[&'c Curve]) -> Option<&'c Curve> {
    let refused = |c: &Curve| {
        let Ok(circle) = antipodal::shapes::Circle::new(1.0, [0.0, 0.0]) else {
            return false;
        };
        antipodal::common_tangents(c.plane_curve(), &circle, &antipodal::Options::default())
            .is_err()
    };
    match curves {
        [first, second, ..] if !refused(first) => Some(second),
        _ => curves.first().copied(),
    }
}

/// A number as a user would write it: the shorter of the plain and the scientific notation
/// (`1e-12`, not `0.000000000001`).
fn number(x: f64) -> String {
    let (plain, scientific) = (format!("{x}"), format!("{x:e}"));
    if scientific.len() < plain.len() {
        scientific
    } else {
        plain
    }
}
