//! The regions from the pieces of their boundaries: pieces joined into loops where zero sets
//! cross and along the border of the half square `s < t`, loops sorted into parts and holes,
//! and parts glued across the seam of a closed curve into regions.
//!
//! The pairs `s < t` of a closed curve with domain `[a, b]` fill the triangle above the
//! diagonal. Its left edge `s = a` and its top edge `t = b` are the same pairs (`(a, u)` and
//! `(u, b)` both pair `C(a) = C(b)` with `C(u)`), so a region running across the seam shows
//! as parts touching both edges, glued where their stretches of those edges overlap.

use numeric::certificate::{Doubt, Doubts};
use zeroset::{BoundaryPiece, NonNegativeSet, PieceEnd};

/// Two ends are one point when this close, relative to the domain (crossings are polished
/// onto both zero sets; an unpolished one lies within the chord tolerance, added to this).
const SAME_POINT: f64 = 1e-7;

/// Stretches of the border overlap when they share more than this, relative to the domain.
const BORDER_OVERLAP: f64 = 1e-9;

/// A region as closed polylines in the triangle `s < t`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RawRegion {
    /// Its parts, each a closed polyline (first vertex repeated last), the region on the
    /// left; more than one where it runs across the seam.
    pub(crate) parts: Vec<Vec<[f64; 2]>>,
    /// Holes in it, clockwise.
    pub(crate) holes: Vec<Vec<[f64; 2]>>,
    /// What is not proven about its boundary.
    pub(crate) doubts: Doubts,
}

/// A loop and the stretches of the two border edges it runs along.
struct Loop {
    pts: Vec<[f64; 2]>,
    /// Stretches `[lo, hi]` of `s` along the top edge `t = b`.
    top: Vec<[f64; 2]>,
    /// Stretches of `t` along the left edge `s = a`.
    left: Vec<[f64; 2]>,
    doubts: Doubts,
}

/// The regions bounded by `set`'s pieces on the domain `[a, b]` of a closed curve.
pub(crate) fn regions(set: &NonNegativeSet, (a, b): (f64, f64), chord: f64) -> Vec<RawRegion> {
    let tol = SAME_POINT * (b - a) + chord;
    let mut loops = Vec::new();
    let open: Vec<&BoundaryPiece> = set.pieces.iter().filter(|p| p.ends.is_some()).collect();
    for p in set.pieces.iter().filter(|p| p.ends.is_none()) {
        loops.push(Loop {
            pts: p.pts.clone(),
            top: Vec::new(),
            left: Vec::new(),
            doubts: Doubts::none(),
        });
    }
    let mut used = vec![false; open.len()];
    let walk = Walk {
        open: &open,
        a,
        b,
        tol,
    };
    for first in 0..open.len() {
        if !used[first] {
            loops.push(walk.trace(first, &mut used));
        }
    }
    let mut unresolved = Doubts::none();
    if !set.unresolved.is_empty() {
        unresolved.add(Doubt::GraspBoundaryUnresolved);
    }
    let mut out = sort_and_glue(loops, &unresolved);
    for &p in &set.points {
        out.push(RawRegion {
            parts: vec![vec![p, p]],
            holes: Vec::new(),
            doubts: Doubt::GraspPointRegion.into(),
        });
    }
    out
}

/// Joins open pieces into loops.
struct Walk<'a> {
    open: &'a [&'a BoundaryPiece],
    a: f64,
    b: f64,
    tol: f64,
}

impl Walk<'_> {
    /// The place of a border point along the border walked counterclockwise round the
    /// triangle: the top edge from `(b, b)` to `(a, b)`, then the left edge down to `(a, a)`.
    fn border_place(&self, p: [f64; 2]) -> f64 {
        let w = self.b - self.a;
        if (p[1] - self.b).abs() <= (p[0] - self.a).abs() {
            (self.b - p[0]).clamp(0.0, w)
        } else {
            w + (self.b - p[1]).clamp(0.0, w)
        }
    }

    fn ends(&self, i: usize) -> [PieceEnd; 2] {
        self.open[i].ends.unwrap_or([PieceEnd::Loose; 2])
    }

    fn first(&self, i: usize) -> [f64; 2] {
        self.open[i].pts[0]
    }

    fn last(&self, i: usize) -> [f64; 2] {
        let pts = &self.open[i].pts;
        pts[pts.len() - 1]
    }

    /// The piece that goes on from the end of piece `i`, with the border walked between.
    fn next(
        &self,
        i: usize,
        used: &[bool],
        start: usize,
    ) -> Option<(usize, Vec<[f64; 2]>, [f64; 2])> {
        let end = self.last(i);
        let available = |j: usize| !used[j] || j == start;
        match self.ends(i)[1] {
            PieceEnd::Crossing(other) => {
                let mine = self.open[i].function;
                (0..self.open.len())
                    .filter(|&j| available(j))
                    .filter(|&j| {
                        self.open[j].function == other
                            && self.ends(j)[0] == PieceEnd::Crossing(mine)
                    })
                    .map(|j| (j, dist(self.first(j), end)))
                    .filter(|&(_, d)| d <= self.tol)
                    .min_by(|x, y| x.1.total_cmp(&y.1))
                    .map(|(j, _)| (j, Vec::new(), [0.0; 2]))
            }
            PieceEnd::Border => {
                let from = self.border_place(end);
                let j = (0..self.open.len())
                    .filter(|&j| available(j) && self.ends(j)[0] == PieceEnd::Border)
                    .map(|j| (j, self.border_place(self.first(j))))
                    .filter(|&(_, at)| at >= from)
                    .min_by(|x, y| x.1.total_cmp(&y.1))?;
                let w = self.b - self.a;
                let mut between = Vec::new();
                if from < w && j.1 > w {
                    between.push([self.a, self.b]);
                }
                Some((j.0, between, [from, j.1]))
            }
            PieceEnd::Loose => None,
        }
    }

    /// The loop through piece `first`.
    fn trace(&self, first: usize, used: &mut [bool]) -> Loop {
        let w = self.b - self.a;
        let mut l = Loop {
            pts: self.open[first].pts.clone(),
            top: Vec::new(),
            left: Vec::new(),
            doubts: Doubts::none(),
        };
        used[first] = true;
        let mut at = first;
        for _ in 0..=self.open.len() {
            let Some((next, between, [from, to])) = self.next(at, used, first) else {
                // Nothing goes on: close the loop by a chord, and say so.
                l.doubts.add(Doubt::GraspBoundaryUnresolved);
                break;
            };
            if self.ends(at)[1] == PieceEnd::Border {
                // The walked stretches, on each edge.
                if from < w {
                    l.top.push([self.b - to.min(w), self.b - from]);
                }
                if to > w {
                    l.left.push([self.b - (to - w), self.b - (from.max(w) - w)]);
                }
            }
            l.pts.extend(between);
            if next == first {
                break;
            }
            used[next] = true;
            l.pts.extend_from_slice(&self.open[next].pts);
            at = next;
        }
        let p0 = l.pts[0];
        l.pts.push(p0);
        l
    }
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// Twice the signed area of a closed polyline.
pub(crate) fn signed_area(pts: &[[f64; 2]]) -> f64 {
    pts.windows(2)
        .map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1])
        .sum()
}

/// Whether `p` lies inside the closed polyline `pts` (even-odd).
pub(crate) fn inside(pts: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut c = false;
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < x {
                c = !c;
            }
        }
    }
    c
}

/// Outer loops as parts with their holes, glued across the seam into regions.
fn sort_and_glue(loops: Vec<Loop>, shared: &Doubts) -> Vec<RawRegion> {
    let (outer, holes): (Vec<Loop>, Vec<Loop>) =
        loops.into_iter().partition(|l| signed_area(&l.pts) >= 0.0);
    // Union-find over the outer loops: glued where a left stretch of one overlaps a top
    // stretch of another (or of itself).
    let mut root: Vec<usize> = (0..outer.len()).collect();
    fn find(root: &mut [usize], i: usize) -> usize {
        let mut i = i;
        while root[i] != i {
            root[i] = root[root[i]];
            i = root[i];
        }
        i
    }
    let span = outer
        .iter()
        .flat_map(|l| l.pts.iter())
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()))
        .max(1.0);
    for i in 0..outer.len() {
        for j in 0..outer.len() {
            let glued = outer[i].left.iter().any(|l| {
                outer[j]
                    .top
                    .iter()
                    .any(|t| l[1].min(t[1]) - l[0].max(t[0]) > BORDER_OVERLAP * span)
            });
            if glued {
                let (ri, rj) = (find(&mut root, i), find(&mut root, j));
                root[ri] = rj;
            }
        }
    }
    let mut regions: Vec<(usize, RawRegion)> = Vec::new();
    for (i, l) in outer.iter().enumerate() {
        let r = find(&mut root, i);
        let slot = match regions.iter().position(|(k, _)| *k == r) {
            Some(k) => k,
            None => {
                regions.push((
                    r,
                    RawRegion {
                        parts: Vec::new(),
                        holes: Vec::new(),
                        doubts: shared.clone(),
                    },
                ));
                regions.len() - 1
            }
        };
        regions[slot].1.parts.push(l.pts.clone());
        regions[slot].1.doubts.join(l.doubts.clone());
    }
    for h in holes {
        // The hole belongs to the smallest part around it.
        let home = regions
            .iter()
            .enumerate()
            .flat_map(|(k, (_, r))| r.parts.iter().map(move |p| (k, p)))
            .filter(|(_, p)| inside(p, h.pts[0]))
            .min_by(|x, y| signed_area(x.1).total_cmp(&signed_area(y.1)))
            .map(|(k, _)| k);
        match home {
            Some(k) => {
                regions[k].1.holes.push(h.pts);
                regions[k].1.doubts.join(h.doubts);
            }
            // A clockwise loop round nothing: the boundary was not resolved.
            None => {
                for (_, r) in regions.iter_mut() {
                    r.doubts.add(Doubt::GraspBoundaryUnresolved);
                }
            }
        }
    }
    regions.into_iter().map(|(_, r)| r).collect()
}
