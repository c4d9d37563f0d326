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

mod bad_drawings;
mod blocks;
#[path = "../common/mod.rs"]
mod common;
mod corpus;
mod fixtures;
mod lines_and_arcs;
mod polylines;
mod random_polygons;
mod splines;
mod written;

use curve::{ParamCurve, Profile, Segment, V2};
use curvekit::io::{read_curve_picked, CurveFileError, CurveKind};
use dxf::entities::{Arc, Entity, EntityType, Line};
use dxf::enums::AcadVersion;
use dxf::{Drawing, Point};
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

/// Groups from `(code, text)` pairs.
fn groups(pairs: &[(i32, &str)]) -> Vec<(i32, String)> {
    pairs.iter().map(|&(c, v)| (c, v.to_string())).collect()
}

/// The groups of a LINE whose last group is malformed (`21` holds a word): the dxf crate
/// drops such an entity without a word, and the reader must not.
fn line_with_a_malformed_last_group() -> Vec<(i32, String)> {
    groups(&[(10, "0"), (20, "1"), (11, "0"), (21, "zero")])
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
