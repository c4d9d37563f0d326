//! Antipodal pairs with a corner (beyond the papers; the contract's definition). At a convex
//! corner the inward normals form a cone, between the inward normals of the two segments
//! meeting there; reflex corners take no part.
//!
//! - Corner and corner: the segment between them lies inside both cones (pointing inward).
//! - Corner `C` and a smooth point `P(s)`: `P(s)` is a foot point of `C`, a root of
//!   `(P(s) − C) · P′(s)`, isolated by certified root finding on that function's exact
//!   numerator; then `C − P(s)` points along the inward normal at `s`, and `P(s) − C` lies
//!   inside `C`'s cone.
//!
//! A direction within rounding of a cone's edge is the contract's limit case (it may be
//! reported or not): such candidates are left out. Every other decision is clear of rounding.
//!
//! A smooth joint whose two tangents still turn by more than the noise the segments' searches
//! take in (the rounding of a drawing far from the origin: a fillet at 1e8 turns by 1e-8) has
//! a fan of normals the searches of both segments miss: a pair whose normal lies in it has
//! its root just beyond the end of each. Its fan, widened by what the rounding may hide, is
//! searched the same way, and a pair found there is a smooth pair.

use crate::driver::pair_type;
use crate::profiles::at_corner;
use crate::types::{AntipodalPair, Options};
use bspline::roots::{find_roots_in, prove_positive_in, RootKind, RootOptions};
use bspline::Piecewise;
use curve::{Frame, ParamCurve, Profile, SegmentKind, SplineCurve, V2};
use numeric::certificate::{Doubt, Doubts};
use numeric::rounding::gamma;

/// How far inside a cone (the sine of the angle to its nearer edge) a direction must be to be
/// inside it rather than on its edge: far above the rounding of the unit directions compared,
/// far below any drawn angle.
const CONE_EDGE: f64 = 1e-9;

/// How close (relative to the profile's size) a foot point may come to its corner and still be
/// the corner itself: the root at the end of a segment that meets the corner, or a joint's gap
/// (and never less than the rounding of the profile's points, [`Profile::point_rounding`]).
const FOOT_AT_CORNER: f64 = 1e-8;

/// A convex corner, or a smooth joint whose tangents turn by rounding (see the module
/// documentation), in the frame's coordinates.
#[derive(Debug, Clone, Copy)]
pub(crate) struct JointSite {
    /// The profile parameter of the joint.
    pub(crate) u: f64,
    /// The segment that starts there.
    pub(crate) segment: usize,
    /// The point.
    pub(crate) p: V2,
    /// The inward unit normals of the incoming and outgoing segments: the cone's edges.
    pub(crate) cone: [V2; 2],
    /// A corner; else a smooth joint, its cone the fan of normals rounding left it.
    pub(crate) corner: bool,
    /// How far (the sine of the angle) a direction may lie beyond an edge of a smooth joint's
    /// fan and still be in it: the turn the rounding of its tangents may hide (its own,
    /// [`curve::Joint::smooth_turn`]).
    pub(crate) widening: f64,
}

impl JointSite {
    /// Whether `d` points inside the cone: a corner's strictly (clear of its edges by
    /// [`CONE_EDGE`]), a smooth joint's fan widened by its rounding.
    fn holds(&self, d: V2) -> bool {
        let d = d.unit();
        let [a, b] = self.cone;
        // The cone of a convex corner spans less than π: inside means on the inner side of
        // both edges.
        let turn = a.cross(b).signum();
        let room = if self.corner {
            -CONE_EDGE
        } else {
            self.widening
        };
        turn * a.cross(d) > -room && turn * d.cross(b) > -room
    }
}

/// The pairs with a corner, and the doubts met finding them.
pub(crate) struct CornerPairs {
    pub(crate) pairs: Vec<AntipodalPair>,
    pub(crate) doubts: Doubts,
}

/// Every pair with a convex corner at one end or both (see the module documentation), with
/// `curves` the profile's segments in `frame`.
pub(crate) fn corner_pairs(
    profile: &Profile,
    frame: &Frame,
    sites: &[JointSite],
    curves: &[&SplineCurve],
    opts: &Options,
) -> CornerPairs {
    let mut out = CornerPairs {
        pairs: Vec::new(),
        doubts: Doubts::none(),
    };
    let global = |p: V2| frame.to_global(p.arr());
    // A pair's type where both ends are smooth points of curved segments (`None` otherwise):
    // the curvatures signed the way the profile runs round its region.
    let curvature = |i: usize, x: f64| {
        let curved = profile.segments()[i].kind() != SegmentKind::Line;
        curved.then(|| curves[i].jet_to(x, 2).curvature() * profile.orientation())
    };
    // (At a smooth joint, the curvature of the segment starting there; none where either
    // segment there is straight, as a pair found from the straight side would have none.)
    let n = curves.len();
    let site_curvature = |site: &JointSite| {
        let c = curves[site.segment];
        let before = (site.segment + n - 1) % n;
        let straight_before = profile.segments()[before].kind() == SegmentKind::Line;
        (!site.corner && !straight_before)
            .then(|| curvature(site.segment, c.domain().0))
            .flatten()
    };
    let kind = |ks: Option<f64>, kt: Option<f64>, r: f64| Some(pair_type(ks?, kt?, r));
    for (k, a) in sites.iter().enumerate() {
        for b in &sites[k + 1..] {
            let d = b.p - a.p;
            if a.holds(d) && b.holds(-d) {
                let (p, q) = (global(a.p), global(b.p));
                out.pairs.push(
                    AntipodalPair {
                        s: a.u,
                        t: b.u,
                        p,
                        q,
                        distance: (V2::from_arr(q) - V2::from_arr(p)).norm(),
                        kind: kind(site_curvature(a), site_curvature(b), d.norm()),
                        corner: Some([a.corner, b.corner]),
                        segment: Some([a.segment, b.segment]),
                    }
                    .ordered(),
                );
            }
        }
    }
    let at_corner_room = frame.length_to_local(profile.same_point_room(FOOT_AT_CORNER));
    for site in sites {
        for (i, c) in curves.iter().enumerate() {
            match foot_points(c, site.p, opts) {
                Ok(feet) => {
                    for foot in feet {
                        let s = foot.u;
                        if at_corner(profile, i, s) {
                            // (A corner at the other end too: decided as a pair of corners.)
                            continue;
                        }
                        let j = c.jet_to(s, 1);
                        let d = j.p - site.p;
                        if d.norm() <= at_corner_room {
                            continue;
                        }
                        if !foot.separated {
                            out.doubts.add(if site.corner {
                                Doubt::FootFromCorner {
                                    u: site.u,
                                    segment: i,
                                }
                            } else {
                                Doubt::FootFromJoint {
                                    u: site.u,
                                    segment: i,
                                }
                            });
                            continue;
                        }
                        // Inward at the smooth point: the corner lies on the side of its
                        // inward normal (left on a counterclockwise profile).
                        let inward = j.d1.perp() * profile.orientation();
                        if inward.dot(-d) <= 0.0 || !site.holds(d) {
                            continue;
                        }
                        let (p, q) = (global(site.p), global(j.p));
                        out.pairs.push(
                            AntipodalPair {
                                s: site.u,
                                t: profile.profile_param(i, s),
                                p,
                                q,
                                distance: (V2::from_arr(q) - V2::from_arr(p)).norm(),
                                kind: kind(site_curvature(site), curvature(i, s), d.norm()),
                                corner: Some([site.corner, false]),
                                segment: Some([site.segment, i]),
                            }
                            .ordered(),
                        );
                    }
                }
                Err(e) => {
                    out.doubts.add(Doubt::CornerFeetNotFound {
                        segment: i,
                        why: e.to_string(),
                    });
                }
            }
        }
    }
    out
}

/// A point of the curve whose normal line passes through the corner `q`: the foot of a
/// perpendicular from `q` (a root of the foot-point function), not necessarily the nearest.
struct Perpendicular {
    /// Its parameter (a cluster's middle).
    u: f64,
    /// One simple root, proven (or certification is off), not a cluster of roots.
    separated: bool,
}

/// The roots of `(C(u) − q) · C′(u)` on the curve's domain (the points whose normal line
/// passes through `q`). With `R = X − q w` the homogeneous difference, the numerator is
/// `w (R · R′) − w′ |R|²` (`R · R′` for a polynomial curve); its coefficients carry their
/// rounding bounds into the root isolation.
fn foot_points(c: &SplineCurve, q: V2, opts: &Options) -> bspline::Result<Vec<Perpendicular>> {
    if let Some(feet) = straight_foot(c, q) {
        return Ok(feet);
    }
    let pieces = c.exact_pieces();
    let hom = &pieces.hom;
    let rx = hom.weighted(&[1.0, 0.0, -q.x]);
    let ry = hom.weighted(&[0.0, 1.0, -q.y]);
    let r = Piecewise::stack(&[&rx, &ry])?;
    let dr = r.derivative();
    let f = if pieces.polynomial {
        r.dot(&dr)?
    } else {
        let w = hom.components(&[2])?;
        let dw = w.derivative();
        w.mul(&r.dot(&dr)?)?.sub(&dw.mul(&r.dot(&r)?)?)?
    };
    let (a, b) = f.domain();
    // (The numerator is `w³ (C − q) · C′`: its sign is continuous across a knot where the
    // homogeneous form is only C0, as a rational arc's middle is, on a segment without
    // corners inside.)
    let ropts = RootOptions::default()
        .tolerance(opts.settings.tol.get())
        .sign_continuous(true);
    let roots = find_roots_in(&f, a, b, &ropts)?;
    let df = f.derivative();
    let mut feet = Vec::with_capacity(roots.len());
    for r in roots {
        let proven = r.kind == RootKind::Simple && r.certified;
        let (lo, hi) = r.bracket;
        // A root at an end of the domain (a foot point at a joint, found from the segments
        // on both sides) shows no sign change there: it is one root, at the end to within
        // the bracket, where the function is proven monotone across the bracket.
        let at_end = (lo <= a || hi >= b) && hi > lo;
        let monotone = || {
            let pos = prove_positive_in(&df, lo, hi, &ropts);
            let neg = prove_positive_in(&df.scale(-1.0), lo, hi, &ropts);
            matches!(pos, Ok(None)) || matches!(neg, Ok(None))
        };
        if !proven && at_end && monotone() {
            feet.push(Perpendicular {
                u: if lo <= a { a } else { b },
                separated: true,
            });
            continue;
        }
        feet.push(Perpendicular {
            u: r.u,
            separated: (r.kind == RootKind::Simple && r.certified) || !opts.certify,
        });
    }
    Ok(feet)
}

/// [`foot_points`] on a straight segment (a polynomial of degree one on one span), in closed
/// form: the foot-point function `(C(u) − q) · C′` is affine with slope `|C′|² > 0`, so its
/// one root is simple, and lies at an end where the end's value is within its rounding of
/// zero. `None` for any other curve, and for a segment too short to tell its ends apart.
fn straight_foot(c: &SplineCurve, q: V2) -> Option<Vec<Perpendicular>> {
    let curve = c.curve();
    let [p0, p1] = curve.straight_ends()?;
    let (a, b) = curve.domain();
    let (p0, p1) = ([p0[0], p0[1]], [p1[0], p1[1]]);
    let d = [p1[0] - p0[0], p1[1] - p0[1]];
    // (The values at the ends, each with a bound on its rounding from its terms' sizes: the
    // differences to q and d = p1 − p0, whose rounding is of the points' size.)
    let d_size = [
        d[0].abs() + p0[0].abs() + p1[0].abs(),
        d[1].abs() + p0[1].abs() + p1[1].abs(),
    ];
    let at = |p: [f64; 2]| {
        let value = (p[0] - q.x) * d[0] + (p[1] - q.y) * d[1];
        let size = (p[0].abs() + q.x.abs()) * d_size[0] + (p[1].abs() + q.y.abs()) * d_size[1];
        (value, gamma(6) * size)
    };
    let ((f0, e0), (f1, e1)) = (at(p0), at(p1));
    let (at_start, at_end) = (f0.abs() <= e0, f1.abs() <= e1);
    let u = match (at_start, at_end) {
        (true, true) => return None,
        (true, false) => a,
        (false, true) => b,
        (false, false) if (f0 > 0.0) != (f1 > 0.0) => (a + (b - a) * (f0 / (f0 - f1))).clamp(a, b),
        (false, false) => return Some(Vec::new()),
    };
    Some(vec![Perpendicular { u, separated: true }])
}
