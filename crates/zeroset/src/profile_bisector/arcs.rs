//! The bisector of an arc and a line or another arc in closed form, in the parameter of the
//! first segment (a line when there is one: its polynomials are of lower degree).
//!
//! The first segment's point `P = p / w` has the unit normal `n = m / (ρ w)`: for an arc of
//! centre `c` and radius `ρ`, `m = p − c w` (away from the centre); for a line from `E₀` to
//! `E₁`, `m = J (E₁ − E₀) w` and `ρ = |E₁ − E₀|`. The point on that normal at signed distance
//! `s`, `X = P + s n`, is at distance `|s|` from the second segment's carrier when
//! - a line through `E` with normal `ν = J v` (`v` along it): `ν·(X − E) = τ |ν| s`, so
//!   `s = N / D` with `N = ρ ν·(p − E w)` and `D = τ ρ |ν| w − ν·m`;
//! - a circle of centre `c₂` and radius `ρ₂`: `|X − c₂| = |ρ₂ + τ s|`, linear in `s` once
//!   the squares cancel: `N = ρ (|p − c₂ w|² − ρ₂² w²)` and `D = 2 (τ ρ₂ ρ w² − m·(p − c₂ w))`;
//!
//! for each sign `τ = ±1` (both signs of `s` come out of one `τ`). The foot on the second
//! segment lies on the line through `X` along `ν`, or on the ray from `c₂` through `X` (on
//! its antipode where `k = ρ₂ + τ s < 0`). With `V = ρ w D (X − q) = ρ D (p − q w) + N m` for
//! a point `q`, the foot is between the planes through the segment's ends (for an arc: its
//! knots, each Bézier span less than half a turn) by the signs of `v·V` or `e × V`. All
//! these are polynomials in exact B-spline algebra, so their certified roots cut the domain
//! into stretches where the foot counts, as for a corner ([`super::point_site`]): at the
//! roots of `D` the point is at infinity, at those of `k D = ρ₂ D + τ N` the foot jumps to
//! the antipode. The vertices keep within the chord tolerance, and step each foot by at most
//! a [`STEPS`]-th of its domain, as the traced zero set does.

use super::lines::STEPS;
use super::point_site::Reach;
use super::polyline::sample_runs;
use super::stretches::{Cut, Cuts};
use super::tangent_centre::tangent_centre;
use crate::bisector::{in_frame, Bisector, Branch};
use crate::error::Result;
use bspline::roots::RootOptions;
use bspline::{Piecewise, Rational};
use curve::Frame;
use numeric::rounding::ulps;

/// What a segment lies on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Carrier {
    /// A straight segment (degree 1, two control points).
    Line,
    /// An arc of this circle.
    Circle { center: [f64; 2], radius: f64 },
}

/// Halvings at most between two vertices to keep each foot's step within a [`STEPS`]-th of
/// its domain (a foot sweeping its whole domain between two vertices needs log2(64) = 6).
const DENSITY_DEPTH: usize = 10;

/// `D` counts as vanishing where its coefficients are below this share of the terms it is
/// the difference of: a line tangent to a circle in the drawing, moved or rotated, is
/// tangent only to the rounding of its data, some 1e-16 relative, which leaves `D` a few
/// units of that instead of zero (and every point of the common normal a bisector point).
const TANGENT: f64 = 1e-12;

/// A foot within this share of the domain of an end of a closed circle is at its seam.
const SEAM: f64 = 1e-9;

/// Newton steps that polish a foot on an arc after its barycentric estimate, which near a
/// span's end is good to the square root of rounding only: each step doubles the digits.
const FOOT_NEWTON: usize = 3;

/// The bisector of segments `c1` on `k1` and `c2` on `k2`, in their own parameters; `None`
/// where the closed form does not apply (two lines, which have their own; an arc whose
/// Bézier spans are not quadratic and under half a turn; a degenerate line).
pub(crate) fn arc_bisector(
    c1: &Rational,
    k1: Carrier,
    c2: &Rational,
    k2: Carrier,
    reach: &Reach,
) -> Result<Option<Bisector>> {
    let swapped = matches!((k1, k2), (Carrier::Circle { .. }, Carrier::Line));
    let (a, ka, b, kb) = if swapped {
        (c2, k2, c1, k1)
    } else {
        (c1, k1, c2, k2)
    };
    if ka == Carrier::Line && kb == Carrier::Line {
        return Ok(None);
    }
    let pts: Vec<[f64; 2]> = [a, b]
        .iter()
        .flat_map(|c| c.control_points())
        .map(|p| [p[0], p[1]])
        .collect();
    let frame = Frame::for_points(&pts);
    let Some(first) = First::new(&in_frame(a, &frame)?, ka, &frame)? else {
        return Ok(None);
    };
    let Some(second) = Second::new(&in_frame(b, &frame)?, kb, &frame)? else {
        return Ok(None);
    };
    let (lo, hi) = a.domain();
    let opts = RootOptions::default().tolerance((reach.tol * (hi - lo)).max(f64::MIN_POSITIVE));
    let mut out = Bisector {
        branches: Vec::new(),
        singular: Vec::new(),
        isolated: Vec::new(),
        complete: true,
    };
    for tau in [1.0, -1.0] {
        let Some(sign) = Signed::new(&first, &second, tau)? else {
            // (A line tangent to the circle: its centre, with feet apart, where the contact
            // is on the segment.)
            if let (Carrier::Line, Carrier::Circle { center, .. }) = (ka, kb) {
                let centre = tangent_centre(a, b, center, swapped);
                out.isolated
                    .extend(centre.filter(|_| out.isolated.is_empty()));
            }
            continue;
        };
        let mut cuts = Cuts::new(lo, hi, opts);
        for i in 0..first.p.pieces() {
            let (x, y) = first.p.piece_span(i);
            cuts.add_end(x);
            cuts.add_end(y);
        }
        cuts.add_roots(&sign.d, lo, hi, Cut::Pole)?;
        if let Some(k) = &sign.k {
            cuts.add_roots(k, lo, hi, Cut::Jump)?;
        }
        let last = sign.edges.len().saturating_sub(1);
        for (e, g) in sign.edges.iter().enumerate() {
            // The segment's own ends: the foot leaves it there (on a closed circle, from one
            // end of the domain to the other).
            let kind = if e == 0 || e == last {
                Cut::Jump
            } else {
                Cut::Sign
            };
            cuts.add_roots(g, lo, hi, kind)?;
        }
        let at = |t: f64| sign.at(&first, &second, t);
        for stretch in cuts.stretches(|t| sign.counts(&first, &second, t)) {
            let point = |t: f64| {
                let x = frame.to_global(sign.point(&first, &second, t)?.0);
                reach.within(x).then_some(x)
            };
            let (runs, done) = sample_runs(&point, stretch.from, stretch.to, reach.chord);
            out.complete &= done;
            for run in runs {
                let mut br = branch_of(&run, &at, &second, [hi - lo, second.extent()], &frame);
                if swapped {
                    br.tr.iter_mut().for_each(|p| p.swap(0, 1));
                }
                if br.xy.len() >= 2 {
                    out.branches.push(br);
                }
            }
        }
    }
    Ok(Some(out))
}

/// A run's vertices with their feet on the second segment, and more between them where a
/// foot would step more than a [`STEPS`]-th of its domain `extents`.
fn branch_of(
    run: &[(f64, [f64; 2])],
    at: &impl Fn(f64) -> Option<Vertex>,
    second: &Second,
    extents: [f64; 2],
    frame: &Frame,
) -> Branch {
    let mut feet: Vec<(f64, f64, [f64; 2])> = run
        .iter()
        .filter_map(|&(t, x)| Some((t, at(t)?.r, x)))
        .collect();
    // A run ends where the foot reaches an end of the segment; on a closed circle either end
    // is that point, and the run's neighbouring vertex says which.
    if let (Some((lo, hi)), n @ 2..) = (second.seam(), feet.len()) {
        let near = SEAM * (hi - lo);
        for (end, next) in [(0, 1), (n - 1, n - 2)] {
            let (r, beside) = (feet[end].1, feet[next].1);
            if (r - lo).abs() <= near || (hi - r).abs() <= near {
                feet[end].1 = if beside - lo < hi - beside { lo } else { hi };
            }
        }
    }
    let steps = extents.map(|e| e / STEPS as f64);
    let densify = Feet { at, steps };
    let mut out = Branch::of_curves(
        Vec::with_capacity(feet.len()),
        Vec::with_capacity(feet.len()),
    );
    for (k, &v) in feet.iter().enumerate() {
        if k > 0 {
            densify.between(
                feet[k - 1],
                v,
                frame,
                DENSITY_DEPTH,
                &mut out.tr,
                &mut out.xy,
            );
        }
        out.tr.push([v.0, v.1]);
        out.xy.push(v.2);
    }
    out
}

/// The first segment's `p`, `w`, `m` and `ρ` (in the local frame).
struct First {
    p: Piecewise,
    w: Piecewise,
    m: Piecewise,
    rho: f64,
}

impl First {
    fn new(c: &Rational, k: Carrier, frame: &Frame) -> Result<Option<Self>> {
        let hom = Piecewise::from_bspline_with_error(c.homogeneous(), c.coefficient_error());
        let p = hom.components(&[0, 1])?;
        let w = hom.components(&[2])?;
        let (m, rho) = match k {
            Carrier::Line => {
                let Some([e0, e1]) = line_ends(c) else {
                    return Ok(None);
                };
                let d = [e1[0] - e0[0], e1[1] - e0[1]];
                let m = Piecewise::stack(&[&w.scale(-d[1]), &w.scale(d[0])])?;
                (m, d[0].hypot(d[1]))
            }
            Carrier::Circle { center, radius } => {
                let c = frame.to_local(center);
                let m = p.sub(&Piecewise::stack(&[&w.scale(c[0]), &w.scale(c[1])])?)?;
                (m, frame.length_to_local(radius))
            }
        };
        Ok(Some(Self { p, w, m, rho }))
    }
}

/// The second segment: its carrier and where its foot may lie (in the local frame). (One per
/// pair of segments, never stored in bulk: the variants' sizes do not matter.)
#[allow(clippy::large_enum_variant)]
enum Second {
    Line {
        from: [f64; 2],
        along: [f64; 2],
        domain: (f64, f64),
    },
    Circle {
        center: [f64; 2],
        radius: f64,
        spans: Vec<Span>,
        hom: Piecewise,
        velocity: Piecewise,
    },
}

/// A Bézier span of an arc: control points, weights, parameters, and its turning sign.
struct Span {
    points: [[f64; 2]; 3],
    weights: [f64; 3],
    domain: (f64, f64),
    turn: f64,
}

impl Second {
    fn new(c: &Rational, k: Carrier, frame: &Frame) -> Result<Option<Self>> {
        match k {
            Carrier::Line => {
                let Some([e0, e1]) = line_ends(c) else {
                    return Ok(None);
                };
                Ok(Some(Second::Line {
                    from: e0,
                    along: [e1[0] - e0[0], e1[1] - e0[1]],
                    domain: c.domain(),
                }))
            }
            Carrier::Circle { center, radius } => {
                let center = frame.to_local(center);
                let hom = Piecewise::from_bspline(c.homogeneous());
                if hom.degree() != 2 {
                    return Ok(None);
                }
                let mut spans = Vec::with_capacity(hom.pieces());
                for i in 0..hom.pieces() {
                    let h = hom.piece(i);
                    let weights = [h[2], h[5], h[8]];
                    // A middle weight ≤ 0 is a span of half a turn or more: its two end
                    // planes no longer bound it.
                    if weights.iter().any(|&x| x.is_nan() || x <= 0.0) {
                        return Ok(None);
                    }
                    let points =
                        [0, 1, 2].map(|j| [h[3 * j] / h[3 * j + 2], h[3 * j + 1] / h[3 * j + 2]]);
                    let e0 = sub(points[0], center);
                    let turn = cross(e0, sub(points[1], center)).signum();
                    spans.push(Span {
                        points,
                        weights,
                        domain: hom.piece_span(i),
                        turn,
                    });
                }
                let velocity = hom.derivative();
                Ok(Some(Second::Circle {
                    center,
                    radius: frame.length_to_local(radius),
                    spans,
                    hom,
                    velocity,
                }))
            }
        }
    }

    /// The length of the parameter domain.
    fn extent(&self) -> f64 {
        match self {
            Second::Line { domain, .. } => domain.1 - domain.0,
            Second::Circle { spans, .. } => match (spans.first(), spans.last()) {
                (Some(a), Some(b)) => b.domain.1 - a.domain.0,
                _ => 0.0,
            },
        }
    }

    /// The ends of the domain of a closed circle, whose foot at the seam is either.
    fn seam(&self) -> Option<(f64, f64)> {
        match self {
            Second::Circle { spans, .. } => {
                let (a, b) = (spans.first()?, spans.last()?);
                (a.points[0] == b.points[2]).then_some((a.domain.0, b.domain.1))
            }
            Second::Line { .. } => None,
        }
    }

    /// The point `q` that `V` is taken about, and the edge points whose planes bound the foot.
    fn pivot(&self) -> [f64; 2] {
        match self {
            Second::Line { from, .. } => *from,
            Second::Circle { center, .. } => *center,
        }
    }

    /// The foot of `x` (whose distance from the carrier is `|s|`, on the side `k` says for a
    /// circle): its parameter, clamped to the segment (with `exact`; else only the span's
    /// start on an arc), and whether it lies on the segment.
    fn foot(&self, x: [f64; 2], k: f64, exact: bool) -> Option<(f64, bool)> {
        match self {
            Second::Line {
                from,
                along,
                domain,
            } => {
                let f = dot(sub(x, *from), *along) / dot(*along, *along);
                let inside = (0.0..=1.0).contains(&f);
                let f = f.clamp(0.0, 1.0);
                Some((domain.0 + f * (domain.1 - domain.0), inside))
            }
            Second::Circle {
                center,
                radius,
                spans,
                hom,
                velocity,
            } => {
                if k == 0.0 || !k.is_finite() {
                    return None;
                }
                let dir = sub(x, *center);
                let dir = [dir[0] * k.signum(), dir[1] * k.signum()];
                let len = dir[0].hypot(dir[1]);
                if len.is_nan() || len == 0.0 {
                    return None;
                }
                let dir = [dir[0] / len, dir[1] / len];
                let within = |s: &Span| {
                    let (e0, e1) = (sub(s.points[0], *center), sub(s.points[2], *center));
                    s.turn * cross(e0, dir) >= 0.0 && s.turn * cross(dir, e1) >= 0.0
                };
                let (span, inside) = match spans.iter().find(|s| within(s)) {
                    Some(s) => (s, true),
                    // Outside the arc: the nearer end (by the angle to it).
                    None => {
                        let (first, last) = (spans.first()?, spans.last()?);
                        let cos_to = |p: [f64; 2]| dot(sub(p, *center), dir);
                        let r = if cos_to(first.points[0]) >= cos_to(last.points[2]) {
                            first.domain.0
                        } else {
                            last.domain.1
                        };
                        return Some((r, false));
                    }
                };
                if !exact {
                    return Some((span.domain.0, inside));
                }
                let foot = [center[0] + radius * dir[0], center[1] + radius * dir[1]];
                let mut r = barycentric(span, foot);
                // Newton on the side of the foot's ray, `dir × (C(r) − c₂) = 0`.
                for _ in 0..FOOT_NEWTON {
                    let (mut h, mut dh) = ([0.0; 3], [0.0; 3]);
                    hom.eval(r, &mut h);
                    velocity.eval(r, &mut dh);
                    let c = [h[0] / h[2], h[1] / h[2]];
                    let dc = [(dh[0] - c[0] * dh[2]) / h[2], (dh[1] - c[1] * dh[2]) / h[2]];
                    let g = cross(dir, sub(c, *center));
                    let dg = cross(dir, dc);
                    if dg == 0.0 || !dg.is_finite() {
                        break;
                    }
                    let next = (r - g / dg).clamp(span.domain.0, span.domain.1);
                    let converged = (next - r).abs() <= ulps(1.0) * (1.0 + r.abs());
                    r = next;
                    if converged {
                        break;
                    }
                }
                Some((r, inside))
            }
        }
    }
}

/// The parameter of `foot` (on the arc, inside the span) from its barycentric coordinates in
/// the control triangle, which are the rational Bernstein terms: `λ₂ / λ₀ = u² w₂ / ((1 − u)² w₀)`.
fn barycentric(s: &Span, foot: [f64; 2]) -> f64 {
    let [q0, q1, q2] = s.points;
    let orient = cross(sub(q1, q0), sub(q2, q0)).signum();
    let l0 = (orient * cross(sub(q1, foot), sub(q2, foot))).max(0.0);
    let l2 = (orient * cross(sub(q0, foot), sub(q1, foot))).max(0.0);
    let (a, b) = ((l2 * s.weights[0]).sqrt(), (l0 * s.weights[2]).sqrt());
    let u = if a + b > 0.0 { a / (a + b) } else { 0.5 };
    s.domain.0 + u * (s.domain.1 - s.domain.0)
}

/// `N`, `D` and the cut functions for one sign `τ`.
struct Signed {
    tau: f64,
    d: Piecewise,
    /// `N`, `D`, `p`, `w` and `m` stacked: one evaluation per point.
    values: Piecewise,
    /// `k D` (a circle's): where the foot jumps to the antipode.
    k: Option<Piecewise>,
    /// The sign functions of the foot's planes, one per edge point in order.
    edges: Vec<Piecewise>,
}

/// A bisector point and the parameter of its foot on the second segment.
struct Vertex {
    x: [f64; 2],
    r: f64,
}

impl Signed {
    /// `None` where `D` vanishes for this sign: a line tangent to the circle, all of whose
    /// bisector points for this sign lie on the normal common to both at the point of contact,
    /// with both feet there (none determined by the feet) but for the circle's centre
    /// ([`tangent_centre`]).
    fn new(a: &First, b: &Second, tau: f64) -> Result<Option<Self>> {
        let q0 = b.pivot();
        let q =
            a.p.sub(&Piecewise::stack(&[&a.w.scale(q0[0]), &a.w.scale(q0[1])])?)?;
        let rho = a.rho;
        // `terms`: the two terms `D` is the difference of, by their largest coefficients.
        let (n, d, k, terms) = match b {
            Second::Line { along, .. } => {
                let nu = [-along[1], along[0]];
                let n = q
                    .components(&[0])?
                    .lincomb(nu[0], &q.components(&[1])?, nu[1])?
                    .scale(rho);
                let m_nu =
                    a.m.components(&[0])?
                        .lincomb(nu[0], &a.m.components(&[1])?, nu[1])?;
                let d = a.w.lincomb(tau * rho * nu[0].hypot(nu[1]), &m_nu, -1.0)?;
                let terms = [rho * nu[0].hypot(nu[1]) * largest(&a.w), largest(&m_nu)];
                (n, d, None, terms)
            }
            Second::Circle { radius, .. } => {
                let w2 = a.w.mul(&a.w)?;
                let n = q.dot(&q)?.lincomb(1.0, &w2, -radius * radius)?.scale(rho);
                let m_q = a.m.dot(&q)?;
                let d = w2.lincomb(2.0 * tau * radius * rho, &m_q, -2.0)?;
                let terms = [2.0 * radius * rho * largest(&w2), 2.0 * largest(&m_q)];
                let k = d.lincomb(*radius, &n, tau)?;
                (n, d, Some(k), terms)
            }
        };
        let noise = TANGENT * terms[0].max(terms[1]);
        let vanishes =
            (0..d.pieces()).all(|i| d.piece(i).iter().all(|x| x.abs() <= d.error(i).max(noise)));
        if vanishes {
            return Ok(None);
        }
        let v = d.mul(&q)?.scale(rho).lincomb(1.0, &n.mul(&a.m)?, 1.0)?;
        let (v0, v1) = (v.components(&[0])?, v.components(&[1])?);
        let edges = match b {
            Second::Line { along, .. } => {
                let g0 = v0.lincomb(along[0], &v1, along[1])?;
                let g1 = g0.lincomb(1.0, &a.w.mul(&d)?, -rho * dot(*along, *along))?;
                vec![g0, g1]
            }
            Second::Circle { center, spans, .. } => {
                let mut points: Vec<[f64; 2]> = spans.iter().map(|s| s.points[0]).collect();
                points.extend(spans.last().map(|s| s.points[2]));
                points
                    .into_iter()
                    .map(|p| {
                        let e = sub(p, *center);
                        v1.lincomb(e[0], &v0, -e[1])
                    })
                    .collect::<std::result::Result<_, _>>()?
            }
        };
        let values = Piecewise::stack(&[&n, &d, &a.p, &a.w, &a.m])?;
        Ok(Some(Self {
            tau,
            d,
            values,
            k,
            edges,
        }))
    }

    /// The bisector point at `t` and, for a circle, `k = ρ₂ + τ s` (`None` at infinity).
    fn point(&self, a: &First, b: &Second, t: f64) -> Option<([f64; 2], f64)> {
        let mut v = [0.0; 7];
        self.values.eval(t, &mut v);
        let [n, d, px, py, w, mx, my] = v;
        let s = n / d;
        let k = a.rho * w;
        let x = [px / w + s * (mx / k), py / w + s * (my / k)];
        if !(x[0].is_finite() && x[1].is_finite()) {
            return None;
        }
        let k = match b {
            Second::Line { .. } => 1.0,
            Second::Circle { radius, .. } => radius + self.tau * s,
        };
        Some((x, k))
    }

    /// Whether the foot of the bisector point at `t` lies on the second segment.
    fn counts(&self, a: &First, b: &Second, t: f64) -> bool {
        self.point(a, b, t)
            .and_then(|(x, k)| b.foot(x, k, false))
            .is_some_and(|(_, inside)| inside)
    }

    /// The bisector point at `t` with its foot (`None` at infinity, or at a circle's centre).
    fn at(&self, a: &First, b: &Second, t: f64) -> Option<Vertex> {
        let (x, k) = self.point(a, b, t)?;
        let (r, _) = b.foot(x, k, true)?;
        Some(Vertex { x, r })
    }
}

/// Inserts vertices between two, so that each foot moves by at most its step.
struct Feet<'a, F: Fn(f64) -> Option<Vertex>> {
    at: &'a F,
    steps: [f64; 2],
}

impl<F: Fn(f64) -> Option<Vertex>> Feet<'_, F> {
    /// The vertices strictly between `a` and `b` (`t`, `r`, global point), appended.
    fn between(
        &self,
        a: (f64, f64, [f64; 2]),
        b: (f64, f64, [f64; 2]),
        frame: &Frame,
        depth: usize,
        tr: &mut Vec<[f64; 2]>,
        xy: &mut Vec<[f64; 2]>,
    ) {
        let dense = (b.0 - a.0).abs() <= self.steps[0] && (b.1 - a.1).abs() <= self.steps[1];
        if dense || depth == 0 {
            return;
        }
        let t = 0.5 * (a.0 + b.0);
        let Some(v) = (self.at)(t) else { return };
        let m = (t, v.r, frame.to_global(v.x));
        self.between(a, m, frame, depth - 1, tr, xy);
        tr.push([m.0, m.1]);
        xy.push(m.2);
        self.between(m, b, frame, depth - 1, tr, xy);
    }
}

/// The largest coefficient of a function, in magnitude.
fn largest(f: &Piecewise) -> f64 {
    (0..f.pieces())
        .flat_map(|i| f.piece(i).iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

/// The end points of a straight segment (degree 1, two control points, apart).
fn line_ends(c: &Rational) -> Option<[[f64; 2]; 2]> {
    let pts = c.control_points();
    if c.degree() != 1 || c.is_rational() || pts.len() != 2 {
        return None;
    }
    let (a, b) = ([pts[0][0], pts[0][1]], [pts[1][0], pts[1][1]]);
    (a != b).then_some([a, b])
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

#[cfg(test)]
mod tests;
