//! Degenerate input: continua of antipodal pairs (circles, concentric arcs, facing straight
//! stretches) are reported as families instead of floods of pairs.

use crate::dissect::Piece;
use crate::ledger::Ledger;
use crate::pairs::Pair;
use crate::types::Family;
use crate::view::View;
use curve::exact::cross_sign;
use numeric::certificate::Doubt;
use std::cmp::Ordering;

/// Pairs involving a straight stretch: two facing parallel stretches make a family; a curved
/// piece pairs with a stretch where its normal is opposite to the stretch's and the normal line
/// meets the stretch. The pieces may lie on two views of one curve's stretches (the segments of
/// a profile); pairs and families come out with the straight piece's side first (`p`'s where
/// both are straight).
pub(crate) fn flat_pairs(
    vp: &View,
    p: &Piece,
    vq: &View,
    q: &Piece,
    raw: &mut Vec<(f64, f64)>,
    families: &mut Vec<(f64, f64, f64, f64)>,
    ledger: &mut Ledger,
) {
    let ((vf, f), (vg, g)) = if !p.flat {
        ((vq, q), (vp, p))
    } else {
        ((vp, p), (vq, q))
    };
    let nf = vf.normal(0.5 * (f.lo + f.hi));
    let pf = vf.point(f.lo);
    let scale = vf.scale.max(vg.scale);
    if g.flat {
        let ng = vg.normal(0.5 * (g.lo + g.hi));
        if (nf + ng).norm() > OPPOSITE_NORMALS || nf.dot(vg.point(g.lo) - pf) <= 0.0 {
            return;
        }
        // A continuum of pairs only between exactly parallel stretches: proven on the data
        // where both are proven straight, a judgement elsewhere.
        let parallel = match (vf.straight_span(f.lo, f.hi), vg.straight_span(g.lo, g.hi)) {
            (Some(a), Some(b)) => cross_sign(a.from, a.to, b.from, b.to) == Some(Ordering::Equal),
            _ => false,
        };
        // Coordinates along the stretch direction.
        let dir = nf.perp();
        let x = |v: &View, u: f64| (v.point(u) - pf).dot(dir);
        let (f0, f1) = (x(vf, f.lo), x(vf, f.hi));
        let (g0, g1) = (x(vg, g.lo), x(vg, g.hi));
        let lo = f0.min(f1).max(g0.min(g1));
        let hi = f0.max(f1).min(g0.max(g1));
        if hi - lo <= OVERLAP_ROUNDING * scale {
            return;
        }
        // (Stretches that do not overlap along their direction face no pair across: their
        // parallelism, proven or not, decides nothing.)
        if !parallel {
            ledger.of(vf).add(Doubt::Continuum);
        }
        // Parameter on a stretch at coordinate c: where the line across it meets it.
        let mut at = |v: &View, piece: &Piece, c: f64| {
            v.point_on_ray(
                piece.lo,
                piece.hi,
                pf + dir * c - nf * scale,
                nf,
                crate::prims::Prefer::Low,
                f64::NAN,
                ledger.of(v),
            )
            .unwrap_or(if (x(v, piece.lo) - c).abs() < (x(v, piece.hi) - c).abs() {
                piece.lo
            } else {
                piece.hi
            })
        };
        let (s0, s1) = (at(vf, f, lo), at(vf, f, hi));
        let (t0, t1) = (at(vg, g, lo), at(vg, g, hi));
        let family = (
            s0.min(s1),
            s0.max(s1),
            if s0 <= s1 { t0 } else { t1 },
            if s0 <= s1 { t1 } else { t0 },
        );
        families.push(family);
        return;
    }
    let Some(t) = vg.point_with_normal(g.lo, g.hi, -nf, ledger.of(vg)) else {
        return;
    };
    let pt = vg.point(t);
    let Some(s) = vf.point_on_ray(
        f.lo,
        f.hi,
        pt,
        vg.normal(t),
        crate::prims::Prefer::Low,
        f64::NAN,
        ledger.of(vf),
    ) else {
        return;
    };
    if nf.dot(pt - vf.point(s)) > 0.0 {
        raw.push((s, t));
    }
}

/// A continuum: θ vanishes all along the pair (a circle, concentric arcs).
pub(crate) fn is_family(p: &Pair, ledger: &mut Ledger) -> bool {
    let doubts = ledger.of(p.vt);
    (0..=4).all(|k| {
        let s = p.sa + (p.sb - p.sa) * k as f64 / 4.0;
        let t = if k == 0 {
            Some(p.ta)
        } else if k == 4 {
            Some(p.tb)
        } else {
            p.opposite(s, doubts)
        };
        t.is_some_and(|t| p.is_noise(s, t, p.sin_theta(s, t)) && p.d(s, t) > 0.0)
    })
}

/// Joins families that continue each other (a circle is cut into pieces by the dissection).
pub(crate) fn merge_families(
    v: &View,
    mut fs: Vec<(f64, f64, f64, f64)>,
) -> Vec<(f64, f64, f64, f64)> {
    let same = |x: f64, y: f64| {
        let d = (x - y).rem_euclid(v.period);
        d.min(v.period - d) <= SAME_END * v.period
    };
    fs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<(f64, f64, f64, f64)> = Vec::new();
    for _ in 0..fs.len() {
        let Some(mut cur) = fs.first().copied() else {
            break;
        };
        fs.remove(0);
        // Extend at the end as long as some family continues it.
        while let Some(k) = fs.iter().position(|g| same(g.0, cur.1) && same(g.2, cur.3)) {
            let g = fs.remove(k);
            let ds = (g.1 - g.0).abs();
            let dt = g.3 - g.2;
            cur = (cur.0, cur.1 + ds, cur.2, cur.3 + dt);
        }
        out.push(cur);
    }
    out
}

/// A family `(sa, sb, ta, tb)` in view parameters, as curve parameters.
pub(crate) fn family_of(v: &View, f: (f64, f64, f64, f64)) -> Family {
    let (s0, s1) = (v.to_curve(f.0), v.to_curve(f.1));
    let (t0, t1) = (v.to_curve(f.2), v.to_curve(f.3));
    if v.rev {
        Family {
            s: [s1, s0],
            t: [t1, t0],
            p: None,
            q: None,
        }
    } else {
        Family {
            s: [s0, s1],
            t: [t0, t1],
            p: None,
            q: None,
        }
    }
}

/// How far from opposite two straight stretches' unit normals may be for them to face each
/// other (a judgement where they are not proven parallel on the data, then uncertified).
const OPPOSITE_NORMALS: f64 = 1e-9;

/// The overlap (relative to the size) of two facing stretches below which it is rounding.
const OVERLAP_ROUNDING: f64 = 1e-12;

/// How close (relative to the period) one family's end and the next one's start are the same
/// point: the dissection's cuts, solved far more finely.
const SAME_END: f64 = 1e-9;
