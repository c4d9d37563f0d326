//! Root isolation: subdivision of a function into parts with at most one certified root,
//! each refined by a safeguarded Newton iteration, and the clusters left over joined, or
//! proven one simple root where the signs on their two sides and the derivative allow.

use super::subdivision::{split_point, Part};
use super::{prove_positive_in, value, Count, Root, RootKind, RootOptions};
use crate::piecewise::Piecewise;
use numeric::subdivide::{depth_first, Decision, Visit};

fn cluster(lo: f64, hi: f64) -> Root {
    Root {
        u: 0.5 * (lo + hi),
        bracket: (lo, hi),
        certified: false,
        kind: RootKind::Cluster,
    }
}

/// Joins clusters whose brackets touch (the same unresolved root seen from two parts).
pub(super) fn merge_clusters(mut roots: Vec<Root>) -> Vec<Root> {
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

/// Subdivision of one scalar function into parts with at most one certified root.
pub(super) struct Isolation<'a> {
    pub(super) f: &'a Piecewise,
    pub(super) tol: f64,
    pub(super) opts: RootOptions,
    pub(super) parts: usize,
    pub(super) roots: Vec<Root>,
}

/// Widenings (by 4 each) of a cluster's bracket searched for trusted values on both sides:
/// up to 4^12 ≈ 1.7e7 times its width, far inside any neighbouring feature at a bracket of the
/// tolerance's width.
const CLUSTER_WIDENINGS: usize = 12;

impl Isolation<'_> {
    /// The clusters that are one simple root, proven and refined: where the function has
    /// trusted values of opposite signs on both sides of the bracket (short of the next roots)
    /// and its derivative is proven of one sign between them. Rounding, not multiplicity, can
    /// keep the control polygon from proving a root: a function whose coefficients are large
    /// beside its slope (a foot-point function `(C − q) · C′` of a small arc from a far point)
    /// is within its error bound on a bracket wider than the tolerance. A cluster at an end of
    /// the search has one side only, and stays one.
    pub(super) fn separate_simple_clusters(
        &self,
        mut roots: Vec<Root>,
        a: f64,
        b: f64,
    ) -> Vec<Root> {
        // (The derivative is made once, for the first cluster that needs it.)
        let mut df: Option<Piecewise> = None;
        for k in 0..roots.len() {
            if roots[k].kind != RootKind::Cluster {
                continue;
            }
            let (lo, hi) = roots[k].bracket;
            let floor = if k > 0 { roots[k - 1].bracket.1 } else { a };
            let ceiling = roots.get(k + 1).map_or(b, |r| r.bracket.0);
            if lo <= floor || hi >= ceiling {
                continue;
            }
            let mut width = (hi - lo).max(self.tol);
            for _ in 0..CLUSTER_WIDENINGS {
                let (left, right) = ((lo - width).max(floor), (hi + width).min(ceiling));
                let ((fl, el), (fr, er)) = (value(self.f, left), value(self.f, right));
                if fl.abs() > el && fr.abs() > er {
                    let opposite = (fl > 0.0) != (fr > 0.0);
                    if opposite
                        && self.monotone(df.get_or_insert_with(|| self.f.derivative()), left, right)
                    {
                        roots[k] = self.refine(left, right, fl < 0.0);
                    }
                    break;
                }
                if left == floor && right == ceiling {
                    break;
                }
                width *= 4.0;
            }
        }
        roots
    }

    /// Whether the derivative `df` is proven of one sign on `[lo, hi]` (piece by piece),
    /// across no jump of the function that may change its sign (a sign change at a jump is no
    /// root).
    fn monotone(&self, df: &Piecewise, lo: f64, hi: f64) -> bool {
        let breaks = self.f.breaks();
        let jump = !self.opts.sign_continuous
            && (0..breaks.len())
                .any(|k| breaks[k] > lo && breaks[k] < hi && self.f.continuity(k) < 0);
        if jump {
            return false;
        }
        let rising = prove_positive_in(df, lo, hi, &self.opts);
        let falling = prove_positive_in(&df.scale(-1.0), lo, hi, &self.opts);
        matches!(rising, Ok(None)) || matches!(falling, Ok(None))
    }

    /// Subdivides `root` depth first, the left part first (so the roots come in order), until
    /// each part holds no root, one (refined and kept) or a cluster (a part within rounding of
    /// zero, of the tolerance's width, at the depth bound or past the budget of parts).
    pub(super) fn isolate(&mut self, root: Part) {
        depth_first(root, self.opts.max_depth, |part, visit| {
            self.decide(part, visit)
        });
    }

    /// What [`Self::isolate`] does with one part.
    fn decide(&mut self, part: Part, visit: Visit) -> Decision<Part, ()> {
        self.parts += 1;
        let (lo, hi) = part.interval();
        let (count, flat) = part.count();
        match count.finish() {
            Count::Zero => return Decision::Decided,
            Count::One(a, b) => {
                let root = self.refine(a.max(lo), b.min(hi), count.starts_negative());
                self.roots.push(root);
                return Decision::Decided;
            }
            Count::AtEnd(_) | Count::Open => {}
        }
        // A straight stretch is within rounding of zero on one interval, found in closed form
        // rather than by halving toward it (a root at an end takes some forty halvings).
        if let Some((z0, z1)) = part.straight_zeros() {
            self.roots.push(self.cluster_of_width(z0, z1, lo, hi));
            return Decision::Decided;
        }
        if flat || hi - lo <= self.tol || !visit.can_halve || self.parts >= self.opts.max_pieces {
            self.roots.push(cluster(lo, hi));
            return Decision::Decided;
        }
        let (left, right) = part.split(self.f, split_point(self.f, lo, hi));
        Decision::Halve(left, right)
    }

    /// A cluster on `[z0, z1]`, widened to the tolerance inside `[lo, hi]` (as a part halved
    /// down to the tolerance would give).
    fn cluster_of_width(&self, z0: f64, z1: f64, lo: f64, hi: f64) -> Root {
        if z1 - z0 >= self.tol || hi - lo <= self.tol {
            return cluster(z0, z1);
        }
        let start = (0.5 * (z0 + z1 - self.tol)).clamp(lo, hi - self.tol);
        cluster(start, start + self.tol)
    }

    /// Safeguarded Newton inside a bracket where the function has exactly one simple root and
    /// end values of opposite, trusted signs (`rising`: negative at `a`). The bracket reported is the last one whose end
    /// values have trusted signs; the estimate goes on narrowing to the tolerance on computed
    /// signs, which is the best the floating-point function can say.
    fn refine(&self, a: f64, b: f64, rising: bool) -> Root {
        let f = self.f;
        let (flo, fhi) = (value(f, a).0, value(f, b).0);
        let (mut lo, mut hi) = (a, b);
        let (mut tlo, mut thi) = (a, b);
        // Start from the secant (regula falsi) point of the end values.
        let mut x = lo + (hi - lo) * (flo / (flo - fhi));
        if !(x > lo && x < hi) {
            x = 0.5 * (lo + hi);
        }
        let mut d = [0.0; 2];
        for _ in 0..200 {
            f.eval_derivs(x, 1, &mut d);
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
            if fx.abs() > f.eval_error(f.piece_at(x), 0) {
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
        f.eval_derivs(x, 1, &mut d);
        let step = if d[1] != 0.0 { x - d[0] / d[1] } else { x };
        let u = if step.is_finite() {
            step.clamp(lo, hi)
        } else {
            0.5 * (lo + hi)
        };
        // Where the last trusted values are far from the estimate (the function was within
        // rounding of zero near the root), probe outward for the nearest trusted signs.
        let trusted = |v: f64, right: bool| {
            let (fv, e) = value(f, v);
            fv.abs() > e && ((fv > 0.0) == rising) == right
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
