//! Long work behaves (issue 39): a medial axis that takes seconds stops soon after its watch
//! is cancelled, with "cancelled" (never a partial axis), and reports its stage meanwhile.

#![allow(clippy::unwrap_used, missing_docs)]

use curve::watch::Watch;
use curve::Region;
use medial::{medial_axis, Error, MedialOptions};
use numeric::certificate::Verdict;
use std::sync::Arc;
use std::time::{Duration, Instant};

#[test]
fn a_cancelled_axis_stops_soon_and_says_so() {
    let region = testkit::outlines::rounded_outline(1500);
    let watch = Arc::new(Watch::default());
    let canceller = {
        let watch = Arc::clone(&watch);
        std::thread::spawn(move || {
            std::thread::sleep(Duration::from_millis(300));
            let stage = watch.progress().stage;
            watch.cancel();
            (Instant::now(), stage)
        })
    };
    let found = watch.run(|| medial_axis(&region, &MedialOptions::default()));
    let stopped = Instant::now();
    let (cancelled_at, stage) = canceller.join().unwrap();
    assert!(matches!(found, Err(Error::Cancelled)), "{found:?}");
    assert!(stage.starts_with("medial axis"), "{stage:?}");
    // (The target is 0.1 s; a loaded test machine is allowed more.)
    let late = stopped.saturating_duration_since(cancelled_at);
    assert!(
        late < Duration::from_secs(1),
        "stopped {late:?} after the cancel"
    );
    // The same work unwatched runs on (it is not cancelled by another's watch).
    assert!(!curve::watch::cancelled());
}

/// A watched axis large enough that its seed's diagram is built on a thread of its own
/// (the CAD outline of 5,000 lines) answers a cancel with "cancelled", the diagram's build
/// left to finish alone; unwatched, the same region's axis is certified.
#[test]
fn a_cancel_during_the_seed_diagram_is_answered() {
    let outline = testkit::outlines::polygon(&testkit::outlines::dense_outline(5000));
    let region = Region::new(outline, vec![]).unwrap();
    let watch = Arc::new(Watch::default());
    watch.cancel();
    let found = watch.run(|| medial_axis(&region, &MedialOptions::default()));
    assert!(matches!(found, Err(Error::Cancelled)), "{found:?}");
    assert_eq!(
        watch.progress().stage,
        "medial axis: the Voronoi diagram of the chords"
    );
    let axis = medial_axis(&region, &MedialOptions::default()).unwrap();
    assert!(axis.certified(), "{:?}", axis.reason());
}
