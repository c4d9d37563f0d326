//! The results: regions of force-closure grasps in the square of contact parameters.

use numeric::certificate::Doubts;
use serde::{Deserialize, Serialize};

/// Every two-finger force-closure grasp of a closed curve for one friction coefficient
/// ([`crate::grasps`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Grasps {
    /// The friction coefficient μ.
    pub friction: f64,
    /// The gripper's least opening, if limited.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub min_width: Option<f64>,
    /// The gripper's greatest opening, if limited.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub max_width: Option<f64>,
    /// The regions, each a connected set of pairs `(s, t)`.
    pub regions: Vec<GraspRegion>,
    /// The doubts met (none: every region's boundary follows from certified zero sets, and
    /// each best grasp is an antipodal pair). Read with
    /// [`Verdict`](numeric::certificate::Verdict): `certified()` and `reason()`.
    #[serde(flatten)]
    pub doubts: Doubts,
    /// False when a work limit was hit (regions may then be missing).
    pub complete: bool,
}

/// One connected region of force-closure pairs `(s, t)`, `s < t`, in the curve's own
/// parameter.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GraspRegion {
    /// Its boundary: a closed polyline in the square of parameters on the side `s < t`, the
    /// region on its left (the largest of its parts).
    pub boundary: Vec<[f64; 2]>,
    /// Where the region runs across the curve's seam or across joints, the square shows it in
    /// several parts: all of them, `boundary` first (a region of one part has just
    /// `boundary`). Pairs with a finger at a corner lie on the corner's line: such a stretch
    /// is a part without area, there and back, and a single pair a part of two equal points.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub parts: Vec<Vec<[f64; 2]>>,
    /// Holes in it (closed polylines, clockwise), if any.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub holes: Vec<Vec<[f64; 2]>>,
    /// Its independent contact region: stretches of the boundary such that any `s` of one
    /// with any `t` of the other is force closure (`None` where none was proven: a region
    /// that is a single point).
    pub contact: Option<ContactRegion>,
    /// Its most robust grasp.
    pub best: BestGrasp,
    /// Whether its boundary is proven (every piece from certified zero sets, every end
    /// joined).
    pub certified: bool,
}

/// An independent contact region: the pairs `[s0, s1] × [t0, t1]`, all force closure. An
/// interval may run across the seam of the curve: its ends then lie beyond the domain, to be
/// read modulo the period.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ContactRegion {
    /// The stretch `[s0, s1]` of the first finger.
    pub s: [f64; 2],
    /// The stretch `[t0, t1]` of the second finger.
    pub t: [f64; 2],
    /// The ends of the first stretch, `C(s0)` and `C(s1)`.
    pub p: [[f64; 2]; 2],
    /// The ends of the second stretch.
    pub q: [[f64; 2]; 2],
}

/// A region's most robust grasp: the pair farthest (in angle) from the edges of both
/// friction cones. An antipodal pair where the region holds one; otherwise found by search,
/// and proven the most robust to one part in 10⁴ of its `min_friction` (but for pairs with a
/// finger in a stretch of `toward`) unless the result reports `GraspBestUnproven`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BestGrasp {
    /// The first contact's parameter.
    pub s: f64,
    /// The second contact's parameter.
    pub t: f64,
    /// The first contact.
    pub p: [f64; 2],
    /// The second contact.
    pub q: [f64; 2],
    /// The least friction coefficient for which this pair is force closure (0 at an
    /// antipodal pair).
    pub min_friction: f64,
    /// Stretches `[u0, u1]` of the curve's parameter, each round a corner the region does
    /// not reach (a reflex corner, or one of two corners at one point) toward which its least
    /// friction falls without being attained: pairs with a finger in one may need less
    /// friction than this one, no other pair of the region does. Empty where the least
    /// friction is attained. A stretch may run across the seam, as a contact region's.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub toward: Vec<[f64; 2]>,
}

numeric::impl_verdict!(Grasps);
