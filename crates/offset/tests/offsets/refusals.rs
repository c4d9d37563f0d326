//! What is refused or stopped: options out of range (by name), a malformed axis, a cancelled
//! watch.

use crate::helpers::pocket;
use medial::{medial_axis, MedialOptions};
use offset::{offsets, OffsetOptions};

/// The options are checked against what the algorithms deliver, by the tolerances' one
/// range, where the settings are made: a chord tolerance in [1e-9, 0.5] for the offsets, as
/// for the axis (whose size must also be a finite number above zero); out of it, an error
/// naming the field. Settings in range are taken.
#[test]
fn options_out_of_range_are_refused_by_name() {
    use numeric::tolerance::{Settings, DEFAULT_CHORD_TOL, DEFAULT_PARAM_TOL};
    let region = pocket();
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    for (chord_tol, ok) in [
        (1e-9, true),
        (0.5, true),
        (1e-10, false),
        (0.6, false),
        (f64::NAN, false),
    ] {
        match Settings::new(DEFAULT_PARAM_TOL, chord_tol, None) {
            Ok(settings) => {
                assert!(ok, "chord_tol {chord_tol} taken");
                let found = offsets(&region, &axis, &[0.5], &OffsetOptions { settings });
                assert!(found.is_ok(), "chord_tol {chord_tol}: {found:?}");
            }
            Err(e) => {
                assert!(!ok, "chord_tol {chord_tol} refused: {e}");
                assert!(e.to_string().contains("chord_tol"), "{e}");
            }
        }
    }
    for size in [0.0, -1.0, f64::INFINITY, f64::NAN] {
        let e = Settings::new(DEFAULT_PARAM_TOL, DEFAULT_CHORD_TOL, Some(size)).unwrap_err();
        assert!(e.to_string().contains("size"), "{e}");
    }
    let tiny = Settings::new(1e-16, DEFAULT_CHORD_TOL, None).unwrap_err();
    assert_eq!(tiny.field, "tol", "{tiny}");
    assert!(tiny.to_string().starts_with("tol: "), "{tiny}");
}

/// An axis that is not the region's is an error, not a panic: arrays of unequal lengths, a
/// number that is not finite, a boundary or a foot out of range.
#[test]
fn a_malformed_axis_is_an_error() {
    let region = pocket();
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    let opts = OffsetOptions::default();
    let breakages: [&dyn Fn(&mut medial::MedialAxis); 6] = [
        &|a| {
            a.edges[0].radius.pop();
        },
        &|a| a.edges[0].xy[0][0] = f64::NAN,
        &|a| a.edges[0].radius[0] = -1.0,
        &|a| a.edges[0].boundary[0][1] = 7,
        &|a| a.edges[0].feet[0][0] = 1e9,
        &|a| a.edges[0].to = 1000,
    ];
    for (k, breaks) in breakages.iter().enumerate() {
        let mut broken = axis.clone();
        breaks(&mut broken);
        let got = offsets(&region, &broken, &[0.5], &opts);
        assert!(
            matches!(got, Err(offset::Error::BadAxis(_))),
            "breakage {k}: {got:?}"
        );
    }
    assert!(offsets(&region, &axis, &[0.5], &opts).is_ok());
}

/// Offsets run under a cancelled watch stop with `Cancelled`, never a partial list; the same
/// call unwatched, or under a watch not cancelled, gives every offset.
#[test]
fn cancelled_offsets_say_so() {
    use curve::watch::Watch;
    use std::sync::Arc;
    let region = pocket();
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    let opts = OffsetOptions::default();
    let distances = [0.25, 0.5, 0.75];
    let watch = Arc::new(Watch::default());
    let found = watch.run(|| offsets(&region, &axis, &distances, &opts));
    assert_eq!(found.unwrap().offsets.len(), 3);
    assert_eq!(watch.progress().stage, "offsets: one distance each");
    watch.cancel();
    let found = watch.run(|| offsets(&region, &axis, &distances, &opts));
    assert!(matches!(found, Err(offset::Error::Cancelled)), "{found:?}");
    assert_eq!(
        offsets(&region, &axis, &distances, &opts)
            .unwrap()
            .offsets
            .len(),
        3
    );
}
