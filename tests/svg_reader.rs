//! The SVG reader: path data as design tools and fonts write it, transforms, the basic
//! shapes, `--pick`, malformed files (exit 2, never a panic), and a property test that
//! writes random profiles as path data and reads them back.
#![allow(clippy::unwrap_used)]

mod common;

use common::Tally;
use common::{curvekit, fixture};
use curvekit::curve::{ParamCurve, Profile, Segment, SegmentKind, V2};
use curvekit::io::{read_curve_picked, CurveKind};
use proptest::prelude::*;
use std::f64::consts::TAU;
use std::io::Write;

fn write_svg(body: &str) -> tempfile::NamedTempFile {
    let mut f = tempfile::Builder::new().suffix(".svg").tempfile().unwrap();
    write!(f, r#"<svg xmlns="http://www.w3.org/2000/svg">{body}</svg>"#).unwrap();
    f
}

fn profile_of(body: &str, pick: Option<usize>) -> Profile {
    let f = write_svg(body);
    match read_curve_picked(f.path(), pick).unwrap().shape {
        CurveKind::Profile(p) => *p,
        other => panic!("not a profile: {other:?}"),
    }
}

/// `n` points of each segment, in order.
fn samples(p: &Profile, n: usize) -> Vec<V2> {
    p.segments()
        .iter()
        .flat_map(|s| (0..=n).map(move |k| s.jet(k as f64 / n as f64).p))
        .collect()
}

#[test]
fn transforms_of_groups_and_elements_compose() {
    let plain = profile_of(r#"<path d="M 0 0 L 4 0 A 2 2 0 0 1 4 4 L 0 4 Z"/>"#, None);
    let moved = profile_of(
        r#"<g transform="translate(10 20)"><g transform="rotate(90)">
           <path transform="scale(2)" d="M 0 0 L 4 0 A 2 2 0 0 1 4 4 L 0 4 Z"/></g></g>"#,
        None,
    );
    // p ↦ translate(rotate(scale(p))): (x, y) ↦ (10 − 2y, 20 + 2x).
    let map = |p: V2| V2::new(10.0 - 2.0 * p.y, 20.0 + 2.0 * p.x);
    for (a, b) in samples(&plain, 8).into_iter().zip(samples(&moved, 8)) {
        assert!((map(a) - b).norm() < 1e-12, "{a:?} ↦ {b:?}");
    }
    // A similarity keeps the arc circular; a shear makes it elliptical.
    assert!(moved
        .segments()
        .iter()
        .any(|s| s.kind() == SegmentKind::Arc));
    let sheared = profile_of(
        r#"<path transform="matrix(1 0 0.5 1 0 0)" d="M 0 0 L 4 0 A 2 2 0 0 1 4 4 L 0 4 Z"/>"#,
        None,
    );
    assert!(sheared
        .segments()
        .iter()
        .any(|s| s.kind() == SegmentKind::EllipticArc));
}

#[test]
fn basic_shapes_are_read() {
    let c = profile_of(r#"<circle cx="5" cy="6" r="2"/>"#, None);
    assert!(samples(&c, 16)
        .iter()
        .all(|p| ((*p - V2::new(5.0, 6.0)).norm() - 2.0).abs() < 1e-12));
    let e = profile_of(r#"<ellipse cx="1" cy="2" rx="3" ry="1"/>"#, None);
    assert!(samples(&e, 16)
        .iter()
        .all(|p| (((p.x - 1.0) / 3.0).powi(2) + (p.y - 2.0).powi(2) - 1.0).abs() < 1e-12));
    let r = profile_of(r#"<rect x="1" y="2" width="10" height="6" rx="2"/>"#, None);
    assert_eq!(r.segments().len(), 8);
    assert!(
        r.corners().next().is_none(),
        "a rounded rectangle has no corner"
    );
    let sharp = profile_of(r#"<rect width="10" height="6"/>"#, None);
    assert_eq!((sharp.segments().len(), sharp.corners().count()), (4, 4));
    let poly = profile_of(r#"<polygon points="0,0 4,0 4,3"/>"#, None);
    assert!(poly.is_closed() && poly.segments().len() == 3);
    // A filled polyline is filled as closed (SVG's rule); one drawn with a stroke only is open.
    let filled = profile_of(r#"<polyline points="0,0 4,0 4,3"/>"#, None);
    assert!(filled.is_closed() && filled.segments().len() == 3);
    let open = profile_of(
        r#"<polyline fill="none" stroke="black" points="0,0 4,0 4,3"/>"#,
        None,
    );
    assert!(!open.is_closed());
}

#[test]
fn hidden_elements_are_skipped_and_several_profiles_need_pick() {
    let body = r#"<defs><path d="M 0 0 L 9 9 L 9 0 Z"/></defs>
        <path d="M 0 0 L 1 0 L 1 1 Z M 5 5 L 6 5 L 6 6 Z"/>"#;
    let f = write_svg(body);
    let e = read_curve_picked(f.path(), None).unwrap_err();
    assert!(
        e.to_string().contains("2 profiles") && e.to_string().contains("--pick"),
        "{e}"
    );
    let second = profile_of(body, Some(1));
    assert_eq!(second.segments()[0].start(), V2::new(5.0, 5.0));
    let e = read_curve_picked(f.path(), Some(2)).unwrap_err();
    assert_eq!(e.field, "--pick");
}

#[test]
fn the_glyph_pocket_and_gear_fixtures_read() {
    let read =
        |name: &str, pick| match read_curve_picked(std::path::Path::new(&fixture(name)), pick)
            .unwrap()
            .shape
        {
            CurveKind::Profile(p) => *p,
            _ => unreachable!(),
        };
    // The D: outer contour with two corners, its counter with two.
    let outer = read("drawing-glyph-d.svg", Some(0));
    let counter = read("drawing-glyph-d.svg", Some(1));
    assert_eq!((outer.corners().count(), counter.corners().count()), (2, 2));
    // The font's y-up outline was flipped by its transform.
    assert!(samples(&outer, 4).iter().all(|p| p.y <= 0.0));
    let pocket = read("drawing-pocket.svg", Some(0));
    assert_eq!(pocket.corners().count(), 0);
    let gear = read("drawing-gear.svg", None);
    assert_eq!((gear.segments().len(), gear.corners().count()), (48, 48));
}

#[test]
fn malformed_files_exit_2_naming_the_element() {
    let cases = [
        ("not xml <", "document"),
        ("<html><body/></html>", "document"),
        (
            r#"<svg xmlns="http://www.w3.org/2000/svg"></svg>"#,
            "document",
        ),
        (
            r#"<svg xmlns="http://www.w3.org/2000/svg"><path id="p" d="M 0 0 L"/></svg>"#,
            "path#p d",
        ),
        (
            r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 1 1 Z" transform="rotate(x)"/></svg>"#,
            "path[0] transform",
        ),
        (
            r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 1 1 L 1 0 Z" transform="scale(0)"/></svg>"#,
            "path[0] transform",
        ),
        (
            r#"<svg xmlns="http://www.w3.org/2000/svg"><circle r="-1"/></svg>"#,
            "circle[0] geometry",
        ),
        (
            r#"<svg xmlns="http://www.w3.org/2000/svg"><rect width="5mm" height="2"/></svg>"#,
            "rect[0] width",
        ),
        (
            r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 2 2 L 2 0 L 0 2 Z"/></svg>"#,
            "path[0] subpath 0 segment 2",
        ),
    ];
    for (text, field) in cases {
        let mut f = tempfile::Builder::new().suffix(".svg").tempfile().unwrap();
        f.write_all(text.as_bytes()).unwrap();
        let path = f.path().to_str().unwrap().to_string();
        let r = curvekit(&["inflections", &path]);
        assert_eq!(r.code, 2, "{text}: {}", r.stderr);
        assert!(
            r.stderr.contains(&format!("{path}: {field}")),
            "{text}: expected field `{field}` in {}",
            r.stderr
        );
    }
}

/// A random closed profile of lines and circular arcs (a star polygon with some corners
/// rounded), written as SVG path data with each command absolute or relative at random.
fn path_data(v: &[V2], round: &[f64], relative: &[bool]) -> Option<(String, Profile)> {
    let n = v.len();
    let mut segs = Vec::new();
    let mut d = String::new();
    let cmd =
        |d: &mut String, k: usize, abs: char, rel: char, args: &[f64], to: V2, at: &mut V2| {
            let r = relative[k % relative.len()];
            let c = if r { rel } else { abs };
            d.push(c);
            let nargs = args.len();
            for (i, a) in args.iter().enumerate() {
                // The end point (the last two numbers) relative when asked.
                let x = if r && i + 2 >= nargs {
                    if (nargs - i).is_multiple_of(2) {
                        a - at.x
                    } else {
                        a - at.y
                    }
                } else {
                    *a
                };
                // (An arc's flags are the digits 0 and 1.)
                if (abs == 'A') && (i == 3 || i == 4) {
                    d.push_str(&format!(" {}", x as u8));
                } else {
                    d.push_str(&format!(" {x:?}"));
                }
            }
            d.push(' ');
            *at = to;
        };
    // Corner i is cut back along both edges where it is rounded.
    let mut cut = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b, c) = (v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
        let (din, dout) = ((b - a).unit(), (c - b).unit());
        let turn = din.cross(dout).atan2(din.dot(dout));
        if round[i] <= 0.0 || turn.abs() < 0.1 {
            cut.push((b, b, None));
            continue;
        }
        let reach = round[i] * 0.45 * (b - a).norm().min((c - b).norm());
        let r = reach / (0.5 * turn.abs()).tan();
        // (An arc far smaller than its coordinates: its end points as written, rounded to
        // doubles, leave its tangents there uncertain by about ε·|b| / (r cos(turn/2)) (SVG's
        // centre from the chord magnifies the rounding near a half turn). Where that nears the
        // contract's 1e-9 rad, the file as written has corners there.)
        let magnitude = b.x.abs().max(b.y.abs());
        if f64::EPSILON * magnitude / (r * (0.5 * turn).cos().abs()) > 1e-11 {
            cut.push((b, b, None));
            continue;
        }
        cut.push((b - din * reach, b + dout * reach, Some((r, turn))));
    }
    let start = cut[0].1;
    d.push_str(&format!("M {:?} {:?} ", start.x, start.y));
    let mut at = start;
    for i in 0..n {
        let from = cut[i].1;
        let (to, next, arc) = cut[(i + 1) % n];
        segs.push(Segment::line(from.arr(), to.arr()).ok()?);
        cmd(&mut d, 2 * i, 'L', 'l', &[to.x, to.y], to, &mut at);
        if let Some((r, turn)) = arc {
            let (din, _) = ((to - from).unit(), ());
            let center = to + din.perp() * (r * turn.signum());
            let a0 = (to - center).angle();
            segs.push(Segment::arc(center.arr(), r, a0, a0 + turn).ok()?);
            // Sweep flag 1: increasing angle.
            let sweep = if turn > 0.0 { 1.0 } else { 0.0 };
            cmd(
                &mut d,
                2 * i + 1,
                'A',
                'a',
                &[r, r, 0.0, 0.0, sweep, next.x, next.y],
                next,
                &mut at,
            );
        }
    }
    d.push('Z');
    Some((d, Profile::new(segs, None).ok()?))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Written as path data and read back, a profile has the same segments: same kinds, same
    /// points (to rounding of the printed numbers, which are exact, and of the arcs' centres).
    fn profiles_survive_a_round_trip_through_path_data(
        steps in proptest::collection::vec(0.5f64..1.5, 3..8),
        radii in proptest::collection::vec(1.0f64..20.0, 8),
        round in proptest::collection::vec(prop_oneof![Just(0.0), 0.2f64..1.0], 8),
        relative in proptest::collection::vec(any::<bool>(), 16),
        offset in (-1e4f64..1e4, -1e4f64..1e4),
    ) {
        let n = steps.len();
        let total: f64 = steps.iter().sum();
        let mut acc = 0.0;
        let v: Vec<V2> = (0..n).map(|i| {
            let a = TAU * acc / total;
            acc += steps[i];
            V2::new(offset.0, offset.1) + V2::polar(a) * radii[i]
        }).collect();
        let Some((d, want)) = path_data(&v, &round[..n], &relative) else {
            return Ok(());
        };
        let got = profile_of(&format!(r#"<path d="{d}"/>"#), None);
        prop_assert_eq!(got.segments().len(), want.segments().len(), "{}", d);
        let scale = radii.iter().fold(0.0f64, |m, &r| m.max(r)) + offset.0.abs().max(offset.1.abs());
        for (a, b) in got.segments().iter().zip(want.segments()) {
            prop_assert_eq!(a.kind(), b.kind());
            for k in 0..=8 {
                let x = k as f64 / 8.0;
                let (pa, pb) = (a.jet(x).p, b.jet(x).p);
                prop_assert!((pa - pb).norm() <= 1e-11 * scale, "{:?} against {:?} in {}", pa, pb, d);
            }
        }
        prop_assert_eq!(got.corners().count(), want.corners().count(), "{}", d);
        ROUND_TRIPS.add(1);
        if want.segments().iter().any(|s| s.kind() == SegmentKind::Arc) {
            WITH_ARCS.add(1);
        }
    }
}

static ROUND_TRIPS: Tally = Tally::new();
static WITH_ARCS: Tally = Tally::new();

/// Runs the round trip and checks it is not vacuous: most cases make a profile, most of them
/// with arcs.
#[test]
fn profiles_survive_a_round_trip_through_path_data_and_many() {
    profiles_survive_a_round_trip_through_path_data();
    let (n, arcs) = (ROUND_TRIPS.get(), WITH_ARCS.get());
    assert!(n >= 150 && arcs >= 100, "{n} round trips, {arcs} with arcs");
}

/// Found by fuzzing: a drawing moved 1e63 away (far beyond its size) made the self-crossing
/// test halve chords to its depth limit everywhere (the points round by more than the
/// flatness asked for). It now reads at once: the flatness never goes below the rounding of
/// the coordinates.
#[test]
fn drawings_far_from_the_origin_read_at_once() {
    let f = write_svg(
        r#"<g transform="matrix(8 0 0 -1 1e63 0)"><path d="M100 0V700H300Q430 700 490 610T5503 50Q550 180 490 90T300 0Z"/></g>"#,
    );
    // (The profile or a refusal: either is an answer.)
    let _ = read_curve_picked(f.path(), Some(0));
    let far = profile_of(
        r#"<path transform="translate(1e12 -3e12)" d="M 0 0 L 4 0 A 2 2 0 0 1 4 4 Q 2 6 0 4 Z"/>"#,
        None,
    );
    assert_eq!(far.segments().len(), 4);
}
