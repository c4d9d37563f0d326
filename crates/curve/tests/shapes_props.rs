//! The curve model against independent definitions: the shapes' exact rational forms against
//! their equations, their jets on the rational circle against the forms' own derivatives, and
//! changes of frame against the curves they move.
#![allow(clippy::unwrap_used)]

use curve::circle::{circle_angle, Angle};
use curve::shapes::{Convexities, Ellipse, EllipticLemniscate, Limacon, Shape};
use curve::{rational_derivs, Frame, OnCircle, ParamCurve, PlaneCurve, SplineCurve, V2};
use proptest::prelude::*;
use std::f64::consts::TAU;
use testkit::stars::Star;

/// Point and three derivatives of a homogeneous form in pieces at `u`, by the quotient rule.
fn form_jet(shape: &Shape, u: f64) -> [V2; 4] {
    let pieces = shape.exact_pieces().unwrap();
    let mut out = [0.0; 8];
    rational_derivs(&pieces.hom, u, 3, &mut out);
    [0, 1, 2, 3].map(|k| V2::new(out[2 * k], out[2 * k + 1]))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// The exact forms lie on the shapes' equations at the circle's angle (the lemniscate's at
    /// `tan φ = (a/b) tan ψ`).
    #[test]
    fn exact_forms_match_their_equations(
        u in 0.0f64..4.0,
        a in 1.0f64..5.0, bfrac in 0.0f64..0.99,
        p in 0.5f64..5.0, eps in 0.01f64..0.95, m in 2u32..9,
    ) {
        let phi = circle_angle(u);
        let lim = Shape::Limacon(Limacon::new(a, a * bfrac).unwrap());
        let r = a + a * bfrac * phi.cos();
        let q = form_jet(&lim, u)[0];
        prop_assert!((q.x - r * phi.cos()).abs() < 1e-12 * a && (q.y - r * phi.sin()).abs() < 1e-12 * a);
        let cv = Shape::Convexities(Convexities::new(p, eps, m).unwrap());
        prop_assert_eq!(cv.exact_pieces().unwrap().hom.degree(), 2 * m as usize);
        let r = p / (1.0 + eps * (m as f64 * phi).cos());
        let q = form_jet(&cv, u)[0];
        prop_assert!((q.x - r * phi.cos()).abs() < 1e-11 * r && (q.y - r * phi.sin()).abs() < 1e-11 * r,
            "{:?} vs {}", q, r);
        let lem = Shape::EllipticLemniscate(EllipticLemniscate::new(a, a / (1.0 + 3.0 * bfrac)).unwrap());
        let Shape::EllipticLemniscate(l) = lem else { unreachable!() };
        let (sl, cl) = phi.sin_cos();
        let phl = (sl / l.b()).atan2(cl / l.a());
        let r = (l.a() * l.a() * phl.cos().powi(2) + l.b() * l.b() * phl.sin().powi(2)).sqrt();
        let q = form_jet(&lem, u)[0];
        prop_assert!((q.x - r * phl.cos()).abs() < 1e-12 * a && (q.y - r * phl.sin()).abs() < 1e-12 * a,
            "{:?} vs {}", q, r);
        let el = Shape::Ellipse(Ellipse::new(a, p, [1.0, -2.0]).unwrap());
        let q = form_jet(&el, u)[0];
        prop_assert!((q.x - 1.0 - a * phi.cos()).abs() < 1e-12 * a && (q.y + 2.0 - p * phi.sin()).abs() < 1e-12 * a.max(p));
    }
}

/// The shapes on the circle: the jets from their formulas against the exact forms' own
/// derivatives, and the reported angle against the point's polar angle and the shape's own
/// formula in φ.
#[test]
fn circle_jets_match_the_exact_forms() {
    let shapes = [
        Shape::Ellipse(Ellipse::new(3.0, 2.0, [0.5, -1.0]).unwrap()),
        Shape::Limacon(Limacon::new(4.0, 2.5).unwrap()),
        Shape::Convexities(Convexities::new(3.0, 0.5, 3).unwrap()),
        Shape::Convexities(Convexities::new(4.5, 0.2, 4).unwrap()),
        Shape::Convexities(Convexities::new(1.0, 0.9, 2).unwrap()),
        Shape::Convexities(Convexities::new(2.0, 0.3, 7).unwrap()),
        Shape::EllipticLemniscate(EllipticLemniscate::new(6.0, 3.0).unwrap()),
        Shape::EllipticLemniscate(EllipticLemniscate::new(1.0, 4.0).unwrap()),
        Shape::EllipticLemniscate(EllipticLemniscate::new(1.0, 1.0).unwrap()),
    ];
    for shape in shapes {
        let on = OnCircle::new(shape.circle_shape().unwrap());
        let angle = on.angle();
        for i in 0..2000 {
            // (u = 4 is the seam: the jet wraps to u = 0, where ψ″ jumps.)
            let u = 4.0 * i as f64 / 2000.0;
            let j = on.jet_to(u, 3);
            let exact = form_jet(&shape, u);
            let scale = exact.iter().map(|v| v.norm()).sum::<f64>();
            for (k, (x, y)) in [j.p, j.d1, j.d2, j.d3].into_iter().zip(exact).enumerate() {
                assert!(
                    (x - y).norm() <= 1e-12 * scale,
                    "{shape:?} u = {u} d{k}: {x:?} vs {y:?}"
                );
            }
            let phi = angle.phi(u);
            assert!((0.0..TAU).contains(&phi), "{u}: {phi}");
            let own = shape.jet(phi).p;
            assert!(
                (own - j.p).norm() <= 1e-12 * scale,
                "{shape:?} {u}: {own:?} vs {:?}",
                j.p
            );
            if matches!(angle, Angle::Squeezed { .. }) {
                let polar = j.p.y.atan2(j.p.x).rem_euclid(TAU);
                let d = (phi - polar).abs();
                assert!(d.min(TAU - d) <= 1e-14 * TAU, "{u}: {phi} vs {polar}");
            }
        }
    }
    // Too slender a lemniscate has no circle form (it stays sampled).
    let slender = Shape::EllipticLemniscate(EllipticLemniscate::new(6.0, 1.0).unwrap());
    assert!(slender.circle_shape().is_none());
}

/// The forms close up, run counterclockwise, and the shapes validate their parameters.
#[test]
fn forms_are_closed_counterclockwise_and_shapes_validated() {
    let shapes = [
        Shape::Limacon(Limacon::new(4.0, 2.5).unwrap()),
        Shape::Convexities(Convexities::new(3.0, 0.5, 3).unwrap()),
        Shape::Ellipse(Ellipse::new(2.0, 1.0, [0.0; 2]).unwrap()),
        Shape::EllipticLemniscate(EllipticLemniscate::new(6.0, 3.0).unwrap()),
    ];
    for shape in shapes {
        let (p0, p1) = (form_jet(&shape, 0.0)[0], form_jet(&shape, 4.0)[0]);
        assert!((p0 - p1).norm() < 1e-14, "{shape:?}");
        let n = 400;
        let pts: Vec<V2> = (0..n)
            .map(|i| form_jet(&shape, 4.0 * i as f64 / n as f64)[0])
            .collect();
        let area: f64 = (0..n).map(|i| pts[i].cross(pts[(i + 1) % n])).sum();
        assert!(area > 0.0, "{shape:?}");
    }
    assert!(Convexities::new(3.0, 1.5, 3).is_err());
    assert!(Ellipse::new(-1.0, 1.0, [0.0; 2]).is_err());
    assert!(EllipticLemniscate::new(1.0, 0.0).is_err());
    assert!(EllipticLemniscate::new(f64::NAN, 1.0).is_err());
    assert!(Limacon::new(2.0, 2.0).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// A curve moved into the frame of its extent, far from the origin and of any size, is the
    /// same curve: a polynomial spline's control points come back bit for bit and its local
    /// form carries no error from the change; near the origin the local jets scaled back are
    /// the global ones.
    #[test]
    fn frames_keep_the_curve(
        offset in prop_oneof![Just(0.0), Just(1e8), Just(-3e15), -1e6f64..1e6],
        log_size in -250.0f64..250.0,
        seed in proptest::collection::vec(0.0f64..1.0, 16),
        weights in proptest::option::of(proptest::collection::vec(0.5f64..2.0, 8)),
        u in 0.0f64..1.0,
    ) {
        let size = 10f64.powf(log_size);
        let star = Star { size, center: [offset, offset], ..Star::default() };
        let pts = star.points_from_seed(&seed);
        let c = SplineCurve::periodic(3, &pts, weights.as_deref()).unwrap();
        let exact = c.exact().unwrap();
        let frame = Frame::for_points(&exact.extent());
        let local = exact.in_frame(&frame);
        let curve::ExactCurve::Spline(ls) = &local else { unreachable!() };
        if weights.is_none() {
            prop_assert_eq!(ls.curve().coefficient_error(), 0.0);
            for (l, g) in ls.control_points().iter().zip(c.control_points()) {
                prop_assert_eq!(frame.to_global(*l), g);
            }
        }
        // The local control points are of about unit size.
        prop_assert!(ls.control_points().iter().all(|p| p[0].abs() <= 4.0 && p[1].abs() <= 4.0));
        if offset == 0.0 {
            let (a, b) = c.domain();
            let x = a + (b - a) * u;
            let (g, j) = (c.jet(x), local.curve().jet(x));
            let s = frame.scale();
            for (l, gl) in [(j.p, g.p), (j.d1, g.d1), (j.d2, g.d2)] {
                prop_assert!((l * s - gl).norm() <= 1e-12 * (g.p.norm() + g.d1.norm() + g.d2.norm()),
                    "{:?} vs {:?}", l * s, gl);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// A shape's jet scales with the shape, at every size a file may give: lengths times 2^k
    /// give points and derivatives times 2^k (to rounding), never an overflow of a square
    /// or an underflow to zero.
    #[test]
    fn jets_scale_with_the_shape(
        k in -1000i32..1000,
        a in 0.2f64..5.0, b in 0.2f64..5.0,
        eps in 0.01f64..0.95, m in 2u32..9,
        u in 0.0f64..TAU,
    ) {
        let s = 2f64.powi(k);
        let pairs = [
            (Shape::Ellipse(Ellipse::new(a, b, [b, -a]).unwrap()),
             Shape::Ellipse(Ellipse::new(a * s, b * s, [b * s, -a * s]).unwrap())),
            (Shape::Limacon(Limacon::new(a + b, b).unwrap()),
             Shape::Limacon(Limacon::new((a + b) * s, b * s).unwrap())),
            (Shape::EllipticLemniscate(EllipticLemniscate::new(a, b).unwrap()),
             Shape::EllipticLemniscate(EllipticLemniscate::new(a * s, b * s).unwrap())),
            (Shape::Convexities(Convexities::new(a, eps, m).unwrap()),
             Shape::Convexities(Convexities::new(a * s, eps, m).unwrap())),
        ];
        for (unit, scaled) in pairs {
            let (j, js) = (unit.jet_to(u, 3), scaled.jet_to(u, 3));
            let size = j.p.norm() + j.d1.norm() + j.d2.norm() + j.d3.norm();
            for (x, xs) in [(j.p, js.p), (j.d1, js.d1), (j.d2, js.d2), (j.d3, js.d3)] {
                for (c, cs) in [(x.x, xs.x), (x.y, xs.y)] {
                    // (Relative to the jet's size in the scaled units; subnormal results
                    // keep what precision they have.)
                    let err = (cs / s - c).abs();
                    prop_assert!(
                        err <= 1e-13 * size || (cs.abs() < 1e-290 && err <= 1e-10 * size),
                        "{}: {c} vs {cs} at scale 2^{k}", unit.kind()
                    );
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// A shape or a periodic spline as the segment that runs once round it: the profile of
    /// that segment at the whole curve's parameter `x`, mapped through
    /// `Segment::form_param_of_whole`, is the curve's point at `x` (by evaluation of each, the
    /// shape by its equations); and its seam is no corner, however far from the origin.
    #[test]
    fn whole_curves_keep_their_parameter(
        a in 0.2f64..5.0, b in 0.2f64..5.0, eps in 0.01f64..0.95, m in 2u32..9,
        offset in prop_oneof![Just(0.0), Just(1e8), -1e3f64..1e3],
        seed in proptest::collection::vec(0.0f64..1.0, 16),
        weights in proptest::option::of(proptest::collection::vec(0.5f64..2.0, 8)),
        share in 0.0f64..1.0,
    ) {
        use curve::{Profile, Segment, SegmentKind};
        let shapes = [
            Shape::Circle(curve::shapes::Circle::new(a, [offset, -offset]).unwrap()),
            Shape::Ellipse(Ellipse::new(a, b, [offset, b]).unwrap()),
            Shape::Limacon(Limacon::new(a + b, b).unwrap()),
            Shape::EllipticLemniscate(EllipticLemniscate::new(a, b).unwrap()),
            Shape::Convexities(Convexities::new(a, eps, m).unwrap()),
        ];
        let star = Star { center: [offset, offset], ..Star::default() };
        let spline = SplineCurve::periodic(3, &star.points_from_seed(&seed), weights.as_deref())
            .unwrap();
        let mut cases: Vec<(Segment, &dyn PlaneCurve)> = shapes
            .iter()
            .map(|s| (Segment::of_shape(*s).unwrap(), s as &dyn PlaneCurve))
            .collect();
        cases.push((Segment::periodic_spline(SegmentKind::BSpline, &spline).unwrap(), &spline));
        for (segment, curve) in cases {
            let (lo, hi) = curve.domain();
            let x = lo + (hi - lo) * share;
            let v = segment.form_param_of_whole(x).unwrap();
            let whole = segment.whole_curve().unwrap().curve().jet(x).p;
            let want = curve.jet(x).p;
            prop_assert_eq!(whole, want);
            let profile = Profile::of_curve(segment, (lo, hi)).unwrap();
            prop_assert!(profile.corners().next().is_none());
            let got = profile.jet(profile.profile_param(0, v)).p;
            // (Far from the origin the form's points round to units of their coordinates.)
            let room = 1e-13 * (a + b) + 8.0 * f64::EPSILON * want.norm();
            prop_assert!((got - want).norm() <= room, "{:?} against {:?}", got, want);
        }
    }
}
