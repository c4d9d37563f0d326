//! One boundary model (issue 41, move 6): a smooth closed curve read as a profile of one
//! segment (an analytic shape, a periodic spline, a spline closed by its points without a
//! corner at its seam) is that curve. On every shipped curve
//! fixture, and on the variants where the two paths once parted (a circle's family, a stadium,
//! slender lemniscates, many convexities, a shape far from the origin), the commands on the
//! profile answer what they answer on the curve: the same pairs, families, inflections and
//! lines, the same verdicts, in the curve's parameters once mapped back through the
//! profile's document. And where the profile's own segment-by-segment path decides too, it
//! finds the same points (a second algorithm on the same segment).
#![allow(clippy::unwrap_used)]

use antipodal::{Antipodal, Options, Verdict};
use curve::{ParamCurve, Profile, Segment, SegmentKind, SplineCurve};
use curvekit::io::{curve_profile, parse_curve, Curve};
use numeric::rounding::ulps;

/// The curve fixtures (not profiles or regions), and the variants.
fn inputs() -> Vec<(String, String)> {
    let mut files: Vec<_> = std::fs::read_dir("fixtures")
        .unwrap()
        .chain(std::fs::read_dir("fixtures/singular").unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    let mut out: Vec<(String, String)> = files
        .iter()
        .map(|f| {
            let name = f.file_name().unwrap().to_string_lossy().to_string();
            (name, std::fs::read_to_string(f).unwrap())
        })
        .filter(|(_, text)| !text.contains("\"profile\"") && !text.contains("\"region"))
        .collect();
    let variants = [
        r#"{"kind":"convexities","p":4.5,"eps":0.2,"m":12}"#,
        r#"{"kind":"convexities","p":3,"eps":0.5,"m":24}"#,
        r#"{"kind":"elliptic_lemniscate","a":20,"b":1}"#,
        r#"{"kind":"elliptic_lemniscate","a":1,"b":100}"#,
        r#"{"kind":"ellipse","a":3,"b":2,"center":[1e8,-1e8]}"#,
        r#"{"kind":"circle","r":2.5,"center":[1e8,3]}"#,
        r#"{"kind":"limacon","a":4,"b":3.9}"#,
    ];
    out.extend(
        variants
            .iter()
            .enumerate()
            .map(|(k, v)| (format!("variant {k}"), v.to_string())),
    );
    out
}

/// The inputs read, each with its profile where that is one smooth closed curve: a shape, a
/// periodic spline, a spline closed by its points without a corner at its seam.
fn whole_curves() -> Vec<(String, Curve, Profile)> {
    let mut out = Vec::new();
    for (name, text) in inputs() {
        let Ok(curve) = parse_curve(&name, &text) else {
            continue;
        };
        let Some(Ok(profile)) = curve_profile(&curve) else {
            continue;
        };
        let only = &profile.segments()[0];
        let smooth_closed = profile.segments().len() == 1
            && profile.is_closed()
            && profile.corners().next().is_none();
        let spline = matches!(only.kind(), SegmentKind::Bezier | SegmentKind::BSpline);
        if smooth_closed && (only.whole_curve().is_some() || spline) {
            out.push((name, curve, profile));
        }
    }
    out
}

/// Parameters mapped back agree to rounding of the domain.
fn same_param(profile: &Profile, u: f64, want: f64, period: f64, what: &str) {
    let got = profile.document_param(u);
    // (A parameter on the seam may come back at either end.)
    let gap = (got - want).abs().min(period - (got - want).abs());
    assert!(gap <= 1e-12 * period, "{what}: {got} against {want}");
}

#[test]
fn the_profile_of_a_smooth_closed_curve_answers_as_the_curve() {
    let opts = Options::default();
    let found = whole_curves();
    // Every analytic fixture and every periodic spline fixture, and the variants.
    assert!(found.len() >= 25, "{}", found.len());
    for (name, curve, profile) in &found {
        assert!(
            profile.is_closed() && profile.corners().next().is_none(),
            "{name}"
        );
        let plane = curve.plane_curve();
        let (a, b) = plane.domain();
        let period = b - a;
        let on_curve = antipodal::antipodal(plane, &opts);
        let on_profile = antipodal::antipodal(profile, &opts);
        let (r, q): (Antipodal, Antipodal) = match (on_curve, on_profile) {
            (Ok(r), Ok(q)) => (r, q),
            (Err(e), Err(f)) => {
                assert_eq!(e.to_string(), f.to_string(), "{name}");
                continue;
            }
            (r, q) => panic!("{name}: {:?} against {:?}", r.err(), q.err()),
        };
        assert_eq!(r.doubts, q.doubts, "{name}");
        assert_eq!(r.complete, q.complete, "{name}");
        assert_eq!(q.corners, Some(Vec::new()), "{name}");
        assert_eq!(r.pairs.len(), q.pairs.len(), "{name}");
        for (x, y) in r.pairs.iter().zip(&q.pairs) {
            assert_eq!((x.p, x.q, x.distance), (y.p, y.q, y.distance), "{name}");
            assert_eq!(
                (x.kind, y.corner, y.segment),
                (y.kind, Some([false; 2]), Some([0; 2]))
            );
            same_param(profile, y.s, x.s, period, name);
            same_param(profile, y.t, x.t, period, name);
        }
        assert_eq!(r.families.len(), q.families.len(), "{name}");
        for (x, y) in r.families.iter().zip(&q.families) {
            for k in 0..2 {
                same_param(profile, y.s[k], x.s[k], period, name);
                same_param(profile, y.t[k], x.t[k], period, name);
                let ends = y.p.expect("a profile's family has its end points");
                assert_eq!(ends[k], plane.jet(x.s[k]).p.arr(), "{name}");
            }
        }
        let alone = antipodal::inflections(plane, &opts).unwrap();
        let on_profile = antipodal::inflections(profile, &opts).unwrap();
        assert_eq!(alone.doubts, on_profile.doubts, "{name}");
        for list in [&r.inflections, &q.inflections] {
            assert_eq!(alone.inflections.len(), list.len(), "{name}");
        }
        for (x, y) in alone.inflections.iter().zip(&on_profile.inflections) {
            assert_eq!((x.p, x.certified, x.kind), (y.p, y.certified, y.kind));
            assert_eq!(y.segment, Some(0), "{name}");
            same_param(profile, y.u, x.u, period, name);
            assert_eq!(x.bracket.is_some(), y.bracket.is_some(), "{name}");
            if let (Some([lo, hi]), Some([ylo, yhi])) = (x.bracket, y.bracket) {
                // (A bracket across the seam is given unwrapped, beyond the domain's end.)
                let unwrapped = |u: f64| {
                    let turns = u.floor();
                    profile.document_param(u - turns) + turns * period
                };
                for (got, want) in [(unwrapped(ylo), lo), (unwrapped(yhi), hi)] {
                    assert!((got - want).abs() <= 1e-12 * period, "{name}: {got} {want}");
                }
            }
        }
    }
}

#[test]
fn two_smooth_closed_curves_have_the_tangents_of_their_profiles() {
    let opts = Options::default();
    let found = whole_curves();
    let pick = |file: &str| found.iter().find(|(name, ..)| name == file).unwrap();
    for (first, second) in [
        ("ellipse.json", "limacon.json"),
        ("circle.json", "periodic_nurbs.json"),
        ("periodic_cubic.json", "periodic_cubic.json"),
    ] {
        let ((_, c1, p1), (_, c2, p2)) = (pick(first), pick(second));
        let (d1, d2) = (c1.plane_curve().domain(), c2.plane_curve().domain());
        let r = antipodal::common_tangents(c1.plane_curve(), c2.plane_curve(), &opts).unwrap();
        let q = antipodal::common_tangents(p1, p2, &opts).unwrap();
        assert_eq!(r.doubts, q.doubts, "{first} {second}");
        assert_eq!(r.lines.len(), q.lines.len(), "{first} {second}");
        assert!(!r.lines.is_empty());
        for (x, y) in r.lines.iter().zip(&q.lines) {
            assert_eq!(
                (x.p, x.q, y.corner, y.segment),
                (y.p, y.q, Some([false; 2]), Some([0; 2]))
            );
            same_param(p1, y.s, x.s, d1.1 - d1.0, first);
            same_param(p2, y.t, x.t, d2.1 - d2.0, second);
        }
    }
}

/// The profile's segment split in two at the middle of its exact form's domain: the same
/// curve, which the profile's segment-by-segment path runs (two segments, a smooth joint at
/// the cut and at the seam): an algorithm of its own, on the same points.
fn split_in_two(profile: &Profile) -> Profile {
    let form = profile.segments()[0].curve();
    let (a, b) = form.domain();
    let m = 0.5 * (a + b);
    let half = |lo: f64, hi: f64| {
        let piece = SplineCurve::new(form.curve().restrict(lo, hi).unwrap()).unwrap();
        Segment::spline(SegmentKind::BSpline, piece).unwrap()
    };
    Profile::new(vec![half(a, m), half(m, b)], None).unwrap()
}

#[test]
fn the_segment_path_finds_the_same_pairs() {
    let opts = Options::default();
    let found = whole_curves();
    // Where the curve's path knows more than the segments do: a circle's continuum is proven
    // by its definition (halves of its form are no arcs defined on one centre); a stretch of
    // vanishing curvature is proven straight on the data as given, or settled by the shape's
    // sampled run; a shape that loses precision on its exact form is sampled by the curve's
    // path. And a lemniscate a hundred times longer than wide is sampled on both paths, each
    // to its own accuracy (its nearly singular pairs 1e-6 apart).
    let curve_knows_more = [
        "antipodal-circle.json",
        "circle.json",
        "antipodal-stadium.json",
        "variant 1",
        "variant 3",
        "variant 5",
    ];
    let mut compared = 0;
    for (file, _, profile) in &found {
        if curve_knows_more.contains(&file.as_str()) {
            continue;
        }
        let whole = antipodal::antipodal(profile, &opts).unwrap();
        let other = antipodal::antipodal(&split_in_two(profile), &opts).unwrap();
        // (A slender lemniscate is sampled on both paths, each for its own reason.)
        assert_eq!(whole.certified(), other.certified(), "{file}");
        assert_eq!(whole.pairs.len(), other.pairs.len(), "{file}");
        assert!(!whole.pairs.is_empty(), "{file}");
        // (Far from the origin, two evaluations of one point agree to a few units of rounding
        // of its coordinates.)
        let magnitude = whole
            .pairs
            .iter()
            .flat_map(|x| [x.p, x.q])
            .flatten()
            .fold(0.0f64, |m, c| m.max(c.abs()));
        let room = 1e-9 * profile.scale() + ulps(8.0) * magnitude;
        for x in &whole.pairs {
            let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) <= room;
            assert!(
                other
                    .pairs
                    .iter()
                    .any(|y| (near(x.p, y.p) && near(x.q, y.q))
                        || (near(x.p, y.q) && near(x.q, y.p))),
                "{file}: {x:?}"
            );
        }
        compared += 1;
    }
    // (Each case left out was met.)
    assert_eq!(compared + curve_knows_more.len(), found.len());
}
