//! What a grasp computation is asked for.

use crate::error::{Error, Result};
use numeric::tolerance::Settings;

/// GraspOptions for [`crate::grasps`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GraspOptions {
    /// The Coulomb friction coefficient μ between finger and boundary (`> 0`): the friction
    /// cone's half-angle is `atan μ`.
    pub friction: f64,
    /// The gripper's least opening: pairs closer than this are left out.
    pub min_width: Option<f64>,
    /// The gripper's greatest opening: pairs farther apart are left out.
    pub max_width: Option<f64>,
    /// The tolerances: the chord tolerance is relative to the parameter domain (the region
    /// boundaries live in the square of contact parameters), the parameter tolerance the
    /// smallest patch the subdivision resolves.
    pub settings: Settings,
    /// Limit on the patches each function's zero set examines; hitting it makes the result
    /// incomplete.
    pub max_patches: usize,
}

impl GraspOptions {
    /// The options for friction `mu`, with no width limits and the default tolerances.
    pub fn friction(mu: f64) -> Self {
        Self {
            friction: mu,
            min_width: None,
            max_width: None,
            settings: Settings::default(),
            max_patches: 400_000,
        }
    }

    /// Checks each number against what it can be.
    pub(crate) fn check(&self) -> Result<()> {
        let bad = |field, value, expected| {
            Err(Error::Option {
                field,
                value,
                expected,
            })
        };
        if !(self.friction > 0.0 && self.friction.is_finite()) {
            return bad("friction", self.friction, "a finite coefficient above 0");
        }
        for (field, w) in [("min_width", self.min_width), ("max_width", self.max_width)] {
            if let Some(w) = w {
                if !(w > 0.0 && w.is_finite()) {
                    return bad(field, w, "a finite width above 0");
                }
            }
        }
        if let (Some(lo), Some(hi)) = (self.min_width, self.max_width) {
            if lo >= hi {
                return bad("max_width", hi, "above min_width");
            }
        }
        Ok(())
    }
}
