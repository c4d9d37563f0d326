//! One seeded generator of uniform draws, for tests and benchmarks that must draw the same
//! numbers on every machine (proptest draws the rest).

/// A linear congruential generator (Knuth's MMIX constants) of draws in `[0, 1)`, from the
/// top 53 bits of its state.
#[derive(Debug, Clone)]
pub struct Lcg(pub u64);

impl Lcg {
    /// The next draw, in `[0, 1)`.
    #[allow(clippy::should_implement_trait)] // (not an iterator: it never ends)
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The draws of [`Lcg`] from `seed`, as a closure.
pub fn rng(seed: u64) -> impl FnMut() -> f64 {
    let mut lcg = Lcg(seed);
    move || lcg.next()
}
