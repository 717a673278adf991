//! What a real logger adds to a process's answer: noise (white or AR(1)-coloured, Gaussian
//! or uniform), isolated spikes and dropouts, a converter's resolution. Shared by the
//! challenges and the diagnosis's generated-record tests, so both draw the same flaws.

use crate::random::Lcg;

/// `n` samples of noise of standard deviation `sd`: Gaussian or uniform innovations (even
/// odds), AR(1) with coefficient `rho` (0 for white), started in its stationary spread.
pub fn noise(rng: &mut Lcg, n: usize, sd: f64, rho: f64) -> Vec<f64> {
    let gauss = rng.unit() < 0.5;
    let innovation = |rng: &mut Lcg| {
        if gauss {
            rng.gaussian()
        } else {
            3f64.sqrt() * rng.symmetric()
        }
    };
    let scale = sd * (1.0 - rho * rho).sqrt();
    let mut x = innovation(rng) * sd;
    (0..n)
        .map(|_| {
            x = rho * x + scale * innovation(rng);
            x
        })
        .collect()
}

/// Replaces a share (drawn in `share`) of the samples, at least three, by spikes or dropouts
/// of 6–15 `sd`; returns how many were drawn (a sample may be drawn twice).
pub fn outliers(rng: &mut Lcg, y: &mut [f64], share: (f64, f64), sd: f64) -> usize {
    let n = y.len();
    let count = ((rng.range(share) * n as f64).round() as usize).max(3);
    for _ in 0..count {
        let i = rng.below(n);
        let size = rng.range((6.0, 15.0)) * sd;
        y[i] += if rng.unit() < 0.5 { -size } else { size };
    }
    count
}

/// Rounds every sample to a multiple of `quantum` (a converter's or sensor's resolution).
pub fn quantise(y: &mut [f64], quantum: f64) {
    for v in y {
        *v = (*v / quantum).round() * quantum;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coloured_noise_keeps_its_spread_and_correlation() {
        let mut rng = Lcg(7);
        let e = noise(&mut rng, 20_000, 2.0, 0.8);
        let n = e.len() as f64;
        let var = e.iter().map(|x| x * x).sum::<f64>() / n;
        let lag = e.windows(2).map(|w| w[0] * w[1]).sum::<f64>() / n;
        assert!((var.sqrt() - 2.0).abs() < 0.15, "sd {}", var.sqrt());
        assert!((lag / var - 0.8).abs() < 0.03, "rho {}", lag / var);
    }

    #[test]
    fn quantised_samples_are_multiples_of_the_quantum() {
        let mut y = vec![0.26, -1.74, 3.0];
        quantise(&mut y, 0.5);
        assert_eq!(y, vec![0.5, -1.5, 3.0]);
    }
}
