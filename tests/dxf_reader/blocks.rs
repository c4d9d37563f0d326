//! Block references (`INSERT`) expanded with their transforms: a drawing with a block inserted
//! reads as the same drawing with the block's entities written out where the reference puts
//! them (exploded), for translations, rotations, uniform and non-uniform scales, mirrors,
//! MINSERT arrays and blocks nested two deep; and a reference that cannot be expanded (a
//! missing or external block, a cycle, nesting too deep, too much work) is skipped or refused
//! by name, without hanging.

use super::polylines::bulge_circle;
use super::written::{
    arc, block, circle, entity, exploded, file, lwpolyline, rectangle, Block, Placement, Prim,
    Written,
};
use super::{groups, line_with_a_malformed_last_group, temp_dxf};
use curve::{ParamCurve, Profile, Region, V2};
use curvekit::geometry::NearestPoint;
use curvekit::io::{read_region, CurveFileError, CurveKind, Skipped};
use proptest::prelude::*;
use std::f64::consts::{PI, TAU};
use std::time::{Duration, Instant};

fn v(x: f64, y: f64) -> V2 {
    V2::new(x, y)
}

/// The block's outlines in block coordinates, as written and as pieces: a half disc (a LINE
/// and an ARC chained), a CIRCLE, and a square with one side bulged out (an LWPOLYLINE).
fn content() -> (Vec<Written>, Vec<Prim>) {
    let square = [
        (v(6.0, 0.0), 0.0),
        (v(7.0, 0.0), 0.4),
        (v(7.0, 1.0), 0.0),
        (v(6.0, 1.0), 0.0),
    ];
    let written = vec![
        super::written::line(v(0.0, 0.0), v(2.0, 0.0)),
        arc(v(1.0, 0.0), 1.0, 0.0, 180.0),
        circle(v(4.0, 0.5), 0.5),
        lwpolyline(&square, true),
    ];
    let (c, r, _) = bulge_circle(square[1].0, square[2].0, 0.4);
    let a0 = (square[1].0 - c).angle();
    let prims = vec![
        Prim::Line(v(0.0, 0.0), v(2.0, 0.0)),
        Prim::Arc(v(1.0, 0.0), 1.0, 0.0, PI),
        Prim::Arc(v(4.0, 0.5), 0.5, 0.0, TAU),
        Prim::Line(square[0].0, square[1].0),
        Prim::Arc(c, r, a0, a0 + 4.0 * 0.4f64.atan()),
        Prim::Line(square[2].0, square[3].0),
        Prim::Line(square[3].0, square[0].0),
    ];
    (written, prims)
}

/// The plate every drawing here is cut from.
fn plate() -> Written {
    rectangle(v(-500.0, -500.0), v(500.0, 500.0))
}

/// A block `PART` of [`content`] (base point `base`) inserted by `outer`, directly or through
/// a block `GROUP` (base point `group_base`) holding one reference `inner` to it; and the same
/// drawing exploded.
fn inserted_and_exploded(
    outer: &Placement,
    inner: Option<&Placement>,
    base: V2,
    group_base: V2,
) -> (String, String) {
    let (written, prims) = content();
    let mut blocks = vec![Block {
        entities: written,
        ..block("PART", base, Vec::new())
    }];
    let (top, top_base) = match inner {
        Some(i) => {
            blocks.push(block("GROUP", group_base, vec![i.insert("PART")]));
            ("GROUP", group_base)
        }
        None => ("PART", base),
    };
    let inserted = file(None, &blocks, &[plate(), outer.insert(top)]);
    let mut entities = vec![plate()];
    for row in 0..outer.grid.1 {
        for column in 0..outer.grid.0 {
            let cell = outer.map(top_base, column, row);
            let map = match inner {
                Some(i) => cell.after(&i.map(base, 0, 0)),
                None => cell,
            };
            entities.extend(prims.iter().map(|&p| exploded(p, &map)));
        }
    }
    (inserted, file(None, &[], &entities))
}

fn region_of(text: &str) -> Result<(Region, Vec<Skipped>, Option<String>), CurveFileError> {
    let c = read_region(&temp_dxf(text.as_bytes()), None)?;
    let doubt = c.drawing_doubt();
    let skipped = c.drawing.map(|d| d.skipped).unwrap_or_default();
    match c.shape {
        CurveKind::Region(r) => Ok((*r, skipped, doubt)),
        other => panic!("not one region: {other:?}"),
    }
}

fn region(text: &str) -> Region {
    region_of(text).unwrap().0
}

/// Whether two boundaries are the same curve: as many segments and corners, and every
/// segment's points at eighths of its parameter within `tol` of the other (both ways).
fn same_boundary(a: &Profile, b: &Profile, tol: f64) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.segments().len(), b.segments().len());
    prop_assert_eq!(a.corners().count(), b.corners().count());
    for (x, y) in [(a, b), (b, a)] {
        for i in 0..x.segments().len() {
            for k in 0..8 {
                let p = x.jet(i as f64 + k as f64 / 8.0).p;
                let d = y.nearest(p.arr(), 0.0).distance;
                prop_assert!(d <= tol, "{:?} is {:e} from the other", p, d);
            }
        }
    }
    Ok(())
}

/// Whether two regions are the same: the same outer boundary, and each hole the same as the
/// other's hole nearest to its start.
fn same_region(a: &Region, b: &Region, tol: f64) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.holes().len(), b.holes().len());
    same_boundary(a.outer(), b.outer(), tol)?;
    for h in a.holes() {
        let at = h.start().arr();
        let other = b
            .holes()
            .iter()
            .min_by(|x, y| {
                x.nearest(at, 0.0)
                    .distance
                    .total_cmp(&y.nearest(at, 0.0).distance)
            })
            .unwrap();
        same_boundary(h, other, tol)?;
    }
    Ok(())
}

/// A placement: a move, a rotation (exact quarter turns among others), scales uniform or not
/// and of either sign, the object coordinates mirrored or not; a MINSERT grid when `grid`.
fn placement(grid: bool) -> impl Strategy<Value = Placement> {
    let cells = if grid { 1i32..=3 } else { 1i32..=1 };
    (
        (-5.0f64..5.0, -5.0f64..5.0),
        prop_oneof![Just(0.0), Just(90.0), Just(-180.0), 0.0f64..360.0],
        (0.5f64..2.0, proptest::option::of(0.5f64..2.0)),
        (any::<bool>(), any::<bool>(), any::<bool>()),
        (cells.clone(), cells, any::<bool>(), any::<bool>()),
    )
        .prop_map(
            |(at, degrees, (s, sy), (neg_x, neg_y, flipped), (c, r, neg_c, neg_r))| {
                let sign = |neg: bool| if neg { -1.0 } else { 1.0 };
                Placement {
                    at: v(at.0, at.1),
                    scale: (s * sign(neg_x), sy.unwrap_or(s) * sign(neg_y)),
                    degrees,
                    flipped,
                    grid: (c, r),
                    // (Far enough apart for the copies not to meet: each is within 60 of
                    // its insertion point.)
                    spacing: (130.0 * sign(neg_c), 130.0 * sign(neg_r)),
                }
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn a_block_inserted_reads_as_its_entities_exploded(
        outer in placement(true),
        inner in proptest::option::of(placement(false)),
        base in (-2.0f64..2.0, -2.0f64..2.0),
        group_base in (-2.0f64..2.0, -2.0f64..2.0),
    ) {
        let (inserted, exploded) = inserted_and_exploded(
            &outer,
            inner.as_ref(),
            v(base.0, base.1),
            v(group_base.0, group_base.1),
        );
        let (a, skipped, doubt) = region_of(&inserted)
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(skipped.is_empty(), "{:?}", skipped);
        prop_assert_eq!(doubt, None);
        let b = region(&exploded);
        let cells = (outer.grid.0 * outer.grid.1) as usize;
        prop_assert_eq!(a.holes().len(), 3 * cells);
        same_region(&a, &b, 1e-9 * 1000.0)?;
    }
}

#[test]
fn each_kind_of_placement_reads_as_exploded() {
    // The cases the property samples, each once: a move, a quarter turn, a uniform scale, a
    // mirror (negative x scale), a non-uniform scale, the object coordinates mirrored, a
    // MINSERT grid rotated, and a block nested in a block placed non-uniformly after a turn.
    let at = Placement::at(v(3.0, -2.0));
    let cases = [
        (at, None),
        (
            Placement {
                degrees: 90.0,
                ..at
            },
            None,
        ),
        (
            Placement {
                scale: (1.5, 1.5),
                degrees: 30.0,
                ..at
            },
            None,
        ),
        (
            Placement {
                scale: (-1.0, 1.0),
                ..at
            },
            None,
        ),
        (
            Placement {
                scale: (2.0, 0.5),
                degrees: 30.0,
                ..at
            },
            None,
        ),
        (
            Placement {
                flipped: true,
                degrees: 45.0,
                ..at
            },
            None,
        ),
        (
            Placement {
                grid: (3, 2),
                spacing: (130.0, -130.0),
                degrees: 15.0,
                ..at
            },
            None,
        ),
        (
            Placement {
                scale: (2.0, 0.7),
                ..at
            },
            Some(Placement {
                degrees: 40.0,
                scale: (1.0, -1.0),
                ..at
            }),
        ),
    ];
    for (outer, inner) in cases {
        let (inserted, exploded) =
            inserted_and_exploded(&outer, inner.as_ref(), v(0.5, -1.0), v(-1.0, 2.0));
        let a = region(&inserted);
        let b = region(&exploded);
        let cells = (outer.grid.0 * outer.grid.1) as usize;
        assert_eq!(a.holes().len(), 3 * cells, "{outer:?}");
        same_region(&a, &b, 1e-9).unwrap_or_else(|e| panic!("{outer:?}, {inner:?}: {e}"));
    }
}

/// A plate with `entities` and `blocks`; its region, what was skipped and the doubt.
fn plate_with(
    blocks: &[Block],
    entities: Vec<Written>,
) -> Result<(Region, Vec<Skipped>, Option<String>), CurveFileError> {
    let plate = rectangle(v(-10.0, -10.0), v(100.0, 10.0));
    let all: Vec<Written> = std::iter::once(plate).chain(entities).collect();
    region_of(&file(None, blocks, &all))
}

fn skipped_count(skipped: &[Skipped], kind: &str) -> usize {
    skipped
        .iter()
        .find(|s| s.kind == kind)
        .map_or(0, |s| s.count)
}

/// Asserts that `count` INSERTs were skipped, and that the doubt they leave names each of
/// `words`.
fn assert_inserts_skipped(
    skipped: &[Skipped],
    doubt: Option<String>,
    count: usize,
    words: &[&str],
) {
    assert_eq!(skipped_count(skipped, "INSERT"), count, "{skipped:?}");
    let doubt = doubt.expect("a skipped INSERT leaves a doubt");
    for word in words {
        assert!(doubt.contains(word), "{word:?} is not in: {doubt}");
    }
}

/// Runs `f` on a thread of its own and fails if it takes more than `limit`.
fn within<T: Send + 'static>(limit: Duration, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(limit)
        .unwrap_or_else(|_| panic!("still running after {limit:?}"))
}

#[test]
fn an_expanded_entity_is_named_by_its_path() {
    let bad = circle(v(0.0, 0.0), -1.0).handle("3F");
    let blocks = [block("PART", v(0.0, 0.0), vec![bad])];
    let e = plate_with(
        &blocks,
        vec![Placement::at(v(5.0, 0.0)).insert("PART").handle("2A")],
    )
    .unwrap_err();
    assert_eq!(e.field, "INSERT 2A > CIRCLE 3F radius", "{e}");
    // Two deep, in a MINSERT's second column.
    let blocks = [
        block(
            "PART",
            v(0.0, 0.0),
            vec![circle(v(0.0, 0.0), -1.0).handle("3F")],
        ),
        block(
            "GROUP",
            v(0.0, 0.0),
            vec![Placement::at(v(0.0, 0.0)).insert("PART").handle("4B")],
        ),
    ];
    let grid = Placement {
        grid: (2, 1),
        spacing: (20.0, 0.0),
        ..Placement::at(v(5.0, 0.0))
    };
    let e = plate_with(&blocks, vec![grid.insert("GROUP").handle("2A")]).unwrap_err();
    assert_eq!(
        e.field, "INSERT 2A (row 0, column 0) > INSERT 4B > CIRCLE 3F radius",
        "{e}"
    );
}

#[test]
fn blocks_never_inserted_are_not_drawn_and_anonymous_ones_inserted_are() {
    let blocks = [
        block("UNUSED", v(0.0, 0.0), vec![circle(v(50.0, 0.0), 1.0)]),
        Block {
            flags: 1,
            ..block("*U7", v(0.0, 0.0), vec![circle(v(20.0, 0.0), 1.0)])
        },
    ];
    let (r, skipped, doubt) =
        plate_with(&blocks, vec![Placement::at(v(0.0, 0.0)).insert("*U7")]).unwrap();
    assert_eq!(r.holes().len(), 1);
    let hole = r.holes()[0].start();
    assert!((hole - v(21.0, 0.0)).norm() < 1e-12, "{hole:?}");
    assert!(skipped.is_empty() && doubt.is_none(), "{skipped:?}");
    // Block names are case-insensitive, as in CAD programs.
    let (r, _, _) = plate_with(&blocks, vec![Placement::at(v(0.0, 0.0)).insert("*u7")]).unwrap();
    assert_eq!(r.holes().len(), 1);
}

#[test]
fn a_reference_to_a_missing_or_external_block_is_skipped_and_uncertified() {
    let inserts = vec![
        circle(v(50.0, 0.0), 1.0),
        Placement::at(v(0.0, 0.0)).insert("NOPE").handle("2A"),
    ];
    let (r, skipped, doubt) = plate_with(&[], inserts).unwrap();
    assert_eq!(r.holes().len(), 1);
    assert_inserts_skipped(&skipped, doubt, 1, &["INSERT 2A", "NOPE"]);
    // An external reference (XREF, flag 4): its drawing is another file.
    let xref = Block {
        flags: 4,
        ..block("OTHER", v(0.0, 0.0), Vec::new())
    };
    let (_, skipped, doubt) = plate_with(
        &[xref],
        vec![Placement::at(v(0.0, 0.0)).insert("OTHER").handle("2B")],
    )
    .unwrap();
    assert_inserts_skipped(&skipped, doubt, 1, &["INSERT 2B", "external"]);
    // Out of the drawing's plane (a tilted extrusion direction).
    let tilted = Placement::at(v(0.0, 0.0))
        .insert("PART")
        .handle("2C")
        .with(&[(210, "0.0"), (220, "0.6"), (230, "0.8")]);
    let part = block("PART", v(0.0, 0.0), vec![circle(v(20.0, 0.0), 1.0)]);
    let (r, skipped, doubt) = plate_with(&[part], vec![tilted]).unwrap();
    assert_eq!(r.holes().len(), 0);
    assert_inserts_skipped(&skipped, doubt, 1, &["INSERT 2C"]);
}

#[test]
fn blocks_inserted_inside_themselves_are_skipped_by_name_without_hanging() {
    // A holds a circle and a reference to itself; B and C refer to each other.
    // (name, the circle's x, the block referred to, the reference's handle.)
    let blocks: Vec<Block> = [
        ("A", 20.0, "A", "3A"),
        ("B", 40.0, "C", "3B"),
        ("C", 40.0, "B", "3C"),
    ]
    .into_iter()
    .map(|(name, x, to, handle)| {
        let reference = Placement::at(v(5.0, 0.0)).insert(to).handle(handle);
        block(name, v(0.0, 0.0), vec![circle(v(x, 0.0), 1.0), reference])
    })
    .collect();
    let (r, skipped, doubt) = within(Duration::from_secs(20), move || {
        plate_with(
            &blocks,
            vec![
                Placement::at(v(0.0, 0.0)).insert("A").handle("2A"),
                Placement::at(v(0.0, 0.0)).insert("B").handle("2B"),
            ],
        )
    })
    .unwrap();
    // A's circle once, B's and C's once each.
    assert_eq!(r.holes().len(), 3);
    assert_inserts_skipped(
        &skipped,
        doubt,
        2,
        &["INSERT 2A > INSERT 3A", "inside itself"],
    );
}

#[test]
fn nesting_deeper_than_the_bound_is_skipped_by_name() {
    // B1 … B20, each with a circle and a reference to the next.
    let blocks: Vec<Block> = (1..=20)
        .map(|k| {
            let mut e = vec![circle(v(4.0 * k as f64, 0.0), 1.0)];
            if k < 20 {
                e.push(
                    Placement::at(v(0.0, 0.0))
                        .insert(&format!("B{}", k + 1))
                        .handle(&format!("{:X}", 0x100 + k)),
                );
            }
            block(&format!("B{k}"), v(0.0, 0.0), e)
        })
        .collect();
    let (r, skipped, doubt) = within(Duration::from_secs(20), move || {
        plate_with(&blocks, vec![Placement::at(v(0.0, 0.0)).insert("B1")])
    })
    .unwrap();
    // Blocks 1 to 16 drawn; the reference to block 17, the 17th level, skipped.
    assert_eq!(r.holes().len(), 16);
    assert_inserts_skipped(&skipped, doubt, 1, &["INSERT 110", "16"]);
}

#[test]
fn an_expansion_past_the_bound_on_work_is_refused_quickly() {
    // Ten references to the block below, eight levels: 10^8 circles.
    let mut blocks = vec![block("L0", v(0.0, 0.0), vec![circle(v(0.0, 0.0), 0.1)])];
    for k in 1..=8 {
        let refs = (0..10)
            .map(|i| Placement::at(v(0.0, i as f64)).insert(&format!("L{}", k - 1)))
            .collect();
        blocks.push(block(&format!("L{k}"), v(0.0, 0.0), refs));
    }
    let start = Instant::now();
    let e = within(Duration::from_secs(30), move || {
        plate_with(
            &blocks,
            vec![Placement::at(v(0.0, 0.0)).insert("L8").handle("2A")],
        )
    })
    .unwrap_err();
    assert!(e.field.starts_with("INSERT 2A"), "{e}");
    assert!(e.to_string().contains("at most"), "{e}");
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "{:?}",
        start.elapsed()
    );
    // A MINSERT of 32767 × 32767 cells: refused as quickly.
    let big = Placement {
        grid: (32767, 32767),
        spacing: (1.0, 1.0),
        ..Placement::at(v(0.0, 0.0))
    };
    let part = block("P", v(0.0, 0.0), vec![circle(v(0.0, 0.0), 0.1)]);
    let e = within(Duration::from_secs(30), move || {
        plate_with(&[part], vec![big.insert("P").handle("2B")])
    })
    .unwrap_err();
    assert!(e.field.starts_with("INSERT 2B"), "{e}");
}

#[test]
fn attributes_are_text_and_cells_at_one_place_are_drawn_once() {
    let attdef = entity(
        "ATTDEF",
        groups(&[
            (10, "0"),
            (20, "0"),
            (40, "1"),
            (1, ""),
            (3, "Part number?"),
            (2, "PN"),
        ]),
    );
    let part = block("TAG", v(0.0, 0.0), vec![attdef, circle(v(20.0, 0.0), 1.0)]);
    let attrib = entity(
        "ATTRIB",
        groups(&[(10, "0"), (20, "0"), (40, "1"), (1, "A-113"), (2, "PN")]),
    );
    let insert = Placement::at(v(0.0, 0.0)).insert("TAG").with(&[(66, "1")]);
    let (r, skipped, doubt) = plate_with(
        std::slice::from_ref(&part),
        vec![insert, attrib, entity("SEQEND", Vec::new())],
    )
    .unwrap();
    assert_eq!(r.holes().len(), 1);
    assert_eq!(skipped_count(&skipped, "ATTDEF"), 1);
    assert_eq!(skipped_count(&skipped, "ATTRIB"), 1);
    assert_eq!(skipped.len(), 2, "{skipped:?}");
    assert_eq!(doubt, None, "text is not an outline");
    // A MINSERT whose spacing is 0: its cells coincide, drawn once (as CAD programs show it).
    let stacked = Placement {
        grid: (3, 3),
        spacing: (0.0, 0.0),
        ..Placement::at(v(0.0, 0.0))
    };
    let (r, _, _) = plate_with(&[part], vec![stacked.insert("TAG")]).unwrap();
    assert_eq!(r.holes().len(), 1);
}

#[test]
fn references_that_place_nothing_or_name_two_blocks_are_skipped() {
    let part = || block("PART", v(0.0, 0.0), vec![circle(v(20.0, 0.0), 1.0)]);
    // A scale of 0 collapses the block; an array of no columns has no cell.
    let flat = Placement {
        scale: (0.0, 1.0),
        ..Placement::at(v(0.0, 0.0))
    };
    let empty = Placement::at(v(0.0, 0.0))
        .insert("PART")
        .handle("2E")
        .with(&[(70, "0"), (44, "5.0")]);
    for (insert, h, why) in [
        (flat.insert("PART").handle("2D"), "2D", "collapses"),
        (empty, "2E", "no cell"),
    ] {
        let (r, skipped, doubt) = plate_with(&[part()], vec![insert]).unwrap();
        assert_eq!(r.holes().len(), 0);
        assert_inserts_skipped(&skipped, doubt, 1, &[&format!("INSERT {h}"), why]);
    }
    // Two blocks of one name (names are compared without case): which one is meant is unknown.
    let other = block("part", v(0.0, 0.0), vec![circle(v(40.0, 0.0), 1.0)]);
    let (_, skipped, doubt) = plate_with(
        &[part(), other],
        vec![Placement::at(v(0.0, 0.0)).insert("PART")],
    )
    .unwrap();
    assert_inserts_skipped(&skipped, doubt, 1, &["twice"]);
}

#[test]
fn a_block_the_crate_cannot_read_refuses_only_a_drawing_that_inserts_it() {
    // The LINE's last group is malformed: the dxf crate drops it without a word.
    let broken = entity("LINE", line_with_a_malformed_last_group());
    let blocks = [
        block("BROKEN", v(0.0, 0.0), vec![broken]),
        block("PART", v(0.0, 0.0), vec![circle(v(20.0, 0.0), 1.0)]),
    ];
    let e = plate_with(
        &blocks,
        vec![Placement::at(v(0.0, 0.0)).insert("BROKEN").handle("2A")],
    )
    .unwrap_err();
    assert_eq!(e.field, "INSERT 2A > LINE #1", "{e}");
    // Never inserted, it is not drawn: the rest reads.
    let (r, _, doubt) =
        plate_with(&blocks, vec![Placement::at(v(0.0, 0.0)).insert("PART")]).unwrap();
    assert_eq!(r.holes().len(), 1);
    assert_eq!(doubt, None);
    // A BLOCKS section the crate cannot parse at all (an entity outside any block): refused
    // where a reference needs it, named.
    let text = file(None, &[], &[rectangle(v(-10.0, -10.0), v(100.0, 10.0))]).replace(
        "  0\nSECTION\n  2\nENTITIES\n",
        "  0\nSECTION\n  2\nBLOCKS\n  0\nLINE\n  0\nENDSEC\n  0\nSECTION\n  2\nENTITIES\n  0\nINSERT\n  5\n2B\n  2\nPART\n",
    );
    let e = region_of(&text).unwrap_err();
    assert_eq!(e.field, "INSERT 2B", "{e}");
    assert!(e.to_string().contains("BLOCKS section"), "{e}");
}
