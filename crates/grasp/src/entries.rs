//! The crate's command: every force-closure grasp of a closed curve or profile.

use crate::assemble::{regions, RawRegion};
use crate::best::{bounds, most_robust};
use crate::cones::{functions, Form};
use crate::contact::{around, Positivity};
use crate::error::{Error, Result};
use crate::near::NearContacts;
use crate::options::GraspOptions;
use crate::quality::{min_friction, point_tangent};
use crate::types::{BestGrasp, ContactRegion, GraspRegion, Grasps};
use curve::{Boundary, Frame, ParamCurve, Profile};
use numeric::certificate::{Doubt, Doubts};
use numeric::tolerance::Size;
use zeroset::{nonnegative_set, NonNegativeOptions, ZeroSetOptions};

/// Every two-finger force-closure grasp of a closed curve for Coulomb friction μ (Nguyen's
/// condition: the chord between the contacts lies inside both friction cones), as regions of
/// the square of contact parameters, each with its independent contact region and its most
/// robust grasp. Every antipodal pair and family lies inside a region.
///
/// ```
/// use grasp::{grasps, GraspOptions};
/// use curve::shapes::Ellipse;
/// // An ellipse has two antipodal pairs (its axes): two regions, each holding one.
/// let e = Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap();
/// let g = grasps(&e, &GraspOptions::friction(0.3)).unwrap();
/// assert!(g.complete);
/// assert_eq!(g.regions.len(), 2);
/// assert!(g.regions.iter().all(|r| r.best.min_friction < 1e-9));
/// ```
pub fn grasps<'a>(boundary: impl Into<Boundary<'a>>, opts: &GraspOptions) -> Result<Grasps> {
    opts.check()?;
    let boundary = boundary.into();
    let profile = boundary.to_profile()?.ok_or(Error::NotExact)?;
    let profile: &Profile = &profile;
    if !profile.is_closed() {
        return Err(Error::NotClosed);
    }
    let corners = profile.corners().count();
    let [segment] = profile.segments() else {
        return Err(Error::Segments {
            segments: profile.segments().len(),
            corners,
        });
    };
    if corners > 0 {
        return Err(Error::Segments {
            segments: 1,
            corners,
        });
    }
    let spline = segment.curve();
    let frame = Frame::for_points(&spline.control_points());
    let local = spline.in_frame(&frame);
    let form = Form::new(local.curve(), profile.orientation())?;
    let (a, b) = form.domain();
    let widths = [opts.min_width, opts.max_width].map(|w| w.map(|w| frame.length_to_local(w)));
    let fs: Vec<_> = functions(&form, &form, opts.friction, widths)?
        .into_iter()
        .map(|(_, f)| f)
        .collect();
    let near = NearContacts::new(&form, opts.friction, true);
    let zero = ZeroSetOptions {
        settings: opts.settings,
        max_patches: opts.max_patches,
    };
    let set = nonnegative_set(
        &fs,
        &NonNegativeOptions {
            zero,
            pairs: true,
            seam: true,
        },
        &|bx| near.excluded(bx),
    )?;
    let diag = std::f64::consts::SQRT_2 * (b - a);
    let chord = opts.settings.chord_tol.get() * opts.settings.size.map_or(diag, Size::get);
    let raw = regions(&set, (a, b), chord);

    let seeds = antipodal_seeds(boundary, profile, (a, b))?;
    let proof = Positivity::new(&fs, (a, b));
    let out = Output {
        form: &form,
        frame: &frame,
        profile,
    };
    let mut doubts = Doubts::none();
    if !set.complete {
        doubts.add(Doubt::SearchLimit);
    }
    let mut found = Vec::with_capacity(raw.len());
    for r in &raw {
        let (center, proven) = most_robust(&form, r, &seeds);
        let mut region_doubts = r.doubts.clone();
        if !proven {
            region_doubts.add(Doubt::GraspBestUnproven);
        }
        let (lo, hi) = r.parts.iter().fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), p| {
                let (l, h) = bounds(p);
                (
                    [lo[0].min(l[0]), lo[1].min(l[1])],
                    [hi[0].max(h[0]), hi[1].max(h[1])],
                )
            },
        );
        let reach = [hi[0] - lo[0], hi[1] - lo[1]];
        let contact = around(&form, &proof, center, reach);
        let certified = !r.doubts.iter().any(|d| *d != Doubt::GraspBestUnproven);
        doubts.join(region_doubts);
        found.push(out.region(r, center, contact, certified));
    }
    Ok(Grasps {
        friction: opts.friction,
        min_width: opts.min_width,
        max_width: opts.max_width,
        regions: found,
        doubts,
        complete: set.complete,
    })
}

/// The antipodal pairs and the middles of the families, in the form's parameter.
fn antipodal_seeds(
    boundary: Boundary<'_>,
    profile: &Profile,
    (a, b): (f64, f64),
) -> Result<Vec<[f64; 2]>> {
    let found = antipodal::antipodal(boundary, &antipodal::Options::default())?;
    let form = |d: f64| {
        let u = profile.internal_param(d);
        a + u.fract() * (b - a) + if u >= 1.0 { b - a } else { 0.0 }
    };
    let (da, db) = profile.document_domain();
    let mut seeds: Vec<[f64; 2]> = found.pairs.iter().map(|p| [form(p.s), form(p.t)]).collect();
    for f in &found.families {
        let mid = |[lo, hi]: [f64; 2]| {
            let span = if hi >= lo {
                hi - lo
            } else {
                hi - lo + (db - da)
            };
            let m = lo + 0.5 * span;
            if m >= db {
                m - (db - da)
            } else {
                m
            }
        };
        seeds.push([form(mid(f.s)), form(mid(f.t))]);
    }
    Ok(seeds)
}

/// Writes regions in the curve's own parameter and coordinates.
struct Output<'a> {
    form: &'a Form,
    frame: &'a Frame,
    profile: &'a Profile,
}

impl Output<'_> {
    /// The document's parameter at the form's `v`, unwrapped: beyond the domain by whole
    /// periods where `v` is.
    fn param(&self, v: f64) -> f64 {
        let (a, b) = self.form.domain();
        let (da, db) = self.profile.document_domain();
        let turns = ((v - a) / (b - a)).floor();
        let x = ((v - a) / (b - a) - turns).clamp(0.0, 1.0);
        self.profile.document_param_on(0, x) - da + da + turns * (db - da)
    }

    fn point(&self, v: f64) -> [f64; 2] {
        self.frame.to_global(point_tangent(self.form, v).0)
    }

    fn polyline(&self, pts: &[[f64; 2]]) -> Vec<[f64; 2]> {
        pts.iter()
            .map(|p| [self.param(p[0]), self.param(p[1])])
            .collect()
    }

    fn region(
        &self,
        r: &RawRegion,
        center: [f64; 2],
        contact: Option<([f64; 2], [f64; 2])>,
        certified: bool,
    ) -> GraspRegion {
        let mut parts: Vec<Vec<[f64; 2]>> = r.parts.iter().map(|p| self.polyline(p)).collect();
        parts.sort_by(|x, y| {
            crate::assemble::signed_area(y).total_cmp(&crate::assemble::signed_area(x))
        });
        let boundary = parts[0].clone();
        if parts.len() == 1 {
            parts.clear();
        }
        GraspRegion {
            boundary,
            parts,
            holes: r.holes.iter().map(|h| self.polyline(h)).collect(),
            contact: contact.map(|(s, t)| ContactRegion {
                s: s.map(|v| self.param(v)),
                t: t.map(|v| self.param(v)),
                p: s.map(|v| self.point(v)),
                q: t.map(|v| self.point(v)),
            }),
            best: BestGrasp {
                s: self.param(center[0]),
                t: self.param(center[1]),
                p: self.point(center[0]),
                q: self.point(center[1]),
                min_friction: min_friction(self.form, center[0], center[1]),
            },
            certified,
        }
    }
}
