//! The text reports of the curve commands (`inflections`, `antipodal`, `tangents`,
//! `bisector`), on curves and on profiles.

use super::{describe, n, time_line};
use crate::cli::timing::Stats;
use antipodal::{
    Antipodal, CornerKind, Inflection, InflectionKind, Inflections, ProfileAntipodal,
    ProfileInflections, ProfileTangents, Tangents,
};
use curvekit::io::Curve;
use numeric::certificate::Verdict;
use std::fmt::Write as _;
use zeroset::{Bisector, ProfileBisector, ProfileBranch};

/// The readable inflection report.
pub(crate) fn inflections_text(curve: &Curve, r: &Inflections, stats: Option<&Stats>) -> String {
    let mut s = inflection_lines(curve, &r.inflections, r.certified());
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
    let mut s = inflection_lines(curve, &r.inflections, r.certified());
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
        certified_word(r.certified())
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
        certified_word(r.certified())
    );
    if let Some(why) = r.reason().as_ref().filter(|_| !r.certified()) {
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
        doubts: r.doubts.clone(),
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
        certified_word(r.certified())
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
        certified_word(r.certified())
    );
    if let Some(why) = r.reason().as_ref().filter(|_| !r.certified()) {
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
