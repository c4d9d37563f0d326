//! The zero set of a bivariate B-spline function: the public entry point.

use crate::assemble::assemble;
use crate::error::Result;
use crate::extract::{Pieces, Settle, Tracer};
use crate::patch::Patch;
use bspline::tensor::TensorBSpline;
use numeric::tolerance::{ChordTol, ParamTol, Settings, Size};
use numeric::Rect;
use serde::{Deserialize, Serialize};

/// The least tolerance whose reciprocal gives a depth limit: a zero, negative or NaN
/// tolerance (the system options are not range-checked) then means the deepest subdivision
/// (~1000 halvings) rather than a NaN depth.
pub(crate) const TOL_FLOOR: f64 = 1e-300;

/// Options for [`zero_set`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZeroSetOptions {
    /// The tolerances: the parameter tolerance relative to the domain (patches this small
    /// that are still not resolved become singular or isolated points), and the chord
    /// tolerance relative to the size, by default the domain diagonal (the polylines stay
    /// this close to the zero set; vertices are placed adaptively where it bends).
    pub settings: Settings,
    /// Limit on the number of patches examined; hitting it makes the result incomplete.
    pub max_patches: usize,
}

impl Default for ZeroSetOptions {
    fn default() -> Self {
        Self {
            settings: Settings::default(),
            max_patches: 200_000,
        }
    }
}

impl ZeroSetOptions {
    /// Sets the parameter tolerance.
    pub fn tolerance(mut self, tol: ParamTol) -> Self {
        self.settings.tol = tol;
        self
    }
    /// Sets the chord tolerance.
    pub fn chord_tolerance(mut self, chord_tol: ChordTol) -> Self {
        self.settings.chord_tol = chord_tol;
        self
    }

    /// Depth limit implied by the tolerance: halving both sides down to `tol`, plus slack.
    pub(crate) fn max_depth(&self) -> usize {
        let halvings = (1.0 / self.settings.tol.get())
            .log2()
            .ceil()
            .clamp(1.0, 1100.0) as usize;
        2 * (halvings + 4)
    }
}

/// One connected piece of a zero set, as a polyline in `(t, r)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Polyline {
    /// Vertices `[t, r]`, each on `F = 0` to rounding.
    pub pts: Vec<[f64; 2]>,
    /// True for a closed loop (first vertex repeated at the end).
    pub closed: bool,
}

/// The zero set of `F(t, r)` on its domain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ZeroSet {
    /// The curves of the zero set.
    pub branches: Vec<Polyline>,
    /// Points where branches cross or end inside the domain (resolved to the tolerance).
    pub singular: Vec<[f64; 2]>,
    /// Isolated zeros (or loops smaller than the tolerance).
    pub isolated: Vec<[f64; 2]>,
    /// False when the patch limit was hit or `F` vanishes on a whole cell.
    pub complete: bool,
    /// Patches examined (a measure of the work done).
    pub patches: usize,
}

/// The zero set of `f` on its whole domain.
///
/// ```
/// use bspline::{tensor::TensorBSpline, BSpline};
/// use zeroset::{zero_set, ZeroSetOptions};
/// // F = t² + r² − 0.25 on [−1, 1]²: the circle of radius 1/2.
/// let sq = BSpline::bezier(1, vec![1., -1., 1.]).unwrap().reparam(-1.0, 1.0).unwrap();
/// let one = BSpline::constant(&[1.0], 0, -1.0, 1.0).unwrap();
/// let quarter = BSpline::constant(&[-0.25], 0, -1.0, 1.0).unwrap();
/// let f = TensorBSpline::sum_of_outer(&[(sq.clone(), one.clone()), (one.clone(), sq), (one, quarter.clone())])
///     .unwrap();
/// let z = zero_set(&f, &ZeroSetOptions::default()).unwrap();
/// assert_eq!(z.branches.len(), 1);
/// assert!(z.branches[0].closed);
/// ```
pub fn zero_set(f: &TensorBSpline, opts: &ZeroSetOptions) -> Result<ZeroSet> {
    let cells: Vec<Patch> = f.bezier_patches().iter().map(Patch::from_bezier).collect();
    let (dt, dr) = (f.domain_t(), f.domain_r());
    let dom = Rect::of(dt, dr);
    let diag = (dt.1 - dt.0).hypot(dr.1 - dr.0);
    let map = |t: f64, r: f64| Some([t, r]);
    let pieces = run_cells(
        &cells,
        dom,
        opts,
        &map,
        opts.settings.chord_tol.get() * opts.settings.size.map_or(diag, Size::get),
        &Filters::none(),
    );
    Ok(finish(&pieces, dom, &cells))
}

/// What a caller of [`run_cells`] filters: which patches to look at, where a corner zero of
/// high order is known, and whether a simple patch's arc may stand (see [`Tracer`]).
pub(crate) struct Filters<'a> {
    pub(crate) keep: &'a dyn Fn(&Patch) -> bool,
    pub(crate) lax: &'a dyn Fn(&Patch) -> bool,
    pub(crate) settle: &'a dyn Fn(&Patch) -> Settle,
    pub(crate) settle_vertices: &'a dyn Fn(&Patch, &[[f64; 2]]) -> bool,
}

impl Filters<'static> {
    /// Every patch, none lax, every arc as traced.
    pub(crate) fn none() -> Self {
        Filters {
            keep: &|_| true,
            lax: &|_| false,
            settle: &|_| Settle::Stands,
            settle_vertices: &|_, _| true,
        }
    }
}

/// The subdivision with a mapping for the chord test and a region filter (shared with the
/// bisector, which measures chords in the plane and may skip half of a square domain).
pub(crate) fn run_cells(
    cells: &[Patch],
    dom: Rect,
    opts: &ZeroSetOptions,
    map: &dyn Fn(f64, f64) -> Option<[f64; 2]>,
    chord_abs: f64,
    filters: &Filters<'_>,
) -> Pieces {
    let extent = [dom.t.width(), dom.r.width()];
    let tracer = Tracer {
        min_size: [
            opts.settings.tol.get() * extent[0],
            opts.settings.tol.get() * extent[1],
        ],
        extent,
        dom,
        max_depth: opts.max_depth(),
        max_patches: opts.max_patches,
        map,
        chord_tol: chord_abs,
        keep: filters.keep,
        lax: filters.lax,
        settle: filters.settle,
        settle_vertices: filters.settle_vertices,
    };
    let mut pieces = Pieces::default();
    tracer.run(cells, &mut pieces);
    pieces
}

pub(crate) fn finish(pieces: &Pieces, dom: Rect, cells: &[Patch]) -> ZeroSet {
    let a = assemble(pieces, dom, cells);
    ZeroSet {
        branches: a
            .lines
            .into_iter()
            .map(|(pts, closed)| Polyline { pts, closed })
            .collect(),
        singular: a.singular,
        isolated: a.isolated,
        complete: !pieces.truncated,
        patches: pieces.patches,
    }
}
