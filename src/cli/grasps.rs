//! `curvekit grasps`: the two-finger force-closure grasps of a closed curve for a friction
//! coefficient, as text, JSON or a figure (the curve with each region's contact stretches,
//! beside it the regions in the square of contact parameters).

use super::report::{describe, draw_curve, n, verdict_lines};
use super::{Common, Failure};
use curvekit::commands::{self, CommandFamily, Stats};
use curvekit::grasp::{GraspOptions, GraspRegion, Grasps};
use curvekit::io::Curve;
use curvekit::svg::{side_by_side, Figure, Mark};
use std::fmt::Write as _;
use std::path::Path;

/// The colours of the regions, in turn (set apart from the curve's dark blue and from each
/// other; more regions than colours reuse them, and their numbers tell them apart).
const REGION_COLORS: [&str; 8] = [
    "#e6550d", "#31a354", "#d62728", "#756bb1", "#e7298a", "#17becf", "#bcbd22", "#8c564b",
];

/// Points drawn per contact stretch, whatever its length (dense enough to follow the curve
/// at the figures' 640 pixels).
const STRETCH_POINTS: usize = 96;

/// Where along a best grasp's chord its region's number is written, from its first contact.
const LABEL_ALONG: f64 = 0.1;

/// The grasp options of the command line: `--friction`, the widths and the tolerances.
pub(super) struct GraspArgs {
    /// The friction coefficient μ.
    pub(super) friction: f64,
    /// The gripper's least opening, if limited.
    pub(super) min_width: Option<f64>,
    /// The gripper's greatest opening, if limited.
    pub(super) max_width: Option<f64>,
    /// The chord tolerance of the regions' boundaries, relative to the parameter domain.
    pub(super) chord_tol: f64,
}

impl GraspArgs {
    /// The library's options, checked (before any file is read: a usage error comes first).
    fn options(&self, tol: f64) -> Result<GraspOptions, Failure> {
        let opts = GraspOptions {
            min_width: self.min_width,
            max_width: self.max_width,
            settings: commands::settings(CommandFamily::Bisector, tol, self.chord_tol)?,
            ..GraspOptions::friction(self.friction)
        };
        commands::validate_grasp_options(&opts)?;
        Ok(opts)
    }
}

/// Runs `grasps` on the curve at `path`.
pub(super) fn run(path: &Path, args: &GraspArgs, common: &Common) -> Result<(), Failure> {
    let opts = args.options(common.tol)?;
    let curve = common.read_curve(path)?;
    let (found, stats) = common.computed(|| commands::grasps(&curve, &opts))?;
    common.draw(|| Ok(figure(&curve, &found, title(&curve.file, &found))))?;
    common.report(&found, &[&curve], stats.as_ref(), || {
        text(&curve, &found, stats.as_ref())
    })
}

/// A grasp figure's title: the input, the friction and the regions found.
pub(super) fn title(file: &str, found: &Grasps) -> String {
    let regions = match found.regions.len() {
        1 => "1 region".to_string(),
        k => format!("{k} regions"),
    };
    let incomplete = if found.complete {
        ""
    } else {
        " (incomplete: a search limit was hit)"
    };
    format!(
        "{file} — grasps at μ = {}: {regions}{incomplete}",
        n(found.friction)
    )
}

/// The colour of region `k`.
fn color(k: usize) -> &'static str {
    REGION_COLORS[k % REGION_COLORS.len()]
}

/// `u` brought into the curve's domain `[a, b)`: contact stretches may run across the seam.
fn in_domain(u: f64, (a, b): (f64, f64)) -> f64 {
    a + (u - a).rem_euclid(b - a)
}

/// The points of the curve over the parameters `[u0, u1]` (read modulo the period).
fn stretch_points(curve: &Curve, [u0, u1]: [f64; 2]) -> Vec<[f64; 2]> {
    let domain = curve.domain();
    (0..=STRETCH_POINTS)
        .map(|i| {
            let u = u0 + (u1 - u0) * i as f64 / STRETCH_POINTS as f64;
            curve.point_at(in_domain(u, domain))
        })
        .collect()
}

/// A region's boundary loops in the parameter square: its parts, or its one boundary.
fn loops(region: &GraspRegion) -> &[Vec<[f64; 2]>] {
    if region.parts.is_empty() {
        std::slice::from_ref(&region.boundary)
    } else {
        &region.parts
    }
}

/// The figure: the curve, each region's two contact stretches thick in the region's colour
/// and its best grasp's contacts marked and joined; beside it the triangle `s < t` of the
/// parameter square with each region filled in its colour. Regions are numbered as in the
/// text report.
pub(super) fn figure(curve: &Curve, found: &Grasps, title: String) -> String {
    let mut plane = Figure::new();
    draw_curve(&mut plane, curve);
    for (k, r) in found.regions.iter().enumerate() {
        if let Some(c) = &r.contact {
            plane.stretch(stretch_points(curve, c.s), color(k));
            plane.stretch(stretch_points(curve, c.t), color(k));
        }
        plane.thin(vec![r.best.p, r.best.q], color(k));
        plane.dots(&[r.best.p, r.best.q], color(k));
        // (Near the first contact: the chords of several regions often share their middle.)
        let near_p = [
            r.best.p[0] + LABEL_ALONG * (r.best.q[0] - r.best.p[0]),
            r.best.p[1] + LABEL_ALONG * (r.best.q[1] - r.best.p[1]),
        ];
        plane.text(near_p, (k + 1).to_string());
    }
    if !found.regions.is_empty() {
        let c = color(0);
        if found.regions.iter().any(|r| r.contact.is_some()) {
            plane.legend(
                Mark::Line(c.into(), 5.0),
                "contact stretches: any point of one with any of the other grasps (a colour \
                 per region)",
            );
        }
        plane.legend(
            Mark::Dot(c.into()),
            "most robust grasp of a region, its contacts joined and numbered",
        );
        plane.legend(Mark::Line(c.into(), 8.0), "region in the (s, t) square");
    }
    plane.title(title);
    plane.status(found.doubts.is_empty(), found.doubts.reason().as_deref());

    // The parameter square, scaled to a unit square; the regions live above its diagonal.
    let (a, b) = curve.domain();
    let unit = |p: &[f64; 2]| [(p[0] - a) / (b - a), (p[1] - a) / (b - a)];
    let mut params = Figure::new();
    params.thin(
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]],
        "#bbbbbb",
    );
    params.thin(
        vec![[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]],
        "#444444",
    );
    for (k, r) in found.regions.iter().enumerate() {
        for part in loops(r) {
            params.area(part.iter().map(unit).collect(), color(k));
        }
        for hole in &r.holes {
            let mut ring: Vec<[f64; 2]> = hole.iter().map(unit).collect();
            ring.extend(ring.first().copied());
            params.thin(ring, color(k));
        }
        params.text(unit(&[r.best.s, r.best.t]), (k + 1).to_string());
    }
    params.text([0.45, -0.08], format!("s ∈ [{}, {}]", n(a), n(b)));
    params.text([-0.05, 1.03], format!("t ∈ [{}, {}]", n(a), n(b)));
    params.frame([-0.08, -0.1], [1.02, 1.06]);
    params.title("grasp regions in (s, t), s < t");
    side_by_side(&[&plane, &params])
}

/// The readable report: the curve and the friction, then per region its best grasp, its
/// contact stretches and whether it is certified; then the verdict.
pub(super) fn text(curve: &Curve, found: &Grasps, stats: Option<&Stats>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "curve:       {} ({})", curve.file, describe(curve));
    let _ = writeln!(
        s,
        "friction:    μ = {} (cone half-angle {}°)",
        n(found.friction),
        n(found.friction.atan().to_degrees())
    );
    match (found.min_width, found.max_width) {
        (None, None) => {}
        (lo, hi) => {
            let bound = |w: Option<f64>, none: &str| w.map_or(none.to_string(), n);
            let _ = writeln!(
                s,
                "widths:      from {} to {}",
                bound(lo, "0"),
                bound(hi, "any")
            );
        }
    }
    let _ = writeln!(s, "regions:     {}", found.regions.len());
    for (k, r) in found.regions.iter().enumerate() {
        let b = &r.best;
        let _ = writeln!(
            s,
            "  {:>3}  best s = {}, t = {}: p = ({}, {}), q = ({}, {}), min friction {}",
            k + 1,
            n(b.s),
            n(b.t),
            n(b.p[0]),
            n(b.p[1]),
            n(b.q[0]),
            n(b.q[1]),
            n(b.min_friction)
        );
        for [u0, u1] in &b.toward {
            let _ = writeln!(
                s,
                "       less friction only with a finger in [{}, {}] (toward a corner)",
                n(*u0),
                n(*u1)
            );
        }
        match &r.contact {
            Some(c) => {
                let _ = writeln!(
                    s,
                    "       contact s ∈ [{}, {}] × t ∈ [{}, {}]",
                    n(c.s[0]),
                    n(c.s[1]),
                    n(c.t[0]),
                    n(c.t[1])
                );
            }
            None => {
                let _ = writeln!(s, "       contact: none proven");
            }
        }
        let parts = if r.parts.is_empty() {
            String::new()
        } else {
            format!(", {} parts across the seam", r.parts.len())
        };
        let holes = if r.holes.is_empty() {
            String::new()
        } else {
            format!(", {} holes", r.holes.len())
        };
        let _ = writeln!(
            s,
            "       {}{parts}{holes}",
            if r.certified {
                "certified"
            } else {
                "not certified"
            }
        );
    }
    verdict_lines(&mut s, &found.doubts, found.complete, stats);
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stretch across the seam is read modulo the period.
    #[test]
    fn parameters_beyond_the_domain_come_back_into_it() {
        let tau = std::f64::consts::TAU;
        for (u, want) in [(tau + 0.5, 0.5), (-0.5, tau - 0.5), (1.0, 1.0), (tau, 0.0)] {
            let got = in_domain(u, (0.0, tau));
            assert!((got - want).abs() < 1e-12, "{u}: {got} vs {want}");
        }
    }
}
