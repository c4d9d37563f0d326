//! Arbitrary input to the public constructors and operations returns a value or a typed error,
//! never a panic or a hang.
#![allow(clippy::unwrap_used)]

use bspline::roots::{find_roots, RootOptions};
use bspline::{knots::KnotVector, BSpline, Error, Rational};
use proptest::prelude::*;

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        -10.0f64..10.0,
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(1e308),
        Just(-1e-308),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn constructors_never_panic(
        degree in 0usize..6,
        dim in 0usize..4,
        knots in prop::collection::vec(wild(), 0..16),
        coefs in prop::collection::vec(wild(), 0..24),
        weights in prop::collection::vec(wild(), 0..10),
        u in wild(),
    ) {
        let _ = KnotVector::new(degree, knots.clone());
        let _ = BSpline::clamped_uniform(degree, dim, coefs.clone());
        let _ = BSpline::periodic(degree, dim, coefs.clone());
        let _ = BSpline::bezier(dim, coefs.clone());
        if let Ok(f) = BSpline::new(degree, knots, dim, coefs) {
            // Whatever was accepted is a usable spline.
            let _ = f.eval(u);
            let _ = f.deriv().eval(u);
            let _ = f.refine(&[u]);
            let _ = f.split_at(u);
            let _ = f.restrict(u, u + 1.0);
            let _ = f.elevate(1);
            if f.dim() == 1 {
                let _ = find_roots(&f, f.domain().0, f.domain().1, &RootOptions::default());
            }
            let _ = Rational::new(f, Some(&weights));
        }
    }
}

#[test]
fn errors_name_what_is_wrong() {
    let e = BSpline::new(2, vec![0., 0., 0., 2., 1., 3., 3., 3.], 1, vec![0.; 5]).unwrap_err();
    assert_eq!(
        e,
        Error::DecreasingKnots {
            index: 4,
            value: 1.0,
            previous: 2.0
        }
    );
    assert!(e.to_string().contains("knots[4]"));
    let e = BSpline::new(2, vec![0., 0., 0., 1., 1., 1.], 1, vec![0.; 4]).unwrap_err();
    assert!(matches!(
        e,
        Error::CountMismatch {
            expected: 7,
            got: 6,
            ..
        }
    ));
    let e = BSpline::new(1, vec![0., 0., 1., 1.], 1, vec![0., f64::NAN]).unwrap_err();
    assert!(e.to_string().contains("coefs[1]"));
    let e = BSpline::new(2, vec![0., 0., 0., 1., 1., 1., 2., 2., 2.], 1, vec![0.; 6]).unwrap_err();
    assert!(matches!(
        e,
        Error::KnotMultiplicity {
            multiplicity: 3,
            max: 2,
            ..
        }
    ));
    let e = BSpline::new(3, vec![0.; 8], 1, vec![0.; 4]).unwrap_err();
    assert!(matches!(e, Error::EmptyDomain { .. }));
    assert!(matches!(
        BSpline::clamped_uniform(3, 1, vec![0.; 3]),
        Err(Error::TooFewPoints {
            needed: 4,
            got: 3,
            ..
        })
    ));
    assert!(matches!(
        BSpline::bezier(0, vec![]),
        Err(Error::ZeroDimension)
    ));
    let a = BSpline::bezier(1, vec![0., 1.]).unwrap();
    let b = BSpline::bezier(1, vec![0., 1.])
        .unwrap()
        .reparam(0.0, 2.0)
        .unwrap();
    assert!(matches!(a.mul(&b), Err(Error::DomainMismatch { .. })));
    let c = BSpline::bezier(2, vec![0., 1., 2., 3.]).unwrap();
    assert!(matches!(
        c.cross(&a),
        Err(Error::DimensionMismatch {
            expected: 2,
            got: 1
        })
    ));
}
