//! An independent approximation of a region's medial axis: the Voronoi diagram of a dense
//! sampling of its boundaries (by `spade`'s Delaunay triangulation), kept where the two
//! samples an edge separates lie far apart along the boundary, each kept edge then refined to
//! a point of the true axis. Shares no code with the crates but the profiles' evaluation.
//!
//! Refinement: on the line through the Voronoi edge's midpoint parallel to its two samples,
//! the point whose distances to the boundary near either sample are equal (each distance a
//! local search about its own sample), solved by the Illinois method. The caller's global
//! distance then tells whether that point is on the axis (near a junction a third stretch
//! of boundary may be closer: such points are counted, not returned).
#![allow(dead_code, unreachable_pub)]

use curve::{ParamCurve, Profile};
use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation};

/// Samples per size of the region: the spacing of the sampling is `size / DENSITY` (each
/// knot span or segment gets at least `MIN_PER_PIECE`).
const DENSITY: f64 = 800.0;
const MIN_PER_PIECE: usize = 16;
/// A Delaunay edge is kept when its samples lie on different boundaries or this fraction
/// of the size apart along their boundary: closer ones are the boundary's own normals.
const FAR: f64 = 0.02;
/// Samples to either side of an edge's sample searched for its foot (at most a third of
/// the gap between the edge's samples, so that the two searches never meet).
const WINDOW: usize = 24;
/// A point is dominated (not on the axis) when the global distance is below its two equal
/// distances by more than this fraction of the size.
const DOMINATED: f64 = 1e-9;

struct Sample {
    at: Point2<f64>,
    boundary: usize,
    index: usize,
}

impl HasPosition for Sample {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.at
    }
}

/// One boundary's samples: profile parameters, points and arc positions.
struct Sampled<'a> {
    profile: &'a Profile,
    u: Vec<f64>,
    pts: Vec<[f64; 2]>,
    arc: Vec<f64>,
    length: f64,
}

impl<'a> Sampled<'a> {
    fn new(profile: &'a Profile, step: f64) -> Self {
        let mut u = Vec::new();
        for (i, s) in profile.segments().iter().enumerate() {
            let spans = s.curve().curve().homogeneous().breakpoints().len().max(2) - 1;
            let fine = 64 * spans;
            let length: f64 = (0..fine)
                .map(|k| {
                    let a = profile.jet(i as f64 + k as f64 / fine as f64).p.arr();
                    let b = profile.jet(i as f64 + (k + 1) as f64 / fine as f64).p.arr();
                    (b[0] - a[0]).hypot(b[1] - a[1])
                })
                .sum();
            let n = (MIN_PER_PIECE * spans).max((length / step).ceil() as usize);
            u.extend((0..n).map(|k| i as f64 + k as f64 / n as f64));
        }
        let pts: Vec<[f64; 2]> = u.iter().map(|&u| profile.jet(u).p.arr()).collect();
        let mut arc = Vec::with_capacity(pts.len());
        let mut length = 0.0;
        for k in 0..pts.len() {
            arc.push(length);
            let (a, b) = (pts[k], pts[(k + 1) % pts.len()]);
            length += (b[0] - a[0]).hypot(b[1] - a[1]);
        }
        Self {
            profile,
            u,
            pts,
            arc,
            length,
        }
    }

    /// The profile parameter at a fractional sample index (cyclic).
    fn param(&self, at: f64) -> f64 {
        let n = self.u.len() as isize;
        let k = at.floor() as isize;
        let (i, j) = (k.rem_euclid(n) as usize, (k + 1).rem_euclid(n) as usize);
        let period = self.profile.segments().len() as f64;
        let mut next = self.u[j];
        if next < self.u[i] {
            next += period;
        }
        (self.u[i] + (at - k as f64) * (next - self.u[i])).rem_euclid(period)
    }

    /// The length of the boundary between two samples, the short way round.
    fn gap(&self, a: usize, b: usize) -> f64 {
        let d = (self.arc[a] - self.arc[b]).abs();
        d.min(self.length - d)
    }

    /// [`Self::local_distance`], its window doubled up to `widest` samples while the least
    /// sample is at the window's end.
    fn widening_distance(
        &self,
        x: [f64; 2],
        k: usize,
        window: usize,
        widest: usize,
    ) -> (f64, FootSearch) {
        let mut w = window;
        loop {
            let (d, inside) = self.local_distance(x, k, w);
            if inside {
                return (d, FootSearch::Inside);
            }
            if w >= widest {
                return (d, FootSearch::Widest);
            }
            w = (2 * w).min(widest);
        }
    }

    /// The distance from `x` to the boundary within `window` samples of sample `k`, and
    /// whether its minimum is inside the window (not at its ends).
    fn local_distance(&self, x: [f64; 2], k: usize, window: usize) -> (f64, bool) {
        let n = self.pts.len() as isize;
        let dist = |q: [f64; 2]| ((q[0] - x[0]).powi(2) + (q[1] - x[1]).powi(2)).sqrt();
        let w = window as isize;
        let (mut best, mut at) = (f64::INFINITY, 0);
        for o in -w..=w {
            let d = dist(self.pts[(k as isize + o).rem_euclid(n) as usize]);
            if d < best {
                (best, at) = (d, o);
            }
        }
        let inside = at.abs() < w;
        // Golden section between the best sample's neighbours.
        let f = |t: f64| dist(self.profile.jet(self.param(t)).p.arr());
        let centre = (k as isize + at) as f64;
        let (mut a, mut b) = (centre - 1.0, centre + 1.0);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut c, mut e) = (b - g * (b - a), a + g * (b - a));
        let (mut fc, mut fe) = (f(c), f(e));
        for _ in 0..48 {
            if fc < fe {
                (b, e, fe) = (e, c, fc);
                c = b - g * (b - a);
                fc = f(c);
            } else {
                (a, c, fc) = (c, e, fe);
                e = a + g * (b - a);
                fe = f(e);
            }
        }
        (best.min(fc).min(fe).min(f(0.5 * (a + b))), inside)
    }
}

/// Where a foot search ended: its least point inside its window, or at the end of the
/// widest window.
#[derive(Clone, Copy, PartialEq, Eq)]
enum FootSearch {
    Inside,
    Widest,
}

/// A point of the medial axis found from the samples' Voronoi diagram.
pub struct MedialPoint {
    pub xy: [f64; 2],
    pub radius: f64,
}

/// What the sampled diagram gave: the refined points of the axis, and how many kept edges
/// there were, how many did not refine (no sign change, no convergence), how many had a
/// foot beyond the widest search window (beside nearly concentric arcs the distance barely
/// changes along the boundary, and a foot may lie anywhere on it) and how many refined to a
/// point a third stretch of boundary is closer to.
pub struct Approximation {
    pub points: Vec<MedialPoint>,
    pub kept: usize,
    pub unrefined: usize,
    pub unresolved: usize,
    pub dominated: usize,
}

/// The axis of the region bounded by `boundaries` (outer first), of the given size, with
/// the caller's global distance to the boundary and test of being inside the region.
pub fn sampled_medial_points(
    boundaries: &[&Profile],
    size: f64,
    distance: impl Fn([f64; 2]) -> f64,
    inside: impl Fn([f64; 2]) -> bool,
) -> Approximation {
    let step = size / DENSITY;
    let sampled: Vec<Sampled<'_>> = boundaries.iter().map(|p| Sampled::new(p, step)).collect();
    let samples: Vec<Sample> = sampled
        .iter()
        .enumerate()
        .flat_map(|(boundary, s)| {
            s.pts.iter().enumerate().map(move |(index, q)| Sample {
                at: Point2::new(q[0], q[1]),
                boundary,
                index,
            })
        })
        .collect();
    let triangulation: DelaunayTriangulation<Sample> =
        DelaunayTriangulation::bulk_load(samples).expect("the samples triangulate");
    let mut out = Approximation {
        points: Vec::new(),
        kept: 0,
        unrefined: 0,
        unresolved: 0,
        dominated: 0,
    };
    for edge in triangulation.undirected_edges() {
        let [va, vb] = edge.vertices();
        let (va, vb) = (va.data(), vb.data());
        let same = va.boundary == vb.boundary;
        if same && sampled[va.boundary].gap(va.index, vb.index) <= FAR * size {
            continue;
        }
        let directed = edge.as_directed();
        let (Some(f), Some(g)) = (directed.face().as_inner(), directed.rev().face().as_inner())
        else {
            continue;
        };
        let (c, e) = (f.circumcenter(), g.circumcenter());
        let mid = [0.5 * (c.x + e.x), 0.5 * (c.y + e.y)];
        if !inside(mid) {
            continue;
        }
        out.kept += 1;
        // The widest window: a third of the gap between the samples on one boundary (so
        // that the two searches never meet), else half the boundary.
        let widest = |k: usize| {
            if same {
                let gap = va.index.abs_diff(vb.index);
                gap.min(sampled[va.boundary].pts.len() - gap) / 3
            } else {
                sampled[k].pts.len() / 2
            }
        };
        let (pa, pb) = (va.at, vb.at);
        let half = 0.5 * (pb.x - pa.x).hypot(pb.y - pa.y);
        let dir = [(pb.x - pa.x) / (2.0 * half), (pb.y - pa.y) / (2.0 * half)];
        let at = |t: f64| [mid[0] + t * dir[0], mid[1] + t * dir[1]];
        let sides = |t: f64| {
            let foot = |v: &Sample| {
                let widest = widest(v.boundary);
                sampled[v.boundary].widening_distance(at(t), v.index, WINDOW.min(widest), widest)
            };
            let ((da, ia), (db, ib)) = (foot(va), foot(vb));
            (da - db, da, [ia, ib])
        };
        match illinois(&sides, -half, half, size) {
            Err(Miss::BeyondWindows) => out.unresolved += 1,
            Err(Miss::Unrefined) => out.unrefined += 1,
            Ok((t, r)) => {
                let z = at(t);
                if distance(z) < r - DOMINATED * size {
                    out.dominated += 1;
                } else if inside(z) {
                    out.points.push(MedialPoint { xy: z, radius: r });
                }
            }
        }
    }
    out
}

/// Why an edge did not refine.
enum Miss {
    /// No sign change, no convergence, or a foot at the end of a window that could widen.
    Unrefined,
    /// A foot at the end of the widest window.
    BeyondWindows,
}

/// The root of `sides(t).0` in `[a, b]` by the Illinois method, with the distance there
/// (`sides(t).2`: per foot, whether it lies inside its window, and if not, whether that
/// window could not widen further).
fn illinois(
    sides: &impl Fn(f64) -> (f64, f64, [FootSearch; 2]),
    mut a: f64,
    mut b: f64,
    size: f64,
) -> Result<(f64, f64), Miss> {
    let (mut fa, _, _) = sides(a);
    let (mut fb, _, _) = sides(b);
    if fa.signum() == fb.signum() {
        return Err(Miss::Unrefined);
    }
    let mut side = 0;
    for _ in 0..100 {
        let t = (a * fb - b * fa) / (fb - fa);
        let (ft, r, feet) = sides(t);
        if ft.abs() <= 1e-13 * size || (b - a).abs() <= 1e-15 * size {
            return match feet {
                _ if feet.contains(&FootSearch::Widest) => Err(Miss::BeyondWindows),
                [FootSearch::Inside, FootSearch::Inside] if ft.abs() <= 1e-10 * size => Ok((t, r)),
                _ => Err(Miss::Unrefined),
            };
        }
        if ft.signum() == fb.signum() {
            (b, fb) = (t, ft);
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            (a, fa) = (t, ft);
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    Err(Miss::Unrefined)
}
