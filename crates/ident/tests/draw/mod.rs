//! Random draws shared by the generated-record tests (seeded `Lcg`, so a case is the same
//! every run): a uniform value in a range, the same with a random sign, a standard normal.
#![allow(dead_code)] // each test binary uses its own subset

use degrau_ident::random::Lcg;

/// Uniform in [a, b).
pub fn range(rng: &mut Lcg, (a, b): (f64, f64)) -> f64 {
    a + (b - a) * rng.unit()
}

/// Uniform in ±[a, b).
pub fn signed(rng: &mut Lcg, r: (f64, f64)) -> f64 {
    let s = if rng.unit() < 0.5 { -1.0 } else { 1.0 };
    s * range(rng, r)
}
