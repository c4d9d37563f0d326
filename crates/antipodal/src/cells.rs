//! What Taylor models prove over equal cells of a fine piece of the symbolic forms (the
//! curvature and the rates of the radii of curvature), and the unions of runs of cells, read
//! in constant time: the stretches the bounds of [`crate::bounds`] are asked about end
//! anywhere inside pieces.

use std::sync::OnceLock;

/// What Taylor models prove over the equal cells of a fine piece, at two resolutions:
/// [`COARSE_CELLS`] cells, and [`FINE_CELLS`] ones built on first use, for where the coarse
/// ones prove too little. (Built for every piece a stretch ends in, the fine rates of the radii
/// made the first run on the ellipse a third more costly, most of them never needed.)
#[derive(Debug, Clone)]
pub(crate) struct Cells<T> {
    coarse: RunUnions<T>,
    fine: OnceLock<RunUnions<T>>,
}

impl<T: Union> Cells<T> {
    pub(crate) fn new(coarse: RunUnions<T>) -> Self {
        Self {
            coarse,
            fine: OnceLock::new(),
        }
    }

    /// Over the whole piece.
    pub(crate) fn whole(&self) -> T {
        self.coarse.union(0, COARSE_CELLS - 1)
    }

    /// Over the coarse cells holding fine cells `c0 ..= c1`.
    pub(crate) fn coarse_over(&self, c0: usize, c1: usize) -> T {
        self.coarse.union(c0 / SPLIT, c1 / SPLIT)
    }

    /// Over fine cells `c0 ..= c1` (`build`: all fine cells, on first use).
    pub(crate) fn fine(&self, c0: usize, c1: usize, build: impl FnOnce() -> RunUnions<T>) -> T {
        self.fine.get_or_init(build).union(c0, c1)
    }
}

/// What Taylor models prove over the equal cells of a fine piece, at two resolutions:
/// [`COARSE_CELLS`] cells, and [`SPLIT`] fine ones in each, built on first use. A stretch reads
/// fine cells where it ends inside a coarse one, coarse cells in between. (A whole table of
/// fine cells per piece proves a little more, but building it for every piece a stretch ends
/// in made the first run on a curve up to half as costly again, on the limaçon.)
#[derive(Debug, Clone)]
pub(crate) struct Blocks<T> {
    coarse: RunUnions<T>,
    /// Per coarse cell, its fine cells.
    fine: Vec<OnceLock<Split<T>>>,
}

/// The fine cells of a coarse cell, with the unions of those from its first to each and from
/// each to its last, and of those from the piece's start to each and from each to the piece's
/// end (a stretch that ends in a piece reads what it covers of it at once).
#[derive(Debug, Clone)]
struct Split<T> {
    cells: [T; SPLIT],
    prefix: [T; SPLIT],
    suffix: [T; SPLIT],
    from_start: [T; SPLIT],
    to_end: [T; SPLIT],
}

impl<T: Union> Split<T> {
    /// `before`, `after`: the unions of the coarse cells before and after this one.
    fn new(cells: [T; SPLIT], before: Option<T>, after: Option<T>) -> Self {
        let (mut prefix, mut suffix) = (cells, cells);
        for c in 1..SPLIT {
            prefix[c] = prefix[c - 1].union(cells[c]);
            suffix[SPLIT - 1 - c] = suffix[SPLIT - c].union(cells[SPLIT - 1 - c]);
        }
        let join = |x: T, y: Option<T>| y.map_or(x, |y| x.union(y));
        Self {
            cells,
            prefix,
            suffix,
            from_start: prefix.map(|x| join(x, before)),
            to_end: suffix.map(|x| join(x, after)),
        }
    }
}

/// Coarse cells per fine piece: built with the piece, so the fewer the cheaper the first run
/// on a curve, as long as most stretches are proven on them.
pub(crate) const COARSE_CELLS: usize = 8;

/// Fine cells per coarse cell, built where the coarse ones fail: the rates of the radii and
/// the curvature beside a found pair must be tight enough for the proofs that spare a march
/// (64 fine cells per piece; 32 left a periodic quartic's stretch of nearly constant width
/// unproven).
pub(crate) const SPLIT: usize = 8;

/// Fine cells per fine piece.
pub(crate) const FINE_CELLS: usize = COARSE_CELLS * SPLIT;

/// The span of cell `c` of `n` equal ones of `[a, b]` (the last ends at `b` exactly).
pub(crate) fn cell_span((a, b): (f64, f64), n: usize, c: usize) -> (f64, f64) {
    let w = (b - a) / n as f64;
    let x1 = if c + 1 == n {
        b
    } else {
        a + w * (c + 1) as f64
    };
    (a + w * c as f64, x1)
}

impl<T: Union> Blocks<T> {
    pub(crate) fn new(coarse: &[T]) -> Self {
        Self {
            coarse: RunUnions::new(coarse),
            fine: (0..coarse.len()).map(|_| OnceLock::new()).collect(),
        }
    }

    /// Over the whole piece.
    pub(crate) fn whole(&self) -> T {
        self.coarse.union(0, COARSE_CELLS - 1)
    }

    /// The union of fine cells `c0 ..= c1` (`c0 ≤ c1 < FINE_CELLS`): fine ones in the coarse
    /// cells where the run ends part way, coarse ones elsewhere. `build(k)`: the fine cells
    /// of coarse cell `k`.
    pub(crate) fn union(&self, c0: usize, c1: usize, build: impl Fn(usize) -> [T; SPLIT]) -> T {
        let (k0, k1) = (c0 / SPLIT, c1 / SPLIT);
        let (r0, r1) = (c0 % SPLIT, c1 % SPLIT);
        let last = self.fine.len() - 1;
        let split = |k: usize| {
            self.fine[k].get_or_init(|| {
                let before = (k > 0).then(|| self.coarse.union(0, k - 1));
                let after = (k < last).then(|| self.coarse.union(k + 1, last));
                Split::new(build(k), before, after)
            })
        };
        // Runs from the piece's start or to its end first (the ends of longer stretches).
        if c1 == FINE_CELLS - 1 {
            return match r0 {
                0 => self.coarse.union(k0, last),
                _ => split(k0).to_end[r0],
            };
        }
        if c0 == 0 {
            return match r1 {
                r if r == SPLIT - 1 => self.coarse.union(0, k1),
                _ => split(k1).from_start[r1],
            };
        }
        if k0 == k1 {
            if r0 == 0 && r1 == SPLIT - 1 {
                return self.coarse.union(k0, k0);
            }
            let cells = &split(k0).cells;
            return cells[r0 + 1..=r1]
                .iter()
                .fold(cells[r0], |acc, &x| acc.union(x));
        }
        let head = match r0 {
            0 => self.coarse.union(k0, k0),
            _ => split(k0).suffix[r0],
        };
        let tail = match r1 {
            r if r == SPLIT - 1 => self.coarse.union(k1, k1),
            _ => split(k1).prefix[r1],
        };
        let ends = head.union(tail);
        match k1 - k0 {
            1 => ends,
            _ => ends.union(self.coarse.union(k0 + 1, k1 - 1)),
        }
    }
}

/// The cell of a fine piece spanning `(a, b)` that holds `x` (the first or last for `x`
/// outside). (On values clamped to be non-negative, the conversion's truncation is the floor.)
pub(crate) fn cell_of(x: f64, (a, b): (f64, f64)) -> usize {
    (((x - a) / (b - a) * FINE_CELLS as f64).max(0.0) as usize).min(FINE_CELLS - 1)
}

/// The unions of every run of `2ᵏ` neighbouring cells of a piece (a sparse table): the union
/// of any run `c0 ..= c1` is that of two such runs, read in constant time however many cells
/// it spans.
#[derive(Debug, Clone)]
pub(crate) struct RunUnions<T> {
    /// Level `k` (`len` entries each, the last `2ᵏ − 1` unused): the union of cells
    /// `c .. c + 2ᵏ`.
    levels: Vec<T>,
    len: usize,
}

/// What a cell proves, joined with another cell's: what both together prove.
pub(crate) trait Union: Copy {
    fn union(self, other: Self) -> Self;
}

impl<T: Union> RunUnions<T> {
    pub(crate) fn new(cells: &[T]) -> Self {
        let len = cells.len();
        let mut levels = cells.to_vec();
        let mut width = 1;
        while 2 * width <= len {
            let base = levels.len() - len;
            for c in 0..len {
                let x = match c + width < len {
                    true => levels[base + c].union(levels[base + c + width]),
                    false => levels[base + c],
                };
                levels.push(x);
            }
            width *= 2;
        }
        Self { levels, len }
    }

    /// The union of cells `c0 ..= c1` (`c0 ≤ c1 < len`): that of the two runs of `2ᵏ` cells
    /// starting at `c0` and ending at `c1` (the same run twice where one is enough).
    pub(crate) fn union(&self, c0: usize, c1: usize) -> T {
        let k = (usize::BITS - 1 - (c1 + 1 - c0).leading_zeros()) as usize;
        let base = k * self.len;
        self.levels[base + c0].union(self.levels[base + c1 + 1 - (1 << k)])
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::bounds::KappaCell;
    use numeric::Interval;
    use proptest::prelude::*;

    /// Random cells of one piece: fine ones, and coarse ones holding their fine cells
    /// (widened by random amounts, as coarse Taylor models are), each with a speed.
    fn random_cells(seed: &[(f64, f64, f64)], widen: &[f64]) -> (Vec<KappaCell>, Vec<KappaCell>) {
        let fine: Vec<_> = (0..FINE_CELLS)
            .map(|c| {
                let (a, b, v) = seed[c % seed.len()];
                let shift = c as f64 * 0.01;
                Some((Interval::new(a.min(b) + shift, a.max(b) + shift), v))
            })
            .collect();
        let coarse = fine
            .chunks(SPLIT)
            .zip(widen.iter().cycle())
            .map(|(cells, &w)| {
                let (k, v) = cells[1..].iter().fold(cells[0], |a, &x| a.union(x))?;
                Some((Interval::new(k.lo - w, k.hi + w), v + w))
            })
            .collect();
        (fine, coarse)
    }

    proptest! {
        /// The sparse table's union of any run of cells is the union of its cells, one by one.
        /// The two-level cells' union of a run of fine cells holds the union of those cells,
        /// and lies within the union of the coarse cells that hold them: built lazily, it is
        /// sound and never looser than the coarse cells alone.
        #[test]
        fn unions_of_runs_of_cells(
            seed in proptest::collection::vec((-3.0f64..3.0, -3.0f64..3.0, 0.0f64..5.0), FINE_CELLS),
            widen in proptest::collection::vec(0.0f64..0.1, COARSE_CELLS),
            runs in proptest::collection::vec((0usize..FINE_CELLS, 0usize..FINE_CELLS), 1..40),
        ) {
            let (fine, coarse) = random_cells(&seed, &widen);
            let exact = |c0: usize, c1: usize, cells: &[KappaCell]| {
                cells[c0 + 1..=c1].iter().fold(cells[c0], |a, &x| a.union(x))
            };
            let table = RunUnions::new(&fine);
            let blocks = Blocks::new(&coarse);
            let built = std::cell::Cell::new(0usize);
            for &(x, y) in &runs {
                let (c0, c1) = (x.min(y), x.max(y));
                prop_assert_eq!(table.union(c0, c1), exact(c0, c1, &fine));
                let got = blocks.union(c0, c1, |k| {
                    built.set(built.get() + 1);
                    std::array::from_fn(|c| fine[k * SPLIT + c])
                });
                let ((g, gv), (want, wv)) = (got.unwrap(), exact(c0, c1, &fine).unwrap());
                prop_assert!(g.lo <= want.lo && g.hi >= want.hi && gv >= wv, "{:?} misses {:?}", g, want);
                let (outer, ov) = exact(c0 / SPLIT, c1 / SPLIT, &coarse).unwrap();
                prop_assert!(g.lo >= outer.lo && g.hi <= outer.hi && gv <= ov, "{:?} beyond {:?}", g, outer);
            }
            // Each coarse cell's fine cells are built once at most.
            prop_assert!(built.get() <= COARSE_CELLS);
        }
    }

    /// A cell that proves nothing (`None`) makes every union over it prove nothing.
    #[test]
    fn unions_over_a_cell_without_proof_prove_nothing() {
        let (mut fine, mut coarse) = random_cells(&[(0.0, 1.0, 1.0), (-1.0, 2.0, 3.0)], &[0.5]);
        fine[21] = None;
        coarse[21 / SPLIT] = None;
        let (table, blocks) = (RunUnions::new(&fine), Blocks::new(&coarse));
        let build = |k: usize| std::array::from_fn(|c| fine[k * SPLIT + c]);
        let last = FINE_CELLS - 1;
        for (c0, c1) in [(0, last), (21, 21), (20, 22), (3, 30), (0, 21), (21, last)] {
            assert_eq!(table.union(c0, c1), None, "{c0}..{c1}");
            assert_eq!(blocks.union(c0, c1, build), None, "{c0}..{c1}");
        }
        assert!(blocks.union(22, last, build).is_some());
        assert!(table.union(0, 20).is_some());
    }
}
