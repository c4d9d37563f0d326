//! The grasp tests' shared oracle: force closure decided from the curve's points and tangents
//! alone (`ParamCurve::jet`, angles, no B-spline algebra), membership in the reported regions
//! by winding numbers on the torus of pairs, and the dense check of a whole result.
#![allow(dead_code)] // (each test file uses its own share)

use curve::shapes::Shape;
use curve::{Boundary, ParamCurve, Profile, SplineCurve};
use grasp::{GraspOptions, GraspRegion, Grasps};
use numeric::certificate::Doubt;
use testkit::boundary_oracle::{off_segment, winding};
use testkit::grasp_oracle::{in_stretches, BEST_PROVEN_SHARE};

/// Grid points per side of the square of pairs in the dense check.
pub(crate) const GRID: usize = 90;

/// Samples per side of a contact rectangle.
pub(crate) const CONTACT_SAMPLES: usize = 24;

/// Slack on the angles of a contact rectangle's pairs: the rectangle is pushed out until it
/// touches a region's boundary, where the slip angle equals α up to the crate's rounding
/// allowance and the oracle's own (both far below 1e-9 rad on curves of unit size).
pub(crate) const CONTACT_ANGLE_SLACK: f64 = 1e-9;

/// Relative slack on the widths of a contact rectangle's pairs, for the same reason.
pub(crate) const CONTACT_WIDTH_SLACK: f64 = 1e-9;

/// How far `best.min_friction` may stray from the oracle's value at the same pair: both are
/// the tangent of an angle computed from the same points, so only rounding parts them.
pub(crate) const BEST_ROUNDING: f64 = 1e-9;

/// The oracle's own rounding of an angle, in units of `ε · |coordinates|` over the lengths
/// it divides by (the chord and both tangents): its jets are evaluated where the curve lies,
/// so far from the origin (1e6) every point and tangent carries the rounding of the
/// coordinates' magnitude, summed over up to five control points and the levels of de Boor's
/// recursion (the crate works in a shifted frame and is more precise).
pub(crate) const JET_ROUNDING_ULPS: f64 = 64.0;

/// How much less friction a grid point of a region may need than the region's best grasp:
/// the best is a minimum found to the parameter tolerance (1e-12 of the domain), where
/// `min_friction` is flat; a grid point beats it only by rounding.
pub(crate) const BEST_GRID_SLACK: f64 = 1e-9;

/// How far a reported point (a best grasp's or a contact end's) may lie from the curve's
/// point at its parameter, relative to the curve's size and distance from the origin: both
/// come from the same parameter, through frames that round only in the last bits.
pub(crate) const POINT_ROUNDING: f64 = 1e-9;

/// The curves the tests draw: splines and analytic shapes.
#[derive(Debug, Clone)]
pub(crate) enum TestCurve {
    /// A closed spline (periodic, optionally rational), boxed (it is far larger than a
    /// shape).
    Spline(Box<SplineCurve>),
    /// An analytic shape.
    Shape(Shape),
    /// A closed profile, read in its document's parameter.
    Profile(Box<Documented>),
}

/// A profile as a curve of its document's parameter (the parameter the grasps are reported
/// in): its jets at the profile parameter of each document parameter (the tangents' lengths
/// differ from the document parameter's derivatives; the oracle needs only their directions).
#[derive(Debug, Clone)]
pub(crate) struct Documented(pub(crate) Profile);

impl ParamCurve for Documented {
    fn domain(&self) -> (f64, f64) {
        self.0.document_domain()
    }
    fn is_closed(&self) -> bool {
        self.0.is_closed()
    }
    fn jet_to(&self, u: f64, order: usize) -> curve::Jet {
        self.0.jet_to(self.0.internal_param(u), order)
    }
}

impl TestCurve {
    /// The curve as the crate takes it.
    pub(crate) fn boundary(&self) -> Boundary<'_> {
        match self {
            TestCurve::Spline(c) => c.as_ref().into(),
            TestCurve::Shape(c) => c.into(),
            TestCurve::Profile(c) => (&c.0).into(),
        }
    }

    /// The curve as the oracle evaluates it.
    pub(crate) fn param(&self) -> &dyn ParamCurve {
        match self {
            TestCurve::Spline(c) => c.as_ref(),
            TestCurve::Shape(c) => c,
            TestCurve::Profile(c) => c.as_ref(),
        }
    }
}

/// Force closure of pairs, from jets only.
pub(crate) struct Oracle<'a> {
    curve: &'a dyn ParamCurve,
    /// +1 for a counterclockwise curve (the inward normal is the left one), −1 otherwise.
    orientation: f64,
    /// The friction cone's half-angle, `atan μ`.
    pub(crate) alpha: f64,
    min_width: Option<f64>,
    max_width: Option<f64>,
}

impl<'a> Oracle<'a> {
    /// The oracle for the options' friction and widths.
    pub(crate) fn new(curve: &'a dyn ParamCurve, opts: &GraspOptions) -> Self {
        Self {
            curve,
            orientation: orientation(curve),
            alpha: opts.friction.atan(),
            min_width: opts.min_width,
            max_width: opts.max_width,
        }
    }

    /// The curve's jet at `u` read modulo the period (a closed curve's jets beyond its domain
    /// are not its own: a spline's run on along its end pieces).
    pub(crate) fn jet(&self, u: f64) -> curve::Jet {
        let (a, b) = self.curve.domain();
        self.curve.jet(a + (u - a).rem_euclid(b - a))
    }

    /// The domain `[a, b)`, one period.
    pub(crate) fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    /// The angles between each contact's inward normal and the chord to the other contact,
    /// signed (positive on the side of the tangent), at `s` then at `t`.
    pub(crate) fn signed_angles(&self, s: f64, t: f64) -> [f64; 2] {
        let (js, jt) = (self.jet(s), self.jet(t));
        let d = [jt.p.x - js.p.x, jt.p.y - js.p.y];
        let angle = |tan: [f64; 2], d: [f64; 2]| {
            let n = [-self.orientation * tan[1], self.orientation * tan[0]];
            (tan[0] * d[0] + tan[1] * d[1]).atan2(n[0] * d[0] + n[1] * d[1])
        };
        [
            angle([js.d1.x, js.d1.y], d),
            angle([jt.d1.x, jt.d1.y], [-d[0], -d[1]]),
        ]
    }

    /// The larger angle between a contact's inward normal and the chord to the other one.
    pub(crate) fn slip_angle(&self, s: f64, t: f64) -> f64 {
        let [u, v] = self.signed_angles(s, t);
        u.abs().max(v.abs())
    }

    /// The least friction for which `(s, t)` is force closure (infinite beyond a right angle).
    pub(crate) fn min_friction(&self, s: f64, t: f64) -> f64 {
        let angle = self.slip_angle(s, t);
        if angle >= std::f64::consts::FRAC_PI_2 {
            f64::INFINITY
        } else {
            angle.tan()
        }
    }

    /// The rounding of the oracle's angles at `(s, t)` ([`JET_ROUNDING_ULPS`]).
    pub(crate) fn angle_rounding(&self, s: f64, t: f64) -> f64 {
        let (js, jt) = (self.jet(s), self.jet(t));
        let far = [js.p.x, js.p.y, jt.p.x, jt.p.y]
            .iter()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        let chord = (jt.p.x - js.p.x).hypot(jt.p.y - js.p.y);
        let lengths = 1.0 / chord + 1.0 / js.d1.x.hypot(js.d1.y) + 1.0 / jt.d1.x.hypot(jt.d1.y);
        JET_ROUNDING_ULPS * f64::EPSILON * far * lengths
    }

    /// `|C(t) − C(s)|`.
    pub(crate) fn width(&self, s: f64, t: f64) -> f64 {
        let (p, q) = (self.jet(s).p, self.jet(t).p);
        (q.x - p.x).hypot(q.y - p.y)
    }

    /// A size of the curve: its largest coordinate or its diameter, whichever is larger.
    pub(crate) fn size(&self) -> f64 {
        let (a, b) = self.domain();
        let n = 64;
        let p: Vec<_> = (0..n)
            .map(|i| self.curve.jet(a + (b - a) * i as f64 / n as f64).p)
            .collect();
        let far = p
            .iter()
            .map(|q| q.x.abs().max(q.y.abs()))
            .fold(0.0, f64::max);
        let wide = p
            .iter()
            .flat_map(|u| p.iter().map(move |v| (u.x - v.x).hypot(u.y - v.y)));
        far.max(wide.fold(0.0, f64::max))
    }

    /// Checks that `p` is the curve's point at `u`.
    pub(crate) fn check_point(&self, p: [f64; 2], u: f64, what: &str) -> Result<(), String> {
        let e = self.jet(u).p;
        let gap = (p[0] - e.x).hypot(p[1] - e.y);
        if gap > POINT_ROUNDING * self.size() {
            return Err(format!(
                "{what} at {u} reported at {p:?}, the curve has {e:?}"
            ));
        }
        Ok(())
    }

    /// Whether `(s, t)` is force closure within the width limits, with slack on the angle and
    /// (relative) on the widths.
    pub(crate) fn grasps_with_slack(&self, s: f64, t: f64, angle: f64, width: f64) -> bool {
        if self.slip_angle(s, t) > self.alpha + angle {
            return false;
        }
        let w = self.width(s, t);
        self.min_width.is_none_or(|lo| w >= lo * (1.0 - width))
            && self.max_width.is_none_or(|hi| w <= hi * (1.0 + width))
    }

    /// Whether `(s, t)` is force closure within the width limits.
    pub(crate) fn grasps(&self, s: f64, t: f64) -> bool {
        self.grasps_with_slack(s, t, 0.0, 0.0)
    }
}

/// The sign of the signed area of a sampled closed curve: its orientation.
pub(crate) fn orientation(c: &dyn ParamCurve) -> f64 {
    let (a, b) = c.domain();
    let n = 400;
    let p: Vec<_> = (0..n)
        .map(|i| c.jet(a + (b - a) * i as f64 / n as f64).p)
        .collect();
    let area: f64 = (0..n)
        .map(|i| {
            let (u, v) = (p[i], p[(i + 1) % n]);
            u.x * v.y - v.x * u.y
        })
        .sum();
    area.signum()
}

/// The pair `(s, t)`, read modulo the period `[a, b)`, as the point of the triangle `s ≤ t`.
pub(crate) fn on_torus((a, b): (f64, f64), [s, t]: [f64; 2]) -> [f64; 2] {
    let wrap = |x: f64| a + (x - a).rem_euclid(b - a);
    let (s, t) = (wrap(s), wrap(t));
    [s.min(t), s.max(t)]
}

/// Closed polylines in the square of pairs.
pub(crate) type Polylines<'a> = Vec<&'a [[f64; 2]]>;

/// The closed polylines of a region: its parts (or its boundary) and holes.
pub(crate) fn outlines(r: &GraspRegion) -> (Polylines<'_>, Polylines<'_>) {
    let parts = if r.parts.is_empty() {
        vec![r.boundary.as_slice()]
    } else {
        r.parts.iter().map(Vec::as_slice).collect()
    };
    (parts, r.holes.iter().map(Vec::as_slice).collect())
}

/// Whether the region holds the pair (any pair of parameters, read on the torus).
pub(crate) fn region_holds(r: &GraspRegion, domain: (f64, f64), p: [f64; 2]) -> bool {
    let p = on_torus(domain, p);
    let (parts, holes) = outlines(r);
    parts.iter().any(|part| winding(part, p) != 0) && !holes.iter().any(|h| winding(h, p) != 0)
}

/// The regions holding the pair.
pub(crate) fn holders(g: &Grasps, domain: (f64, f64), p: [f64; 2]) -> usize {
    g.regions
        .iter()
        .filter(|r| region_holds(r, domain, p))
        .count()
}

/// Every boundary polyline of the result (parts, holes).
pub(crate) fn lines(g: &Grasps) -> Vec<&[[f64; 2]]> {
    g.regions
        .iter()
        .flat_map(|r| {
            let (parts, holes) = outlines(r);
            parts.into_iter().chain(holes)
        })
        .collect()
}

/// The distance from `p` to the nearest of the closed polylines (their closing edges too).
pub(crate) fn off_lines(p: [f64; 2], lines: &[&[[f64; 2]]]) -> f64 {
    lines
        .iter()
        .flat_map(|l| (0..l.len()).map(move |k| off_segment(p, l[k], l[(k + 1) % l.len()])))
        .fold(f64::INFINITY, f64::min)
}

/// The chord tolerance of the options in the square of parameters of `domain` (relative to
/// its diagonal, as the options say).
pub(crate) fn chord((a, b): (f64, f64), opts: &GraspOptions) -> f64 {
    opts.settings.chord_tol.get() * std::f64::consts::SQRT_2 * (b - a)
}

/// Whether `x` lies in `[lo, hi]` read modulo the period `b − a` (an interval no longer than
/// a period).
pub(crate) fn in_stretch((a, b): (f64, f64), [lo, hi]: [f64; 2], x: f64) -> bool {
    let w = b - a;
    let x = lo + (x - lo).rem_euclid(w);
    x <= hi || (x - w - lo).abs() <= f64::EPSILON * w
}

/// What a dense check saw.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Seen {
    /// Grid points decided (away from every boundary).
    pub(crate) decided: usize,
    /// Of them, the force-closure ones.
    pub(crate) inside: usize,
    /// Regions reported.
    pub(crate) regions: usize,
}

/// The dense check of one result: the grid against the oracle, every contact rectangle
/// sampled, every best grasp recomputed and compared with its region's grid points.
pub(crate) fn dense_check(curve: &TestCurve, opts: &GraspOptions) -> Result<Seen, String> {
    dense_check_of(curve, opts, Checks::All)
}

/// What a dense check looks at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Checks {
    /// Everything.
    All,
    /// The grid only, not the best grasps and contact rectangles (which a known defect of
    /// the crate spoils; a test of its own shows it).
    Grid,
    /// Everything, but the best grasps' robustness against the grid only where the crate
    /// does not itself report `GraspBestUnproven` (its local search is known to stop short
    /// of the minimum at a knot; a test of its own shows it).
    UnlessBestDoubted,
}

/// [`dense_check`], of the parts `checks` names.
pub(crate) fn dense_check_of(
    curve: &TestCurve,
    opts: &GraspOptions,
    checks: Checks,
) -> Result<Seen, String> {
    let g = grasp::grasps(curve.boundary(), opts).map_err(|e| format!("grasps: {e}"))?;
    if !g.complete {
        return Err("the result is incomplete".into());
    }
    check_result_of(curve.param(), opts, &g, checks)
}

/// [`dense_check`] on a result already computed.
pub(crate) fn check_result(
    c: &dyn ParamCurve,
    opts: &GraspOptions,
    g: &Grasps,
) -> Result<Seen, String> {
    check_result_of(c, opts, g, Checks::All)
}

/// [`dense_check_of`] on a result already computed.
pub(crate) fn check_result_of(
    c: &dyn ParamCurve,
    opts: &GraspOptions,
    g: &Grasps,
    checks: Checks,
) -> Result<Seen, String> {
    let oracle = Oracle::new(c, opts);
    let domain = c.domain();
    let (a, b) = domain;
    let margin = chord(domain, opts);
    let boundaries = lines(g);
    let mut seen = Seen {
        regions: g.regions.len(),
        ..Seen::default()
    };
    // Per region, the least friction its grid points need.
    let mut least = vec![f64::INFINITY; g.regions.len()];
    for i in 0..GRID {
        for j in i + 1..GRID {
            // (Offsets off the simple fractions, where symmetric shapes put their features.)
            let s = a + (b - a) * (i as f64 + 0.31) / GRID as f64;
            let t = a + (b - a) * (j as f64 + 0.37) / GRID as f64;
            let p = [s, t];
            if off_lines(p, &boundaries) <= margin {
                continue;
            }
            seen.decided += 1;
            let fc = oracle.grasps(s, t);
            seen.inside += usize::from(fc);
            let held = holders(g, domain, p);
            if held > 1 {
                return Err(format!("pair ({s}, {t}) is held by {held} regions"));
            }
            if fc != (held == 1) {
                return Err(format!(
                    "pair ({s}, {t}): slip angle {} against α = {}, width {}; held: {}; {} regions",
                    oracle.slip_angle(s, t),
                    oracle.alpha,
                    oracle.width(s, t),
                    held == 1,
                    g.regions.len()
                ));
            }
            for (k, r) in g.regions.iter().enumerate() {
                // (Pairs with a finger in a stretch the best grasp's proof spares may need
                // less: the region's least friction falls toward a corner there.)
                if region_holds(r, domain, p) && !in_stretches(&r.best.toward, domain, p) {
                    least[k] = least[k].min(oracle.min_friction(s, t));
                }
            }
        }
    }
    if checks == Checks::Grid {
        return Ok(seen);
    }
    let doubted = g.doubts.iter().any(|d| *d == Doubt::GraspBestUnproven);
    if checks == Checks::UnlessBestDoubted && doubted {
        least.fill(f64::INFINITY);
    }
    for (k, r) in g.regions.iter().enumerate() {
        check_best(&oracle, domain, k, r, least[k])?;
        check_contact(&oracle, domain, k, r)?;
    }
    Ok(seen)
}

/// The best grasp: force closure, in its region, its `min_friction` the oracle's, and no grid
/// point of the region needing less.
fn check_best(
    oracle: &Oracle<'_>,
    domain: (f64, f64),
    k: usize,
    r: &GraspRegion,
    least_on_grid: f64,
) -> Result<(), String> {
    let best = &r.best;
    let mu = oracle.min_friction(best.s, best.t);
    // (The tangent's slope is 1 + μ²: the angle's rounding in μ.)
    let rounding = oracle.angle_rounding(best.s, best.t) * (1.0 + mu * mu);
    if (best.min_friction - mu).abs() > BEST_ROUNDING * (1.0 + mu) + rounding {
        return Err(format!(
            "region {k}: best ({}, {}) reports min_friction {}, the oracle {mu}",
            best.s, best.t, best.min_friction
        ));
    }
    if !oracle.grasps(best.s, best.t) {
        return Err(format!(
            "region {k}: best ({}, {}) is not force closure (slip angle {} against α = {}, width \
             {} against [{:?}, {:?}])",
            best.s,
            best.t,
            oracle.slip_angle(best.s, best.t),
            oracle.alpha,
            oracle.width(best.s, best.t),
            oracle.min_width,
            oracle.max_width,
        ));
    }
    oracle.check_point(best.p, best.s, &format!("region {k}: best's first contact"))?;
    oracle.check_point(
        best.q,
        best.t,
        &format!("region {k}: best's second contact"),
    )?;
    if !region_holds(r, domain, [best.s, best.t]) {
        return Err(format!(
            "region {k}: best ({}, {}) lies outside the region",
            best.s, best.t
        ));
    }
    if least_on_grid < best.min_friction * (1.0 - BEST_PROVEN_SHARE) - BEST_GRID_SLACK - rounding {
        return Err(format!(
            "region {k}: a grid point needs friction {least_on_grid}, below the best's {}",
            best.min_friction
        ));
    }
    Ok(())
}

/// The contact rectangle: every sampled pair force closure, the best grasp inside.
fn check_contact(
    oracle: &Oracle<'_>,
    domain: (f64, f64),
    k: usize,
    r: &GraspRegion,
) -> Result<(), String> {
    let Some(c) = &r.contact else {
        return Ok(());
    };
    let (a, b) = domain;
    for [lo, hi] in [c.s, c.t] {
        if !(lo <= hi && hi - lo <= b - a) {
            return Err(format!("region {k}: contact stretch [{lo}, {hi}]"));
        }
    }
    // (The contact region is the largest product of stretches in the region; it need not
    // hold the most robust grasp, which may lie near the region's edge, as on a width limit.)
    let at =
        |[lo, hi]: [f64; 2], i: usize| lo + (hi - lo) * i as f64 / (CONTACT_SAMPLES - 1) as f64;
    let wrap = |x: f64| a + (x - a).rem_euclid(b - a);
    for i in 0..CONTACT_SAMPLES {
        for j in 0..CONTACT_SAMPLES {
            let (s, t) = (wrap(at(c.s, i)), wrap(at(c.t, j)));
            let slack = CONTACT_ANGLE_SLACK + oracle.angle_rounding(s, t);
            if !oracle.grasps_with_slack(s, t, slack, CONTACT_WIDTH_SLACK) {
                return Err(format!(
                    "region {k}: contact pair ({s}, {t}) of {:?} × {:?}: slip angle {} against \
                     α = {}, width {}",
                    c.s,
                    c.t,
                    oracle.slip_angle(s, t),
                    oracle.alpha,
                    oracle.width(s, t)
                ));
            }
        }
    }
    for (x, [lo, hi]) in [(c.p, c.s), (c.q, c.t)] {
        for (p, u) in x.iter().zip([lo, hi]) {
            oracle.check_point(*p, wrap(u), &format!("region {k}: contact end"))?;
        }
    }
    Ok(())
}
