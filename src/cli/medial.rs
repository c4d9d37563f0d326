//! `curvekit medial`: the medial axis of a region, as text, JSON or a figure.

use super::report::{describe, draw_curve, verdict_lines};
use super::{Common, Failure, OutFiles};
use curvekit::commands;
use curvekit::export::{dxf_file, svg_paths};
use curvekit::io::Curve;
use curvekit::medial::{MedialAxis, NodeKind};
use curvekit::svg::{scale_color, Figure, Mark, BOUNDARY};
use numeric::certificate::Verdict;
use std::fmt::Write as _;
use std::path::Path;

/// Maximal disks drawn in the figure: the largest few, enough to show what the radius means.
const DISKS_DRAWN: usize = 6;

/// `flags`: `--fit`, `--exterior`.
pub(super) fn run(
    path: &Path,
    chord_tol: f64,
    (fit, exterior): (bool, bool),
    out: &OutFiles,
    common: &Common,
) -> Result<(), Failure> {
    let opts = common.axis_options(chord_tol, (fit, exterior))?;
    let curve = common.read_region(path)?;
    let (axis, stats) = common.computed(|| commands::medial(&curve, &opts))?;
    common.draw(|| Ok(axis_figure(&curve, &axis)))?;
    out.write(
        &axis,
        curve.units(),
        dxf_file::medial_dxf,
        svg_paths::medial_svg,
    )?;
    common.report(&axis, &[&curve], stats.as_ref(), || {
        let mut s = String::new();
        let count = |k: NodeKind| axis.nodes.iter().filter(|n| n.kind == k).count();
        let _ = writeln!(s, "region:      {} ({})", curve.file, describe(&curve));
        let _ = writeln!(
            s,
            "nodes:       {} ({} junctions, {} ends, {} corners, {} joints{})",
            axis.nodes.len(),
            count(NodeKind::Junction),
            count(NodeKind::End),
            count(NodeKind::Corner),
            count(NodeKind::Joint),
            if exterior {
                format!(", {} at the clip box", count(NodeKind::Clip))
            } else {
                String::new()
            }
        );
        let vertices: usize = axis.edges.iter().map(|e| e.xy.len()).sum();
        let _ = writeln!(s, "edges:       {} ({vertices} vertices)", axis.edges.len());
        if fit {
            let splines = axis.edges.iter().filter_map(|e| e.bspline.as_ref());
            let (points, error) = splines.fold((0, 0.0f64), |(n, m), b| {
                (n + b.points.len(), m.max(b.error))
            });
            let _ = writeln!(
                s,
                "fitted:      {points} control points, at most {error:.3e} from the polylines"
            );
        }
        verdict_lines(&mut s, &axis, axis.complete, stats.as_ref());
        s
    })
}

/// The figure of a region's medial axis: the region, the axis coloured by radius (with its
/// colour bar), the nodes by kind, the widest maximal disks; the header names the file and says
/// whether the axis is certified.
pub(super) fn axis_figure(region: &Curve, axis: &MedialAxis) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, region);
    draw_axis(&mut fig, axis);
    let widest = widest_radius(axis);
    fig.title(format!(
        "{} — medial axis: {} nodes, {} edges",
        region.file,
        axis.nodes.len(),
        axis.edges.len()
    ));
    fig.status(axis.certified(), axis.reason().as_deref());
    fig.color_bar("radius", 0.0, widest, region.units());
    fig.render()
}

/// How each kind of node is marked, and its name in the legend.
const NODE_MARKS: [(NodeKind, &str, &str); 5] = [
    (
        NodeKind::Junction,
        "#d62020",
        "junction (three or more edges)",
    ),
    (NodeKind::End, "#2a8c4a", "end (a centre of curvature)"),
    (NodeKind::Corner, "#1f5fbf", "corner (a convex corner)"),
    (NodeKind::Joint, "#8c2a7a", "joint (a cycle's one node)"),
    (NodeKind::Clip, "#777777", "clip (the exterior axis's box)"),
];

/// Shades of the radius scale: the axis is drawn in runs of one shade.
const SHADES: usize = 16;

/// The largest radius on the axis.
fn widest_radius(axis: &MedialAxis) -> f64 {
    axis.edges
        .iter()
        .flat_map(|e| e.radius.iter().copied())
        .chain(axis.nodes.iter().map(|n| n.radius))
        .fold(0.0, f64::max)
}

/// The axis's edges coloured by radius, and the maximal disks of its widest nodes.
fn draw_axis(fig: &mut Figure, axis: &MedialAxis) {
    let widest = widest_radius(axis);
    let bucket = |r: f64| {
        if widest > 0.0 {
            ((r / widest * SHADES as f64) as usize).min(SHADES - 1)
        } else {
            0
        }
    };
    for e in &axis.edges {
        // Runs of vertices whose steps share a shade (a step takes its middle radius).
        let mut run: Vec<[f64; 2]> = Vec::new();
        let mut current = None;
        for (w, r) in e.xy.windows(2).zip(e.radius.windows(2)) {
            let b = bucket(0.5 * (r[0] + r[1]));
            if current != Some(b) {
                if let Some(prev) = current {
                    fig.colored(
                        std::mem::take(&mut run),
                        scale_color((prev as f64 + 0.5) / SHADES as f64),
                    );
                }
                run.push(w[0]);
                current = Some(b);
            }
            run.push(w[1]);
        }
        if let Some(prev) = current {
            fig.colored(run, scale_color((prev as f64 + 0.5) / SHADES as f64));
        }
    }
    if !axis.edges.is_empty() {
        fig.legend(
            Mark::Line(scale_color(0.6), 1.4),
            "medial axis, coloured by radius",
        );
    }
    fig.legend(Mark::Line(BOUNDARY.into(), 1.6), "boundary");
    // (Nodes of radius 0, convex corners, have no disk to draw.)
    let mut widest: Vec<_> = axis.nodes.iter().filter(|n| n.radius > 0.0).collect();
    widest.sort_by(|a, b| b.radius.total_cmp(&a.radius));
    if !widest.is_empty() {
        fig.legend(
            Mark::Ring("#999999".into()),
            match widest.len().min(DISKS_DRAWN) {
                1 => "the widest maximal disk".to_string(),
                k => format!("the {k} widest maximal disks"),
            },
        );
    }
    for n in widest.iter().take(DISKS_DRAWN) {
        let circle = (0..=64)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / 64.0;
                [n.xy[0] + n.radius * a.cos(), n.xy[1] + n.radius * a.sin()]
            })
            .collect();
        fig.thin(circle, "#999999");
    }
    for (kind, color, name) in NODE_MARKS {
        let nodes: Vec<_> = axis.nodes.iter().filter(|n| n.kind == kind).collect();
        if nodes.is_empty() {
            continue;
        }
        fig.dots(&nodes.iter().map(|n| n.xy).collect::<Vec<_>>(), color);
        fig.legend(Mark::Dot(color.into()), format!("{name}: {}", nodes.len()));
    }
}
