//! B-spline and NURBS plane curves.

use crate::error::{Error, Result};
use crate::frame::{exact_difference, exponent_of, Frame};
use crate::geom::{Jet, V2};
use crate::param::ParamCurve;
use bspline::symbolic::{homogeneous_pieces, CurvePieces};
use bspline::{BSpline, Piecewise, Rational};
use numeric::rounding::UNIT_ROUNDOFF;

/// A B-spline or NURBS plane curve, closed (periodic or clamped with equal end points) or open.
#[derive(Debug, Clone)]
pub struct SplineCurve {
    curve: Rational,
    closed: bool,
    /// For a periodic curve, the order of continuity of its homogeneous form across the seam.
    periodic: Option<i32>,
    /// The homogeneous curve as Bézier pieces (fast evaluation).
    pieces: Piecewise,
    /// The curve's data as given (Euclidean control points and weights), when it was made
    /// from them: a frame moves the points themselves, so that a curve moved exactly is
    /// computed exactly as the original (moving `w·x` would round differently).
    data: Option<Data>,
}

/// A stretch of parameters on which a curve is exactly a straight segment, with two distinct
/// points of the curve's data on its line (for exact tests of parallelism).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StraightSpan {
    /// Where the stretch starts (a knot).
    pub lo: f64,
    /// Where it ends (a knot; past the domain's end for a stretch across a closed curve's
    /// seam).
    pub hi: f64,
    /// A control point on the line.
    pub from: [f64; 2],
    /// Another control point on the line.
    pub to: [f64; 2],
}

/// Euclidean control points and their weights.
#[derive(Debug, Clone)]
struct Data {
    points: BSpline,
    weights: Option<Vec<f64>>,
}

impl PartialEq for SplineCurve {
    fn eq(&self, other: &Self) -> bool {
        self.curve == other.curve && self.closed == other.closed && self.periodic == other.periodic
    }
}

/// The largest gap between the end points, relative to the control points' scale, that still
/// makes a clamped curve closed: a few units of rounding of the points.
const CLOSED_GAP: f64 = 1e-12;

impl SplineCurve {
    /// Wraps a planar rational curve; it counts as closed when its end points coincide (within
    /// `1e-12` of its size). Its homogeneous coefficients are taken as given (with the error
    /// the curve carries, [`Rational::coefficient_error`]).
    pub fn new(curve: Rational) -> Result<Self> {
        if curve.dim() != 2 {
            return Err(Error::Spline(bspline::Error::DimensionMismatch {
                expected: 2,
                got: curve.dim(),
            }));
        }
        let scale = control_scale(&curve);
        let closed = end_gap_of(&curve) <= CLOSED_GAP * scale.max(f64::MIN_POSITIVE);
        Ok(Self::from_rational(curve, closed, None, None))
    }

    fn from_rational(
        curve: Rational,
        closed: bool,
        periodic: Option<i32>,
        data: Option<Data>,
    ) -> Self {
        let pieces = Piecewise::from_bspline(curve.homogeneous());
        Self {
            curve,
            closed,
            periodic,
            pieces,
            data,
        }
    }

    /// A closed uniform periodic B-spline (optionally rational) through `points`: domain
    /// `[0, n)`, the piece on `[i, i+1]` shaped by points `i..=i+p` (indices mod `n`).
    pub fn periodic(degree: usize, points: &[[f64; 2]], weights: Option<&[f64]>) -> Result<Self> {
        if let Some(w) = weights {
            if w.len() != points.len() {
                return Err(Error::Spline(bspline::Error::CountMismatch {
                    what: "weights (one per control point)",
                    expected: points.len(),
                    got: w.len(),
                }));
            }
        }
        let flat: Vec<f64> = points.iter().flat_map(|p| p.iter().copied()).collect();
        let spline = BSpline::periodic(degree, 2, flat)?;
        // The wrapped control points repeat the first `degree` ones, weights alike.
        let wrapped: Option<Vec<f64>> =
            weights.map(|w| w.iter().chain(&w[..degree.min(w.len())]).copied().collect());
        let curve = Rational::new(spline.clone(), wrapped.as_deref())?;
        let data = Data {
            points: spline,
            weights: wrapped,
        };
        Ok(Self::from_rational(
            curve,
            true,
            Some(degree as i32 - 1),
            Some(data),
        ))
    }

    /// A clamped B-spline (optionally rational) with the given knots, or uniform ones on
    /// `[0, 1]`. It is closed when its first and last points coincide.
    pub fn clamped(
        degree: usize,
        points: &[[f64; 2]],
        weights: Option<&[f64]>,
        knots: Option<Vec<f64>>,
    ) -> Result<Self> {
        let flat: Vec<f64> = points.iter().flat_map(|p| p.iter().copied()).collect();
        let spline = match knots {
            Some(k) => BSpline::new(degree, k, 2, flat)?,
            None => BSpline::clamped_uniform(degree, 2, flat)?,
        };
        let mut c = Self::new(Rational::new(spline.clone(), weights)?)?;
        // Judged again on the points as given, which carry no rounding of `X / w`.
        if let Some(gap) = end_gap(degree, spline.knots(), points, weights, 0.0) {
            c.closed = gap <= CLOSED_GAP * control_scale(&c.curve).max(f64::MIN_POSITIVE);
        }
        c.data = Some(Data {
            points: spline,
            weights: weights.map(<[f64]>::to_vec),
        });
        Ok(c)
    }

    /// The underlying rational curve.
    pub fn curve(&self) -> &Rational {
        &self.curve
    }

    /// For a periodic curve, the order of continuity of its homogeneous form across the seam.
    pub fn periodic_order(&self) -> Option<i32> {
        self.periodic
    }

    /// The Euclidean control points (homogeneous points over their weights).
    pub fn control_points(&self) -> Vec<[f64; 2]> {
        self.curve
            .control_points()
            .iter()
            .map(|p| [p[0], p[1]])
            .collect()
    }

    /// The stretches on which the curve is exactly straight, proven from its data: a knot
    /// span is a straight segment when the control points that shape it are collinear
    /// (exactly: [`crate::exact::orientation`]); neighbouring spans on one line join, across
    /// the seam of a closed curve too. Empty for a curve given by homogeneous coefficients
    /// (no data to prove it on).
    ///
    /// ```
    /// use curve::SplineCurve;
    /// // A quadratic with its first three control points on y = 0.1 (not a double, exactly
    /// // the same double each time).
    /// let pts = [[0.0, 0.1], [1.0, 0.1], [2.0, 0.1], [2.0, 1.0], [0.0, 1.0]];
    /// let c = SplineCurve::clamped(2, &pts, None, None).unwrap();
    /// let spans = c.straight_spans();
    /// assert_eq!(spans.len(), 1);
    /// assert_eq!((spans[0].lo, spans[0].hi), (0.0, 1.0 / 3.0));
    /// ```
    pub fn straight_spans(&self) -> Vec<StraightSpan> {
        let Some(data) = &self.data else {
            return Vec::new();
        };
        let (pts, p) = (&data.points, data.points.degree());
        let knots = pts.knots();
        let on_line = |from: [f64; 2], to: [f64; 2], q: [f64; 2]| {
            crate::exact::orientation(from, to, q) == Some(std::cmp::Ordering::Equal)
        };
        let point = |i: usize| [pts.ctrl(i)[0], pts.ctrl(i)[1]];
        let mut spans: Vec<StraightSpan> = Vec::new();
        for j in p..pts.n_ctrl() {
            let (lo, hi) = (knots[j], knots[j + 1]);
            if hi <= lo {
                continue;
            }
            let from = point(j - p);
            // (All control points equal: the span is a point, not a segment.)
            let Some(to) = (j - p + 1..=j).map(point).find(|&q| q != from) else {
                continue;
            };
            if !(j - p + 1..=j).all(|i| {
                let q = point(i);
                q == from || q == to || on_line(from, to, q)
            }) {
                continue;
            }
            match spans.last_mut() {
                Some(last)
                    if last.hi == lo
                        && on_line(last.from, last.to, from)
                        && on_line(last.from, last.to, to) =>
                {
                    last.hi = hi;
                }
                _ => spans.push(StraightSpan { lo, hi, from, to }),
            }
        }
        let (a, b) = self.curve.domain();
        if self.closed && spans.len() > 1 {
            let (first, last) = (spans[0], spans[spans.len() - 1]);
            if first.lo == a
                && last.hi == b
                && on_line(last.from, last.to, first.from)
                && on_line(last.from, last.to, first.to)
            {
                spans.remove(0);
                if let Some(l) = spans.last_mut() {
                    l.hi = first.hi + (b - a);
                }
            }
        }
        spans
    }

    /// The number of polynomial (or rational) pieces: the spans between distinct knots.
    pub fn piece_count(&self) -> usize {
        self.pieces.pieces()
    }

    /// The homogeneous Bézier pieces `(X, Y, w)` (point-major), each with the bound on its
    /// coefficients' error from their extraction.
    pub fn bezier_pieces(&self) -> &Piecewise {
        &self.pieces
    }

    /// The curve's exact form in pieces, with bounds on its coefficients and its seam.
    pub fn exact_pieces(&self) -> CurvePieces {
        let pieces = homogeneous_pieces(&self.curve);
        match self.periodic {
            Some(order) => pieces.periodic(order),
            None => pieces,
        }
    }

    /// The same curve in `frame`: each homogeneous point `(X, Y, w)` becomes
    /// `((X − oₓw) 2^−e, (Y − o_y w) 2^−e, w 2^−k)` with the weights scaled by the power of two
    /// `2^−k` that brings the largest to about 1. Exact for a polynomial curve (w = 1) in the
    /// frame chosen for its points; otherwise the rounding of `o·w` and of the difference is
    /// added to the coefficients' error bound.
    pub fn in_frame(&self, frame: &Frame) -> SplineCurve {
        match &self.data {
            Some(data) => self.data_in_frame(data, frame),
            None => self.homogeneous_in_frame(frame),
        }
    }

    /// [`SplineCurve::in_frame`] from the data: the points moved (exactly in the frame chosen
    /// for them) and the weights scaled by a power of two, then multiplied out as given ones
    /// are, so that the local curve of a curve moved exactly is that of the original.
    fn data_in_frame(&self, data: &Data, frame: &Frame) -> SplineCurve {
        let mut moved_err = 0.0f64;
        let points = data.points.map_points(2, |p, q| {
            let (local, err) = frame.to_local_checked([p[0], p[1]]);
            moved_err = moved_err.max(err);
            q.copy_from_slice(&local);
        });
        let weights = data.weights.as_ref().map(|w| {
            let wmax = w.iter().fold(0.0f64, |m, &x| m.max(x));
            let down = Frame::new([0.0, 0.0], exponent_of(wmax)).length_to_local(1.0);
            w.iter().map(|&x| x * down).collect::<Vec<f64>>()
        });
        let curve = match Rational::new(points.clone(), weights.as_deref()) {
            Ok(c) if moved_err == 0.0 => c,
            Ok(c) => {
                // A moved point off by δ moves its homogeneous point by w·δ (w ≤ 2 scaled).
                let err = c.coefficient_error() + 2.0 * moved_err;
                match Rational::from_homogeneous_with_error(c.homogeneous().clone(), err) {
                    Ok(c) => c,
                    Err(_) => return self.homogeneous_in_frame(frame),
                }
            }
            // (Scaled weights stay positive unless they underflow.)
            Err(_) => return self.homogeneous_in_frame(frame),
        };
        let data = Data { points, weights };
        Self::from_rational(curve, self.closed, self.periodic, Some(data))
    }

    /// [`SplineCurve::in_frame`] from the homogeneous coefficients (a curve given by them).
    fn homogeneous_in_frame(&self, frame: &Frame) -> SplineCurve {
        let h = self.curve.homogeneous();
        let o = frame.origin();
        let wmax = h
            .coefs()
            .chunks_exact(3)
            .fold(0.0f64, |m, p| m.max(p[2].abs()));
        let wscale = Frame::new([0.0, 0.0], exponent_of(wmax)).length_to_local(1.0);
        // The error of each new coordinate, before scaling (the scalings by powers of two are
        // exact): none where `X − o·w` is exact, else the rounding of `o·w` and of the
        // difference.
        let mut extra = 0.0f64;
        let local = h.map_points(3, |p, q| {
            let w = p[2];
            for k in 0..2 {
                let ow = o[k] * w;
                let d = p[k] - ow;
                let exact = (w == 1.0 || o[k] == 0.0) && exact_difference(p[k], ow);
                if !exact {
                    extra = extra.max(UNIT_ROUNDOFF * (ow.abs() + d.abs()));
                }
                q[k] = frame.length_to_local(d) * wscale;
            }
            q[2] = w * wscale;
        });
        let extra = frame.length_to_local(extra) * wscale;
        let err = frame.length_to_local(self.curve.coefficient_error()) * wscale + extra;
        let curve = match Rational::from_homogeneous_with_error(local, err) {
            Ok(c) => c,
            // (A positive weight stays positive scaled by a power of two.)
            Err(_) => return self.clone(),
        };
        Self::from_rational(curve, self.closed, self.periodic, None)
    }
}

/// Diagonal of the control points' bounding box.
/// The distance between the end points of the curve with `degree`, `knots`, Euclidean control
/// points `pts` and `weights` (none: polynomial), beyond the rounding of the points
/// (`rounding`, in units of their largest coordinate): the curve is evaluated relative to its
/// first control point, so that a curve far from the origin is judged on its own scale
/// (evaluated in place, the ends of a quadratic 8 units apart at 7e16 from the origin came out
/// equal, and an open curve was taken for closed, its one inflection certified).
fn end_gap(
    degree: usize,
    knots: &[f64],
    pts: &[[f64; 2]],
    weights: Option<&[f64]>,
    rounding: f64,
) -> Option<f64> {
    let first = pts[0];
    let far = pts
        .iter()
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    let coefs: Vec<f64> = pts
        .iter()
        .flat_map(|p| [p[0] - first[0], p[1] - first[1]])
        .collect();
    let moved = BSpline::new(degree, knots.to_vec(), 2, coefs)
        .and_then(|d| Rational::new(d, weights))
        .ok()?;
    let (a, b) = moved.domain();
    let (pa, pb) = (moved.point(a), moved.point(b));
    let gap = (pa[0] - pb[0]).hypot(pa[1] - pb[1]);
    Some((gap - rounding * far).max(0.0))
}

/// [`end_gap`] of a rational curve known by its homogeneous form: its Euclidean points carry
/// the rounding of `X / w` (a few units of the largest coordinate) unless it is polynomial.
fn end_gap_of(curve: &Rational) -> f64 {
    let h = curve.homogeneous();
    let pts: Vec<[f64; 2]> = curve
        .control_points()
        .iter()
        .map(|p| [p[0], p[1]])
        .collect();
    let weights = curve.weights();
    let rational = curve.is_rational();
    let rounding = if rational { 8.0 * UNIT_ROUNDOFF } else { 0.0 };
    end_gap(
        h.degree(),
        h.knots(),
        &pts,
        rational.then_some(&weights[..]),
        rounding,
    )
    .unwrap_or_else(|| {
        // (Not expected: the same knots and weights made the curve.)
        let (a, b) = curve.domain();
        let (pa, pb) = (curve.point(a), curve.point(b));
        (pa[0] - pb[0]).hypot(pa[1] - pb[1])
    })
}

/// The scale of a curve's control points ([`crate::points_scale`]).
pub(crate) fn control_scale(c: &Rational) -> f64 {
    crate::geom::points_scale(c.control_points().iter().map(|p| [p[0], p[1]]))
}

/// Point and derivatives up to order `k ≤ 3` of the planar rational curve with homogeneous
/// form `h` (`out[2j..2j+2]` the j-th derivative), by the quotient rule
/// `C⁽ʲ⁾ = (X⁽ʲ⁾ − Σᵢ C(j,i) w⁽ⁱ⁾ C⁽ʲ⁻ⁱ⁾) / w`.
///
/// ```
/// use curve::{rational_derivs, ParamCurve, SplineCurve};
/// // A quarter of the unit circle as a rational quadratic: its point and derivatives agree
/// // with the curve's jet.
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let points = [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let c = SplineCurve::clamped(2, &points, Some(&[1.0, w, 1.0]), None).unwrap();
/// let mut out = [0.0; 8];
/// rational_derivs(&c.exact_pieces().hom, 0.3, 2, &mut out);
/// let j = c.jet(0.3);
/// assert!((out[0] - j.p.x).abs() < 1e-15 && (out[3] - j.d1.y).abs() < 1e-14);
/// assert!((out[0].hypot(out[1]) - 1.0).abs() < 1e-15);
/// ```
pub fn rational_derivs(h: &Piecewise, u: f64, k: usize, out: &mut [f64; 8]) {
    let mut hv = [0.0; 12];
    let k = k.min(3);
    h.eval_derivs(u, k, &mut hv[..3 * (k + 1)]);
    // Written out per order (the binomials of the rule are 1; 1, 2, 1; 1, 3, 3, 1).
    let inv = 1.0 / hv[2];
    let (w1, w2, w3) = (hv[5], hv[8], hv[11]);
    for c in 0..2 {
        let c0 = hv[c] * inv;
        out[c] = c0;
        if k >= 1 {
            let c1 = (hv[3 + c] - w1 * c0) * inv;
            out[2 + c] = c1;
            if k >= 2 {
                let c2 = (hv[6 + c] - 2.0 * w1 * c1 - w2 * c0) * inv;
                out[4 + c] = c2;
                if k >= 3 {
                    out[6 + c] = (hv[9 + c] - 3.0 * w1 * c2 - 3.0 * w2 * c1 - w3 * c0) * inv;
                }
            }
        }
    }
}

impl ParamCurve for SplineCurve {
    fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        let mut o = [0.0; 8];
        let k = order.min(3);
        rational_derivs(&self.pieces, u, k, &mut o);
        Jet {
            p: V2::new(o[0], o[1]),
            d1: V2::new(o[2], o[3]),
            d2: V2::new(o[4], o[5]),
            d3: V2::new(o[6], o[7]),
        }
    }
}
