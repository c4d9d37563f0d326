//! The fixtures (the bracket, the plate) read as profiles, and the commands run on them.

use super::common::{curvekit_json, fixture};
use super::read_path;
use curve::{ParamCurve, SegmentKind};

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
