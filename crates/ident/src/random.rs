//! The one random generator: small, reproducible from its seed, and the same on every
//! machine, so that a fit's spread-out starts, a designed test's noise and every generated
//! record of the tests come out the same each run.

/// A small reproducible generator (Knuth's MMIX linear congruential constants) for the
/// spread-out starts, a PRBS test's noise, and the tests' noise and random walks: the one
/// generator of the workspace.
pub struct Lcg(pub u64);

impl Lcg {
    /// The next 53 random bits.
    pub fn bits(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 11
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        self.bits() as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [−1, 1).
    pub fn symmetric(&mut self) -> f64 {
        2.0 * self.unit() - 1.0
    }
    /// Uniform in 0..n (n > 0).
    pub fn below(&mut self, n: usize) -> usize {
        (self.bits() % n as u64) as usize
    }
    /// A standard normal draw (Box–Muller, from two uniform draws).
    pub fn gaussian(&mut self) -> f64 {
        let u1 = 1.0 - self.unit();
        let u2 = self.unit();
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
    /// Uniform in [a, b).
    pub fn range(&mut self, (a, b): (f64, f64)) -> f64 {
        a + (b - a) * self.unit()
    }
    /// −1 or +1, even odds.
    pub fn sign(&mut self) -> f64 {
        if self.unit() < 0.5 { -1.0 } else { 1.0 }
    }
    /// Uniform in ±[a, b).
    pub fn signed(&mut self, r: (f64, f64)) -> f64 {
        let s = self.sign();
        s * self.range(r)
    }
    /// One of `items` (not empty), uniformly.
    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}
