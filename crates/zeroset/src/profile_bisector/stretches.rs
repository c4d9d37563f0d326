//! Stretches of a curve's domain where a bisector's foot counts, between the certified roots
//! of the polynomials whose signs decide it: between two neighbouring cuts every sign is
//! fixed, so one test at the middle decides the whole window.

use crate::error::Result;
use bspline::roots::{find_roots_in, RootOptions};
use bspline::Piecewise;

/// A span of the domain on which the foot counts and the bisector point is finite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FiniteSpan {
    pub(crate) from: f64,
    pub(crate) to: f64,
}

/// What a root does to the stretches on either side of it, weakest first: where several fall
/// on one value, the strongest (the greatest in this order) holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Cut {
    /// A sign that decides whether the foot counts may change here: stretches on both sides
    /// that count are one.
    Sign,
    /// The other foot jumps here (to the antipode on a circle): the sides stay apart.
    Jump,
    /// The bisector point is at infinity here: the root's whole bracket is out, and the sides
    /// stay apart.
    Pole,
}

/// The cuts of one domain, gathered from the roots of several functions.
#[derive(Debug, Clone)]
pub(crate) struct Cuts {
    list: Vec<(f64, Cut)>,
    /// The brackets of the poles: out, whatever the signs say there.
    poles: Vec<(f64, f64)>,
    opts: RootOptions,
}

impl Cuts {
    /// The cuts of `[a, b]` (its ends among them), roots searched to `opts`.
    pub(crate) fn new(a: f64, b: f64, opts: RootOptions) -> Self {
        Self {
            list: vec![(a, Cut::Sign), (b, Cut::Sign)],
            poles: Vec::new(),
            opts,
        }
    }

    /// Adds an end of a piece (where the functions change; nothing changes sign there).
    pub(crate) fn add_end(&mut self, x: f64) {
        self.list.push((x, Cut::Sign));
    }

    /// Adds the roots of the scalar `f` in `[a, b]`, as cuts of `kind` (a pole's bracket ends
    /// too).
    pub(crate) fn add_roots(&mut self, f: &Piecewise, a: f64, b: f64, kind: Cut) -> Result<()> {
        for root in find_roots_in(f, a, b, &self.opts)? {
            self.list.push((root.u, kind));
            if kind == Cut::Pole {
                self.list.push((root.bracket.0, kind));
                self.list.push((root.bracket.1, kind));
                self.poles.push(root.bracket);
            }
        }
        Ok(())
    }

    /// The maximal stretches where `counts` holds at the middle of a window between cuts;
    /// neighbouring windows join unless a jump or a pole separates them.
    pub(crate) fn stretches(mut self, counts: impl Fn(f64) -> bool) -> Vec<FiniteSpan> {
        // Sorted, one entry per value: the strongest cut there.
        self.list
            .sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        self.list.dedup_by(|later, earlier| {
            let same = later.0 == earlier.0;
            if same {
                earlier.1 = earlier.1.max(later.1);
            }
            same
        });
        let mut out: Vec<FiniteSpan> = Vec::new();
        let mut open = false; // the last window counted and reached the current cut
        for pair in self.list.windows(2) {
            let ((x0, cut0), (x1, _)) = (pair[0], pair[1]);
            let mid = 0.5 * (x0 + x1);
            let keep = !self.poles.iter().any(|&(a, b)| a <= mid && mid <= b) && counts(mid);
            match out.last_mut() {
                Some(last) if keep && open && cut0 == Cut::Sign => last.to = x1,
                _ if keep => out.push(FiniteSpan { from: x0, to: x1 }),
                _ => {}
            }
            open = keep;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use bspline::BSpline;

    fn cubic(coefs: Vec<f64>) -> Piecewise {
        Piecewise::from_bspline(&BSpline::bezier(1, coefs).expect("cubic"))
    }

    /// Windows of one sign join across a root where the sign does not change, and stay apart
    /// across a pole, whose bracket is out.
    #[test]
    fn windows_join_across_signs_and_part_at_poles() {
        // (u − 0.25)(u − 0.75)·const, a Bézier: two simple roots.
        let f = cubic(vec![0.1875, -0.3125, 0.1875]);
        let mut cuts = Cuts::new(0.0, 1.0, RootOptions::default());
        cuts.add_roots(&f, 0.0, 1.0, Cut::Sign).unwrap();
        // Counts everywhere: one stretch, the roots joined over.
        let all = cuts.clone().stretches(|_| true);
        assert_eq!(all, vec![FiniteSpan { from: 0.0, to: 1.0 }]);
        // Counts where f is negative: the middle window.
        let mid = cuts.stretches(|u| (u - 0.25) * (u - 0.75) < 0.0);
        assert_eq!(mid.len(), 1);
        assert!((mid[0].from - 0.25).abs() < 1e-12 && (mid[0].to - 0.75).abs() < 1e-12);
        // As poles: three stretches, each stopping at a bracket.
        let mut poles = Cuts::new(0.0, 1.0, RootOptions::default());
        poles.add_roots(&f, 0.0, 1.0, Cut::Pole).unwrap();
        let parts = poles.stretches(|_| true);
        assert_eq!(parts.len(), 3, "{parts:?}");
        let near = |x: f64, y: f64| (x - y).abs() < 1e-9;
        assert!(parts[0].from == 0.0 && near(parts[0].to, 0.25));
        assert!(near(parts[1].from, 0.25) && near(parts[1].to, 0.75));
        assert!(near(parts[2].from, 0.75) && parts[2].to == 1.0);
    }
}
