//! How wide each boundary's inscribed disks get, read from the axis: the widest radius of the
//! axis points with a foot on it, and the nodes no edge reaches (a round hole's centre).

use curve::{ParamCurve, Profile};
use medial::MedialAxis;

/// The nodes no edge reaches.
pub(crate) fn isolated_nodes(axis: &MedialAxis) -> impl Iterator<Item = &medial::Node> {
    axis.nodes
        .iter()
        .filter(|n| !axis.edges.iter().any(|e| e.from == n.id || e.to == n.id))
}

/// Whether the closed profile winds round `p` (its winding number on a fine polygon of it: a
/// node at a hole's centre is far from its boundary).
pub(crate) fn encloses(profile: &Profile, p: [f64; 2]) -> bool {
    let (a, b) = profile.domain();
    let n = 64 * profile.segments().len();
    let at = |k: usize| {
        let q = profile.jet_to(a + (b - a) * (k % n) as f64 / n as f64, 0).p;
        (q.x - p[0]).atan2(q.y - p[1])
    };
    let mut turned = 0.0;
    for k in 0..n {
        let step = at(k + 1) - at(k);
        turned +=
            (step + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
    }
    turned.abs() > std::f64::consts::PI
}

/// Per boundary, the widest radius of the axis points with a foot on it (a disk's single node
/// for an inner axis without edges; outside, a boundary no axis point reaches, as a convex
/// outline's, has no bound at all).
pub(crate) fn widest_per_boundary(axis: &MedialAxis, boundaries: usize, outward: bool) -> Vec<f64> {
    let mut widest = vec![f64::NEG_INFINITY; boundaries];
    for edge in &axis.edges {
        for (k, pair) in edge.boundary.iter().enumerate() {
            for &b in pair {
                if let Some(w) = widest.get_mut(b) {
                    *w = w.max(edge.radius[k]);
                }
            }
        }
    }
    if outward {
        for w in &mut widest {
            if *w == f64::NEG_INFINITY {
                *w = f64::INFINITY;
            }
        }
    } else if axis.edges.is_empty() {
        if let (Some(node), Some(w)) = (axis.nodes.first(), widest.first_mut()) {
            *w = node.radius;
        }
    }
    widest
}
