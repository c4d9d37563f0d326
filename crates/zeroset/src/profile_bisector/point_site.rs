//! Bisectors with a point site: a profile's corner `P`, which is the nearest point of its
//! chain only for the directions of its cone (`d·a ≥ 0` and `d·b ≤ 0` for the unit tangents
//! `a` arriving and `b` leaving there: the wedge on the side the chain bends away from).
//!
//! Against a curve `C = H / w` (moved so that `P` is the origin) the bisector is a rational
//! curve in the curve's parameter: the bisector point of the foot `C(r)` lies on the normal
//! there, `X = C + λ·J C'`, at equal distance from `P`, which gives
//! `X = Num / (2 w E)` with `Q = H' w − H w'` (along `C'`), `E = H × Q` and
//! `Num = 2 E H + |H|² J Q`. Where `E` vanishes the normal is perpendicular to `C − P` and the
//! point is at infinity; the foot counts where `X` is in the cone, `E (Num·a) > 0` and
//! `E (Num·b) < 0` (as `w > 0`). All three are polynomials in exact B-spline algebra, so their
//! certified roots cut the domain into stretches of one sign each. When `P` is the curve's own
//! end (the corner between it and its neighbour), `E` and `Num` share a double root there,
//! divided out exactly: the branch then starts at the centre of curvature of that end.
//!
//! Against another corner the bisector is a piece of the perpendicular bisector of the two
//! points, cut by both cones.

use super::polyline::{sample_runs, Run};
use super::stretches::{Cut, Cuts, FiniteSpan};
use crate::bisector::Side;
use crate::error::Result;
use bspline::roots::RootOptions;
use bspline::{Piecewise, Rational, JUMP};
use curve::Frame;
use numeric::rounding::ulps;

/// A corner as a point site: the point and the unit tangents arriving and leaving there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Corner {
    pub(crate) p: [f64; 2],
    pub(crate) arriving: [f64; 2],
    pub(crate) leaving: [f64; 2],
}

/// Which end of the curve is the corner itself (the corner between it and its neighbour).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SharedEnd {
    Start,
    End,
}

/// Where the bisector may be drawn: points farther than `far` from `center` count as at
/// infinity, and the polylines keep within `chord` of the bisector.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Reach {
    pub(crate) center: [f64; 2],
    pub(crate) far: f64,
    pub(crate) chord: f64,
    /// Parameter tolerance of the root searches, relative to the curve's domain.
    pub(crate) tol: f64,
}

impl Reach {
    pub(crate) fn within(&self, x: [f64; 2]) -> bool {
        x[0].is_finite()
            && x[1].is_finite()
            && (x[0] - self.center[0]).hypot(x[1] - self.center[1]) <= self.far
    }
}

/// The bisector of a corner and a curve (in the curve's parameter), as runs of vertices;
/// `shared` says when the corner is one of the curve's ends; with `side`, only its points on
/// that side of the curve (`λ` above has the sign of `E`, `J` turning left). `false` in the
/// flag when a polyline hit its vertex limit.
pub(crate) fn corner_curve(
    corner: &Corner,
    c: &Rational,
    shared: Option<SharedEnd>,
    side: Option<Side>,
    reach: &Reach,
) -> Result<(Vec<Run>, bool)> {
    let pts: Vec<[f64; 2]> = c.control_points().iter().map(|p| [p[0], p[1]]).collect();
    let origin = match shared {
        // The curve's own end point exactly: then `H` vanishes there exactly.
        Some(SharedEnd::Start) => pts[0],
        Some(SharedEnd::End) => pts[pts.len() - 1],
        None => corner.p,
    };
    let frame = Frame::new(origin, Frame::for_points(&pts).exponent());
    let local = crate::bisector::in_frame(c, &frame)?;
    let parts = Parts::new(&local, corner, shared)?;
    let Some(parts) = parts else {
        return Ok((Vec::new(), true)); // the corner on the line a straight curve lies on
    };
    let (lo, hi) = c.domain();
    let opts = RootOptions::default().tolerance((reach.tol * (hi - lo)).max(f64::MIN_POSITIVE));
    let stretches = parts.stretches(&opts, side)?;
    let point = |r: f64| -> Option<[f64; 2]> {
        let x = frame.to_global(parts.local_point(r)?);
        reach.within(x).then_some(x)
    };
    let mut runs = Vec::new();
    let mut complete = true;
    for s in stretches {
        let (found, done) = sample_runs(&point, s.from, s.to, reach.chord);
        runs.extend(found);
        complete &= done;
    }
    Ok((runs, complete))
}

/// The bisector of two corners: the part of their perpendicular bisector inside both cones
/// and within reach, as its two end points (none when the cones leave nothing).
pub(crate) fn corner_corner(c1: &Corner, c2: &Corner, reach: &Reach) -> Option<[[f64; 2]; 2]> {
    let m = [0.5 * (c1.p[0] + c2.p[0]), 0.5 * (c1.p[1] + c2.p[1])];
    let d = [c2.p[0] - c1.p[0], c2.p[1] - c1.p[1]];
    let len = d[0].hypot(d[1]);
    if len.is_nan() || len <= 0.0 {
        return None;
    }
    let dir = [-d[1] / len, d[0] / len];
    // X(s) = m + s·dir; each cone condition is linear in s.
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for (c, v, sign) in [
        (c1, c1.arriving, 1.0),
        (c1, c1.leaving, -1.0),
        (c2, c2.arriving, 1.0),
        (c2, c2.leaving, -1.0),
    ] {
        // sign·((m − P)·v + s·(dir·v)) > 0
        let k = sign * dot([m[0] - c.p[0], m[1] - c.p[1]], v);
        let slope = sign * dot(dir, v);
        if slope > 0.0 {
            lo = lo.max(-k / slope);
        } else if slope < 0.0 {
            hi = hi.min(-k / slope);
        } else if k <= 0.0 {
            return None;
        }
    }
    // Within reach: |m + s·dir − center| ≤ far.
    let off = [m[0] - reach.center[0], m[1] - reach.center[1]];
    let b = dot(off, dir);
    let disc = b * b - (dot(off, off) - reach.far * reach.far);
    if disc.is_nan() || disc <= 0.0 {
        return None;
    }
    let root = disc.sqrt();
    let (lo, hi) = (lo.max(-b - root), hi.min(-b + root));
    (lo < hi).then(|| {
        let at = |s: f64| [m[0] + s * dir[0], m[1] + s * dir[1]];
        [at(lo), at(hi)]
    })
}

/// A function constant on every piece (a polynomial curve's weight) as pieces of degree 0
/// on the same breaks, with the same error bounds.
fn constant_of(w: &Piecewise) -> Result<Piecewise> {
    let n = w.pieces();
    let coefs = (0..n).map(|i| w.piece(i)[0]).collect();
    let err = (0..n).map(|i| w.error(i)).collect();
    let smooth = (0..=n).map(|_| i32::MAX).collect();
    Ok(Piecewise::from_parts(
        0,
        1,
        w.breaks().to_vec(),
        coefs,
        err,
        smooth,
    )?)
}

/// `E`, `Num`, `Num·a`, `Num·b` and `w` on each Bézier piece of the curve (the shared end's
/// piece with the double root divided out).
struct Parts {
    pieces: Vec<PieceParts>,
}

struct PieceParts {
    span: (f64, f64),
    e: Piecewise,
    num: Piecewise,
    num_a: Piecewise,
    num_b: Piecewise,
    w: Piecewise,
}

impl Parts {
    /// `None` when `E` vanishes identically (within its rounding): every normal passes
    /// through the corner... or none does; either way no bisector point (a straight curve
    /// on a line through the corner).
    fn new(c: &Rational, corner: &Corner, shared: Option<SharedEnd>) -> Result<Option<Parts>> {
        let hom = Piecewise::from_bspline_with_error(c.homogeneous(), c.coefficient_error());
        let h = hom.components(&[0, 1])?;
        let w = hom.components(&[2])?;
        // A polynomial curve's weight is one constant: as a constant, `q = W h'` keeps the
        // degree of `h'` (held at `h`'s degree it would raise every part below by `p`).
        let w = if c.is_rational() { w } else { constant_of(&w)? };
        let q = w.mul(&h.derivative())?.sub(&w.derivative().mul(&h)?)?;
        let e = h.cross(&q)?;
        let jq = Piecewise::stack(&[&q.components(&[1])?.scale(-1.0), &q.components(&[0])?])?;
        let num = e.mul(&h)?.lincomb(2.0, &h.dot(&h)?.mul(&jq)?, 1.0)?;
        let along = |v: [f64; 2]| -> Result<Piecewise> {
            Ok(num
                .components(&[0])?
                .lincomb(v[0], &num.components(&[1])?, v[1])?)
        };
        let (num_a, num_b) = (along(corner.arriving)?, along(corner.leaving)?);
        let vanishes = (0..e.pieces()).all(|i| e.piece(i).iter().all(|x| x.abs() <= e.error(i)));
        if vanishes {
            return Ok(None);
        }
        let n = e.pieces();
        let mut pieces = Vec::with_capacity(n);
        for i in 0..n {
            let at = match shared {
                Some(SharedEnd::Start) if i == 0 => Some(SharedEnd::Start),
                Some(SharedEnd::End) if i == n - 1 => Some(SharedEnd::End),
                _ => None,
            };
            let take = |f: &Piecewise| -> Result<Piecewise> {
                let one = piece_of(f, i)?;
                Ok(match at {
                    Some(end) => deflate_twice(&one, end)?,
                    None => one,
                })
            };
            pieces.push(PieceParts {
                span: e.piece_span(i),
                e: take(&e)?,
                num: take(&num)?,
                num_a: take(&num_a)?,
                num_b: take(&num_b)?,
                w: piece_of(&w, i)?,
            });
        }
        Ok(Some(Parts { pieces }))
    }

    fn piece_at(&self, r: f64) -> &PieceParts {
        let i = self.pieces.partition_point(|p| p.span.1 <= r);
        &self.pieces[i.min(self.pieces.len() - 1)]
    }

    /// The bisector point of the foot at `r`, in the local frame (`None` at infinity).
    fn local_point(&self, r: f64) -> Option<[f64; 2]> {
        let p = self.piece_at(r);
        let (mut e, mut w, mut num) = ([0.0], [0.0], [0.0; 2]);
        p.e.eval(r, &mut e);
        p.w.eval(r, &mut w);
        p.num.eval(r, &mut num);
        let den = 2.0 * w[0] * e[0];
        let x = [num[0] / den, num[1] / den];
        (x[0].is_finite() && x[1].is_finite()).then_some(x)
    }

    /// The stretches where the foot counts (inside the cone, bisector point finite), each
    /// maximal.
    fn stretches(&self, opts: &RootOptions, side: Option<Side>) -> Result<Vec<FiniteSpan>> {
        let (Some(first), Some(last)) = (self.pieces.first(), self.pieces.last()) else {
            return Ok(Vec::new());
        };
        let mut cuts = Cuts::new(first.span.0, last.span.1, *opts);
        for p in &self.pieces {
            let (a, b) = p.span;
            cuts.add_end(a);
            cuts.add_end(b);
            cuts.add_roots(&p.e, a, b, Cut::Pole)?;
            cuts.add_roots(&p.num_a, a, b, Cut::Sign)?;
            cuts.add_roots(&p.num_b, a, b, Cut::Sign)?;
        }
        Ok(cuts.stretches(|r| counts(self.piece_at(r), r, side)))
    }
}

/// Whether the foot at `r` (inside a stretch where `E`, `Num·a` and `Num·b` keep their signs)
/// counts: bisector point finite, strictly inside the cone, and on `side` of the curve.
fn counts(p: &PieceParts, r: f64, side: Option<Side>) -> bool {
    let (mut e, mut na, mut nb) = ([0.0], [0.0], [0.0]);
    p.e.eval(r, &mut e);
    p.num_a.eval(r, &mut na);
    p.num_b.eval(r, &mut nb);
    let on_side = side.is_none_or(|s| (e[0] > 0.0) == (s == Side::Left));
    e[0] != 0.0 && e[0] * na[0] > 0.0 && e[0] * nb[0] < 0.0 && on_side
}

/// Piece `i` of `f` as a function of its own.
fn piece_of(f: &Piecewise, i: usize) -> Result<Piecewise> {
    let (a, b) = f.piece_span(i);
    Ok(Piecewise::from_parts(
        f.degree(),
        f.dim(),
        vec![a, b],
        f.piece(i).to_vec(),
        f.errors(i).to_vec(),
        vec![JUMP, JUMP],
    )?)
}

/// A one-piece function with a double root at `end` divided by `u²` (or `(1 − u)²`, `u` the
/// piece's own parameter): in Bernstein form `u² B_j^(m−2) = C(m−2, j)/C(m, j+2) B_(j+2)^m`,
/// so the quotient's coefficients are the others scaled, and the two dropped ones, zero but
/// for rounding, go into the error bound.
fn deflate_twice(f: &Piecewise, end: SharedEnd) -> Result<Piecewise> {
    let (m, d) = (f.degree(), f.dim());
    if m < 2 {
        return Ok(f.clone());
    }
    let c = f.piece(0);
    let mm = (m * (m - 1)) as f64;
    let mut coefs = Vec::with_capacity((m - 1) * d);
    let mut dropped = vec![0.0f64; d];
    let mut largest_factor = 1.0f64;
    for j in 0..=m - 2 {
        let (src, factor) = match end {
            SharedEnd::Start => (j + 2, mm / ((j + 1) * (j + 2)) as f64),
            SharedEnd::End => (j, mm / ((m - j) * (m - j - 1)) as f64),
        };
        largest_factor = largest_factor.max(factor);
        for k in 0..d {
            coefs.push(c[src * d + k] * factor);
        }
    }
    let skipped: [usize; 2] = match end {
        SharedEnd::Start => [0, 1],
        SharedEnd::End => [m - 1, m],
    };
    for s in skipped {
        for (k, x) in dropped.iter_mut().enumerate() {
            *x += c[s * d + k].abs();
        }
    }
    let err: Vec<f64> = (0..d)
        .map(|k| {
            let magnitude = coefs
                .iter()
                .skip(k)
                .step_by(d)
                .fold(0.0f64, |a, x| a.max(x.abs()));
            largest_factor * (f.errors(0)[k] + dropped[k]) + ulps(4.0) * magnitude
        })
        .collect();
    let (a, b) = f.piece_span(0);
    Ok(Piecewise::from_parts(
        m - 2,
        d,
        vec![a, b],
        coefs,
        err,
        vec![JUMP, JUMP],
    )?)
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

#[cfg(test)]
mod tests {
    use super::*;
    use bspline::BSpline;

    fn reach() -> Reach {
        Reach {
            center: [0.0, 0.0],
            far: 1e3,
            chord: 1e-6,
            tol: 1e-12,
        }
    }

    /// Every vertex is equidistant from the corner and its foot, on the foot's normal, and in
    /// the corner's cone.
    fn check(corner: &Corner, c: &Rational, runs: &[Run]) {
        for run in runs {
            for &(r, x) in run {
                let mut o = [0.0; 4];
                c.eval_derivs(r, 1, &mut o);
                let (f, d) = ([o[0], o[1]], [o[2], o[3]]);
                let to_foot = (x[0] - f[0]).hypot(x[1] - f[1]);
                let to_corner = (x[0] - corner.p[0]).hypot(x[1] - corner.p[1]);
                let scale = 1.0 + to_corner;
                testkit::assert_near!(
                    to_foot,
                    to_corner,
                    1e-9 * scale,
                    "{r}: {to_foot} {to_corner}"
                );
                let along = ((x[0] - f[0]) * d[0] + (x[1] - f[1]) * d[1]) / d[0].hypot(d[1]);
                assert!(
                    along.abs() <= 1e-9 * scale,
                    "{r}: off the normal by {along}"
                );
                let v = [x[0] - corner.p[0], x[1] - corner.p[1]];
                assert!(dot(v, corner.arriving) >= -1e-9 * scale);
                assert!(dot(v, corner.leaving) <= 1e-9 * scale);
            }
        }
    }

    /// A circle's centre as a corner with the full half-plane cone: the bisector is the circle
    /// of half the radius, where the cone lets it be.
    #[test]
    fn centre_and_circle_arc_give_the_half_radius_arc() {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let pts = BSpline::bezier(2, vec![2., 0., 2., 2., 0., 2.]).unwrap();
        let quarter = Rational::new(pts, Some(&[1.0, w, 1.0])).unwrap();
        let corner = Corner {
            p: [0.0, 0.0],
            arriving: [0.0, 1.0],
            leaving: [0.0, -1.0],
        };
        // Cone: d·(0,1) > 0 and d·(0,−1) < 0, the upper half-plane: all of the quarter.
        let (runs, complete) = corner_curve(&corner, &quarter, None, None, &reach()).unwrap();
        assert!(complete);
        assert_eq!(runs.len(), 1);
        check(&corner, &quarter, &runs);
        for &(_, x) in &runs[0] {
            testkit::assert_near!(x[0].hypot(x[1]), 1.0, 1e-12);
        }
        assert!(runs[0].first().unwrap().0 < 1e-9 && runs[0].last().unwrap().0 > 1.0 - 1e-9);
        // The arc runs counterclockwise about the centre: its bisector points lie on its
        // left, and none on its right.
        let on = |side| corner_curve(&corner, &quarter, None, Some(side), &reach()).unwrap();
        assert_eq!(on(Side::Left), (runs, true));
        assert!(on(Side::Right).0.is_empty());
    }

    /// A corner at the start of the parabola `y = x²/2`, its cone the quadrant `x < 0 < y`:
    /// the branch starts at the centre of curvature `(0, 1)` (the double root divided out)
    /// and every vertex is a bisector point inside the cone.
    #[test]
    fn a_corner_at_the_curves_own_end_starts_at_its_centre_of_curvature() {
        // (0,0), (1,0), (2,2) is C(r) = (2r, 2r²).
        let q = Rational::polynomial(&BSpline::bezier(2, vec![0., 0., 1., 0., 2., 2.]).unwrap());
        let corner = Corner {
            p: [0.0, 0.0],
            arriving: [0.0, 1.0],
            leaving: [1.0, 0.0],
        };
        let (runs, complete) =
            corner_curve(&corner, &q, Some(SharedEnd::Start), None, &reach()).unwrap();
        assert!(complete);
        assert_eq!(runs.len(), 1, "{runs:?}");
        check(&corner, &q, &runs);
        let (r0, x0) = runs[0][0];
        assert_eq!(r0, 0.0);
        assert!(x0[0].abs() < 1e-12 && (x0[1] - 1.0).abs() < 1e-12, "{x0:?}");
        assert!(runs[0].last().unwrap().0 > 1.0 - 1e-9);
        // The parabola bends left (up): so does its bisector with the corner.
        let on = |side| corner_curve(&corner, &q, Some(SharedEnd::Start), Some(side), &reach());
        assert_eq!(on(Side::Left).unwrap(), (runs, true));
        assert!(on(Side::Right).unwrap().0.is_empty());
    }

    #[test]
    fn two_corners_meet_on_their_perpendicular_bisector_inside_both_cones() {
        // Two corners whose cones (the quadrants x > 0 < y about each) face each other
        // across x = 1.
        let c1 = Corner {
            p: [0.0, 0.0],
            arriving: [1.0, 0.0],
            leaving: [0.0, -1.0],
        };
        let c2 = Corner {
            p: [2.0, 0.0],
            arriving: [-1.0, 0.0],
            leaving: [0.0, -1.0],
        };
        let seg = corner_corner(&c1, &c2, &reach()).unwrap();
        for x in seg {
            testkit::assert_near!(x[0], 1.0, 1e-12);
        }
        // From the corners' height up to the edge of reach.
        assert!(seg[0][1].abs() < 1e-12, "{seg:?}");
        testkit::assert_near!(seg[1][0].hypot(seg[1][1]), reach().far, 1e-9 * reach().far);
        // Cones that face away leave nothing.
        let away = Corner {
            arriving: [-1.0, 0.0],
            leaving: [0.0, 1.0],
            ..c1
        };
        assert!(corner_corner(&away, &c2, &reach()).is_none());
    }
}
