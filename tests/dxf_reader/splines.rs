//! Splines: rational ones keeping their weights, written without z groups, interior knots of
//! multiplicity two, periodic ones clamped exactly, and the refusals that name the entity and
//! field.

use super::{add, drawing, dxf_text, g, groups, line, near, p3, read, read_err, read_text};
use curve::{ParamCurve, Profile, SegmentKind, SplineCurve, V2};
use dxf::entities::{EntityType, Spline};
use dxf::Drawing;
use std::f64::consts::FRAC_1_SQRT_2;

pub(crate) fn spline_entity(
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
pub(crate) fn quarter_circle_text(with_z: bool) -> String {
    let mut s = groups(&[
        (5, "4A"),
        (100, "AcDbEntity"),
        (8, "0"),
        (100, "AcDbSpline"),
        (70, "12"),
        (71, "2"),
        (72, "6"),
        (73, "3"),
        (74, "0"),
    ]);
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
