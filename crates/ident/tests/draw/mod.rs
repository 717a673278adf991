//! Random draws shared by the generated-record tests (seeded `Lcg`, so a case is the same
//! every run): a uniform value in a range, a random sign, the two together, a standard
//! normal; as functions of an `Lcg` or as methods of a test's own generator ([`Draws`]).
//! The draws themselves are the library's (`Lcg::range`, …, shared with the challenges).
#![allow(dead_code)] // each test binary uses its own subset

use degrau_ident::random::Lcg;

/// Uniform in [a, b).
pub fn range(rng: &mut Lcg, r: (f64, f64)) -> f64 {
    rng.range(r)
}

/// −1 or +1, even odds.
pub fn sign(rng: &mut Lcg) -> f64 {
    rng.sign()
}

/// Uniform in ±[a, b).
pub fn signed(rng: &mut Lcg, r: (f64, f64)) -> f64 {
    rng.signed(r)
}

/// The same draws as methods of a test's own generator around an `Lcg` (its seeding and
/// its other shapes its own).
pub trait Draws {
    /// The generator drawn from.
    fn lcg(&mut self) -> &mut Lcg;

    /// Uniform in [a, b).
    fn range(&mut self, r: (f64, f64)) -> f64 {
        range(self.lcg(), r)
    }

    /// −1 or +1, even odds.
    fn sign(&mut self) -> f64 {
        sign(self.lcg())
    }

    /// Uniform in ±[a, b).
    fn signed(&mut self, r: (f64, f64)) -> f64 {
        signed(self.lcg(), r)
    }

    /// Standard normal (Box–Muller).
    fn gaussian(&mut self) -> f64 {
        self.lcg().gaussian()
    }
}
