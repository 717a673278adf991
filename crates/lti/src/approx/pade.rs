//! Rational stand-ins for a dead time e^{−θs}, as the Tognetti notes list them: Padé (m, n)
//! for any m ≤ n, Taylor's 1 − θs and 1/(1 + θs), and the limit (1 + θs/n)^{−n}; and the
//! system with its dead time replaced by one of them (what a closed loop around a dead time
//! needs, since the exact core refuses to close a loop around a true delay).
//!
//! Padé (m, n) of e^{−θs}, written as the notes write it (constant term (m + n)!/m!):
//! numerator Σ_k C(m, k)·(m + n − k)!/m!·(−θs)^k, denominator Σ_k C(n, k)·(m + n − k)!/m!·(θs)^k,
//! e.g. G_{1,1} = (−θs + 2)/(θs + 2), G_{2,2} = (θ²s² − 6θs + 12)/(θ²s² + 6θs + 12). Its
//! Taylor series equals the delay's to order m + n; its zeros are in the right half plane
//! (the initial wrong-way jump of a step response), its poles in the left.

use serde::{Deserialize, Serialize};

use super::ApproxError;
use super::reduce::low_frequency_gain;
use crate::tf::MAX_ORDER;
use crate::{C64, TransferFunction, poly};

/// A rational approximant of e^{−θs}.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum DelayApproximant {
    /// Padé (m, n), m ≤ n, n ≥ 1.
    Pade { m: usize, n: usize },
    /// Taylor to first order: 1 − θs (a zero at 1/θ).
    TaylorZero,
    /// Taylor of e^{θs} to first order, inverted: 1/(1 + θs) (a pole at −1/θ).
    TaylorLag,
    /// (1 + θs/n)^{−n}: n equal lags θ/n, e^{−θs} as n → ∞.
    Limit { n: usize },
}

/// An approximant of e^{−θs} for one θ: its polynomials (descending powers of s) and its
/// zeros, poles and the k of its zero-pole-gain form (roots exact where they are known in
/// closed form, so a repeated pole stays repeated).
#[derive(Debug, Clone, PartialEq)]
pub struct DelayFactor {
    pub num: Vec<f64>,
    pub den: Vec<f64>,
    pub zeros: Vec<C64>,
    pub poles: Vec<C64>,
    pub gain: f64,
}

fn check_delay(delay: f64) -> Result<(), ApproxError> {
    if delay.is_finite() && delay > 0.0 {
        Ok(())
    } else {
        Err(ApproxError::BadDelay(delay))
    }
}

/// C(n, k), exactly for the orders accepted here.
fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1u128, |acc, i| acc * (n - i) as u128 / (i + 1) as u128) as f64
}

/// (m + n − k)!/m!, the product m+1 … m+n−k (k ≤ n).
fn falling(m: usize, n: usize, k: usize) -> f64 {
    (m + 1..=m + n - k).map(|i| i as f64).product()
}

/// The notes' Padé (m, n) polynomials of e^{−θs}, descending powers of s, with constant term
/// (m + n)!/m! in both (e.g. (1, 2): −2θs + 6 over θ²s² + 4θs + 6). Refused when a
/// coefficient falls outside double precision's normal range (θ = 1e-300 with n ≥ 2: the
/// θ²s² term would underflow to 0 and the degree drop).
pub fn pade_coefficients(
    delay: f64,
    m: usize,
    n: usize,
) -> Result<(Vec<f64>, Vec<f64>), ApproxError> {
    check_delay(delay)?;
    if n == 0 || m > n || n > MAX_ORDER {
        return Err(ApproxError::PadeOrder { m, n });
    }
    // factor·θ^k as the notes write it; where θ^k alone leaves the normal range, the factor
    // times θ one power at a time, which stays in range whenever the coefficient does.
    let term = |k: usize, degree: usize, theta: f64| {
        let (factor, power) = (binomial(degree, k) * falling(m, n, k), theta.powi(k as i32));
        if power.is_normal() {
            factor * power
        } else {
            (0..k).fold(factor, |c, _| c * theta)
        }
    };
    let num: Vec<f64> = (0..=m).rev().map(|k| term(k, m, -delay)).collect();
    let den: Vec<f64> = (0..=n).rev().map(|k| term(k, n, delay)).collect();
    if num.iter().chain(&den).any(|c| !c.is_normal()) {
        return Err(ApproxError::PadeRange { delay, m, n });
    }
    Ok((num, den))
}

/// The approximant `approximant` of e^{−θs} for θ = `delay` > 0.
pub fn delay_factor(approximant: DelayApproximant, delay: f64) -> Result<DelayFactor, ApproxError> {
    check_delay(delay)?;
    let factor = match approximant {
        DelayApproximant::Pade { m, n } => {
            let (num, den) = pade_coefficients(delay, m, n)?;
            DelayFactor {
                zeros: poly::roots(&num)?,
                poles: poly::roots(&den)?,
                gain: num[0] / den[0],
                num,
                den,
            }
        }
        DelayApproximant::TaylorZero => DelayFactor {
            num: vec![-delay, 1.0],
            den: vec![1.0],
            zeros: vec![C64::new(1.0 / delay, 0.0)],
            poles: Vec::new(),
            gain: -delay,
        },
        DelayApproximant::TaylorLag => DelayFactor {
            num: vec![1.0],
            den: vec![delay, 1.0],
            zeros: Vec::new(),
            poles: vec![C64::new(-1.0 / delay, 0.0)],
            gain: 1.0 / delay,
        },
        DelayApproximant::Limit { n } => {
            if n == 0 || n > MAX_ORDER {
                return Err(ApproxError::PadeOrder { m: 0, n });
            }
            let lag = delay / n as f64;
            DelayFactor {
                num: vec![1.0],
                den: (0..=n)
                    .rev()
                    .map(|k| binomial(n, k) * lag.powi(k as i32))
                    .collect(),
                zeros: Vec::new(),
                poles: vec![C64::new(-1.0 / lag, 0.0); n],
                gain: lag.powi(-(n as i32)),
            }
        }
    };
    Ok(factor)
}

/// Padé (m, n) of e^{−θs} as a transfer function (m ≤ n, n ≥ 1, θ > 0): MATLAB's
/// `pade(θ, n)` is (n, n).
pub fn pade(delay: f64, m: usize, n: usize) -> Result<TransferFunction, ApproxError> {
    let f = delay_factor(DelayApproximant::Pade { m, n }, delay)?;
    Ok(TransferFunction::from_zpk(&f.zeros, &f.poles, f.gain)?)
}

/// `g` with its dead time replaced by `approximant`: G(s)·R(s), no delay left, with g's
/// low-frequency gain kept exactly (every approximant is 1 at s = 0). A system without
/// dead time is refused ([`ApproxError::NoDelay`]).
pub fn replace_delay(
    g: &TransferFunction,
    approximant: DelayApproximant,
) -> Result<TransferFunction, ApproxError> {
    if g.delay() == 0.0 {
        return Err(ApproxError::NoDelay);
    }
    let f = delay_factor(approximant, g.delay())?;
    let zeros: Vec<C64> = g.zeros().iter().chain(&f.zeros).copied().collect();
    let poles: Vec<C64> = g.poles().iter().chain(&f.poles).copied().collect();
    let product = TransferFunction::from_zpk(&zeros, &poles, g.gain() * f.gain)?;
    let k = low_frequency_gain(g);
    let now = low_frequency_gain(&product);
    // k/now first: it is near 1, where gain·k may overflow (a gain of 1e153 over a den of
    // 1e-2 gave k ≈ 1e155 and an infinite product).
    Ok(TransferFunction::from_zpk(
        product.zeros(),
        product.poles(),
        product.gain() * (k / now),
    )?)
}

/// `g` with its dead time replaced by Padé (m, n); `g` itself when it has no dead time.
/// What a closed loop around a dead time uses (`TransferFunction::closed_loop` refuses a
/// true delay).
pub fn delay_free_with_pade(
    g: &TransferFunction,
    m: usize,
    n: usize,
) -> Result<TransferFunction, ApproxError> {
    if g.delay() == 0.0 {
        return Ok(g.clone());
    }
    replace_delay(g, DelayApproximant::Pade { m, n })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials_and_falling_products_are_exact() {
        assert_eq!(binomial(6, 3), 20.0);
        assert_eq!(binomial(30, 15), 155_117_520.0);
        assert_eq!(falling(1, 2, 0), 6.0);
        assert_eq!(falling(3, 3, 3), 1.0);
    }

    #[test]
    fn a_limit_keeps_its_repeated_pole_exact() {
        let f = delay_factor(DelayApproximant::Limit { n: 4 }, 2.0).unwrap();
        assert_eq!(f.poles, vec![C64::new(-2.0, 0.0); 4]);
        // (0.5 s + 1)^4 = 0.0625 s⁴ + 0.5 s³ + 1.5 s² + 2 s + 1.
        assert_eq!(f.den, vec![0.0625, 0.5, 1.5, 2.0, 1.0]);
    }
}
