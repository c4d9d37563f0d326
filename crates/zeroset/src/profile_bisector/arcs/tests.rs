//! The tests of the parent module.

use super::*;
use crate::profile_bisector::closed_form_checks::{agrees_with_traced, check_vertices};
use curve::Segment;
use proptest::prelude::*;

/// A segment's curve and carrier.
fn arc(c: [f64; 2], r: f64, start: f64, sweep: f64) -> (Rational, Carrier) {
    let s = Segment::arc(c, r, start, start + sweep).expect("arc");
    (
        s.curve().curve().clone(),
        Carrier::Circle {
            center: c,
            radius: r,
        },
    )
}

fn line(a: [f64; 2], b: [f64; 2]) -> (Rational, Carrier) {
    let s = Segment::line(a, b).expect("line");
    (s.curve().curve().clone(), Carrier::Line)
}

fn pair_strategy() -> impl Strategy<Value = ((Rational, Carrier), (Rational, Carrier))> {
    let point = (-2.0f64..2.0, -2.0f64..2.0).prop_map(|(x, y)| [x, y]);
    let arc_s = (
        point.clone(),
        0.3f64..2.0,
        -3.2f64..3.2,
        0.3f64..6.0,
        any::<bool>(),
    )
        .prop_map(|(c, r, a, s, ccw)| arc(c, r, a, if ccw { s } else { -s }));
    let line_s = (point.clone(), point)
        .prop_filter("apart", |(a, b)| (a[0] - b[0]).hypot(a[1] - b[1]) > 0.2)
        .prop_map(|(a, b)| line(a, b));
    let first = prop_oneof![arc_s.clone(), line_s.clone()];
    (first, arc_s)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// On random pairs of an arc with a line or another arc (either first): every vertex
    /// is a bisector point, and the closed form and the traced zero set of the general
    /// bisector lie within the chord tolerance of each other.
    #[test]
    fn the_closed_form_is_the_traced_zero_set(
        ((c1, k1), (c2, k2)) in pair_strategy(),
        arc_first in any::<bool>(),
    ) {
        let ((c1, k1), (c2, k2)) = if arc_first { ((c2, k2), (c1, k1)) } else { ((c1, k1), (c2, k2)) };
        let chord = 1e-4;
        let reach = Reach { center: [0.0, 0.0], far: 20.0, chord, tol: 1e-12 };
        let closed = arc_bisector(&c1, k1, &c2, k2, &reach).expect("algebra").expect("applies");
        prop_assert!(closed.complete);
        check_vertices(&c1, &c2, &closed, |x| 1e-9 * (1.0 + x[0].hypot(x[1])))?;
        agrees_with_traced(&c1, &c2, &closed, chord, reach.far, 8.0)?;
    }
}
