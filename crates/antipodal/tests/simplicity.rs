//! The simplicity test against a brute-force one: the dense polygon of the curve searched for
//! crossings, on random closed B-splines and NURBS of which about half cross themselves.

#![allow(clippy::unwrap_used)] // test helpers outside #[test] fns

use antipodal::{antipodal, Error, Options, PlaneCurve, SplineCurve};
use numeric::certificate::Verdict as _;
use proptest::prelude::*;
use testkit::stars::Star;

/// Points of the polygon with `n` vertices through the curve.
fn polygon(c: &dyn PlaneCurve, n: usize) -> Vec<[f64; 2]> {
    let (a, b) = c.domain();
    (0..n)
        .map(|i| c.jet(a + (b - a) * i as f64 / n as f64).p.arr())
        .collect()
}

fn cross(o: [f64; 2], p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
}

/// A proper crossing of two edges of the closed polygon (edges sorted by their least x, swept).
fn polygon_crosses(pts: &[[f64; 2]]) -> bool {
    let n = pts.len();
    let seg = |i: usize| (pts[i], pts[(i + 1) % n]);
    let minx = |i: usize| seg(i).0[0].min(seg(i).1[0]);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&i, &j| minx(i).total_cmp(&minx(j)));
    for (k, &i) in order.iter().enumerate() {
        let (p, q) = seg(i);
        let maxx = p[0].max(q[0]);
        for &j in &order[k + 1..] {
            if minx(j) > maxx {
                break;
            }
            if j == (i + 1) % n || i == (j + 1) % n {
                continue;
            }
            let (r, s) = seg(j);
            let (d1, d2) = (cross(p, q, r), cross(p, q, s));
            let (d3, d4) = (cross(r, s, p), cross(r, s, q));
            if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
                return true;
            }
        }
    }
    false
}

/// What the algorithm says of a curve's simplicity.
#[derive(Debug, PartialEq)]
enum Verdict {
    /// Simple, certified.
    Simple,
    /// No error, but not certified.
    Undecided,
    /// Not simple (a crossing, or a tangent that does not turn once around).
    Crossing,
    /// Rejected for another reason (a cusp).
    Other,
}

fn verdict(c: &dyn PlaneCurve) -> Verdict {
    match antipodal(c, &Options::default()) {
        Ok(r) if r.certified() => Verdict::Simple,
        Ok(_) => Verdict::Undecided,
        Err(Error::SelfIntersecting { .. } | Error::Winding { .. }) => Verdict::Crossing,
        Err(_) => Verdict::Other,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// A curve certified simple has no crossing in its dense polygon, and a curve said to
    /// cross itself has one.
    fn simplicity_matches_the_dense_polygon(
        deg in 3usize..=5,
        seed in proptest::collection::vec((0.0f64..1.0, 0.0f64..1.0), 6..=14),
        jitter in 0.0f64..5.0,
        w in proptest::collection::vec(0.5f64..2.0, 14),
        rational in any::<bool>(),
    ) {
        // A star-shaped polygon whose angles are jittered by up to `jitter` of their spacing:
        // from simple curves (small jitter) to ones folding over themselves.
        let pts = Star { jitter, inner: 0.1, ..Star::default() }.points(&seed);
        let weights = rational.then(|| w[..pts.len()].to_vec());
        let Ok(c) = SplineCurve::periodic(deg, &pts, weights.as_deref()) else {
            return Ok(());
        };
        let v = verdict(&c);
        let brute = polygon_crosses(&polygon(&c, 20_000));
        match v {
            Verdict::Simple => prop_assert!(!brute, "certified simple, but the polygon crosses"),
            Verdict::Crossing => prop_assert!(brute, "said to cross, but the polygon does not"),
            Verdict::Undecided | Verdict::Other => {}
        }
        COUNTS.with(|k| {
            let mut k = k.borrow_mut();
            k[usize::from(brute)] += 1;
            k[2] += usize::from(v == Verdict::Undecided);
        });
    }
}

thread_local! {
    /// Cases without and with a crossing, and undecided ones.
    static COUNTS: std::cell::RefCell<[usize; 3]> = const { std::cell::RefCell::new([0; 3]) };
}

/// Runs the property, and checks that both kinds of curve were met and few left undecided.
#[test]
fn simplicity_matches_the_dense_polygon_on_both_kinds() {
    simplicity_matches_the_dense_polygon();
    let [simple, crossing, undecided] = COUNTS.with(|k| *k.borrow());
    assert!(
        simple >= 30 && crossing >= 30,
        "{simple} simple, {crossing} crossing"
    );
    assert!(
        undecided * 10 <= simple,
        "{undecided} undecided of {simple} simple"
    );
}

/// A band bent into a C whose ends overlap: it crosses itself twice, and its tangent still
/// turns once around (the turning test alone cannot see it).
#[test]
fn overlapping_band_crosses_itself() {
    let outer: Vec<[f64; 2]> = (0..=10)
        .map(|i| {
            let a = 0.15 * std::f64::consts::PI + 2.1 * std::f64::consts::PI * i as f64 / 10.0;
            [1.0 * a.cos(), 1.0 * a.sin()]
        })
        .collect();
    let inner: Vec<[f64; 2]> = outer
        .iter()
        .rev()
        .map(|p| [0.7 * p[0], 0.7 * p[1]])
        .collect();
    let pts: Vec<[f64; 2]> = outer.into_iter().chain(inner).collect();
    let c = SplineCurve::periodic(3, &pts, None).unwrap();
    assert!(polygon_crosses(&polygon(&c, 20_000)));
    let r = antipodal(&c, &Options::default());
    assert!(
        matches!(r, Err(Error::SelfIntersecting { .. })),
        "{:?}",
        r.map(|r| r.pairs.len())
    );
}
