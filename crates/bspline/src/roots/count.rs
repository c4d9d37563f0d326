//! The one certified root counter: what the signs of a function's control polygon over an
//! interval prove about its roots there.
//!
//! The polygon is read piece by piece (the Bernstein coefficients of consecutive pieces, as the
//! B-spline with every break of full multiplicity), each coefficient with the bound on its error.
//! A coefficient beyond its bound has a trusted sign; one within it may have either sign (or be
//! zero). By the variation-diminishing property the function has at most as many roots in the
//! interval as the polygon has sign changes, and as many modulo two; so the *greatest* number of
//! sign changes any polygon within the bounds can have settles it:
//!
//! - 0 (every coefficient trusted, of one sign): no root;
//! - 1 with both ends trusted (so of opposite signs): exactly one root, and it is simple;
//! - 1 with one end untrusted and the rest of one sign: no root inside, but the value at that
//!   end is within rounding of zero ([`Count::AtEnd`]);
//! - anything else: open (subdivide, or decide otherwise).
//!
//! At a break where the function is continuous the two pieces' end coefficients are the same
//! exact value, counted once; across a jump the signs on both sides must agree (a sign change
//! there is no root), or the count is open.

/// What the control polygon of a function over an interval proves about its roots there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Count {
    /// No root in the interval.
    Zero,
    /// Exactly one root, simple, inside `[a, b]` (the pieces around the one sign change).
    One(f64, f64),
    /// No root inside; the value at this end of the interval is within rounding of zero (at
    /// most one root, at that end up to rounding).
    AtEnd(f64),
    /// The signs do not decide.
    Open,
}

/// A sentinel for "no polygon ends with this sign".
const NONE: i64 = i64::MIN / 2;

/// The counter, fed the pieces of the polygon in order ([`SignCount::piece`]) and read once at
/// the end ([`SignCount::finish`]).
#[derive(Debug, Clone)]
pub struct SignCount {
    lo: f64,
    hi: f64,
    state: State,
    /// The state before the previous piece's last coefficient (a joint counted untrusted there
    /// and trusted in the next piece is counted again from it).
    before_end: State,
    /// The previous piece's last coefficient and its bound (for the joint).
    prev_end: Option<(f64, f64)>,
    open: bool,
}

/// What the coefficients fed so far leave.
#[derive(Debug, Clone, Copy)]
struct State {
    /// The most sign changes of a polygon within the bounds ending positive / negative.
    pos: i64,
    neg: i64,
    /// Sign of the last trusted coefficient (`true`: negative) and the start of its piece.
    last: Option<(bool, f64)>,
    /// Sign changes between trusted coefficients, and where the first one happened.
    changes: usize,
    bracket: (f64, f64),
    /// Untrusted coefficients before the first trusted one, and since the last trusted one.
    lead: usize,
    trail: usize,
    /// The sign of the first trusted coefficient (`true`: negative).
    first_negative: bool,
}

impl SignCount {
    /// A counter for the interval `[lo, hi]`.
    pub fn new(lo: f64, hi: f64) -> Self {
        let state = State {
            pos: NONE,
            neg: NONE,
            last: None,
            changes: 0,
            bracket: (lo, hi),
            lead: 0,
            trail: 0,
            first_negative: false,
        };
        Self {
            lo,
            hi,
            state,
            before_end: state,
            prev_end: None,
            open: false,
        }
    }

    /// True once the count is known to be open (feeding more pieces cannot change that).
    pub fn is_open(&self) -> bool {
        self.open
    }

    /// Feeds the coefficients `c` of the piece on `[a, b]`, each within `err` of the exact
    /// ones; `joint` is the order of continuity at `a` (ignored for the first piece; negative:
    /// the function may jump there). Returns false once the count is open.
    pub fn piece(&mut self, a: f64, b: f64, c: &[f64], err: f64, joint: i32) -> bool {
        if self.open || c.is_empty() {
            return !self.open;
        }
        let mut skip_first = false;
        if let Some((prev, perr)) = self.prev_end {
            let trusted = |x: f64, e: f64| (x.abs() > e).then_some(x < 0.0);
            match (trusted(prev, perr), trusted(c[0], err)) {
                // A continuous function: the same exact value twice, counted once, with the
                // sign either copy proves; two copies that disagree prove nothing.
                (Some(x), Some(y)) if x != y => self.open = true,
                (None, Some(_)) if joint >= 0 => self.state = self.before_end,
                _ if joint >= 0 => skip_first = true,
                // A jump: no root hides in it only when both sides show one sign.
                (Some(x), Some(y)) if x == y => skip_first = true,
                _ => self.open = true,
            }
            if self.open {
                return false;
            }
        }
        let last = c.len() - 1;
        for (i, &x) in c.iter().enumerate() {
            if i == 0 && skip_first {
                continue;
            }
            if i == last {
                self.before_end = self.state;
            }
            self.state.push(x, err, a, b);
        }
        self.prev_end = Some((c[last], err));
        true
    }

    /// True when the first trusted coefficient is negative (with [`Count::One`]: the function
    /// rises through its root).
    pub fn starts_negative(&self) -> bool {
        self.state.first_negative
    }

    /// What the polygon fed so far proves.
    pub fn finish(&self) -> Count {
        let s = &self.state;
        if self.open || s.last.is_none() {
            return Count::Open;
        }
        match (s.pos.max(s.neg).max(0), s.changes, s.lead, s.trail) {
            (0, 0, 0, 0) => Count::Zero,
            (1, 1, 0, 0) => Count::One(s.bracket.0, s.bracket.1),
            (1, 0, 1, 0) => Count::AtEnd(self.lo),
            (1, 0, 0, 1) => Count::AtEnd(self.hi),
            _ => Count::Open,
        }
    }
}

impl State {
    /// One coefficient `x` (within `err` of the exact one) of the piece on `[a, b]`.
    fn push(&mut self, x: f64, err: f64, a: f64, b: f64) {
        // (Zero is either sign: with no error, a zero coefficient is still untrusted.)
        let (can_pos, can_neg) = (x >= -err, x <= err);
        let start = if self.pos == NONE && self.neg == NONE {
            0
        } else {
            NONE
        };
        let np = if can_pos {
            self.pos.max(self.neg + 1).max(start)
        } else {
            NONE
        };
        let nn = if can_neg {
            self.neg.max(self.pos + 1).max(start)
        } else {
            NONE
        };
        (self.pos, self.neg) = (np, nn);
        if x.abs() <= err {
            if self.last.is_none() {
                self.lead += 1;
            } else {
                self.trail += 1;
            }
            return;
        }
        self.trail = 0;
        let sign = x < 0.0;
        if self.last.is_none() {
            self.first_negative = sign;
        }
        if let Some((s0, start)) = self.last {
            if s0 != sign {
                self.changes += 1;
                if self.changes == 1 {
                    self.bracket = (start, b);
                }
            }
        }
        self.last = Some((sign, a));
    }
}

/// The largest number of sign changes the coefficient sequence `c` can have when each
/// coefficient within `err` of zero may take either sign.
pub fn most_sign_changes(c: &[f64], err: f64) -> usize {
    let mut count = SignCount::new(0.0, 1.0);
    count.piece(0.0, 1.0, c, err, 0);
    count.state.pos.max(count.state.neg).max(0) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    fn count(pieces: &[(&[f64], f64)]) -> Count {
        let mut c = SignCount::new(0.0, pieces.len() as f64);
        for (i, (coefs, err)) in pieces.iter().enumerate() {
            c.piece(i as f64, i as f64 + 1.0, coefs, *err, 0);
        }
        c.finish()
    }

    #[test]
    fn decisions_of_small_polygons() {
        assert_eq!(count(&[(&[1.0, 2.0, 0.5], 0.1)]), Count::Zero);
        assert_eq!(count(&[(&[1.0, -2.0, -0.5], 0.1)]), Count::One(0.0, 1.0));
        assert_eq!(count(&[(&[0.05, 2.0, 0.5], 0.1)]), Count::AtEnd(0.0));
        assert_eq!(count(&[(&[1.0, 2.0, -0.05], 0.1)]), Count::AtEnd(1.0));
        // Two changes, or an untrusted coefficient between equal signs: open.
        assert_eq!(count(&[(&[1.0, -2.0, 0.5], 0.1)]), Count::Open);
        assert_eq!(count(&[(&[1.0, 0.05, 0.5], 0.1)]), Count::Open);
        // One untrusted between opposite signs: still exactly one; two: up to three.
        assert_eq!(count(&[(&[1.0, 0.05, -0.5], 0.1)]), Count::One(0.0, 1.0));
        assert_eq!(count(&[(&[1.0, 0.05, -0.05, -0.5], 0.1)]), Count::Open);
    }

    #[test]
    fn joints_count_once_and_jumps_need_one_sign() {
        // A root exactly at the break: the joint value untrusted in both copies.
        assert_eq!(
            count(&[(&[1.0, 0.5, 0.0], 0.1), (&[0.0, -0.5, -1.0], 0.1)]),
            Count::One(0.0, 2.0)
        );
        let mut c = SignCount::new(0.0, 2.0);
        c.piece(0.0, 1.0, &[1.0, 0.5], 0.1, 0);
        c.piece(1.0, 2.0, &[-0.5, -1.0], 0.1, -1);
        assert_eq!(c.finish(), Count::Open);
        let mut c = SignCount::new(0.0, 2.0);
        c.piece(0.0, 1.0, &[1.0, 0.5], 0.1, 0);
        c.piece(1.0, 2.0, &[2.0, 1.0], 0.1, -1);
        assert_eq!(c.finish(), Count::Zero);
    }
}
