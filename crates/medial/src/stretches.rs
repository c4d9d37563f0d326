//! The stretches of each candidate branch that belong to the axis: inside the region, with
//! empty disks. Where a stretch ends inside its branch, the end is refined on the exact
//! branch to the point where a third boundary point reaches the disk: a tri-tangent disk.

mod curvature_centres;
mod exact_vertices;
mod junctions;
mod on_axis;

use crate::candidates::{Candidate, Vertex};
use crate::curvature::sign_change;
use crate::parallel::in_order;
use crate::sites::Sites;
use curve::watch::Stage;
use curve::ParamCurve;

/// Halvings that look for a stretch on the axis hidden between two polyline vertices off
/// it (down to 2^-20 of the step).
const HIDDEN_DEPTH: usize = 20;

/// What the site entering a disk is taken to be: boundary and segment, and how deep it
/// reaches into the disk (0 where no site enters: the nearest site then).
type Intruder = ((usize, usize), f64);

/// How much longer than the chord between two of its points a stretch of a candidate
/// branch may be, when the search for a hidden stretch bounds what lies between them.
const LENGTH_SLACK: f64 = 1.5;

/// Most distance (a share of the region's size) between the points tested along the
/// bisector of two corners: a stretch of it on the axis between two junctions (at the
/// circumcentre of three reflex corners, the bisectors of two pairs of them run on from the
/// third's) is found where it is longer than that.
const CORNER_LINE_STEP: f64 = 1e-2;

/// A stretch of one candidate on the axis.
#[derive(Debug, Clone)]
pub(crate) struct Stretch {
    /// The candidate it lies on.
    pub(crate) candidate: usize,
    pub(crate) vertices: Vec<Vertex>,
}

/// The stretches of every candidate, in the candidates' order (on all cores with the
/// `parallel` feature).
pub(crate) fn stretches(sites: &Sites<'_>, found: &[Candidate]) -> Vec<Stretch> {
    // (A cancelled watch trims no candidate more: the caller answers "cancelled".)
    let stage = curve::watch::stage("medial axis: candidates trimmed to the axis");
    let order: Vec<usize> = (0..found.len()).collect();
    let per_candidate = in_order(&order, |&k| {
        if stage.go_on(1) {
            stretches_of(sites, k, &found[k], &stage)
        } else {
            Vec::new()
        }
    });
    per_candidate.into_iter().flatten().collect()
}

/// The stretches of candidate `k`.
fn stretches_of(sites: &Sites<'_>, k: usize, c: &Candidate, stage: &Stage) -> Vec<Stretch> {
    let mut out = Vec::new();
    let branch = Branch { sites, c, stage };
    let samples = branch.samples();
    let n = samples.len();
    let mut i = 0;
    while i < n {
        if samples[i].on_axis.is_none() {
            i += 1;
            continue;
        }
        let start = i;
        while i < n && samples[i].on_axis.is_some() {
            i += 1;
        }
        let mut vertices: Vec<Vertex> =
            samples[start..i].iter().filter_map(|s| s.on_axis).collect();
        if start > 0 {
            let before = &samples[start - 1];
            // (Not the vertex itself again: the junction may lie on it.)
            if let Some(v) = branch.junction(vertices[0], before.tr, before.xy) {
                if v != vertices[0] {
                    vertices.insert(0, v);
                }
            }
        }
        if i < n {
            let after = &samples[i];
            let last = vertices[vertices.len() - 1];
            if let Some(v) = branch.junction(last, after.tr, after.xy) {
                if v != last {
                    vertices.push(v);
                }
            }
        }
        if vertices.len() >= 2 || n == 1 {
            out.push(Stretch {
                candidate: k,
                vertices,
            });
        }
    }
    out
}

/// A point of a candidate branch: feet, point, and the vertex when it is on the axis.
struct Sample {
    tr: [f64; 2],
    xy: [f64; 2],
    on_axis: Option<Vertex>,
}

/// One candidate branch with the region: exact points on it, and the test of the axis.
struct Branch<'s, 'a> {
    sites: &'s Sites<'a>,
    c: &'s Candidate,
    /// The stage's watch, looked at for every point tested and every step of the searches:
    /// one candidate may have thousands of points, each a disk test.
    stage: &'s Stage,
}

impl Branch<'_, '_> {
    /// The candidate's vertices, tested; between two vertices off the axis whose disks are
    /// entered by different boundary sites, a stretch on the axis shorter than the polyline's
    /// step may lie (two junctions close together): it is searched for by halving.
    fn samples(&self) -> Vec<Sample> {
        let c = self.c;
        let mut out: Vec<Sample> = Vec::with_capacity(c.tr.len());
        let mut last_intruder: Option<Intruder> = None;
        for (tr, xy) in self.points() {
            // (Cancelled: what is tested so far is no answer, and the caller says so.)
            if self.stage.cancelled() {
                break;
            }
            let (on_axis, intruder) = match self.vertex(tr, xy) {
                Some(v) => match self.classify(&v) {
                    Ok(()) => (Some(v), None),
                    Err(site) => (None, Some(site)),
                },
                None => (None, Some((self.nearest_site(xy), 0.0))),
            };
            if let (Some(v), Some(prev)) = (on_axis, out.last().and_then(|p| p.on_axis)) {
                if let Some(m) = self.past_evolute(&prev, &v) {
                    out.push(Sample {
                        tr: m.tr,
                        xy: m.xy,
                        on_axis: None,
                    });
                }
            }
            if let (Some(a), Some(b), Some(prev)) = (last_intruder, intruder, out.last()) {
                if a.0 != b.0 {
                    let (ptr, pxy) = (prev.tr, prev.xy);
                    if let Some(v) = self.between((ptr, pxy, a), (tr, xy, b), HIDDEN_DEPTH) {
                        out.push(Sample {
                            tr: v.tr,
                            xy: v.xy,
                            on_axis: Some(v),
                        });
                    }
                }
            }
            last_intruder = intruder;
            out.push(Sample { tr, xy, on_axis });
        }
        out
    }

    /// The candidate's points to test: its vertices, but for the bisector of two corners
    /// (a line given by its two ends) points along it within the box the axis lies in, at
    /// most [`CORNER_LINE_STEP`] of the size apart: a stretch between two points whose disks
    /// one site enters is not searched for, and the line's ends lie far apart.
    fn points(&self) -> Vec<([f64; 2], [f64; 2])> {
        let c = self.c;
        let line = c.corner == [true, true] && c.xy.len() == 2;
        let clipped = line
            .then(|| clip_to_box(c.xy[0], c.xy[1], crate::candidates::root_box(self.sites)))
            .flatten();
        let Some((a, b)) = clipped else {
            return c.tr.iter().copied().zip(c.xy.iter().copied()).collect();
        };
        let length = (b[0] - a[0]).hypot(b[1] - a[1]);
        let steps = ((length / (CORNER_LINE_STEP * self.sites.size)).ceil() as usize).max(1);
        (0..=steps)
            .map(|k| {
                let s = k as f64 / steps as f64;
                (
                    c.tr[0],
                    [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])],
                )
            })
            .collect()
    }

    /// Between two vertices on the axis, a point of the branch off it where a foot passes a
    /// curvature maximum whose centre lies nearer the foot than the branch: there the
    /// boundary beside the foot enters the disk (the branch crosses the evolute and back,
    /// between two junctions with one disk), a window too narrow for the polyline's steps.
    /// The vertex with its foot at the maximum, if its disk is entered.
    fn past_evolute(&self, a: &Vertex, b: &Vertex) -> Option<Vertex> {
        let c = self.c;
        (0..2).filter(|&s| !c.corner[s]).find_map(|s| {
            let boundary = self.sites.boundaries[c.boundary[s]];
            let rate = |u: f64| boundary.jet_on(c.segment[s], u, 3).curvature_rate();
            let (lo, hi) = (a.tr[s].min(b.tr[s]), a.tr[s].max(b.tr[s]));
            // (Not across a closed boundary's seam, where the foot runs on from the end of
            // its parameter to the start: between the two lies the rest of the boundary.)
            let n = boundary.domain().1;
            if boundary.is_closed() && hi - lo > 0.5 * n {
                return None;
            }
            if !(rate(lo).signum() != rate(hi).signum() && hi > lo) {
                return None;
            }
            let u = sign_change(&rate, lo, hi);
            let share = (u - a.tr[s]) / (b.tr[s] - a.tr[s]);
            let lerp = |x: [f64; 2], y: [f64; 2]| {
                [x[0] + share * (y[0] - x[0]), x[1] + share * (y[1] - x[1])]
            };
            let mut guess = lerp(a.tr, b.tr);
            guess[s] = u;
            let v = self.snap_keeping(s, guess, lerp(a.xy, b.xy), a.tr, b.tr)?;
            self.classify(&v).is_err().then_some(v)
        })
    }

    /// A vertex on the axis strictly between two points of the branch off it (feet, point
    /// and the site entering their disks), by halving where the entering sites differ.
    fn between(
        &self,
        a: ([f64; 2], [f64; 2], Intruder),
        b: ([f64; 2], [f64; 2], Intruder),
        depth: usize,
    ) -> Option<Vertex> {
        if depth == 0 || a.2 .0 == b.2 .0 || self.stage.cancelled() {
            return None;
        }
        // How far the boundary is inside the disk less its radius changes at most twice as
        // fast as the point moves: where the two ends are too deep for their distance, no
        // disk between them is empty.
        let apart = (b.1[0] - a.1[0]).hypot(b.1[1] - a.1[1]);
        if 2.0 * LENGTH_SLACK * apart < a.2 .1 + b.2 .1 {
            return None;
        }
        let tr = [0.5 * (a.0[0] + b.0[0]), 0.5 * (a.0[1] + b.0[1])];
        let xy = [0.5 * (a.1[0] + b.1[0]), 0.5 * (a.1[1] + b.1[1])];
        let v = self.snap(tr, xy, a.0, b.0)?;
        let site = match self.classify(&v) {
            Ok(()) => return Some(v),
            Err(site) => site,
        };
        let m = (v.tr, v.xy, site);
        self.between(a, m, depth - 1)
            .or_else(|| self.between(m, b, depth - 1))
    }
}

/// The part of the segment `a`–`b` inside the box `[lo x, lo y, hi x, hi y]` (Liang and
/// Barsky), `None` where it misses the box.
fn clip_to_box(a: [f64; 2], b: [f64; 2], bx: [f64; 4]) -> Option<([f64; 2], [f64; 2])> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d[0], a[0] - bx[0]),
        (d[0], bx[2] - a[0]),
        (-d[1], a[1] - bx[1]),
        (d[1], bx[3] - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    let at = |t: f64| [a[0] + t * d[0], a[1] + t * d[1]];
    (t0 <= t1).then(|| (at(t0), at(t1)))
}

#[cfg(test)]
mod tests {
    use super::clip_to_box;

    #[test]
    fn a_segment_is_clipped_to_the_box() {
        let bx = [0.0, 0.0, 2.0, 1.0];
        // Across the box, inside it, and beside it.
        assert_eq!(
            clip_to_box([-1.0, 0.5], [3.0, 0.5], bx),
            Some(([0.0, 0.5], [2.0, 0.5]))
        );
        assert_eq!(
            clip_to_box([0.5, 0.5], [1.0, 0.75], bx),
            Some(([0.5, 0.5], [1.0, 0.75]))
        );
        assert_eq!(clip_to_box([-1.0, 2.0], [3.0, 2.0], bx), None);
        assert_eq!(clip_to_box([-1.0, -1.0], [-0.5, 3.0], bx), None);
        // A diagonal through a corner of the box.
        let (a, b) = clip_to_box([-1.0, -1.0], [3.0, 3.0], bx).unwrap();
        assert_eq!((a, b), ([0.0, 0.0], [1.0, 1.0]));
    }
}
