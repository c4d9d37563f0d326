//! Certified root isolation for scalar B-spline functions.
//!
//! The function is subdivided until each piece's coefficients show no sign change (no root:
//! proven by the convex-hull property) or exactly one between end values of opposite, trusted
//! signs (exactly one simple root: proven by the variation-diminishing property). A coefficient
//! within its rounding-error bound of zero has no trusted sign and may count either way. Each
//! isolated root is then refined by Newton steps that never leave the bracket (bisection when a
//! step would). What does not separate above the tolerance is reported as a cluster, a possible
//! multiple root, never dropped.
//!
//! [`sign_changes`] builds on it: which roots (and which discontinuities) are sign changes of
//! the function, which clusters are flat stretches, which could not be decided.

use crate::error::{Error, Result};
use crate::refine::Bezier;
use crate::spline::BSpline;
use serde::{Deserialize, Serialize};

mod sign_changes;
pub use sign_changes::{sign_changes, Flat, SignChange, SignChangeKind, SignChanges, FLAT_WIDTH};

/// Options for [`find_roots`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RootOptions {
    /// Parameter tolerance: brackets are refined to this width (never below a few ulps).
    pub tol: f64,
    /// Subdivision depth limit (each level halves a piece).
    pub max_depth: usize,
    /// Limit on the number of pieces examined; what is left is reported as clusters.
    pub max_pieces: usize,
}

impl Default for RootOptions {
    fn default() -> Self {
        Self {
            tol: 1e-12,
            max_depth: 80,
            max_pieces: 200_000,
        }
    }
}

impl RootOptions {
    /// Sets the parameter tolerance.
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tol = tol;
        self
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

/// Unit roundoff.
const EPS: f64 = f64::EPSILON * 0.5;

/// The root searches take scalar functions only.
pub(crate) fn require_scalar(f: &BSpline) -> Result<()> {
    if f.dim() == 1 {
        Ok(())
    } else {
        Err(Error::DimensionMismatch {
            expected: 1,
            got: f.dim(),
        })
    }
}

/// All roots of the scalar function `f` in `[a, b]`, sorted.
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
    require_scalar(f)?;
    if !(opts.tol.is_finite() && opts.tol > 0.0) {
        return Err(Error::NotFinite {
            what: "tolerance",
            index: 0,
            value: opts.tol,
        });
    }
    let g = f.restrict(a, b)?;
    let scale = g.max_abs_coef();
    let mut st = State {
        f: &g,
        eval_err: 2.0 * (g.degree() + 2) as f64 * EPS * scale,
        tol: opts.tol.max(8.0 * f64::EPSILON * a.abs().max(b.abs())),
        opts: *opts,
        pieces: 0,
        roots: Vec::new(),
    };
    // Initial rounding: the coefficients of the restricted spline come from knot insertion.
    let err = 4.0 * (g.degree() + 2) as f64 * EPS * scale;
    if scale == 0.0 {
        st.roots.push(cluster(a, b));
        return Ok(st.roots);
    }
    st.visit(Node::new(g.clone()), err, 0);
    Ok(merge_clusters(st.roots))
}

/// Proves that the scalar function `f` is positive on `[a, b]`: `Ok(None)` when every piece of
/// a subdivision has all coefficients above their rounding-error bound (a proof, by the
/// convex-hull property); else `Ok(Some(u))` with `u` the middle of the first (leftmost) stretch
/// where positivity could not be shown down to the tolerance: there `f` is within rounding of
/// zero or below it. For a double zero (a vanishing speed) that middle is the zero; a stretch
/// that reaches an end of `[a, b]` is reported at that end.
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
    require_scalar(f)?;
    let g = f.restrict(a, b)?;
    let scale = g.max_abs_coef();
    if scale == 0.0 {
        return Ok(Some(a));
    }
    let tol = opts.tol.max(8.0 * f64::EPSILON * a.abs().max(b.abs()));
    let err = 4.0 * (g.degree() + 2) as f64 * EPS * scale;
    // Depth-first, left piece first: unproven pieces come out in order. The first run of
    // touching unproven pieces is where the function reaches zero (within rounding); its middle
    // is the estimate (a double zero, as of a speed, sits in the middle of its rounding zone).
    let mut run: Option<(f64, f64)> = None;
    let mut stack = vec![(Node::new(g), err, 0usize)];
    let mut pieces = 0usize;
    while let Some((node, err, depth)) = stack.pop() {
        pieces += 1;
        let c = node.coefs();
        let (lo, hi) = node.interval();
        if c.iter().all(|&x| x > err) {
            if run.is_some() {
                break;
            }
            continue;
        }
        // A piece within rounding of zero (or below it) is not split further: rounding would
        // keep it unproven at every depth.
        let flat = c.iter().all(|&x| x <= err);
        if flat || hi - lo <= tol || depth >= opts.max_depth || pieces >= opts.max_pieces {
            match &mut run {
                None => run = Some((lo, hi)),
                Some(r) if lo <= r.1 => r.1 = hi,
                Some(_) => break,
            }
            continue;
        }
        let m = 0.5 * (lo + hi);
        let Some((l, r)) = node.split(m) else {
            run = run.or(Some((lo, hi)));
            break;
        };
        let child_err = err
            + 2.0 * (node.degree() + 1) as f64 * EPS * c.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        stack.push((r, child_err, depth + 1));
        stack.push((l, child_err, depth + 1));
    }
    // A stretch at an end of the interval has only one side: the zero is at that end.
    Ok(run.map(|(lo, hi)| match (lo <= a, hi >= b) {
        (true, false) => a,
        (false, true) => b,
        _ => 0.5 * (lo + hi),
    }))
}

/// The roots of a periodic function over one whole period, with no seam: the search runs on
/// the period rotated to start where the function has a trusted sign, so a root at the domain
/// ends is found once, as an interior root. `u` is reported in the domain; a bracket may cross
/// the seam (it is then given in the unwrapped parameter, beyond the domain end).
///
/// `f` must take the same value at both ends of its domain (within rounding), else
/// [`Error::NotPeriodic`].
pub fn find_roots_periodic(f: &BSpline, opts: &RootOptions) -> Result<Vec<Root>> {
    require_scalar(f)?;
    let (a, b) = f.domain();
    let period = b - a;
    let (fa, fb) = (f.eval_scalar(a), f.eval_scalar(b));
    if (fa - fb).abs() > 1e-9 * f.max_abs_coef().max(f64::MIN_POSITIVE) {
        return Err(Error::NotPeriodic { start: fa, end: fb });
    }
    // Start the period where |f| is largest among a few candidates.
    let u0 = (0..16)
        .map(|i| a + period * (i as f64 + 0.5) / 16.0)
        .max_by(|x, y| f.eval_scalar(*x).abs().total_cmp(&f.eval_scalar(*y).abs()))
        .unwrap_or(a + 0.5 * period);
    let rotated = join(
        &f.restrict(u0, b)?,
        &f.restrict(a, u0)?.reparam(b, b + (u0 - a))?,
    );
    let mut roots = find_roots(&rotated, u0, b + (u0 - a), opts)?;
    for r in &mut roots {
        if r.u >= b {
            r.u -= period;
            r.bracket = (r.bracket.0 - period, r.bracket.1 - period);
        }
    }
    roots.sort_by(|x, y| x.u.total_cmp(&y.u));
    Ok(roots)
}

/// Joins two clamped splines of one degree where the first ends and the second starts
/// (a knot of multiplicity p there: C⁰, which is all their common end value guarantees).
fn join(left: &BSpline, right: &BSpline) -> BSpline {
    let p = left.degree();
    let mut knots = left.knots()[..left.knots().len() - 1].to_vec();
    knots.extend_from_slice(&right.knots()[p + 1..]);
    let mut coefs = left.coefs().to_vec();
    if let (Some(last), Some(first)) = (coefs.last_mut(), right.coefs().first()) {
        *last = 0.5 * (*last + first);
    }
    coefs.extend_from_slice(&right.coefs()[1..]);
    BSpline::from_raw(p, 1, knots, coefs)
}

fn cluster(lo: f64, hi: f64) -> Root {
    Root {
        u: 0.5 * (lo + hi),
        bracket: (lo, hi),
        certified: false,
        kind: RootKind::Cluster,
    }
}

/// Joins clusters whose brackets touch (the same unresolved root seen from two pieces).
fn merge_clusters(mut roots: Vec<Root>) -> Vec<Root> {
    roots.sort_by(|x, y| x.bracket.0.total_cmp(&y.bracket.0));
    let mut out: Vec<Root> = Vec::with_capacity(roots.len());
    for r in roots {
        if let Some(last) = out.last_mut() {
            if last.kind == RootKind::Cluster
                && r.kind == RootKind::Cluster
                && r.bracket.0 <= last.bracket.1
            {
                *last = cluster(last.bracket.0, last.bracket.1.max(r.bracket.1));
                continue;
            }
        }
        out.push(r);
    }
    out
}

/// A piece of the function: a single Bézier piece (fast de Casteljau path) or a B-spline.
enum Node {
    Bezier(Bezier),
    Spline(BSpline),
}

impl Node {
    fn new(g: BSpline) -> Self {
        if g.n_ctrl() == g.degree() + 1 {
            let (a, b) = g.domain();
            Node::Bezier(Bezier {
                a,
                b,
                degree: g.degree(),
                dim: 1,
                coefs: g.coefs().to_vec(),
            })
        } else {
            Node::Spline(g)
        }
    }
    fn coefs(&self) -> &[f64] {
        match self {
            Node::Bezier(z) => &z.coefs,
            Node::Spline(s) => s.coefs(),
        }
    }
    fn interval(&self) -> (f64, f64) {
        match self {
            Node::Bezier(z) => (z.a, z.b),
            Node::Spline(s) => s.domain(),
        }
    }
    fn degree(&self) -> usize {
        match self {
            Node::Bezier(z) => z.degree,
            Node::Spline(s) => s.degree(),
        }
    }
    fn value(&self, u: f64) -> f64 {
        match self {
            Node::Bezier(z) => bernstein_eval(&z.coefs, (u - z.a) / (z.b - z.a)),
            Node::Spline(s) => s.eval_scalar(u),
        }
    }
    /// A split point near the middle where the value has a trusted sign, if there is one.
    fn split_point(&self, err: f64) -> f64 {
        let (lo, hi) = self.interval();
        let mut candidates: smallvec::SmallVec<[f64; 12]> = smallvec::SmallVec::new();
        if let Node::Spline(s) = self {
            // Prefer the interior knot nearest the middle: children get fewer pieces.
            let mid = 0.5 * (lo + hi);
            if let Some(k) = s
                .breakpoints()
                .into_iter()
                .filter(|&k| k > lo && k < hi)
                .min_by(|x, y| (x - mid).abs().total_cmp(&(y - mid).abs()))
            {
                candidates.push(k);
            }
        }
        for f in [0.5, 0.4375, 0.5625, 0.375, 0.625, 0.3125, 0.6875] {
            candidates.push(lo + (hi - lo) * f);
        }
        candidates
            .iter()
            .copied()
            .find(|&u| self.value(u).abs() > 2.0 * err)
            .unwrap_or(0.5 * (lo + hi))
    }
    fn split(&self, u: f64) -> Option<(Node, Node)> {
        match self {
            Node::Bezier(z) => {
                let (l, r) = z.split(u);
                Some((Node::Bezier(l), Node::Bezier(r)))
            }
            Node::Spline(s) => {
                let (l, r) = s.split_at(u).ok()?;
                Some((Node::new(l), Node::new(r)))
            }
        }
    }
}

/// Value of a Bernstein polynomial at the local parameter `s`, by de Casteljau (stable).
fn bernstein_eval(c: &[f64], s: f64) -> f64 {
    let mut w: smallvec::SmallVec<[f64; 32]> = c.iter().copied().collect();
    for level in 1..c.len() {
        for k in 0..c.len() - level {
            w[k] = (1.0 - s) * w[k] + s * w[k + 1];
        }
    }
    w[0]
}

/// The largest number of sign changes the coefficient sequence can have, when coefficients
/// within `err` of zero may take either sign.
fn max_sign_changes(c: &[f64], err: f64) -> usize {
    const NONE: i64 = i64::MIN / 2;
    let (mut pos, mut neg) = (NONE, NONE);
    for (i, &x) in c.iter().enumerate() {
        let (can_pos, can_neg) = (x > -err, x < err);
        let start = if i == 0 { 0 } else { NONE };
        let np = if can_pos {
            pos.max(neg + 1).max(start)
        } else {
            NONE
        };
        let nn = if can_neg {
            neg.max(pos + 1).max(start)
        } else {
            NONE
        };
        pos = np;
        neg = nn;
    }
    pos.max(neg).max(0) as usize
}

struct State<'a> {
    f: &'a BSpline,
    eval_err: f64,
    tol: f64,
    opts: RootOptions,
    pieces: usize,
    roots: Vec<Root>,
}

impl State<'_> {
    fn visit(&mut self, node: Node, err: f64, depth: usize) {
        self.pieces += 1;
        let c = node.coefs();
        let (lo, hi) = node.interval();
        let changes = max_sign_changes(c, err);
        if changes == 0 {
            return;
        }
        let (c0, cn) = (c[0], c[c.len() - 1]);
        if changes == 1 && c0.abs() > err && cn.abs() > err && (c0 > 0.0) != (cn > 0.0) {
            let root = self.refine(&node);
            self.roots.push(root);
            return;
        }
        if c.iter().all(|x| x.abs() <= err)
            || hi - lo <= self.tol
            || depth >= self.opts.max_depth
            || self.pieces >= self.opts.max_pieces
        {
            self.roots.push(cluster(lo, hi));
            return;
        }
        let m = node.split_point(err);
        let Some((l, r)) = node.split(m) else {
            self.roots.push(cluster(lo, hi));
            return;
        };
        // Each split level is p convex combinations per coefficient.
        let child_err = err
            + 2.0 * (node.degree() + 1) as f64 * EPS * c.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        self.visit(l, child_err, depth + 1);
        self.visit(r, child_err, depth + 1);
    }

    /// Safeguarded Newton inside a bracket with end values of opposite trusted signs.
    ///
    /// Evaluation uses the top-level function (`self.f`), whose rounding error `self.eval_err`
    /// is far below that of a deeply subdivided piece. The bracket reported is the last one
    /// whose end values have trusted signs; the estimate goes on narrowing to the tolerance on
    /// computed signs, which is the best the floating-point function can say.
    fn refine(&self, node: &Node) -> Root {
        let (mut lo, mut hi) = node.interval();
        let (mut tlo, mut thi) = (lo, hi);
        let c = node.coefs();
        let (flo, fhi) = (c[0], c[c.len() - 1]);
        let rising = fhi > 0.0;
        // Start from the secant (regula falsi) point of the end values.
        let mut x = lo + (hi - lo) * (flo / (flo - fhi));
        let mut d = [0.0; 2];
        for _ in 0..200 {
            self.f.eval_d1(x, &mut d);
            let (fx, dfx) = (d[0], d[1]);
            if fx == 0.0 {
                lo = x;
                hi = x;
                break;
            }
            let right_of_root = (fx > 0.0) == rising;
            if right_of_root {
                hi = x;
            } else {
                lo = x;
            }
            if fx.abs() > self.eval_err {
                if right_of_root {
                    thi = x;
                } else {
                    tlo = x;
                }
            }
            if hi - lo <= self.tol {
                break;
            }
            let newton = x - fx / dfx;
            if newton > lo && newton < hi && dfx != 0.0 {
                // Newton approaches a simple root from one side, so the bracket need not
                // shrink: stop once the step is far below the tolerance (the error is then of
                // the order of its square). The outward probes below bracket the result.
                let converged = (newton - x).abs() <= 0.25 * self.tol;
                x = newton;
                if converged {
                    break;
                }
            } else {
                x = 0.5 * (lo + hi);
            }
        }
        // A last Newton step from the final iterate, kept inside the bracket.
        self.f.eval_d1(x, &mut d);
        let step = if d[1] != 0.0 { x - d[0] / d[1] } else { x };
        let u = if step.is_finite() {
            step.clamp(lo, hi)
        } else {
            0.5 * (lo + hi)
        };
        // Where the last trusted values are far from the estimate (the function was within
        // rounding of zero near the root), probe outward for the nearest trusted signs.
        let trusted = |v: f64, right: bool| {
            let fv = self.f.eval_scalar(v);
            fv.abs() > self.eval_err && ((fv > 0.0) == rising) == right
        };
        let mut delta = self.tol;
        while u - delta > tlo {
            if trusted(u - delta, false) {
                tlo = u - delta;
                break;
            }
            delta *= 4.0;
        }
        let mut delta = self.tol;
        while u + delta < thi {
            if trusted(u + delta, true) {
                thi = u + delta;
                break;
            }
            delta *= 4.0;
        }
        Root {
            u,
            bracket: (tlo.min(u), thi.max(u)),
            certified: true,
            kind: RootKind::Simple,
        }
    }
}
