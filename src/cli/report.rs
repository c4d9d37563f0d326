//! Text and JSON reports, and drawing a curve into a figure.

use super::timing::Stats;
use antipodal::{Antipodal, Tangents};
use curvekit::inflections::Inflections;
use curvekit::io::{Curve, Shape};
use curvekit::svg::Figure;
use serde::Serialize;
use serde_json::{json, Value};
use std::fmt::Write as _;
use zeroset::Bisector;

/// The curve as a dense polyline in a figure.
pub(crate) fn draw_curve(fig: &mut Figure, curve: &Curve) {
    let n = match &curve.shape {
        Shape::Spline(s) => (24 * s.n_points).clamp(600, 20_000),
        Shape::Analytic(_) => 1200,
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
        Shape::Analytic(_) => curve.kind().to_string(),
    };
    let closed = if curve.is_closed() { "closed" } else { "open" };
    format!("{shape}, {closed}, domain [{a}, {b}]")
}

/// The `curve` object of JSON reports (an extension: which curve the numbers belong to).
pub(crate) fn curve_json(curve: &Curve) -> Value {
    let (a, b) = curve.domain();
    json!({
        "file": curve.file,
        "kind": curve.kind(),
        "closed": curve.is_closed(),
        "domain": [a, b],
    })
}

/// One JSON document: the result's own fields (as the contract names them), then the
/// extensions `curve` (or `curves`) and, with `--time`, `stats`.
pub(crate) fn json_doc(
    result: &impl Serialize,
    curves: &[&Curve],
    stats: Option<&Stats>,
) -> String {
    let mut doc = serde_json::to_value(result).unwrap_or(Value::Null);
    if let Some(map) = doc.as_object_mut() {
        match curves {
            [one] => {
                map.insert("curve".into(), curve_json(one));
            }
            many => {
                let list: Vec<Value> = many.iter().map(|c| curve_json(c)).collect();
                map.insert("curves".into(), Value::Array(list));
            }
        }
        if let Some(s) = stats {
            map.insert("stats".into(), json!(s));
        }
    }
    format!("{doc}\n")
}

/// The readable inflection report.
pub(crate) fn inflections_text(curve: &Curve, r: &Inflections, stats: Option<&Stats>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "curve:       {} ({})", curve.file, describe(curve));
    let _ = writeln!(
        s,
        "inflections: {} ({})",
        r.inflections.len(),
        certified_word(r.certified)
    );
    for (i, f) in r.inflections.iter().enumerate() {
        let note = match (f.certified, f.kind) {
            (true, _) => "",
            (false, bspline::roots::RootKind::Cluster) => "  cluster, not certified",
            (false, _) => "  not certified",
        };
        let _ = writeln!(
            s,
            "  {:>3}  u = {:<22}  p = ({}, {}){note}",
            i + 1,
            n(f.u),
            n(f.p[0]),
            n(f.p[1])
        );
    }
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// The `--time` line of text reports.
pub(crate) fn time_line(st: &Stats) -> String {
    format!(
        "time:        median {:.3} µs per run over {} runs",
        st.median_us, st.runs
    )
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

/// The readable bisector report (branch ends; the full polylines are in the JSON).
pub(crate) fn bisector_text(curves: &[&Curve], r: &Bisector, stats: Option<&Stats>) -> String {
    let mut s = String::new();
    for (k, c) in curves.iter().enumerate() {
        curve_line(&mut s, &format!("curve {}:", k + 1), c);
    }
    let complete = if r.complete {
        ""
    } else {
        " (INCOMPLETE: search limit hit)"
    };
    let _ = writeln!(s, "branches:    {}{complete}", r.branches.len());
    for (k, b) in r.branches.iter().enumerate() {
        if let (Some(first), Some(last)) = (b.xy.first(), b.xy.last()) {
            let _ = writeln!(
                s,
                "  {:>3}  {} points, from ({}, {}) to ({}, {})",
                k + 1,
                b.xy.len(),
                n(first[0]),
                n(first[1]),
                n(last[0]),
                n(last[1])
            );
        }
    }
    let _ = writeln!(
        s,
        "singular:    {}\nisolated:    {}",
        r.singular.len(),
        r.isolated.len()
    );
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
    s
}

/// Bisector branches as thin polylines, with a few foot-point lines per branch.
pub(crate) fn draw_bisector(fig: &mut Figure, c1: &Curve, c2: &Curve, r: &Bisector) {
    let (Ok(p1), Ok(p2)) = (c1.plane_curve(), c2.plane_curve()) else {
        return;
    };
    for b in &r.branches {
        fig.thin(b.xy.clone(), "#d62020");
        let step = (b.xy.len() / 6).max(1);
        for (tr, xy) in b.tr.iter().zip(&b.xy).step_by(step) {
            fig.thin(
                vec![p1.jet(tr[0]).p.arr(), *xy, p2.jet(tr[1]).p.arr()],
                "#999999",
            );
        }
    }
}

/// A number for text reports: shortest round-trip form, scientific when tiny or huge.
fn n(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e7).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
