//! The region's boundaries as the medial axis reads them: foot points by boundary and
//! profile parameter, which side of a boundary is inside, and the distance from a point to
//! the whole boundary.

use curve::{JointKind, ParamCurve, Profile, Region};
use geometry::{Clearance, NearestPoint, ProfileClearance};
use std::sync::atomic::{AtomicBool, Ordering};

/// A disk counts as empty when no boundary point is nearer its centre than its radius by
/// more than this share of the region's size: the radius and the distances carry rounding
/// of ~1e-16 of the coordinates, and the nearest-point search converges to ~1e-15.
pub(crate) const EMPTY_SLACK: f64 = 1e-9;

/// What a disk holds of the boundary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Disk {
    /// No point nearer its centre than its radius (less the slack).
    Empty,
    /// The point of boundary `.0` at profile parameter `.1` lies nearer, by `.2` (at least
    /// the slack).
    Entered(usize, f64, f64),
}

/// How far the box the exterior axis is clipped to reaches beyond the region's box, as a
/// share of the region's size (the contract's half).
const CLIP_GROWTH: f64 = 0.5;

/// The boundaries of a region: 0 the outer one, 1.. the holes.
pub(crate) struct Sites<'a> {
    pub(crate) boundaries: Vec<&'a Profile>,
    /// +1 where the part of the plane whose axis is sought (the region, or its exterior)
    /// lies left of a boundary as it runs, −1 where right.
    inside_left: Vec<f64>,
    /// Whether that part is the exterior.
    exterior: bool,
    /// The box the exterior axis is clipped to, `[lo x, lo y, hi x, hi y]`.
    pub(crate) clip: Option<[f64; 4]>,
    /// The box of the outer boundary's control points (it holds the region).
    pub(crate) outer_box: [f64; 4],
    /// Per boundary, the profile parameters where its pieces start (segments, and the knot
    /// spans of spline segments), in order.
    piece_starts: Vec<Vec<f64>>,
    /// max(width, height) of the region's box (of its points), the scale of the relative
    /// tolerances.
    pub(crate) size: f64,
    /// The diagonal of that box.
    pub(crate) diagonal: f64,
    /// Whether some disk was decided by the nearest point found, not proven (set from any
    /// thread).
    undecided: AtomicBool,
}

impl<'a> Sites<'a> {
    /// The sites of `region`, for its axis inside or, with `exterior`, outside it (beyond
    /// the outer boundary and inside the holes), clipped to its box grown by half its size.
    pub(crate) fn new(region: &'a Region, exterior: bool) -> Self {
        let boundaries: Vec<&Profile> = std::iter::once(region.outer())
            .chain(region.holes())
            .collect();
        let inside_left = boundaries
            .iter()
            .enumerate()
            .map(|(k, b)| {
                let side = if k == 0 {
                    b.orientation()
                } else {
                    -b.orientation()
                };
                if exterior {
                    -side
                } else {
                    side
                }
            })
            .collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in region
            .outer()
            .segments()
            .iter()
            .flat_map(|s| s.curve().control_points())
        {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let bounds = region.bounding_box();
        let size = curve::box_size(bounds);
        let grow = CLIP_GROWTH * size;
        let piece_starts = boundaries
            .iter()
            .map(|b| {
                b.segments()
                    .iter()
                    .enumerate()
                    .flat_map(|(i, seg)| {
                        let breaks = seg.piece_breaks();
                        let starts = &breaks[..breaks.len() - 1];
                        starts
                            .iter()
                            .map(|&v| b.profile_param(i, v))
                            .collect::<Vec<_>>()
                    })
                    .collect()
            })
            .collect();
        Self {
            boundaries,
            piece_starts,
            inside_left,
            exterior,
            clip: exterior.then_some([
                bounds[0] - grow,
                bounds[1] - grow,
                bounds[2] + grow,
                bounds[3] + grow,
            ]),
            outer_box: [lo[0], lo[1], hi[0], hi[1]],
            size,
            diagonal: (hi[0] - lo[0]).hypot(hi[1] - lo[1]),
            undecided: AtomicBool::new(false),
        }
    }

    /// The side of boundary `k` (as it runs) the axis is sought on.
    pub(crate) fn side(&self, k: usize) -> zeroset::Side {
        if self.inside_left[k] > 0.0 {
            zeroset::Side::Left
        } else {
            zeroset::Side::Right
        }
    }

    /// +1 where the axis is sought left of boundary `k` as it runs, −1 where right.
    pub(crate) fn inside_left(&self, k: usize) -> f64 {
        self.inside_left[k]
    }

    /// The piece of boundary `k` holding profile parameter `u` (its index in order).
    pub(crate) fn piece_of(&self, k: usize, u: f64) -> usize {
        let starts = &self.piece_starts[k];
        starts.partition_point(|&s| s <= u).max(1) - 1
    }

    /// The boundary point at profile parameter `u` of boundary `b`.
    pub(crate) fn foot(&self, b: usize, u: f64) -> [f64; 2] {
        self.boundaries[b].jet_to(u, 0).p.arr()
    }

    /// The distance from `x` to the boundary, or some distance below `enough` when there is
    /// one; with the boundary and parameter of the point found.
    pub(crate) fn nearest(&self, x: [f64; 2], enough: f64) -> (f64, usize, f64) {
        let mut best = (f64::INFINITY, 0, 0.0);
        for (k, b) in self.boundaries.iter().enumerate() {
            let n = b.nearest(x, enough);
            if n.distance < best.0 {
                best = (n.distance, k, n.u);
                if n.distance < enough {
                    break;
                }
            }
        }
        best
    }

    /// What the disk centred at `x` of radius `rho` holds: no boundary point nearer its
    /// centre than the radius less the slack, or one such point. Proven on the boundaries'
    /// control hulls ([`ProfileClearance::clearance`], nearest segments first) where rounding allows,
    /// else decided by the nearest point found.
    pub(crate) fn disk(&self, x: [f64; 2], rho: f64) -> Disk {
        let (disk, decided) = self.disk_verdict(x, rho);
        if !decided {
            self.undecided.store(true, Ordering::Relaxed);
        }
        disk
    }

    /// [`Sites::disk`] for a search whose outcome is proven again: the search for where a
    /// stretch ends, whose node (a junction's or an end's place, and its disk) the
    /// certificate proves by itself. A verdict left to the nearest point is not recorded: a
    /// bracket of the search that closes in on where the boundary touches the disk meets
    /// disks within rounding of touching it, and the worst it does is move the bracket by
    /// that much.
    pub(crate) fn probe(&self, x: [f64; 2], rho: f64) -> Disk {
        self.disk_verdict(x, rho).0
    }

    /// What the disk holds, and whether the bounds proved it.
    fn disk_verdict(&self, x: [f64; 2], rho: f64) -> (Disk, bool) {
        let r = rho - EMPTY_SLACK * self.size;
        let mut undecided = false;
        for (k, b) in self.boundaries.iter().enumerate() {
            match b.clearance(x, r) {
                Clearance::Clear => {}
                Clearance::Entered { u, distance } => {
                    return (Disk::Entered(k, u, rho - distance), true)
                }
                Clearance::Unresolved => undecided = true,
            }
        }
        if !undecided {
            return (Disk::Empty, true);
        }
        let disk = match self.nearest(x, r) {
            (d, _, _) if d >= r => Disk::Empty,
            (d, k, u) => Disk::Entered(k, u, rho - d),
        };
        (disk, false)
    }

    /// Whether some disk's verdict was not proven by bounds.
    pub(crate) fn some_disk_undecided(&self) -> bool {
        self.undecided.load(Ordering::Relaxed)
    }

    /// Whether `x` lies in the box the axis is clipped to (always, inside the region).
    pub(crate) fn in_clip(&self, x: [f64; 2]) -> bool {
        self.clip
            .is_none_or(|c| x[0] >= c[0] && x[0] <= c[2] && x[1] >= c[1] && x[1] <= c[3])
    }

    /// Whether `x`, the bisector point of the foot at `u` on segment `i` of boundary `b`,
    /// lies inside the region: on the inner side of the segment there (a corner's foot:
    /// where the corner is reflex for the region, its cone lies inside).
    pub(crate) fn inside_of(&self, b: usize, i: usize, u: f64, corner: bool, x: [f64; 2]) -> bool {
        let p = self.boundaries[b];
        if corner {
            // A reflex corner of the outer boundary (a convex one of a hole, as the hole runs)
            // points into the region; the others into the exterior.
            // (The joints are in order of their parameters.)
            let joint = p
                .joints()
                .binary_search_by(|j| j.u.total_cmp(&u))
                .ok()
                .map(|k| &p.joints()[k]);
            return match joint {
                Some(j) if (b == 0) != self.exterior => j.kind == JointKind::Reflex,
                Some(j) => j.kind == JointKind::Convex,
                None => false,
            };
        }
        let j = p.jet_on(i, u, 1);
        let v = [x[0] - j.p.x, x[1] - j.p.y];
        let side = j.d1.x * v[1] - j.d1.y * v[0];
        side * self.inside_left[b] > 0.0
    }
}
