//! Exact rational arithmetic for the oracles: every `f64` is a rational number, and the
//! Bernstein and B-spline operations below are carried out on them without rounding.
#![allow(dead_code)]

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// An exact rational.
pub type Q = BigRational;

/// The exact value of a finite double.
pub fn q(x: f64) -> Q {
    BigRational::from_float(x).expect("finite")
}

/// The nearest double (for messages).
pub fn f(x: &Q) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

/// `|a − b|` as a double rounded up (an exact comparison with a bound follows by `le`).
pub fn exceeds(a: &Q, b: f64, bound: f64) -> bool {
    (a - q(b)).abs() > q(bound)
}

fn binomial(n: usize, k: usize) -> Q {
    let mut r = BigInt::one();
    for i in 0..k {
        r = r * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    Q::from_integer(r)
}

/// Exact Bernstein coefficients (one coordinate) as rationals.
pub fn exact(c: &[f64]) -> Vec<Q> {
    c.iter().map(|&x| q(x)).collect()
}

/// The product of two Bernstein polynomials (one coordinate each) on one interval: in the
/// scaled basis (coefficient `k` times `C(n, k)`) a product is a plain convolution.
pub fn product(a: &[Q], b: &[Q]) -> Vec<Q> {
    let (p, r) = (a.len() - 1, b.len() - 1);
    let scale = |c: &[Q]| -> Vec<Q> {
        let n = c.len() - 1;
        c.iter()
            .enumerate()
            .map(|(k, x)| x * binomial(n, k))
            .collect()
    };
    let (sa, sb) = (scale(a), scale(b));
    let mut h = vec![Q::zero(); p + r + 1];
    for (i, ai) in sa.iter().enumerate() {
        for (j, bj) in sb.iter().enumerate() {
            h[i + j] += ai * bj;
        }
    }
    h.iter()
        .enumerate()
        .map(|(k, x)| x / binomial(p + r, k))
        .collect()
}

/// An exact dyadic number `m · 2^e` (sums and products of doubles, without the gcd of
/// general rationals).
#[derive(Clone, Debug)]
struct Dyadic {
    m: BigInt,
    e: i64,
}

impl Dyadic {
    fn of(x: f64) -> Self {
        let r = q(x);
        // A double's denominator is a power of two.
        let e = -(r.denom().bits() as i64 - 1);
        Dyadic {
            m: r.numer().clone(),
            e,
        }
    }
    fn mul(&self, o: &Dyadic) -> Dyadic {
        Dyadic {
            m: &self.m * &o.m,
            e: self.e + o.e,
        }
    }
    fn add(&self, o: &Dyadic) -> Dyadic {
        let e = self.e.min(o.e);
        let (a, b) = (&self.m << (self.e - e) as usize, &o.m << (o.e - e) as usize);
        Dyadic { m: a + b, e }
    }
    fn to_q(&self) -> Q {
        if self.e >= 0 {
            Q::from_integer(&self.m << self.e as usize)
        } else {
            Q::new(self.m.clone(), BigInt::one() << (-self.e) as usize)
        }
    }
}

/// `s a + t b` of two Bernstein polynomials of one degree.
pub fn lincomb(s: &Q, a: &[Q], t: &Q, b: &[Q]) -> Vec<Q> {
    a.iter().zip(b).map(|(x, y)| s * x + t * y).collect()
}

/// The derivative of a Bernstein polynomial on `[lo, hi]`.
pub fn derivative(c: &[Q], lo: f64, hi: f64) -> Vec<Q> {
    let p = c.len() - 1;
    if p == 0 {
        return vec![Q::zero()];
    }
    let f = Q::from_integer(BigInt::from(p)) / (q(hi) - q(lo));
    c.windows(2).map(|w| &f * (&w[1] - &w[0])).collect()
}

/// The degree raised by one.
pub fn elevate(c: &[Q]) -> Vec<Q> {
    let p = c.len() - 1;
    let q1 = Q::from_integer(BigInt::from(p + 1));
    (0..=p + 1)
        .map(|j| {
            let a = Q::from_integer(BigInt::from(j)) / &q1;
            let left = if j > 0 { c[j - 1].clone() } else { Q::zero() };
            let right = if j <= p { c[j].clone() } else { Q::zero() };
            &a * left + (Q::one() - &a) * right
        })
        .collect()
}

/// The part of a Bernstein polynomial on `[0, r]` (de Casteljau, exact).
pub fn split_left(c: &[Q], r: &Q) -> Vec<Q> {
    let mut w = c.to_vec();
    let p = c.len() - 1;
    let mut out = vec![w[0].clone()];
    for level in 1..=p {
        for k in 0..=p - level {
            w[k] = (Q::one() - r) * &w[k] + r * &w[k + 1];
        }
        out.push(w[0].clone());
    }
    out
}

/// The part of a Bernstein polynomial on `[r, 1]`.
pub fn split_right(c: &[Q], r: &Q) -> Vec<Q> {
    let mut w = c.to_vec();
    let p = c.len() - 1;
    let mut out = vec![w[p].clone()];
    for level in 1..=p {
        for k in 0..=p - level {
            w[k] = (Q::one() - r) * &w[k] + r * &w[k + 1];
        }
        out.push(w[p - level].clone());
    }
    out.reverse();
    out
}

/// The value of a Bernstein polynomial at the local parameter `s`.
pub fn value(c: &[Q], s: &Q) -> Q {
    split_left(c, s).pop().expect("non-empty")
}

/// The Bézier coefficients of the B-spline (`degree`, `knots`, one coordinate `coefs`) on the
/// non-empty span `[knots[s], knots[s + 1]]`, by exact blossoming: coefficient `j` is the blossom
/// at `knots[s]` (`p − j` times) and `knots[s + 1]` (`j` times).
pub fn bezier_of_span(degree: usize, knots: &[f64], coefs: &[Q], s: usize) -> Vec<Q> {
    let p = degree;
    let t: Vec<Q> = knots.iter().map(|&k| q(k)).collect();
    (0..=p)
        .map(|j| {
            let args: Vec<Q> = std::iter::repeat_n(t[s].clone(), p - j)
                .chain(std::iter::repeat_n(t[s + 1].clone(), j))
                .collect();
            // de Boor's triangle with one argument per level.
            let mut d: Vec<Q> = coefs[s - p..=s].to_vec();
            for (r, x) in args.iter().enumerate() {
                let level = r + 1;
                for k in (level..=p).rev() {
                    let i = s - p + k;
                    let den = &t[i + p + 1 - level] - &t[i];
                    let alpha = (x - &t[i]) / &den;
                    d[k] = (Q::one() - &alpha) * &d[k - 1] + &alpha * &d[k];
                }
            }
            d[p].clone()
        })
        .collect()
}

/// The exact polynomial `c · Π (x − rᵢ)` on `[0, 1]` as Bernstein coefficients (the roots and
/// `c` doubles), by convolution in the scaled basis on dyadic numbers.
pub fn from_roots(roots: &[f64], c: f64) -> Vec<Q> {
    let mut f = vec![Dyadic::of(c)];
    for &r in roots {
        // (x − r) on [0, 1]: Bernstein coefficients −r and 1 − r (scaled: the same).
        let lin = [Dyadic::of(-r), Dyadic::of(1.0).add(&Dyadic::of(-r))];
        let mut h = vec![Dyadic::of(0.0); f.len() + 1];
        for (i, a) in f.iter().enumerate() {
            for (j, b) in lin.iter().enumerate() {
                h[i + j] = h[i + j].add(&a.mul(b));
            }
        }
        f = h;
    }
    let n = f.len() - 1;
    f.iter()
        .enumerate()
        .map(|(k, x)| x.to_q() / binomial(n, k))
        .collect()
}

/// The rounded coefficients and the exact bound on their rounding (as a double rounded up).
pub fn rounded(c: &[Q]) -> (Vec<f64>, f64) {
    let v: Vec<f64> = c.iter().map(f).collect();
    let mut err = 0.0f64;
    for (x, y) in v.iter().zip(c) {
        let d = f(&(q(*x) - y).abs());
        err = err.max(d * (1.0 + 4.0 * f64::EPSILON) + f64::MIN_POSITIVE);
    }
    (v, err)
}
