//! Inflections: for spline curves the certified pipeline of `bspline` (curvature numerator →
//! its certified sign changes, periodic search on closed curves so the seam is no special case);
//! for analytic shapes the sampled search of `antipodal` (reported as not certified).

use crate::io::{Curve, Shape, SplineCurve};
use bspline::roots::{sign_changes, RootKind, RootOptions, SignChangeKind};
use bspline::symbolic::curvature_numerator;
use serde::Serialize;
use thiserror::Error;

/// A computation that could not be carried out (the input itself was valid).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ComputeError {
    /// The antipodal crate refused the curve or the options.
    #[error(transparent)]
    Antipodal(#[from] antipodal::Error),
    /// The spline library refused an operation.
    #[error("spline arithmetic failed: {0}")]
    Spline(#[from] bspline::Error),
    /// The curve's speed vanishes (a cusp or a stationary point): the curvature, and so an
    /// inflection, is undefined there.
    #[error("the curve is singular (zero speed or cusp) near u = {u}")]
    Singular {
        /// Where the speed is within rounding of zero.
        u: f64,
    },
}

/// One inflection (or an unresolved cluster of them).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Inflection {
    /// Parameter.
    pub u: f64,
    /// Point on the curve.
    pub p: [f64; 2],
    /// Existence and uniqueness in `bracket` are proven by coefficient signs.
    pub certified: bool,
    /// `simple` or `cluster` (curvature within rounding of zero on the bracket: a flat piece,
    /// a higher-order zero, or roots closer than the tolerance).
    pub kind: RootKind,
    /// An interval of parameters that provably contains it (may cross the seam of a closed
    /// curve); absent where the inflection was found by sampling.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bracket: Option<[f64; 2]>,
}

/// The inflections of a curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Inflections {
    /// Sorted by parameter.
    pub inflections: Vec<Inflection>,
    /// True when every reported inflection is certified.
    pub certified: bool,
}

/// All inflections of `curve` with parameter tolerance `tol`.
pub fn inflections(curve: &Curve, tol: f64) -> Result<Inflections, ComputeError> {
    match &curve.shape {
        Shape::Spline(s) => spline_inflections(s, tol),
        // Analytic shapes have no symbolic form: Jia's sampled search in `antipodal`.
        Shape::Analytic(_) => {
            let plane = curve.plane_curve()?;
            let opts = antipodal::Options::default().tolerance(tol);
            let found = antipodal::inflections(plane.as_ref(), &opts)?;
            Ok(Inflections {
                inflections: found
                    .inflections
                    .iter()
                    .map(|i| Inflection {
                        u: i.u,
                        p: i.p,
                        certified: found.certified,
                        kind: RootKind::Simple,
                        bracket: None,
                    })
                    .collect(),
                certified: found.certified,
            })
        }
    }
}

/// Certified inflections of a B-spline or NURBS curve: the sign changes of its curvature
/// numerator ([`bspline::roots::sign_changes`]).
pub fn spline_inflections(s: &SplineCurve, tol: f64) -> Result<Inflections, ComputeError> {
    // At a cusp the curvature numerator vanishes too: it would pass for an inflection.
    if let Some(u) = bspline::symbolic::singular_point(&s.curve, tol)? {
        return Err(ComputeError::Singular { u });
    }
    let k = curvature_numerator(&s.curve)?;
    let opts = RootOptions::default().tolerance(tol);
    let found = sign_changes(&k, s.closed, &opts)?;
    let (a, b) = k.domain();
    let mut inflections: Vec<Inflection> = Vec::new();
    let mut push = |u: f64, bracket: (f64, f64), certified: bool, kind: RootKind| {
        let p = s.curve.point(u);
        inflections.push(Inflection {
            u,
            p: [p[0], p[1]],
            certified,
            kind,
            bracket: Some([bracket.0, bracket.1]),
        });
    };
    for c in &found.changes {
        match c.kind {
            SignChangeKind::Simple => push(c.u, c.bracket, c.certified, RootKind::Simple),
            SignChangeKind::Cluster => push(c.u, c.bracket, c.certified, RootKind::Cluster),
            // The seam of a clamped closed curve that is not curvature-continuous there: an
            // inflection where the tangent is continuous (at a corner the curve does not
            // inflect), decided by evaluations, so not certified.
            SignChangeKind::Jump if s.closed && c.u == a => {
                if tangent_continuous(s, a, b, 1e-9) {
                    push(c.u, c.bracket, false, RootKind::Simple);
                }
            }
            // A jump of the curvature at an interior knot (a quadratic spline's every knot,
            // or a knot of high multiplicity): an inflection where the tangent is continuous.
            // Below full multiplicity less one the curve is C¹ there (certified as the jump);
            // otherwise the two one-sided tangents are compared (not certified).
            SignChangeKind::Jump => {
                let (continuous, certain) = interior_tangent_continuous(s, c.u);
                if continuous {
                    push(c.u, c.bracket, c.certified && certain, RootKind::Simple);
                }
            }
        }
    }
    // A flat piece between a convex and a concave arc is an inflection (unresolved: a cluster);
    // a straight line or a touching zero is not (Jia neglects even-order inflections: they do
    // not change convexity).
    for f in found.flats.iter().filter(|f| f.sign_change) {
        push(f.u, f.bracket, false, RootKind::Cluster);
    }
    inflections.sort_by(|x, y| x.u.total_cmp(&y.u));
    Ok(Inflections {
        certified: inflections.iter().all(|i| i.certified),
        inflections,
    })
}

/// Whether the tangent is continuous at the interior knot `u`, and whether that is certain
/// (knot multiplicity below the degree: the curve is C¹ there) or read from the one-sided
/// tangents a little to each side.
fn interior_tangent_continuous(s: &SplineCurve, u: f64) -> (bool, bool) {
    let h = s.curve.homogeneous();
    let mult = h.knots().iter().filter(|&&k| k == u).count();
    if mult < h.degree() {
        return (true, true);
    }
    let (a, b) = h.domain();
    let d = 1e-9 * (b - a);
    (tangent_continuous(s, u + d, u - d, 1e-6), false)
}

/// The tangent directions at `b` (coming in) and at `a` (going out) agree to within the sine
/// `tol`.
fn tangent_continuous(s: &SplineCurve, a: f64, b: f64, tol: f64) -> bool {
    let mut da = [0.0; 4];
    let mut db = [0.0; 4];
    s.curve.eval_derivs(a, 1, &mut da);
    s.curve.eval_derivs(b, 1, &mut db);
    let (ta, tb) = ([da[2], da[3]], [db[2], db[3]]);
    let dot = ta[0] * tb[0] + ta[1] * tb[1];
    let cross = ta[0] * tb[1] - ta[1] * tb[0];
    dot > 0.0 && cross.abs() <= tol * ta[0].hypot(ta[1]) * tb[0].hypot(tb[1])
}
