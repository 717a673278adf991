//! Random draws shared by the generated-record tests (seeded `Lcg`, so a case is the same
//! every run): a uniform value in a range, a random sign, the two together, a standard
//! normal; as functions of an `Lcg` or as methods of a test's own generator ([`Draws`]).
#![allow(dead_code)] // each test binary uses its own subset

use degrau_ident::random::Lcg;

/// Uniform in [a, b).
pub fn range(rng: &mut Lcg, (a, b): (f64, f64)) -> f64 {
    a + (b - a) * rng.unit()
}

/// −1 or +1, even odds.
pub fn sign(rng: &mut Lcg) -> f64 {
    if rng.unit() < 0.5 { -1.0 } else { 1.0 }
}

/// Uniform in ±[a, b).
pub fn signed(rng: &mut Lcg, r: (f64, f64)) -> f64 {
    let s = sign(rng);
    s * range(rng, r)
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
