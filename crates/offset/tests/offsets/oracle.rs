//! The independent oracle: a region's boundary as dense chords, for the distance and the
//! inside, and the check that every offset loop closes and lies at its distance.

use crate::common::{ends, samples};
use curve::{ParamCurve, Region};
use offset::Offsets;

/// Chords a query looks at together: one box stands for them all.
pub(crate) const RUN: usize = 32;

/// A region's boundary as chords (lines as they are, every other segment by `per_curve`
/// chords), for the distance and the inside by dense sampling, independent of the code under
/// test. The chords are kept in runs of [`RUN`] with their boxes, and the queries skip the
/// runs whose box is too far to matter: brute force with the same answers, several times
/// quicker.
pub(crate) struct Chords {
    chords: Vec<([f64; 2], [f64; 2])>,
    /// Each run's box (low and high corners).
    boxes: Vec<([f64; 2], [f64; 2])>,
}

impl Chords {
    pub(crate) fn of(region: &Region, per_curve: usize) -> Self {
        let mut chords = Vec::new();
        for b in std::iter::once(region.outer()).chain(region.holes()) {
            for (i, s) in b.segments().iter().enumerate() {
                let n = if s.kind() == curve::SegmentKind::Line {
                    1
                } else {
                    per_curve
                };
                let at = |k: usize| b.jet_to(i as f64 + k as f64 / n as f64, 0).p.arr();
                chords.extend((0..n).map(|k| (at(k), at(k + 1))));
            }
        }
        let boxes = chords
            .chunks(RUN)
            .map(|run| {
                run.iter().fold(
                    ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
                    |(lo, hi), (a, b)| {
                        (
                            [lo[0].min(a[0]).min(b[0]), lo[1].min(a[1]).min(b[1])],
                            [hi[0].max(a[0]).max(b[0]), hi[1].max(a[1]).max(b[1])],
                        )
                    },
                )
            })
            .collect();
        Self { chords, boxes }
    }

    /// The distance from `p` to the boundary: at most that to the nearest run's first point,
    /// so runs whose box is farther cannot hold a nearer chord.
    pub(crate) fn distance(&self, p: [f64; 2]) -> f64 {
        let gap = |q: [f64; 2]| (q[0] - p[0]).hypot(q[1] - p[1]);
        let mut best = self
            .chords
            .iter()
            .step_by(RUN)
            .map(|(a, _)| gap(*a))
            .fold(f64::INFINITY, f64::min);
        for (run, (lo, hi)) in self.chords.chunks(RUN).zip(&self.boxes) {
            let dx = (lo[0] - p[0]).max(p[0] - hi[0]).max(0.0);
            let dy = (lo[1] - p[1]).max(p[1] - hi[1]).max(0.0);
            if dx.hypot(dy) >= best {
                continue;
            }
            for (a, b) in run {
                best = best.min(curve::distance_to_segment(p, *a, *b));
            }
        }
        best
    }

    /// Whether `p` is in the region (even-odd over all its boundaries' chords, counting
    /// crossings of the ray to its right; a run wholly above, below or left of `p` has none).
    pub(crate) fn inside(&self, p: [f64; 2]) -> bool {
        let mut crossings = 0;
        for (run, (lo, hi)) in self.chords.chunks(RUN).zip(&self.boxes) {
            if p[1] < lo[1] || p[1] >= hi[1] || p[0] >= hi[0] {
                continue;
            }
            crossings += run
                .iter()
                .filter(|(a, b)| {
                    (a[1] > p[1]) != (b[1] > p[1])
                        && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
                })
                .count();
        }
        crossings % 2 == 1
    }

    /// The boundary's box (low and high corners).
    pub(crate) fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        self.boxes.iter().fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), (a, b)| {
                (
                    [lo[0].min(a[0]), lo[1].min(a[1])],
                    [hi[0].max(b[0]), hi[1].max(b[1])],
                )
            },
        )
    }
}

/// Every loop closes, every sampled point is at the distance (within `tol`), and the signed
/// area of each loop says which way it runs.
pub(crate) fn check(region: &Region, found: &Offsets, tol: f64) -> Vec<Vec<f64>> {
    check_against(&fine_chords(region), found, tol, 2000)
}

/// The boundary within the sagitta of 4,000 chords a curve: far below any tolerance asked.
pub(crate) fn fine_chords(region: &Region) -> Chords {
    Chords::of(region, 4000)
}

/// [`check`] against `chords`, each loop's area summed over `area_samples` points a piece.
pub(crate) fn check_against(
    chords: &Chords,
    found: &Offsets,
    tol: f64,
    area_samples: usize,
) -> Vec<Vec<f64>> {
    let mut areas = Vec::new();
    for o in &found.offsets {
        let mut per = Vec::new();
        for l in &o.loops {
            assert!(!l.segments.is_empty());
            let mut area = 0.0;
            for (k, s) in l.segments.iter().enumerate() {
                let (_, end) = ends(s);
                let (next, _) = ends(&l.segments[(k + 1) % l.segments.len()]);
                let gap = ((end[0] - next[0]).powi(2) + (end[1] - next[1]).powi(2)).sqrt();
                // (Rounding of the coordinates: relative to their size, far from the origin.)
                assert!(
                    gap < 1e-9 * end[0].abs().max(end[1].abs()).max(1.0),
                    "d = {}: piece {k} ends {gap} from the next",
                    o.distance
                );
                let fine = samples(s, area_samples);
                for w in fine.windows(2) {
                    area += 0.5 * (w[0][0] * w[1][1] - w[1][0] * w[0][1]);
                }
                for p in samples(s, 24) {
                    let dist = chords.distance(p);
                    testkit::assert_near!(
                        dist,
                        o.distance,
                        tol,
                        "d = {}: {p:?} is {dist} from the boundary",
                        o.distance
                    );
                }
            }
            per.push(area);
        }
        areas.push(per);
    }
    areas
}
