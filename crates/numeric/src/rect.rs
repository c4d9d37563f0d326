//! Closed rectangles of a parameter plane: the cells, domains and hulls of the bivariate
//! searches, one layout for all.

use crate::Interval;

/// A closed rectangle `t × r` of a parameter plane (`t` across, `r` up: the order the
/// bivariate functions of `zeroset` take their parameters).
///
/// ```
/// use numeric::{Interval, Rect};
/// let cell = Rect::of((0.0, 2.0), (1.0, 2.0));
/// assert_eq!(cell.widths(), [2.0, 1.0]);
/// assert_eq!(cell.mid(), [1.0, 1.5]);
/// assert!(cell.contains([2.0, 1.0]) && !cell.contains([2.5, 1.0]));
/// assert!(cell.on_boundary([0.5, 2.0]) && !cell.on_boundary([0.5, 1.5]));
/// let grown = cell.grown([0.5, 0.0]);
/// assert_eq!((grown.t, grown.r), (Interval::new(-0.5, 2.5), Interval::new(1.0, 2.0)));
/// assert!(cell.overlaps(&Rect::of((2.0, 3.0), (0.0, 1.0))));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// The range across.
    pub t: Interval,
    /// The range up.
    pub r: Interval,
}

impl Rect {
    /// The rectangle `t × r`.
    pub fn new(t: Interval, r: Interval) -> Self {
        Self { t, r }
    }

    /// The rectangle `[t0, t1] × [r0, r1]`.
    pub fn of((t0, t1): (f64, f64), (r0, r1): (f64, f64)) -> Self {
        Self::new(Interval::new(t0, t1), Interval::new(r0, r1))
    }

    /// The widths across and up.
    pub fn widths(&self) -> [f64; 2] {
        [self.t.width(), self.r.width()]
    }

    /// The midpoint.
    pub fn mid(&self) -> [f64; 2] {
        [self.t.mid(), self.r.mid()]
    }

    /// Grown by `dt` across and `dr` up on every side.
    pub fn grown(&self, [dt, dr]: [f64; 2]) -> Self {
        Self::of(
            (self.t.lo - dt, self.t.hi + dt),
            (self.r.lo - dr, self.r.hi + dr),
        )
    }

    /// The least rectangle holding both.
    pub fn hull(&self, o: &Rect) -> Self {
        Self::new(self.t.hull(o.t), self.r.hull(o.r))
    }

    /// Whether the two closed rectangles meet (touching counts).
    pub fn overlaps(&self, o: &Rect) -> bool {
        o.t.lo <= self.t.hi && self.t.lo <= o.t.hi && o.r.lo <= self.r.hi && self.r.lo <= o.r.hi
    }

    /// Whether the closed rectangle holds `q`.
    pub fn contains(&self, q: [f64; 2]) -> bool {
        q[0] >= self.t.lo && q[0] <= self.t.hi && q[1] >= self.r.lo && q[1] <= self.r.hi
    }

    /// Whether `q` lies exactly on the line of one of the edges (a point a search placed on
    /// the boundary, compared bit for bit).
    pub fn on_boundary(&self, q: [f64; 2]) -> bool {
        q[0] == self.t.lo || q[0] == self.t.hi || q[1] == self.r.lo || q[1] == self.r.hi
    }
}
