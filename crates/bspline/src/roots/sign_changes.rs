//! Sign changes of a scalar function: where it changes sign, as opposed to where it merely
//! vanishes. The inflections of a curve are the sign changes of its curvature numerator
//! ([`crate::symbolic::curvature_numerator`]); a double zero bends back and a straight stretch
//! between two arcs that turn the same way changes nothing.
//!
//! The search isolates the roots ([`find_roots`], or [`find_roots_periodic`] on a periodic
//! domain, so that the seam is no special case) and decides each one by the signs on its two
//! sides, taken between it and its neighbours, where isolation proved there is no root. Root
//! isolation does not see a sign change across a discontinuity (a knot of multiplicity
//! `p + 1`, or the seam of a closed domain on which the function is not periodic): those are
//! added as jumps.

use super::{
    find_roots_in, find_roots_periodic_in, require_scalar, value, Root, RootKind, RootOptions,
    PERIODIC_MATCH,
};
use crate::error::Result;
use crate::piecewise::Piecewise;
use crate::spline::BSpline;
use numeric::rounding::ulps;
use serde::{Deserialize, Serialize};

/// A cluster of roots wider than this fraction of the domain length is a [`Flat`]: the function
/// is within rounding of zero all along it.
pub const FLAT_WIDTH: f64 = 1e-6;

/// A sign change within this fraction of the domain length of a flat counts as at its end,
/// which is the flat's business: the reduction modulo the period moves a parameter by
/// rounding, far less than this.
const FLAT_SLACK: f64 = 1e-9;

/// How a sign change was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SignChangeKind {
    /// A simple root: exactly one in the bracket (proven when `certified`).
    Simple,
    /// A narrow cluster of roots (a root of odd multiplicity, or roots closer than the
    /// tolerance) across which the sign changes; never certified.
    Cluster,
    /// A discontinuity (a knot of multiplicity `p + 1`, or the seam of a closed domain on
    /// which the function is not periodic) across which the sign changes; certified when both
    /// one-sided limits are beyond their rounding-error bound.
    Jump,
}

/// One sign change of a scalar function.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SignChange {
    /// Best estimate of where the sign changes (in the domain).
    pub u: f64,
    /// An interval that contains it (on a closed domain it may cross the seam: it is then given
    /// in the unwrapped parameter, beyond a domain end). `(u, u)` for a jump.
    pub bracket: (f64, f64),
    /// True when the sign change follows from coefficient signs.
    pub certified: bool,
    /// Simple root, cluster or jump.
    pub kind: SignChangeKind,
}

/// A stretch where the function is within rounding of zero all along (a cluster of roots wider
/// than [`FLAT_WIDTH`] of the domain): the straight stretches of a curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Flat {
    /// The middle of the stretch (in the domain).
    pub u: f64,
    /// The stretch, `lo < hi` (on a closed domain it may cross the seam, as a
    /// [`SignChange::bracket`]).
    pub bracket: (f64, f64),
    /// The function has opposite signs on the two sides of the stretch (a straight stretch
    /// between a left and a right turn). Such a stretch is not repeated in
    /// [`SignChanges::changes`].
    pub sign_change: bool,
}

/// Everything [`sign_changes`] found.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct SignChanges {
    /// The sign changes outside flats, sorted by `u`. On a closed domain every `u` lies in
    /// `[a, b)`.
    pub changes: Vec<SignChange>,
    /// The flats, sorted by `u`.
    pub flats: Vec<Flat>,
    /// Narrow clusters across which the sign does not change: a double root or a touching zero
    /// (no sign change, correctly not reported), or two roots closer than the tolerance (two
    /// sign changes, not reported). Root isolation cannot tell these apart.
    pub unresolved: Vec<Root>,
}

impl SignChanges {
    /// True when every decision follows from coefficient signs: every reported sign change is
    /// certified and no cluster was left unresolved. Flats do not count against it.
    pub fn certified(&self) -> bool {
        self.unresolved.is_empty() && self.changes.iter().all(|c| c.certified)
    }
}

/// A root, or a discontinuity that is not inside a root's bracket.
enum Event {
    Root(Root),
    /// A discontinuity at `u` with its left and right limits (each with its error bound).
    Jump {
        u: f64,
        left: (f64, f64),
        right: (f64, f64),
    },
}

impl Event {
    fn u(&self) -> f64 {
        match self {
            Event::Root(r) => r.u,
            Event::Jump { u, .. } => *u,
        }
    }
    fn bracket(&self) -> (f64, f64) {
        match self {
            Event::Root(r) => r.bracket,
            Event::Jump { u, .. } => (*u, *u),
        }
    }
}

/// The sign changes of the scalar function `f` over its domain `[a, b]`, its flats, and the
/// clusters that could not be decided.
///
/// With `closed`, the domain is a circle: where `f` takes the same value at both ends (within
/// rounding) the search is periodic and a root at the seam is found once; otherwise (a clamped
/// closed curve that is not curvature-continuous at its seam) the seam is a discontinuity like
/// any other. Either way the signs beside a root are read across the seam.
///
/// - A simple root is a sign change (certified: existence and uniqueness in its bracket follow
///   from coefficient signs).
/// - A cluster (the function within rounding of zero on its bracket) wider than
///   [`FLAT_WIDTH`] of the domain is a [`Flat`], which records whether the sign differs on its
///   two sides. A narrower one is a sign change (uncertified) when it does, else it is
///   [`unresolved`](SignChanges::unresolved).
/// - A discontinuity (an interior knot of multiplicity `p + 1`, where the one-sided limits are
///   the coefficients on either side, or the seam of a closed, non-periodic domain) is a sign
///   change when the sign differs on its two sides and no root is reported there already.
///   (Root isolation may report the sign change across an interior knot as a simple root; it
///   is left so.)
///
/// The sign on a side is the sign of `f` halfway to the next root or discontinuity (or to the
/// end of an open domain), where isolation proved there is none; a value within its rounding
/// error of zero counts as no sign. A sign change inside a flat (within `1e-9` of the domain
/// length) is the flat's business and is not reported.
///
/// ```
/// use bspline::roots::{sign_changes, RootOptions, SignChangeKind};
/// use bspline::BSpline;
/// // (u − 0.2)(u − 0.6)² on [0, 1]: a simple root, and a double root that is no sign change.
/// let lin = |r: f64| BSpline::new(1, vec![0., 0., 1., 1.], 1, vec![-r, 1.0 - r]).unwrap();
/// let f = lin(0.2).mul(&lin(0.6)).unwrap().mul(&lin(0.6)).unwrap();
/// let s = sign_changes(&f, false, &RootOptions::default()).unwrap();
/// assert_eq!(s.changes.len(), 1);
/// assert_eq!(s.changes[0].kind, SignChangeKind::Simple);
/// assert!(s.changes[0].certified && (s.changes[0].u - 0.2).abs() < 1e-12);
/// assert!(s.flats.is_empty());
/// // The double root: a cluster with the same sign on both sides, which could also be two
/// // roots closer than the tolerance, so the answer is not certified.
/// assert_eq!(s.unresolved.len(), 1);
/// assert!(!s.certified());
///
/// // 2u − 1 on a closed domain: a root at 0.5, and a jump from 1 to −1 at the seam.
/// let g = lin(0.5).scale(2.0);
/// let s = sign_changes(&g, true, &RootOptions::default()).unwrap();
/// let found: Vec<_> = s.changes.iter().map(|c| (c.u, c.kind)).collect();
/// assert_eq!(found[0], (0.0, SignChangeKind::Jump));
/// assert_eq!(found[1].1, SignChangeKind::Simple);
/// assert!(s.certified() && found.len() == 2);
/// ```
///
/// Errors: those of [`super::find_roots`] (a function that is not scalar, an invalid
/// tolerance).
pub fn sign_changes(f: &BSpline, closed: bool, opts: &RootOptions) -> Result<SignChanges> {
    require_scalar(f.dim())?;
    let pieces = super::computed(f);
    // A closed domain on which the function takes one value at both ends is periodic: taken
    // as continuous across the seam.
    let (a, b) = f.domain();
    let (fa, fb) = (f.eval_scalar(a), f.eval_scalar(b));
    let periodic =
        closed && (fa - fb).abs() <= PERIODIC_MATCH * f.max_abs_coef().max(f64::MIN_POSITIVE);
    let pieces = if periodic {
        pieces.with_periodic_seam(0)
    } else {
        pieces
    };
    sign_changes_in(&pieces, closed, opts)
}

/// [`sign_changes`] of a piecewise function; with `closed`, its domain is a circle, searched
/// periodically when the function is declared periodic ([`Piecewise::with_periodic_seam`]),
/// else with its seam a discontinuity like any other.
pub fn sign_changes_in(f: &Piecewise, closed: bool, opts: &RootOptions) -> Result<SignChanges> {
    require_scalar(f.dim())?;
    let (a, b) = f.domain();
    let period = b - a;
    let periodic = closed && f.is_periodic();
    let mut roots = if periodic {
        find_roots_periodic_in(f, opts)?
    } else {
        find_roots_in(f, a, b, opts)?
    };
    // Two parameters this close are one place (a few times the tolerance root isolation
    // refines to).
    let tol = opts.tol.max(ulps(8.0) * a.abs().max(b.abs()));
    let near = 16.0 * tol * period.max(1.0);
    if closed && !periodic && roots.len() > 1 {
        // A root at the seam is seen at both ends of the open search: keep it once. Clusters
        // touching the seam from both sides are one (a straight stretch across the seam of a
        // closed curve): kept as one cluster over the unwrapped bracket.
        let n = roots.len();
        let (first, last) = (roots[0], roots[n - 1]);
        let clusters = first.kind == RootKind::Cluster && last.kind == RootKind::Cluster;
        if clusters && first.bracket.0 <= a + near && last.bracket.1 >= b - near {
            let bracket = (last.bracket.0, first.bracket.1 + period);
            let mid = 0.5 * (bracket.0 + bracket.1);
            roots.remove(0);
            roots[n - 2] = Root {
                u: if mid >= b { mid - period } else { mid },
                bracket,
                ..last
            };
        } else if (first.u - a).abs() <= near && (last.u - b).abs() <= near {
            roots.pop();
        }
    }
    let wrap = |u: f64| {
        if closed {
            a + (u - a).rem_euclid(period)
        } else {
            u
        }
    };
    // The same place as some root's bracket (modulo the period on a closed domain).
    let covered = |u: f64| {
        let shifts: &[f64] = if closed {
            &[0.0, -period, period]
        } else {
            &[0.0]
        };
        roots.iter().any(|r| {
            shifts.iter().any(|s| {
                let x = u + s;
                x >= r.bracket.0 - near && x <= r.bracket.1 + near
            })
        })
    };

    let mut events: Vec<Event> = jumps(f, closed && !periodic)
        .into_iter()
        .filter(|&(u, _, _)| !covered(u))
        .map(|(u, left, right)| Event::Jump { u, left, right })
        .collect();
    events.extend(roots.iter().copied().map(Event::Root));
    events.sort_by(|x, y| x.u().total_cmp(&y.u()));

    let sign_at = |u: f64| -> i32 {
        let (v, err) = value(f, wrap(u));
        if v > err {
            1
        } else if v < -err {
            -1
        } else {
            0
        }
    };
    let n = events.len();
    // The sign of `f` halfway between event `i` and its neighbour on the left or the right;
    // 0 where there is no room (an open domain's end, a neighbour that overlaps).
    let side = |i: usize, left: bool| -> i32 {
        let (lo, hi) = events[i].bracket();
        let x = if left {
            match (i.checked_sub(1), closed) {
                (Some(j), _) => events[j].bracket().1,
                (None, true) => events[n - 1].bracket().1 - period,
                (None, false) => a,
            }
        } else {
            match (i + 1 < n, closed) {
                (true, _) => events[i + 1].bracket().0,
                (false, true) => events[0].bracket().0 + period,
                (false, false) => b,
            }
        };
        match left {
            true if x < lo => sign_at(0.5 * (x + lo)),
            false if x > hi => sign_at(0.5 * (x + hi)),
            _ => 0,
        }
    };

    let mut out = SignChanges::default();
    for (i, e) in events.iter().enumerate() {
        let change = || side(i, true) * side(i, false) < 0;
        match *e {
            Event::Root(r) if r.kind == RootKind::Simple => out.changes.push(SignChange {
                u: r.u,
                bracket: r.bracket,
                certified: r.certified,
                kind: SignChangeKind::Simple,
            }),
            Event::Root(r) => {
                let (lo, hi) = r.bracket;
                if hi - lo > FLAT_WIDTH * period {
                    out.flats.push(Flat {
                        u: r.u,
                        bracket: r.bracket,
                        sign_change: change(),
                    });
                } else if change() {
                    out.changes.push(SignChange {
                        u: r.u,
                        bracket: r.bracket,
                        certified: false,
                        kind: SignChangeKind::Cluster,
                    });
                } else {
                    out.unresolved.push(r);
                }
            }
            Event::Jump { u, left, right } => {
                if change() {
                    // One-sided limits beyond their bounds are trusted.
                    let trusted = left.0.abs() > left.1
                        && right.0.abs() > right.1
                        && (left.0 > 0.0) != (right.0 > 0.0);
                    out.changes.push(SignChange {
                        u,
                        bracket: (u, u),
                        certified: trusted,
                        kind: SignChangeKind::Jump,
                    });
                }
            }
        }
    }

    // Sign changes at the ends of flats are the flats' business.
    let slack = FLAT_SLACK * period;
    let flats = &out.flats;
    out.changes.retain(|c| {
        !flats.iter().any(|fl| {
            let (lo, hi) = fl.bracket;
            let u = if closed {
                c.u - ((c.u - lo) / period).floor() * period
            } else {
                c.u
            };
            u >= lo - slack && u <= hi + slack
        })
    });
    if closed {
        for c in &mut out.changes {
            let w = wrap(c.u);
            let shift = if w >= b { a - c.u } else { w - c.u };
            c.u += shift;
            c.bracket = (c.bracket.0 + shift, c.bracket.1 + shift);
        }
        out.changes.sort_by(|x, y| x.u.total_cmp(&y.u));
    }
    Ok(out)
}

/// A one-sided limit and the bound on its error.
type Limit = (f64, f64);

/// The discontinuities of `f` in its domain, with their left and right limits and the bounds
/// on their error: the interior breaks where it may jump (the coefficient before the break is
/// the left limit, the one after it the right limit) and, with `seam`, the domain start as the
/// meeting point of the end (left) and the start (right).
fn jumps(f: &Piecewise, seam: bool) -> Vec<(f64, Limit, Limit)> {
    let n = f.pieces();
    let first = |i: usize| (f.piece(i)[0], f.error(i));
    let last = |i: usize| {
        let c = f.piece(i);
        (c[c.len() - 1], f.error(i))
    };
    let mut out = Vec::new();
    if seam {
        out.push((f.domain().0, last(n - 1), first(0)));
    }
    for i in 1..n {
        if f.continuity(i) < 0 {
            out.push((f.breaks()[i], last(i - 1), first(i)));
        }
    }
    out
}
