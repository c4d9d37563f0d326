//! The independent oracle the axes of drawn and adversarial shapes are judged by: dense
//! boundary distances and the sampled Voronoi diagram (see `medial_axis.rs`).

use crate::graph::components_and_cycles as shape;
use crate::sampled_voronoi::sampled_medial_points;
use crate::traced::{off_axis, CHORD};
use curve::{Profile, Region};
use medial::MedialAxis;
use testkit::boundary_oracle::{winding, Oracle};

/// The oracle's verdict on the axis of `region`: `Err` with what is wrong.
pub(crate) fn judge(region: &Region, a: &MedialAxis) -> Result<(), String> {
    let profiles: Vec<&Profile> = std::iter::once(region.outer())
        .chain(region.holes())
        .collect();
    let oracles: Vec<Oracle<'_>> = profiles.iter().map(|p| Oracle::new(p)).collect();
    let size = region.size();
    let distance = |x: [f64; 2]| {
        oracles
            .iter()
            .map(|o| o.nearest(x).0)
            .fold(f64::INFINITY, f64::min)
    };
    let inside = |x: [f64; 2]| {
        let w = |o: &Oracle<'_>| winding(&o.pts, x) != 0;
        w(&oracles[0]) && !oracles[1..].iter().any(w)
    };
    for e in &a.edges {
        for (k, (&x, &r)) in e.xy.iter().zip(&e.radius).enumerate() {
            let d = distance(x);
            if (d - r).abs() > 1e-9 * size {
                return Err(format!("vertex {k} {x:?}: radius {r}, distance {d}"));
            }
            if r > 1e-9 * size && !inside(x) {
                return Err(format!("vertex {x:?} outside"));
            }
        }
    }
    for n in &a.nodes {
        let d = distance(n.xy);
        if (d - n.radius).abs() > 1e-9 * size {
            return Err(format!("node {n:?}: distance {d}"));
        }
    }
    let (components, cycles) = shape(a);
    if (components, cycles) != (1, region.holes().len()) {
        return Err(format!(
            "{components} components and {cycles} cycles for {} holes",
            region.holes().len()
        ));
    }
    let sampled = sampled_medial_points(&profiles, size, distance, inside);
    for z in &sampled.points {
        let off = off_axis(a, z.xy);
        if off > CHORD * size + 1e-6 * size {
            return Err(format!(
                "medial point {:?} (radius {}) is {off} off the axis",
                z.xy, z.radius
            ));
        }
    }
    Ok(())
}
