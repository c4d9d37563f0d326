//! Bad drawings: gaps within and beyond the tolerance, branch points, empty drawings, garbage
//! and truncated files, entities the dxf crate drops silently, entities left out, and
//! profiles ordered and named by their first entity.

use super::common::curvekit;
use super::splines::quarter_circle_text;
use super::{
    add, drawing, dxf_text, g, groups, line, line_with_a_malformed_last_group, p3, read, read_err,
    read_path, read_text, saved, temp_dxf,
};
use curve::ParamCurve;
use curvekit::io::read_curve_picked;
use dxf::entities::{Circle, Entity, EntityType};
use dxf::Drawing;

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
        groups(&[(1, "hello"), (10, "0"), (20, "0"), (40, "1")]),
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
        ("LINE", line_with_a_malformed_last_group()),
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
