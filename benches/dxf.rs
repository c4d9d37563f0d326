//! Reading a DXF drawing of 1,000 entities: four outlines of 125 arcs and 125 lines each (a
//! circle's arcs joined by chords), the entities shuffled and half the lines drawn backwards,
//! as CAD files list them in no useful order. Target: under 10 ms for the whole read (the
//! `dxf` crate's parse, the SPLINE and handle tokenizer, chaining, and the profiles' checks),
//! as `curvekit antipodal FILE --pick 0` starts with it.
#![allow(missing_docs, clippy::unwrap_used)]

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use curve::ParamCurve;
use curvekit::io::{parse_drawing, read_curve_picked, CurveKind, DrawingFormat};
use std::io::Write;
use std::time::Duration;

use testkit::rng;

/// The drawing's text: `outlines` outlines of `teeth` arcs and `teeth` chords each.
fn drawing(outlines: usize, teeth: usize) -> String {
    let mut rnd = rng(11);
    let mut entities: Vec<String> = Vec::new();
    for k in 0..outlines {
        let (cx, cy, r) = (100.0 * k as f64, 50.0, 40.0);
        let at = |deg: f64| {
            let a = deg.to_radians();
            (cx + r * a.cos(), cy + r * a.sin())
        };
        let step = 360.0 / teeth as f64;
        for i in 0..teeth {
            let (a0, a1) = (step * i as f64, step * i as f64 + 0.6 * step);
            entities.push(format!(
                "ARC\n8\nOUTLINE\n100\nAcDbCircle\n10\n{cx:?}\n20\n{cy:?}\n30\n0.0\n40\n{r:?}\n\
                 100\nAcDbArc\n50\n{a0:?}\n51\n{a1:?}\n"
            ));
            let (mut p, mut q) = (at(a1), at(step * (i + 1) as f64));
            if rnd() < 0.5 {
                std::mem::swap(&mut p, &mut q);
            }
            entities.push(format!(
                "LINE\n8\nOUTLINE\n100\nAcDbLine\n10\n{:?}\n20\n{:?}\n30\n0.0\n11\n{:?}\n21\n{:?}\n\
                 31\n0.0\n",
                p.0, p.1, q.0, q.1
            ));
        }
    }
    // Shuffled (Fisher–Yates), then numbered with handles.
    for i in (1..entities.len()).rev() {
        let j = (rnd() * (i + 1) as f64) as usize;
        entities.swap(i, j.min(i));
    }
    let mut s = String::from("0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n0\nENDSEC\n");
    s += "0\nSECTION\n2\nENTITIES\n";
    for (i, e) in entities.iter().enumerate() {
        let (kind, rest) = e.split_once('\n').unwrap();
        s += &format!("0\n{kind}\n5\n{:X}\n100\nAcDbEntity\n{rest}", 0x100 + i);
    }
    s + "0\nENDSEC\n0\nEOF\n"
}

fn dxf(c: &mut Criterion) {
    let text = drawing(4, 125);
    let mut file = tempfile::Builder::new().suffix(".dxf").tempfile().unwrap();
    file.write_all(text.as_bytes()).unwrap();
    let path = file.into_temp_path();
    // The drawing is what it should be: four closed profiles of 250 segments.
    for k in 0..4 {
        match read_curve_picked(&path, Some(k)).unwrap().shape {
            CurveKind::Profile(p) => assert!(p.is_closed() && p.segments().len() == 250),
            _ => unreachable!(),
        }
    }
    let mut g = c.benchmark_group("dxf");
    g.measurement_time(Duration::from_secs(5));
    g.bench_function("read_1000_entities", |b| {
        b.iter(|| read_curve_picked(black_box(&path), Some(0)).unwrap())
    });
    g.bench_function("parse_1000_entities_in_memory", |b| {
        b.iter(|| {
            parse_drawing(
                "bench.dxf",
                DrawingFormat::Dxf,
                black_box(text.as_bytes()),
                Some(0),
            )
            .unwrap()
        })
    });
    g.finish();
}

criterion_group!(benches, dxf);
criterion_main!(benches);
