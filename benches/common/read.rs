//! Reading the benchmarks' region texts through the tool's reader (apart from `mod.rs`, which
//! the crates' tests share and which cannot reach the tool).

use curvekit::curve::Region;
use curvekit::io::{parse_region, CurveKind};

/// The region a benchmark's text holds.
pub(crate) fn region_of(text: &str) -> Region {
    match parse_region("bench", None, text.as_bytes(), None)
        .expect("a benchmark's region reads")
        .shape
    {
        CurveKind::Region(r) => *r,
        _ => unreachable!("a benchmark's text is a region"),
    }
}
