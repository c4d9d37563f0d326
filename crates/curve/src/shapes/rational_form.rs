//! The shapes' exact homogeneous forms on the rational circle, built by exact products of the
//! circle's pieces, each with its rounding bound: only the certified path needs them.

use super::jets::CircleShape;
use crate::circle::circle_pieces;
use bspline::{BSpline, Piecewise};
use numeric::rounding::gamma;

/// `s · f` for a constant `s` computed with up to `roundings` roundings from the shape's exact
/// parameters: the rounding of `s` itself is carried as error of the coefficients.
fn scaled(f: &Piecewise, s: f64, roundings: usize) -> Piecewise {
    f.scale_inexact(s, gamma(roundings) * s.abs())
}

/// The homogeneous form `(X, Y, W)` of a shape on the rational circle, from the circle's
/// `(x, y, w)` by exact products (each with its rounding bound).
pub(super) fn circle_form(shape: CircleShape) -> bspline::Result<Piecewise> {
    let circle = circle_pieces()?;
    let (x, y, w) = (
        circle.components(&[0])?,
        circle.components(&[1])?,
        circle.components(&[2])?,
    );
    let (nx, ny, den) = match shape {
        CircleShape::Ellipse { a, b, center } => {
            (x.lincomb(a, &w, center.x)?, y.lincomb(b, &w, center.y)?, w)
        }
        CircleShape::Limacon { a, b } => {
            // W²·r·cos φ = X(aW + bX), W²·r·sin φ = Y(aW + bX).
            let rw = w.lincomb(a, &x, b)?;
            (x.mul(&rw)?, y.mul(&rw)?, w.mul(&w)?)
        }
        CircleShape::Convexities { p, eps, m } => {
            // Wᵐ cos mφ = Re (X + iY)ᵐ, by repeated complex multiplication.
            let (mut re, mut im, mut wm) = (x.clone(), y.clone(), w.clone());
            for _ in 1..m {
                let nre = re.mul(&x)?.sub(&im.mul(&y)?)?;
                let nim = re.mul(&y)?.lincomb(1.0, &im.mul(&x)?, 1.0)?;
                re = nre;
                im = nim;
                wm = wm.mul(&w)?;
            }
            // r cos φ = p X W^(m−1) / (Wᵐ + ε Re(X+iY)ᵐ), and likewise with Y.
            let den = wm.lincomb(1.0, &re, eps)?;
            let mut wmm1 = w.clone();
            for _ in 2..m {
                wmm1 = wmm1.mul(&w)?;
            }
            (x.mul(&wmm1)?.scale(p), y.mul(&wmm1)?.scale(p), den)
        }
        CircleShape::Lemniscate { a, b } => {
            // With X = x/(aw), Y = y/(bw): V/|V|² = (xw/a, yw/b) / (x²/a² + y²/b²), scaled by
            // a²b² (a homogeneous factor) to keep the divisions out.
            let den =
                scaled(&x.mul(&x)?, b * b, 1).lincomb(1.0, &scaled(&y.mul(&y)?, a * a, 1), 1.0)?;
            (
                scaled(&x.mul(&w)?, a * b * b, 2),
                scaled(&y.mul(&w)?, a * a * b, 2),
                den,
            )
        }
    };
    Piecewise::stack(&[&nx, &ny, &den])
}

/// The homogeneous form of [`circle_form`] as one B-spline (knots of full multiplicity at the
/// quarters, where its pieces meet), with a bound on the error of its coefficients: the
/// pieces' bounds, and where two pieces' shared end points were rounded apart, their gap.
pub(crate) fn circle_form_spline(shape: CircleShape) -> bspline::Result<(BSpline, f64)> {
    let form = circle_form(shape)?;
    let (p, dim, n) = (form.degree(), form.dim(), form.pieces());
    let mut knots = vec![form.breaks()[0]; p + 1];
    let mut coefs: Vec<f64> = Vec::with_capacity((n * p + 1) * dim);
    let mut err = form.max_error();
    for i in 0..n {
        let piece = form.piece(i);
        if i == 0 {
            coefs.extend_from_slice(&piece[..dim]);
        } else {
            let shared = coefs.len() - dim;
            for c in 0..dim {
                err = err.max((coefs[shared + c] - piece[c]).abs());
            }
            knots.extend(std::iter::repeat_n(form.breaks()[i], p));
        }
        coefs.extend_from_slice(&piece[dim..]);
    }
    knots.extend(std::iter::repeat_n(form.breaks()[n], p + 1));
    Ok((BSpline::new(p, knots, dim, coefs)?, err))
}
