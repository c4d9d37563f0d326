//! The grasp benchmarks' batch: the points of 100 random star-shaped outlines of 8–20 points
//! (deterministic seeds), read as periodic cubics through them or as polygons.

use antipodal::SplineCurve;
use testkit::stars::Star;

/// The points of the batch's 100 outlines.
pub(crate) fn outline_points() -> Vec<Vec<[f64; 2]>> {
    let mut draw = testkit::rng(42);
    (0..100)
        .map(|i| {
            let n = (8 + (draw() * 13.0) as usize).min(20);
            Star::default().drawn(n, &mut testkit::rng(1000 + i))
        })
        .collect()
}

/// The outlines as periodic cubic B-splines through their points.
pub(crate) fn cubics(outlines: &[Vec<[f64; 2]>]) -> Vec<SplineCurve> {
    outlines
        .iter()
        .map(|points| SplineCurve::periodic(3, points, None).expect("a star's points"))
        .collect()
}

/// The outlines as polygons (the straight sides' cells affine).
pub(crate) fn polygons(outlines: &[Vec<[f64; 2]>]) -> Vec<curve::Profile> {
    outlines
        .iter()
        .map(|points| testkit::outlines::polygon(points))
        .collect()
}
