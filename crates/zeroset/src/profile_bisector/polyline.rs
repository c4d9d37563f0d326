//! Polylines of a plane curve given point by point, `x(r)` (`None` where it is at infinity
//! or out of reach): vertices placed so that the polyline keeps within a chord tolerance of
//! the curve, measured between the vertices, and runs cut where the curve leaves its reach.

/// One polyline: parameter and point per vertex.
pub(crate) type Run = Vec<(f64, [f64; 2])>;

/// Samples of the first, even grid (each then refined as the chord tolerance asks).
const INITIAL: usize = 16;

/// Refinement depth at most (each level splits a span in three: 3^-30 of the grid's step is
/// below the parameter's rounding).
const MAX_POLYLINE_DEPTH: usize = 30;

/// Vertices at most per call: the work stays bounded whatever the curve.
const MAX_VERTICES: usize = 1 << 20;

/// Halvings that locate where the curve leaves its reach (from a grid step down to rounding).
const EDGE_STEPS: usize = 60;

/// A span is fine when the curve at its thirds is within this share of the chord tolerance
/// of the chord: a curve that is locally a parabola deviates most at the middle, and at the
/// thirds by 8/9 of that.
const AT_THIRDS: f64 = 8.0 / 9.0;

/// Depth to which a span with both ends out of reach is probed for a stretch within reach.
const PROBE_DEPTH: usize = 4;

/// The polylines of `x` on `[a, b]` within `chord` of the curve, and whether every span met
/// the tolerance within the limits.
pub(crate) fn sample_runs(
    x: &dyn Fn(f64) -> Option<[f64; 2]>,
    a: f64,
    b: f64,
    chord: f64,
) -> (Vec<Run>, bool) {
    let mut s = Sampler {
        x,
        chord,
        out: Vec::new(),
        complete: true,
    };
    let at = |k: usize| {
        if k == INITIAL {
            b
        } else {
            a + (b - a) * k as f64 / INITIAL as f64
        }
    };
    let mut prev = (a, x(a));
    s.push(prev);
    for k in 1..=INITIAL {
        let r = at(k);
        let cur = (r, x(r));
        s.span(prev, cur, 0);
        s.push(cur);
        prev = cur;
    }
    let mut runs = Vec::new();
    let mut run: Run = Vec::new();
    for v in s.out {
        match v {
            Some(p) => {
                if run.last().is_none_or(|q| q.0 < p.0) {
                    run.push(p);
                }
            }
            None => {
                if run.len() >= 2 {
                    runs.push(std::mem::take(&mut run));
                }
                run.clear();
            }
        }
    }
    if run.len() >= 2 {
        runs.push(run);
    }
    (runs, s.complete)
}

type Sample = (f64, Option<[f64; 2]>);

struct Sampler<'a> {
    x: &'a dyn Fn(f64) -> Option<[f64; 2]>,
    chord: f64,
    /// Vertices in order, `None` where a run breaks.
    out: Vec<Option<(f64, [f64; 2])>>,
    complete: bool,
}

impl Sampler<'_> {
    fn push(&mut self, s: Sample) {
        self.out.push(s.1.map(|p| (s.0, p)));
    }

    /// The vertices strictly between `a` and `b` (both already placed or to be placed).
    fn span(&mut self, a: Sample, b: Sample, depth: usize) {
        if self.out.len() >= MAX_VERTICES {
            self.complete = false;
            return;
        }
        match (a.1, b.1) {
            (Some(pa), Some(pb)) => {
                let third = (b.0 - a.0) / 3.0;
                let (r1, r2) = (a.0 + third, b.0 - third);
                if !(a.0 < r1 && r1 < r2 && r2 < b.0) {
                    return; // parameters exhausted: the curve jumps here
                }
                let (s1, s2) = ((r1, (self.x)(r1)), (r2, (self.x)(r2)));
                let off = |s: &Sample| {
                    s.1.is_none_or(|p| off_chord(p, pa, pb) > AT_THIRDS * self.chord)
                };
                if !off(&s1) && !off(&s2) {
                    return;
                }
                if depth >= MAX_POLYLINE_DEPTH {
                    self.complete = false;
                    return;
                }
                self.span(a, s1, depth + 1);
                self.push(s1);
                self.span(s1, s2, depth + 1);
                self.push(s2);
                self.span(s2, b, depth + 1);
            }
            // The run ends between: the edge of reach found, and the stretch up to it
            // refined as any other.
            (Some(_), None) => {
                let last = self.edge(a.0, b.0);
                if last.0 != a.0 {
                    self.span(a, last, depth + 1);
                    self.push(last);
                }
            }
            (None, Some(_)) => {
                let first = self.edge(b.0, a.0);
                self.push((a.0, None));
                if first.0 != b.0 {
                    self.push(first);
                    self.span(first, b, depth + 1);
                }
            }
            (None, None) => {
                if depth < PROBE_DEPTH {
                    let m = 0.5 * (a.0 + b.0);
                    let sm = (m, (self.x)(m));
                    if sm.1.is_some() {
                        self.span(a, sm, depth + 1);
                        self.push(sm);
                        self.span(sm, b, depth + 1);
                    }
                }
            }
        }
    }

    /// The sample nearest `outside` that is within reach, from `inside` (within reach).
    fn edge(&self, mut inside: f64, mut outside: f64) -> Sample {
        let mut best = (inside, (self.x)(inside));
        for _ in 0..EDGE_STEPS {
            let m = 0.5 * (inside + outside);
            if m == inside || m == outside {
                break;
            }
            match (self.x)(m) {
                Some(p) => {
                    inside = m;
                    best = (m, Some(p));
                }
                None => outside = m,
            }
        }
        best
    }
}

/// The distance from `p` to the segment `a b`.
pub(crate) fn off_chord(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let v = [p[0] - a[0], p[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let s = if len2 > 0.0 {
        ((v[0] * d[0] + v[1] * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (v[0] - s * d[0]).hypot(v[1] - s * d[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A circle arc sampled to a chord tolerance: every sampled polyline stays within the
    /// tolerance of the circle (checked densely between the vertices), and no finer than
    /// needed by more than the split factor.
    #[test]
    fn an_arc_is_sampled_within_its_chord_tolerance() {
        for chord in [1e-2, 1e-4, 1e-7] {
            let x = |r: f64| Some([r.cos(), r.sin()]);
            let (runs, complete) = sample_runs(&x, 0.0, 3.0, chord);
            assert!(complete && runs.len() == 1);
            let run = &runs[0];
            for w in run.windows(2) {
                // The sagitta of the chord between two vertices of the unit circle.
                let h = 1.0 - (0.5 * (w[1].0 - w[0].0)).cos();
                assert!(h <= chord * (1.0 + 1e-6), "{chord}: sagitta {h}");
            }
            // Thirds of a span whose sagitta met the tolerance would be ~9 times under it.
            let finest = run
                .windows(2)
                .map(|w| 1.0 - (0.5 * (w[1].0 - w[0].0)).cos())
                .fold(f64::INFINITY, f64::min);
            assert!(finest > chord / 100.0, "{chord}: {finest}");
        }
    }

    /// A curve that runs off to infinity at a pole is cut where it leaves its reach, on both
    /// sides, to the parameter's rounding.
    #[test]
    fn a_pole_cuts_the_runs_at_the_edge_of_reach() {
        let far = 100.0;
        let x = |r: f64| {
            let y = 1.0 / (r - 0.3);
            (y.abs() <= far).then_some([r, y])
        };
        let (runs, _) = sample_runs(&x, 0.0, 1.0, 1e-6);
        assert_eq!(runs.len(), 2);
        let end = runs[0].last().unwrap().1;
        let start = runs[1][0].1;
        testkit::assert_near!(end[1].abs(), far, 1e-6 * far, "{end:?}");
        testkit::assert_near!(start[1].abs(), far, 1e-6 * far, "{start:?}");
    }
}
