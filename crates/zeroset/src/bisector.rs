//! Bisectors of two planar curves and self-bisectors (Elber & Kim): the zero set of `F(t, r)`
//! mapped to bisector points and cleaned.
//!
//! Cleaning: a vertex is kept only when its point `P(t, r)` is a genuine, finite bisector point
//! (equidistant from both foot points, on both normal lines, to a relative residual of
//! [`RESIDUAL`]). This drops the parallel-normal component of `F1`/`F2` (Eq. 4) and the points
//! at infinity; a branch is split where it leaves the valid set. A vertex that fails only
//! because `F` is ill-conditioned there (beside a point where the curves cross, a crossing of
//! the zero set) is first polished by Newton on the bisector condition itself. For the
//! self-bisector the trivial diagonal `t = r` is divided out of the diagonal Bézier cells
//! symbolically (`(t − r)⁴` for F3, `(t − r)⁵` for F1 and F2), only the half `t ≤ r` is
//! searched, and mirrored parts are clipped at the diagonal.

mod jets;
mod knot_corners;
mod output;
mod point;
mod sides;
mod straight_spans;
mod vertices;

pub use output::{Bisector, BisectorPoint, Branch};
pub use point::{bisector_point, RESIDUAL};
pub use sides::Side;

use crate::error::Result;
use crate::patch::Patch;
use crate::symbolic::{bisector_function_scaled, Method};
use crate::zeroset::{run_cells, Filters, ZeroSetOptions};
use bspline::Rational;
use curve::Frame;
use jets::Jets;
use numeric::tolerance::{Settings, Size};
use numeric::Rect;
use point::bbox;
pub(crate) use point::{bbox_of_points, chord_size};
use sides::SideFilter;
use straight_spans::StraightSpans;
use vertices::Ctx;
pub(crate) use vertices::{FAR, TRIM_SLACK};

/// Relative residual below which a diagonal cell counts as divisible by `t − r`.
pub(crate) const DIVISIBLE: f64 = 1e-8;

/// Options for [`bisector`](fn@crate::bisector) and [`self_bisector`](crate::self_bisector).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BisectorOptions {
    /// Which function of §3 to use (default `F3`).
    pub method: Method,
    /// The tolerances: the parameter tolerance relative to the domains (default 1e-12), and
    /// the chord tolerance (default 1e-3) relative to the size, by default the curves'
    /// bounding-box diagonal (of a profile bisector, max(width, height) of the profiles'
    /// box): the bisector polylines stay this close to the bisector in the plane.
    pub settings: Settings,
    /// Keep only points whose foot points are the nearest points of the curves.
    pub trimmed: bool,
    /// Patch limit of the zero-set search.
    pub max_patches: usize,
    /// Only the bisector points on these sides of the two curves (as they run), or every
    /// point (`None`, the default). Patches of the search where a foot is proven to have
    /// the bisector point on its other side are skipped (for polynomial curves; rational
    /// ones are searched whole, and their points on the other side are still reported). In
    /// profile bisectors the sides are the two profiles', and a corner's bisector with a
    /// segment keeps exactly the points on the segment's side.
    pub sides: Option<[Side; 2]>,
}

impl Default for BisectorOptions {
    fn default() -> Self {
        Self {
            method: Method::F3,
            settings: Settings::default(),
            trimmed: false,
            max_patches: 200_000,
            sides: None,
        }
    }
}

/// The zero set's options of a bisector's search (its chord tolerance is measured in the
/// plane, apart).
fn zero_set_options(opts: &BisectorOptions) -> ZeroSetOptions {
    ZeroSetOptions {
        settings: opts.settings,
        max_patches: opts.max_patches,
    }
}

/// The absolute chord tolerance of a bisector of `curves`: relative to the size given, else
/// to their bounding-box diagonal.
fn chord_of(opts: &BisectorOptions, curves: &[&Rational]) -> f64 {
    let size = opts
        .settings
        .size
        .map_or_else(|| chord_size(curves), Size::get);
    opts.settings.chord_tol.get() * size
}

/// The bisector of the rational curves `c1(t)` and `c2(r)` (planar: [`crate::bisector`]
/// takes them as spline curves).
pub(crate) fn curve_bisector(
    c1: &Rational,
    c2: &Rational,
    opts: &BisectorOptions,
) -> Result<Bisector> {
    let z = zero_set_options(opts);
    let (frame, local) = local_curves(&[c1, c2])?;
    let (c1, c2) = (&local[0], &local[1]);
    let (f, terms) = bisector_function_scaled(c1, c2, opts.method)?;
    let (center, diag) = bbox(&[c1, c2]);
    let ctx = Ctx {
        c1,
        c2,
        jets1: Jets::of(c1),
        jets2: Jets::of(c2),
        center,
        diag,
        selfb: false,
        trimmed: opts.trimmed,
        chord: chord_of(opts, &[c1, c2]),
    };
    // (Cells pairing two pieces of one line hold no bisector point: skipped.)
    let (s1, s2) = (StraightSpans::of(c1, diag), StraightSpans::of(c2, diag));
    let cells: Vec<Patch> = f
        .bezier_patches()
        .iter()
        .map(|b| within_rounding_as_zero(Patch::from_bezier(b), terms))
        .filter(|p| !s1.on_one_line([p.t0, p.t1], &s2, [p.r0, p.r1]))
        .collect();
    let (dt, dr) = (f.domain_t(), f.domain_r());
    let dom = Rect::of(dt, dr);
    let map = |t: f64, r: f64| ctx.map(t, r);
    let pieces = [ctx.jets1.pieces(), ctx.jets2.pieces()];
    let sides = opts
        .sides
        .and_then(|s| SideFilter::new([c1, c2], pieces, s));
    let keep = |p: &Patch| sides.as_ref().is_none_or(|f| f.may_hold(p));
    let filters = Filters {
        keep: &keep,
        ..Filters::none()
    };
    let pieces = run_cells(&cells, dom, &z, &map, ctx.chord, &filters);
    Ok(to_global(ctx.build(&pieces, dom, &cells), &frame))
}

/// A cell whose coefficients are all within the rounding of the terms that formed them
/// (`terms`, see [`bisector_function_scaled`]) as zero: the function vanishes there as far
/// as double precision tells (two straight pieces; rationally parametrised they left noise
/// that the extractor ground through for seconds), and the extractor reports it so.
fn within_rounding_as_zero(mut p: Patch, terms: f64) -> Patch {
    if p.max_abs() <= VANISHING * terms {
        p.c.iter_mut().for_each(|x| *x = 0.0);
    }
    p
}

/// The size of a cell's coefficients, relative to the terms that formed them, below which
/// they are rounding: a few hundred roundings of the products (degree-12 products of
/// degree-3 pieces, six outer products summed).
const VANISHING: f64 = 1e-12;

/// The curves moved into one frame (a local origin and a power-of-two scale, see
/// [`Frame`]): the bisector is the same in parameters and moves with the plane, and its
/// functions, products of coordinate differences, keep the precision of unit-size data
/// (a curve of size 100 at 2e14 from the origin lost all of it, and the extraction ground
/// through noise without end).
fn local_curves(curves: &[&Rational]) -> Result<(Frame, Vec<Rational>)> {
    let points: Vec<Vec<[f64; 2]>> = curves
        .iter()
        .map(|c| c.control_points().iter().map(|p| [p[0], p[1]]).collect())
        .collect();
    let sets: Vec<&[[f64; 2]]> = points.iter().map(Vec::as_slice).collect();
    let frame = Frame::for_all(&sets);
    let local = curves
        .iter()
        .map(|c| in_frame(c, &frame))
        .collect::<Result<Vec<_>>>()?;
    Ok((frame, local))
}

/// A planar curve in a frame's local coordinates (the same weights, the control points
/// moved).
pub(crate) fn in_frame(c: &Rational, frame: &Frame) -> Result<Rational> {
    let pts = c.control_points();
    let mut at = pts.iter();
    let moved = c.homogeneous().map_points(2, |_, dst| {
        if let Some(p) = at.next() {
            dst.copy_from_slice(&frame.to_local([p[0], p[1]]));
        }
    });
    let weights = c.weights();
    Ok(Rational::new(
        moved,
        c.is_rational().then_some(&weights[..]),
    )?)
}

/// A bisector found in a frame, in global coordinates (the parameters are the same).
fn to_global(mut b: Bisector, frame: &Frame) -> Bisector {
    let points = b
        .branches
        .iter_mut()
        .flat_map(|br| br.xy.iter_mut())
        .chain(b.singular.iter_mut().map(|p| &mut p.xy))
        .chain(b.isolated.iter_mut().map(|p| &mut p.xy));
    for xy in points {
        *xy = frame.to_global(*xy);
    }
    b
}

/// The self-bisector of the rational curve `c`: pairs `t < r` of distinct foot points on
/// the same curve.
pub(crate) fn curve_self_bisector(c: &Rational, opts: &BisectorOptions) -> Result<Bisector> {
    let z = zero_set_options(opts);
    let (frame, local) = local_curves(&[c])?;
    let c = &local[0];
    let (f, terms) = bisector_function_scaled(c, c, opts.method)?;
    let (center, diag) = bbox(&[c]);
    let ctx = Ctx {
        c1: c,
        c2: c,
        jets1: Jets::of(c),
        jets2: Jets::of(c),
        center,
        diag,
        selfb: true,
        trimmed: opts.trimmed,
        chord: chord_of(opts, &[c]),
    };
    let spans = StraightSpans::of(c, diag);
    let mut cells: Vec<Patch> = Vec::new();
    for b in f.bezier_patches() {
        let mut p = within_rounding_as_zero(Patch::from_bezier(&b), terms);
        if p.t0 >= p.r1 {
            continue; // entirely below the diagonal: the mirror of a cell above it
        }
        if spans.on_one_line([p.t0, p.t1], &spans, [p.r0, p.r1]) {
            continue; // two pieces of one line (or one with itself): no bisector point
        }
        // Diagonal cells: divide (t − r) out as often as it divides. For F3 that is four
        // times: F3 = den · F̂3 with den = C'(t) × C'(r) = O(t − r) and F̂3 = O((t − r)³)
        // (|P − C(u)|² has critical points at both foot points, so its difference between
        // them is a cubic in t − r). The quotient vanishes on the diagonal only at curvature
        // extrema, where self-bisector branches end. A divisible cell has a relative
        // residual near 1e-13, an indivisible one near 1; a cell left with a factor (t − r)
        // would keep the extractor grinding along the whole diagonal.
        for _ in 0..8 {
            match p.divide_diagonal(DIVISIBLE) {
                Some(q) => p = q,
                None => break,
            }
        }
        cells.push(p);
    }
    let (dt, dr) = (f.domain_t(), f.domain_r());
    let dom = Rect::of(dt, dr);
    let map = |t: f64, r: f64| ctx.map(t, r);
    let pieces = [ctx.jets1.pieces(), ctx.jets1.pieces()];
    let sides = opts.sides.and_then(|s| SideFilter::new([c, c], pieces, s));
    let keep = |p: &Patch| p.t0 < p.r1 && sides.as_ref().is_none_or(|f| f.may_hold(p));
    // Cells touching the diagonal at a corner (t1 = r0), and for a closed curve the cell at
    // the corner (start, end) — the diagonal across the seam: F vanishes to fourth order at
    // that corner (see `lax` in the tracer).
    let lax = |p: &Patch| p.t1 == p.r0 || (p.t0 == dom.t.lo && p.r1 == dom.r.hi);
    let filters = Filters {
        keep: &keep,
        lax: &lax,
        ..Filters::none()
    };
    let pieces = run_cells(&cells, dom, &z, &map, ctx.chord, &filters);
    Ok(to_global(ctx.build(&pieces, dom, &cells), &frame))
}

#[cfg(test)]
mod tests {
    use super::*;
    use bspline::BSpline;

    /// How often `(t − r)` divides each diagonal cell of the self-bisector function.
    fn divisions(c: &Rational, method: Method) -> Vec<usize> {
        let f = crate::bisector_function(c, c, method).unwrap();
        f.bezier_patches()
            .iter()
            .map(Patch::from_bezier)
            .filter(|p| p.t0 == p.r0 && p.t1 == p.r1)
            .map(|mut p| {
                let mut k = 0;
                while let Some(q) = p.divide_diagonal(DIVISIBLE) {
                    p = q;
                    k += 1;
                    assert!(k <= 8);
                }
                k
            })
            .collect()
    }

    fn pts(v: &[[f64; 2]]) -> Vec<f64> {
        v.iter().flat_map(|p| [p[0], p[1]]).collect()
    }

    /// F3 of a curve with itself vanishes to fourth order on the diagonal (den = O(t − r),
    /// F̂3 = O((t − r)³)), F1 and F2 to fifth (they carry den once more, and are
    /// antisymmetric). The division finds exactly that in every diagonal cell, for a cubic
    /// B-spline, a cubic NURBS (degree 11 cells) and a periodic NURBS.
    #[test]
    fn self_bisector_functions_divide_by_the_expected_power() {
        let seven = pts(&testkit::outlines::FIG5_CUBIC_POINTS);
        let cubic = Rational::polynomial(&BSpline::clamped_uniform(3, 2, seven.clone()).unwrap());
        let w = [1.0, 3.0, 1.0, 1.0, 0.5, 2.0, 1.0];
        let nurbs =
            Rational::new(BSpline::clamped_uniform(3, 2, seven).unwrap(), Some(&w)).unwrap();
        let ring = pts(&testkit::outlines::PERIODIC_NURBS_POINTS);
        let mut wr = testkit::outlines::PERIODIC_NURBS_WEIGHTS.to_vec();
        wr.extend_from_slice(&[1.0, 2.0, 0.5]);
        let periodic = Rational::new(BSpline::periodic(3, 2, ring).unwrap(), Some(&wr)).unwrap();
        for c in [&cubic, &nurbs, &periodic] {
            let d3 = divisions(c, Method::F3);
            assert!(!d3.is_empty() && d3.iter().all(|&k| k == 4), "F3: {d3:?}");
        }
        for m in [Method::F1, Method::F2] {
            let d = divisions(&cubic, m);
            assert!(!d.is_empty() && d.iter().all(|&k| k == 5), "{m:?}: {d:?}");
        }
    }
}
