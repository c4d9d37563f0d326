//! The ASCII DXF reader end to end: drawings written by the `dxf` crate's writer (another
//! tool's output) and by hand, read through `read_curve_picked` and the command line.
//!
//! What the `dxf` crate gets wrong, and each case tested here: it drops every control point of
//! a `SPLINE` written without z groups (30), and silently drops an entity whose last group
//! value is malformed or that a blank line interrupts. Its writer leaves out `LWPOLYLINE`,
//! `SPLINE` and `ELLIPSE` entities at its default version (R12): every drawing here is
//! written as R2013. And it writes every number to 12 decimals (2π as 6.28318530718, 1e-13
//! as 0.0): drawings written with it are compared within that rounding, or made of numbers
//! it writes exactly.
#![allow(clippy::unwrap_used)]

mod blocks;
#[path = "../common/mod.rs"]
mod common;
mod corpus;
mod written;

use common::{curvekit, curvekit_json, fixture};
use curve::{ParamCurve, Profile, Segment, SegmentKind, SplineCurve, V2};
use curvekit::io::{read_curve_picked, CurveFileError, CurveKind};
use dxf::entities::{
    Arc, Circle, Ellipse, Entity, EntityType, Line, LwPolyline, Polyline, Spline, Vertex,
};
use dxf::enums::AcadVersion;
use dxf::{Drawing, LwPolylineVertex, Point, Vector};
use proptest::prelude::*;
use std::f64::consts::{FRAC_1_SQRT_2, PI, TAU};
use std::io::Write;

// ---------------------------------------------------------------------------------------------
// Helpers.

/// An empty drawing at a version that has every entity type read.
fn drawing() -> Drawing {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2013;
    d
}

/// Adds an entity; returns its handle as the reader names it (upper-case hex).
fn add(d: &mut Drawing, specific: EntityType) -> String {
    let e = d.add_entity(Entity::new(specific));
    format!("{:X}", e.common.handle.0)
}

fn p3(x: f64, y: f64) -> Point {
    Point::new(x, y, 0.0)
}

fn line(x0: f64, y0: f64, x1: f64, y1: f64) -> EntityType {
    EntityType::Line(Line::new(p3(x0, y0), p3(x1, y1)))
}

fn arc(cx: f64, cy: f64, r: f64, start: f64, end: f64) -> EntityType {
    EntityType::Arc(Arc::new(p3(cx, cy), r, start, end))
}

/// A temporary `.dxf` file holding `bytes`.
fn temp_dxf(bytes: &[u8]) -> tempfile::TempPath {
    let mut f = tempfile::Builder::new().suffix(".dxf").tempfile().unwrap();
    f.write_all(bytes).unwrap();
    f.into_temp_path()
}

fn saved(d: &Drawing) -> tempfile::TempPath {
    let mut bytes = Vec::new();
    d.save(&mut bytes).unwrap();
    temp_dxf(&bytes)
}

/// The `pick`-th profile of the file.
fn read_path(path: &std::path::Path, pick: usize) -> Result<Profile, CurveFileError> {
    let c = read_curve_picked(path, Some(pick))?;
    match c.shape {
        CurveKind::Profile(p) => Ok(*p),
        other => panic!("not a profile: {other:?}"),
    }
}

fn read(d: &Drawing) -> Profile {
    read_path(&saved(d), 0).unwrap()
}

fn read_err(d: &Drawing) -> CurveFileError {
    read_path(&saved(d), 0).unwrap_err()
}

/// The profile of a hand-written file.
fn read_text(text: &str) -> Result<Profile, CurveFileError> {
    read_path(&temp_dxf(text.as_bytes()), 0)
}

/// An ASCII DXF file whose ENTITIES section holds `entities`, each `(type, [(code, value)])`.
fn dxf_text(entities: &[(&str, Vec<(i32, String)>)]) -> String {
    let mut s = String::from("  0\nSECTION\n  2\nENTITIES\n");
    for (kind, groups) in entities {
        s += &format!("  0\n{kind}\n");
        for (code, value) in groups {
            s += &format!("{code:>3}\n{value}\n");
        }
    }
    s + "  0\nENDSEC\n  0\nEOF\n"
}

/// Groups from `(code, number)` pairs.
fn g(pairs: &[(i32, f64)]) -> Vec<(i32, String)> {
    pairs.iter().map(|&(c, v)| (c, format!("{v:?}"))).collect()
}

fn near(a: V2, b: V2, tol: f64) -> bool {
    (a - b).norm() <= tol
}

/// Points along the whole profile.
fn samples(p: &Profile, per_segment: usize) -> Vec<V2> {
    let n = p.segments().len();
    (0..=n * per_segment)
        .map(|k| p.jet(k as f64 / per_segment as f64).p)
        .collect()
}

/// The distance from `q` to the segment (sampled, then refined by golden sections).
fn distance_to(seg: &Segment, q: V2) -> f64 {
    let (a, b) = seg.domain();
    let d = |v: f64| (seg.jet(v).p - q).norm();
    let n: usize = 256;
    let k = (0..=n)
        .min_by(|&i, &j| {
            let (x, y) = (
                a + (b - a) * i as f64 / n as f64,
                a + (b - a) * j as f64 / n as f64,
            );
            d(x).total_cmp(&d(y))
        })
        .unwrap();
    let (mut lo, mut hi) = (
        a + (b - a) * k.saturating_sub(1) as f64 / n as f64,
        a + (b - a) * (k + 1).min(n) as f64 / n as f64,
    );
    let r = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (x1, x2) = (hi - r * (hi - lo), lo + r * (hi - lo));
        if d(x1) < d(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    d(0.5 * (lo + hi))
}

/// A profile's corner points.
fn corners(p: &Profile) -> Vec<V2> {
    p.corners().map(|j| p.jet(j.u).p).collect::<Vec<_>>()
}

// ---------------------------------------------------------------------------------------------
// Lines and arcs, chained.

#[test]
fn lines_drawn_either_way_and_out_of_order_chain_into_a_closed_profile() {
    let mut d = drawing();
    // A 4 × 3 rectangle, sides listed out of order and drawn both ways.
    let first = add(&mut d, line(4.0, 3.0, 4.0, 0.0));
    add(&mut d, line(0.0, 0.0, 0.0, 3.0));
    add(&mut d, line(0.0, 0.0, 4.0, 0.0));
    add(&mut d, line(0.0, 3.0, 4.0, 3.0));
    let p = read(&d);
    assert!(p.is_closed());
    assert_eq!(p.segments().len(), 4);
    // The chain starts with the first entity, as drawn.
    assert_eq!(p.segments()[0].start().arr(), [4.0, 3.0]);
    assert_eq!(p.segments()[0].end().arr(), [4.0, 0.0]);
    for w in p.segments().windows(2) {
        assert_eq!(w[0].end(), w[1].start());
    }
    let mut c: Vec<[f64; 2]> = corners(&p).iter().map(|v| v.arr()).collect();
    c.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(c, [[0.0, 0.0], [0.0, 3.0], [4.0, 0.0], [4.0, 3.0]]);
    // The profile is named after its first entity in errors: a --pick beyond it says so.
    let e = read_path(&saved(&d), 1).unwrap_err();
    assert_eq!(e.field, "--pick", "{e}");
    assert!(!first.is_empty());
}

#[test]
fn arcs_crossing_zero_degrees_run_counterclockwise_through_it() {
    // A lens: ARC from 300° to 60° about (0, 0) (through 0°), closed by a line.
    let mut d = drawing();
    let r = 2.0;
    let (s, e) = (300f64.to_radians(), 60f64.to_radians());
    add(&mut d, arc(0.0, 0.0, r, 300.0, 60.0));
    add(
        &mut d,
        line(r * e.cos(), r * e.sin(), r * s.cos(), r * s.sin()),
    );
    let p = read(&d);
    assert!(p.is_closed());
    let a = &p.segments()[0];
    assert_eq!(a.kind(), SegmentKind::Arc);
    // A 120° arc is two quarter-turn pieces: its middle is at 0°, on the x axis.
    let mid = a.jet(0.5).p;
    assert!(near(mid, V2::new(r, 0.0), 1e-14), "{mid:?}");
    for k in 0..=32 {
        let q = a.jet(k as f64 / 32.0).p;
        testkit::assert_near!(q.norm(), r, 1e-14);
        assert!(q.x > 0.99, "the arc left the 300°..60° range: {q:?}");
    }
    // 350° → 10°: a 20° arc through 0°, not a 340° one.
    let mut d = drawing();
    let (s, e) = (350f64.to_radians(), 10f64.to_radians());
    add(&mut d, line(s.cos(), s.sin(), e.cos(), e.sin()));
    add(&mut d, arc(0.0, 0.0, 1.0, 350.0, 10.0));
    let p = read(&d);
    let a = p
        .segments()
        .iter()
        .find(|s| s.kind() == SegmentKind::Arc)
        .unwrap();
    assert!(a.curve().control_points().iter().all(|q| q[0] > 0.9));
}

#[test]
fn a_circle_is_a_closed_profile_by_itself() {
    let mut d = drawing();
    add(&mut d, EntityType::Circle(Circle::new(p3(3.0, -1.0), 2.5)));
    let p = read(&d);
    assert!(p.is_closed());
    assert!(p.orientation() > 0.0);
    for q in samples(&p, 64) {
        testkit::assert_near!((q - V2::new(3.0, -1.0)).norm(), 2.5, 1e-14);
    }
    assert_eq!(p.corners().count(), 0);
}

/// The point of the ellipse at eccentric angle `t`.
fn ellipse_at(c: V2, major: V2, ratio: f64, t: f64) -> V2 {
    let minor = major.perp() * ratio;
    c + major * t.cos() + minor * t.sin()
}

#[test]
fn ellipses_full_and_partial_rotated() {
    let c = V2::new(1.0, 2.0);
    let major = V2::new(3.0, 4.0); // length 5, rotated by atan(4/3)
    let ratio = 0.4;
    let ellipse = |start: f64, end: f64| {
        EntityType::Ellipse(Ellipse {
            center: p3(c.x, c.y),
            major_axis: Vector::new(major.x, major.y, 0.0),
            minor_axis_ratio: ratio,
            start_parameter: start,
            end_parameter: end,
            ..Default::default()
        })
    };
    // A partial one from `start` to `end` closed by its chord: the profile read, and the arc's
    // ends.
    let closed_by_chord = |start: f64, end: f64| {
        let mut d = drawing();
        let (a, b) = (
            ellipse_at(c, major, ratio, start),
            ellipse_at(c, major, ratio, end),
        );
        add(&mut d, ellipse(start, end));
        add(&mut d, line(b.x, b.y, a.x, a.y));
        (read(&d), a, b)
    };
    // Its implicit equation in its own axes.
    let on = |q: V2| {
        let u = major * (1.0 / major.norm());
        let d = q - c;
        let (x, y) = (d.dot(u), d.cross(u).abs());
        (x / 5.0).powi(2) + (y / 2.0).powi(2) - 1.0
    };
    let mut d = drawing();
    add(&mut d, ellipse(0.0, TAU));
    let full = read(&d);
    assert!(full.is_closed());
    for q in samples(&full, 64) {
        assert!(on(q).abs() < 1e-14, "{q:?}");
    }
    // A partial one from 1 to 4 radians (eccentric angles), closed by its chord.
    let (p, a, b) = closed_by_chord(1.0, 4.0);
    assert!(p.is_closed());
    let e = &p.segments()[0];
    assert_eq!(e.kind(), SegmentKind::EllipticArc);
    assert!(near(e.start(), a, 1e-13) && near(e.end(), b, 1e-13));
    for k in 0..=32 {
        assert!(on(e.jet(k as f64 / 32.0).p).abs() < 1e-14);
    }
    // Counterclockwise: it passes the angle 2.5 between them, not 0.
    let mid = ellipse_at(c, major, ratio, 2.5);
    assert!(distance_to(e, mid) < 1e-12);
    // Start above end (5 → 1 radians): through 0, once round.
    let (p, _, _) = closed_by_chord(5.0, 1.0);
    assert!(distance_to(&p.segments()[0], ellipse_at(c, major, ratio, 0.0)) < 1e-12);
}

#[test]
fn mirrored_extrusion_flips_ocs_entities_in_x_and_runs_ellipses_clockwise() {
    // An ARC with extrusion (0, 0, −1): its centre (2, 0) in object coordinates is (−2, 0) in
    // the world, and its 0°..90° runs from (−3, 0) to (−2, 1) in the world, clockwise.
    let mut d = drawing();
    add(
        &mut d,
        EntityType::Arc(Arc {
            normal: Vector::new(0.0, 0.0, -1.0),
            ..Arc::new(p3(2.0, 0.0), 1.0, 0.0, 90.0)
        }),
    );
    add(&mut d, line(-2.0, 1.0, -3.0, 0.0));
    let p = read(&d);
    let a = &p.segments()[0];
    assert!(
        near(a.start(), V2::new(-3.0, 0.0), 1e-15),
        "{:?}",
        a.start()
    );
    assert!(near(a.end(), V2::new(-2.0, 1.0), 1e-15), "{:?}", a.end());
    let mid = V2::new(-2.0 - FRAC_1_SQRT_2, FRAC_1_SQRT_2);
    assert!(distance_to(a, mid) < 1e-14);
    assert!(p.orientation() < 0.0, "mirrored: clockwise");
    // An ELLIPSE with extrusion (0, 0, −1) is in world coordinates, running clockwise: from
    // the major axis' end at t = 0 to (0, −ratio·|major|) at t = π/2.
    let mut d = drawing();
    add(
        &mut d,
        EntityType::Ellipse(Ellipse {
            center: p3(0.0, 0.0),
            major_axis: Vector::new(2.0, 0.0, 0.0),
            normal: Vector::new(0.0, 0.0, -1.0),
            minor_axis_ratio: 0.5,
            start_parameter: 0.0,
            end_parameter: PI / 2.0,
        }),
    );
    add(&mut d, line(0.0, -1.0, 2.0, 0.0));
    let p = read(&d);
    let e = &p.segments()[0];
    assert!(near(e.start(), V2::new(2.0, 0.0), 1e-15));
    // (π/2 written to 12 decimals.)
    assert!(near(e.end(), V2::new(0.0, -1.0), 1e-12), "{:?}", e.end());
    // A mirrored LWPOLYLINE: vertices mirrored, its bulge arc too.
    let mut d = drawing();
    add(
        &mut d,
        EntityType::LwPolyline(LwPolyline {
            flags: 1,
            extrusion_direction: Vector::new(0.0, 0.0, -1.0),
            vertices: vec![lw(0.0, 0.0, 1.0), lw(2.0, 0.0, 0.0)],
            ..Default::default()
        }),
    );
    let p = read(&d);
    // In object coordinates the half circle bulges to (1, −1): in the world, (−1, −1).
    assert!(near(p.segments()[0].start(), V2::new(0.0, 0.0), 1e-15));
    assert!(near(p.segments()[0].end(), V2::new(-2.0, 0.0), 1e-15));
    assert!(distance_to(&p.segments()[0], V2::new(-1.0, -1.0)) < 1e-14);
}

#[test]
fn a_tilted_extrusion_alone_is_refused_naming_the_entity() {
    // (Beside other geometry it is skipped, and the answer uncertified: see `corpus`.)
    let mut d = drawing();
    let h = add(
        &mut d,
        EntityType::Circle(Circle {
            normal: Vector::new(0.0, 0.6, 0.8),
            ..Circle::new(p3(0.0, 0.0), 1.0)
        }),
    );
    let e = read_err(&d);
    assert!(e.to_string().contains(&format!("CIRCLE {h}")), "{e}");
    assert!(e.to_string().contains("not in the drawing's plane"), "{e}");
}

// ---------------------------------------------------------------------------------------------
// Polylines.

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

fn lw(x: f64, y: f64, bulge: f64) -> LwPolylineVertex {
    LwPolylineVertex {
        x,
        y,
        bulge,
        ..Default::default()
    }
}

/// The centre and radius of the arc of bulge `b` from `p` to `q`, by the sagitta.
fn bulge_circle(p: V2, q: V2, b: f64) -> (V2, f64, V2) {
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

// ---------------------------------------------------------------------------------------------
// Splines.

fn spline_entity(
    degree: i32,
    knots: &[f64],
    points: &[[f64; 2]],
    weights: &[f64],
    flags: i32,
) -> EntityType {
    EntityType::Spline(Spline {
        degree_of_curve: degree,
        knot_values: knots.to_vec(),
        weight_values: weights.to_vec(),
        control_points: points.iter().map(|p| p3(p[0], p[1])).collect(),
        flags,
        ..Default::default()
    })
}

/// A rational quadratic quarter circle of radius 2 from (2, 0) to (0, 2), closed by two lines
/// through the origin.
fn quarter_circle(d: &mut Drawing) -> String {
    let h = add(
        d,
        spline_entity(
            2,
            &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            &[[2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
            &[1.0, FRAC_1_SQRT_2, 1.0],
            4 | 8,
        ),
    );
    add(d, line(0.0, 2.0, 0.0, 0.0));
    add(d, line(0.0, 0.0, 2.0, 0.0));
    h
}

fn assert_quarter_circle(p: &Profile) {
    let s = &p.segments()[0];
    assert_eq!(s.kind(), SegmentKind::BSpline);
    assert!(s.curve().curve().is_rational(), "the weights were dropped");
    let (a, b) = s.domain();
    for k in 0..=16 {
        let q = s.jet(a + (b - a) * k as f64 / 16.0).p;
        // (Within the rounding of the weight √2/2 to 12 decimals by the crate's writer.)
        testkit::assert_near!(q.norm(), 2.0, 1e-11, "off the circle: {q:?}");
    }
    // Without the weights the middle would be at (1.5, 1.5), 2.12 from the origin.
    let mid = s.jet(0.5 * (a + b)).p;
    assert!(
        near(mid, V2::new(2.0f64.sqrt(), 2.0f64.sqrt()), 1e-11),
        "{mid:?}"
    );
}

#[test]
fn a_rational_spline_keeps_its_weights() {
    let mut d = drawing();
    quarter_circle(&mut d);
    let p = read(&d);
    assert!(p.is_closed());
    assert_quarter_circle(&p);
}

/// The hand-written SPLINE groups of the quarter circle, as AutoCAD orders them (each weight
/// after its point), with or without z groups.
fn quarter_circle_text(with_z: bool) -> String {
    let mut s = vec![
        (5, "4A".to_string()),
        (100, "AcDbEntity".into()),
        (8, "0".into()),
        (100, "AcDbSpline".into()),
        (70, "12".into()),
        (71, "2".into()),
        (72, "6".into()),
        (73, "3".into()),
        (74, "0".into()),
    ];
    s.extend(g(&[
        (40, 0.0),
        (40, 0.0),
        (40, 0.0),
        (40, 1.0),
        (40, 1.0),
        (40, 1.0),
    ]));
    for (x, y, w) in [(2.0, 0.0, 1.0), (2.0, 2.0, FRAC_1_SQRT_2), (0.0, 2.0, 1.0)] {
        s.extend(g(&[(10, x), (20, y)]));
        if with_z {
            s.extend(g(&[(30, 0.0)]));
        }
        s.extend(g(&[(41, w)]));
    }
    dxf_text(&[
        ("SPLINE", s),
        ("LINE", g(&[(10, 0.0), (20, 2.0), (11, 0.0), (21, 0.0)])),
        ("LINE", g(&[(10, 0.0), (20, 0.0), (11, 2.0), (21, 0.0)])),
    ])
}

#[test]
fn a_spline_written_without_z_groups_keeps_its_control_points() {
    // The dxf crate alone reads no control point here (it pairs x, y and z lists).
    let text = quarter_circle_text(false);
    let crate_view = Drawing::load(&mut text.as_bytes()).unwrap();
    let Some(EntityType::Spline(s)) = crate_view.entities().next().map(|e| &e.specific) else {
        panic!("no spline");
    };
    assert!(s.control_points.is_empty(), "the crate was fixed: {s:?}");
    let p = read_text(&text).unwrap();
    assert_quarter_circle(&p);
    let p = read_text(&quarter_circle_text(true)).unwrap();
    assert_quarter_circle(&p);
}

#[test]
fn an_interior_knot_of_multiplicity_two_is_kept() {
    // A cubic with a double knot at 1: C¹ there. Dropping or merging it changes the curve.
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 2.5, 2.5, 2.5, 2.5];
    let pts = [
        [0.0, 0.0],
        [1.0, 2.0],
        [2.0, 2.5],
        [3.0, 1.0],
        [4.0, 3.0],
        [6.0, 0.0],
    ];
    let mut d = drawing();
    add(&mut d, spline_entity(3, &knots, &pts, &[], 8));
    add(&mut d, line(6.0, 0.0, 0.0, 0.0));
    let p = read(&d);
    let s = &p.segments()[0];
    let want = SplineCurve::clamped(3, &pts, None, Some(knots.to_vec())).unwrap();
    assert_eq!(s.domain(), (0.0, 2.5));
    for k in 0..=50 {
        let u = 2.5 * k as f64 / 50.0;
        let (a, b) = (s.jet(u).p, want.jet(u).p);
        assert!(near(a, b, 1e-14), "u = {u}: {a:?} vs {b:?}");
    }
    // And by de Boor's algorithm directly, at the double knot and beside it.
    for u in [0.7, 1.0, 1.3, 2.2] {
        let q = de_boor(3, &knots, &pts, u);
        assert!(near(s.jet(u).p, q, 1e-14), "u = {u}");
    }
}

/// The point of the polynomial B-spline at `u` by de Boor's algorithm.
fn de_boor(p: usize, t: &[f64], c: &[[f64; 2]], u: f64) -> V2 {
    let n = c.len();
    let mut k = p;
    while k + 1 < n && t[k + 1] <= u {
        k += 1;
    }
    let mut d: Vec<V2> = (0..=p).map(|j| V2::from_arr(c[j + k - p])).collect();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = j + k - p;
            let a = (u - t[i]) / (t[i + p + 1 - r] - t[i]);
            d[j] = d[j - 1] * (1.0 - a) + d[j] * a;
        }
    }
    d[p]
}

#[test]
fn a_periodic_spline_is_clamped_exactly_and_closes() {
    // As AutoCAD writes a periodic cubic: the first three control points repeated at the end,
    // uniform unclamped knots, flags closed | periodic | planar.
    let unique = [[0.0, 0.0], [4.0, -1.0], [6.0, 2.0], [3.0, 5.0], [-1.0, 3.0]];
    let mut pts = unique.to_vec();
    pts.extend_from_slice(&unique[..3]);
    let knots: Vec<f64> = (0..pts.len() + 4).map(|i| i as f64).collect();
    let mut d = drawing();
    add(&mut d, spline_entity(3, &knots, &pts, &[], 1 | 2 | 8));
    let p = read(&d);
    assert!(p.is_closed());
    assert_eq!(p.segments().len(), 1);
    let s = &p.segments()[0];
    // Domain [3, 8], the periodic curve's [0, 5) shifted.
    assert_eq!(s.domain(), (3.0, 8.0));
    let periodic = SplineCurve::periodic(3, &unique, None).unwrap();
    for k in 0..50 {
        let u = 5.0 * k as f64 / 50.0;
        let (a, b) = (s.jet(u + 3.0).p, periodic.jet(u).p);
        assert!(near(a, b, 1e-13), "u = {u}: {a:?} vs {b:?}");
        assert!(near(
            s.jet(u + 3.0).p,
            de_boor(3, &knots, &pts, u + 3.0),
            1e-13
        ));
    }
    // Smooth at the seam: no corner.
    assert_eq!(p.corners().count(), 0);
    // Flagged closed with the repeats left out: the ends do not meet, refused.
    let knots: Vec<f64> = (0..unique.len() + 4).map(|i| i as f64).collect();
    let mut d = drawing();
    let h2 = add(&mut d, spline_entity(3, &knots, &unique, &[], 1 | 2 | 8));
    let e = read_err(&d);
    assert_eq!(e.field, format!("SPLINE {h2}"), "{e}");
    assert!(e.to_string().contains("flagged closed"), "{e}");
}

#[test]
fn a_rational_periodic_spline_keeps_its_weights_when_clamped() {
    // The full circle as a periodic rational quadratic? Not exact; instead: a periodic
    // quadratic with weights, compared with de Boor in homogeneous form.
    let unique = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];
    let w_unique = [1.0, 2.0, 1.0, 2.0];
    let mut pts = unique.to_vec();
    pts.extend_from_slice(&unique[..2]);
    let mut w = w_unique.to_vec();
    w.extend_from_slice(&w_unique[..2]);
    let knots: Vec<f64> = (0..pts.len() + 3).map(|i| i as f64).collect();
    let mut d = drawing();
    add(&mut d, spline_entity(2, &knots, &pts, &w, 1 | 2 | 4 | 8));
    let p = read(&d);
    let s = &p.segments()[0];
    let hom: Vec<[f64; 2]> = pts
        .iter()
        .zip(&w)
        .map(|(p, w)| [p[0] * w, p[1] * w])
        .collect();
    let ws: Vec<[f64; 2]> = w.iter().map(|&w| [w, 0.0]).collect();
    for k in 0..=40 {
        let u = 2.0 + 4.0 * k as f64 / 40.0;
        let x = de_boor(2, &knots, &hom, u);
        let wt = de_boor(2, &knots, &ws, u).x;
        assert!(near(s.jet(u).p, x * (1.0 / wt), 1e-13), "u = {u}");
    }
}

#[test]
fn spline_refusals_name_the_entity_and_field() {
    // Rational flag without weights.
    let mut d = drawing();
    let h = add(
        &mut d,
        spline_entity(
            2,
            &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            &[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]],
            &[],
            4,
        ),
    );
    let e = read_err(&d);
    assert_eq!(e.field, format!("SPLINE {h} weights"), "{e}");
    // Wrong knot count.
    let mut d = drawing();
    let h = add(
        &mut d,
        spline_entity(
            2,
            &[0.0, 0.0, 1.0, 1.0, 1.0],
            &[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]],
            &[],
            0,
        ),
    );
    assert_eq!(read_err(&d).field, format!("SPLINE {h} knots"));
    // Interior multiplicity above the degree (a break in the curve).
    let mut d = drawing();
    let h = add(
        &mut d,
        spline_entity(
            1,
            &[0.0, 0.0, 1.0, 1.0, 2.0, 2.0],
            &[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 0.0]],
            &[],
            0,
        ),
    );
    assert_eq!(read_err(&d).field, format!("SPLINE {h} knots"));
    // Fit points only.
    let text = dxf_text(&[(
        "SPLINE",
        [
            vec![(5, "4A".to_string()), (71, "3".into())],
            g(&[(11, 0.0), (21, 0.0), (11, 1.0), (21, 1.0)]),
        ]
        .concat(),
    )]);
    let e = read_text(&text).unwrap_err();
    assert_eq!(e.field, "SPLINE 4A control points", "{e}");
    assert!(e.to_string().contains("fit points"), "{e}");
    // A degree beyond the limit.
    let text = dxf_text(&[(
        "SPLINE",
        vec![(71, "65".to_string()), (10, "0".into()), (20, "0".into())],
    )]);
    let e = read_text(&text).unwrap_err();
    assert_eq!(e.field, "SPLINE #1 degree", "{e}");
}

// ---------------------------------------------------------------------------------------------
// Bad drawings.

/// A square of side 10 with its last side stopping `gap` short.
fn square_with_gap(gap: f64) -> (Drawing, Vec<String>) {
    let mut d = drawing();
    let h = vec![
        add(&mut d, line(0.0, 0.0, 10.0, 0.0)),
        add(&mut d, line(10.0, 0.0, 10.0, 10.0)),
        add(&mut d, line(10.0, 10.0, 0.0, 10.0)),
        add(&mut d, line(0.0, 10.0, 0.0, gap)),
    ];
    (d, h)
}

#[test]
fn ends_within_the_tolerance_join_and_a_gap_beyond_it_is_refused() {
    // 1e-9 of the size (14.1): a gap of 1e-9 joins, one of 1e-6 is a gap.
    let (d, _) = square_with_gap(1e-9);
    assert!(read(&d).is_closed());
    let (d, h) = square_with_gap(1e-6);
    let e = read_err(&d);
    assert_eq!(e.field, format!("LINE {}", h[0]), "{e}");
    let msg = e.to_string();
    assert!(
        msg.contains("gap of 1e-6") && msg.contains("(0, 0.000001)"),
        "{msg}"
    );
    assert!(msg.contains(&format!("LINE {}", h[3])), "{msg}");
    // On the command line: exit 2, one line naming the entity.
    let path = saved(&d);
    let r = curvekit(&["antipodal", path.to_str().unwrap()]);
    assert_eq!(r.code, 2, "{}", r.stderr);
    assert!(r.stderr.contains(&format!("LINE {}", h[0])) && r.stderr.contains("gap"));
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    // A gap of a third of the side is an open outline drawn so: read as an open profile,
    // which antipodal refuses (exit 2) and inflections takes.
    let (d, _) = square_with_gap(3.0);
    assert!(!read(&d).is_closed());
    let path = saved(&d);
    assert_eq!(curvekit(&["antipodal", path.to_str().unwrap()]).code, 2);
    assert_eq!(curvekit(&["inflections", path.to_str().unwrap()]).code, 0);
}

#[test]
fn a_short_open_line_is_no_gap() {
    // A centre mark 0.05 long beside a part 1000 across: its ends are 5e-5 of the drawing
    // apart, but its whole length apart: an open profile of its own.
    let mut d = drawing();
    add(
        &mut d,
        EntityType::Circle(Circle::new(p3(500.0, 500.0), 500.0)),
    );
    add(&mut d, line(500.0, 500.0, 500.05, 500.0));
    let path = saved(&d);
    assert!(read_path(&path, 0).unwrap().is_closed());
    assert!(!read_path(&path, 1).unwrap().is_closed());
}

#[test]
fn a_branch_point_is_refused_naming_the_entities() {
    let mut d = drawing();
    let a = add(&mut d, line(0.0, 0.0, 1.0, 0.0));
    let b = add(&mut d, line(1.0, 0.0, 2.0, 0.0));
    let c = add(&mut d, line(1.0, 0.0, 1.0, 1.0));
    let e = read_err(&d);
    assert_eq!(e.field, format!("LINE {a}"), "{e}");
    let msg = e.to_string();
    assert!(
        msg.contains("branch") && msg.contains(&b) && msg.contains(&c),
        "{msg}"
    );
    let path = saved(&d);
    let r = curvekit(&["inflections", path.to_str().unwrap()]);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("branch"), "{}", r.stderr);
}

#[test]
fn an_empty_drawing_and_one_of_text_only_are_bad_input() {
    let d = drawing();
    let path = saved(&d);
    let r = curvekit(&["antipodal", path.to_str().unwrap()]);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("no usable geometry"), "{}", r.stderr);
    let text = dxf_text(&[(
        "TEXT",
        vec![
            (1, "hello".to_string()),
            (10, "0".into()),
            (20, "0".into()),
            (40, "1".into()),
        ],
    )]);
    let e = read_text(&text).unwrap_err();
    assert!(e.to_string().contains("no usable geometry"), "{e}");
}

#[test]
fn garbage_and_truncated_files_are_refused_without_panicking() {
    let good = quarter_circle_text(false);
    let mut inputs: Vec<Vec<u8>> = vec![
        Vec::new(),
        b"\n\n\n".to_vec(),
        b"hello world".to_vec(),
        vec![0xff, 0xfe, 0x00, 0x01, 0x80],
        b"AutoCAD Binary DXF\r\n\x1a\x00".to_vec(),
        b"0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nnan\n20\n0\n11\n1\n21\n1\n0\nENDSEC\n0\nEOF\n"
            .to_vec(),
        b"0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1e999\n20\n0\n11\n1\n21\n1\n0\nENDSEC\n0\nEOF\n"
            .to_vec(),
    ];
    // Every prefix of a good file, cut at each line.
    let bytes = good.as_bytes();
    for (i, _) in bytes.iter().enumerate().filter(|(_, &b)| b == b'\n') {
        inputs.push(bytes[..i].to_vec());
    }
    for input in &inputs {
        let path = temp_dxf(input);
        match read_path(&path, 0) {
            Ok(p) => assert!(!p.segments().is_empty()),
            Err(e) => assert!(!e.to_string().is_empty()),
        }
    }
    // Through the binary: exit 2 and no panic.
    for input in inputs.iter().take(7) {
        let path = temp_dxf(input);
        let r = curvekit(&["inflections", path.to_str().unwrap()]);
        assert_eq!(r.code, 2, "{input:?}: {}", r.stderr);
        assert!(!r.stderr.contains("panicked"), "{}", r.stderr);
    }
}

#[test]
fn an_entity_the_crate_drops_silently_is_refused() {
    // The last LINE's last group is malformed: the dxf crate returns the drawing without it.
    let text = dxf_text(&[
        ("LINE", g(&[(10, 0.0), (20, 0.0), (11, 1.0), (21, 0.0)])),
        ("LINE", g(&[(10, 1.0), (20, 0.0), (11, 0.0), (21, 1.0)])),
        (
            "LINE",
            vec![
                (10, "0".to_string()),
                (20, "1".into()),
                (11, "0".into()),
                (21, "zero".into()),
            ],
        ),
    ]);
    let crate_view = Drawing::load(&mut text.as_bytes()).unwrap();
    assert_eq!(crate_view.entities().count(), 2, "the crate was fixed");
    let e = read_text(&text).unwrap_err();
    assert_eq!(e.field, "LINE #3", "{e}");
    // A blank line where a group code should be, before the section's end: the crate drops
    // the entity it interrupts, and reads on.
    let lines = [
        ("LINE", g(&[(10, 0.0), (20, 0.0), (11, 1.0), (21, 0.0)])),
        ("LINE", g(&[(10, 1.0), (20, 0.0), (11, 0.0), (21, 1.0)])),
    ];
    let text = dxf_text(&lines).replace("  0\nENDSEC", "\n  0\nENDSEC");
    let crate_view = Drawing::load(&mut text.as_bytes()).unwrap();
    assert_eq!(crate_view.entities().count(), 1, "the crate was fixed");
    let e = read_text(&text).unwrap_err();
    assert!(e.to_string().contains("empty line"), "{e}");
}

#[test]
fn paper_space_and_other_entity_types_are_left_out() {
    let mut d = drawing();
    add(&mut d, line(0.0, 0.0, 1.0, 0.0));
    add(&mut d, line(1.0, 0.0, 0.0, 1.0));
    add(&mut d, line(0.0, 1.0, 0.0, 0.0));
    // A circle in paper space, and a point, are not part of the profile.
    let mut c = Entity::new(EntityType::Circle(Circle::new(p3(5.0, 5.0), 1.0)));
    c.common.is_in_paper_space = true;
    d.add_entity(c);
    add(
        &mut d,
        EntityType::ModelPoint(dxf::entities::ModelPoint::new(p3(9.0, 9.0))),
    );
    let p = read(&d);
    assert_eq!(p.segments().len(), 3);
    // One profile only: --pick 1 is beyond it.
    assert_eq!(read_path(&saved(&d), 1).unwrap_err().field, "--pick");
}

#[test]
fn profiles_are_ordered_and_named_by_their_first_entity() {
    let mut d = drawing();
    add(&mut d, EntityType::Circle(Circle::new(p3(20.0, 0.0), 1.0)));
    add(&mut d, line(0.0, 0.0, 1.0, 0.0));
    add(&mut d, line(1.0, 0.0, 0.0, 1.0));
    add(&mut d, line(0.0, 1.0, 0.0, 0.0));
    let path = saved(&d);
    let circle = read_path(&path, 0).unwrap();
    assert_eq!(circle.segments().len(), 1);
    let triangle = read_path(&path, 1).unwrap();
    assert_eq!(triangle.segments().len(), 3);
    // Without --pick: two profiles, a choice to make.
    let e = read_curve_picked(&path, None).unwrap_err();
    assert!(e.to_string().contains("--pick"), "{e}");
}

// ---------------------------------------------------------------------------------------------
// Fixtures and the commands on them.

#[test]
fn the_bracket_fixture_reads_as_one_closed_profile() {
    let path = std::path::PathBuf::from(fixture("drawing-bracket.dxf"));
    let p = read_path(&path, 0).unwrap();
    assert!(p.is_closed());
    let kinds: Vec<SegmentKind> = p.segments().iter().map(|s| s.kind()).collect();
    assert!(kinds.contains(&SegmentKind::Arc) && kinds.contains(&SegmentKind::BSpline));
    let v = curvekit_json(&["inflections", &fixture("drawing-bracket.dxf")]);
    assert!(
        v["corners"].as_array().is_some_and(|c| !c.is_empty()),
        "{v}"
    );
    let v = curvekit_json(&["antipodal", &fixture("drawing-bracket.dxf")]);
    assert!(v["pairs"].as_array().is_some_and(|c| !c.is_empty()), "{v}");
}

#[test]
fn the_plate_fixture_is_a_rounded_rectangle() {
    let path = std::path::PathBuf::from(fixture("drawing-plate.dxf"));
    let p = read_path(&path, 0).unwrap();
    assert!(p.is_closed());
    assert_eq!(p.corners().count(), 0, "fillets are tangent to the sides");
    let arcs = p
        .segments()
        .iter()
        .filter(|s| s.kind() == SegmentKind::Arc)
        .count();
    assert_eq!(arcs, 4);
    let v = curvekit_json(&["antipodal", &fixture("drawing-plate.dxf")]);
    assert!(v["pairs"].as_array().is_some_and(|c| !c.is_empty()), "{v}");
}

// ---------------------------------------------------------------------------------------------
// Property: random polygons with random bulges, written by the dxf crate, read back.

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
