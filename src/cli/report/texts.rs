//! The text reports of the curve commands (`inflections`, `antipodal`, `tangents`,
//! `bisector`), on curves and on profiles.

use super::{describe, n, time_line};
use crate::cli::timing::Stats;
use antipodal::{
    Antipodal, AntipodalPair, CornerKind, Inflection, InflectionKind, Inflections, Tangents,
};
use curvekit::io::Curve;
use numeric::certificate::Verdict;
use std::fmt::Write as _;
use zeroset::{Bisector, Branch};

/// The readable inflection report.
pub(crate) fn inflections_text(curve: &Curve, r: &Inflections, stats: Option<&Stats>) -> String {
    let mut s = inflection_lines(curve, &r.inflections, r);
    push_time_line(&mut s, stats);
    s
}

/// The curve, then a line per inflection (with its segment on a profile).
fn inflection_lines(curve: &Curve, inflections: &[Inflection], r: &impl Verdict) -> String {
    let mut s = String::new();
    curve_line(&mut s, "curve:", curve);
    count_line(
        &mut s,
        "inflections:",
        inflections.len(),
        r,
        Why::Unstated,
        "",
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
        inflection_row(&mut s, i, f, &format!("{seg}{note}"));
    }
    s
}

/// The line of the `k`-th inflection: its number, parameter and point, then `after`.
fn inflection_row(s: &mut String, k: usize, f: &Inflection, after: &str) {
    let _ = writeln!(
        s,
        "  {:>3}  u = {:<22}  p = ({}, {}){after}",
        k + 1,
        n(f.u),
        n(f.p[0]),
        n(f.p[1])
    );
}

/// The text report of `inflections` on a profile: its inflections, then its corners.
pub(crate) fn profile_inflections_text(
    curve: &Curve,
    r: &Inflections,
    stats: Option<&Stats>,
) -> String {
    let mut s = inflection_lines(curve, &r.inflections, r);
    let _ = writeln!(s, "corners:     {}", r.corner_list().len());
    for (i, c) in r.corner_list().iter().enumerate() {
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
    push_time_line(&mut s, stats);
    s
}

fn curve_line(s: &mut String, label: &str, curve: &Curve) {
    let _ = writeln!(s, "{label:<13}{} ({})", curve.file, describe(curve));
}

/// A line per curve of a two-curve report (`curve 1:`, `curve 2:`).
fn curves_lines(s: &mut String, curves: &[&Curve]) {
    for (k, c) in curves.iter().enumerate() {
        curve_line(s, &format!("curve {}:", k + 1), c);
    }
}

fn certified_word(certified: bool) -> &'static str {
    if certified {
        "certified"
    } else {
        "not certified"
    }
}

/// The count line of what a result found (`pairs:       3 (certified)`), and on a profile
/// the reason it is not certified.
fn count_line(s: &mut String, label: &str, count: usize, r: &impl Verdict, why: Why, extra: &str) {
    let _ = writeln!(
        s,
        "{label:<13}{count} ({}{extra})",
        certified_word(r.certified())
    );
    if why == Why::Stated && !r.certified() {
        if let Some(reason) = r.reason() {
            let _ = writeln!(s, "  (why: {reason})");
        }
    }
}

/// Whether a report states why its result is not certified (the profile reports do).
#[derive(Clone, Copy, PartialEq)]
enum Why {
    Stated,
    Unstated,
}

/// The time line, where the command was timed.
fn push_time_line(s: &mut String, stats: Option<&Stats>) {
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
}

/// Where on a profile a point lies: at a corner or on a segment, by its number.
fn site(corner: bool, segment: usize) -> String {
    let what = if corner { "corner" } else { "segment" };
    format!("{what} {segment}")
}

/// The two sites a pair or a tangent line joins on profiles: `  (corner 1, segment 3)`;
/// nothing between smooth curves, which have neither.
fn sites(corner: Option<[bool; 2]>, segment: Option<[usize; 2]>) -> String {
    let (Some(corner), Some(segment)) = (corner, segment) else {
        return String::new();
    };
    format!(
        "  ({}, {})",
        site(corner[0], segment[0]),
        site(corner[1], segment[1])
    )
}

/// The parameters and points of a chord that joins `p` at `s` to `q` at `t` (an antipodal
/// pair, a common tangent line).
fn chord(s: f64, t: f64, p: [f64; 2], q: [f64; 2]) -> String {
    format!(
        "s = {:<20}  t = {:<20}  p = ({}, {})  q = ({}, {})",
        n(s),
        n(t),
        n(p[0]),
        n(p[1]),
        n(q[0]),
        n(q[1])
    )
}

/// The ranges of parameters a family of antipodal pairs spans.
fn family_range(s: [f64; 2], t: [f64; 2]) -> String {
    format!(
        "s in [{}, {}]  t in [{}, {}]",
        n(s[0]),
        n(s[1]),
        n(t[0]),
        n(t[1])
    )
}

/// A line of an antipodal report, on a curve or a profile: the pair's type (if it has one),
/// its chord, its length and (on a profile) its sites.
struct PairRow {
    kind: String,
    chord: String,
    distance: f64,
    sites: String,
}

/// The head of an antipodal report, on a curve or a profile: the curve, the pairs and the
/// families (each family's range and what follows it).
fn antipodal_head(
    curve: &Curve,
    r: &impl Verdict,
    complete: bool,
    why: Why,
    pairs: impl ExactSizeIterator<Item = PairRow>,
    families: impl ExactSizeIterator<Item = String>,
) -> String {
    let mut s = String::new();
    curve_line(&mut s, "curve:", curve);
    let complete = if complete { "" } else { ", INCOMPLETE" };
    count_line(&mut s, "pairs:", pairs.len(), r, why, complete);
    for (k, p) in pairs.enumerate() {
        let _ = writeln!(
            s,
            "  {:>3}  type {}  {}  distance {}{}",
            k + 1,
            p.kind,
            p.chord,
            n(p.distance),
            p.sites
        );
    }
    let _ = writeln!(s, "families:    {}", families.len());
    for f in families {
        let _ = writeln!(s, "       {f}");
    }
    s
}

/// A pair's row: its type (`-` where it has none), chord, distance and, on a profile, its
/// sites.
fn pair_row(p: &AntipodalPair) -> PairRow {
    PairRow {
        kind: p.kind.map_or("-".to_string(), |t| format!("{t:?}")),
        chord: chord(p.s, p.t, p.p, p.q),
        distance: p.distance,
        sites: sites(p.corner, p.segment),
    }
}

/// The readable antipodal report.
pub(crate) fn antipodal_text(curve: &Curve, r: &Antipodal, stats: Option<&Stats>) -> String {
    let pairs = r.pairs.iter().map(pair_row);
    let families = r.families.iter().map(|f| family_range(f.s, f.t));
    let mut s = antipodal_head(curve, r, r.complete, Why::Unstated, pairs, families);
    let _ = writeln!(s, "inflections: {}", r.inflections.len());
    for (k, i) in r.inflections.iter().enumerate() {
        inflection_row(&mut s, k, i, "");
    }
    push_time_line(&mut s, stats);
    s
}

/// The readable antipodal report of a profile: pairs (with their corners and segments),
/// families with their end points, inflections and corners.
pub(crate) fn profile_antipodal_text(
    curve: &Curve,
    r: &Antipodal,
    stats: Option<&Stats>,
) -> String {
    let pairs = r.pairs.iter().map(pair_row);
    let families = r.families.iter().map(|f| {
        // (A profile's family has its end points.)
        let (p, q) = (f.p.unwrap_or_default(), f.q.unwrap_or_default());
        format!(
            "{}  from ({}, {})-({}, {}) to ({}, {})-({}, {})",
            family_range(f.s, f.t),
            n(p[0][0]),
            n(p[0][1]),
            n(q[0][0]),
            n(q[0][1]),
            n(p[1][0]),
            n(p[1][1]),
            n(q[1][0]),
            n(q[1][1]),
        )
    });
    let mut s = antipodal_head(curve, r, r.complete, Why::Stated, pairs, families);
    let corners = Inflections {
        inflections: r.inflections.clone(),
        corners: r.corners.clone(),
        doubts: r.doubts.clone(),
    };
    // (Its first line names the curve again.)
    let rest = profile_inflections_text(curve, &corners, stats);
    s.push_str(rest.split_once('\n').map_or("", |(_, rest)| rest));
    s
}

/// A common-tangent report, of curves or profiles: the curves, then each line's chord and
/// what follows it.
fn tangent_lines(
    curves: &[&Curve],
    r: &impl Verdict,
    why: Why,
    lines: impl ExactSizeIterator<Item = String>,
    stats: Option<&Stats>,
) -> String {
    let mut s = String::new();
    curves_lines(&mut s, curves);
    count_line(&mut s, "lines:", lines.len(), r, why, "");
    for (k, line) in lines.enumerate() {
        let _ = writeln!(s, "  {:>3}  {line}", k + 1);
    }
    push_time_line(&mut s, stats);
    s
}

/// The readable common-tangent report.
pub(crate) fn tangents_text(curves: &[&Curve], r: &Tangents, stats: Option<&Stats>) -> String {
    let lines = r.lines.iter().map(|l| chord(l.s, l.t, l.p, l.q));
    tangent_lines(curves, r, Why::Unstated, lines, stats)
}

/// The readable common-tangent report of profiles: each line with its corners and segments.
pub(crate) fn profile_tangents_text(
    curves: &[&Curve],
    r: &Tangents,
    stats: Option<&Stats>,
) -> String {
    let lines = r
        .lines
        .iter()
        .map(|l| chord(l.s, l.t, l.p, l.q) + &sites(l.corner, l.segment));
    tangent_lines(curves, r, Why::Stated, lines, stats)
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
    r: &Bisector,
    stats: Option<&Stats>,
) -> String {
    let site = |k: usize, b: &Branch| site(b.corners()[k], b.segments()[k]);
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
    curves_lines(&mut s, curves);
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
    push_time_line(&mut s, stats);
    s
}
