//! `coloured_noise`: the final model's residuals are correlated although no structural
//! extension pays for itself. The deterministic model is then adequate, and the noise is
//! not white: its lag-one autocorrelation ρ (an AR(1) coefficient) is named, and the
//! parameters' intervals, computed as if the N residuals were independent, are widened by
//! the AR(1) correction √((1 + ρ)/(1 − ρ)) (the variance of a mean of AR(1) samples is that
//! factor squared times the white one's).

use super::{Handling, TestCause, TestCauseKind, TestEvidence};
use crate::stats::{ar1_widening, lag_one};

/// The least lag-one autocorrelation named.
pub const MIN_LAG1: f64 = 0.3;
/// ... and its least significance, ρ·√N (the white-noise band is ±1.96/√N at 95 %).
pub const MIN_Z: f64 = 4.0;

/// Coloured noise in the final model's `residuals`, if correlated enough.
pub fn detect(times: &[f64], residuals: &[f64]) -> Option<TestCause> {
    let lag1 = lag_one(residuals);
    let n = residuals.len() as f64;
    if !(lag1 >= MIN_LAG1 && lag1 * n.sqrt() >= MIN_Z) {
        return None;
    }
    let factor = ar1_widening(lag1);
    Some(TestCause {
        kind: TestCauseKind::ColouredNoise,
        evidence: TestEvidence::ColouredNoise {
            lag1,
            widening: factor,
        },
        interval: times.first().zip(times.last()).map(|(a, b)| (*a, *b)),
        handling: Handling::IntervalsWidened { factor },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_ar1_sequence_is_coloured_and_white_noise_is_not() {
        // x_k = 0.9·x_{k−1} + e_k with a deterministic, zero-mean e.
        let mut rng = crate::random::Lcg(11);
        let white: Vec<f64> = (0..2000).map(|_| rng.symmetric()).collect();
        let mut x = vec![0.0; 2000];
        for i in 1..x.len() {
            x[i] = 0.9 * x[i - 1] + white[i];
        }
        let times: Vec<f64> = (0..x.len()).map(|k| k as f64).collect();
        let c = detect(&times, &x).unwrap();
        let TestEvidence::ColouredNoise { lag1, widening } = c.evidence else {
            panic!()
        };
        assert!((lag1 - 0.9).abs() < 0.05, "{lag1}");
        assert!((widening - (1.9f64 / 0.1).sqrt()).abs() < 1.0);
        assert!(detect(&times, &white).is_none());
    }
}
