//! The square of pairs cut into cells, one per pair of segments `i ≤ j`: on each the functions
//! of force closure ([`crate::cones`]) and the pieces of the boundary of the set where all
//! hold, in the profile's parameter.

use crate::cones::functions;
use crate::error::Result;
use crate::model::Model;
use crate::near::NearContacts;
use crate::options::GraspOptions;
use bspline::tensor::TensorBSpline;
use numeric::tolerance::{Settings, Size};
use zeroset::{nonnegative_set_mapped, BoundaryPiece, NonNegativeOptions, ZeroSetOptions};

/// A pair of segments: contacts `s` on segment `i` and `t` on segment `j`, `i ≤ j`.
pub(crate) struct Cell {
    pub(crate) i: usize,
    pub(crate) j: usize,
    /// The functions of force closure on the forms' parameters, in the order of
    /// [`crate::cones::functions`].
    pub(crate) fs: Vec<TensorBSpline>,
}

/// What the zero sets gave on one cell, in the profile's parameter.
pub(crate) struct Traced {
    pub(crate) pieces: Vec<BoundaryPiece>,
    /// Isolated points of the set.
    pub(crate) points: Vec<[f64; 2]>,
    /// Whether some point of the boundary was not resolved.
    pub(crate) unresolved: bool,
    /// False when the patch limit was hit.
    pub(crate) complete: bool,
}

/// The cells of `model`, with their functions for `opts` (widths in the frame's units).
pub(crate) fn cells(
    model: &Model<'_>,
    opts: &GraspOptions,
    widths: [Option<f64>; 2],
) -> Result<Vec<Cell>> {
    let n = model.n();
    let mut out = Vec::with_capacity(n * (n + 1) / 2);
    for i in 0..n {
        for j in i..n {
            let fs = functions(&model.forms[i], &model.forms[j], opts.friction, widths)?;
            out.push(Cell { i, j, fs });
        }
    }
    Ok(out)
}

/// The boundary pieces of the force-closure set on `cell`.
pub(crate) fn trace(
    model: &Model<'_>,
    cell: &Cell,
    opts: &GraspOptions,
    near: &NearContacts<'_>,
) -> Result<Traced> {
    let (i, j, n) = (cell.i, cell.j, model.n());
    let (si, ti) = (model.forms[i].domain(), model.forms[j].domain());
    // Where the two contacts meet besides the diagonal: the seam of a closed curve of one
    // segment, the joint of two consecutive segments, the closing joint.
    let mut meets = Vec::new();
    if i == j && n == 1 {
        meets.push([si.0, ti.1]);
    }
    if j == i + 1 {
        meets.push([si.1, ti.0]);
    }
    if i == 0 && j == n - 1 && n >= 2 {
        meets.push([si.0, ti.1]);
    }
    // The boundary is reported in the document's parameter, which need not be linear in the
    // forms' (an analytic shape's angle against its rational circle's): chords are measured
    // there, against the tolerance of a cell of the document's mean width per segment.
    let cell_diagonal = std::f64::consts::SQRT_2 * model.document_cell();
    // (A profile's document domain has a length: the fallback, the forms' own diagonal, is
    // never taken.)
    let settings = Settings {
        size: Size::new(cell_diagonal).ok(),
        ..opts.settings
    };
    let options = NonNegativeOptions {
        zero: ZeroSetOptions {
            settings,
            max_patches: opts.max_patches,
        },
        pairs: i == j,
        meets,
    };
    let document = |t: f64, r: f64| {
        Some([
            model.document_param(model.profile_param(i, t)),
            model.document_param(model.profile_param(j, r)),
        ])
    };
    let set = nonnegative_set_mapped(&cell.fs, &options, &|bx| near.excluded(i, j, bx), &document)?;
    let to_profile = |p: [f64; 2]| [model.profile_param(i, p[0]), model.profile_param(j, p[1])];
    let pieces = set
        .pieces
        .into_iter()
        .map(|mut p| {
            p.pts.iter_mut().for_each(|x| *x = to_profile(*x));
            p
        })
        .collect();
    Ok(Traced {
        pieces,
        points: set.points.into_iter().map(to_profile).collect(),
        unresolved: !set.unresolved.is_empty(),
        complete: set.complete,
    })
}
