//! The crate's entry points: every force-closure grasp of a closed curve or profile, and the
//! curve or profile prepared once for its grasps at any friction and gripper widths: what
//! neither changes (the exact forms in one frame, with the friction-free parts of their cone
//! functions, and the antipodal pairs that seed the most robust grasps) is kept.

use crate::compute::grasps_of;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::options::GraspOptions;
use crate::types::Grasps;
use curve::{Boundary, ParamCurve, Profile};

/// Every two-finger force-closure grasp of a closed curve or profile for Coulomb friction μ
/// (Nguyen's condition: the chord between the contacts lies inside both friction cones; at a
/// convex corner, inside its cone of inward normals widened by the friction angle), as regions
/// of the square of contact parameters, each with its independent contact region and its
/// most robust grasp. Every antipodal pair and family lies inside a region.
///
/// ```
/// use grasp::{grasps, GraspOptions};
/// use curve::shapes::Ellipse;
/// // An ellipse has two antipodal pairs (its axes): two regions, each holding one.
/// let e = Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap();
/// let g = grasps(&e, &GraspOptions::friction(0.3)).unwrap();
/// assert!(g.complete);
/// assert_eq!(g.regions.len(), 2);
/// assert!(g.regions.iter().all(|r| r.certified && r.best.min_friction < 1e-9));
/// ```
pub fn grasps<'a>(boundary: impl Into<Boundary<'a>>, opts: &GraspOptions) -> Result<Grasps> {
    opts.check()?;
    prepare(boundary)?.grasps(opts)
}

/// A closed curve or profile prepared for [`PreparedGrasps::grasps`] ([`prepare`]).
pub struct PreparedGrasps<'a> {
    model: Model<'a>,
    /// The antipodal pairs and the middles of the families, in the profile's parameter.
    seeds: Vec<[f64; 2]>,
}

/// Prepares a closed curve or profile for its grasps at several frictions or widths: each
/// [`PreparedGrasps::grasps`] answers as [`grasps`] does, without repeating the work
/// that does not depend on them.
///
/// ```
/// use grasp::{grasps, prepare, GraspOptions};
/// use curve::shapes::Ellipse;
/// let e = Ellipse::new(3.0, 2.0, [0.0, 0.0]).unwrap();
/// let prepared = prepare(&e).unwrap();
/// for mu in [0.1, 0.3, 1.0] {
///     let opts = GraspOptions::friction(mu);
///     assert_eq!(prepared.grasps(&opts).unwrap(), grasps(&e, &opts).unwrap());
/// }
/// ```
pub fn prepare<'a>(boundary: impl Into<Boundary<'a>>) -> Result<PreparedGrasps<'a>> {
    let boundary = boundary.into();
    let profile = boundary.to_profile()?.ok_or(Error::NotExact)?;
    if !profile.is_closed() {
        return Err(Error::NotClosed);
    }
    let seeds = antipodal_seeds(boundary, &profile)?;
    Ok(PreparedGrasps {
        model: Model::new(profile)?,
        seeds,
    })
}

impl PreparedGrasps<'_> {
    /// Every two-finger force-closure grasp for the options' friction and widths, as
    /// [`grasps`] gives them.
    pub fn grasps(&self, opts: &GraspOptions) -> Result<Grasps> {
        opts.check()?;
        grasps_of(&self.model, &self.seeds, opts)
    }
}

/// The antipodal pairs and the middles of the families, in the profile's parameter.
///
/// A profile's pairs come in its own parameter already (the exact forms', as `antipodal`
/// answers a profile); a curve's come in the curve's own parameter, its document's (an
/// analytic shape's angle), which the profile of its one segment maps to its form's.
fn antipodal_seeds(boundary: Boundary<'_>, profile: &Profile) -> Result<Vec<[f64; 2]>> {
    let found = antipodal::antipodal(boundary, &antipodal::Options::default())?;
    let (internal, (da, db)): (&dyn Fn(f64) -> f64, (f64, f64)) = match boundary {
        Boundary::Profile(p) => (&|u| u, p.domain()),
        Boundary::Curve(_) => (&|u| profile.internal_param(u), profile.document_domain()),
    };
    let mut seeds: Vec<[f64; 2]> = found
        .pairs
        .iter()
        .map(|p| [internal(p.s), internal(p.t)])
        .collect();
    let period = db - da;
    for f in &found.families {
        // The middle pair: each range halved the short way round (a range runs backwards
        // where its pairs are matched so, or across the seam).
        let mid = |[a, b]: [f64; 2]| {
            let step = (b - a + 0.5 * period).rem_euclid(period) - 0.5 * period;
            internal(da + (a + 0.5 * step - da).rem_euclid(period))
        };
        seeds.push([mid(f.s), mid(f.t)]);
    }
    Ok(seeds)
}
