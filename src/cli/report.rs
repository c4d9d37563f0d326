//! Text and JSON reports, and drawing a curve into a figure.

mod figures;
mod texts;

pub(crate) use figures::{antipodal_figure, bisector_figure, profile_bisector_figure};
pub(crate) use texts::{
    antipodal_text, bisector_text, inflections_text, profile_antipodal_text, profile_bisector_text,
    profile_inflections_text, profile_tangents_text, tangents_text,
};

use super::timing::Stats;
use curvekit::io::{Curve, CurveKind};
use curvekit::svg::Figure;
use geometry::Flatten;
use std::fmt::Write as _;

/// How far a region's drawn boundary strays from it, as a share of its size (a tenth of a
/// pixel at the figures' 640 pixels).
const REGION_FLATNESS: f64 = 1e-4;

/// The curve as a dense polyline in a figure.
pub(crate) fn draw_curve(fig: &mut Figure, curve: &Curve) {
    let n = match &curve.shape {
        CurveKind::Spline(s) => (24 * s.n_points).clamp(600, 20_000),
        CurveKind::Analytic(_) | CurveKind::Segment(_) => 1200,
        CurveKind::Profile(p) => (200 * p.segments().len()).clamp(600, 20_000),
        CurveKind::Region(_) | CurveKind::Regions(_) => {
            // (Within 1e-4 of the size, in the neutral colour: a region is the ground its
            // results are drawn on.)
            let parts = curve.parts();
            for b in parts
                .iter()
                .flat_map(|r| std::iter::once(r.outer()).chain(r.holes()))
            {
                fig.boundary(b.flattened(REGION_FLATNESS * b.scale()), true);
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
        CurveKind::Spline(s) => {
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
        CurveKind::Analytic(_) | CurveKind::Segment(_) => curve.kind().to_string(),
        CurveKind::Profile(p) => format!(
            "profile, {} segments, {} corners",
            p.segments().len(),
            p.corners().count()
        ),
        CurveKind::Region(r) => format!("region, {} holes", r.holes().len()),
        CurveKind::Regions(parts) => format!(
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

/// The closing lines of a region command's text report: whether it is certified (and why
/// not), whether it is complete, and the time line where it was timed.
pub(crate) fn verdict_lines(
    s: &mut String,
    found: &impl numeric::certificate::Verdict,
    complete: bool,
    stats: Option<&Stats>,
) {
    let _ = writeln!(s, "certified:   {}", found.certified());
    if let Some(why) = &found.reason() {
        let _ = writeln!(s, "  (why: {why})");
    }
    let _ = writeln!(s, "complete:    {complete}");
    if let Some(st) = stats {
        let _ = writeln!(s, "{}", time_line(st));
    }
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

/// Magnitudes that text reports print in plain decimals; outside, in scientific form (not a
/// tolerance: plain form would run to many zeros before or after the digits that matter).
const PLAIN: std::ops::Range<f64> = 1e-4..1e7;

/// A number for text reports: shortest round-trip form, scientific when tiny or huge.
pub(super) fn n(x: f64) -> String {
    if x != 0.0 && !PLAIN.contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
