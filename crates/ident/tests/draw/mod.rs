//! Random draws shared by the generated-record tests (seeded `Lcg`, so a case is the same
//! every run): a uniform value in a range, a random sign, the two together, a standard
//! normal; as functions of an `Lcg` or as methods of a test's own generator ([`Draws`]); and the
//! level a record holds before its first change.
//! The draws themselves are the library's (`Lcg::range`, …, shared with the challenges).
#![allow(dead_code)] // each test binary uses its own subset

use degrau_ident::fit::FitData;
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

    /// Log-uniform in [a, b] (a, b > 0).
    fn log_range(&mut self, (a, b): (f64, f64)) -> f64 {
        (a.ln() + (b.ln() - a.ln()) * self.lcg().unit()).exp()
    }
}

/// The mean of the samples before the first logged change.
pub fn mean_before(data: &FitData) -> f64 {
    let t0 = data.input.t0();
    let before: Vec<f64> = data
        .times
        .iter()
        .zip(&data.y)
        .take_while(|(t, _)| **t < t0)
        .map(|(_, y)| *y)
        .collect();
    before.iter().sum::<f64>() / before.len() as f64
}
