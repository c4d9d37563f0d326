//! A corner of a patch where the function vanishes, blown up: on each triangle of the patch cut
//! by its diagonal through that corner, the function in the coordinates `(w, λ)` of
//! `(x, y) = (w, wλ)` (below the diagonal) or `(wλ, w)` (above), divided by `w`.
//!
//! Where two contacts on a curve meet at a joint, every condition of the pair vanishes, and
//! zero sets leave that point in several directions: no subdivision of `(t, r)` tells them
//! apart there, however fine. Divided by the distance to the corner, each function takes at
//! `w = 0` its derivative in the direction `λ`, whose zeros are the directions in which the
//! zero sets leave: on `[0, 1]²` of `(w, λ)` they are ordinary zero sets, crossing the edge
//! `w = 0` apart. The substitution is exact Bernstein algebra: de Casteljau's left part for
//! `y = wλ`, products of Bernstein bases, degree elevation, and the division by `w` of a
//! polynomial vanishing at `w = 0`.

use crate::patch::Patch;
use bspline::tensor::{BezierPatch, TensorBSpline};
use numeric::Rect;

/// A corner of the domain where every function vanishes, blown up: the functions on each
/// half of the patch there.
pub(crate) struct Corner {
    /// The corner.
    pub(crate) meet: [f64; 2],
    /// The patch's box, traced apart from the rest of the domain.
    pub(crate) bx: Rect,
    /// Each half's chart, with every function on it, divided by `w`.
    pub(crate) halves: Vec<(Chart, Vec<TensorBSpline>)>,
}

impl Corner {
    /// The corner `meet` of `patches` (one per function, on one box), blown up; `None` when
    /// their boxes differ or a function is constant there.
    pub(crate) fn new(meet: [f64; 2], patches: &[&Patch]) -> Option<Self> {
        let first = patches.first()?;
        let bx = first.rect();
        if patches.iter().any(|p| p.rect() != bx) {
            return None;
        }
        let far = [
            if meet[0] == first.t0 {
                first.t1
            } else {
                first.t0
            },
            if meet[1] == first.r0 {
                first.r1
            } else {
                first.r0
            },
        ];
        let halves = [Half::Below, Half::Above]
            .into_iter()
            .map(|half| {
                let chart = Chart {
                    corner: meet,
                    far,
                    half,
                };
                let hs = patches
                    .iter()
                    .map(|p| {
                        let (coefs, deg_t, deg_r) = chart.blow_up(p)?;
                        let unit = BezierPatch {
                            t0: 0.0,
                            t1: 1.0,
                            r0: 0.0,
                            r1: 1.0,
                            deg_t,
                            deg_r,
                            coefs,
                        };
                        Some(unit.to_tensor())
                    })
                    .collect::<Option<Vec<_>>>()?;
                Some((chart, hs))
            })
            .collect::<Option<Vec<_>>>()?;
        Some(Self { meet, bx, halves })
    }
}

/// The triangle of a corner's patch on one side of the diagonal through the corner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Half {
    /// `y ≤ x`: `(x, y) = (w, wλ)`.
    Below,
    /// `x ≤ y`: `(x, y) = (wλ, w)`.
    Above,
}

/// The map of one half of a corner's patch: `(w, λ) ∈ [0, 1]²` to `(t, r)`, where `x` runs
/// along `t` from the corner to the patch's far side and `y` along `r`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Chart {
    /// The corner, where the function vanishes.
    pub(crate) corner: [f64; 2],
    /// The patch's corner opposite it.
    pub(crate) far: [f64; 2],
    pub(crate) half: Half,
}

impl Chart {
    /// The local `(x, y)` of `(w, λ)`.
    fn local(&self, [w, l]: [f64; 2]) -> [f64; 2] {
        match self.half {
            Half::Below => [w, w * l],
            Half::Above => [w * l, w],
        }
    }

    /// The point `(t, r)` of `(w, λ)`.
    pub(crate) fn point(&self, p: [f64; 2]) -> [f64; 2] {
        let [x, y] = self.local(p);
        [
            self.corner[0] + x * (self.far[0] - self.corner[0]),
            self.corner[1] + y * (self.far[1] - self.corner[1]),
        ]
    }

    /// A box of `(t, r)` holding the image of the box `bx` of `(w, λ)` (its corners' images
    /// bound it: `x` and `y` are monotone in `w` and `λ` on the unit square).
    pub(crate) fn image(&self, bx: Rect) -> Rect {
        let corners = [
            [bx.t.lo, bx.r.lo],
            [bx.t.lo, bx.r.hi],
            [bx.t.hi, bx.r.lo],
            [bx.t.hi, bx.r.hi],
        ]
        .map(|p| self.point(p));
        let span = |k: usize| {
            corners
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    (lo.min(p[k]), hi.max(p[k]))
                })
        };
        Rect::of(span(0), span(1))
    }

    /// Whether the map turns orientations over (the set's left becomes its right).
    pub(crate) fn reverses(&self) -> bool {
        let flips = (self.far[0] < self.corner[0]) != (self.far[1] < self.corner[1]);
        // (Above, `(wλ, w)` is a reflection of `(w, wλ)`.)
        flips != (self.half == Half::Above)
    }

    /// The Bernstein coefficients on `[0, 1]²` of `(w, λ)` of the patch's function composed
    /// with this map and divided by `w` (degree `pt + pr − 1` in `w`, and in `λ` that of the
    /// direction `λ` scales), row-major with `w` first; `None` for a patch of degree 0 both
    /// ways (a constant vanishing at the corner vanishes throughout).
    pub(crate) fn blow_up(&self, p: &Patch) -> Option<(Vec<f64>, usize, usize)> {
        let (pt, pr, w) = (p.pt, p.pr, p.pr + 1);
        if pt + pr == 0 {
            return None;
        }
        // The coefficients with the corner at local (0, 0): an index counted from the far
        // side is reversed.
        let from_t = |i: usize| if self.corner[0] == p.t0 { i } else { pt - i };
        let from_r = |j: usize| if self.corner[1] == p.r0 { j } else { pr - j };
        let local = |i: usize, j: usize| p.c[from_t(i) * w + from_r(j)];
        let (deg_w, deg_l, coefs): (usize, usize, Vec<f64>) = match self.half {
            Half::Below => (
                pt,
                pr,
                (0..=pt)
                    .flat_map(|i| (0..=pr).map(move |j| (i, j)))
                    .map(|(i, j)| local(i, j))
                    .collect(),
            ),
            Half::Above => (
                pr,
                pt,
                (0..=pr)
                    .flat_map(|j| (0..=pt).map(move |i| (i, j)))
                    .map(|(i, j)| local(i, j))
                    .collect(),
            ),
        };
        Some((
            divided_composition(&coefs, deg_w, deg_l),
            deg_w + deg_l - 1,
            deg_l,
        ))
    }
}

/// `F(w, wλ) / w` for `F(x, y) = Σ c[i][j] Bᵢᵖ(x) Bⱼ^q(y)` (row-major `(p + 1) × (q + 1)`,
/// `F(0, 0) = 0` taken as exact): row-major `(p + q) × (q + 1)`, degree `p + q − 1` in `w`
/// and `q` in `λ`.
///
/// For each row, `Σⱼ cⱼ Bⱼ^q(wλ) = Σₖ Dₖ(w) Bₖ^q(λ)` with `Dₖ(w) = Σ_{j ≤ k} cⱼ Bⱼᵏ(w)` (the
/// left part of de Casteljau's subdivision at `w`); then `Bᵢᵖ Bⱼᵏ = C(p,i) C(k,j) / C(p+k,i+j)
/// B_{i+j}^{p+k}`, each `λ` column is raised to degree `p + q`, and `w Bₘⁿ⁻¹ = (m+1)/n
/// Bₘ₊₁ⁿ` divides by `w`.
pub(crate) fn divided_composition(c: &[f64], p: usize, q: usize) -> Vec<f64> {
    let n = p + q;
    let width = q + 1;
    let mut out = vec![0.0; n * width];
    for k in 0..=q {
        let mut e = vec![0.0; p + k + 1];
        for i in 0..=p {
            for j in 0..=k {
                e[i + j] += c[i * width + j] * binomial(p, i) * binomial(k, j);
            }
        }
        for (m, x) in e.iter_mut().enumerate() {
            *x /= binomial(p + k, m);
        }
        for deg in p + k..n {
            e = elevated(&e, deg);
        }
        for m in 0..n {
            out[m * width + k] = e[m + 1] * n as f64 / (m + 1) as f64;
        }
    }
    out
}

/// The coefficients of degree `deg + 1` of a polynomial of degree `deg`.
fn elevated(e: &[f64], deg: usize) -> Vec<f64> {
    let up = (deg + 1) as f64;
    (0..=deg + 1)
        .map(|i| {
            let a = i as f64 / up;
            let left = if i > 0 { a * e[i - 1] } else { 0.0 };
            let right = if i <= deg { (1.0 - a) * e[i] } else { 0.0 };
            left + right
        })
        .collect()
}

/// `C(n, k)`, exact in `f64` for the degrees of patches.
fn binomial(n: usize, k: usize) -> f64 {
    (0..k.min(n - k)).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn patch(c: Vec<f64>, pt: usize, pr: usize, bx: [f64; 4]) -> Patch {
        Patch {
            t0: bx[0],
            t1: bx[1],
            r0: bx[2],
            r1: bx[3],
            pt,
            pr,
            c,
        }
    }

    proptest! {
        /// Against evaluation: `w · H(w, λ)` equals the patch's value at the chart's point, for
        /// every corner and half, on random patches vanishing at that corner.
        #[test]
        fn the_blown_up_function_times_w_is_the_function_at_the_chart_point(
            pt in 0usize..5,
            pr in 0usize..5,
            coefs in prop::collection::vec(-1.0..1.0f64, 25),
            corner in 0usize..4,
            above in any::<bool>(),
            w in 0.0..1.0f64,
            l in 0.0..1.0f64,
        ) {
            prop_assume!(pt + pr > 0);
            let bx = [0.5, 2.0, -1.0, 0.25];
            let (ct, cr) = (corner & 1 == 1, corner & 2 == 2);
            let width = pr + 1;
            let mut c = coefs[..(pt + 1) * width].to_vec();
            // The function vanishes at the chosen corner.
            c[(if ct { pt } else { 0 }) * width + (if cr { pr } else { 0 })] = 0.0;
            let f = patch(c, pt, pr, bx);
            let chart = Chart {
                corner: [if ct { bx[1] } else { bx[0] }, if cr { bx[3] } else { bx[2] }],
                far: [if ct { bx[0] } else { bx[1] }, if cr { bx[2] } else { bx[3] }],
                half: if above { Half::Above } else { Half::Below },
            };
            let (h, dw, dl) = chart.blow_up(&f).unwrap();
            let h = patch(h, dw, dl, [0.0, 1.0, 0.0, 1.0]);
            let [t, r] = chart.point([w, l]);
            let want = f.eval(t, r);
            let got = w * h.eval(w, l);
            prop_assert!((got - want).abs() <= 1e-12, "{got} against {want}");
        }

        /// The image box holds the images of points of the box.
        #[test]
        fn the_image_holds_the_box_points(
            a in 0.0..1.0f64, b in 0.0..1.0f64, c in 0.0..1.0f64, d in 0.0..1.0f64,
            u in 0.0..1.0f64, v in 0.0..1.0f64, above in any::<bool>(),
        ) {
            let chart = Chart {
                corner: [3.0, 1.0],
                far: [2.0, 4.0],
                half: if above { Half::Above } else { Half::Below },
            };
            let bx = Rect::of((a.min(b), a.max(b)), (c.min(d), c.max(d)));
            let p = [bx.t.lo + u * bx.t.width(), bx.r.lo + v * bx.r.width()];
            let img = chart.image(bx);
            let q = chart.point(p);
            prop_assert!(img.t.lo <= q[0] && q[0] <= img.t.hi && img.r.lo <= q[1] && q[1] <= img.r.hi);
        }
    }

    /// Orientation: the sign of the chart's Jacobian, by finite differences.
    #[test]
    fn reverses_matches_the_jacobian_sign() {
        for half in [Half::Below, Half::Above] {
            for far in [[2.0, 4.0], [4.0, 4.0], [2.0, 0.0], [4.0, 0.0]] {
                let chart = Chart {
                    corner: [3.0, 1.0],
                    far,
                    half,
                };
                let (p, h) = ([0.5, 0.5], 1e-6);
                let o = chart.point(p);
                let a = chart.point([p[0] + h, p[1]]);
                let b = chart.point([p[0], p[1] + h]);
                let det = (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
                assert_eq!(chart.reverses(), det < 0.0, "{half:?} {far:?}");
            }
        }
    }
}
