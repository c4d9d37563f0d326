//! The analytic shapes of the curve files, defined once: their parameters (validated), their
//! jets in the angle φ, their formulas in the cosine and sine of the rational circle's angle,
//! and their exact rational forms on that circle, with bounds on the forms' coefficients. All
//! run counterclockwise over `φ ∈ [0, 2π)`.

use crate::circle::circle_pieces;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::geom::{Jet, V2};
use crate::param::ParamCurve;
use bspline::rounding::gamma;
use bspline::symbolic::CurvePieces;
use bspline::Piecewise;
use std::f64::consts::TAU;

fn check(field: &'static str, value: f64, ok: bool, why: &'static str) -> Result<()> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidShape { field, value, why })
    }
}

/// A polar curve `r(φ)(cos φ, sin φ)` from the sine and cosine of φ, `r` and its first three
/// derivatives.
fn polar_jet_cs(s: f64, c: f64, r: [f64; 4]) -> Jet {
    polar_jet_to(s, c, r, 3)
}

/// [`polar_jet_cs`] up to derivative `order` (higher ones left zero).
#[inline]
fn polar_jet_to(s: f64, c: f64, r: [f64; 4], order: usize) -> Jet {
    let [r0, r1, r2, r3] = r;
    let mut j = Jet {
        p: V2::new(r0 * c, r0 * s),
        d1: V2::new(r1 * c - r0 * s, r1 * s + r0 * c),
        ..Jet::default()
    };
    if order >= 2 {
        j.d2 = V2::new(
            r2 * c - 2.0 * r1 * s - r0 * c,
            r2 * s + 2.0 * r1 * c - r0 * s,
        );
    }
    if order >= 3 {
        j.d3 = V2::new(
            r3 * c - 3.0 * r2 * s - 3.0 * r1 * c + r0 * s,
            r3 * s + 3.0 * r2 * c - 3.0 * r1 * s - r0 * c,
        );
    }
    j
}

/// The shapes with a rational-circle form, as formulas in `(cos ψ, sin ψ)` of the circle's
/// angle ψ (jets in ψ): the shape's own angle φ for all but the elliptic lemniscate, whose
/// form inverts an ellipse (`tan φ = (a/b) tan ψ`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CircleShape {
    /// `(cx + a cos ψ, cy + b sin ψ)`.
    Ellipse {
        /// Semi-axis along x.
        a: f64,
        /// Semi-axis along y.
        b: f64,
        /// Center.
        center: V2,
    },
    /// `r = a + b cos ψ`.
    Limacon {
        /// Constant term.
        a: f64,
        /// Cosine amplitude.
        b: f64,
    },
    /// `r = p / (1 + ε cos mψ)`.
    Convexities {
        /// Scale.
        p: f64,
        /// Eccentricity.
        eps: f64,
        /// Lobes.
        m: u32,
    },
    /// The inverse of the ellipse point `(cos ψ / a, sin ψ / b)` in the unit circle.
    Lemniscate {
        /// Radius at φ = 0.
        a: f64,
        /// Radius at φ = π/2.
        b: f64,
    },
}

impl CircleShape {
    /// Point and derivatives in ψ up to `order` at the angle with cosine `c` and sine `s`.
    /// (Inlined into the circle form's jets, the hottest path of a run: left to itself the
    /// compiler stopped doing so as the crate grew, at 3 % of a run.)
    #[inline]
    pub fn jet(self, c: f64, s: f64, order: usize) -> Jet {
        match self {
            CircleShape::Lemniscate { a, b } => inverted_ellipse_jet(a, b, s, c, order),
            CircleShape::Ellipse { a, b, center } => ellipse_jet(a, b, center, s, c),
            CircleShape::Limacon { a, b } => {
                polar_jet_to(s, c, [a + b * c, -b * s, -b * c, b * s], order)
            }
            CircleShape::Convexities { p, eps, m } => {
                // cos mφ + i sin mφ = (c + i s)ᵐ, by repeated complex products (m ≥ 2): the
                // error grows only linearly in m, unlike the Chebyshev three-term recurrence.
                let (mut cm, mut sm) = (c, s);
                for _ in 1..m {
                    (cm, sm) = (cm * c - sm * s, cm * s + sm * c);
                }
                convexities_jet(p, eps, m, s, c, sm, cm, order)
            }
        }
    }
}

/// The elliptic lemniscate as the inverse `P = V / |V|²` of the ellipse point
/// `V = (cos ψ / a, sin ψ / b)`, with derivatives in ψ up to `order`: `V″ = −V`, so with
/// `q = |V|²`: `q′ = 2V·V′`, `q″ = 2(|V′|² − q)`, `q‴ = −4q′`, and `Pq = V` differentiated
/// gives each derivative of `P` from the lower ones (one division).
#[inline]
fn inverted_ellipse_jet(a: f64, b: f64, s: f64, c: f64, order: usize) -> Jet {
    let v = V2::new(c / a, s / b);
    let v1 = V2::new(-s / a, c / b);
    let q = v.dot(v);
    let q1 = 2.0 * v.dot(v1);
    let inv = 1.0 / q;
    let p = v * inv;
    let p1 = (v1 - p * q1) * inv;
    let mut j = Jet {
        p,
        d1: p1,
        ..Jet::default()
    };
    if order >= 2 {
        let q2 = 2.0 * (v1.dot(v1) - q);
        j.d2 = (-v - p1 * (2.0 * q1) - p * q2) * inv;
        if order >= 3 {
            let q3 = -4.0 * q1;
            j.d3 = (-v1 - j.d2 * (3.0 * q1) - p1 * (3.0 * q2) - p * q3) * inv;
        }
    }
    j
}

fn ellipse_jet(a: f64, b: f64, center: V2, s: f64, c: f64) -> Jet {
    Jet {
        p: center + V2::new(a * c, b * s),
        d1: V2::new(-a * s, b * c),
        d2: V2::new(-a * c, -b * s),
        d3: V2::new(a * s, -b * c),
    }
}

/// `r(φ) = p / (1 + ε cos mφ)` from the sines and cosines of φ and mφ, up to `order`.
#[allow(clippy::too_many_arguments)] // the shape's three parameters and two angles
#[inline]
fn convexities_jet(p: f64, e: f64, m: u32, s: f64, c: f64, sm: f64, cm: f64, order: usize) -> Jet {
    let m = m as f64;
    // h = 1 + ε cos mφ and r = p/h: with k = h′/h and gⱼ = h⁽ʲ⁾/h (one division),
    // r′ = −rk, r″ = r(2k² − g₂), r‴ = r(6k(g₂ − k²) − g₃).
    let inv = 1.0 / (1.0 + e * cm);
    let r = p * inv;
    let em = e * m;
    let k = -em * sm * inv;
    let r1 = -r * k;
    let (mut r2, mut r3) = (0.0, 0.0);
    if order >= 2 {
        let g2 = -em * m * cm * inv;
        r2 = r * (2.0 * k * k - g2);
        if order >= 3 {
            let g3 = em * m * m * sm * inv;
            r3 = r * (6.0 * k * (g2 - k * k) - g3);
        }
    }
    polar_jet_to(s, c, [r, r1, r2, r3], order)
}

/// Circle `(cx + r cos φ, cy + r sin φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    r: f64,
    center: V2,
}

impl Circle {
    /// A circle of radius `r > 0`.
    pub fn new(r: f64, center: [f64; 2]) -> Result<Self> {
        check("r", r, r > 0.0, "must be > 0")?;
        check("center", center[0], center[1].is_finite(), "must be finite")?;
        Ok(Self {
            r,
            center: V2::from_arr(center),
        })
    }
    /// The radius.
    pub fn r(&self) -> f64 {
        self.r
    }
    /// The center.
    pub fn center(&self) -> [f64; 2] {
        self.center.arr()
    }
}

/// Ellipse `(cx + a cos φ, cy + b sin φ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    a: f64,
    b: f64,
    center: V2,
}

impl Ellipse {
    /// An ellipse with semi-axes `a, b > 0`.
    pub fn new(a: f64, b: f64, center: [f64; 2]) -> Result<Self> {
        check("a", a, a > 0.0, "must be > 0")?;
        check("b", b, b > 0.0, "must be > 0")?;
        check("center", center[0], center[1].is_finite(), "must be finite")?;
        Ok(Self {
            a,
            b,
            center: V2::from_arr(center),
        })
    }
    /// Semi-axis along x.
    pub fn a(&self) -> f64 {
        self.a
    }
    /// Semi-axis along y.
    pub fn b(&self) -> f64 {
        self.b
    }
    /// The center.
    pub fn center(&self) -> [f64; 2] {
        self.center.arr()
    }
}

/// Limaçon `r(φ) = a + b cos φ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limacon {
    a: f64,
    b: f64,
}

impl Limacon {
    /// A simple limaçon: `a > b ≥ 0`.
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check("b", b, b >= 0.0, "must be ≥ 0")?;
        check("a", a, a > b, "must be > b for a simple curve")?;
        Ok(Self { a, b })
    }
    /// Constant term.
    pub fn a(&self) -> f64 {
        self.a
    }
    /// Cosine amplitude.
    pub fn b(&self) -> f64 {
        self.b
    }
}

/// The most slender elliptic lemniscate (`a/b` or `b/a`) run on its circle form. Beyond, the
/// lobes are so nearly circular (θ of order `(b/a)⁴` across them) that no stretch of them is
/// proven monotone: the march crawls and the sampled width settles them on either path (from
/// `a/b = 6` on). The form would only cost precision there: its parameter runs up to `a/b`
/// times slower than φ, and the lobes' nearly singular pairs come out that much coarser (at
/// `a/b = 200`, 2e-5 in φ against 6e-8; at 300, families at the default tolerance).
const MAX_SQUEEZE: f64 = 5.0;

/// Elliptic lemniscate `r(φ) = sqrt(a² cos² φ + b² sin² φ)`: certified on its exact rational
/// form (the inverse of an ellipse) up to `a/b = 5` (either way round), sampled beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticLemniscate {
    a: f64,
    b: f64,
}

impl EllipticLemniscate {
    /// An elliptic lemniscate with `a, b > 0`.
    pub fn new(a: f64, b: f64) -> Result<Self> {
        check("a", a, a > 0.0, "must be > 0")?;
        check("b", b, b > 0.0, "must be > 0")?;
        Ok(Self { a, b })
    }
    /// Radius at φ = 0.
    pub fn a(&self) -> f64 {
        self.a
    }
    /// Radius at φ = π/2.
    pub fn b(&self) -> f64 {
        self.b
    }
}

/// Curve with convexities `r(φ) = p / (1 + ε cos mφ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Convexities {
    p: f64,
    eps: f64,
    m: u32,
}

impl Convexities {
    /// `p > 0`, `0 < ε < 1`, integer `m ≥ 2`.
    pub fn new(p: f64, eps: f64, m: u32) -> Result<Self> {
        check("p", p, p > 0.0, "must be > 0")?;
        check("eps", eps, eps > 0.0 && eps < 1.0, "must be in (0, 1)")?;
        check("m", m as f64, m >= 2, "must be an integer ≥ 2")?;
        Ok(Self { p, eps, m })
    }
    /// Scale.
    pub fn p(&self) -> f64 {
        self.p
    }
    /// Eccentricity.
    pub fn eps(&self) -> f64 {
        self.eps
    }
    /// Number of lobes.
    pub fn m(&self) -> u32 {
        self.m
    }
}

/// One of the analytic shapes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A circle.
    Circle(Circle),
    /// An ellipse.
    Ellipse(Ellipse),
    /// A limaçon.
    Limacon(Limacon),
    /// An elliptic lemniscate.
    EllipticLemniscate(EllipticLemniscate),
    /// A curve with convexities.
    Convexities(Convexities),
}

impl Shape {
    /// The `kind` of the curve files.
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Circle(_) => "circle",
            Shape::Ellipse(_) => "ellipse",
            Shape::Limacon(_) => "limacon",
            Shape::EllipticLemniscate(_) => "elliptic_lemniscate",
            Shape::Convexities(_) => "convexities",
        }
    }

    /// How many times the shape's curvature oscillates around it (the lobes of a curve with
    /// convexities; 1 for the others): what a sampled search must resolve.
    pub fn lobes(&self) -> u32 {
        match self {
            Shape::Convexities(c) => c.m,
            _ => 1,
        }
    }

    /// Two corners of a box holding the shape.
    pub fn extent(&self) -> [[f64; 2]; 2] {
        let boxed = |c: V2, rx: f64, ry: f64| [[c.x - rx, c.y - ry], [c.x + rx, c.y + ry]];
        let origin = V2::new(0.0, 0.0);
        match *self {
            Shape::Circle(c) => boxed(c.center, c.r, c.r),
            Shape::Ellipse(e) => boxed(e.center, e.a, e.b),
            Shape::Limacon(l) => boxed(origin, l.a + l.b, l.a + l.b),
            Shape::EllipticLemniscate(l) => boxed(origin, l.a.max(l.b), l.a.max(l.b)),
            Shape::Convexities(c) => {
                let r = c.p / (1.0 - c.eps);
                boxed(origin, r, r)
            }
        }
    }

    /// The same shape in `frame`: lengths scaled by its power of two (exact), the center
    /// moved (exact for the frame chosen for the shape's extent). The shapes without a center
    /// lie about the origin, which such a frame keeps.
    pub fn in_frame(&self, frame: &Frame) -> Shape {
        let len = |x: f64| frame.length_to_local(x);
        let at = |c: V2| V2::from_arr(frame.to_local(c.arr()));
        match *self {
            Shape::Circle(c) => Shape::Circle(Circle {
                r: len(c.r),
                center: at(c.center),
            }),
            Shape::Ellipse(e) => Shape::Ellipse(Ellipse {
                a: len(e.a),
                b: len(e.b),
                center: at(e.center),
            }),
            Shape::Limacon(l) => Shape::Limacon(Limacon {
                a: len(l.a),
                b: len(l.b),
            }),
            Shape::EllipticLemniscate(l) => Shape::EllipticLemniscate(EllipticLemniscate {
                a: len(l.a),
                b: len(l.b),
            }),
            Shape::Convexities(c) => Shape::Convexities(Convexities { p: len(c.p), ..c }),
        }
    }

    /// The shape's formula in the cosine and sine of the rational circle's angle, when it has
    /// an exact form on that circle (all but the slender lemniscates; a circle is an ellipse
    /// with equal axes).
    pub fn circle_shape(&self) -> Option<CircleShape> {
        match *self {
            Shape::Circle(c) => Some(CircleShape::Ellipse {
                a: c.r,
                b: c.r,
                center: c.center,
            }),
            Shape::Ellipse(e) => Some(CircleShape::Ellipse {
                a: e.a,
                b: e.b,
                center: e.center,
            }),
            Shape::Limacon(l) => Some(CircleShape::Limacon { a: l.a, b: l.b }),
            Shape::EllipticLemniscate(l) => ((l.a / l.b).max(l.b / l.a) <= MAX_SQUEEZE)
                .then_some(CircleShape::Lemniscate { a: l.a, b: l.b }),
            Shape::Convexities(c) => Some(CircleShape::Convexities {
                p: c.p,
                eps: c.eps,
                m: c.m,
            }),
        }
    }

    /// True when the shape is exactly a circle by its parameters (a circle, an ellipse with
    /// equal axes): every pair of its opposite points is antipodal, one continuous family,
    /// which no computation in rounded arithmetic can tell from a curve that is nearly a
    /// circle.
    pub fn is_exact_circle(&self) -> bool {
        match *self {
            Shape::Circle(_) => true,
            Shape::Ellipse(e) => e.a == e.b,
            _ => false,
        }
    }

    /// The exact rational form on the rational circle (see [`crate::circle`]) in pieces, with
    /// bounds on its coefficients, when the shape has one ([`Shape::circle_shape`]).
    pub fn exact_pieces(&self) -> Option<CurvePieces> {
        let form = self.circle_shape()?;
        let hom = circle_form(form).ok()?;
        let pieces = CurvePieces::new(hom, false).ok()?;
        Some(pieces.periodic(0).numerators_continuous())
    }

    fn as_curve(&self) -> &dyn ParamCurve {
        match self {
            Shape::Circle(c) => c,
            Shape::Ellipse(c) => c,
            Shape::Limacon(c) => c,
            Shape::EllipticLemniscate(c) => c,
            Shape::Convexities(c) => c,
        }
    }
}

/// `s · f` for a constant `s` computed with up to `roundings` roundings from the shape's exact
/// parameters: the rounding of `s` itself is carried as error of the coefficients.
fn scaled(f: &Piecewise, s: f64, roundings: usize) -> Piecewise {
    f.scale_inexact(s, gamma(roundings) * s.abs())
}

/// The homogeneous form `(X, Y, W)` of a shape on the rational circle, from the circle's
/// `(x, y, w)` by exact products (each with its rounding bound).
fn circle_form(shape: CircleShape) -> bspline::Result<Piecewise> {
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

impl ParamCurve for Shape {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        self.as_curve().jet_to(u, order)
    }
}

impl ParamCurve for Circle {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet_to(&self, u: f64, _order: usize) -> Jet {
        let (s, c) = u.sin_cos();
        let r = self.r;
        Jet {
            p: self.center + V2::new(r * c, r * s),
            d1: V2::new(-r * s, r * c),
            d2: V2::new(-r * c, -r * s),
            d3: V2::new(r * s, -r * c),
        }
    }
}

impl ParamCurve for Ellipse {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet_to(&self, u: f64, _order: usize) -> Jet {
        let (s, c) = u.sin_cos();
        ellipse_jet(self.a, self.b, self.center, s, c)
    }
}

impl ParamCurve for Limacon {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet_to(&self, u: f64, _order: usize) -> Jet {
        let (s, c) = u.sin_cos();
        let (a, b) = (self.a, self.b);
        polar_jet_cs(s, c, [a + b * c, -b * s, -b * c, b * s])
    }
}

impl ParamCurve for EllipticLemniscate {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        // r² = g = A + B cos 2φ; differentiate r² = g three times. The value itself as
        // a² cos² φ + b² sin² φ: the form with cos 2φ cancels near the waist (φ = π/2) of a
        // slender lemniscate, where g ≈ b² ≪ a².
        // (In units of the larger radius: the squares of radii of 1e-180 or 1e180 would
        // underflow or overflow.)
        let unit = self.a.max(self.b);
        let (a, b) = (self.a / unit, self.b / unit);
        let (aa, bb) = (a * a, b * b);
        let big_b = 0.5 * (aa - bb);
        // One sine and cosine: the double angle from them (sin 2φ = 2sc, cos 2φ = (c − s)(c + s),
        // the factored form exact near φ = π/4 up to the rounding of c and s themselves).
        let (s, c) = u.sin_cos();
        let (s2, c2) = (2.0 * s * c, (c - s) * (c + s));
        let g = aa * c * c + bb * s * s;
        let r = g.sqrt();
        let inv = 1.0 / r;
        // 2rr′ = g′, 2(rr″ + r′²) = g″, 2(rr‴ + 3r′r″) = g‴.
        let r1 = -big_b * s2 * inv;
        let (mut r2, mut r3) = (0.0, 0.0);
        if order >= 2 {
            r2 = (-2.0 * big_b * c2 - r1 * r1) * inv;
            if order >= 3 {
                r3 = (4.0 * big_b * s2 - 3.0 * r1 * r2) * inv;
            }
        }
        polar_jet_to(s, c, [r, r1, r2, r3].map(|x| x * unit), order)
    }
}

impl ParamCurve for Convexities {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn jet_to(&self, u: f64, order: usize) -> Jet {
        let (sm, cm) = (self.m as f64 * u).sin_cos();
        let (s, c) = u.sin_cos();
        convexities_jet(self.p, self.eps, self.m, s, c, sm, cm, order.max(1))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::PlaneCurve;

    /// Each derivative of `c`'s jet against central differences of the one below, at many φ.
    fn check_against_differences(c: &dyn PlaneCurve) {
        let h = 1e-5;
        for i in 0..=720 {
            let u = TAU * i as f64 / 720.0 + 1e-3;
            let j = c.jet(u);
            let (lo, hi) = (c.jet(u - h), c.jet(u + h));
            let scale = j.p.norm() + j.d1.norm() + j.d2.norm() + j.d3.norm();
            let pairs = [
                (j.d1, hi.p - lo.p),
                (j.d2, hi.d1 - lo.d1),
                (j.d3, hi.d2 - lo.d2),
            ];
            for (k, (d, diff)) in pairs.into_iter().enumerate() {
                let err = (d - diff * (0.5 / h)).norm();
                assert!(
                    err <= 1e-7 * scale,
                    "{u}: derivative {} off by {err}",
                    k + 1
                );
            }
            // Lower orders agree with the full jet.
            for order in 0..3 {
                let l = c.jet_to(u, order);
                assert_eq!((l.p, l.d1), (j.p, j.d1), "{u} order {order}");
                if order >= 2 {
                    assert_eq!(l.d2, j.d2, "{u} order {order}");
                }
            }
        }
    }

    #[test]
    fn jets_match_central_differences() {
        check_against_differences(&Circle::new(1.5, [1.0, 2.0]).unwrap());
        check_against_differences(&Ellipse::new(3.0, 2.0, [0.5, -1.0]).unwrap());
        check_against_differences(&Limacon::new(4.0, 2.5).unwrap());
        check_against_differences(&EllipticLemniscate::new(6.0, 3.0).unwrap());
        check_against_differences(&EllipticLemniscate::new(1.0, 0.05).unwrap());
        check_against_differences(&Convexities::new(3.0, 0.5, 3).unwrap());
        check_against_differences(&Convexities::new(4.5, 0.2, 4).unwrap());
        check_against_differences(&Convexities::new(2.0, 0.3, 7).unwrap());
    }

    /// The shapes' formulas in `(cos φ, sin φ)` against their jets from `sin mφ, cos mφ` by the
    /// library's sine and cosine.
    #[test]
    fn circle_shapes_match_the_angle_formulas() {
        for (p, eps, m) in [(3.0, 0.5, 3), (4.5, 0.2, 4), (1.0, 0.9, 2), (2.0, 0.3, 7)] {
            let c = Convexities::new(p, eps, m).unwrap();
            let shape = CircleShape::Convexities { p, eps, m };
            for i in 0..=2000 {
                let u = TAU * i as f64 / 2000.0;
                let (s, co) = u.sin_cos();
                let (a, b) = (shape.jet(co, s, 3), c.jet(u));
                let scale = b.p.norm() + b.d1.norm() + b.d2.norm() + b.d3.norm();
                for (x, y) in [(a.p, b.p), (a.d1, b.d1), (a.d2, b.d2), (a.d3, b.d3)] {
                    assert!((x - y).norm() <= 1e-13 * scale, "m={m} {u}: {a:?} vs {b:?}");
                }
            }
        }
    }

    /// The elliptic lemniscate's jet from one sine and cosine against the former evaluation
    /// (the double angle by its own sine and cosine, divisions by r).
    #[test]
    fn lemniscate_matches_the_double_angle_formula() {
        for (a, b) in [(6.0, 3.0), (1.0, 0.05), (2.0, 2.0), (0.3, 5.0)] {
            let c = EllipticLemniscate::new(a, b).unwrap();
            let (aa, bb) = (a * a, b * b);
            let big_b = 0.5 * (aa - bb);
            for i in 0..=4000 {
                let u = TAU * i as f64 / 4000.0;
                let (s, co) = u.sin_cos();
                let (s2, c2) = (2.0 * u).sin_cos();
                let r = (aa * co * co + bb * s * s).sqrt();
                let r1 = -2.0 * big_b * s2 / (2.0 * r);
                let r2 = (-2.0 * big_b * c2 - r1 * r1) / r;
                let r3 = (4.0 * big_b * s2 - 3.0 * r1 * r2) / r;
                let want = polar_jet_cs(s, co, [r, r1, r2, r3]);
                let got = c.jet(u);
                let scale = want.p.norm() + want.d1.norm() + want.d2.norm() + want.d3.norm();
                for (x, y) in [
                    (got.p, want.p),
                    (got.d1, want.d1),
                    (got.d2, want.d2),
                    (got.d3, want.d3),
                ] {
                    assert!(
                        (x - y).norm() <= 1e-14 * scale,
                        "{a},{b} {u}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }
}
