//! Certified root counting and isolation for scalar functions in piecewise Bézier form.
//!
//! [`count_roots`] reads the control polygon of a function over an interval with the bound on
//! each coefficient's error ([`Count`], the one counter every certified decision goes through).
//! [`find_roots_in`] subdivides until each part's polygon shows no root or exactly one simple
//! root, and refines each isolated root by Newton steps that never leave its bracket. What does
//! not separate above the tolerance is reported as a cluster, a possible multiple root, never
//! dropped. The B-spline entry points ([`find_roots`], [`prove_positive`],
//! [`find_roots_periodic`]) take the spline's coefficients as exact and run on its pieces.
//!
//! [`sign_changes`] builds on it: which roots (and which discontinuities) are sign changes of
//! the function, which clusters are flat stretches, which could not be decided.

use crate::error::{Error, Result};
use crate::piecewise::Piecewise;
use crate::spline::BSpline;
use numeric::rounding::ulps;
use numeric::subdivide::{depth_first, Decision};
use serde::{Deserialize, Serialize};

mod count;
mod isolate;
mod sign_changes;
mod subdivision;
pub use count::{most_sign_changes, Count, SignCount};
use isolate::{merge_clusters, Isolation};
pub use sign_changes::{
    sign_changes, sign_changes_in, Flat, SignChange, SignChangeKind, SignChanges, FLAT_WIDTH,
};
use subdivision::{split_point, Part};

/// How close the values at the two ends of a domain must be, relative to the largest
/// coefficient, for a function to count as periodic: the two ends are evaluated separately,
/// so a periodic function's end values differ by rounding, far below this.
const PERIODIC_MATCH: f64 = 1e-9;

/// Options for [`find_roots`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RootOptions {
    /// Parameter tolerance: brackets are refined to this width (never below a few ulps).
    pub tol: f64,
    /// Subdivision depth limit (each level halves a piece).
    pub max_depth: usize,
    /// Limit on the number of pieces examined; what is left is reported as clusters.
    pub max_pieces: usize,
    /// The function's sign is continuous across its breaks even where the function jumps: it
    /// is, piece by piece, a positive multiple of a continuous function (the foot-point
    /// function `w³ (C − q) · C′` of a regular curve whose homogeneous form is only C0 at a
    /// knot). A cluster at a break can then be proven one simple root (see
    /// [`find_roots_in`]).
    pub sign_continuous: bool,
}

impl Default for RootOptions {
    fn default() -> Self {
        Self {
            // (The workspace's one: brackets 1e-12 wide on a domain of size ~1, the unit-size
            // frame the callers work in, are some 500 times the few ulps allowed at the least,
            // so decisions stay above rounding, and far finer than any feature of a curve.)
            tol: numeric::tolerance::DEFAULT_PARAM_TOL,
            max_depth: 80,
            max_pieces: 200_000,
            sign_continuous: false,
        }
    }
}

impl RootOptions {
    /// Declares the function's sign continuous across its breaks (see the field).
    pub fn sign_continuous(mut self, yes: bool) -> Self {
        self.sign_continuous = yes;
        self
    }

    /// Sets the parameter tolerance.
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tol = tol;
        self
    }

    /// The tolerance used on `[a, b]`: the one asked for, but never below a few units of
    /// rounding of the parameters there (no bracket can be narrower).
    fn effective_tol(&self, a: f64, b: f64) -> f64 {
        self.tol.max(ulps(8.0) * a.abs().max(b.abs()))
    }

    fn validate(&self) -> Result<()> {
        if self.tol.is_finite() && self.tol > 0.0 {
            Ok(())
        } else {
            Err(Error::NotFinite {
                what: "tolerance",
                index: 0,
                value: self.tol,
            })
        }
    }
}

/// What is known about a reported root.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RootKind {
    /// Exactly one simple root in the bracket (proven when `certified`).
    Simple,
    /// The function is within rounding of zero on the bracket and the roots did not separate
    /// above the tolerance: a multiple root, a cluster, or a zero stretch.
    Cluster,
}

/// One root (or unresolved cluster) of a scalar function.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Root {
    /// Best estimate of the root.
    pub u: f64,
    /// An interval that contains it.
    pub bracket: (f64, f64),
    /// True when existence and uniqueness in the bracket follow from coefficient signs.
    pub certified: bool,
    /// Simple root or cluster.
    pub kind: RootKind,
}

/// The root searches take scalar functions only.
fn require_scalar(dim: usize) -> Result<()> {
    if dim == 1 {
        Ok(())
    } else {
        Err(Error::DimensionMismatch {
            expected: 1,
            got: dim,
        })
    }
}

/// `[a, b]` must be a non-empty interval inside the domain.
fn require_inside(f: &Piecewise, a: f64, b: f64) -> Result<()> {
    let (lo, hi) = f.domain();
    if a.is_finite() && b.is_finite() && lo <= a && a < b && b <= hi {
        Ok(())
    } else {
        Err(Error::OutOfDomain {
            a,
            b,
            domain: (lo, hi),
        })
    }
}

/// What the control polygon of `Σ weights[c] f_c` over `[lo, hi]` (inside the domain) proves
/// about its roots there, with every coefficient's error bounded (see [`Count`]).
///
/// ```
/// use bspline::roots::{count_roots, Count};
/// use bspline::{BSpline, Piecewise};
/// // (u − 0.2)(u − 0.7) on [0, 1]: open over [0, 1], exactly one root on [0, 0.5].
/// let f = Piecewise::from_bspline(&BSpline::bezier(1, vec![0.14, -0.31, 0.24]).unwrap());
/// assert_eq!(count_roots(&f, &[1.0], 0.0, 1.0), Count::Open);
/// assert!(matches!(count_roots(&f, &[1.0], 0.0, 0.5), Count::One(..)));
/// assert_eq!(count_roots(&f, &[1.0], 0.8, 1.0), Count::Zero);
/// ```
pub fn count_roots(f: &Piecewise, weights: &[f64], lo: f64, hi: f64) -> Count {
    let mut count = SignCount::new(lo, hi);
    f.for_each_restricted(weights, lo, hi, |i, x0, x1, c, err| {
        count.piece(x0, x1, c, err, f.continuity(i))
    });
    count.finish()
}

/// The piecewise form of a B-spline handed to the entry points below: its coefficients are
/// taken to be computed ones, in error by [`crate::rounding::computed_coefficients`].
pub(crate) fn computed(f: &BSpline) -> Piecewise {
    let err = crate::rounding::computed_coefficients(f.degree(), f.max_abs_coef());
    Piecewise::from_bspline_with_error(f, err)
}

/// All roots of the scalar B-spline `f` in `[a, b]`, sorted (its coefficients taken as computed
/// ones, known to [`crate::rounding::computed_coefficients`]).
///
/// ```
/// use bspline::{roots::{find_roots, RootOptions}, BSpline};
/// // (u − 0.2)(u − 0.7) as a quadratic Bézier: coefficients from the blossom.
/// let f = BSpline::bezier(1, vec![0.14, -0.31, 0.24]).unwrap();
/// let r = find_roots(&f, 0.0, 1.0, &RootOptions::default()).unwrap();
/// assert_eq!(r.len(), 2);
/// assert!(r.iter().all(|x| x.certified));
/// assert!((r[0].u - 0.2).abs() < 1e-12 && (r[1].u - 0.7).abs() < 1e-12);
/// ```
pub fn find_roots(f: &BSpline, a: f64, b: f64, opts: &RootOptions) -> Result<Vec<Root>> {
    require_scalar(f.dim())?;
    opts.validate()?;
    find_roots_in(&computed(f), a, b, opts)
}

/// All roots of the scalar piecewise function `f` in `[a, b]` (inside its domain), sorted:
/// certified simple roots where the coefficient signs prove one, clusters elsewhere. A cluster
/// with trusted values of opposite signs on either side, between which the derivative is
/// proven of one sign and the function does not jump (or jumps keeping its sign,
/// [`RootOptions::sign_continuous`]), is one simple root, proven so.
pub fn find_roots_in(f: &Piecewise, a: f64, b: f64, opts: &RootOptions) -> Result<Vec<Root>> {
    require_scalar(f.dim())?;
    opts.validate()?;
    require_inside(f, a, b)?;
    let mut search = Isolation {
        f,
        tol: opts.effective_tol(a, b),
        opts: *opts,
        parts: 0,
        roots: Vec::new(),
    };
    search.isolate(Part::of(f, a, b));
    let roots = merge_clusters(std::mem::take(&mut search.roots));
    Ok(search.separate_simple_clusters(roots, a, b))
}

/// Proves that the scalar function `f` is positive on `[a, b]`: `Ok(None)` when every piece of
/// a subdivision has all coefficients above their error bound (a proof, by the convex-hull
/// property); else `Ok(Some(u))` with `u` the middle of the first (leftmost) stretch where
/// positivity could not be shown down to the tolerance: there `f` is within rounding of zero
/// or below it. For a double zero (a vanishing speed) that middle is the zero; a stretch that
/// reaches an end of `[a, b]` is reported at that end.
///
/// ```
/// use bspline::{roots::{prove_positive, RootOptions}, BSpline};
/// // (u − 0.5)² + 0.01 > 0, and (u − 0.5)² touches zero at 0.5.
/// let pos = BSpline::bezier(1, vec![0.26, -0.24, 0.26]).unwrap();
/// let touch = BSpline::bezier(1, vec![0.25, -0.25, 0.25]).unwrap();
/// let opts = RootOptions::default();
/// assert_eq!(prove_positive(&pos, 0.0, 1.0, &opts).unwrap(), None);
/// let u = prove_positive(&touch, 0.0, 1.0, &opts).unwrap().unwrap();
/// assert!((u - 0.5).abs() < 1e-6);
/// ```
pub fn prove_positive(f: &BSpline, a: f64, b: f64, opts: &RootOptions) -> Result<Option<f64>> {
    require_scalar(f.dim())?;
    prove_positive_in(&computed(f), a, b, opts)
}

/// [`prove_positive`] on a piecewise function (inside its domain).
pub fn prove_positive_in(f: &Piecewise, a: f64, b: f64, opts: &RootOptions) -> Result<Option<f64>> {
    require_scalar(f.dim())?;
    opts.validate()?;
    require_inside(f, a, b)?;
    let tol = opts.effective_tol(a, b);
    // Depth-first, left part first: unproven parts come out in order. The first run of
    // touching unproven parts is where the function reaches zero (within rounding); its middle
    // is the estimate (a double zero, as of a speed, sits in the middle of its rounding zone).
    let mut run: Option<(f64, f64)> = None;
    let mut parts = 0usize;
    depth_first(Part::of(f, a, b), opts.max_depth, |part, visit| {
        parts += 1;
        let (lo, hi) = part.interval();
        let positive = part
            .spans
            .iter()
            .all(|s| s.coefs.iter().all(|&x| x > s.err));
        if positive {
            return match run {
                Some(_) => Decision::Stop(()),
                None => Decision::Decided,
            };
        }
        // A part within rounding of zero (or below it) is not split further: rounding would
        // keep it unproven at every depth.
        let flat = part
            .spans
            .iter()
            .all(|s| s.coefs.iter().all(|&x| x <= s.err));
        if flat || hi - lo <= tol || !visit.can_halve || parts >= opts.max_pieces {
            return match &mut run {
                None => {
                    run = Some((lo, hi));
                    Decision::Decided
                }
                Some(r) if lo <= r.1 => {
                    r.1 = hi;
                    Decision::Decided
                }
                Some(_) => Decision::Stop(()),
            };
        }
        let (left, right) = part.split(f, split_point(f, lo, hi));
        Decision::Halve(left, right)
    });
    // A stretch at an end of the interval has only one side: the zero is at that end.
    Ok(run.map(|(lo, hi)| match (lo <= a, hi >= b) {
        (true, false) => a,
        (false, true) => b,
        _ => 0.5 * (lo + hi),
    }))
}

/// The roots of a periodic B-spline over one whole period (see [`find_roots_periodic_in`]).
/// `f` must take the same value at both ends of its domain (within `1e-9` of its largest
/// coefficient), else [`Error::NotPeriodic`]; it is then taken as continuous across the seam.
pub fn find_roots_periodic(f: &BSpline, opts: &RootOptions) -> Result<Vec<Root>> {
    require_scalar(f.dim())?;
    let (a, b) = f.domain();
    let (fa, fb) = (f.eval_scalar(a), f.eval_scalar(b));
    if (fa - fb).abs() > PERIODIC_MATCH * f.max_abs_coef().max(f64::MIN_POSITIVE) {
        return Err(Error::NotPeriodic { start: fa, end: fb });
    }
    find_roots_periodic_in(&computed(f).with_periodic_seam(0), opts)
}

/// The roots of a periodic function (declared so: [`Piecewise::with_periodic_seam`]) over one
/// whole period, with no seam: the search runs on the period rotated to start where the
/// function has a trusted sign, so a root at the domain ends is found once, as an interior
/// root. `u` is reported in the domain; a bracket may cross the seam (it is then given in the
/// unwrapped parameter, beyond the domain end).
pub fn find_roots_periodic_in(f: &Piecewise, opts: &RootOptions) -> Result<Vec<Root>> {
    require_scalar(f.dim())?;
    let (a, b) = f.domain();
    if !f.is_periodic() {
        let (mut fa, mut fb) = ([0.0], [0.0]);
        f.eval(a, &mut fa);
        f.eval(b, &mut fb);
        return Err(Error::NotPeriodic {
            start: fa[0],
            end: fb[0],
        });
    }
    let period = b - a;
    // Start the period where |f| is largest among a few candidates.
    let value = |u: f64| {
        let mut v = [0.0];
        f.eval(u, &mut v);
        v[0].abs()
    };
    let u0 = (0..16)
        .map(|i| a + period * (i as f64 + 0.5) / 16.0)
        .max_by(|x, y| value(*x).total_cmp(&value(*y)))
        .unwrap_or(a + 0.5 * period);
    let Some(rotated) = f.rotated(u0) else {
        // Breaks too close for the shifted period: the seam stays where it is.
        return find_roots_in(f, a, b, opts);
    };
    let (r0, r1) = rotated.domain();
    let mut roots = find_roots_in(&rotated, r0, r1, opts)?;
    for r in &mut roots {
        if r.u >= b {
            r.u -= period;
            r.bracket = (r.bracket.0 - period, r.bracket.1 - period);
        }
    }
    roots.sort_by(|x, y| x.u.total_cmp(&y.u));
    Ok(roots)
}

/// The value of the scalar `f` at `u` and the bound on its error there.
fn value(f: &Piecewise, u: f64) -> (f64, f64) {
    let mut v = [0.0];
    f.eval(u, &mut v);
    (v[0], f.eval_error(f.piece_at(u), 0))
}
