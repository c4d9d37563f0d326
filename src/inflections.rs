//! Inflections: for spline curves the certified pipeline of `bspline` (curvature numerator →
//! certified root isolation, periodic search on closed curves so the seam is no special case);
//! for analytic shapes the sampled search of `antipodal` (reported as not certified).

use crate::io::{Curve, Shape, SplineCurve};
use bspline::roots::{find_roots, find_roots_periodic, Root, RootKind, RootOptions};
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

/// Certified inflections of a B-spline or NURBS curve.
pub fn spline_inflections(s: &SplineCurve, tol: f64) -> Result<Inflections, ComputeError> {
    // At a cusp the curvature numerator vanishes too: it would pass for an inflection.
    if let Some(u) = bspline::symbolic::singular_point(&s.curve, tol)? {
        return Err(ComputeError::Singular { u });
    }
    let k = curvature_numerator(&s.curve)?;
    let opts = RootOptions::default().tolerance(tol);
    let (a, b) = k.domain();
    let roots = if s.closed {
        match find_roots_periodic(&k, &opts) {
            Ok(r) => r,
            // A clamped closed curve need not be curvature-continuous at its seam.
            Err(bspline::Error::NotPeriodic { .. }) => seam_roots(s, &k, &opts)?,
            Err(e) => return Err(e.into()),
        }
    } else {
        find_roots(&k, a, b, &opts)?
    };
    let roots = sign_changes(&k, roots, s.closed);
    let inflections: Vec<Inflection> = roots
        .iter()
        .map(|r| {
            let p = s.curve.point(r.u);
            Inflection {
                u: r.u,
                p: [p[0], p[1]],
                certified: r.certified,
                kind: r.kind,
                bracket: Some([r.bracket.0, r.bracket.1]),
            }
        })
        .collect();
    Ok(Inflections {
        certified: inflections.iter().all(|i| i.certified),
        inflections,
    })
}

/// Keeps the roots where the curvature changes sign. Simple roots always do; a cluster (a flat
/// stretch, a multiple root) counts only when the curvature has opposite signs on its two sides,
/// taken between it and its neighbours, where isolation proved there is no root: a flat piece
/// between a convex and a concave arc is an inflection, a straight line or a touching zero is
/// not (Jia neglects even-order inflections: they do not change convexity).
fn sign_changes(k: &bspline::BSpline, roots: Vec<Root>, closed: bool) -> Vec<Root> {
    let (a, b) = k.domain();
    let period = b - a;
    let wrap = |u: f64| {
        if closed {
            a + (u - a).rem_euclid(period)
        } else {
            u
        }
    };
    let sign_at = |u: f64| {
        let v = k.eval_scalar(wrap(u));
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    };
    let n = roots.len();
    let side = |i: usize, left: bool| -> i32 {
        let r = &roots[i];
        let (lo, hi) = r.bracket;
        let neighbour = if left {
            match (i.checked_sub(1), closed) {
                (Some(j), _) => Some(roots[j].bracket.1),
                (None, true) => roots.last().map(|x| x.bracket.1 - period),
                (None, false) => Some(a),
            }
        } else {
            match (i + 1 < n, closed) {
                (true, _) => Some(roots[i + 1].bracket.0),
                (false, true) => roots.first().map(|x| x.bracket.0 + period),
                (false, false) => Some(b),
            }
        };
        match neighbour {
            // An open curve's cluster that reaches a domain end has nothing on that side.
            Some(x) if (left && x < lo) || (!left && x > hi) => {
                sign_at(0.5 * (x + if left { lo } else { hi }))
            }
            _ => 0,
        }
    };
    (0..n)
        .filter(|&i| roots[i].kind == RootKind::Simple || side(i, true) * side(i, false) < 0)
        .map(|i| roots[i])
        .collect()
}

/// Roots on a closed curve whose curvature jumps at the seam: the open search, a root seen at
/// both ends reported once, and a sign change across a tangent-continuous seam reported as an
/// (uncertified: decided by two evaluations) inflection at the seam.
fn seam_roots(
    s: &SplineCurve,
    k: &bspline::BSpline,
    opts: &RootOptions,
) -> Result<Vec<Root>, ComputeError> {
    let (a, b) = k.domain();
    let mut roots = find_roots(k, a, b, opts)?;
    let near = |u: f64, v: f64| (u - v).abs() <= 4.0 * opts.tol.max(1e-12 * (b - a));
    let at_start = roots.first().is_some_and(|r| near(r.u, a));
    if at_start && roots.last().is_some_and(|r| near(r.u, b)) {
        roots.pop();
    }
    let at_seam = at_start || roots.last().is_some_and(|r| near(r.u, b));
    let (ka, kb) = (k.eval_scalar(a), k.eval_scalar(b));
    if !at_seam && ka * kb < 0.0 && tangent_continuous(s, a, b) {
        roots.insert(
            0,
            Root {
                u: a,
                bracket: (a, a),
                certified: false,
                kind: RootKind::Simple,
            },
        );
    }
    Ok(roots)
}

fn tangent_continuous(s: &SplineCurve, a: f64, b: f64) -> bool {
    let mut da = [0.0; 4];
    let mut db = [0.0; 4];
    s.curve.eval_derivs(a, 1, &mut da);
    s.curve.eval_derivs(b, 1, &mut db);
    let (ta, tb) = ([da[2], da[3]], [db[2], db[3]]);
    let dot = ta[0] * tb[0] + ta[1] * tb[1];
    let cross = ta[0] * tb[1] - ta[1] * tb[0];
    dot > 0.0 && cross.abs() <= 1e-9 * ta[0].hypot(ta[1]) * tb[0].hypot(tb[1])
}
