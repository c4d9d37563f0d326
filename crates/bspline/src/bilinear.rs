//! The bilinear forms products combine coordinates by (a scalar times a vector, dot, planar
//! and 3-D cross), written once for the B-spline form ([`crate::BSpline`]) and the piecewise
//! Bézier form ([`crate::Piecewise`]), with the dimension checks they need.

use crate::error::{Error, Result};
use std::borrow::Cow;

/// One term `(i, j, k, c)` of a bilinear form: `out[k] += c · a[i] · b[j]`.
pub(crate) type Term = (usize, usize, usize, f64);

/// The planar cross product `x_a y_b − y_a x_b`.
const CROSS: [Term; 2] = [(0, 1, 0, 1.0), (1, 0, 0, -1.0)];

/// The 3-D cross product.
const CROSS3: [Term; 6] = [
    (1, 2, 0, 1.0),
    (2, 1, 0, -1.0),
    (2, 0, 1, 1.0),
    (0, 2, 1, -1.0),
    (0, 1, 2, 1.0),
    (1, 0, 2, -1.0),
];

/// How the coordinates of two factors combine into the product's coordinates:
/// `out[k] += c · a[i] · b[j]` for every term `(i, j, k, c)`.
pub(crate) struct Bilinear {
    pub(crate) terms: Cow<'static, [Term]>,
    pub(crate) out_dim: usize,
}

impl Bilinear {
    /// A scalar function (dimension 1) times one of dimension `dim`.
    pub(crate) fn scalar_times(dim: usize) -> Self {
        Self {
            terms: (0..dim).map(|k| (0, k, k, 1.0)).collect(),
            out_dim: dim,
        }
    }

    /// The dot product of two functions of dimension `dim`, checked equal.
    pub(crate) fn dot(dims: [usize; 2]) -> Result<Self> {
        require(dims[1], dims[0])?;
        Ok(Self {
            terms: (0..dims[0]).map(|k| (k, k, 0, 1.0)).collect(),
            out_dim: 1,
        })
    }

    /// The planar cross product of two functions of dimension 2, checked.
    pub(crate) fn cross(dims: [usize; 2]) -> Result<Self> {
        dims.iter().try_for_each(|&d| require(d, 2))?;
        Ok(Self {
            terms: Cow::Borrowed(&CROSS),
            out_dim: 1,
        })
    }

    /// The 3-D cross product of two functions of dimension 3, checked.
    pub(crate) fn cross3(dims: [usize; 2]) -> Result<Self> {
        dims.iter().try_for_each(|&d| require(d, 3))?;
        Ok(Self {
            terms: Cow::Borrowed(&CROSS3),
            out_dim: 3,
        })
    }

    /// The number of terms of output coordinate `k`.
    pub(crate) fn terms_of(&self, k: usize) -> usize {
        self.terms.iter().filter(|t| t.2 == k).count()
    }
}

/// `Ok` when a dimension `got` is the `expected` one.
fn require(got: usize, expected: usize) -> Result<()> {
    if got == expected {
        Ok(())
    } else {
        Err(Error::DimensionMismatch { expected, got })
    }
}
