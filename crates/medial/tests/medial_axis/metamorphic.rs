//! Metamorphic: a certified axis moved, scaled or rotated is the moved axis.

use crate::helpers::{circle, closed_cubic, pocket_outline};
use crate::oracle::size_of;
use crate::traced::axis;
use curve::Region;
use numeric::certificate::Verdict;

/// Metamorphic: an axis certified after the region is moved far from the origin, scaled by
/// 2^±20 or 1e±6, or rotated, is the moved axis (every node, of its kind, within 1e-9 of the
/// size of a moved node of the axis at unit size), on a pocket of lines and arcs with a hole
/// and on the periodic cubic; at least the unit size, the scalings and the rotation
/// are certified.
#[test]
fn a_certified_axis_moved_scaled_or_rotated_is_the_same_axis() {
    let pocket = Region::new(pocket_outline(), vec![circle([6.5, 3.0], 1.2)]).unwrap();
    let pts = testkit::outlines::PERIODIC_CUBIC_POINTS;
    let cubic = Region::new(closed_cubic(&pts, None).unwrap(), vec![]).unwrap();
    let (c, s) = (0.6f64, 0.8f64); // a rotation with exact sine and cosine
    let maps: [(curve::Affine, bool); 7] = [
        (curve::Affine([1.0, 0.0, 0.0, 1.0, 1e3, -2e3]), false),
        (curve::Affine([1.0, 0.0, 0.0, 1.0, 1e6, 1e6]), false),
        (
            curve::Affine([2f64.powi(-20), 0.0, 0.0, 2f64.powi(-20), 0.0, 0.0]),
            true,
        ),
        (
            curve::Affine([2f64.powi(20), 0.0, 0.0, 2f64.powi(20), 0.0, 0.0]),
            true,
        ),
        (curve::Affine([1e-6, 0.0, 0.0, 1e-6, 3e-6, 0.0]), true),
        (curve::Affine([1e6, 0.0, 0.0, 1e6, 0.0, -7e6]), true),
        (curve::Affine([c, s, -s, c, 0.25, 0.5]), true),
    ];
    for region in [&pocket, &cubic] {
        let base = axis(region);
        assert!(base.certified(), "{:?}", base.reason());
        let size = size_of(region);
        for (map, must_certify) in &maps {
            let moved = axis(&region.transformed(map).unwrap());
            assert!(
                moved.certified() || !must_certify,
                "{map:?}: {:?}",
                moved.reason()
            );
            if !moved.certified() {
                continue;
            }
            let scale = map.determinant().abs().sqrt();
            assert_eq!(moved.nodes.len(), base.nodes.len(), "{map:?}");
            for n in &moved.nodes {
                let near = base.nodes.iter().any(|b| {
                    let p = map.apply(b.xy);
                    b.kind == n.kind
                        && (p[0] - n.xy[0]).hypot(p[1] - n.xy[1]) <= 1e-9 * size * scale
                        && (b.radius * scale - n.radius).abs() <= 1e-9 * size * scale
                });
                assert!(near, "{map:?}: node {n:?} is no moved node");
            }
        }
    }
}
