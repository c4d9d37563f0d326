//! What curvekit writes for other programs (DXF, SVG paths), read back by curvekit's own
//! readers and by the `dxf` crate: the same geometry within 1e-9 of the size, judged on the
//! exact curves (points of one set on the curves of the other, each measured by its nearest
//! point), piece for piece in DXF.
#![allow(clippy::unwrap_used)]

mod common;

use common::fixture;
use curvekit::commands::{self, Distances};
use curvekit::curve::{ParamCurve, Profile, SegmentKind};
use curvekit::export::{dxf_file, svg_paths};
use curvekit::geometry::NearestPoint;
use curvekit::io::{parse_drawing, parse_region, read_region, Curve, DrawingFormat};
use curvekit::medial::{MedialOptions, NodeKind};
use curvekit::offset::{OffsetOptions, OffsetSegment, Offsets};

/// The round trip's bound, relative to the size (the contract's).
const ROUND_TRIP: f64 = 1e-9;

/// How far apart two evaluations of one curve at neighbouring parameters may come out, in
/// units of the coordinates' magnitude: each rounds by a few units (a drawing placed far from
/// the origin is measured to its coordinates' rounding, not to its size's).
const EVALUATION_ROUNDING: f64 = curvekit::numeric::rounding::ulps(4.0);

/// Points sampled per piece of a profile when measuring how far two profiles are apart.
const SAMPLES_PER_PIECE: usize = 16;

/// The inputs: lines, arcs and a whole circle (the pocket), quadratic splines (a glyph, whose
/// offsets are fitted cubics), cubic Béziers with corners (an icon).
const INPUTS: [&str; 3] = [
    "drawing-pocket.svg",
    "corpus/glyphs/roboto/0061-a.svg",
    "corpus/icons/heroicons-solid/light-bulb.svg",
];

fn input(name: &str) -> Curve {
    read_region(std::path::Path::new(&fixture(name)), None).unwrap()
}

fn offsets_of(region: &Curve, distances: &[f64]) -> Offsets {
    commands::offset(
        region,
        &Distances::List(distances.to_vec()),
        &OffsetOptions::default(),
        &MedialOptions::default(),
    )
    .unwrap()
}

/// The farthest point of `a` (sampled on its exact pieces) from `b`.
fn farthest_from(a: &Profile, b: &Profile) -> f64 {
    let (u0, u1) = a.domain();
    let n = SAMPLES_PER_PIECE * a.segments().len();
    (0..=n)
        .map(|k| {
            let p = a.jet_to(u0 + (u1 - u0) * k as f64 / n as f64, 0).p;
            b.nearest([p.x, p.y], 0.0).distance
        })
        .fold(0.0, f64::max)
}

/// The largest coordinate of a profile's control points.
fn magnitude(p: &Profile) -> f64 {
    p.segments()
        .iter()
        .flat_map(|s| s.curve().control_points())
        .fold(0.0f64, |m, c| m.max(c[0].abs()).max(c[1].abs()))
}

/// Every boundary of the regions read back, as profiles.
fn boundaries(back: &Curve) -> Vec<Profile> {
    back.parts()
        .into_iter()
        .flat_map(|r| std::iter::once(r.outer()).chain(r.holes()).cloned())
        .collect()
}

/// Each loop of `written` matches one profile of `back` (the same count), both ways within
/// the round trip's bound; with `piecewise`, with the same pieces (kinds in order from some
/// start, either way round).
fn assert_same_loops(
    written: &[Profile],
    back: &[Profile],
    size: f64,
    piecewise: bool,
    what: &str,
) {
    assert_eq!(
        written.len(),
        back.len(),
        "{what}: loops written and read back"
    );
    for w in written {
        let (gap, twin) = back
            .iter()
            .map(|b| (farthest_from(w, b).max(farthest_from(b, w)), b))
            .min_by(|x, y| x.0.total_cmp(&y.0))
            .unwrap();
        assert!(
            gap <= ROUND_TRIP * size,
            "{what}: a loop read back {gap:e} away (size {size})"
        );
        if piecewise {
            let kinds = |p: &Profile| -> Vec<SegmentKind> {
                p.segments().iter().map(|s| s.kind()).collect()
            };
            let (a, mut b) = (kinds(w), kinds(twin));
            let same = |a: &[SegmentKind], b: &[SegmentKind]| {
                (0..b.len().max(1)).any(|k| {
                    let mut r = b.to_vec();
                    r.rotate_left(k);
                    r == a
                })
            };
            let forward = same(&a, &b);
            b.reverse();
            assert!(
                forward || same(&a, &b),
                "{what}: pieces {a:?} read back as {b:?}"
            );
        }
    }
}

/// The offsets at one distance, as DXF, read back piece for piece; as SVG paths, read back
/// as the same curves.
#[test]
fn offsets_read_back_as_written() {
    for name in INPUTS {
        let region = input(name);
        let size = commands::size_of(&region);
        for fraction in [0.02, 0.1] {
            let d = fraction * size;
            let found = offsets_of(&region, &[d]);
            let written: Vec<Profile> = found.offsets[0]
                .loops
                .iter()
                .map(|l| l.profile().unwrap())
                .collect();
            assert!(!written.is_empty(), "{name} at {d}");
            let what = format!("{name} offset {d} (dxf)");
            let dxf = dxf_file::offsets_dxf(&found, region.units()).unwrap();
            let back = parse_region("back.dxf", Some(DrawingFormat::Dxf), &dxf, None).unwrap();
            assert_same_loops(&written, &boundaries(&back), size, true, &what);
            let what = format!("{name} offset {d} (svg)");
            let svg = svg_paths::offsets_svg(&found, region.units()).unwrap();
            let back =
                parse_region("back.svg", Some(DrawingFormat::Svg), svg.as_bytes(), None).unwrap();
            assert_same_loops(&written, &boundaries(&back), size, false, &what);
        }
    }
}

/// Several distances in one DXF: a layer each, named by the distance, holding its loops'
/// pieces; lines and splines as written, arcs counterclockwise (clockwise ones turned round).
#[test]
fn each_distance_is_a_layer_of_its_pieces() {
    let region = input("corpus/glyphs/roboto/0061-a.svg");
    let size = commands::size_of(&region);
    let found = offsets_of(&region, &[0.01 * size, 0.03 * size, 0.05 * size]);
    let dxf = dxf_file::offsets_dxf(&found, Some("mm")).unwrap();
    let drawing = dxf::Drawing::load(&mut dxf.as_slice()).unwrap();
    assert_eq!(
        drawing.header.default_drawing_units,
        dxf::enums::Units::Millimeters
    );
    for o in &found.offsets {
        let layer = format!("offset_{}", o.distance);
        assert!(drawing.layers().any(|l| l.name == layer), "{layer}");
        let on_layer: Vec<_> = drawing
            .entities()
            .filter(|e| e.common.layer == layer)
            .collect();
        // (Arcs that sweep nothing are not written.)
        let pieces: Vec<&OffsetSegment> = o
            .loops
            .iter()
            .flat_map(|l| &l.segments)
            .filter(|s| {
                !matches!(s, OffsetSegment::Arc { start, end, .. }
                    if (end - start).abs() <= curvekit::export::NO_SWEEP)
            })
            .collect();
        assert_eq!(on_layer.len(), pieces.len(), "{layer}");
        for (e, s) in on_layer.iter().zip(&pieces) {
            match (&e.specific, s) {
                (dxf::entities::EntityType::Line(l), OffsetSegment::Line { from, to }) => {
                    assert_eq!(
                        [l.p1.x, l.p1.y, l.p2.x, l.p2.y],
                        [from[0], from[1], to[0], to[1]].map(|v| (v * 1e12).round() / 1e12)
                    );
                }
                (dxf::entities::EntityType::Arc(a), OffsetSegment::Arc { r, start, end, .. }) => {
                    assert!(a.end_angle != a.start_angle);
                    let sweep = (a.end_angle - a.start_angle).rem_euclid(360.0);
                    testkit::assert_near!(sweep, (end - start).abs().to_degrees(), 1e-9);
                    testkit::assert_near!(a.radius, r, 1e-12);
                }
                (dxf::entities::EntityType::Circle(_), OffsetSegment::Arc { .. }) => {}
                (
                    dxf::entities::EntityType::Spline(sp),
                    OffsetSegment::BSpline {
                        degree,
                        knots,
                        points,
                    },
                ) => {
                    assert_eq!(sp.degree_of_curve as usize, *degree);
                    assert_eq!(sp.knot_values.len(), knots.len());
                    assert_eq!(sp.control_points.len(), points.len());
                    for (p, q) in sp.control_points.iter().zip(points) {
                        assert!((p.x - q[0]).abs() <= 1e-12 && (p.y - q[1]).abs() <= 1e-12);
                    }
                }
                (e, s) => panic!("{layer}: {s:?} written as {e:?}"),
            }
        }
    }
}

/// The medial axis: as DXF, an edge a spline (fitted) or a polyline with the edge's vertices,
/// a node a point on its kind's layer; as SVG paths, each edge read back as an open profile
/// through the same vertices.
#[test]
fn medial_axes_read_back_as_written() {
    let region = input("drawing-pocket.svg");
    let size = commands::size_of(&region);
    for fit in [false, true] {
        let axis = commands::medial(
            &region,
            &MedialOptions {
                fit,
                ..MedialOptions::default()
            },
        )
        .unwrap();
        let dxf = dxf_file::medial_dxf(&axis, None).unwrap();
        let drawing = dxf::Drawing::load(&mut dxf.as_slice()).unwrap();
        let edges: Vec<_> = drawing
            .entities()
            .filter(|e| e.common.layer == dxf_file::MEDIAL_EDGES)
            .collect();
        assert_eq!(edges.len(), axis.edges.len());
        for (e, edge) in edges.iter().zip(&axis.edges) {
            match &e.specific {
                dxf::entities::EntityType::Polyline(p) => {
                    assert!(!fit);
                    let xy: Vec<[f64; 2]> =
                        p.vertices().map(|v| [v.location.x, v.location.y]).collect();
                    assert_eq!(xy.len(), edge.xy.len());
                    for (a, b) in xy.iter().zip(&edge.xy) {
                        assert!((a[0] - b[0]).abs().max((a[1] - b[1]).abs()) <= 1e-12);
                    }
                }
                dxf::entities::EntityType::Spline(s) => {
                    let b = edge.bspline.as_ref().unwrap();
                    assert_eq!(s.control_points.len(), b.points.len());
                    assert_eq!(
                        s.knot_values,
                        b.knots
                            .iter()
                            .map(|k| (k * 1e12).round() / 1e12)
                            .collect::<Vec<_>>()
                    );
                }
                other => panic!("an edge written as {other:?}"),
            }
        }
        for kind in [
            NodeKind::Junction,
            NodeKind::End,
            NodeKind::Corner,
            NodeKind::Joint,
        ] {
            let layer = dxf_file::node_layer(kind);
            let points = drawing
                .entities()
                .filter(|e| e.common.layer == layer)
                .count();
            let nodes = axis.nodes.iter().filter(|n| n.kind == kind).count();
            assert_eq!(points, nodes, "{layer}");
        }
        let svg = svg_paths::medial_svg(&axis, None).unwrap();
        for (k, edge) in axis.edges.iter().enumerate() {
            let back =
                parse_drawing("back.svg", DrawingFormat::Svg, svg.as_bytes(), Some(k)).unwrap();
            let curvekit::io::CurveKind::Profile(p) = back.shape else {
                panic!("edge {k} read back as {:?}", back.shape);
            };
            let (u0, u1) = p.domain();
            let ends = [p.jet_to(u0, 0).p, p.jet_to(u1, 0).p];
            let first = edge.xy[0];
            let last = edge.xy[edge.xy.len() - 1];
            assert!(
                (ends[0].x - first[0])
                    .abs()
                    .max((ends[0].y - first[1]).abs())
                    <= ROUND_TRIP * size
            );
            assert!(
                (ends[1].x - last[0]).abs().max((ends[1].y - last[1]).abs()) <= ROUND_TRIP * size
            );
            if !fit {
                assert_eq!(p.segments().len(), edge.xy.len() - 1, "edge {k}");
            }
        }
    }
}

/// A drawing written back as the contract's document (`region`, `regions`) reads as the same
/// region: every boundary, segment for segment, within 1e-12 of the size.
#[test]
fn drawings_read_back_from_their_documents() {
    let mut read = 0;
    for dir in ["corpus/glyphs", "corpus/icons", "corpus/dxf"] {
        let root = std::path::PathBuf::from(fixture(dir));
        let mut files: Vec<_> = walk(&root);
        files.sort();
        for path in files {
            let Ok(region) = read_region(&path, None) else {
                continue;
            };
            let doc = curvekit::io::shape_document(&region.shape).unwrap();
            let back =
                curvekit::io::parse_region("back.json", None, doc.to_string().as_bytes(), None)
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            let size = commands::size_of(&region);
            let (a, b) = (boundaries(&region), boundaries(&back));
            for (x, y) in a.iter().zip(&b) {
                assert_eq!(x.segments().len(), y.segments().len(), "{}", path.display());
                let gap = farthest_from(x, y).max(farthest_from(y, x));
                let bound = 1e-12 * size + EVALUATION_ROUNDING * magnitude(x);
                assert!(gap <= bound, "{}: {gap:e}", path.display());
            }
            assert_eq!(a.len(), b.len());
            read += 1;
        }
    }
    assert!(read >= 40, "only {read} drawings read as regions");
}

/// The files under `dir`, every level down.
fn walk(dir: &std::path::Path) -> Vec<std::path::PathBuf> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            found.extend(walk(&path));
        } else if matches!(
            path.extension().and_then(|e| e.to_str()),
            Some("svg" | "dxf")
        ) {
            found.push(path);
        }
    }
    found
}
