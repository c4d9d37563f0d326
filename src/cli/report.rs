//! Text and JSON reports, and drawing a curve into a figure.

use super::timing::Stats;
use antipodal::{
    Antipodal, CornerKind, Inflection, InflectionKind, Inflections, ProfileAntipodal,
    ProfileInflections, ProfileTangents, Tangents,
};
use curvekit::curve::ParamCurve;
use curvekit::curve::Profile;
use curvekit::io::{Curve, Shape};
use curvekit::svg::{side_by_side, Figure, Mark, DOT};
use std::fmt::Write as _;
use zeroset::{Bisector, Branch, ProfileBisector, ProfileBranch};

/// How far a region's drawn boundary strays from it, as a share of its size (a tenth of a
/// pixel at the figures' 640 pixels).
const REGION_FLATNESS: f64 = 1e-4;

/// The curve as a dense polyline in a figure.
pub(crate) fn draw_curve(fig: &mut Figure, curve: &Curve) {
    let n = match &curve.shape {
        Shape::Spline(s) => (24 * s.n_points).clamp(600, 20_000),
        Shape::Analytic(_) | Shape::Segment(_) => 1200,
        Shape::Profile(p) => (200 * p.segments().len()).clamp(600, 20_000),
        Shape::Region(_) | Shape::Regions(_) => {
            // (Within 1e-4 of the size, in the neutral colour: a region is the ground its
            // results are drawn on.)
            let parts = curve.parts();
            for b in parts
                .iter()
                .flat_map(|r| std::iter::once(r.outer()).chain(r.holes()))
            {
                fig.boundary(b.flattened(REGION_FLATNESS * b.size()), true);
            }
            return;
        }
    };
    fig.curve(curve.polyline(n), curve.is_closed());
}

/// One line describing a curve.
pub(crate) fn describe(curve: &Curve) -> String {
    let (a, b) = curve.domain();
    let shape = match &curve.shape {
        Shape::Spline(s) => {
            let mut d = format!(
                "{}, degree {}, {} points",
                curve.kind(),
                s.curve.degree(),
                s.n_points
            );
            if s.weighted {
                d.push_str(", rational");
            }
            if s.periodic {
                d.push_str(", periodic");
            }
            d
        }
        Shape::Analytic(_) | Shape::Segment(_) => curve.kind().to_string(),
        Shape::Profile(p) => format!(
            "profile, {} segments, {} corners",
            p.segments().len(),
            p.corners().count()
        ),
        Shape::Region(r) => format!("region, {} holes", r.holes().len()),
        Shape::Regions(parts) => format!(
            "{} parts, {} holes",
            parts.len(),
            parts.iter().map(|r| r.holes().len()).sum::<usize>()
        ),
    };
    let closed = if curve.is_closed() { "closed" } else { "open" };
    let mut line = format!("{shape}, {closed}, domain [{a}, {b}]");
    if let Some(d) = &curve.drawing {
        if let Some(units) = &d.units {
            line.push_str(&format!(", in {units}"));
        }
        if !d.skipped.is_empty() {
            let list: Vec<String> = d
                .skipped
                .iter()
                .map(|s| format!("{} {}", s.count, s.kind))
                .collect();
            line.push_str(&format!("; not read: {}", list.join(", ")));
        }
    }
    line
}

/// The readable inflection report.
pub(crate) fn inflections_text(curve: &Curve, r: &Inflections, stats: Option<&Stats>) -> String {
    let mut s = inflection_lines(curve, &r.inflections, r.certified);
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// The curve, then a line per inflection (with its segment on a profile).
fn inflection_lines(curve: &Curve, inflections: &[Inflection], certified: bool) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "curve:       {} ({})", curve.file, describe(curve));
    let _ = writeln!(
        s,
        "inflections: {} ({})",
        inflections.len(),
        certified_word(certified)
    );
    for (i, f) in inflections.iter().enumerate() {
        let note = match (f.certified, f.kind) {
            (true, _) => "",
            (false, InflectionKind::Cluster) => "  cluster, not certified",
            (false, _) => "  not certified",
        };
        let seg = f
            .segment
            .map_or(String::new(), |k| format!("  segment {k}"));
        let _ = writeln!(
            s,
            "  {:>3}  u = {:<22}  p = ({}, {}){seg}{note}",
            i + 1,
            n(f.u),
            n(f.p[0]),
            n(f.p[1])
        );
    }
    s
}

/// The text report of `inflections` on a profile: its inflections, then its corners.
pub(crate) fn profile_inflections_text(
    curve: &Curve,
    r: &ProfileInflections,
    stats: Option<&Stats>,
) -> String {
    let mut s = inflection_lines(curve, &r.inflections, r.certified);
    let _ = writeln!(s, "corners:     {}", r.corners.len());
    for (i, c) in r.corners.iter().enumerate() {
        let kind = match c.kind {
            CornerKind::Convex => "convex",
            CornerKind::Reflex => "reflex",
        };
        let _ = writeln!(
            s,
            "  {:>3}  u = {:<22}  p = ({}, {})  turn {} rad, {kind}",
            i + 1,
            n(c.u),
            n(c.p[0]),
            n(c.p[1]),
            n(c.turn)
        );
    }
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// The `--time` line of text reports.
pub(crate) fn time_line(st: &Stats) -> String {
    let mut line = format!(
        "time:        median {:.3} µs per run over {} runs",
        st.median_us, st.runs
    );
    if let (Some(cold), Some(runs)) = (st.cold_median_us, st.cold_runs) {
        let _ = write!(
            line,
            "; first run on a freshly read curve {cold:.3} µs ({runs} runs)"
        );
    }
    line
}

fn curve_line(s: &mut String, label: &str, curve: &Curve) {
    let _ = writeln!(s, "{label:<13}{} ({})", curve.file, describe(curve));
}

fn certified_word(certified: bool) -> &'static str {
    if certified {
        "certified"
    } else {
        "not certified"
    }
}

/// The readable antipodal report.
pub(crate) fn antipodal_text(curve: &Curve, r: &Antipodal, stats: Option<&Stats>) -> String {
    let mut s = String::new();
    curve_line(&mut s, "curve:", curve);
    let complete = if r.complete { "" } else { ", INCOMPLETE" };
    let _ = writeln!(
        s,
        "pairs:       {} ({}{complete})",
        r.pairs.len(),
        certified_word(r.certified)
    );
    for (k, p) in r.pairs.iter().enumerate() {
        let _ = writeln!(
            s,
            "  {:>3}  type {:?}  s = {:<20}  t = {:<20}  p = ({}, {})  q = ({}, {})  distance {}",
            k + 1,
            p.kind,
            n(p.s),
            n(p.t),
            n(p.p[0]),
            n(p.p[1]),
            n(p.q[0]),
            n(p.q[1]),
            n(p.distance)
        );
    }
    let _ = writeln!(s, "families:    {}", r.families.len());
    for f in &r.families {
        let _ = writeln!(
            s,
            "       s in [{}, {}]  t in [{}, {}]",
            n(f.s[0]),
            n(f.s[1]),
            n(f.t[0]),
            n(f.t[1])
        );
    }
    let _ = writeln!(s, "inflections: {}", r.inflections.len());
    for (k, i) in r.inflections.iter().enumerate() {
        let _ = writeln!(
            s,
            "  {:>3}  u = {:<22}  p = ({}, {})",
            k + 1,
            n(i.u),
            n(i.p[0]),
            n(i.p[1])
        );
    }
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// The readable antipodal report of a profile: pairs (with their corners and segments),
/// families with their end points, inflections and corners.
pub(crate) fn profile_antipodal_text(
    curve: &Curve,
    r: &ProfileAntipodal,
    stats: Option<&Stats>,
) -> String {
    let mut s = String::new();
    curve_line(&mut s, "curve:", curve);
    let complete = if r.complete { "" } else { ", INCOMPLETE" };
    let _ = writeln!(
        s,
        "pairs:       {} ({}{complete})",
        r.pairs.len(),
        certified_word(r.certified)
    );
    if let Some(why) = r.reason.as_ref().filter(|_| !r.certified) {
        let _ = writeln!(s, "  (why: {why})");
    }
    for (k, p) in r.pairs.iter().enumerate() {
        let kind = p.kind.map_or("-".to_string(), |t| format!("{t:?}"));
        let end = |corner: bool, segment: usize| {
            if corner {
                format!("corner {segment}")
            } else {
                format!("segment {segment}")
            }
        };
        let _ = writeln!(
            s,
            "  {:>3}  type {kind}  s = {:<20}  t = {:<20}  p = ({}, {})  q = ({}, {})  distance {}  ({}, {})",
            k + 1,
            n(p.s),
            n(p.t),
            n(p.p[0]),
            n(p.p[1]),
            n(p.q[0]),
            n(p.q[1]),
            n(p.distance),
            end(p.corner[0], p.segment[0]),
            end(p.corner[1], p.segment[1]),
        );
    }
    let _ = writeln!(s, "families:    {}", r.families.len());
    for f in &r.families {
        let _ = writeln!(
            s,
            "       s in [{}, {}]  t in [{}, {}]  from ({}, {})-({}, {}) to ({}, {})-({}, {})",
            n(f.s[0]),
            n(f.s[1]),
            n(f.t[0]),
            n(f.t[1]),
            n(f.p[0][0]),
            n(f.p[0][1]),
            n(f.q[0][0]),
            n(f.q[0][1]),
            n(f.p[1][0]),
            n(f.p[1][1]),
            n(f.q[1][0]),
            n(f.q[1][1]),
        );
    }
    let corners = ProfileInflections {
        inflections: r.inflections.clone(),
        corners: r.corners.clone(),
        certified: r.certified,
        reason: None,
    };
    // (Its first line names the curve again.)
    let rest = profile_inflections_text(curve, &corners, stats);
    s.push_str(rest.split_once('\n').map_or("", |(_, rest)| rest));
    s
}

/// The readable common-tangent report.
pub(crate) fn tangents_text(curves: &[&Curve], r: &Tangents, stats: Option<&Stats>) -> String {
    let mut s = String::new();
    for (k, c) in curves.iter().enumerate() {
        curve_line(&mut s, &format!("curve {}:", k + 1), c);
    }
    let _ = writeln!(
        s,
        "lines:       {} ({})",
        r.lines.len(),
        certified_word(r.certified)
    );
    for (k, l) in r.lines.iter().enumerate() {
        let _ = writeln!(
            s,
            "  {:>3}  s = {:<20}  t = {:<20}  p = ({}, {})  q = ({}, {})",
            k + 1,
            n(l.s),
            n(l.t),
            n(l.p[0]),
            n(l.p[1]),
            n(l.q[0]),
            n(l.q[1])
        );
    }
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// The readable common-tangent report of profiles: each line with its corners and segments.
pub(crate) fn profile_tangents_text(
    curves: &[&Curve],
    r: &ProfileTangents,
    stats: Option<&Stats>,
) -> String {
    let mut s = String::new();
    for (k, c) in curves.iter().enumerate() {
        curve_line(&mut s, &format!("curve {}:", k + 1), c);
    }
    let _ = writeln!(
        s,
        "lines:       {} ({})",
        r.lines.len(),
        certified_word(r.certified)
    );
    if let Some(why) = r.reason.as_ref().filter(|_| !r.certified) {
        let _ = writeln!(s, "  (why: {why})");
    }
    let end = |corner: bool, segment: usize| {
        if corner {
            format!("corner {segment}")
        } else {
            format!("segment {segment}")
        }
    };
    for (k, l) in r.lines.iter().enumerate() {
        let _ = writeln!(
            s,
            "  {:>3}  s = {:<20}  t = {:<20}  p = ({}, {})  q = ({}, {})  ({}, {})",
            k + 1,
            n(l.s),
            n(l.t),
            n(l.p[0]),
            n(l.p[1]),
            n(l.q[0]),
            n(l.q[1]),
            end(l.corner[0], l.segment[0]),
            end(l.corner[1], l.segment[1]),
        );
    }
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// The readable bisector report (branch ends; the full polylines are in the JSON).
pub(crate) fn bisector_text(curves: &[&Curve], r: &Bisector, stats: Option<&Stats>) -> String {
    let branches = r.branches.iter().map(|b| (&b.xy[..], String::new()));
    let counts = [r.singular.len(), r.isolated.len()];
    bisector_lines(curves, r.complete, branches, counts, stats)
}

/// The readable bisector report of profiles: as for curves, with the sites of each branch.
pub(crate) fn profile_bisector_text(
    curves: &[&Curve],
    r: &ProfileBisector,
    stats: Option<&Stats>,
) -> String {
    let site = |k: usize, b: &ProfileBranch| {
        let what = if b.corner[k] { "corner" } else { "segment" };
        format!("{what} {}", b.segment[k])
    };
    let branches = r
        .branches
        .iter()
        .map(|b| (&b.xy[..], format!(", {} and {}", site(0, b), site(1, b))));
    let counts = [r.singular.len(), r.isolated.len()];
    bisector_lines(curves, r.complete, branches, counts, stats)
}

/// The lines of a bisector report: the curves, each branch's ends (and what follows them),
/// the counts of singular and isolated points.
fn bisector_lines<'a>(
    curves: &[&Curve],
    complete: bool,
    branches: impl ExactSizeIterator<Item = (&'a [[f64; 2]], String)>,
    [singular, isolated]: [usize; 2],
    stats: Option<&Stats>,
) -> String {
    let mut s = String::new();
    for (k, c) in curves.iter().enumerate() {
        curve_line(&mut s, &format!("curve {}:", k + 1), c);
    }
    let complete = if complete {
        ""
    } else {
        " (INCOMPLETE: search limit hit)"
    };
    let _ = writeln!(s, "branches:    {}{complete}", branches.len());
    for (k, (xy, sites)) in branches.enumerate() {
        if let (Some(first), Some(last)) = (xy.first(), xy.last()) {
            let _ = writeln!(
                s,
                "  {:>3}  {} points, from ({}, {}) to ({}, {}){sites}",
                k + 1,
                xy.len(),
                n(first[0]),
                n(first[1]),
                n(last[0]),
                n(last[1])
            );
        }
    }
    let _ = writeln!(s, "singular:    {singular}\nisolated:    {isolated}");
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// The colour of a family of antipodal pairs (its two end pairs), set apart from the isolated
/// pairs' dashed grey.
const FAMILY: &str = "#2a8c4a";

/// The legend of an antipodal figure: what each mark is, for those drawn.
fn antipodal_legend(
    fig: &mut Figure,
    pairs: usize,
    families: usize,
    inflections: usize,
    corners: usize,
) {
    if pairs > 0 {
        fig.legend(Mark::Dashed, format!("antipodal pair, numbered: {pairs}"));
    }
    if families > 0 {
        fig.legend(
            Mark::Line(FAMILY.into(), 1.4),
            format!("family of pairs (its two end pairs): {families}"),
        );
    }
    if inflections > 0 {
        fig.legend(Mark::Dot(DOT.into()), format!("inflection: {inflections}"));
    }
    if corners > 0 {
        fig.legend(Mark::Square, format!("corner: {corners}"));
    }
}

/// The antipodal figure: the curve, its inflections, each pair as a numbered segment (Jia's
/// Figures 1 and 24) and each family by its two end pairs; the header says whether the answer
/// is certified.
pub(crate) fn antipodal_figure(curve: &Curve, found: &Antipodal, title: String) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, curve);
    for (k, pair) in found.pairs.iter().enumerate() {
        fig.segment(pair.p, pair.q, Some((k + 1).to_string()));
    }
    for f in &found.families {
        for k in 0..2 {
            let (p, q) = (curve.point_at(f.s[k]), curve.point_at(f.t[k]));
            fig.colored(vec![p, q], FAMILY.into());
        }
    }
    found.inflections.iter().for_each(|i| fig.dot(i.p));
    antipodal_legend(
        &mut fig,
        found.pairs.len(),
        found.families.len(),
        found.inflections.len(),
        0,
    );
    fig.title(title);
    fig.status(found.certified, found.reason.as_deref());
    fig.render()
}

/// The antipodal figure of a profile: as for a curve, with the corners marked.
pub(crate) fn profile_antipodal_figure(
    curve: &Curve,
    found: &ProfileAntipodal,
    title: String,
) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, curve);
    for (k, pair) in found.pairs.iter().enumerate() {
        fig.segment(pair.p, pair.q, Some((k + 1).to_string()));
    }
    for f in &found.families {
        fig.colored(vec![f.p[0], f.q[0]], FAMILY.into());
        fig.colored(vec![f.p[1], f.q[1]], FAMILY.into());
    }
    found.inflections.iter().for_each(|i| fig.dot(i.p));
    found.corners.iter().for_each(|c| fig.corner(c.p));
    antipodal_legend(
        &mut fig,
        found.pairs.len(),
        found.families.len(),
        found.inflections.len(),
        found.corners.len(),
    );
    fig.title(title);
    fig.status(found.certified, found.reason.as_deref());
    fig.render()
}

/// The bisector figure, as in Elber and Kim's: the curves, the bisector branches and thin
/// lines from a few bisector points to their foot points, framed around the curves (branches
/// run off to infinity where the normals turn parallel); beside it, the zero set in the
/// `(t, r)` parameter square. `curves` holds one curve for a self-bisector.
pub(crate) fn bisector_figure(curves: &[&Curve], r: &Bisector, title: String) -> String {
    let (c1, c2) = match curves {
        [c1] => (*c1, *c1),
        [c1, c2, ..] => (*c1, *c2),
        [] => return Figure::new().render(),
    };
    // (The parameters reported are the documents'.)
    let foot = |k: usize, u: f64| {
        if k == 0 {
            c1.point_at(u)
        } else {
            c2.point_at(u)
        }
    };
    let domains = [c1.domain(), c2.domain()];
    plane_and_parameters(curves, r, &foot, domains, &[], title)
}

/// The bisector figure of profiles: as for curves, the corners marked, the foot points and
/// the parameter square the profiles'.
pub(crate) fn profile_bisector_figure(
    curves: &[&Curve],
    profiles: &[Profile],
    r: &ProfileBisector,
    title: String,
) -> String {
    let (Some(a), Some(b)) = (profiles.first(), profiles.last()) else {
        return Figure::new().render();
    };
    let plain = Bisector {
        branches: r
            .branches
            .iter()
            .map(|b| Branch {
                tr: b.tr.clone(),
                xy: b.xy.clone(),
            })
            .collect(),
        singular: Vec::new(),
        isolated: Vec::new(),
        complete: r.complete,
    };
    // (The parameters reported are the documents'.)
    let on = |p: &Profile, u: f64| p.jet(p.internal_param(u)).p.arr();
    let foot = |k: usize, u: f64| if k == 0 { on(a, u) } else { on(b, u) };
    let corners: Vec<[f64; 2]> = profiles
        .iter()
        .flat_map(|p| p.corners().map(|j| p.jet(j.u).p.arr()))
        .collect();
    plane_and_parameters(
        curves,
        &plain,
        &foot,
        [a.document_domain(), b.document_domain()],
        &corners,
        title,
    )
}

/// The curves, the bisector branches and thin lines from a few bisector points to their foot
/// points (`foot(k, u)` on curve `k`), corners marked, framed around the curves; beside it
/// the zero set in the parameter square of `domains`.
fn plane_and_parameters(
    curves: &[&Curve],
    r: &Bisector,
    foot: &dyn Fn(usize, f64) -> [f64; 2],
    domains: [(f64, f64); 2],
    corners: &[[f64; 2]],
    title: String,
) -> String {
    let mut plane = Figure::new();
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for c in curves {
        draw_curve(&mut plane, c);
        for p in c.polyline(256) {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    if lo[0] <= hi[0] {
        let pad = 0.5 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
        plane.frame([lo[0] - pad, lo[1] - pad], [hi[0] + pad, hi[1] + pad]);
    }
    // (A few foot-point lines, spread over the branches, from points inside the frame: more
    // would hide the bisector.)
    let inside = |p: &[f64; 2]| {
        let pad = 0.5 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
        (lo[0] - pad..=hi[0] + pad).contains(&p[0]) && (lo[1] - pad..=hi[1] + pad).contains(&p[1])
    };
    let framed: usize = r
        .branches
        .iter()
        .map(|b| b.xy.iter().filter(|p| inside(p)).count())
        .sum();
    let every = (framed / FOOT_LINES).max(1);
    let mut seen = 0;
    for b in &r.branches {
        plane.thin(b.xy.clone(), "#d62020");
        for (tr, xy) in b.tr.iter().zip(&b.xy).filter(|(_, p)| inside(p)) {
            if seen % every == every / 2 {
                plane.thin(vec![foot(0, tr[0]), *xy, foot(1, tr[1])], "#999999");
            }
            seen += 1;
        }
    }
    corners.iter().for_each(|&c| plane.corner(c));
    if !r.branches.is_empty() {
        plane.legend(Mark::Line("#d62020".into(), 0.6), "bisector");
        plane.legend(
            Mark::Line("#999999".into(), 0.6),
            "a bisector point to its two foot points",
        );
    }
    if !corners.is_empty() {
        plane.legend(Mark::Square, "corner");
    }
    plane.title(title);

    // The parameter square, scaled to a unit square so that both domains read alike.
    let [(t0, t1), (r0, r1)] = domains;
    let unit = |tr: &[f64; 2]| [(tr[0] - t0) / (t1 - t0), (tr[1] - r0) / (r1 - r0)];
    let mut params = Figure::new();
    params.thin(
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]],
        "#444444",
    );
    for b in &r.branches {
        params.thin(b.tr.iter().map(unit).collect(), "#d62020");
    }
    params.text([0.45, -0.08], format!("t ∈ [{}, {}]", n(t0), n(t1)));
    params.text([-0.05, 1.03], format!("r ∈ [{}, {}]", n(r0), n(r1)));
    params.frame([-0.08, -0.1], [1.02, 1.06]);
    params.title("zero set in (t, r)");
    side_by_side(&[&plane, &params])
}

/// Foot-point lines drawn in a bisector figure, over all its branches.
const FOOT_LINES: usize = 12;

/// Magnitudes that text reports print in plain decimals; outside, in scientific form (not a
/// tolerance: plain form would run to many zeros before or after the digits that matter).
const PLAIN: std::ops::Range<f64> = 1e-4..1e7;

/// A number for text reports: shortest round-trip form, scientific when tiny or huge.
fn n(x: f64) -> String {
    if x != 0.0 && !PLAIN.contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
