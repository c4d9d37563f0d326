//! Whether chains of segments cross, themselves or each other, and how a closed chain
//! winds round a point: decided on [`BezierPiece`]s, by bounds rather than samples. Pairs of
//! stretches whose boxes do not meet are apart; neighbours whose tangent cones lie together
//! within a half-turn meet only at their common end; a stretch whose cone does cannot meet
//! itself. What those leave open is halved until each stretch of a pair lies within
//! [`FLATNESS`] of the chains' size of its chord, and the chords are tested. Two stretches
//! that come closer than the flatness without crossing may be judged either way; anything
//! farther apart is judged right.

use crate::bezier_piece::{pieces_of, BezierPiece};
use crate::geom::V2;
use crate::segment::Segment;
use numeric::rounding::ulps;
use numeric::subdivide::{depth_first, Decision};

/// How far (relative to the chains' size) a stretch tested by its chord may stray from it.
pub(crate) const FLATNESS: f64 = 1e-7;

/// Units of rounding of the largest coordinate below which the flatness is noise: far from
/// the origin a curve's points are known only to a few units of rounding of their
/// coordinates, and finer stretches never get flatter.
const FLAT_ROUNDING: f64 = ulps(64.0);

/// Halvings of a Bézier piece before it is taken as flat: a part 2^-24 of a piece.
const MAX_CROSSING_DEPTH: usize = 24;

/// Pairs and stretches looked at in one test, per Bézier piece of the chains and beyond
/// them: a bound on the work and the memory whatever the curves (two copies of one curve
/// meet all along their length). A test that reaches it is left undecided.
const TESTS_PER_PIECE: usize = 64;
const MORE_TESTS: usize = 1 << 18;

/// Units of rounding of the largest coordinate within which a stretch's way back is on its
/// way there (a retrace): the halvings' rounding of points on one line.
const RETRACE_ROUNDING: f64 = ulps(256.0);

/// A test that did not finish within its bound on the work.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Undecided {
    pub(crate) tests: usize,
}

impl From<Undecided> for crate::error::Error {
    fn from(u: Undecided) -> Self {
        crate::error::Error::Undecided { tests: u.tests }
    }
}

/// A crossing: the two segments (of chains `chains`, the same for a chain crossing itself)
/// and a point where they meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Crossing {
    pub(crate) chains: (usize, usize),
    pub(crate) first: usize,
    pub(crate) second: usize,
    pub(crate) at: [f64; 2],
}

/// A chain to test: its segments and whether its last segment joins its first.
pub(crate) type Chain<'a> = (&'a [Segment], bool);

/// The first crossing of a chain with itself (`closed`: its last segment joins its first),
/// for a chain of `size`.
pub(crate) fn first_crossing(
    segments: &[Segment],
    closed: bool,
    size: f64,
) -> Result<Option<Crossing>, Undecided> {
    first_crossing_among(&[(segments, closed)], false, size)
}

/// What is left to look at.
enum Task {
    /// Whether a stretch meets itself.
    Itself(usize),
    /// Whether two stretches meet (other than at a common end of neighbours).
    Pair(usize, usize),
}

/// The first crossing among chains of `size` (first by chain, then by segment): of one with
/// itself or of two with each other, or only the latter (`apart`: each chain is known
/// simple).
pub(crate) fn first_crossing_among(
    chains: &[Chain<'_>],
    apart: bool,
    size: f64,
) -> Result<Option<Crossing>, Undecided> {
    let (delta, magnitude) = flatness(chains.iter().flat_map(|c| c.0.iter()), size);
    let rounding = RETRACE_ROUNDING * magnitude;
    let mut stretches: Vec<BezierPiece> = chains
        .iter()
        .enumerate()
        .flat_map(|(c, &(segments, _))| pieces_of(c, segments))
        .collect();
    let bound = MORE_TESTS + TESTS_PER_PIECE * stretches.len();
    let mut tasks: Vec<Task> = Vec::new();
    if !apart {
        tasks.extend((0..stretches.len()).map(Task::Itself));
    }
    for (i, j) in boxes_meeting(&stretches, bound)? {
        if !(apart && stretches[i].chain == stretches[j].chain) {
            tasks.push(Task::Pair(i, j));
        }
    }
    let neighbours = |a: &BezierPiece, b: &BezierPiece| {
        let (segments, closed) = chains[a.chain];
        let n = segments.len() as f64;
        a.chain == b.chain
            && (a.hi == b.lo
                || b.hi == a.lo
                || (closed && ((a.lo == 0.0 && b.hi == n) || (b.lo == 0.0 && a.hi == n))))
    };
    let mut found: Option<Crossing> = None;
    let mut tests = 0;
    while let Some(task) = tasks.pop() {
        tests += 1;
        if tests > bound {
            return Err(Undecided { tests: bound });
        }
        let settled = |s: &BezierPiece| s.depth >= MAX_CROSSING_DEPTH || s.is_flat(delta);
        let mut record = |a: &BezierPiece, b: &BezierPiece, at: V2| {
            let (x, y) = if (a.chain, a.segment) <= (b.chain, b.segment) {
                (a, b)
            } else {
                (b, a)
            };
            let c = Crossing {
                chains: (x.chain, y.chain),
                first: x.segment,
                second: y.segment,
                at: at.arr(),
            };
            let key = |c: &Crossing| (c.chains, c.first, c.second);
            if found.is_none_or(|f| key(&c) < key(&f)) {
                found = Some(c);
            }
        };
        match task {
            Task::Itself(i) => {
                let s = &stretches[i];
                if s.cone().is_some() {
                    continue;
                }
                // (Flat, it may still go back along its chord: a retrace.)
                if settled(s) {
                    if let Some(at) = s.retrace(delta, rounding) {
                        record(s, s, at);
                    }
                    continue;
                }
                let [h0, h1] = s.halves();
                let k = stretches.len();
                stretches.extend([h0, h1]);
                tasks.extend([Task::Pair(k, k + 1), Task::Itself(k), Task::Itself(k + 1)]);
            }
            Task::Pair(i, j) => {
                let (a, b) = (&stretches[i], &stretches[j]);
                if !a.boxes_meet(b) {
                    continue;
                }
                let touching = neighbours(a, b);
                if touching {
                    if let (Some(ca), Some(cb)) = (a.cone(), b.cone()) {
                        if ca.joins(cb) {
                            continue;
                        }
                    }
                }
                let (split_a, split_b) = (!settled(a), !settled(b));
                if !split_a && !split_b {
                    // (Neighbours' chords share an end: they meet only if one runs back
                    // along the other.)
                    if touching {
                        if let Some(at) = a.retraced_by(b, delta, rounding) {
                            record(a, b, at);
                        }
                        continue;
                    }
                    if let Some(at) = meet(a.start, a.end, b.start, b.end) {
                        record(a, b, at);
                    }
                    continue;
                }
                // (The coarser of the two is halved.)
                let halve_a = split_a && (!split_b || a.extent() >= b.extent());
                let (halved, other) = if halve_a { (i, j) } else { (j, i) };
                let [h0, h1] = stretches[halved].halves();
                let k = stretches.len();
                stretches.extend([h0, h1]);
                tasks.extend([Task::Pair(k + 1, other), Task::Pair(k, other)]);
            }
        }
    }
    Ok(found)
}

/// The pairs of stretches whose boxes meet, by a sweep along x (a stretch without a box
/// pairs with every other); undecided beyond `bound` pairs.
fn boxes_meeting(
    stretches: &[BezierPiece],
    bound: usize,
) -> Result<Vec<(usize, usize)>, Undecided> {
    let mut pairs = Vec::new();
    let (mut boxed, mut unboxed): (Vec<(f64, usize)>, Vec<usize>) = (Vec::new(), Vec::new());
    for (i, s) in stretches.iter().enumerate() {
        match s.bounds {
            Some([lo, _]) => boxed.push((lo.x, i)),
            None => unboxed.push(i),
        }
    }
    for &u in &unboxed {
        pairs.extend(
            (0..stretches.len())
                .filter(|&j| j != u && (j > u || stretches[j].bounds.is_some()))
                .map(|j| (u.min(j), u.max(j))),
        );
    }
    boxed.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let hi_x = |i: usize| stretches[i].bounds.map_or(f64::INFINITY, |[_, hi]| hi.x);
    let mut active: Vec<usize> = Vec::new();
    for &(lo_x, i) in &boxed {
        active.retain(|&j| hi_x(j) >= lo_x);
        for &j in &active {
            if stretches[i].boxes_meet(&stretches[j]) {
                pairs.push((j.min(i), j.max(i)));
            }
        }
        if pairs.len() > bound {
            return Err(Undecided { tests: bound });
        }
        active.push(i);
    }
    Ok(pairs)
}

/// A closed chain's pieces and flatness, made once for the tests of which points it winds
/// round (a region asks each boundary about every other's start).
pub(crate) struct Outline {
    pieces: Vec<BezierPiece>,
    delta: f64,
}

impl Outline {
    /// The outline of the closed chain `segments`, of `size`.
    pub(crate) fn new(segments: &[Segment], size: f64) -> Self {
        Self {
            pieces: pieces_of(0, segments),
            delta: flatness(segments.iter(), size).0,
        }
    }

    /// Whether it winds round `p`: the winding number of the polygon through its
    /// stretches' ends, each stretch whose box holds `p` halved until it does not or lies
    /// within the flatness of its chord (the curve and the polygon then bound no region
    /// holding `p`, unless `p` is within the flatness of the chain).
    pub(crate) fn winds_round(&self, p: V2) -> Result<bool, Undecided> {
        let mut polygon = Vec::new();
        let bound = MORE_TESTS + TESTS_PER_PIECE * self.pieces.len();
        let mut tests = 0;
        // (The pieces in order, each searched before the next: the polygon runs along them.)
        for piece in &self.pieces {
            let undecided = depth_first(piece.clone(), MAX_CROSSING_DEPTH, |s, visit| {
                tests += 1;
                if tests > bound {
                    return Decision::Stop(Undecided { tests: bound });
                }
                if polygon.is_empty() {
                    polygon.push(s.start);
                }
                let settled = !visit.can_halve || s.is_flat(self.delta);
                if s.box_holds(p) && !settled {
                    let [h0, h1] = s.halves();
                    Decision::Halve(h0, h1)
                } else {
                    polygon.push(s.end);
                    Decision::Decided
                }
            });
            if let Some(undecided) = undecided {
                return Err(undecided);
            }
        }
        Ok(winding(&polygon, p) != 0)
    }
}

/// The winding number of `polygon` (closed, last point joined to the first) about `p`.
fn winding(polygon: &[V2], p: V2) -> i32 {
    let n = polygon.len();
    let mut w = 0;
    for k in 0..n {
        let (a, b) = (polygon[k], polygon[(k + 1) % n]);
        let side = (b - a).cross(p - a);
        if a.y <= p.y {
            if b.y > p.y && side > 0.0 {
                w += 1;
            }
        } else if b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

/// The flatness for segments of `size` ([`FLATNESS`] of it, but never below what the
/// coordinates' rounding resolves), and their largest coordinate.
fn flatness<'s>(segments: impl Iterator<Item = &'s Segment>, size: f64) -> (f64, f64) {
    let magnitude = segments
        .flat_map(|s| s.curve().control_points())
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    ((FLATNESS * size).max(FLAT_ROUNDING * magnitude), magnitude)
}

/// Where edges `ab` and `cd` meet, when they do (touching or overlapping included).
fn meet(a: V2, b: V2, c: V2, d: V2) -> Option<V2> {
    let (lo1, hi1) = (
        V2::new(a.x.min(b.x), a.y.min(b.y)),
        V2::new(a.x.max(b.x), a.y.max(b.y)),
    );
    let (lo2, hi2) = (
        V2::new(c.x.min(d.x), c.y.min(d.y)),
        V2::new(c.x.max(d.x), c.y.max(d.y)),
    );
    if hi1.x < lo2.x || hi2.x < lo1.x || hi1.y < lo2.y || hi2.y < lo1.y {
        return None;
    }
    let side = |p: V2, q: V2, r: V2| (q - p).cross(r - p);
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        let t = d1 / (d1 - d2);
        return Some(a + (b - a) * t);
    }
    // Touching or collinear: an end on the other edge.
    let on = |p: V2, q: V2, r: V2| {
        side(p, q, r) == 0.0
            && r.x >= p.x.min(q.x)
            && r.x <= p.x.max(q.x)
            && r.y >= p.y.min(q.y)
            && r.y <= p.y.max(q.y)
    };
    [(c, d, a), (c, d, b), (a, b, c), (a, b, d)]
        .into_iter()
        .find(|&(p, q, r)| on(p, q, r))
        .map(|(_, _, r)| r)
}

#[cfg(test)]
mod tests;
