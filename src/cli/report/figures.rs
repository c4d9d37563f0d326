//! The figures of the antipodal and bisector commands: the curves with what was found on
//! them and, for a bisector, its zero set in the parameter square.

use super::{draw_curve, n};
use antipodal::{Antipodal, Corner, Family, Inflection};
use curvekit::curve::ParamCurve;
use curvekit::curve::Profile;
use curvekit::io::Curve;
use curvekit::svg::{side_by_side, Figure, Mark, DOT};
use numeric::certificate::Verdict;
use zeroset::Bisector;

/// The colour of a family of antipodal pairs (its two end pairs), set apart from the isolated
/// pairs' dashed grey.
const FAMILY: &str = "#2a8c4a";

/// The legend of an antipodal figure: what each mark is, for those drawn.
fn antipodal_legend(
    fig: &mut Figure,
    pairs: usize,
    families: usize,
    inflections: usize,
    corners: usize,
) {
    if pairs > 0 {
        fig.legend(Mark::Dashed, format!("antipodal pair, numbered: {pairs}"));
    }
    if families > 0 {
        fig.legend(
            Mark::Line(FAMILY.into(), 1.4),
            format!("family of pairs (its two end pairs): {families}"),
        );
    }
    if inflections > 0 {
        fig.legend(Mark::Dot(DOT.into()), format!("inflection: {inflections}"));
    }
    if corners > 0 {
        fig.legend(Mark::Square, format!("corner: {corners}"));
    }
}

/// The antipodal figure: the curve, its inflections (and a profile's corners), each pair as a
/// numbered segment (Jia's Figures 1 and 24) and each family by its two end pairs; the header
/// says whether the answer is certified.
pub(crate) fn antipodal_figure(curve: &Curve, found: &Antipodal, title: String) -> String {
    // (A profile's family has its end points; a curve's are found from its parameters.)
    let end_pairs = |f: &Family| match (f.p, f.q) {
        (Some(p), Some(q)) => [[p[0], q[0]], [p[1], q[1]]],
        _ => [0, 1].map(|k| [curve.point_at(f.s[k]), curve.point_at(f.t[k])]),
    };
    let marks = AntipodalMarks {
        pairs: found.pairs.iter().map(|p| [p.p, p.q]).collect(),
        families: found.families.iter().map(end_pairs).collect(),
        inflections: &found.inflections,
        corners: found.corner_list(),
    };
    antipodal_drawing(curve, marks, found, title)
}

/// What an antipodal figure marks, on a curve or on a profile.
struct AntipodalMarks<'a> {
    /// Each pair's two points.
    pairs: Vec<[[f64; 2]; 2]>,
    /// Each family's two end pairs, each by its two points.
    families: Vec<[[[f64; 2]; 2]; 2]>,
    inflections: &'a [Inflection],
    corners: &'a [Corner],
}

/// The antipodal figure of `marks` on `curve`, its header saying whether `found` is certified.
fn antipodal_drawing(
    curve: &Curve,
    marks: AntipodalMarks<'_>,
    found: &impl Verdict,
    title: String,
) -> String {
    let mut fig = Figure::new();
    draw_curve(&mut fig, curve);
    for (k, [p, q]) in marks.pairs.iter().enumerate() {
        fig.segment(*p, *q, Some((k + 1).to_string()));
    }
    for [p, q] in marks.families.iter().flatten() {
        fig.colored(vec![*p, *q], FAMILY.into());
    }
    marks.inflections.iter().for_each(|i| fig.dot(i.p));
    marks.corners.iter().for_each(|c| fig.corner(c.p));
    antipodal_legend(
        &mut fig,
        marks.pairs.len(),
        marks.families.len(),
        marks.inflections.len(),
        marks.corners.len(),
    );
    fig.title(title);
    fig.status(found.certified(), found.reason().as_deref());
    fig.render()
}

/// The bisector figure, as in Elber and Kim's: the curves, the bisector branches and thin
/// lines from a few bisector points to their foot points, framed around the curves (branches
/// run off to infinity where the normals turn parallel); beside it, the zero set in the
/// `(t, r)` parameter square. `curves` holds one curve for a self-bisector.
pub(crate) fn bisector_figure(curves: &[&Curve], r: &Bisector, title: String) -> String {
    let (c1, c2) = match curves {
        [c1] => (*c1, *c1),
        [c1, c2, ..] => (*c1, *c2),
        [] => return Figure::new().render(),
    };
    // (The parameters reported are the documents'.)
    let foot = |k: usize, u: f64| {
        if k == 0 {
            c1.point_at(u)
        } else {
            c2.point_at(u)
        }
    };
    let domains = [c1.domain(), c2.domain()];
    plane_and_parameters(curves, r, &foot, domains, &[], title)
}

/// The bisector figure of profiles: as for curves, the corners marked, the foot points and
/// the parameter square the profiles'.
pub(crate) fn profile_bisector_figure(
    curves: &[&Curve],
    profiles: &[Profile],
    r: &Bisector,
    title: String,
) -> String {
    let (Some(a), Some(b)) = (profiles.first(), profiles.last()) else {
        return Figure::new().render();
    };
    // (The branches alone: the special points are the profiles' sites' own.)
    let plain = Bisector {
        branches: r.branches.clone(),
        singular: Vec::new(),
        isolated: Vec::new(),
        complete: r.complete,
    };
    // (The parameters reported are the documents'.)
    let on = |p: &Profile, u: f64| p.jet(p.internal_param(u)).p.arr();
    let foot = |k: usize, u: f64| if k == 0 { on(a, u) } else { on(b, u) };
    let corners: Vec<[f64; 2]> = profiles
        .iter()
        .flat_map(|p| p.corners().map(|j| p.jet(j.u).p.arr()))
        .collect();
    plane_and_parameters(
        curves,
        &plain,
        &foot,
        [a.document_domain(), b.document_domain()],
        &corners,
        title,
    )
}

/// The curves, the bisector branches and thin lines from a few bisector points to their foot
/// points (`foot(k, u)` on curve `k`), corners marked, framed around the curves; beside it
/// the zero set in the parameter square of `domains`.
fn plane_and_parameters(
    curves: &[&Curve],
    r: &Bisector,
    foot: &dyn Fn(usize, f64) -> [f64; 2],
    domains: [(f64, f64); 2],
    corners: &[[f64; 2]],
    title: String,
) -> String {
    let mut plane = Figure::new();
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for c in curves {
        draw_curve(&mut plane, c);
        for p in c.polyline(256) {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    if lo[0] <= hi[0] {
        let pad = 0.5 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
        plane.frame([lo[0] - pad, lo[1] - pad], [hi[0] + pad, hi[1] + pad]);
    }
    // (A few foot-point lines, spread over the branches, from points inside the frame: more
    // would hide the bisector.)
    let inside = |p: &[f64; 2]| {
        let pad = 0.5 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
        (lo[0] - pad..=hi[0] + pad).contains(&p[0]) && (lo[1] - pad..=hi[1] + pad).contains(&p[1])
    };
    let framed: usize = r
        .branches
        .iter()
        .map(|b| b.xy.iter().filter(|p| inside(p)).count())
        .sum();
    let every = (framed / FOOT_LINES).max(1);
    let mut seen = 0;
    for b in &r.branches {
        plane.thin(b.xy.clone(), "#d62020");
        for (tr, xy) in b.tr.iter().zip(&b.xy).filter(|(_, p)| inside(p)) {
            if seen % every == every / 2 {
                plane.thin(vec![foot(0, tr[0]), *xy, foot(1, tr[1])], "#999999");
            }
            seen += 1;
        }
    }
    corners.iter().for_each(|&c| plane.corner(c));
    if !r.branches.is_empty() {
        plane.legend(Mark::Line("#d62020".into(), 0.6), "bisector");
        plane.legend(
            Mark::Line("#999999".into(), 0.6),
            "a bisector point to its two foot points",
        );
    }
    if !corners.is_empty() {
        plane.legend(Mark::Square, "corner");
    }
    plane.title(title);

    // The parameter square, scaled to a unit square so that both domains read alike.
    let [(t0, t1), (r0, r1)] = domains;
    let unit = |tr: &[f64; 2]| [(tr[0] - t0) / (t1 - t0), (tr[1] - r0) / (r1 - r0)];
    let mut params = Figure::new();
    params.thin(
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]],
        "#444444",
    );
    for b in &r.branches {
        params.thin(b.tr.iter().map(unit).collect(), "#d62020");
    }
    params.text([0.45, -0.08], format!("t ∈ [{}, {}]", n(t0), n(t1)));
    params.text([-0.05, 1.03], format!("r ∈ [{}, {}]", n(r0), n(r1)));
    params.frame([-0.08, -0.1], [1.02, 1.06]);
    params.title("zero set in (t, r)");
    side_by_side(&[&plane, &params])
}

/// Foot-point lines drawn in a bisector figure, over all its branches.
const FOOT_LINES: usize = 12;
