//! Antipodal pairs of a closed profile (Jia 2004 §9.2: the method extends to piecewise `C²`
//! curves). Each segment is dissected on its own into monotone pieces, all in one frame and
//! oriented the way the profile runs counterclockwise; every pair of pieces, of one segment or
//! of two, is then searched exactly as the pieces of one smooth curve are (§5). The pairs with
//! a corner at one end or both come from [`crate::corner_pairs`].

use crate::corner_pairs::{corner_pairs, JointSite};
use crate::dissect::Piece;
use crate::driver::{classify, dissect, sections, trim_antipodal_ends, Dissected};
use crate::error::{Error, Result};
use crate::families::{flat_pairs, is_family};
use crate::forms::SymbolicForms;
use crate::ledger::Ledger;
use crate::pairs::{opposite_pair, polish, touching_ends, THETA_NOISE};
use crate::profiles::{profile_inflections_run, FAN_NOISE};
use crate::search::{antipodal_points, Budget};
use crate::types::{Antipodal, AntipodalPair, Family, Options, Provenance};
use crate::view::{Source, View};
use curve::{Frame, JointKind, ParamCurve, Profile, SegmentKind, SplineCurve, StraightSpan, V2};
use numeric::certificate::{Certified, Doubt, Doubts};

/// Samples per segment of a sampled track (certification off): a segment of a drawing turns
/// little; Jia's sampling resolves a few oscillations with this many.
const SEGMENT_SAMPLES: usize = 96;

/// How far (relative to a segment's domain) the final polish of a pair may move it.
const FINAL_POLISH_REACH: f64 = 1e-4;

/// Two pairs whose points are closer than this (relative to the profile's size; and never
/// less than the rounding of its points, [`Profile::point_rounding`]) are one: a pair at a
/// smooth joint is found from the segments on both sides.
const SAME_PAIR: f64 = 1e-7;

/// Room (in profile parameters, a segment's domain being 1) for a pair on a family's end to
/// count as one of its pairs.
const FAMILY_SLACK: f64 = 1e-9;

/// How far (in profile parameters) from the family's match a pair's other end may lie and
/// still be one of its pairs: a pair at a family's end meets the match to the tolerance it
/// was solved to; any other pair is a whole stretch away.
const FAMILY_MATCH: f64 = 1e-6;

/// A family between segments `i` and `j`, in their views' parameters `(sa, sb, ta, tb)`.
type SegmentFamily = (usize, usize, (f64, f64, f64, f64));

/// A segment in the frame, with what its views borrow.
struct Local {
    curve: SplineCurve,
    forms: Option<SymbolicForms>,
    straight: Vec<StraightSpan>,
}

/// One pair of segment points in view parameters: segment `i` at `s`, segment `j` at `t`.
#[derive(Debug, Clone, Copy)]
struct Raw {
    i: usize,
    s: f64,
    j: usize,
    t: f64,
}

/// Every antipodal pair of a closed profile, with a corner at one end or both where the
/// segment between them lies inside the corner's cone of inward normals (see the contract),
/// and the continua of pairs (facing parallel lines, concentric arcs) as families. Certified
/// where every segment's decisions are (lines and arcs are exact rational curves).
pub(crate) fn profile_antipodal(profile: &Profile, opts: &Options) -> Result<Antipodal> {
    opts.validate()?;
    if !profile.is_closed() {
        let (a, b) = profile.domain();
        return Err(Error::NotClosed {
            gap: (profile.jet(b).p - profile.jet(a).p).norm(),
        });
    }
    if let Some(whole) = crate::whole_curve::whole_curve(profile) {
        return crate::whole_curve::antipodal(&whole, opts);
    }
    let segs = profile.segments();
    let points: Vec<[f64; 2]> = segs
        .iter()
        .flat_map(|s| s.curve().control_points())
        .collect();
    let frame = Frame::for_points(&points);
    let locals: Vec<Local> = segs
        .iter()
        .map(|s| {
            let curve = s.curve().in_frame(&frame);
            let forms = opts
                .certify
                .then(|| SymbolicForms::new(curve.exact_pieces()).ok())
                .flatten();
            let straight = curve.straight_spans();
            Local {
                curve,
                forms,
                straight,
            }
        })
        .collect();
    // Every segment runs the way a counterclockwise profile does.
    let rev = profile.orientation() < 0.0;
    let mut parts: Vec<Dissected> = Vec::with_capacity(locals.len());
    // Each segment's view keeps its doubts in the book of its number.
    let mut ledger = Ledger::new();
    let opens: Vec<Open> = locals.iter().map(|l| Open(&l.curve)).collect();
    for (i, (l, open)) in locals.iter().zip(&opens).enumerate() {
        let src = Source {
            curve: open,
            forms: l.forms.as_ref(),
            simple: false,
            report: None,
            samples: SEGMENT_SAMPLES,
            straight: &l.straight,
            exact_circle: false,
        };
        let d = dissect(src, opts, Some(rev), i).map_err(|e| Error::InSegment {
            segment: i,
            source: Box::new(e),
        })?;
        *ledger.book(i) = d.doubts;
        parts.push(d.value);
    }
    let mut raw: Vec<Raw> = Vec::new();
    let mut families: Vec<SegmentFamily> = Vec::new();
    let mut budget = Budget {
        sections: opts.max_sections,
        exhausted: false,
    };
    let mut stack = Vec::with_capacity(16);
    let mut found = Vec::new();
    let mut flats = Vec::new();
    for (i, di) in parts.iter().enumerate() {
        for (j, dj) in parts.iter().enumerate().skip(i) {
            for p in &di.pieces {
                for q in &dj.pieces {
                    if i == j && q.id <= p.id {
                        continue;
                    }
                    let (vi, vj) = (&di.view, &dj.view);
                    found.clear();
                    if p.flat || q.flat {
                        flats.clear();
                        flat_pairs(vi, p, vj, q, &mut found, &mut flats, &mut ledger);
                        // (The straight piece's side first.)
                        let (a, b) = if p.flat { (i, j) } else { (j, i) };
                        raw.extend(found.iter().map(|&(s, t)| Raw { i: a, s, j: b, t }));
                        families.extend(flats.iter().map(|&f| (a, b, f)));
                        continue;
                    }
                    let centre = |k: usize| segs[k].circle().map(|(c, _)| c);
                    let concentric = centre(i).is_some() && centre(i) == centre(j);
                    // (A pair of piece ends at a corner is the corners' own search's.)
                    let smooth = |k: usize, v: &View, x: f64| {
                        joint_at(profile, k, v, x).is_none_or(|kind| kind == JointKind::Smooth)
                    };
                    let off_corners = |[s, t]: [f64; 2]| smooth(i, vi, s) && smooth(j, vj, t);
                    search_pieces(
                        [(vi, p), (vj, q)],
                        &off_corners,
                        concentric,
                        &mut found,
                        &mut budget,
                        &mut stack,
                        |f| families.push((i, j, f)),
                        &mut ledger,
                    );
                    raw.extend(found.iter().map(|&(s, t)| Raw { i, s, j, t }));
                }
            }
        }
    }
    let views: Vec<&View> = parts.iter().map(|d| &d.view).collect();
    let sites = joint_sites(profile, &locals);
    let mut pairs = finish(profile, &views, &frame, raw, &mut ledger);
    let curves: Vec<&SplineCurve> = locals.iter().map(|l| &l.curve).collect();
    let corner = corner_pairs(profile, &frame, &sites, &curves, opts);
    for c in corner.pairs {
        if !pairs.iter().any(|p| same_pair(profile, p, &c)) {
            pairs.push(c);
        }
    }
    pairs.sort_by(|a, b| a.s.total_cmp(&b.s));
    let families = merged(
        profile,
        families
            .into_iter()
            .map(|(i, j, f)| family(profile, &views, &frame, i, j, f))
            .collect(),
    );
    // A pair on a family (at its end, say) is one of its pairs.
    let period = profile.segments().len() as f64;
    pairs.retain(|p| !families.iter().any(|f| on_family(f, p, period)));
    let (inflections, inflection_doubts) = profile_inflections_run(profile, opts)?.into_parts();
    let out = Antipodal {
        pairs,
        inflections: inflections.inflections,
        corners: inflections.corners,
        families,
        doubts: Doubts::none(),
        complete: !budget.exhausted,
    };
    // The segments' doubts in their order, then the corners', then the inflections'.
    let mut doubts = Doubts::none();
    for v in &views {
        doubts.join(ledger.take(v.book));
    }
    doubts.join(corner.doubts);
    doubts.join(inflection_doubts);
    Ok(Provenance::finished(Certified { value: out, doubts }))
}

/// The search of one pair of curved pieces (as for one smooth curve): continua go to
/// `family` (proven where the pieces lie on arcs `concentric` by definition), isolated
/// pairs to `out`; a pair of the pieces' ends whose normals alone are opposite only where
/// `off_corners` says both ends are off the profile's corners.
#[allow(clippy::too_many_arguments)]
fn search_pieces<'a>(
    [(vi, p), (vj, q)]: [(&'a View<'a>, &Piece); 2],
    off_corners: &dyn Fn([f64; 2]) -> bool,
    concentric: bool,
    out: &mut Vec<(f64, f64)>,
    budget: &mut Budget,
    stack: &mut Vec<crate::pairs::Pair<'a>>,
    mut family: impl FnMut((f64, f64, f64, f64)),
    ledger: &mut Ledger,
) {
    let Some(pair) = opposite_pair(vi, p, vj, q, ledger) else {
        // (Normals opposite only at an end of each: that pair of ends, if antipodal.)
        out.extend(
            touching_ends(vi, p, vj, q)
                .and_then(|at| at.antipodal_start())
                .filter(|&(s, t)| off_corners([s, t])),
        );
        return;
    };
    if is_family(&pair, ledger) {
        // (θ vanishing within rounding all along: a continuum is proven only for arcs defined
        // on one centre.)
        if !concentric {
            ledger.of(vi).add(Doubt::Continuum);
        }
        family((pair.sa, pair.sb, pair.ta, pair.tb));
        return;
    }
    for sec in sections(&pair, ledger) {
        if let Some(sec) = trim_antipodal_ends(&sec, out, ledger) {
            antipodal_points(&sec, out, budget, stack, ledger);
        }
    }
}

/// The convex corners with their cones of inward normals, and the smooth joints whose
/// tangents turn beyond [`FAN_NOISE`] with their fans, in the frame.
fn joint_sites(profile: &Profile, locals: &[Local]) -> Vec<JointSite> {
    let n = profile.segments().len();
    let inward = |t: V2| t.perp() * profile.orientation();
    profile
        .joints()
        .iter()
        .filter(|j| {
            j.kind == JointKind::Convex || (j.kind == JointKind::Smooth && j.turn.abs() > FAN_NOISE)
        })
        .filter_map(|j| {
            let i = j.u as usize;
            let before = &profile.segments()[(i + n - 1) % n];
            let after = &profile.segments()[i];
            let (din, dout) = (before.end_direction()?, after.start_direction()?);
            let c = &locals[i].curve;
            Some(JointSite {
                u: j.u,
                segment: i,
                p: c.jet(c.domain().0).p,
                cone: [inward(din), inward(dout)],
                corner: j.kind == JointKind::Convex,
                widening: j.smooth_turn,
            })
        })
        .collect()
}

/// Polishes, validates (inward normals facing each other), deduplicates, classifies and maps
/// the pairs to profile parameters and global points.
fn finish(
    profile: &Profile,
    views: &[&View],
    frame: &Frame,
    raw: Vec<Raw>,
    ledger: &mut Ledger,
) -> Vec<AntipodalPair> {
    let mut out: Vec<AntipodalPair> = Vec::with_capacity(raw.len());
    for r in raw {
        let (vs, vt) = (views[r.i], views[r.j]);
        let clamp = |v: &View, u: f64| u.clamp(v.a, v.b);
        let reach = FINAL_POLISH_REACH * vs.period.max(vt.period);
        let (s, t) = polish(vs, vt, r.s, r.t, reach)
            .map(|(s, t)| (clamp(vs, s), clamp(vt, t)))
            .unwrap_or((r.s, r.t));
        let (js, jt) = (vs.jet_to(s, 1), vt.jet_to(t, 1));
        let d = jt.p - js.p;
        if js.normal().dot(d) <= 0.0 || js.d1.dot(jt.d1) >= 0.0 {
            continue;
        }
        if js.normal().cross(d).abs() > THETA_NOISE * d.norm() {
            ledger.of(vs).add(Doubt::NotAPair);
            continue;
        }
        // A reflex corner takes no part: a pair found there by one segment's normal is the
        // limit of smooth pairs beside it (the contract's limit case), left out.
        let reflex =
            |k: usize, v: &View, x: f64| joint_at(profile, k, v, x) == Some(JointKind::Reflex);
        if reflex(r.i, vs, s) || reflex(r.j, vt, t) {
            continue;
        }
        let pair = profile_pair(profile, views, frame, (r.i, s), (r.j, t));
        if !out.iter().any(|p| same_pair(profile, p, &pair)) {
            out.push(pair);
        }
    }
    out
}

/// The pair of segment `i` at view parameter `s` and segment `j` at `t`, in profile terms.
fn profile_pair(
    profile: &Profile,
    views: &[&View],
    frame: &Frame,
    (i, s): (usize, f64),
    (j, t): (usize, f64),
) -> AntipodalPair {
    let (vs, vt) = (views[i], views[j]);
    let at_corner = |k: usize, v: &View, x: f64| {
        joint_at(profile, k, v, x).is_some_and(|kind| kind != JointKind::Smooth)
    };
    let corner = [at_corner(i, vs, s), at_corner(j, vt, t)];
    let straight = |k: usize| profile.segments()[k].kind() == SegmentKind::Line;
    let kind =
        (!corner[0] && !corner[1] && !straight(i) && !straight(j)).then(|| classify(vs, vt, s, t));
    let (p, q) = (
        frame.to_global(vs.point(s).arr()),
        frame.to_global(vt.point(t).arr()),
    );
    let us = profile.profile_param(i, vs.to_curve(s));
    let ut = profile.profile_param(j, vt.to_curve(t));
    AntipodalPair {
        s: us,
        t: ut,
        p,
        q,
        distance: (V2::from_arr(q) - V2::from_arr(p)).norm(),
        kind,
        corner: Some(corner),
        segment: Some([i, j]),
    }
    .ordered()
}

/// The kind of the joint where segment `k`'s view `v` is at `x`, if `x` is at one of its ends.
fn joint_at(profile: &Profile, k: usize, v: &View, x: f64) -> Option<JointKind> {
    let share = (v.to_curve(x) - v.reported_domain().0) / v.period;
    crate::profiles::joint_at(profile, k, share)
}

/// The same pair found twice (from two segments meeting at a smooth joint, or as a corner
/// pair and a smooth one on the cone's edge).
fn same_pair(profile: &Profile, a: &AntipodalPair, b: &AntipodalPair) -> bool {
    let room = profile.same_point_room(SAME_PAIR);
    let near = |x: [f64; 2], y: [f64; 2]| (V2::from_arr(x) - V2::from_arr(y)).norm() <= room;
    (near(a.p, b.p) && near(a.q, b.q)) || (near(a.p, b.q) && near(a.q, b.p))
}

/// A family in view parameters as profile parameters and end points.
fn family(
    profile: &Profile,
    views: &[&View],
    frame: &Frame,
    i: usize,
    j: usize,
    f: (f64, f64, f64, f64),
) -> Family {
    let (vs, vt) = (views[i], views[j]);
    let su = |x: f64| profile.profile_param(i, vs.to_curve(x));
    let tu = |x: f64| profile.profile_param(j, vt.to_curve(x));
    let ps = |x: f64| frame.to_global(vs.point(x).arr());
    let pt = |x: f64| frame.to_global(vt.point(x).arr());
    Family {
        s: [su(f.0), su(f.1)],
        t: [tu(f.2), tu(f.3)],
        p: Some([ps(f.0), ps(f.1)]),
        q: Some([pt(f.2), pt(f.3)]),
    }
}

/// Whether the pair is one of the family's: `s` inside one side's range and `t` where the
/// family matches it (interpolated: exact on straight sides, and at a family's ends, where
/// the pairs it absorbs lie). Parameters are read modulo `period` (a pair at the closing
/// joint may say the profile's end where the family says its start).
fn on_family(f: &Family, p: &AntipodalPair, period: f64) -> bool {
    let apart = |x: f64| {
        let d = x.rem_euclid(period);
        d.min(period - d)
    };
    let matches = |s: f64, t: f64, fs: [f64; 2], ft: [f64; 2]| {
        let (lo, hi) = (fs[0].min(fs[1]), fs[0].max(fs[1]));
        if hi <= lo {
            return false;
        }
        [s, s - period, s + period].into_iter().any(|s| {
            let x = (s - fs[0]) / (fs[1] - fs[0]);
            s >= lo - FAMILY_SLACK
                && s <= hi + FAMILY_SLACK
                && apart(ft[0] + x * (ft[1] - ft[0]) - t) <= FAMILY_MATCH
        })
    };
    matches(p.s, p.t, f.s, f.t) || matches(p.t, p.s, f.s, f.t)
}

/// Families that continue each other (the pieces of one arc, a circle's halves) joined into
/// one: where one ends, at both sides, the other starts.
fn merged(profile: &Profile, mut fs: Vec<Family>) -> Vec<Family> {
    let room = profile.same_point_room(SAME_PAIR);
    let near = |x: [f64; 2], y: [f64; 2]| (V2::from_arr(x) - V2::from_arr(y)).norm() <= room;
    // (A profile's family has its end points.)
    let ends = |f: &Family| (f.p.unwrap_or_default(), f.q.unwrap_or_default());
    // (Each join removes one family: at most as many rounds as families.)
    for _ in 0..fs.len() {
        let found = (0..fs.len()).find_map(|a| {
            (0..fs.len())
                .find(|&b| {
                    let ((pa, qa), (pb, qb)) = (ends(&fs[a]), ends(&fs[b]));
                    b != a && near(pa[1], pb[0]) && near(qa[1], qb[0])
                })
                .map(|b| (a, b))
        });
        let Some((a, b)) = found else {
            break;
        };
        let next = fs[b];
        let ((mut p, mut q), (next_p, next_q)) = (ends(&fs[a]), ends(&next));
        p[1] = next_p[1];
        q[1] = next_q[1];
        let f = &mut fs[a];
        f.s[1] = next.s[1];
        f.t[1] = next.t[1];
        f.p = Some(p);
        f.q = Some(q);
        fs.remove(b);
    }
    fs
}

/// A profile's segment seen as the open curve it is: where its ends meet (a closed profile of
/// one segment) the profile's seam joint, not the segment, says how they meet (a corner
/// there is the profile's).
struct Open<'a>(&'a dyn ParamCurve);

impl ParamCurve for Open<'_> {
    fn domain(&self) -> (f64, f64) {
        self.0.domain()
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn jet_to(&self, u: f64, order: usize) -> curve::Jet {
        self.0.jet_to(u, order)
    }
    fn jet(&self, u: f64) -> curve::Jet {
        self.0.jet(u)
    }
}
