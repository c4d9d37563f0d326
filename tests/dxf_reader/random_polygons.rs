//! Property: random polygons with random bulges, written by the dxf crate, read back.

use super::polylines::{bulge_circle, lw};
use super::{add, distance_to, drawing, near, p3, read_path, saved};
use curve::{ParamCurve, SegmentKind, V2};
use dxf::entities::{EntityType, LwPolyline, Polyline, Vertex};
use dxf::Vector;
use proptest::prelude::*;
use std::f64::consts::TAU;

/// `x` rounded to 12 decimals: the number the `dxf` crate's writer writes for it, exactly.
fn decimal(x: f64) -> f64 {
    (x * 1e12).round() / 1e12
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_bulged_polygons_read_back(
        n in 4usize..12,
        jitter in proptest::collection::vec(-0.25f64..0.25, 12),
        radii in proptest::collection::vec(0.7f64..1.0, 12),
        bulges in proptest::collection::vec(prop_oneof![Just(0.0), -0.3f64..0.3], 12),
        scale in prop_oneof![Just(1.0), 1e-3f64..1e3],
        offset in prop_oneof![Just((0.0, 0.0)), (-1e3f64..1e3, -1e3f64..1e3)],
        clockwise in any::<bool>(),
        mirrored in any::<bool>(),
        lightweight in any::<bool>(),
    ) {
        // A star-shaped polygon about the origin (angles jittered by a quarter step at most).
        let step = TAU / n as f64;
        let mut v: Vec<(V2, f64)> = (0..n)
            .map(|i| {
                let a = step * (i as f64 + jitter[i]);
                let p = V2::polar(a) * (radii[i] * scale) + V2::new(offset.0, offset.1);
                // (Numbers the crate's writer keeps: it writes 12 decimals.)
                (V2::new(decimal(p.x), decimal(p.y)), decimal(bulges[i]))
            })
            .collect();
        if clockwise {
            // Reverse the order; each side's bulge moves with it, sign flipped.
            let rev: Vec<(V2, f64)> = (0..n)
                .map(|i| (v[n - 1 - i].0, -v[(2 * n - 2 - i) % n].1))
                .collect();
            v = rev;
        }
        let mut d = drawing();
        let extrusion = Vector::new(0.0, 0.0, if mirrored { -1.0 } else { 1.0 });
        if lightweight {
            add(&mut d, EntityType::LwPolyline(LwPolyline {
                flags: 1,
                extrusion_direction: extrusion,
                vertices: v.iter().map(|&(p, b)| lw(p.x, p.y, b)).collect(),
                ..Default::default()
            }));
        } else {
            let mut poly = Polyline { flags: 1, normal: extrusion, ..Default::default() };
            for &(p, b) in &v {
                poly.add_vertex(&mut d, Vertex { bulge: b, ..Vertex::new(p3(p.x, p.y)) });
            }
            add(&mut d, EntityType::Polyline(poly));
        }
        let prof = match read_path(&saved(&d), 0) {
            Ok(p) => p,
            // (Bulges bent towards a sharp vertex may make neighbouring arcs cross: the
            // drawing is not a profile, whatever the reader.)
            Err(e) if e.to_string().contains("crosses itself") => {
                prop_assume!(false);
                unreachable!()
            }
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        prop_assert!(prof.is_closed());
        prop_assert_eq!(prof.segments().len(), n);
        let size = scale + offset.0.abs().max(offset.1.abs());
        let world = |p: V2| if mirrored { V2::new(-p.x, p.y) } else { p };
        for (i, &(p, b)) in v.iter().enumerate() {
            let seg = &prof.segments()[i];
            let q = v[(i + 1) % n].0;
            prop_assert!(near(seg.start(), world(p), 1e-12 * size), "vertex {}", i);
            prop_assert!(near(seg.end(), world(q), 1e-12 * size), "vertex {}", i + 1);
            if b.abs() <= 1e-9 {
                // (A bulge this small is a straight piece to the reader.)
                prop_assert_eq!(seg.kind(), SegmentKind::Line);
                continue;
            }
            let (center, r, middle) = bulge_circle(p, q, b);
            let (center, middle) = (world(center), world(middle));
            for k in 0..=16 {
                let x = seg.jet(k as f64 / 16.0).p;
                testkit::prop_assert_near!((x - center).norm(), r, 1e-11 * size);
            }
            prop_assert!(distance_to(seg, middle) <= 1e-11 * size, "bulge {} of {}", i, b);
        }
    }
}
