//! The tests of the parent module.

use super::*;
use proptest::prelude::*;

/// A piece point is solved once per piece and angle (angles within rounding are one), and
/// a point on another piece or at another angle is solved anew.
#[test]
fn piece_points_are_solved_once_per_piece_and_angle() {
    let seed = [
        0.3, 0.9, 0.5, 0.7, 0.2, 0.8, 0.4, 0.6, 0.1, 0.95, 0.35, 0.75,
    ];
    let curve = crate::prepare::tests::star_curve(3, &seed, None);
    let prep = crate::prepare::tests::as_given(&curve);
    let v = View::new(prep.source(false), false, 1e-12).value;
    let solves = Cell::new(0);
    let ask = |piece: usize, rel: f64, answer: Option<f64>| {
        v.piece_point_memo(piece, rel, || {
            solves.set(solves.get() + 1);
            answer
        })
    };
    assert_eq!(ask(2, 0.25, Some(0.7)), Some(0.7));
    assert_eq!(ask(2, 0.25 + 1e-15, Some(9.0)), Some(0.7));
    assert_eq!(ask(2, 0.3, None), None);
    assert_eq!(ask(2, 0.3, Some(9.0)), None);
    assert_eq!(ask(0, 0.25, Some(0.8)), Some(0.8));
    assert_eq!(ask(2, 0.25 + 1e-9, Some(0.71)), Some(0.71));
    assert_eq!(solves.get(), 4);
}

proptest! {
    /// Jets asked for through the view (a few parameters again and again, in any order
    /// and to any order of derivatives, with many sharing a slot) are the curve's own.
    #[test]
    fn cached_jets_are_the_curves(
        picks in proptest::collection::vec((0usize..600, 0usize..=3), 1..400),
    ) {
        // (A spline's jet holds the derivatives up to the order asked for only.)
        let seed = [0.3, 0.9, 0.5, 0.7, 0.2, 0.8, 0.4, 0.6, 0.1, 0.95, 0.35, 0.75];
        let curve = crate::prepare::tests::star_curve(3, &seed, None);
        let prep = crate::prepare::tests::as_given(&curve);
        let v = View::new(prep.source(false), false, 1e-12).value;
        let (a, b) = curve.domain();
        for (k, order) in picks {
            let u = a + (b - a) * k as f64 / 600.0;
            let (got, want) = (v.jet_to(u, order), curve.jet_to(v.eval_param(u), order));
            prop_assert_eq!(got.p, want.p);
            if order >= 1 {
                prop_assert_eq!(got.d1, want.d1);
            }
            if order >= 2 {
                prop_assert_eq!(got.d2, want.d2);
            }
            if order >= 3 {
                prop_assert_eq!(got.d3, want.d3);
            }
        }
    }
}
