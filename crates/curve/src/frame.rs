//! Frames: where a curve is computed on. Coordinates far from the origin or of extreme size
//! cost precision in every product the algorithms form (a curve at 1e8 of size 1 loses eight
//! digits in `C(t) − C(s)`); moved to a local origin and scaled to about unit size, the curve
//! is the same curve and the rounding bounds are those of unit-size data.
//!
//! A [`Frame`] changes coordinates exactly: its origin is chosen so that every difference
//! `x − origin` of the data is a double (Sterbenz: `x − y` is exact when `y/2 ≤ x ≤ 2y`), and
//! its scale is a power of two. Results map back by the inverse change, whose only rounding is
//! that of adding the origin to the reported points.

use numeric::rounding::ulps;

/// An exact change of coordinates `local = (global − origin) · 2^−exponent`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    origin: [f64; 2],
    exponent: i32,
}

/// `2^e` for the exponents of finite doubles.
fn pow2(e: i32) -> f64 {
    if (-1022..=1023).contains(&e) {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        2f64.powi(e)
    }
}

/// `x · 2^e`, in steps that each stay in the normal range of the factor (a subnormal datum
/// scaled up by 2^1030 overflows the factor, not the result), exact unless the result
/// underflows or overflows.
pub(crate) fn times_pow2(x: f64, e: i32) -> f64 {
    let (mut x, mut e) = (x, e);
    // (Three steps cover every exponent a finite double and its scale can have.)
    for _ in 0..3 {
        let step = e.clamp(-1022, 1023);
        x *= pow2(step);
        e -= step;
        if e == 0 {
            break;
        }
    }
    x
}

/// `x − c` is a double (checked by the error term of the two-sum, which is zero exactly then).
pub(crate) fn exact_difference(x: f64, c: f64) -> bool {
    let s = x - c;
    let b = s - x;
    (x - (s - b)) + (-c - b) == 0.0 && s.is_finite()
}

/// An origin for one coordinate of the data: 0 where the data's span reaches the origin's
/// neighbourhood (nothing to gain), else the datum nearest the middle, from which every other
/// one differs exactly (they all lie within a factor two of it).
fn axis_origin(values: &[f64]) -> f64 {
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // (Signs compared, not multiplied: the product of two tiny data underflows to zero.)
    if !(lo.is_finite() && hi.is_finite())
        || lo.abs().min(hi.abs()) < hi - lo
        || lo <= 0.0 && hi >= 0.0
    {
        return 0.0;
    }
    let mid = 0.5 * (lo + hi);
    let c = values
        .iter()
        .copied()
        .min_by(|a, b| (a - mid).abs().total_cmp(&(b - mid).abs()))
        .unwrap_or(0.0);
    if values.iter().all(|&x| exact_difference(x, c)) {
        c
    } else {
        0.0
    }
}

impl Frame {
    /// The identity: the data as they are.
    pub const IDENTITY: Frame = Frame {
        origin: [0.0, 0.0],
        exponent: 0,
    };

    /// The frame for data spanning `points` (a curve's control points, or points bounding it):
    /// the origin per coordinate where the data lie away from the origin by more than their
    /// span, and the power of two nearest their size.
    ///
    /// ```
    /// use curve::Frame;
    /// let pts = [[1e8 + 0.25, 1e8], [1e8 - 0.5, 1e8 + 1.0]];
    /// let f = Frame::for_points(&pts);
    /// let local = f.to_local(pts[0]);
    /// assert_eq!(f.to_global(local), pts[0]);
    /// assert!(local[0].abs() <= 2.0 && local[1].abs() <= 2.0);
    /// ```
    pub fn for_points(points: &[[f64; 2]]) -> Frame {
        if points.is_empty() {
            return Frame::IDENTITY;
        }
        let xs: Vec<f64> = points.iter().map(|p| p[0]).collect();
        let ys: Vec<f64> = points.iter().map(|p| p[1]).collect();
        let origin = [axis_origin(&xs), axis_origin(&ys)];
        let size = points
            .iter()
            .map(|p| (p[0] - origin[0]).abs().max((p[1] - origin[1]).abs()))
            .fold(0.0f64, f64::max);
        Frame {
            origin,
            exponent: exponent_of(size),
        }
    }

    /// The frame that scales by `2^exponent` about `origin` (a caller's choice, for curves
    /// that must share one frame).
    pub fn new(origin: [f64; 2], exponent: i32) -> Frame {
        Frame { origin, exponent }
    }

    /// The frame for several sets of data together (two curves whose common tangents are
    /// sought share one frame).
    pub fn for_all(sets: &[&[[f64; 2]]]) -> Frame {
        let all: Vec<[f64; 2]> = sets.iter().flat_map(|s| s.iter().copied()).collect();
        Frame::for_points(&all)
    }

    /// The local origin, in global coordinates.
    pub fn origin(&self) -> [f64; 2] {
        self.origin
    }

    /// The scale `2^exponent`: one local unit in global units.
    pub fn scale(&self) -> f64 {
        pow2(self.exponent)
    }

    /// The exponent of the scale.
    pub fn exponent(&self) -> i32 {
        self.exponent
    }

    /// A global length in local units (exact but for underflow below the normal range).
    pub fn length_to_local(&self, d: f64) -> f64 {
        times_pow2(d, -self.exponent)
    }

    /// A local length in global units (exact but for overflow and underflow).
    pub fn length_to_global(&self, d: f64) -> f64 {
        times_pow2(d, self.exponent)
    }

    /// A global point in local coordinates, and the bound on the error of that change (zero
    /// where the difference and the scaling are exact, as for the data the frame was chosen
    /// for; otherwise what they rounded).
    pub fn to_local_checked(&self, p: [f64; 2]) -> ([f64; 2], f64) {
        let mut err = 0.0f64;
        let local = [0, 1].map(|k| {
            let d = p[k] - self.origin[k];
            let x = times_pow2(d, -self.exponent);
            if !exact_difference(p[k], self.origin[k]) || times_pow2(x, self.exponent) != d {
                // At most half an ulp of the difference (or of the subnormal result).
                err = err.max(ulps(1.0) * x.abs() + ulps(f64::MIN_POSITIVE));
            }
            x
        });
        (local, err)
    }

    /// A global point in local coordinates.
    pub fn to_local(&self, p: [f64; 2]) -> [f64; 2] {
        self.to_local_checked(p).0
    }

    /// A local point in global coordinates (rounded once, by adding the origin).
    pub fn to_global(&self, p: [f64; 2]) -> [f64; 2] {
        [
            self.origin[0] + times_pow2(p[0], self.exponent),
            self.origin[1] + times_pow2(p[1], self.exponent),
        ]
    }
}

/// The exponent `e` with `2^e ≤ size < 2^(e+1)` (0 for a zero or non-finite size).
pub(crate) fn exponent_of(size: f64) -> i32 {
    if !(size.is_finite() && size > 0.0) {
        return 0;
    }
    let bits = size.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: the exponent of its leading bit.
        let mantissa = bits & ((1u64 << 52) - 1);
        -1022 - (mantissa.leading_zeros() as i32 - 11)
    } else {
        biased - 1023
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Data far from their size from the origin, at any scale (tiny data far away: the
        /// origin moves there too): the local data are of about unit size.
        #[test]
        fn far_data_at_any_scale(
            offset in prop_oneof![1e3f64..1e12, -1e12f64..-1e3],
            k in -1000i32..1000,
            xs in proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 2..20),
        ) {
            let scale = 2f64.powi(k);
            let pts: Vec<[f64; 2]> = xs
                .iter()
                .map(|&(x, y)| [(offset + x) * scale, (y - offset) * scale])
                .collect();
            prop_assume!(pts.iter().flatten().all(|v| v.is_finite() && v.abs() > 1e-290));
            let f = Frame::for_points(&pts);
            // (The data lie a thousand spans and more from the origin.)
            prop_assert!(f.origin()[0] != 0.0 && f.origin()[1] != 0.0, "{:?}", f);
            for &p in &pts {
                let (l, err) = f.to_local_checked(p);
                prop_assert_eq!(err, 0.0, "{:?} in {:?}", p, f);
                prop_assert!(l[0].abs() <= 4.0 && l[1].abs() <= 4.0, "{:?} in {:?}", l, f);
            }
        }

        /// Data far from the origin, of any size: the change is exact both ways, and the
        /// local data are of about unit size.
        #[test]
        fn changes_are_exact(
            offset in prop_oneof![Just(0.0), -1e12f64..1e12, Just(3e15), Just(-7.5e7)],
            log_size in -320.0f64..300.0,
            xs in proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 2..20),
        ) {
            let size = 10f64.powf(log_size);
            let pts: Vec<[f64; 2]> = xs.iter().map(|&(x, y)| [offset + size * x, -offset + size * y]).collect();
            let f = Frame::for_points(&pts);
            for &p in &pts {
                let (l, err) = f.to_local_checked(p);
                prop_assert_eq!(err, 0.0, "{:?} in {:?}", p, f);
                prop_assert_eq!(f.to_global(l), p);
                prop_assert!(l[0].abs() <= 4.0 && l[1].abs() <= 4.0, "{:?}", l);
            }
        }
    }

    /// Scaling by powers of two beyond one factor's range (subnormal data scaled up by
    /// 2^1030, the largest doubles down by 2^-1023 and back) is exact.
    #[test]
    fn far_powers_of_two() {
        for x in [5e-324, 1e-310, 3.3e-308, 1.0, 1.7e308] {
            let e = -exponent_of(x);
            let y = times_pow2(x, e);
            assert!((1.0..2.0).contains(&y), "{x} -> {y}");
            assert_eq!(times_pow2(y, -e), x);
        }
        assert_eq!(times_pow2(1.0, -1074), 5e-324);
        assert_eq!(times_pow2(1.0, 2000), f64::INFINITY);
    }

    #[test]
    fn exponents() {
        assert_eq!(exponent_of(1.0), 0);
        assert_eq!(exponent_of(1.5), 0);
        assert_eq!(exponent_of(0.75), -1);
        assert_eq!(exponent_of(1e-310), -1030);
        assert_eq!(pow2(exponent_of(1e-310)), 2f64.powi(-1030));
        assert_eq!(exponent_of(0.0), 0);
    }
}
