//! Polylines: LWPOLYLINEs with bulges made arcs, repeated vertices skipped, open ones kept
//! open, and old-style POLYLINEs of VERTEX entities (the dxf crate's and hand-written).

use super::{add, corners, distance_to, drawing, near, p3, read, read_text};
use curve::{ParamCurve, Profile, SegmentKind, V2};
use dxf::entities::{EntityType, LwPolyline, Polyline, Vertex};
use dxf::LwPolylineVertex;

/// An LWPOLYLINE of `vertices` with `flags` (1: closed).
fn lwpolyline(flags: i32, vertices: Vec<LwPolylineVertex>) -> EntityType {
    EntityType::LwPolyline(LwPolyline {
        flags,
        vertices,
        ..Default::default()
    })
}

/// The profile a drawing of `entity` alone is read as.
fn read_one(entity: EntityType) -> Profile {
    let mut d = drawing();
    add(&mut d, entity);
    read(&d)
}

pub(crate) fn lw(x: f64, y: f64, bulge: f64) -> LwPolylineVertex {
    LwPolylineVertex {
        x,
        y,
        bulge,
        ..Default::default()
    }
}

/// The centre and radius of the arc of bulge `b` from `p` to `q`, by the sagitta.
pub(crate) fn bulge_circle(p: V2, q: V2, b: f64) -> (V2, f64, V2) {
    let c = (q - p).norm();
    let s = b.abs() * c / 2.0; // sagitta
    let r = (c * c / 4.0 + s * s) / (2.0 * s);
    let m = (p + q) * 0.5;
    // The arc's middle is on the chord's right for b > 0 (counterclockwise).
    let right = V2::new((q - p).y, -(q - p).x) * (1.0 / c);
    let middle = m + right * (b * c / 2.0);
    let center = middle - right * (r * b.signum());
    (center, r, middle)
}

#[test]
fn bulges_make_arcs_through_their_middle() {
    let pts = [
        (0.0, 0.0, 0.5),
        (4.0, 0.0, 0.0),
        (4.0, 3.0, -0.25),
        (0.0, 3.0, 0.0),
    ];
    let p = read_one(lwpolyline(
        1,
        pts.iter().map(|&(x, y, b)| lw(x, y, b)).collect(),
    ));
    assert!(p.is_closed());
    assert_eq!(p.segments().len(), 4);
    for (i, &(x, y, b)) in pts.iter().enumerate() {
        let seg = &p.segments()[i];
        let (from, to) = (
            V2::new(x, y),
            V2::new(pts[(i + 1) % 4].0, pts[(i + 1) % 4].1),
        );
        assert!(near(seg.start(), from, 1e-14) && near(seg.end(), to, 1e-14));
        if b == 0.0 {
            assert_eq!(seg.kind(), SegmentKind::Line);
            continue;
        }
        assert_eq!(seg.kind(), SegmentKind::Arc);
        let (center, r, middle) = bulge_circle(from, to, b);
        for k in 0..=32 {
            let q = seg.jet(k as f64 / 32.0).p;
            testkit::assert_near!((q - center).norm(), r, 1e-14, "{q:?}");
        }
        assert!(distance_to(seg, middle) < 1e-13, "vertex {i}");
    }
    // Bulge 0.5 below the bottom side (counterclockwise from (0,0) to (4,0)): its middle is at
    // (2, −1).
    assert!(distance_to(&p.segments()[0], V2::new(2.0, -1.0)) < 1e-14);
}

#[test]
fn repeated_vertices_are_skipped_and_an_open_polyline_stays_open() {
    let open = vec![
        lw(0.0, 0.0, 0.0),
        lw(1.0, 0.0, 0.0),
        lw(1.0, 0.0, 0.0),
        lw(1.0, 1.0, 0.3),
        lw(2.0, 2.0, 0.0),
    ];
    // A closed polyline (flag 1) whose last vertex repeats the first: no zero-length closing
    // piece.
    let closed = vec![
        lw(0.0, 0.0, 0.0),
        lw(1.0, 0.0, 0.0),
        lw(0.0, 1.0, 0.0),
        lw(0.0, 0.0, 0.0),
    ];
    for (flag, vertices) in [(0, open), (1, closed)] {
        let p = read_one(lwpolyline(flag, vertices));
        assert_eq!(p.is_closed(), flag == 1);
        assert_eq!(p.segments().len(), 3);
    }
}

#[test]
fn an_old_style_polyline_with_vertex_entities() {
    let mut d = drawing();
    let mut poly = Polyline {
        flags: 1,
        ..Default::default()
    };
    for (x, y, b) in [
        (0.0, 0.0, 0.0),
        (2.0, 0.0, 1.0),
        (2.0, 2.0, 0.0),
        (0.0, 2.0, 0.0),
    ] {
        poly.add_vertex(
            &mut d,
            Vertex {
                bulge: b,
                ..Vertex::new(p3(x, y))
            },
        );
    }
    add(&mut d, EntityType::Polyline(poly));
    let p = read(&d);
    assert!(p.is_closed());
    assert_eq!(p.segments().len(), 4);
    assert_eq!(p.segments()[1].kind(), SegmentKind::Arc);
    // The half circle from (2, 0) to (2, 2), counterclockwise: it bulges out to (3, 1).
    assert!(distance_to(&p.segments()[1], V2::new(3.0, 1.0)) < 1e-14);
}

#[test]
fn a_hand_written_polyline_with_vertex_entities_and_no_handles() {
    let mut text = String::from("0\nSECTION\n2\nENTITIES\n0\nPOLYLINE\n8\n0\n66\n1\n70\n1\n");
    for (x, y) in [(0, 0), (3, 0), (3, 1), (0, 1)] {
        text += &format!("0\nVERTEX\n8\n0\n10\n{x}\n20\n{y}\n");
    }
    text += "0\nSEQEND\n0\nENDSEC\n0\nEOF\n";
    let p = read_text(&text).unwrap();
    assert!(p.is_closed());
    assert_eq!(p.segments().len(), 4);
    assert_eq!(corners(&p).len(), 4);
}
