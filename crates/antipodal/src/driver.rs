//! The runs on a prepared curve: validation and dissection (§5.1–5.2), the pair loop of §5,
//! and the two-curve common tangents of §2.5, in the curve's frame.

use crate::dissect::{Piece, Zeros};
use crate::error::{Error, Result};
use crate::families::{family_of, flat_pairs, is_family, merge_families};
use crate::finish::certified_rest;
use crate::ledger::Ledger;
use crate::pairs::THETA_NOISE;
use crate::pairs::{negligible, opposite_pair, touching_ends, Pair};
use crate::search::{antipodal_points, Budget};
use crate::tangent;
use crate::tracks::Tracks;
use crate::types::{
    Antipodal, AntipodalPair, Inflection, InflectionKind, Inflections, Options, PairType,
    TangentLine, Tangents,
};
use crate::view::{Source, View};
use curve::{wrap_pi, V2};
use numeric::certificate::{Certified, Doubt, Doubts};
use smallvec::SmallVec;

/// A validated, dissected curve.
pub(crate) struct Dissected<'a> {
    pub(crate) view: View<'a>,
    #[allow(dead_code)] // (kept with the dissection it was built for)
    tracks: Tracks,
    zeros: Zeros,
    pub(crate) pieces: Vec<Piece>,
}

/// Largest angle between the tangents at a closed curve's two ends that is still no corner:
/// far above the rounding of the tangents' directions, far below any drawn corner.
const SEAM_CORNER: f64 = 1e-7;

/// Orients (closed curves counterclockwise, unless `force_rev` is given), validates and
/// dissects, with the doubts met; the view keeps its doubts in the ledgers' book `book`.
pub(crate) fn dissect<'a>(
    src: Source<'a>,
    opts: &Options,
    force_rev: Option<bool>,
    book: usize,
) -> Result<Certified<Dissected<'a>>> {
    opts.validate()?;
    let curve = src.curve;
    let knots: Vec<f64> = src
        .forms
        .map(|f| f.hom.breaks().to_vec())
        .unwrap_or_default();
    let closed = curve.is_closed();
    if closed {
        let (a, b) = curve.domain();
        let (ta, tb) = (curve.jet(a).d1, curve.jet(b).d1);
        let angle = wrap_pi(tb.angle() - ta.angle()).abs();
        if angle > SEAM_CORNER {
            return Err(Error::Corner { angle });
        }
    }
    let (view, tracks) = match force_rev {
        Some(rev) => {
            let view = View::new(src, rev, opts.settings.tol.get());
            let tracks = view.value.tracks(&knots)?;
            (view, tracks)
        }
        None => {
            // Orientation from the turning of the tangent (±2π); a clockwise curve is viewed
            // reversed, reusing the same track.
            let view = View::new(src, false, opts.settings.tol.get());
            let tracks = view.value.tracks(&knots)?;
            if closed && tracks.turn() < 0.0 {
                let (a, b) = curve.domain();
                (
                    View::new(src, true, opts.settings.tol.get()),
                    tracks.reversed(a, b),
                )
            } else {
                (view, tracks)
            }
        }
    };
    // (The view first oriented the other way is dropped with its doubts.)
    let (mut view, mut doubts) = view.into_parts();
    view.book = book;
    let zeros = view.inflections(Some(&tracks), &mut doubts)?;
    if closed && !src.simple {
        view.check_simple(&tracks, &zeros, &mut doubts)?;
    }
    if closed && zeros.zs.len() % 2 == 1 {
        doubts.add(Doubt::OddInflections);
    }
    let pieces = view.pieces(&tracks, &zeros, &mut doubts);
    let dissected = Dissected {
        view,
        tracks,
        zeros,
        pieces,
    };
    Ok(Certified {
        value: dissected,
        doubts,
    })
}

/// The inflections of a dissection as reported: its sign changes of the curvature but the
/// corners, and the straight stretches between a left and a right turn, in the curve's
/// parameters; `certified`: no doubt was met on the view so far.
fn inflection_list(v: &View, zeros: &Zeros, certified: bool) -> Vec<Inflection> {
    let mut out: Vec<Inflection> = zeros
        .zs
        .iter()
        .filter(|z| !z.corner)
        .chain(&zeros.flat_changes)
        .map(|z| Inflection {
            u: v.to_curve(z.u),
            p: v.point(z.u).arr(),
            certified: certified && z.certified,
            kind: match z.cluster {
                true => InflectionKind::Cluster,
                false => InflectionKind::Simple,
            },
            bracket: z.bracket.map(|(lo, hi)| v.bracket_to_curve(lo, hi)),
            segment: None,
        })
        .collect();
    out.sort_by(|a, b| a.u.total_cmp(&b.u));
    out
}

/// All simple inflections of the curve of `src` (Jia §5.1; certified with symbolic forms), in
/// its coordinates, with the doubts met (stated where the result is finished:
/// [`crate::types::Provenance`]).
pub(crate) fn inflections_of(src: Source<'_>, opts: &Options) -> Result<Certified<Inflections>> {
    opts.validate()?;
    let (view, mut doubts) = View::new(src, false, opts.settings.tol.get()).into_parts();
    // With symbolic forms the curve is proven regular (a cusp's vanishing curvature numerator
    // would pass for an inflection) and the inflections need no track; without, Jia's sampled
    // track (which refuses vanishing speeds) finds them.
    // (An analytic shape is regular by construction.)
    let tracks = match &view.cert {
        Some(_) if src.simple => None,
        Some(cert) => {
            if let Some(u) = cert.singular_point(view.tol)? {
                return Err(Error::Cusp {
                    u: view.to_curve(u),
                });
            }
            None
        }
        None => Some(view.tracks(&[])?),
    };
    let zeros = view.inflections(tracks.as_ref(), &mut doubts)?;
    let inflections = inflection_list(&view, &zeros, doubts.is_empty());
    if inflections.iter().any(|i| !i.certified) {
        doubts.add(Doubt::RootCluster);
    }
    let found = Inflections {
        inflections,
        corners: None,
        doubts: Doubts::none(),
    };
    Ok(Certified {
        value: found,
        doubts,
    })
}

/// Every pair of antipodal points of the simple closed curve of `src` (Jia 2004), in its
/// coordinates, with the doubts met (stated where the result is finished:
/// [`crate::types::Provenance`]).
pub(crate) fn antipodal_of(src: Source<'_>, opts: &Options) -> Result<Certified<Antipodal>> {
    let curve = src.curve;
    if !curve.is_closed() {
        let (a, b) = curve.domain();
        return Err(Error::NotClosed {
            gap: (curve.jet(a).p - curve.jet(b).p).norm(),
        });
    }
    let (prep, dissect_doubts) = dissect(src, opts, None, 0)?.into_parts();
    let v = &prep.view;
    // (One view: every doubt of the run is its own, in the order met.)
    let mut ledger = Ledger::new();
    *ledger.of(v) = dissect_doubts;
    let mut raw: Vec<(f64, f64)> = Vec::with_capacity(32);
    let mut families = Vec::new();
    let mut budget = Budget {
        sections: opts.max_sections,
        exhausted: false,
    };
    let mut stack = Vec::with_capacity(16);
    let n = prep.pieces.len();
    // A straight stretch is searched as one segment with one normal: a proven chain of
    // segments (a polyline's corners inside) is not one.
    if prep.pieces.iter().any(|p| {
        p.flat && v.straight_span(p.lo, p.hi).is_none() && v.straight_chain(p.lo, p.hi).is_some()
    }) {
        ledger.of(v).add(Doubt::CornerInStraight);
    }
    for i in 0..n {
        for j in i + 1..n {
            let (p, q) = (&prep.pieces[i], &prep.pieces[j]);
            if p.flat || q.flat {
                flat_pairs(v, p, v, q, &mut raw, &mut families, &mut ledger);
                continue;
            }
            let Some(pair) = opposite_pair(v, p, v, q, &mut ledger) else {
                // (Normals opposite only at an end of each: that pair of ends, if antipodal.)
                raw.extend(touching_ends(v, p, v, q).and_then(|at| at.antipodal_start()));
                continue;
            };
            if is_family(&pair, &mut ledger) {
                // (θ vanishing within rounding all along: only a curve defined as a circle is
                // proven to have a continuum of pairs.)
                if !v.exact_circle {
                    ledger.of(v).add(Doubt::Continuum);
                }
                families.push((pair.sa, pair.sb, pair.ta, pair.tb));
                continue;
            }
            for sec in sections(&pair, &mut ledger) {
                let sec = trim_antipodal_ends(&sec, &mut raw, &mut ledger);
                if let Some(sec) = sec {
                    antipodal_points(&sec, &mut raw, &mut budget, &mut stack, &mut ledger);
                }
            }
        }
    }
    let families = merge_families(v, families);
    let pairs = finish_pairs(v, raw, &families, ledger.of(v));
    let doubts = ledger.take(v.book);
    let found = Antipodal {
        pairs,
        inflections: inflection_list(v, &prep.zeros, doubts.is_empty()),
        corners: None,
        families: families.iter().map(|&f| family_of(v, f)).collect(),
        doubts: Doubts::none(),
        complete: !budget.exhausted,
    };
    Ok(Certified {
        value: found,
        doubts,
    })
}

/// §5.3: the sections of a pair where `N(s) · r(s) > 0` (condition (v)), cut at the common
/// tangents, and where the curvature of either segment may jump ([`curvature_jump_cuts`]).
pub(crate) fn sections<'a>(p: &Pair<'a>, ledger: &mut Ledger) -> SmallVec<[Pair<'a>; 3]> {
    let tangents = tangent::common_tangents(p, ledger);
    let mut cuts: SmallVec<[(f64, f64); 4]> = SmallVec::new();
    cuts.push((p.sa, p.ta));
    cuts.extend(
        tangents
            .iter()
            .copied()
            .filter(|c| c.0 > p.sa && c.0 < p.sb),
    );
    cuts.extend(curvature_jump_cuts(p, ledger));
    cuts[1..].sort_by(|x, y| x.0.total_cmp(&y.0));
    cuts.push((p.sb, p.tb));
    let mut out = SmallVec::new();
    // d has no zero inside a window (its zeros are the common tangents, the cuts): its sign
    // at an end where it is clear of zero is the window's; else it is taken in the middle.
    let clear = D_CLEAR * p.vs.scale.max(p.vt.scale);
    let sign_at = |s: f64, t: f64| {
        let d = p.d(s, t);
        (d.abs() > clear).then_some(d > 0.0)
    };
    for w in cuts.windows(2) {
        let ((s0, t0), (s1, t1)) = (w[0], w[1]);
        if negligible(p.vs, s0, s1) {
            continue;
        }
        let facing = sign_at(s0, t0)
            .or_else(|| sign_at(s1, t1))
            .unwrap_or_else(|| {
                let sm = 0.5 * (s0 + s1);
                let tm = p.opposite_between(sm, (s0, t0), (s1, t1), ledger.of(p.vt));
                p.d(sm, tm) > 0.0
            });
        if facing {
            out.push(p.sub(s0, t0, s1, t1));
        }
    }
    out
}

/// The opposite points `(s, t)` of `p` where the curvature of `S` (at `s`) or of `T` (at `t`)
/// may jump ([`View::curvature_jumps`]), strictly inside the pair. Jia's march and the proofs
/// that a stretch holds no pair assume the curvature continuous: θ has a kink where it jumps
/// and may touch zero there without changing sign (a pair of knots of a quadratic, opposite
/// by symmetry), which no march reports. Cut there, each such point is an end of two
/// sections and is tested as every end is ([`trim_antipodal_ends`]); inside a section the
/// curvature is continuous.
fn curvature_jump_cuts(p: &Pair, ledger: &mut Ledger) -> SmallVec<[(f64, f64); 2]> {
    let mut out: SmallVec<[(f64, f64); 2]> = SmallVec::new();
    let (a, b) = ((p.sa, p.ta), (p.sb, p.tb));
    for s in p.vs.curvature_jumps(p.sa, p.sb) {
        out.push((s, p.opposite_between(s, a, b, ledger.of(p.vt))));
    }
    let (t_lo, t_hi) = p.t_range();
    let jumps_t = p.vt.curvature_jumps(t_lo, t_hi);
    if !jumps_t.is_empty() {
        let q = p.swapped();
        let (qa, qb) = ((q.sa, q.ta), (q.sb, q.tb));
        for t in jumps_t {
            let s = q.opposite_between(t, qa, qb, ledger.of(p.vs));
            if s > p.sa && s < p.sb {
                out.push((s, t));
            }
        }
    }
    out
}

/// Condition (iv): an end that is itself antipodal is reported and cut off: on curves with
/// symbolic forms as far as θ is proven monotone from it (as beside any found pair), else
/// where θ first shows a sign beyond its noise.
pub(crate) fn trim_antipodal_ends<'a>(
    p: &Pair<'a>,
    raw: &mut Vec<(f64, f64)>,
    ledger: &mut Ledger,
) -> Option<Pair<'a>> {
    let mut q = *p;
    // (Only opposite points are solved, on T: its doubts.)
    let doubts = ledger.of(p.vt);
    let certified = p.vs.cert.is_some() && p.vt.cert.is_some();
    for at_a in [true, false] {
        let (s, t) = if at_a { (q.sa, q.ta) } else { (q.sb, q.tb) };
        if q.is_clear(s, t, q.sin_theta(s, t)) || q.d(s, t) <= 0.0 {
            continue;
        }
        raw.push((s, t));
        let dir = if at_a { 1.0 } else { -1.0 };
        if certified {
            match certified_rest(&q, s, t, dir, doubts) {
                Some(None) => return None,
                Some(Some(rest)) => {
                    q = rest;
                    continue;
                }
                None => {}
            }
        }
        let mut eps = 16.0 * q.vs.tol;
        let mut cut = None;
        for _ in 0..64 {
            let se = s + dir * eps;
            if se <= q.sa || se >= q.sb {
                break;
            }
            let te = q.opposite(se, doubts)?;
            if q.is_clear(se, te, q.sin_theta(se, te)) {
                cut = Some((se, te));
                break;
            }
            eps *= 2.0;
        }
        let (se, te) = cut?;
        q = if at_a {
            q.sub(se, te, q.sb, q.tb)
        } else {
            q.sub(q.sa, q.ta, se, te)
        };
    }
    Some(q)
}

/// The type of the pair of `vs` at `s` and `vt` at `t` (Jia 2004, §3.3).
pub(crate) fn classify(vs: &View, vt: &View, s: f64, t: f64) -> PairType {
    let (js, jt) = (vs.jet_to(s, 2), vt.jet_to(t, 2));
    pair_type(js.curvature(), jt.curvature(), (jt.p - js.p).norm())
}

/// The type of a pair at distance `r` whose curvatures are `ks` and `kt`, signed positive
/// where the curve turns the way it runs round its region (Jia 2004, §3.3).
pub(crate) fn pair_type(ks: f64, kt: f64, r: f64) -> PairType {
    let radii = 1.0 / ks + 1.0 / kt;
    match (ks > 0.0, kt > 0.0) {
        (true, true) if radii < r => PairType::A,
        (true, true) => PairType::B,
        (false, false) => PairType::E,
        _ if radii > r => PairType::C,
        _ => PairType::D,
    }
}

/// Polishes, validates (inward normals facing each other), deduplicates modulo the period,
/// classifies and maps to the curve's parameters.
fn finish_pairs(
    v: &View,
    raw: Vec<(f64, f64)>,
    families: &[(f64, f64, f64, f64)],
    doubts: &mut Doubts,
) -> Vec<AntipodalPair> {
    let within = |x: f64, a: f64, b: f64| {
        let (lo, hi) = (a.min(b), a.max(b));
        let slack = FAMILY_SLACK * v.period;
        let k = ((x - lo + slack) / v.period).floor();
        let xx = x - k * v.period;
        xx >= lo - slack && xx <= hi + slack
    };
    let in_family = |s: f64, t: f64| {
        families.iter().any(|&(sa, sb, ta, tb)| {
            (within(s, sa, sb) && within(t, ta, tb)) || (within(t, sa, sb) && within(s, ta, tb))
        })
    };
    let mut keep: Vec<(f64, f64)> = Vec::new();
    // (Both wrapped into the domain: their distance around the curve needs no remainder.)
    let close = |x: f64, y: f64| {
        let d = (x - y).abs();
        d.min(v.period - d) <= DUPLICATE * v.period
    };
    for (s, t) in raw {
        let (s, t) =
            crate::pairs::polish(v, v, s, t, FINAL_POLISH_REACH * v.period).unwrap_or((s, t));
        let (js, jt) = (v.jet_to(s, 1), v.jet_to(t, 1));
        let r = jt.p - js.p;
        if js.normal().dot(r) <= 0.0 || js.d1.dot(jt.d1) >= 0.0 {
            continue;
        }
        // A point that is no pair (θ beyond any rounding) is a defect upstream: never report
        // it.
        if js.normal().cross(r).abs() > THETA_NOISE * r.norm() {
            doubts.add(Doubt::NotAPair);
            continue;
        }
        let (s, t) = (v.wrap(s), v.wrap(t));
        if in_family(s, t) {
            continue;
        }
        if keep
            .iter()
            .any(|&(a, b)| (close(a, s) && close(b, t)) || (close(a, t) && close(b, s)))
        {
            continue;
        }
        keep.push((s, t));
    }
    let mut out: Vec<AntipodalPair> = keep
        .into_iter()
        .map(|(s, t)| {
            let kind = classify(v, v, s, t);
            let (cs, ct) = (v.to_curve(s), v.to_curve(t));
            let (cs, ct, s, t) = if cs <= ct {
                (cs, ct, s, t)
            } else {
                (ct, cs, t, s)
            };
            let (p, q) = (v.point(s), v.point(t));
            AntipodalPair {
                s: cs,
                t: ct,
                p: p.arr(),
                q: q.arr(),
                distance: (q - p).norm(),
                kind: Some(kind),
                corner: None,
                segment: None,
            }
        })
        .collect();
    out.sort_by(|a, b| a.s.total_cmp(&b.s));
    out
}

/// Segments of two different curves may cross, and then Theorem 2 (at most two common
/// tangents) no longer holds. Each segment lies in the triangle of its chord and end tangents;
/// while the two triangles' boxes overlap, the pair is halved (at the middle `s` and its
/// opposite `t`), which keeps conditions (i)–(iii).
fn tangents_of_disjoint(
    p: &Pair,
    depth: usize,
    leaves: &mut usize,
    out: &mut Vec<(f64, f64)>,
    ledger: &mut Ledger,
) {
    // Coinciding stretches (the same curve twice) share a continuum of tangents: skip them.
    let coincide = [0.0, 0.5, 1.0].iter().all(|&f| {
        let s = p.sa + f * (p.sb - p.sa);
        let t = if f == 0.0 {
            Some(p.ta)
        } else if f == 1.0 {
            Some(p.tb)
        } else {
            p.opposite(s, ledger.of(p.vt))
        };
        t.is_some_and(|t| p.r(s, t).norm() <= COINCIDE * p.vs.scale)
    });
    if coincide || *leaves == 0 {
        ledger.of(p.vs).add(Doubt::CurvesTouch);
        return;
    }
    let (tl, th) = p.t_range();
    let overlap = match (p.vs.arc_box(p.sa, p.sb), p.vt.arc_box(tl, th)) {
        (Some(a), Some(b)) => a.0.x <= b.1.x && b.0.x <= a.1.x && a.0.y <= b.1.y && b.0.y <= a.1.y,
        _ => true,
    };
    if overlap && depth < 24 && p.sb - p.sa > 1e3 * p.vs.tol {
        let sm = 0.5 * (p.sa + p.sb);
        if let Some(tm) = p.opposite(sm, ledger.of(p.vt)) {
            tangents_of_disjoint(&p.sub(p.sa, p.ta, sm, tm), depth + 1, leaves, out, ledger);
            tangents_of_disjoint(&p.sub(sm, tm, p.sb, p.tb), depth + 1, leaves, out, ledger);
            return;
        }
    }
    if overlap {
        ledger.of(p.vs).add(Doubt::CurvesTouch);
    }
    *leaves -= 1;
    out.extend(tangent::common_tangents(p, ledger));
}

/// Every line tangent to both curves of `s1` and `s2` (Jia §2.5), in their common
/// coordinates: pairs of monotone pieces with opposite normals, then again with the normals of
/// the second curve reversed. `same`: the two are one curve (a tangent touching it at one
/// point is no common tangent). With the doubts met: the first curve's before the second's
/// (stated where the result is finished: [`crate::types::Provenance`]).
pub(crate) fn tangents_of(
    s1: Source<'_>,
    s2: Source<'_>,
    same: bool,
    opts: &Options,
) -> Result<Certified<Tangents>> {
    let (c1, c2) = (s1.curve, s2.curve);
    let (a, mut doubts) = dissect(s1, opts, Some(false), FIRST_CURVE)?.into_parts();
    // (s, t) reported, and the points of tangency.
    let mut lines: Vec<(f64, f64, V2, V2)> = Vec::new();
    let mut ledger = Ledger::new();
    // The domain of the parameters reported on the second curve.
    let mut pb = (0.0, 0.0);
    for rev in [false, true] {
        let (b, b_doubts) = dissect(s2, opts, Some(rev), SECOND_CURVE)?.into_parts();
        *ledger.of(&b.view) = b_doubts;
        pb = b.view.reported_domain();
        for p in &a.pieces {
            for q in &b.pieces {
                let mut found = Vec::new();
                match opposite_pair(&a.view, p, &b.view, q, &mut ledger) {
                    Some(pair) => {
                        let mut leaves = 4096usize;
                        tangents_of_disjoint(&pair, 0, &mut leaves, &mut found, &mut ledger);
                    }
                    // (Normals opposite only at an end of each: the line there, if tangent
                    // to both.)
                    None => found.extend(
                        touching_ends(&a.view, p, &b.view, q)
                            .and_then(|at| tangent::tangent_start(&at)),
                    ),
                }
                for (s, t) in found {
                    let (s, t) = crate::pairs::polish_tangent(
                        &a.view,
                        &b.view,
                        s,
                        t,
                        TANGENT_POLISH_REACH * a.view.period.max(b.view.period),
                    )
                    .unwrap_or((s, t));
                    lines.push((
                        a.view.to_curve(s),
                        b.view.to_curve(t),
                        a.view.point(s),
                        b.view.point(t),
                    ));
                }
            }
        }
        // The first curve's doubts before the second's (each view of the second is dropped
        // with its own).
        doubts.join(ledger.take(FIRST_CURVE));
        doubts.join(ledger.take(SECOND_CURVE));
    }
    let pa = a.view.reported_domain();
    let close = |x: f64, y: f64, per: f64, closed: bool| {
        let d = (x - y).abs();
        let d = if closed { d.min(per - d) } else { d };
        d <= DUPLICATE * per
    };
    let size = a.view.scale;
    let mut out: Vec<TangentLine> = Vec::new();
    for (s, t, p, q) in lines {
        // With one curve twice, a "common" tangent touching at a single point (an inflection's
        // two sides meeting) is just a tangent: not a line through two points.
        if same && (p - q).norm() <= ONE_POINT * size {
            continue;
        }
        if out.iter().any(|l| {
            close(l.s, s, pa.1 - pa.0, c1.is_closed()) && close(l.t, t, pb.1 - pb.0, c2.is_closed())
        }) {
            continue;
        }
        out.push(TangentLine {
            s,
            t,
            p: p.arr(),
            q: q.arr(),
            corner: None,
            segment: None,
        });
    }
    out.sort_by(|x, y| x.s.total_cmp(&y.s));
    let found = Tangents {
        lines: out,
        doubts: Doubts::none(),
    };
    Ok(Certified {
        value: found,
        doubts,
    })
}

/// The ledgers' books of the two curves of [`tangents_of`].
const FIRST_CURVE: usize = 0;
const SECOND_CURVE: usize = 1;

/// The distance between the tangent lines (relative to the curves' size) from which its sign
/// at a window's end is taken for the window's: far above its rounding.
const D_CLEAR: f64 = 1e-6;

/// Room (relative to the period) for a pair on a family's end to count as inside it.
const FAMILY_SLACK: f64 = 1e-9;

/// Two results closer than this (relative to the period, in both parameters) are one: the
/// same pair or tangent found from two sections, far above the tolerances they were solved to.
const DUPLICATE: f64 = 1e-7;

/// How far (relative to the period) the final polish of a pair may move it: a pair found to
/// a loose tolerance still lies well within this of the root Newton's method converges to.
const FINAL_POLISH_REACH: f64 = 1e-4;

/// The same for a common tangent.
const TANGENT_POLISH_REACH: f64 = 1e-6;

/// The distance (relative to the size) below which two stretches coincide: the same curve
/// twice, with a continuum of tangents.
const COINCIDE: f64 = 1e-9;

/// The distance (relative to the size) below which a common tangent of a curve with itself
/// touches at one point (an inflection's two sides meeting), not two.
const ONE_POINT: f64 = 1e-5;

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::prepare::tests::{as_given, star_curve};
    use crate::Options;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: testkit::cases(48), ..ProptestConfig::default() })]

        /// A periodic quadratic's curvature may jump at every knot (the integers): no section
        /// holds one inside, in `s` or in `t`, so Jia's march and the proofs of a section only
        /// ever see a continuous curvature.
        #[test]
        fn no_section_holds_a_quadratic_knot(
            seed in proptest::collection::vec(0.0f64..1.0, 12..=28),
            weights in proptest::collection::vec(0.5f64..2.0, 14),
            rational in any::<bool>(),
        ) {
            let curve = star_curve(2, &seed, rational.then_some(&weights[..]));
            let given = as_given(&curve);
            let Ok(prep) = dissect(given.source(true), &Options::default(), None, 0) else {
                return Ok(());
            };
            let (prep, _) = prep.into_parts();
            let (v, pieces) = (&prep.view, &prep.pieces);
            // A knot within this of a section's end is that end.
            let slack = 1e-9 * v.period;
            let inside = |lo: f64, hi: f64| {
                let k = (lo + slack).ceil();
                (k < hi - slack).then_some(k)
            };
            let mut ledger = Ledger::new();
            let mut checked = 0;
            for i in 0..pieces.len() {
                for j in i + 1..pieces.len() {
                    let (p, q) = (&pieces[i], &pieces[j]);
                    if p.flat || q.flat {
                        continue;
                    }
                    let Some(pair) = opposite_pair(v, p, v, q, &mut ledger) else {
                        continue;
                    };
                    for sec in sections(&pair, &mut ledger) {
                        let (tl, th) = sec.t_range();
                        prop_assert_eq!(inside(sec.sa, sec.sb), None, "s in [{}, {}]", sec.sa, sec.sb);
                        prop_assert_eq!(inside(tl, th), None, "t in [{}, {}]", tl, th);
                        checked += 1;
                    }
                }
            }
            prop_assert!(checked > 0);
        }
    }
}
