//! The axis as the tests trace it, and how far a point is off it.

use curve::Region;
use medial::{medial_axis, MedialAxis, MedialOptions};
use testkit::boundary_oracle::off_polylines;

/// The chord tolerance the axes judged are traced to (relative to the size).
pub(crate) const CHORD: f64 = 1e-3;

/// The options the tests trace axes with: the chord tolerance [`CHORD`], the others the
/// defaults.
pub(crate) fn traced_options() -> MedialOptions {
    MedialOptions {
        settings: testkit::settings(CHORD, None),
        ..MedialOptions::default()
    }
}

/// The axis of `region` as the tests trace it (with [`traced_options`]).
pub(crate) fn axis(region: &Region) -> MedialAxis {
    medial_axis(region, &traced_options()).unwrap()
}

/// The distance from `x` to the axis's edges (as polylines).
pub(crate) fn off_axis(a: &MedialAxis, x: [f64; 2]) -> f64 {
    off_polylines(x, a.edges.iter().map(|e| &e.xy[..]))
}
