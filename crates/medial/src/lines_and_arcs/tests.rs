use super::LinesAndArcs;
use crate::sites::{Sites, EMPTY_SLACK};
use crate::test_shapes::random_rounded;
use curve::V2;
use testkit::rng;

/// The closed-form disk test is sound and sharp against the boundary's nearest point (found
/// on the exact forms): on 200 random rounded stars with round holes, at random points of
/// their box (inside and out) and at their arcs' centres, with radii within five slacks
/// of the distance to the boundary and within a thousandth of the size below it, it never
/// calls a disk clear that holds a point nearer than its radius less the slack, and calls
/// clear every disk a thousandth of the size smaller than that distance.
#[test]
fn the_closed_form_disk_test_agrees_with_the_nearest_point() {
    let mut rnd = rng(4003);
    let (mut tested, mut clear) = (0, 0);
    for _ in 0..200 {
        let Some(region) = random_rounded(&mut rnd) else {
            continue;
        };
        let sites = Sites::new(&region, false);
        let model = LinesAndArcs::new(&sites, 1e-3).unwrap();
        assert!(model.few);
        let size = sites.size;
        let slack = EMPTY_SLACK * size;
        let centres = sites
            .boundaries
            .iter()
            .flat_map(|b| b.segments().iter().filter_map(|s| s.circle()))
            .map(|(c, _)| V2::from_arr(c));
        let random: Vec<V2> = (0..20)
            .map(|_| V2::new(4.0 * rnd() - 2.0, 4.0 * rnd() - 2.0))
            .collect();
        for x in centres.chain(random) {
            let nearest = sites.nearest(x.arr(), 0.0).0;
            for radius in [
                nearest + slack * (10.0 * rnd() - 5.0),
                nearest - 1e-3 * size * rnd(),
            ] {
                let said = model.clear_in_closed_form(x, radius);
                tested += 1;
                clear += usize::from(said);
                // (The nearest point is found to ~1e-15 of the size.)
                assert!(
                    !said || nearest >= radius - slack - 1e-14 * size,
                    "{x:?}: clear at {radius}, the nearest at {nearest}"
                );
                if radius <= nearest - slack {
                    assert!(
                        said,
                        "{x:?}: not clear at {radius}, the nearest at {nearest}"
                    );
                }
            }
        }
    }
    assert!(
        tested > 6000 && clear > tested / 2,
        "{clear} clear of {tested}"
    );
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
fn hull(mut points: Vec<V2>) -> Vec<V2> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let mut out: Vec<V2> = Vec::new();
    for pass in 0..2 {
        let start = out.len();
        for &p in &points {
            while out.len() >= start + 2
                && (out[out.len() - 1] - out[out.len() - 2]).cross(p - out[out.len() - 2]) <= 0.0
            {
                out.pop();
            }
            out.push(p);
        }
        out.pop();
        if pass == 0 {
            points.reverse();
        }
    }
    out
}

proptest::proptest! {
    /// The disks along a bisector of two lines (each less the slack) lie in the end disks
    /// and the polygon of [`super::empty_disks::sweep_polygon`], checked on dense points of
    /// their rims: for lines meeting at any angle and for parallel ones.
    #[test]
    fn the_sweep_polygon_covers_the_disks_between(
        apex in proptest::array::uniform2(-10.0f64..10.0),
        turn in 0.0f64..6.3,
        half_angle in 0.0f64..1.5,
        s in proptest::array::uniform2(0.01f64..5.0),
    ) {
        use super::empty_disks::sweep_polygon;
        use crate::true_sites::LineSite;
        let slack = 1e-3;
        let (o, u) = (V2::from_arr(apex), V2::polar(turn));
        let parallel = half_angle < 0.05;
        let rotate = |v: V2, a: f64| V2::new(v.x * a.cos() - v.y * a.sin(), v.x * a.sin() + v.y * a.cos());
        let (da, db) = if parallel { (u, u) } else { (rotate(u, half_angle), rotate(u, -half_angle)) };
        let (na, nb) = (rotate(da, -std::f64::consts::FRAC_PI_2), rotate(db, std::f64::consts::FRAC_PI_2));
        // (Parallel lines: 1 on either side of the line through the apex along u.)
        let (sa, sb) = if parallel { (o - na, o - nb) } else { (o, o) };
        let line = |start: V2, along: V2, inward: V2| LineSite { start, along, length: 100.0, inward };
        let lines = [line(sa, da, na), line(sb, db, nb)];
        let (s0, s1) = (s[0].min(s[1]), s[0].max(s[1]));
        let c = [o + u * s0, o + u * (s1 + 0.01)];
        let r = c.map(|x| lines[0].inward.dot(x - lines[0].start));
        proptest::prop_assume!(r[0] > slack);
        let poly = hull(sweep_polygon(c, r, lines, slack).to_vec());
        let inside = |x: V2| {
            (0..poly.len()).all(|k| {
                let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
                (b - a).cross(x - a) >= -1e-12 * (b - a).norm()
            })
        };
        for i in 0..=40 {
            let t = i as f64 / 40.0;
            let (ct, rt) = (c[0] + (c[1] - c[0]) * t, r[0] + (r[1] - r[0]) * t - slack);
            for k in 0..720 {
                let x = ct + V2::polar(std::f64::consts::TAU * k as f64 / 720.0) * rt;
                let in_disk = |j: usize| (x - c[j]).norm() <= r[j] - slack + 1e-12;
                proptest::prop_assert!(in_disk(0) || in_disk(1) || inside(x), "t {t} at {x:?}");
            }
        }
        // (And the polygon keeps clear of both lines.)
        for l in &lines {
            for x in &poly {
                proptest::prop_assert!(l.inward.dot(*x - l.start) >= 0.2 * slack);
            }
        }
    }
}
